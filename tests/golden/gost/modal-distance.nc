modal-distance: G90 absolute, G91 incremental dimensions (GOST 20999 Table 4 group i, §3.2.1, §3.2.5); I, J stay increments from the start (§4.3.3)
%
N1 G90 G00 X10. Y10. (absolute)
N2 G91 X5. Y-5. (incremental - to X15 Y5)
N3 Z-2. (G91 stays in force)
N4 G01 X-15. F100. (the sign gives the direction - to X0)
N5 G02 X10. Y0 I5. (incremental end point X10 Y5, centre X5 Y5)
N6 G90 G01 X0 Y0 (absolute again)
N7 G03 X10. I5. (absolute end point, centre still start + I)
N8 M30
