; corpus-1.2.17-rms-tapping-return-speed: copy of corpus/nc110/part1/
; 1.2.17-rms-tapping-return-speed.nc (§1.2.17 seed L592-593; §2.10.3 L5002-5025).
; Expect: RMS=110 sets the tapping return speed to 110 % of the programmed F (+10 %);
; RMS=10 to 10 % (-90 %). Changed: the manual's two blocks are kept as printed; a G84
; tapping cycle (decision 54) is added after each to show the return: at F200 the way out
; runs at F220; with K1.5 (spindle-synchronised) at S500 it runs at S50.
S500 M3
G0 X10 Y10 Z5
RMS=110
G84 R2 Z-10 F200
X20
G80
RMS=10
G84 R2 Z-10 K1.5
X30
G80
G0 Z50 M5
(DIS,RMS)
