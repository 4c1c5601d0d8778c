; system-value-usb: USB is 0 or 1 (§2.4.4 L1466, Table 3.3 L11267; decision 16): an E
; parameter holding 2 is a run-time error (NC4048) at line 7; the message before it shows.
E1=0
USB=E1
(DIS,USB)
E1=2
USB=E1
