The program 35 example of the manual (seed 003, section 2.3.4) with its elisions ("....",
"N510 ...") filled in as the spec's P-17.1 does; the comments are the manual's.
Expect: subprogram 100 runs twice (N80 G71 L100 Q2): X 200 -> 210 -> 220; subprogram
200 runs once (N120 G71 L200, Q omitted = Q1): Y -> 50; after each call the main part
goes on with its next block; N320 M30 is the logical end, '*' the physical end.
N10 moves at rapid: the motion group starts at G00 (decision 20).
%35 " НАЧАЛО ПАРТПРОГРАММЫ НОМЕР 35 "
 N10 X0 Y0 Z0 G54 " ПЕРВЫЙ БЛОК ПАРТПРОГРАММЫ "
 N20 X200 G1 F300 " ВТОРОЙ БЛОК ПАРТПРОГРАММЫ "
 N80 G71 L100 Q2 " ВЫЗОВ ПОДПРОГРАММЫ НОМЕР 100 "
 " ПОДПРОГРАММА БУДЕТ ВЫЗЫВАТЬСЯ ДВА РАЗА "
 N120 G71 L200 " ВЫЗОВ ПОДПРОГРАММЫ НОМЕР 200 "
 N310 X0 Y0 Z0 G00 " ТЕКУЩИЙ БЛОК ПАРТПРОГРАММЫ "
 N320 M30  " ЛОГИЧЕСКОЕ ОКОНЧАНИЕ ПАРТПРОГРАММЫ "
 "
 " СЛЕДУЮТ ДВЕ ПОДПРОГРАММЫ
 "
 " ПОДПРОГРАММА НОМЕР 100 "
 "
 N500 G79 L100 " ПЕРВЫЙ БЛОК ПОДПРОГРАММЫ НОМЕР 100 "
 N510 G91 X10
 N590 G90 G70 " ПОСЛЕДНИЙ БЛОК ПОДПРОГРАММЫ НОМЕР 100 "
 "
 " ПОДПРОГРАММА НОМЕР 200 "
 "
 N600 G79 L200 " ПЕРВЫЙ БЛОК ПОДПРОГРАММЫ НОМЕР 200 "
 N610 Y50
 N700 G70 " ПОСЛЕДНИЙ БЛОК ПОДПРОГРАММЫ НОМЕР 200 "
 * " ЗВЕЗДОЧКА – ФИЗИЧЕСКИЙ КОНЕЦ ПАРТПРОГРАММЫ"
