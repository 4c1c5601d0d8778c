G83 deep drilling (GOST 20999 Table 6): pecks of Q from R, rapid to R and back after each, the last peck short
%
N1 G90 G00 X0 Y0 Z10. (INITIAL LEVEL Z10)
N2 G83 X10. Y20. Z-9.3 Q4.5 R2.5 F100. S800 M03 (11.8 MM BELOW R IN PECKS OF 4.5, 4.5, 2.8)
N3 X30. (SECOND HOLE, THE SAME PECKS)
N4 G80 M05
N5 M30
