%1
N1 G72 L5 "a macro not in the library: reported at this call, once"
N2 G01 X1 F100
N3 G72 L5 "the second call has errors too, and says nothing more"
N4 M30
