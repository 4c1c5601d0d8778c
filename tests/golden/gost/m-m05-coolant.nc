m-m05-coolant: M05 stops the spindle and switches coolant off (GOST 20999 Table 8, ncc decision 21), after the motion of its block (Table 7)
%
N1 S400 M03 M07 M08 (spindle and both coolants; M07 and M08 may share a block)
N2 G00 X10. M05 (after the move - spindle stop and coolant off)
N3 M08 (coolant alone)
N4 M05 (switches the coolant off with the spindle already stopped)
N5 M30
