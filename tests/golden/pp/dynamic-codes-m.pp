Codes chosen by R parameters (decision 10) follow the group rules at run time: M03
and M04 are both of group M2 (G04 and G03 may share a block).
%1
N1 R1 3 R2 4
N2 MR1 MR2 GR2 GR1 X1
N3 M30
