diag-run: ncc run reports warnings and goes on, and stops at the first run-time error (NC4019, NC4025, NC4003)
%
N1 G01 X10 Y0 F100 T7 (NC4019 - a warning, the run goes on)
N2 X20 I5 (NC4025 - a warning, the run goes on)
N3 G03 X-10 Y0 I-10 (NC4003 - start radius 10, end radius 20 - the run stops here)
N4 G01 X0 (not run)
N5 M30
