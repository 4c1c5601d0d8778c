// NC-110 (NC-110/NC-2xx/NC-3xx): the tokens of one block.
//
// The front end (compiler/frontend/nc110/) reads a file line by line and tells the
// four block types apart before lexing (§2.5): a ';' first is a comment block, a '('
// after the leading fields a three-letter-code block, an '=' an assignment block,
// anything else an ISO block. It starts the lexer in that block's mode, because the
// same characters mean different things in each: `XYM 30` is three words of an ISO
// block, `TIM1` a name and `SK7.3CH` one reference in an assignment, `P800/MP2` a
// program on a device in a code. Blanks are insignificant between tokens (§2.4.3
// examples: `G 72`, `X E31`, `ZE 35`, `"INIZIO" N 125`).
lexer grammar Nc110Lexer;

tokens { RELOP }

// ---- ISO block (the default mode): one-letter addresses (§2.4.2, §2.7) ----------

// The leading fields (§2.4.4), in every mode.
SLASH        : '/' ;                      // block skip; division in expressions
STRING       : '"' ~["\r\n]* '"' ;        // a label definition, a text operand
OPEN_STRING  : '"' ~["\r\n]* ;            // a text the line ends inside
HASH         : '#' ;                      // synchronisation request (§2.16)
AMP          : '&' ;                      // synchronisation cancelled (§2.16)
BLOCK_NUMBER : 'N' [ \t]* [0-9]+ ;

// An E parameter as a value (`XE32`, `GE1`) or alone (the result of G72-G74).
EREF         : 'E' [ \t]* [0-9]+ ;
// Tool and corrector, each digits or an E parameter (§2.7.7, Table 2.9): T1.1, T6,
// T.5, TE14.E15, T1.E15. The front end splits it.
TOOL         : 'T' [ \t]* ([0-9]+ | 'E' [ \t]* [0-9]+)? ('.' ([0-9]+ | 'E' [ \t]* [0-9]+)?)? ;
LETTER       : [A-Za-z] ;
NUMBER       : [0-9]+ ('.' [0-9]*)? | '.' [0-9]+ ;
PLUS         : '+' ;
MINUS        : '-' ;
BLANK        : [ \t]+ -> channel(HIDDEN) ;
// Cyrillic look-alikes of Latin letters are common in copied programs (`Е30`).
CYRILLIC     : [\u0400-\u04FF] ;
INVALID      : . ;

// ---- Assignment block (§2.12, §2.10): names, references, expressions --------------
mode ASSIGN;

A_SLASH        : '/' -> type(SLASH) ;
A_STRING       : '"' ~["\r\n]* '"' -> type(STRING) ;
A_OPEN_STRING  : '"' ~["\r\n]* -> type(OPEN_STRING) ;
A_HASH         : '#' -> type(HASH) ;
A_AMP          : '&' -> type(AMP) ;
A_BLOCK_NUMBER : 'N' [ \t]* [0-9]+ -> type(BLOCK_NUMBER) ;
A_EREF         : 'E' [ \t]* [0-9]+ -> type(EREF) ;
// A PLC packet or the SYVAR area: index, then '.', a count and a format (§2.10.5):
// SA12, SK.BL, SK7.3CH, SYVAR 1.4CH. The front end checks the format letters.
VARREF         : ('SA' | 'SK' | 'SYVAR') ([ \t]* [0-9]+)? ([ \t]* '.' [ \t]* [0-9]* [ \t]* [A-Z] [A-Z])? ;
NAME           : [A-Za-z]+ ;              // TMR, SIN, TIM (then its number)
A_NUMBER       : ([0-9]+ ('.' [0-9]*)? | '.' [0-9]+) -> type(NUMBER) ;
A_PLUS         : '+' -> type(PLUS) ;
A_MINUS        : '-' -> type(MINUS) ;
STAR           : '*' ;
EQUALS         : '=' ;
LPAREN         : '(' ;
RPAREN         : ')' ;
COMMA          : ',' ;
A_BLANK        : [ \t]+ -> channel(HIDDEN) ;
A_CYRILLIC     : [\u0400-\u04FF] -> type(CYRILLIC) ;
A_INVALID      : . -> type(INVALID) ;

// ---- GTL definition (§2.11.3): `l1 = X70 Y40, a150`, `c6=o1I-38J-35r10`, `p1=-l4,c3,s2`
mode GTL;

G_SLASH        : '/' -> type(SLASH) ;
G_STRING       : '"' ~["\r\n]* '"' -> type(STRING) ;
G_OPEN_STRING  : '"' ~["\r\n]* -> type(OPEN_STRING) ;
G_HASH         : '#' -> type(HASH) ;
G_AMP          : '&' -> type(AMP) ;
G_BLOCK_NUMBER : 'N' [ \t]* [0-9]+ -> type(BLOCK_NUMBER) ;
G_EREF         : 'E' [ \t]* [0-9]+ -> type(EREF) ;
G_LETTER       : [A-Za-z] -> type(LETTER) ;
G_NUMBER       : ([0-9]+ ('.' [0-9]*)? | '.' [0-9]+) -> type(NUMBER) ;
G_PLUS         : '+' -> type(PLUS) ;
G_MINUS        : '-' -> type(MINUS) ;
G_EQUALS       : '=' -> type(EQUALS) ;
G_COMMA        : ',' -> type(COMMA) ;
G_BLANK        : [ \t]+ -> channel(HIDDEN) ;
G_CYRILLIC     : [\u0400-\u04FF] -> type(CYRILLIC) ;
G_INVALID      : . -> type(INVALID) ;

// ---- Three-letter-code block (§2.13): the leading fields, then '(' ----------------
mode TLC;

T_SLASH        : '/' -> type(SLASH) ;
T_STRING       : '"' ~["\r\n]* '"' -> type(STRING) ;
T_OPEN_STRING  : '"' ~["\r\n]* -> type(OPEN_STRING) ;
T_HASH         : '#' -> type(HASH) ;
T_AMP          : '&' -> type(AMP) ;
T_BLOCK_NUMBER : 'N' [ \t]* [0-9]+ -> type(BLOCK_NUMBER) ;
T_LPAREN       : '(' -> type(LPAREN), pushMode(OPERANDS) ;
T_BLANK        : [ \t]+ -> channel(HIDDEN) ;
T_CYRILLIC     : [\u0400-\u04FF] -> type(CYRILLIC) ;
T_INVALID      : . -> type(INVALID) ;

// The code and its operands. An operand is kept as its pieces: what they mean
// depends on the code and the position (stdlib/dialects/nc110/three_letter_codes.tsv),
// so the front end reads them: `X-300 X300` is an axis pair, `START` a label, `XC`
// two axis names, `P800/MP2` a program.
mode OPERANDS;

O_LETTER       : [A-Za-z\u0400-\u04FF] -> type(LETTER) ;
O_STAR         : '*' -> type(STAR) ;           // an expression: not an operand
O_RELOP        : [=<>#] -> type(RELOP) ;       // a WAI condition (§4.1.3); elsewhere not an operand
DIGITS         : [0-9]+ ;
DOT            : '.' ;
O_PLUS         : '+' -> type(PLUS) ;
O_MINUS        : '-' -> type(MINUS) ;
O_SLASH        : '/' -> type(SLASH) ;
O_STRING       : '"' ~["\r\n]* '"' -> type(STRING) ;
O_OPEN_STRING  : '"' ~["\r\n]* -> type(OPEN_STRING) ;
O_COMMA        : ',' -> type(COMMA) ;
O_RPAREN       : ')' -> type(RPAREN), mode(AFTER_CODE) ;
O_BLANK        : [ \t]+ -> channel(HIDDEN) ;
O_INVALID      : . -> type(INVALID) ;

// After the code's ')': the block has ended; anything here is a second instruction.
mode AFTER_CODE;

TRAILING       : ~[ \t\r\n] ~[\r\n]* ;
AC_BLANK       : [ \t]+ -> channel(HIDDEN) ;
