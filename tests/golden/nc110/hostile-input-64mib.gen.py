#!/usr/bin/env python3
"""An input script (--input) that is a sparse file one byte over 64 MiB (a line an
answer): refused by its size before it is read."""
import sys
from pathlib import Path

with open(Path(sys.argv[1]) / "big.input", "wb") as f:
    f.truncate((64 << 20) + 1)
