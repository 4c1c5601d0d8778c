The jump example of the manual (seed 003, section 2.3.6), its elisions filled in as
the spec's P-17.2 does. Expect: N25 once; N26..N54 four times (once, then repeated
three times: "the section is executed n+1 times"); then N55. Each pass moves X +10
and Y +5: the end is X40 Y20.
%1
N25 X0 Y0
N26 G91 G1 X10 F100
N27 Y5
N54 G73 L26 Q3
N55 G90 M30
*
