(indirect #[...] to a variable that does not exist: a run-time error at the block)
#1=33;
#[#1]=5;
G01 X#33 F100;
(#200 and #1000 do not exist: an index written as a number is checked as #200 is, NC2026)
#1=#1+1;
#[#1]=6;
G01 X#[#1];
#[200]=7;
G01 X#[200];
#[1000]=8;
G01 X#[1000];
M30;
