// The partprogram (pp) dialect: the program-start line and one block.
//
// Rules the front end checks on the tokens, each with its own diagnostic: the value
// of each address (sign, decimal point, digits, range, R parameter), the separator
// rules of R words, spaces inside a value, one '/' per block.
parser grammar PpParser;
options { tokenVocab = PpLexer; }

// §2.3.1: '%', the program number (spaces may stand between them, as between any
// address and its value) and an optional comment: the listing's title.
programStart : PERCENT NUMBER? comment* element* EOF ;

// §2.2.1 d: a block begins with its number; everything up to the next N is its (an
// N without digits is reported, and its block read all the same).
block        : number=(BLOCK_NUMBER | BARE_ADDRESS) element* EOF ;

element      : WORD | PARAMETER | LINK | BLOCK_SKIP | comment | damaged ;
damaged      : BARE_ADDRESS | SIGN | NUMBER | PERCENT | BLOCK_NUMBER | INVALID ;
comment      : COMMENT | OPEN_COMMENT ;
