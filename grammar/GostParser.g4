// GOST 20999-83 word-address coding: the program-start line and one block.
//
// Rules the front end checks on the parse tree, each with its own diagnostic:
// the block number comes first (§2.1); ':' needs digits (§2.6); '/' carries no
// level (§2.7); a word has at least one digit (§3.1.5); signs, decimal points and
// digit counts follow the format descriptor (§9); comments hold no '%' or ':' (§1.5).
parser grammar GostParser;
options { tokenVocab = GostLexer; }

// '%', a second '%' when the first marks the physical start of the medium (§1.8),
// the program number (§1.6) and an optional comment.
programStart : PERCENT PERCENT? DIGITS* comment? EOF ;

// §2.1: [block number] {information word} LF. A '/' before the block number skips
// the whole block; a '/' inside the block skips the rest of it (Table 2, §2.7).
block        : element* EOF ;

element      : skip
             | blockNumber
             | word
             | comment
             | RPAREN
             ;

skip         : SLASH DIGITS? ;
blockNumber  : (N | COLON) sign? number ;
// §3.1.1: address, sign if needed, digits (with the decimal sign when the format
// has DS). Ignored characters may stand between the digits.
word         : LETTER sign? number ;
sign         : PLUS | MINUS ;
number       : DIGITS* (POINT DIGITS*)? ;
comment      : COMMENT | OPEN_COMMENT ;
