N1 (format-no-controls-errors - the format has no main-block and no block-skip character, NC1017) G01 X10 F100
:2 X20 (main block, NC1017)
/N3 X30 (block skip before the block, NC1017)
N4 X40 /Y5 (block skip inside the block, NC1017)
N5 M02
