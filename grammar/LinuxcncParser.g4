// The linuxcnc dialect: one line (LinuxCNC 2.9, gcode/overview.html and o-code.html).
//
// What the front end checks on the tree, each with its own diagnostic: the keyword of
// an o-word and what it takes, the parameter numbers (1-5602), the codes.
parser grammar LinuxcncParser;
options { tokenVocab = LinuxcncLexer; }

// A leading '/' skips the line when block delete is on; N numbers it.
block     : SLASH? SEQUENCE? ( oword | item* ) EOF ;
// `o100 sub`, `o<name> call [1] [2]`, `o101 if [#1 GT 2]`, `o101 return [#2]`; `O1000`
// alone starts a Fanuc-style program that M98 calls.
oword     : OWORD keyword? ( LBRACKET expr RBRACKET )* ;
keyword   : SUB | ENDSUB | RETURN | CALL | IF | ELSEIF | ELSE | ENDIF | WHILE | ENDWHILE | DO | REPEAT
          | ENDREPEAT | BREAK | CONTINUE ;
item      : assignment | word ;
// A parameter set on a line takes its value when the whole line has been read.
assignment : variable ASSIGN value ;
word      : LETTER value ;
// A value: a number, a parameter, a bracketed expression or a function, with a sign.
value     : ( PLUS | MINUS )? ( NUMBER | variable | LBRACKET expr RBRACKET | call ) ;
variable  : NAMED | HASH ( NUMBER | variable | LBRACKET expr RBRACKET ) ;
call      : FUNCTION LBRACKET expr RBRACKET
          | ATAN LBRACKET expr RBRACKET SLASH LBRACKET expr RBRACKET
          | EXISTS LBRACKET variable RBRACKET ;

// Precedence, loosest first (LinuxCNC's): AND OR XOR; comparisons; + -; * / MOD; **;
// each level left to right; a sign binds tightest (`-2**2` is 4).
expr      : compare ( ( AND | OR | XOR ) compare )* ;
compare   : sum ( ( EQ | NE | GT | GE | LT | LE ) sum )* ;
sum       : term ( ( PLUS | MINUS ) term )* ;
term      : power ( ( STAR | SLASH | MOD ) power )* ;
power     : factor ( POWER factor )* ;
factor    : ( PLUS | MINUS ) factor | NUMBER | variable | LBRACKET expr RBRACKET | call ;
