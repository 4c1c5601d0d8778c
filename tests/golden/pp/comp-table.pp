%14 "G93 loads compensation entries with the words the machine names"
N1 G93 D3 Z120.5 K4 "entry 3: length 120.5, radius 4; D3 is not selected"
N2 G93 D4 K6 "entry 4: the radius only"
N3 D3 &001 "axis 4. plus the length of entry 3"
N4 G93 D3 Z100 "loading the selected entry changes the offset in force"
N5 G01 X10 F100
N6 G93 K5 "no entry"
N7 M30
