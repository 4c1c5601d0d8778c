// The ISO/Fanuc (iso) dialect with Macro B: the tokens of one block.
//
// The reader (compiler/frontend/iso/reader.cpp) cuts the text into blocks at ';', at
// the end of a line and at the braces of a multi-line IF, takes the comments out and
// hands each block here in upper case (decision 2). Whitespace between tokens is not
// significant (`GOTO16`, `DO1`, `G 01`).
lexer grammar IsoLexer;

// Keywords are whole words: `GOTO` is not G = OTO, `DO1` is DO and 1 (a word address
// always has a value right after it, so a keyword never hides one).
IF     : 'IF' ;
THEN   : 'THEN' ;
GOTO   : 'GOTO' ;
ELIF   : 'ELIF' ;
ELSE   : 'ELSE' ;
WHILE  : 'WHILE' ;
DO     : 'DO' ;
END    : 'END' ;
AND    : 'AND' | '&' ;
OR     : 'OR' | '|' ;
XOR    : 'XOR' ;
MOD    : 'MOD' ;
EQ     : 'EQ' | '==' ;
NE     : 'NE' | '<>' ;
GT     : 'GT' | '>' ;
GE     : 'GE' | '>=' ;
LT     : 'LT' | '<' ;
LE     : 'LE' | '<=' ;
FUNCTION : 'ASIN' | 'SIN' | 'ACOS' | 'COS' | 'ATAN' | 'TAN' | 'SQRT' | 'ABS' | 'ROUND'
         | 'EXP' | 'LN' | 'FIX' | 'FUP' ;

// N and O with their digits: a block number and a program number (§8.33: OXXXX);
// ':' is ISO code's other program-number address (decision 53).
SEQUENCE : 'N' [ \t]* DIGITS ;
PROGRAM  : [O:] [ \t]* DIGITS ;
LETTER   : [A-Z] ;
NUMBER   : DIGITS ( '.' DIGITS? )? | '.' DIGITS ;
HASH     : '#' ;
LBRACKET : '[' ;
RBRACKET : ']' ;
PLUS     : '+' ;
MINUS    : '-' ;
STAR     : '*' ;
SLASH    : '/' ;
ASSIGN   : '=' ;
COMMA    : ',' ;
PERCENT  : '%' ;

SPACE    : [ \t\r]+ -> channel(HIDDEN) ;
// Anything else outside a comment: '(' has been taken out with its comment, so a
// ')' here has no '(' before it.
INVALID  : . ;

fragment DIGITS : [0-9]+ ;
