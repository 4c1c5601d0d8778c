N1 (format-no-controls - the format has no program start, main block or block skip, so the program starts at the first line) G01 X10 F100
N2 X20 Y5 (a second feed move)
N3 M02
