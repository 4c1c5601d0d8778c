modal-feed-modes: G93 inverse time, G94 per minute, G95 per revolution (GOST 20999 Table 4 group k, Table 5, §3.3.3)
%
N1 G94 G01 X10. F200. (mm per minute)
N2 G93 X20. F2. (inverse time - this block takes 1/2 minute)
N3 Y10. F0.5 (every feed move in G93 carries its own F)
N4 G02 X30. Y0 J-10. F4. (an arc in G93, 1/4 minute)
N5 G00 X0 (a rapid needs no F in G93)
N6 G95 G01 X5. F0.2 S500 M03 (mm per spindle revolution)
N7 G94 X10. F300. (back to mm per minute)
N8 M30
