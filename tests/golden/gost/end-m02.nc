end-m02: M02 stops spindle and coolant (recorded), then the NC returns to its GOST 20999 §8 state and the next program starts; the position is kept (Table 8, ncc decisions 4, 19, 21)
%1
N1 G91 G00 X10. Y10. (incremental, rapid)
N2 G01 X1. F50. S300 M04 M07 M08 (a feed move with spindle and both coolants)
N3 M02
%2
N1 Y5. F80. (power-on state - G01 and G90 - a feed move to Y5, X kept at 11)
N2 G00 X0 M30
