; syntax-comments: a comment block is one whose first character is ';' (§2.5, seed
; L1509-1519; decision 5). It is neither executed nor shown: no trace event.
;ЭТО – ПРИМЕР
;E1=5
;(DIS,"NOT SHOWN")
;G0 X99
   ; blanks before the ';' are not part of the block: still a comment
;
; E1 is still 0: message E1=0; the only motion is the rapid to X1
(DIS,E1)
G0 X1
; a ';' inside a quoted text is text: message A;B
(DIS,"A;B")
