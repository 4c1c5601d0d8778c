; corpus-1.2.30-assignment-blocks-example-2: corrected copy of corpus/nc110/part1/
; 1.2.30-assignment-blocks-example-2.nc (§1.2.30 seed L802-806; Table 1.2 L745-761).
; Expect: E51 = -0.00000124 + 5 = 4.99999876 (label LAB1); E7 = 81 (byte); E10 = 1
; (integer); E25 = previous E25 + 30 = 30 (real; E parameters start at 0).
; Corrected: the printed line 802 merges two blocks and puts a blank in the label:
; "LAB 1" E51 = -0.00000124 +5/E35 = FEL(37,1). §2.12 prints them as two blocks with
; "LAB1" (L7727, L7733), as here (the as-printed line: corpus-1.2.30-as-printed.nc).
; DIS blocks added. The '/' block reads the GTL line l37, which no block defines
; (decision 71): with USB = 1 (the default) the run stops there with NC4050; with
; the block-skip switch on (variant .skip, USB = 0) it is skipped and all values show.
"LAB1" E51 = -0.00000124 +5
(DIS,E51)
/E35 = FEL(37,1)
E7 = 81
E10 = 1
E25 = E25 + 30
(DIS,E7)
(DIS,E10)
(DIS,E25)
