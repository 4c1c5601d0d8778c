; NC-110 §2.10.3 (RMS 0..255, seed lines 5002-5016), decision 54: RMS=0 is a legal
; setting, but a tap cannot come out at 0 % speed: the G84 hole at line 8 is refused
; (NC4068, 8:1) when its return would run at RMS 0, before it taps: the message says that
; RMS is 0 % at the return (set it to 1..255), not that it "cannot be set to 0" (line 7).
N1 S400 F450 M3
N2 G84 R5 Z-20
N3 RMS=0
N4 X10
N5 G80
