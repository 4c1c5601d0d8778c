#!/usr/bin/env python3
"""A sandbox whose MP1 holds BIG.nca, a sparse file of 1 TiB (issue 17): no
well-formed ASSET file is larger than 17,825,306 bytes, so the store refuses it by
its size, before it would read it (which aborted 'ncc files check')."""
import os
import sys
from pathlib import Path

sandbox = Path(sys.argv[1]) / "sandbox"
for d in range(7):
    (sandbox / f"MP{d}").mkdir(parents=True)
with open(sandbox / "MP1" / "BIG.nca", "wb") as f:
    f.truncate(1 << 40)
