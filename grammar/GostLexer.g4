// GOST 20999-83 (ST SEV 3585-82) word-address coding: the tokens of one block.
//
// The tape reader (compiler/frontend/gost/gost_frontend.cpp) splits the medium into lines at
// LF, skips the leader before '%', and hands the program-start line and each block
// here one at a time. Bytes outside 7-bit ASCII reach the lexer as U+0001, which is
// INVALID outside a comment; comment text is taken from the original bytes.
lexer grammar GostLexer;

// '(' switches processing off, ')' back on (§1.5, Table 2). Inside, every character
// is text; '%' and ':' are forbidden there, which the front end reports.
COMMENT      : '(' ~[)\n]* ')' ;
// A comment not closed before the end of the block (LF).
OPEN_COMMENT : '(' ~[)\n]* ;
RPAREN       : ')' ;

PERCENT      : '%' ;   // program start (Table 2)
SLASH        : '/' ;   // block skip (§2.7)
COLON        : ':' ;   // main block (§2.6)
N            : 'N' ;   // block number address (§3.3.1)
LETTER       : [A-MO-Z] ;   // the other addresses of Table 1
PLUS         : '+' ;
MINUS        : '-' ;
POINT        : '.' ;   // decimal sign
DIGITS       : [0-9]+ ;

// SP, HT, CR, NUL and DEL are not perceived by the NC (Table 2 note 2, S-1.4):
// `X 1030.` reads as `X1030.`.
IGNORED      : [ \t\r\u0000\u007F]+ -> channel(HIDDEN) ;

// Anything else outside a comment: lower-case letters, '*', '=', '#', Cyrillic...
INVALID      : . ;
