motion-axes: rotary A B C and secondary U V W axes (GOST 20999 Table 1); an axis shows in the trace once it has left zero
%
N1 G90 G01 X1. F100. (only X Y Z are shown)
N2 A90. (A leaves zero and is shown from here on, in degrees)
N3 U5. B-45. (axis order in the trace X Y Z A B C U V W)
N4 A0 (A back at zero is still shown)
N5 G91 V2. W-3. C10. (incremental secondary and rotary axes)
N6 G00 U-5. (rapid, U back to zero)
N7 G90 X2. (G00 still in force, words not written keep every axis)
N8 M02
