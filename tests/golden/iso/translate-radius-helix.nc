(translate-radius-helix: a helix into pp is written in its helix mode G09 with its pitch K; an arc by R after a computed move has no known start)
G17 G90 G00 X10. Y0. Z0.
G03 X-10. Y0. Z-2. R10. F100.
G02 X10. Y0. Z-2. R10.
#1=5.
G01 X#1
G02 X-5. Y0. R5.
M30
