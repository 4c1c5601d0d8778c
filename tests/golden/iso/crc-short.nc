(E-12: a move shorter than the tool radius between two others: its offset would run backwards)
G17 G90 G00 X0 Y-10 Z0;
G41 D1 G01 F100 X0 Y0;
X20;
Y3;
X0;
Y0;
G40 X0 Y-10;
M30;
