; Corpus copy of part2/2.8.1.7-G33-fig2.9c-decreasing-pitch.nc (seed §2.8.1.7, formula 2.1
; at L2629, Fig. 2.9 c): initial pitch 10, pitch change I-1 (decreasing), to Z-50.
; Added: the spindle (S100, M03), the start Z0 and the clock.
; The manual: (2.1) |I| <= K^2/(ZK-ZN) must hold so that the pitch never reaches 0:
; 1 < 100/50 = 2 holds (decision 42 reads it with magnitudes and strictly: |I| < K^2/L).
; Derived: end pitch 10 - 50/10 = 5; turns n = -10 ln(1 - 50/100) = 6.931472 at 100 rpm
; = 4.158883 s. The formula's limit is tested in threads-formula-2.1.
N1 S100 M3
N2 G0 Z0
N24 G33 Z-50 K10 I-1
; added: the clock
E25 = TIM0
(DIS,E25)
