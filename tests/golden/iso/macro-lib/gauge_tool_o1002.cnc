%
(the title before the number, decision 51)
O1002;
G1Y2.F100;
M99;
%
