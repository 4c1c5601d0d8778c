(translate-numbering-pp: what a translation back gives again, docs/translate.md "Round trips": ISO's #501 is pp's R1, set before anything reads it, so with no 0 at the start; a comment alone is a comment line of the block before; M99 alone after a subprogram's last block is that block's G70)
#501=5
G01 X#501 F100
(a comment alone)
M98 P100
M30
O100
G91 G01 Y#501
G90
M99
