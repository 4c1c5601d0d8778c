#!/usr/bin/env python3
"""A program that calls O2000 from a library where O2000.nc is a sparse file one byte
over 256 MiB: a called program's IR is held whole, so ncc reads none larger; the
error stands at the call."""
import sys
from pathlib import Path

out = Path(sys.argv[1])
(out / "main.nc").write_text("G90 G01 X0 Y0 Z0 F100;\nM98 P2000;\nM30;\n")
with open(out / "O2000.nc", "wb") as f:
    f.truncate((256 << 20) + 1)
