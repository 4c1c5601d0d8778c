; P800 on device MP2: the program §2.13.2.2 calls with (CLS,P800/MP2) (seed L8438,
; corpus 2.13.2.2-CLS-example-1). The manual gives no body; this one is supplied:
; a message and a rapid move to X80, then the end of the file returns.
N500 (DIS,"P800 ON MP2")
N501 G X80 Y0
