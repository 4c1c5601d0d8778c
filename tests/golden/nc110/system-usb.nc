; system-usb: a block starting with '/' runs only while USB = 1; with USB = 0 it is
; treated as a comment (§2.4.4 seed L1465-1473, Table 3.3 L11267). USB starts at 1, or
; at 0 when the machine's block_skip switch is on (decision 16; variants .skip with
; profiles/lang-block-skip.toml and .cli with --block-skip). A program sets it in an
; assignment block; a label on a '/' block stays a jump target (USB = 0: the run goes on).
(DIS,USB)
/G0 X1
USB=0
/G0 X2
/"L1" E1=5
(DIS,E1)
USB=1
/G0 X3
; a '/' block may set USB itself: USB = 0 from here on, X4 is not reached
E2=0
/USB=E2
/G0 X4
(BNC,L9)
G0 X99
/"L9" G0 X9
(DIS,"AFTER L9, USB=",USB)
