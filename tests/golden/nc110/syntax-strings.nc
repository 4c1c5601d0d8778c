; syntax-strings: '"' is the only text delimiter (Table 2.1, seed L1413); there is no
; escape, and a text lies within one block. An unclosed text is NC1025, reported from
; the opening '"' to the end of the block.
; in an assignment (L5074 with its closing quote lost): column 9
SK7.3CH="RIF
; a label not closed: column 1
"START E1=1
; a stray '"' after an assignment: column 6
E1=1 "
