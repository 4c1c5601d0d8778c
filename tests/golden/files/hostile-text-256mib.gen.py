#!/usr/bin/env python3
"""A text of ASSET files (ncc files load) that is a sparse file one byte over 256 MiB
(the text of the largest files is about 70 MB each): refused by its size before it is
read, and nothing is written."""
import sys
from pathlib import Path

with open(Path(sys.argv[1]) / "big.txt", "wb") as f:
    f.truncate((256 << 20) + 1)
