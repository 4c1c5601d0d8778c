end-power-on: the power-on state of GOST 20999 §8 per control type (machine.control_type, ncc decision 19), seen in blocks without G codes; M02 returns to it
%1
N1 X10. Z5. F100. (positioning - G00 rapid; contouring and lathe - G01)
N2 G02 X20. I5. (positioning and contouring - plane XY; lathe - plane ZX)
N3 X0 I-10. M02 (G02 stays in force until the reset)
%2
N1 X10. F100. (the power-on motion again)
N2 G02 X20. I5.
N3 M30
