(read-only and unknown system variables)
#4001=1;
#5041=3;
#1=#1000;
#1=#5224;
#1=#4004;
M30;
