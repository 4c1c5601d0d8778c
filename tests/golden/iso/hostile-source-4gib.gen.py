#!/usr/bin/env python3
"""A source of 4 GiB and 11 bytes, sparse (issue 17): a block at the start and one
past 2^32. Taken modulo 2^32, the line starts of the second block would point into
the first: ncc refuses the file, by its size, before it reads a byte of it."""
import sys
from pathlib import Path

with open(Path(sys.argv[1]) / "big.nc", "wb") as f:
    f.write(b"G01 X1\n")
    f.seek(1 << 32)
    f.write(b"G01 X2\nM30\n")
