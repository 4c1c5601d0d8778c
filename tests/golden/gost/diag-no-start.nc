diag-no-start: no program-start character anywhere, so everything is leader (NC1008)
N1 G01 X10 F100
N2 M30
