(indirect #[...] to a variable that does not exist: a run-time error at the block)
#1=33;
#[#1]=5;
G01 X#33 F100;
(#34 and #200 do not exist: written literally they are NC2026)
#1=#1+1;
#[#1]=6;
G01 X#[#1];
#[200]=7;
G01 X#[200];
#[1000]=8;
G01 X#[1000];
M30;
