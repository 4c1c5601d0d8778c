; syntax-homoglyphs-codes: a Cyrillic look-alike inside a three-letter code is NC1027
; naming the Latin letter too (decision 2 names (CTL,Т) itself; §2.13.5.4 seed L9499
; prints it so). Expect NC1027 at line 5 column 6 ('Т' U+0422, Latin 'T'), line 6 column
; 6 ('Е' U+0415, Latin 'E'), line 7 column 8 ('Х' U+0425, Latin 'X').
(CTL,Т)
(DIS,Е30)
(UOT,0,Х10)
