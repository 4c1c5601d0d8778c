#!/usr/bin/env python3
"""The speed and memory of `ncc translate` on large generated programs.

    bench/translate.py [--ncc build/compiler/ncc] [--plain N] [--targets iso,linuxcnc,pp,nc110,gost]
                       [--structured]

For each source dialect, a program of N plain blocks (bench/gen.py, default 10^6) is
compiled (`ncc compile`, the reference) and flattened to each target (with
--structured: translated structured); the table gives
wall time, blocks per second and peak RSS of each, and the translation's RSS over the
compile's (the issue's bound: no more than compiling it). Python 3 standard library.
"""
import argparse
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import compare  # noqa: E402
import gen  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ncc", default=str(HERE.parent / "build" / "compiler" / "ncc"))
    ap.add_argument("--plain", type=int, default=1_000_000)
    ap.add_argument("--dialects", default="gost,nc110,pp,iso")
    ap.add_argument("--targets", default="iso,linuxcnc,pp,nc110,gost")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--structured", action="store_true")
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as d:
        out = Path(d)
        sizes = dict(gen.DEFAULTS, plain=args.plain)
        entries = gen.generate(out, sizes, args.dialects.split(","), ["plain"])
        for e in entries:
            if e["dialect"] == "ngc":
                continue
            dialect, program = e["dialect"], e["path"]
            opts = ["--dialect", dialect] + compare.MACHINE.get(dialect, [])
            ref = compare.measure([args.ncc, "compile"] + opts + [str(program), "-o", str(out / "p.ncb")], args.repeat)
            rows.append([f"{dialect} compile", compare.fmt_s(ref), compare.fmt_rate(args.plain / ref.wall),
                         f"{compare.mb(ref.rss):.1f} MB", "1.00"])
            for target in args.targets.split(","):
                mode = [] if args.structured else ["--flatten"]
                r = compare.measure([args.ncc, "translate"] + opts + ["--to", target] + mode + [str(program),
                                                                     "-o", str(out / f"t.{target}")], args.repeat)
                if r.rc != 0:
                    rows.append([f"{dialect} -> {target}", "failed: " + r.first_error(), "", "", ""])
                    continue
                rows.append([f"{dialect} -> {target}", compare.fmt_s(r), compare.fmt_rate(args.plain / r.wall),
                             f"{compare.mb(r.rss):.1f} MB", f"{r.rss / ref.rss:.2f}"])
    print("\n".join(compare.table(["run", "wall s", "blocks/s", "peak RSS", "RSS / compile"], rows)))


if __name__ == "__main__":
    main()
