(E-36: a fourth nested loop, an END that closes the wrong loop, END without DO, index 4, index 0, DO without END)
#1=0;
WHILE [#1 GT 1] DO1;
WHILE [#1 GT 1] DO2;
WHILE [#1 GT 1] DO3;
WHILE [#1 GT 1] DO1;
END1;
END3;
END2;
END1;
(END2 closing DO1)
WHILE [#1 GT 1] DO1;
END2;
END1;
(END without DO)
END3;
(index 4 and index 0)
WHILE [#1 GT 1] DO4;
END4;
WHILE [#1 GT 1] DO0;
END0;
(DO without END)
DO1;
M30;
