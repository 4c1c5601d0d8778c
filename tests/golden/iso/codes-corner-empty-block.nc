(E-05 with an empty block, spec 8.3: an empty block or a comment-only block must not follow a chamfer or fillet block; EXPECTED NC3037 at the lone semicolon of line 4 as for a comment block; ncc skips the empty block and makes the chamfer with line 5)
G90 G00 X0 Y0 Z0;
G01 X20 F100 ,C1;
;
G01 Y10;
M30;
