; NC-110 §2.13.9, §2.15.1.1 (seed lines 9848-9865, 10113-10133): "DPT, 10, 12, 1000 -
; from the console"; "(DPT,10,12,1000) - from the program". The console's form is not
; a block: NC1001 says how a program writes it. Qa = 10, Qs = 12, Vm = 1000 mm/min.
DPT, 10, 12, 1000
(DPT,10,12,1000)
