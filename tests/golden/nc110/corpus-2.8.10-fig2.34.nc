; Corpus copy of part2/2.8.10-G90-G91-G79-fig2.34-example.nc (seed §2.8.10, L4266-4348,
; Fig. 2.34), run with profile motion-origin: origin 0 at machine X100 Y50.
; Changed: the manual's annotations after each block are dropped (they name the points:
; N1 the start, N2 point 1, N3 point 2 = point 1 + (50,25), N4 point 3 = point 2 +
; (-71,12), N5 point 4, N6 point 5 relative to machine zero). Added: N7 to N10.
; Expected (all rapids, N1's bare G = G00): N1 X0 Y0, N2 X30 Y40, N3 X80 Y65, N4 X9 Y77,
; N5 X110 Y35 (program coordinates). N6 G79 goes to machine X70 Y55, which the trace
; shows from origin 0: X-30 Y5 (decision 46). G79 is one-shot: N7 is G90 again (X20
; Y10).
N1 GXY
N2 X30 Y40
N3 G91 X50 Y25
N4 X-71 Y12
N5 G90 X110 Y35
N6 G79 X70 Y55
; added: G90 is back after G79
N7 X20 Y10
; added: under G91, G79 is still absolute machine coordinates (decision 46), and G91
; comes back after it: N9 machine X0 Y0 = X-100 Y-50 shown; N10 X5 incremental = X-95.
N8 G91 X5
N9 G79 X0 Y0
N10 X5
