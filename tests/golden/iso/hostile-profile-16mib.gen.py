#!/usr/bin/env python3
"""A machine profile that is a sparse file one byte over 16 MiB (profiles are a few
kilobytes): refused by its size before it is read."""
import sys
from pathlib import Path

with open(Path(sys.argv[1]) / "big.toml", "wb") as f:
    f.truncate((16 << 20) + 1)
