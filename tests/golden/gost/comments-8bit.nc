comments-8bit: a comment in 8-bit text (KOI8-R): the file is not UTF-8 and is not
read; the message says where, and how to convert it (decision 9).
%
N1 G00 X1. (πεςεθοδ 2: ώιστοχαρ οβςαβοτλα λοξτυςα)
N2 (a	b) M30
