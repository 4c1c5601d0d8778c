; labels-chars: a label is 1 to 6 capital letters, digits or Cyrillic capitals,
; case-sensitive, and a digit may come first (§2.4.4 seed L1478-1480, §1.2.32 L827-834;
; decision 3). The manual's labels НАЧАЛО (L834, 6 characters, 12 bytes), "1" (L8987)
; and "F". Latin A and Cyrillic А are two different labels.
; jumps: line 6 -> 8 -> 11 -> 9 (message CYRILLIC A) -> 10 -> 13 (message END)
(BNC,НАЧАЛО)
"A" (DIS,"LATIN A")
"НАЧАЛО" (BNC,1)
"А" (DIS,"CYRILLIC A")
(BNC,ABCDEF)
"1" (BNC,А)
"F" (DIS,"F")
"ABCDEF" (DIS,"END")
; a label-only block of mixed scripts and a digit does nothing
"Ё9Z"
