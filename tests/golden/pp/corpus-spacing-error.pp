The manual's spacing error (seed 003, section 2.1.2 f): a space in the middle of the
value. Expect an error at X36.  12.
%5
N1 G1 F100 X36.  12
N2 M30
