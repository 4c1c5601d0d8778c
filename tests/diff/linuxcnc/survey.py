#!/usr/bin/env python3
"""The linuxcnc dialect against LinuxCNC's rs274 on programs nobody wrote for ncc.

    survey.py --ncc PATH/TO/ncc [--rs274 rs274] [--installed] [--list] FILE|DIR ...

Each program (`--installed`: also every .ngc file `dpkg -L linuxcnc-uspace` lists)
runs under `rs274 -g` and `ncc run --dialect linuxcnc --trace-format canon`, both on
the suite's machine (README.md), ncc with `--lib` the program's folder and rs274 in
that folder, so that both find the subroutine files beside it. Both outputs are
normalised as compare.py does. Each program is counted once: both refuse, refused
by rs274 only, refused by ncc only (with the cause: ncc's first diagnostic), or both
run: equal, or differing (with the first differing call). Not a test: it reports.
"""
import argparse
import collections
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import compare  # noqa: E402  (the normalisation and the comparison)

SUITE = compare.SUITE


def rs274(tool, program):
    with tempfile.TemporaryDirectory(prefix="survey-rs274-") as tmp:
        params = Path(tmp) / "offsets.var"
        shutil.copyfile(SUITE / "offsets.var", params)
        code, out, err = compare.run([tool, "-g", "-t", str(SUITE / "tool.tbl"), "-v", str(params),
                                      str(program)], cwd=program.parent, env={**os.environ, "HOME": tmp})
    err = "\n".join(l for l in err.splitlines() if l.strip() != "executing")
    ok = code == 0 and not err.strip()
    return ok, out, err.strip() or (f"exit status {code}" if code else "")


def ncc(tool, program):
    code, out, err = compare.run([tool, "run", "--dialect", "linuxcnc", "--trace-format", "canon", "--machine",
                                  str(SUITE / "machine.toml"), "--lib", str(program.parent), str(program)])
    return code == 0, out, err.strip()


def cause(err):
    """ncc's first error, without the file's name: 'NC3034 G10 is not supported ...'."""
    for line in err.splitlines():
        m = re.match(r"^.*?:\d+:\d+: error: (.*) \[(NC\d+)\]$", line)
        if m:
            return f"{m.group(2)} {m.group(1)}"
    return (err.splitlines() or ["no message"])[0]


def judge(program, opts):
    """(category, detail)."""
    r_ok, r_out, r_err = rs274(opts.rs274, program)
    n_ok, n_out, n_err = ncc(opts.ncc, program)
    if not r_ok and not n_ok:
        return "both refuse", f"rs274: {r_err.splitlines()[0] if r_err else '?'}; ncc: {cause(n_err)}"
    if not r_ok:
        return "refused by rs274 only", (r_err.splitlines() or ["?"])[0]
    if not n_ok:
        return "refused by ncc only", cause(n_err)
    try:
        preamble, body = compare.split_preamble(compare.parse_output(r_out))
        start = compare.initial_state(preamble)
        ref = compare.normalise(body, start)
        got = compare.normalise(compare.split_preamble(compare.parse_output(n_out))[1], start)
    except ValueError as e:
        return "differ", f"unreadable output: {e}"
    for i in range(max(len(ref), len(got))):
        if i >= len(ref) or i >= len(got) or not ref[i].same(got[i]):
            a = ref[i].text if i < len(ref) else "(end)"
            b = got[i].text if i < len(got) else "(end)"
            return "differ", f"call {i + 1}: rs274 {a} / ncc {b}"
    return "equal", ""


def installed():
    p = subprocess.run(["dpkg", "-L", "linuxcnc-uspace"], capture_output=True, text=True)
    return sorted(Path(l) for l in p.stdout.splitlines() if l.endswith(".ngc") and Path(l).is_file())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ncc", required=True)
    ap.add_argument("--rs274", default="rs274")
    ap.add_argument("--installed", action="store_true", help="every .ngc file of linuxcnc-uspace")
    ap.add_argument("--list", action="store_true", help="a line for each program")
    ap.add_argument("programs", nargs="*")
    opts = ap.parse_args()
    opts.ncc = str(Path(opts.ncc).resolve())
    progs = installed() if opts.installed else []
    for p in map(Path, opts.programs):
        progs += sorted(p.rglob("*.ngc")) if p.is_dir() else [p]
    counts = collections.Counter()
    causes = collections.Counter()
    for program in progs:
        category, detail = judge(program.resolve(), opts)
        counts[category] += 1
        if category == "refused by ncc only":
            causes[re.sub(r"'[^']*'|\d+(\.\d+)?", "_", detail)[:90]] += 1
        if opts.list:
            print(f"{category:22} {program}  {detail}")
    print(f"{len(progs)} programs")
    for category in ("equal", "differ", "refused by ncc only", "refused by rs274 only", "both refuse"):
        print(f"  {counts[category]:4}  {category}")
    if causes:
        print("ncc's refusals, by cause:")
        for c, n in causes.most_common():
            print(f"  {n:4}  {c}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
