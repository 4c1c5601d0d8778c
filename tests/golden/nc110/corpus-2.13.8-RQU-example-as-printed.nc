; NC-110 §2.13.8 (seed line 9814) as printed, with ';' between the increments: a
; comment starts only a block (§2.5), so the ';' is refused where it stands.
(RQU, 10, 1, ZE40; KE41)
