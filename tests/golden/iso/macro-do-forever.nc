(DO1 .. END1 without WHILE and without a way out: --max-steps stops the run)
#1=0;
DO1;
#1=#1+1;
G01 X#1 F100;
END1;
M30;
