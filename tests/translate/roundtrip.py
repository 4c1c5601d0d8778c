#!/usr/bin/env python3
"""Round trips of `ncc translate --flatten` (docs/translate.md).

    roundtrip.py --ncc PATH/TO/ncc

A program A is translated to B, B back to A's dialect, and that again to B: both B
texts must be the same, comments aside, for every pair of dialects ncc reads.
Python 3 standard library only.
"""
import argparse
import itertools
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from matrix import body  # noqa: E402

GOLDEN = HERE.parent / "golden" / "iso"
PROGRAMS = [("iso", GOLDEN / "translate-contour.nc"), ("iso", GOLDEN / "translate-tlo.nc")]
MACHINE = ["--machine", str(GOLDEN / "translate.toml")]
DIALECTS = ["iso", "pp", "nc110", "gost"]


def translate(ncc, source_dialect, target, program, out):
    p = subprocess.run([ncc, "translate", "--dialect", source_dialect] + MACHINE +
                       ["--to", target, "--flatten", str(program), "-o", str(out)], capture_output=True, text=True)
    return p.returncode, p.stderr.strip()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ncc", required=True)
    args = ap.parse_args()
    failed, done = [], 0
    with tempfile.TemporaryDirectory() as d:
        for (dialect, program), target in itertools.product(PROGRAMS, DIALECTS):
            if target == dialect:
                continue
            here = Path(d) / f"{program.stem}-{target}"
            here.mkdir()
            steps = [(dialect, target, program, here / "b1"), (target, dialect, here / "b1", here / "a2"),
                     (dialect, target, here / "a2", here / "b2")]
            for src, dst, inp, out in steps:
                rc, err = translate(args.ncc, src, dst, inp, out)
                if rc != 0:
                    break
            if rc == 1 and "[NC4096]" in err and not steps[0][3].exists():
                continue  # refused at the first step: the matrix says why
            if rc != 0:
                failed.append(f"{program.name} {dialect} -> {target} -> {dialect} -> {target}: {err}")
            elif body((here / "b1").read_text()) != body((here / "b2").read_text()):
                failed.append(f"{program.name} {dialect} -> {target} -> {dialect} -> {target}: the second {target} text differs")
            else:
                done += 1
    print(f"{done} round trips give the same text")
    for f in failed:
        print("FAILED " + f)
    return 1 if failed or done == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
