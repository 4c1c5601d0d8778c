(translate-reference-bare: G28 without words takes every axis straight to the reference point [docs/dialects/iso.md decision 17], so on a machine of X Y Z it is a rapid in NC-110's and GOST's machine coordinates, also under G91)
G90 G00 X10 Y10 Z10
G91 G01 X5 F100
G28
G00 X1
M30
