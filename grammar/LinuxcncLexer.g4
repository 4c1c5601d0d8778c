// The linuxcnc dialect (RS274NGC as LinuxCNC 2.9 reads it): the tokens of one line.
//
// The reader (compiler/frontend/linuxcnc/reader.cpp) takes the comments out ('( )'
// and ';' to the end of the line), upper-cases the rest and removes every blank, as
// LinuxCNC does: `G 0 1` is G01, `#<my var>` is `#<MYVAR>`. Keywords are safe to
// match anywhere: a word's letter always has its value right after it, so a keyword
// never hides one.
lexer grammar LinuxcncLexer;

// o-word keywords.
SUB       : 'SUB' ;
ENDSUB    : 'ENDSUB' ;
RETURN    : 'RETURN' ;
CALL      : 'CALL' ;
IF        : 'IF' ;
ELSEIF    : 'ELSEIF' ;
ELSE      : 'ELSE' ;
ENDIF     : 'ENDIF' ;
WHILE     : 'WHILE' ;
ENDWHILE  : 'ENDWHILE' ;
DO        : 'DO' ;
REPEAT    : 'REPEAT' ;
ENDREPEAT : 'ENDREPEAT' ;
BREAK     : 'BREAK' ;
CONTINUE  : 'CONTINUE' ;

// Binary operators: the logical ones, the comparisons, MOD and the power.
AND      : 'AND' ;
OR       : 'OR' ;
XOR      : 'XOR' ;
EQ       : 'EQ' ;
NE       : 'NE' ;
GT       : 'GT' ;
GE       : 'GE' ;
LT       : 'LT' ;
LE       : 'LE' ;
MOD      : 'MOD' ;
POWER    : '**' ;
ATAN     : 'ATAN' ;
EXISTS   : 'EXISTS' ;
FUNCTION : 'ABS' | 'ACOS' | 'ASIN' | 'COS' | 'EXP' | 'FIX' | 'FUP' | 'LN' | 'ROUND' | 'SIN'
         | 'SQRT' | 'TAN' ;

// N with its digits; an o-word: O and a number or a <name>.
SEQUENCE : 'N' DIGITS ( '.' DIGITS? )? ;
OWORD    : 'O' ( DIGITS | '<' ~[>]* '>' ) ;
// A named parameter: local #<name>, global #<_name>.
NAMED    : '#<' ~[>]* '>' ;
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

// Anything else outside a comment.
INVALID  : . ;

fragment DIGITS : [0-9]+ ;
