#!/usr/bin/env python3
"""Structure kept by `ncc translate` (docs/translate.md).

    structure.py --ncc PATH/TO/ncc

A loop of 10^5 iterations stays a loop: its translation to ISO, LinuxCNC, NC-110 and
(counted repeats) pp is at most a few times the source's size, and (into the
dialects ncc runs) makes the same motion. A subprogram called 50 times is written once, and called 50
times (into NC-110: a range of blocks EPP runs; NC-110's own CLS program stays the
library's file).
Python 3 standard library only.
"""
import argparse
import re
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import equivalent  # noqa: E402

N = 100000
LOOPS = {
    "iso": f"#1=0\nG01 X0 Y0 F1000\nWHILE [#1 LT {N}] DO1\n#1=#1+1\nG91 X0.001\nG90\nEND1\nM30\n",
    "nc110": f'E30=0\nG1 X0 Y0 F1000\n"TOP" E30=E30+1\nG91 X0.001\nG90\n(BLT,E30,{N},TOP)\nM30\n',
    # 50 x 50 x 40 = 10^5 repeats: the loops pp's counted G73 can say
    "nc110-rpt": "G1 X0 Y0 F1000\n(RPT,50)\n(RPT,50)\n(RPT,40)\nG91 X0.001\nG90\n(ERP)\n(ERP)\n(ERP)\nM30\n",
}
# The targets each loop is translated to: pp has no condition, only counted jumps.
LOOP_TARGETS = {"iso": ("iso", "linuxcnc", "nc110"), "nc110": ("iso", "linuxcnc", "nc110"),
                "nc110-rpt": ("iso", "linuxcnc", "nc110", "pp")}
CALLS = {  # (main program, the subprogram's file under lib/ or "", sub definition, call) in each target
    "pp": ("%1\n" + "".join(f"N{10 * i} G71 L100\n" for i in range(1, 51)) + "N990 M30\nN1000 G79 L100\n"
           "N1010 G91 G1 X1 F500\nN1020 G90 G70\n*\n", "", None),
    "nc110": ("".join("(CLS,SUB1)\n" for _ in range(50)) + "M30\n", "G91 G1 X1 F500\nG90\n", "MP0/SUB1.nc"),
}
SUB = {"iso": r"^O(?!0001$)\d+$", "linuxcnc": r"^o<\w+> sub$", "nc110": r'^"L100"$',  # O0001: the main program
       "pp": r"\bG79 L\d+"}
CALL = {"iso": r"\bM98 P\d+", "linuxcnc": r"^o<\w+> call", "nc110": r"\((EPP,L100,K1|CLS,SUB1/MP0)\)$",
        "pp": r"\bG71 L\d+"}
TARGETS = ("iso", "linuxcnc", "nc110", "pp")
RUNS = ("iso", "nc110", "pp")  # the targets ncc reads: their motion is compared
SIZE_FACTOR = 5


def run(ncc, args):
    return subprocess.run([ncc] + args, capture_output=True, text=True)


def trace(ncc, dialect, program, lib=None):
    args = ["run", "--dialect", dialect, "--trace-frame", "machine", "--trace-format", "jsonl"]
    p = run(ncc, args + (["--lib", lib] if lib else []) + [str(program)])
    if p.returncode != 0:
        return None
    return equivalent.parse(p.stdout.splitlines())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ncc", required=True)
    args = ap.parse_args()
    ncc = str(Path(args.ncc).resolve())
    failed = []
    with tempfile.TemporaryDirectory() as d:
        d = Path(d)
        for name, text in LOOPS.items():
            dialect = name.split("-")[0]
            source = d / f"loop-{name}.nc"
            source.write_text(text)
            for target in LOOP_TARGETS[name]:
                out = d / f"loop-{name}.{target}"
                p = run(ncc, ["translate", "--dialect", dialect, "--to", target, str(source), "-o", str(out)])
                if p.returncode != 0:
                    failed.append(f"loop {name} -> {target}: {p.stderr.strip()}")
                    continue
                size, limit = out.stat().st_size, SIZE_FACTOR * source.stat().st_size + 400  # the start's codes
                if size > limit:
                    failed.append(f"loop {name} -> {target}: {size} bytes from {source.stat().st_size}: not a loop")
                if target in RUNS:
                    a, b = trace(ncc, dialect, source), trace(ncc, target, out)
                    moves = sum(1 for e in a or [] if e.get("event") == "linear")
                    if a is None or b is None or moves != N + 1:
                        failed.append(f"loop {name} -> {target}: a run failed or made {moves} moves")
                    elif equivalent.compare(a, b, 1e-6):
                        failed.append(f"loop {name} -> {target}: " + equivalent.compare(a, b, 1e-6)[0])
        for dialect, (main_text, sub_text, sub_path) in CALLS.items():
            source = d / f"calls.{dialect}"
            source.write_text(main_text)
            lib = None
            if sub_path:
                lib = str(d / "lib")
                Path(lib, sub_path).parent.mkdir(parents=True, exist_ok=True)
                Path(lib, sub_path).write_text(sub_text)
            for target in TARGETS:
                out = d / f"calls-{dialect}.{target}"
                p = run(ncc, ["translate", "--dialect", dialect, "--to", target] + (["--lib", lib] if lib else [])
                        + [str(source), "-o", str(out)])
                if p.returncode != 0:
                    failed.append(f"calls {dialect} -> {target}: {p.stderr.strip()}")
                    continue
                lines = out.read_text().splitlines()
                subs = sum(1 for l in lines if re.search(SUB[target], l))
                calls = sum(1 for l in lines if re.search(CALL[target], l))
                written = 0 if dialect == target == "nc110" else 1  # NC-110 calls its library's program
                if (subs, calls) != (written, 50):
                    failed.append(f"calls {dialect} -> {target}: {subs} subprograms and {calls} calls, not {written} and 50")
                if target in RUNS:
                    a, b = trace(ncc, dialect, source, lib), trace(ncc, target, out, lib)
                    if a is None or b is None or equivalent.compare(a, b, 1e-6):
                        failed.append(f"calls {dialect} -> {target}: not the same motion")
        # A program with errors is refused with its diagnostics, and nothing written.
        bad = d / "bad.nc"
        bad.write_text("#1=[2+\nG01 X#1\nM30\n")
        out = d / "bad.out"
        p = run(ncc, ["translate", "--dialect", "iso", "--to", "linuxcnc", str(bad), "-o", str(out)])
        if p.returncode != 1 or "error" not in p.stderr or out.exists() or Path(str(out) + ".tmp").exists():
            failed.append(f"a program with errors: exit {p.returncode}, output written: {out.exists()}")
    for f in failed:
        print("FAILED " + f)
    print(f"structure: {'ok' if not failed else f'{len(failed)} failures'}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
