; Copy of corpus part1/1.2.17-rms-tapping-return-speed.nc (NC-110 §1.2.17, seed lines
; 588-593; §2.10.3, seed lines 5002-5016): "RMS=110 (+10 % of the programmed F)",
; "RMS=10 (-90 % of the programmed F)". The manual's parenthesised explanations are
; moved here. Added around the two RMS blocks: a G84 tapping at F (profile cycle-mill,
; with encoder but no K) so the return speed shows; RMS=E3 with a BY parameter.
; Checks (decision 54): hole X10 under RMS=110: feed F200 to -10, spindle ccw,
; feed_rate 220, feed back to R5, feed_rate 200, spindle cw; hole X20 under RMS=10:
; feed_rate 20 on the way out; hole X30 under RMS=E3 (E3 = 50): feed_rate 100.
N1 S500 F200 T8.8 M6 M3
N2 G84 R5 Z-10
RMS=110
N4 X10
RMS=10
N6 X20
N7 E3=50
N8 RMS=E3
N9 X30
N10 G80 Z50 M5
