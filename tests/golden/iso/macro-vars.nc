(Macro B variables: locals #1-#33, commons #100-#199 and #500-#999, indirect #[...])
#1=1.5;
#33=2;
#100=3;
#199=4;
#500=5;
#999=6;
G01 X#1 Y#33 Z#100 F100;
G01 X#199 Y#500 Z#999;
(indirect: #[#1+0.5] is #2, #[#100*200-100] is #500)
#[#1+0.5]=7;
#[#100*200-100]=#500+1;
G01 X#2 Y#[2] Z#500;
(the index of #[...] is itself an expression with a variable inside)
#10=33;
#[#10]=#[#10]+1;
G01 X#33 Y[#[#10]*2] Z[-#[#10-23-8]];
(an assignment overwrites; a long value keeps its decimals)
#1=0.1234;
G01 X#1 Y0 Z0;
M30;
