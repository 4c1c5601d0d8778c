// The partprogram (pp) dialect: the tokens of the program-start line and of one block.
//
// The tape reader (compiler/frontend/pp/reader.cpp) skips the leader before '%', hands
// the program-start line here, then cuts the rest into blocks: a block runs from its
// N to the next N outside a comment (lines are not blocks, §2.2.1 d), and '*' ends
// the program text. Bytes outside 7-bit ASCII reach the lexer as U+0001, which only a
// comment accepts; comment text is taken from the original bytes.
lexer grammar PpLexer;

// §2.2.1 c: any characters but '"' between quotes; the end of the line closes a
// comment whose second quote is missing.
COMMENT      : '"' ~["\r\n]* '"' ;
OPEN_COMMENT : '"' ~["\r\n]* ;

// A word is its address, any spaces, and its value (§2.1.2 f: spaces may stand
// between them, never inside the value). A value is read greedily, so `X1004.50` is
// X = 1004.50, while `4.50` at the start of a word is axis 4. = 50 (WORD is tried
// before NUMBER on a tie).
BLOCK_NUMBER : 'N' [ \t]* VALUE ;
PARAMETER    : 'R' DIGITS ( [ \t]* VALUE )? ;   // R<n> <value> (decision 9)
LINK         : '&' [ \t]* VALUE ;               // length-compensation link (decision 12)
WORD         : ADDRESS [ \t]* VALUE ;
BLOCK_SKIP   : '/' [0-9]* ;                     // §2.2.1 i: digits after it are not read
PERCENT      : '%' ;
// What is left of a damaged word: an address without its value, a sign or a number
// without an address (`X-  36.12`, `X36.  12`).
BARE_ADDRESS : ADDRESS | 'N' | 'R' | '&' ;
SIGN         : [+-] ;
NUMBER       : NUM ;

NEWLINE      : ( '\r' '\n'? | '\n' ) -> channel(HIDDEN) ;
SPACE        : [ \t]+ -> channel(HIDDEN) ;
// Lower-case letters, '*' inside a block, '=', '(', Cyrillic... outside a comment.
INVALID      : . ;

fragment ADDRESS : [A-MOP-QS-Z] | [456] '.' ;
fragment VALUE   : [+-]? ( NUM | 'R' DIGITS ) ;
fragment NUM     : DIGITS ( '.' DIGITS? )? | '.' DIGITS ;
fragment DIGITS  : [0-9]+ ;
