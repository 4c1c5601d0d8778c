#!/usr/bin/env python3
"""A sandbox whose device folder MP2 is a symbolic link to a folder outside it: the
store follows no link, so 'ncc files init' refuses it rather than leave a device the
runs cannot use."""
import os
import sys
from pathlib import Path

root = Path(sys.argv[1])
(root / "elsewhere").mkdir()
(root / "sandbox").mkdir()
for d in (0, 1, 3, 4, 5, 6):
    (root / "sandbox" / f"MP{d}").mkdir()
os.symlink(root / "elsewhere", root / "sandbox" / "MP2")
