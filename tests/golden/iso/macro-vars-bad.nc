(variables that do not exist, and #0 which cannot be set)
#0=1;
#34=1;
#200=1;
#1000=2;
#499=3;
#1=#34+#200;
G01 X#1000 F100;
#1=#0;
M30;
