end-tool-unknown: a T not in the profile's [tools] is a warning (NC4019, docs/profile.md); the run goes on and the tool is selected and loaded
%
N1 T9 (the default profile has tools 1 to 3)
N2 M06
N3 T3 M06 (in the table)
N4 M30
