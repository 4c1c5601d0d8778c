#!/usr/bin/env python3
"""A stand-in for ncc that runs rs274 instead, to test compare.py itself:

    compare.py --ncc tests/diff/linuxcnc/rs274_as_ncc.py programs/

Every program must pass: both sides are rs274, but this side goes through ncc's
path in compare.py (its command line, its output parsing, its normalisation). It
takes ncc's `run ... FILE` arguments, ignores all but FILE, and prints rs274's raw
output (sequence and N columns and start-up preamble included).
"""

import sys
from pathlib import Path

sys.dont_write_bytecode = True          # no __pycache__ in the source tree
sys.path.insert(0, str(Path(__file__).resolve().parent))
import compare  # noqa: E402

program = Path(sys.argv[-1])
ok, out, err = compare.run_rs274("rs274", program, compare.directives(program)["rs274-args"])
sys.stdout.write(out)
sys.stderr.write(err)
sys.exit(0 if ok else 1)
