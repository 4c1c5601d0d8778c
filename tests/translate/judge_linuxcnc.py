#!/usr/bin/env python3
"""LinuxCNC judges `ncc translate --to linuxcnc` (docs/translate.md).

    judge_linuxcnc.py --ncc PATH/TO/ncc [--rs274 rs274]

Flattened: every program of the differential suite (tests/diff/linuxcnc/programs) is
flattened to LinuxCNC's RS274NGC. The translation must make the source's motion when
ncc runs it (equivalent.py), and LinuxCNC's own `rs274 -g` must make the same
canonical calls as ncc on it (tests/diff/linuxcnc/compare.py).

Structured (the default of ncc translate): the same programs, and the programs of
judge/ in the other dialects, are translated with their parameters, loops and
subprograms kept as o-words; `rs274 -g` runs the translation and must make the
canonical calls ncc makes running the source. A program ncc refuses to translate is
listed with the reason; the judge fails on a difference, or when fewer than
EXPECTED_STRUCTURED programs translate.
Python 3 standard library only.
"""
import argparse
import subprocess
import sys
import tempfile
from pathlib import Path
from types import SimpleNamespace

HERE = Path(__file__).resolve().parent
SUITE = HERE.parent / "diff" / "linuxcnc"
JUDGE = HERE / "judge"
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(SUITE))
import compare  # noqa: E402
import equivalent  # noqa: E402

# Programs in judge/ by extension: their dialect.
DIALECTS = {".nc": "nc110", ".pp": "pp", ".gost": "gost", ".iso": "iso"}
# Structured translations that must come through (all but the suite's G74, which
# LinuxCNC 2.9 lacks, and the M98 that shares #1-#33 with its subprogram).
EXPECTED_STRUCTURED = 84


def flattened(ncc, rs274, scratch, failed):
    machine = ["--dialect", "iso", "--machine", str(SUITE / "machine.toml")]
    translated = Path(scratch) / "flattened"
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
    p = subprocess.run([sys.executable, str(SUITE / "compare.py"), "--ncc", ncc, "--rs274", rs274, str(translated)],
                       capture_output=True, text=True)
    print("flattened: " + (p.stdout.strip().splitlines()[-1] if p.stdout.strip() else p.stderr.strip()))
    if p.returncode != 0:
        failed.append("rs274 and ncc differ on flattened translations:\n" + p.stdout)


def structured(ncc, rs274, scratch, failed):
    """(source, dialect, machine, rs274 options) of every structured case."""
    cases = []
    for program in sorted((SUITE / "programs").glob("*.ngc")):
        if "(ncc-args:" not in program.read_text():
            cases.append((program, "iso", SUITE / "machine.toml", []))
    for program in sorted(JUDGE.iterdir()):
        if program.suffix in DIALECTS:
            cases.append((program, DIALECTS[program.suffix], JUDGE / "machine.toml", ["-v", str(JUDGE / "zero.var")]))
    translated = Path(scratch) / "structured"
    translated.mkdir()
    opts = SimpleNamespace(ncc=ncc, rs274=rs274, update=False, show=False, ncc_arg=[], dialect="iso")
    passed, refused = 0, []
    for source, dialect, machine, rs274_args in cases:
        out = translated / (source.stem + ".ngc")
        p = subprocess.run([ncc, "translate", "--dialect", dialect, "--machine", str(machine), "--to", "linuxcnc",
                            str(source), "-o", str(out)], capture_output=True, text=True)
        if p.returncode != 0:
            refused.append(f"{source.name}: {p.stderr.strip().splitlines()[0] if p.stderr.strip() else p.returncode}")
            continue
        opts.ncc_arg = ["--machine", str(machine)]
        problems = compare.check(out, opts, source=source, dialect=dialect, rs274_args=rs274_args)
        if problems:
            failed.append(f"{source.name} (structured): " + "\n".join(problems))
        else:
            passed += 1
    print(f"structured: {passed} of {len(cases)} programs translated and judged the same; "
          f"{len(refused)} refused")
    for r in refused:
        print("  refused " + r)
    if passed + len([f for f in failed if "(structured)" in f]) < EXPECTED_STRUCTURED:
        failed.append(f"only {passed} structured translations (expected {EXPECTED_STRUCTURED})")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ncc", required=True)
    ap.add_argument("--rs274", default="rs274")
    args = ap.parse_args()
    ncc = str(Path(args.ncc).resolve())
    failed = []
    with tempfile.TemporaryDirectory() as scratch:
        flattened(ncc, args.rs274, scratch, failed)
        structured(ncc, args.rs274, scratch, failed)
    for f in failed:
        print("FAILED " + f)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
