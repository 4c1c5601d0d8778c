; Without --files there is no sandbox: ASSET is not configured, every I/O statement answers code
; 18 (table 5.2). ERR is 0 at power-on, so the run stops at the first one, located. DER is not an
; I/O statement: it goes by. `ncc check` (asset-no-sandbox.check) runs no ASSET statement: the
; files are the machine's, not the program's, and unknown before the run.
(DER, 1, E10)
(OPN, 1, ORIG/MP3)
(DIS, "NOT REACHED")
M30
