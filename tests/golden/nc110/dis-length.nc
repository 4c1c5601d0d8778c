; dis-length: a text of DIS has at most 32 characters, counted as characters
; (Cyrillic letters are one each, not two bytes): 33 is NC3031 at the text
; (§2.13.6.1 L9601 "up to 32 characters"; §2.6 L1576; decision 37).
; 32 ASCII characters, 32 Cyrillic: allowed
(DIS,"12345678901234567890123456789012")
(DIS,"ЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖ")
; a message of two texts may be longer than 32 in all
(DIS,"A","12345678901234567890123456789012")
; 33 characters: NC3031
(DIS,"123456789012345678901234567890123")
(DIS,"ЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖЖ")
(DIS,"OK","123456789012345678901234567890123")
M30
