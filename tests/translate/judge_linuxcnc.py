#!/usr/bin/env python3
"""LinuxCNC judges `ncc translate --to linuxcnc` (docs/translate.md).

    judge_linuxcnc.py --ncc PATH/TO/ncc [--rs274 rs274]

Every program of the differential suite (tests/diff/linuxcnc/programs) is flattened
to LinuxCNC's RS274NGC. The translation must make the source's motion when ncc runs
it (equivalent.py), and LinuxCNC's own `rs274 -g` must make the same canonical calls
as ncc on it (tests/diff/linuxcnc/compare.py): so LinuxCNC runs the source's motion.
Python 3 standard library only.
"""
import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
SUITE = HERE.parent / "diff" / "linuxcnc"
sys.path.insert(0, str(HERE))
import equivalent  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ncc", required=True)
    ap.add_argument("--rs274", default="rs274")
    args = ap.parse_args()
    ncc = str(Path(args.ncc).resolve())
    machine = ["--dialect", "iso", "--machine", str(SUITE / "machine.toml")]
    failed = []
    with tempfile.TemporaryDirectory() as scratch:
        translated = Path(scratch) / "programs"
        translated.mkdir()
        for program in sorted((SUITE / "programs").glob("*.ngc")):
            if "(ncc-args:" in program.read_text():
                continue  # a machine of its own: the suite's defaults do not hold
            out = translated / f"translated_{program.name}"
            p = subprocess.run([ncc, "translate"] + machine + ["--to", "linuxcnc", "--flatten", str(program), "-o", str(out)],
                               capture_output=True, text=True)
            if p.returncode != 0:
                failed.append(f"{program.name}: translate: {p.stderr.strip()}")
                continue
            traces = []
            for source in (program, out):
                r = subprocess.run([ncc, "run"] + machine + ["--trace-frame", "machine", "--trace-format", "jsonl", str(source)],
                                   capture_output=True, text=True)
                traces.append(equivalent.parse(r.stdout.splitlines()) if r.returncode == 0 else None)
            if None in traces:
                failed.append(f"{program.name}: a run failed")
                continue
            differences = equivalent.compare(traces[0], traces[1], 1e-4)
            if differences:
                failed.append(f"{program.name}: ncc runs the translation differently: {differences[0]}")
        p = subprocess.run([sys.executable, str(SUITE / "compare.py"), "--ncc", ncc, "--rs274", args.rs274, str(translated)],
                           capture_output=True, text=True)
        print(p.stdout.strip().splitlines()[-1] if p.stdout.strip() else p.stderr.strip())
        if p.returncode != 0:
            failed.append("rs274 and ncc differ on translations:\n" + p.stdout)
    for f in failed:
        print("FAILED " + f)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
