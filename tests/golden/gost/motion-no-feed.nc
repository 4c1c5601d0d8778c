motion-no-feed: a feed move needs F; F is unset at power-on (GOST 20999 §3.3.3, §8)
%
N1 G90 G00 X10. (a rapid needs no feed)
N2 G01 X20. (NC4001, no F has been programmed)
N3 M02
