// The ISO/Fanuc (iso) dialect: one block (the spec's §2 syntax, seed §8 and §8.34).
//
// Rules the front end checks on the tree, each with its own diagnostic: what each
// address accepts (constants, variables, expressions; G and M numbers), a condition
// with a comparison (E-34), a DO/END index 1..3 (E-36), a GOTO target written as a
// whole number, the `,C`/`,R` suffix on a feed move (E-03), an O header alone in its
// block.
parser grammar IsoParser;
options { tokenVocab = IsoLexer; }

// A leading '/' skips the block when the block-skip switch is on; N numbers it. An O
// number alone is the header of a subprogram or macro.
block       : SLASH? SEQUENCE? body? EOF
            | PROGRAM EOF
            ;
body        : assignment
            | gotoStmt
            | ifStmt
            | braceHead
            | whileStmt
            | endStmt
            | words
            ;

assignment  : variable ASSIGN expr ;
gotoStmt    : GOTO target=value ;
// `IF [c] GOTO n`, `IF [c] THEN ...` (THEN optional, §8.34.2).
ifStmt      : IF LBRACKET expr RBRACKET ( gotoStmt | THEN? ( assignment | words ) ) ;
// The head of a multi-line IF: a '{' follows it (the reader sees to that).
braceHead   : ( IF | ELIF ) LBRACKET expr RBRACKET | ELSE ;
whileStmt   : ( WHILE LBRACKET expr RBRACKET )? DO NUMBER ;
endStmt     : END NUMBER ;

// Words may follow the ,C or ,R of a corner (`G01 X10 ,R2 F100`: decision 75).
words       : word+ ( COMMA LETTER value word* )? ;
word        : LETTER value ;
// A value: a number, a variable or a bracketed expression, with an optional sign
// (`X-#1`, `B-14.2`); a function call stands for itself (`X SIN[30]` is not ISO,
// but `X[SIN[30]]` is).
value       : ( PLUS | MINUS )? ( NUMBER | variable | LBRACKET expr RBRACKET ) ;
variable    : HASH ( NUMBER | LBRACKET expr RBRACKET ) ;

// Precedence, loosest first: OR XOR, AND, comparisons, + -, * / MOD, sign. The seed
// reads `#1 LE #2 AND #2 GT 45` as (#1 <= #2) AND (#2 > 45) (decision 6).
expr        : andExpr ( ( OR | XOR ) andExpr )* ;
andExpr     : compare ( AND compare )* ;
compare     : sum ( ( EQ | NE | GT | GE | LT | LE ) sum )? ;
sum         : term ( ( PLUS | MINUS ) term )* ;
term        : factor ( ( STAR | SLASH | MOD ) factor )* ;
factor      : ( PLUS | MINUS ) factor | primary ;
primary     : NUMBER                                                         # numberPrimary
            | variable                                                       # variablePrimary
            | LBRACKET expr RBRACKET                                         # groupPrimary
            // ATAN[a]/[b] is the two-argument arctangent (decision 7).
            | FUNCTION LBRACKET expr RBRACKET ( SLASH LBRACKET expr RBRACKET )? # callPrimary
            ;
