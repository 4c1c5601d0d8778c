; PROG1: the program §1.2.31 calls with N35 (CLS,PROG1) (seed L818-826); not in
; the corpus, so this body is supplied: a message and a rapid move to X35.
(DIS,"PROG1 RUNS")
G X35
