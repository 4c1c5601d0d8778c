; DTL while cutter radius compensation is active (NC-110 §2.13.5.2, seed lines 9417-9425:
; "DTL gives an error if G21, G41-G42 or G27-G28 is active"); decision 33 (G27/G28
; allowed), decision 32's NC4064 for G41/G42.
; Checks (ncc check): after G41, (DTL,X0.1) is NC4064 at the code, and the message
; names the tolerance (DTL changes no plane); after G40 it is allowed.
F100
G41 G1 X10
(DTL,X0.1)
G40 G0 X0
(DTL,X0.1)
