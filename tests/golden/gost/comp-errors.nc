comp-errors: an offset number not in the profile's [offsets] is NC4020 (docs/profile.md); G41 and G43 are both group d (GOST 20999 Table 4 note 3, NC3002)
%
N1 D9 (the default profile has offsets 1 to 3)
N2 G43 H4
N3 G41 G43 (two compensations in one block)
N4 M30
