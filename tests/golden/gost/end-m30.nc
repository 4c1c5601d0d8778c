end-m30: M30 stops spindle and coolant after the motion of its block (recorded) and ends the information - nothing after it is read (GOST 20999 §1.9, Tables 7-8)
%
N1 G00 X5. S200 M03 M08
N2 G91 X5. M30
%
N1 X99. (not read)
N2 M02
