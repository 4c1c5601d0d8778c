motion-feed: F is modal; G00 ignores the feed but does not cancel it (GOST 20999 Table 5, G00)
%
N1 G90 G01 X10. F150. (F150 set with a feed move)
N2 G00 X20. (rapid, F150 ignored)
N3 G01 X30. (feed move again without F, F150 still in force)
N4 G00 Y10. F400. (F written in a rapid block is set for later feed moves)
N5 G01 Y0 (moves at F400 without a new F)
N6 F250. (a block with F alone sets F and moves nothing)
N7 X0
N8 M02
