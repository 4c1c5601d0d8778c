// NC-110: the grammar of one block of each type (§2.4-§2.5). Comment blocks (';'
// first) are not parsed: all of them is text.
//
// Rules the front end checks on the parse tree, each with its own diagnostic: the
// order and form of the leading fields (§2.4.4); G words first and of two digits
// (§2.8); what each address accepts, and which class of E parameter (Table 2.9);
// the names of system variables (§2.10) and functions (§2.12); the operands of each
// three-letter code (§2.13, stdlib/dialects/nc110/three_letter_codes.tsv).
parser grammar Nc110Parser;
options { tokenVocab = Nc110Lexer; }

// `/` `"LABEL"` `N..` `#`|`&`, in that order (§2.4.4, §2.16); taken in any order here
// so that a misplaced one gets its own message.
leading     : field* ;
field       : SLASH | STRING | OPEN_STRING | BLOCK_NUMBER | HASH | AMP ;

// ---- ISO block ---------------------------------------------------------------------
isoBlock    : leading isoWord* EOF ;
isoWord     : TOOL                      # toolWord
            | LETTER wordValue?         # addressWord
            | EREF                      # resultWord
            ;
// A constant or one E parameter; nothing means zero (`G Z80 X80`, `I J`).
wordValue   : sign? NUMBER
            | sign? EREF
            ;
sign        : PLUS | MINUS ;

// ---- Assignment block --------------------------------------------------------------
assignBlock : leading target EQUALS value EOF ;
target      : EREF | VARREF | NAME NUMBER? ;
value       : expr | STRING | OPEN_STRING ;
// Usual precedence, left to right (§2.12: "the priority of brackets and signs").
expr        : term ((PLUS | MINUS) term)* ;
term        : factor ((STAR | SLASH) factor)* ;
factor      : (PLUS | MINUS)? primary ;
primary     : NUMBER                                     # numberPrimary
            | EREF                                       # parameterPrimary
            | VARREF                                     # memoryPrimary
            | NAME LPAREN expr (COMMA expr)? RPAREN      # callPrimary
            | NAME NUMBER?                               # systemPrimary
            | LPAREN expr RPAREN                         # groupPrimary
            ;

// ---- GTL definition (§2.11.3) -----------------------------------------------------
// The element and its index, '=', then its operands as words: the front end groups
// them (`X70 Y40`, `I45 J30 r-15`, `m55 a60`, `-l4`, `s2`) and checks the form.
gtlBlock    : leading LETTER wordValue? EQUALS gtlItem* EOF ;
gtlItem     : COMMA | MINUS? LETTER wordValue? ;

// ---- Three-letter-code block -------------------------------------------------------
tlcBlock    : leading LPAREN code (COMMA operand)* RPAREN EOF ;
code        : LETTER* ;
operand     : piece* ;
piece       : LETTER | DIGITS | DOT | PLUS | MINUS | SLASH | STAR | RELOP | STRING ;
