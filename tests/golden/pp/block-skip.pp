%15 "blocks the block-skip switch skips do not run"
N1 X1
N2 /X2
N3 X3 / "the mark may stand anywhere after N"
N4 M30
