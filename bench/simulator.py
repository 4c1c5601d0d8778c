#!/usr/bin/env python3
"""The simulator's speed: `ncc plot`, `ncc view` and `ncc run --time` on generated
programs, beside `ncc run --trace none` (the run they all start from).

    bench/simulator.py [--quick] [--ncc PATH] [--repeat N] [--plain N] [--arcs N]

Generates bench/gen.py's ISO programs (10^6 plain blocks, 200,000 arc blocks; --quick:
20,000 and 5,000), then measures each command once a program (best of --repeat): wall
time, moves per second (the trace's moves: one a block), peak RSS and the size of what
it writes. The anchor is LinuxCNC's C++ preview builder, 1,000,149 moves in 0.73 s
(1.37 M moves/s): reported, never asserted. Python 3 standard library only; the
measuring is bench/compare.py's.
"""

import argparse
import os
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import compare  # noqa: E402
import gen  # noqa: E402

ANCHOR_MOVES_PER_S = 1_000_149 / 0.73


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--ncc", default=str(HERE.parent / "build" / "compiler" / "ncc"))
    p.add_argument("--quick", action="store_true")
    p.add_argument("--repeat", type=int, default=1)
    p.add_argument("--plain", type=int)
    p.add_argument("--arcs", type=int)
    a = p.parse_args()
    plain = a.plain or (20_000 if a.quick else 1_000_000)
    arcs = a.arcs or (5_000 if a.quick else 200_000)
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)
        compare.log(f"generating {plain} plain and {arcs} arc blocks ...")
        gen.generate(str(work), {"plain": plain, "arcs": arcs}, ["iso"], ["plain", "arcs"], log=compare.log)
        rows = []
        for name, moves in (("iso-plain.nc", plain), ("iso-arcs.nc", arcs)):
            program = str(work / name)
            for what, args, out in (
                    ("run --trace none", ["run", program, "--trace", "none"], None),
                    ("run --time", ["run", program, "--time"], None),
                    ("plot", ["plot", program, "-o", str(work / "out.svg")], work / "out.svg"),
                    ("view", ["view", program, "-o", str(work / "out.html")], work / "out.html")):
                compare.log(f"{name}: ncc {what} ...")
                r = compare.measure([a.ncc, *args, "--dialect", "iso"], a.repeat)
                if not r.ok:
                    rows.append([name, what, "FAILED: " + r.first_error(), "", "", ""])
                    continue
                size = f"{os.path.getsize(out) / 1e6:.1f} MB" if out else ""
                rows.append([name, what, f"{r.wall:.2f} s", f"{moves / r.wall / 1e6:.2f} M/s",
                             f"{r.rss / 1e6:.0f} MB", size])
        print("\n".join(line for line in compare.machine_lines(a.ncc, "rs274") if not line.startswith("rs274")))
        print("\n".join(compare.table(["program", "ncc", "wall", "moves/s", "peak RSS", "output"], rows)))
        print(f"\nanchor: LinuxCNC's preview builder, {ANCHOR_MOVES_PER_S / 1e6:.2f} M moves/s")


if __name__ == "__main__":
    main()
