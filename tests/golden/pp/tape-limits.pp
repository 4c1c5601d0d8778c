%13 "an 80-character line; no '*' at the end"
N1 G01 X1 F100 "this line has exactly eighty characters, counting every one...."
N2 G01 X2 F100 "this line has eighty-one characters: one more than allowed......"
N3 M30
