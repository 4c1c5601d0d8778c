#!/usr/bin/env python3
"""The equivalence matrix of `ncc translate` (docs/translate.md).

    matrix.py --ncc PATH/TO/ncc [--targets gost,nc110,pp,iso,linuxcnc] [--jobs N]
              [--structured] [--table] SOURCE-DIALECT ...

Every golden program of each source dialect that `ncc run` runs cleanly
(tests/golden/<dialect>/*.out whose command is `ncc run`) is translated to each
target. A translation is
  equivalent  it passes `ncc check` in the target with no error and no warning, runs,
              makes the source's motion (equivalent.py, within half the target's
              length resolution; a structured translation writes numbers exactly:
              1e-6 mm), and translating it again to its own dialect gives the same
              blocks, comments aside (a translation is a fixed point);
  refused     ncc named what the target cannot say (NC4096), and wrote nothing;
  differing   anything else: the test fails.
Python 3 standard library only.
"""
import argparse
import collections
import concurrent.futures
import os
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
GOLDEN = HERE.parent / "golden"
sys.path.insert(0, str(HERE))
import equivalent  # noqa: E402

TARGETS = ["gost", "nc110", "pp", "iso", "linuxcnc"]
# The length step each target's numbers write (mm, writer_<dialect>.cpp): a point is
# written to half of it, an arc's sweep and centre then agree to about one step.
TOLERANCE = {"gost": 1e-3, "nc110": 1e-4, "pp": 1e-3, "iso": 1e-4, "linuxcnc": 1e-4}
# The options of a golden run that a translation takes too.
KEPT = {"--dialect", "--machine", "--lib", "--files", "--input", "--block-skip", "--optional-stop", "--process",
        "--max-steps", "--max-memory"}  # a loop that never ends stops as the golden stops it
FLAGS = {"--block-skip", "--optional-stop"}
TIMEOUT = 60


def golden_runs(dialect):
    """(name, directory, program, options) of each golden `ncc run` case."""
    for out in sorted((GOLDEN / dialect).glob("*.out")):
        first = out.read_text(encoding="utf-8", errors="replace").split("\n", 1)[0]
        if not first.startswith("$ ncc run ") or "@GEN@" in first:
            continue
        args = shlex.split(first[len("$ ncc run "):])
        options, program, i = [], None, 0
        while i < len(args):
            a = args[i]
            if a in FLAGS:
                options.append(a)
            elif a.startswith("--"):
                if a in KEPT and i + 1 < len(args):
                    options += [a, args[i + 1]]
                i += 1
            elif program is None:
                program = a
            i += 1
        if program:
            if "--dialect" not in options:
                options += ["--dialect", "gost"]  # ncc's default
            yield out.stem, out.parent, program, options


def run(ncc, args, cwd):
    try:
        p = subprocess.run([ncc] + args, cwd=cwd, capture_output=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return 124, b"", b"timed out"
    return p.returncode, p.stdout, p.stderr


# A trace longer than this is not compared here (10^6 moves of Python dicts would
# take gigabytes): bench/translate.py translates such programs.
MAX_TRACE = 20 << 20


def trace(ncc, options, program, cwd):
    rc, out, err = run(ncc, ["run"] + options + ["--trace-frame", "machine", "--trace-format", "jsonl", program], cwd)
    if rc != 0 or len(out) > MAX_TRACE:
        return None, err
    events = equivalent.parse(out.decode("utf-8", "replace").splitlines())
    # M02 and M30 both end the program; they differ in rewinding the tape, which the
    # ISO seed does not know (its M02 is M30): an end is an end (docs/translate.md).
    for e in events:
        if e.get("event") == "end":
            e["kind"] = "end"
    return events, err


def body(text):
    """A program's blocks without its comments: the first names the file it came
    from, and the ISO dialect shows the operator no comment (its run has no comment
    events), so a comment does not come through a second translation from ISO; pp
    reads a comment line as the block's before it. NC-110's (RPT,3) is a code."""
    return [re.sub(r'\s*("[^"]*"|\((?![A-Z]{3}[,)])[^()]*\))', "", line).rstrip() for line in text.splitlines()
            if "flattened from" not in line and "translated from" not in line and not re.fullmatch(r'\s*(\(.*\)|".*"|N\d+\s*".*"|;.*)\s*', line)]


def drop_limits(options):
    out, i = [], 0
    while i < len(options):
        if options[i] in ("--max-steps", "--max-memory"):
            i += 2
        else:
            out.append(options[i])
            i += 1
    return out


def more_steps(options):
    """A structured translation takes more steps than its source (a repeat loop counts
    in a statement of its own): ten times the golden's limit."""
    return [str(int(o) * 10) if i > 0 and options[i - 1] == "--max-steps" else o for i, o in enumerate(options)]


def with_dialect(options, dialect):
    out, i = [], 0
    while i < len(options):
        if options[i] == "--dialect":
            out += ["--dialect", dialect]
            i += 2
        else:
            out.append(options[i])
            i += 1
    return out


# The least program of each dialect: a machine profile it does not check clean with
# (ISO powers on in G54: a profile without work offset 1) is not a machine for it.
EMPTY = {"iso": "M30\n", "gost": "%\nN1 M02\n", "pp": "%1\nN10 M02\n*\n", "nc110": "M02\n"}
_machine_fits = {}


def machine_fits(ncc, options, reader, cwd, scratch):
    key = (tuple(options), reader, str(cwd))
    if key not in _machine_fits:
        path = os.path.join(scratch, f"empty-{len(_machine_fits)}.{reader}")
        Path(path).write_text(EMPTY[reader])
        rc, report, _ = run(ncc, ["check"] + with_dialect(options, reader) + [path], cwd)
        _machine_fits[key] = rc == 0 and " 0 errors" in report.decode("utf-8", "replace")
    return _machine_fits[key]


STRUCTURED_TOLERANCE = 1e-6
RATE_ROUNDING = 1e-2  # kRateRounding, compiler/translate/writer.h
# (source golden, target) of the round trips that do not give the same text yet.
KNOWN = {tuple(line.split("\t")[:2]) for line in (HERE / "roundtrip_known.tsv").read_text().splitlines()
         if line and not line.startswith("#")}


def one(ncc, name, cwd, program, options, targets, scratch, structured=False):
    """The outcome of each target for one source program: (target, kind, detail)."""
    source_events, _ = trace(ncc, options, program, cwd)
    if source_events is None:
        return name, None
    _, report, _ = run(ncc, ["check"] + options + [program], cwd)
    source_warnings = set(re.findall(r"(warning): .*\[(NC\d+)\]", report.decode("utf-8", "replace")))
    results = []
    for target in targets:
        reader = "iso" if target == "linuxcnc" else target
        if not machine_fits(ncc, options, reader, cwd, scratch):
            results.append((target, "no machine", ""))
            continue
        out = os.path.join(scratch, f"{name}.{target}")
        mode = [] if structured else ["--flatten"]
        rc, _, err = run(ncc, ["translate"] + options + ["--to", target] + mode + [program, "-o", out], cwd)
        text = err.decode("utf-8", "replace")
        if structured:  # the blocks the compiler streams are translated as the whole program's
            whole = out + ".whole"
            rc2, _, err2 = run(ncc, ["translate", "--no-stream"] + options + ["--to", target, program, "-o", whole], cwd)
            written = [Path(f).read_bytes() if os.path.exists(f) else None for f in (out, whole)]
            if rc2 != rc or err2 != err or written[0] != written[1]:
                results.append((target, "differing", "streamed, the translation is not the whole program's (--no-stream)"))
                continue
        if rc == 1 and "[NC4096]" in text:
            if os.path.exists(out):
                results.append((target, "differing", "refused, but wrote " + out))
                continue
            reasons = re.findall(r"cannot translate to \S+: (.*?)(?: \(and in \d+ more (?:blocks?|places?)\))? \[NC4096\]", text)
            results.append((target, "refused", reasons[0] if reasons else text.strip()))
            continue
        if rc != 0:
            results.append((target, "differing", f"translate exit {rc}: {text.strip()[:300]}"))
            continue
        # The source's machine; no step limit: a flattened program has no loop to stop.
        target_options = more_steps(with_dialect(options, reader)) if structured else drop_limits(with_dialect(options, reader))
        rc, report, _ = run(ncc, ["check"] + target_options + [out], cwd)
        # No error, and no warning the source has not (an unknown tool stays unknown).
        found = set(re.findall(r"(error|warning): .*\[(NC\d+)\]", report.decode("utf-8", "replace")))
        found.discard(("warning", "NC6005"))  # the source's profile has settings of the source's dialect
        if rc != 0 or not found <= source_warnings:
            results.append((target, "differing", "check: " + report.decode("utf-8", "replace").strip()[:400]))
            continue
        target_events, err = trace(ncc, target_options, out, cwd)
        if target_events is None:
            results.append((target, "differing", "run: " + err.decode("utf-8", "replace").strip()[:300]))
            continue
        if not any(e.get("event") == "end" for e in source_events):
            # The source ran off its end (an ISO tape's '%'); the target needs M02.
            target_events = [e for e in target_events if e.get("event") != "end"]
        # A structured translation is exact unless ncc said it rounded (NC4098): an arc
        # by its radius gets a centre on the target's step.
        rounded = "[NC4098]" in text
        tolerance = STRUCTURED_TOLERANCE if structured and not rounded else TOLERANCE[target]
        if structured and rounded and target != "pp" and any(e.get("event") == "units" and e.get("units") == "inch"
                                                             for e in source_events):
            tolerance *= 25.4  # the step of a program in inches (pp writes millimetres)
        # A feed, a speed or a dwell rounded to the target's decimals (NC4099) moves by a
        # hundredth of itself at most.
        relative = RATE_ROUNDING if "[NC4099]" in text else equivalent.RELATIVE
        differences = equivalent.compare(source_events, target_events, tolerance, relative=relative)
        if differences:
            results.append((target, "differing", "motion: " + " | ".join(differences[:3])[:400]))
            continue
        again = out + ".again"
        rc, _, err = run(ncc, ["translate"] + target_options + ["--to", target] + mode + [out, "-o", again], cwd)
        if rc != 0 or body(Path(again).read_text()) != body(Path(out).read_text()):
            results.append((target, "differing", "not a fixed point: translating the translation again changes it"))
            continue
        trip = ""
        if structured and reader != program_dialect(options):
            trip = round_trip(ncc, options, target_options, target, out, cwd)
            if trip not in ("round trip", "one way"):
                if (name, target) not in KNOWN:
                    results.append((target, "differing", trip))
                    continue
                trip = "known"
        results.append((target, "equivalent", trip))
    return name, results


def program_dialect(options):
    return options[options.index("--dialect") + 1]


def round_trip(ncc, options, target_options, target, out, cwd):
    """A structured translation B of A, translated back to A's dialect and that to B
    again: "round trip" when the second B has the same blocks as the first (comments
    aside), "one way" when the way back or the second way there is refused, else
    what differs."""
    back, again = out + ".back", out + ".trip"
    rc, _, err = run(ncc, ["translate"] + target_options + ["--to", program_dialect(options), out, "-o", back], cwd)
    if rc == 1 and b"[NC4096]" in err and not os.path.exists(back):
        return "one way"
    if rc != 0:
        return "round trip: the way back: " + err.decode("utf-8", "replace").strip()[:300]
    rc, _, err = run(ncc, ["translate"] + more_steps(options) + ["--to", target, back, "-o", again], cwd)
    if rc == 1 and b"[NC4096]" in err and not os.path.exists(again):
        return "one way"  # A's text of B's construct (NC-110's EPP for ISO's M98) goes no further
    if rc != 0:
        return "round trip: the second way there: " + err.decode("utf-8", "replace").strip()[:300]
    first, second = body(Path(out).read_text()), body(Path(again).read_text())
    if first != second:
        at = next((i for i, (a, b) in enumerate(zip(first, second)) if a != b), min(len(first), len(second)))
        return (f"round trip: the second {target} text differs at block {at + 1}: "
                f"{first[at] if at < len(first) else '(end)'!r} / {second[at] if at < len(second) else '(end)'!r}")
    return "round trip"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ncc", required=True)
    ap.add_argument("--targets", default=",".join(TARGETS))
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--table", action="store_true", help="print the totals as a Markdown table")
    ap.add_argument("--verbose", action="store_true", help="print every outcome")
    ap.add_argument("--structured", action="store_true", help="structured translation (the default of ncc translate)")
    ap.add_argument("dialects", nargs="+")
    args = ap.parse_args(argv)
    ncc = str(Path(args.ncc).resolve())
    targets = args.targets.split(",")
    totals = collections.defaultdict(collections.Counter)
    reasons = collections.defaultdict(collections.Counter)
    failures = []
    skipped = collections.Counter()
    trips = collections.Counter()
    known_seen = set()
    with tempfile.TemporaryDirectory() as scratch, concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        jobs = []
        for dialect in args.dialects:
            for name, cwd, program, options in golden_runs(dialect):
                jobs.append((dialect, pool.submit(one, ncc, f"{dialect}-{name}", cwd, program, options, targets, scratch,
                                                   args.structured)))
        for dialect, job in jobs:
            name, results = job.result()
            if results is None:
                skipped[dialect] += 1
                continue
            for target, kind, detail in results:
                totals[(dialect, target)][kind] += 1
                if kind == "equivalent" and detail:
                    trips[detail] += 1
                if detail == "known":
                    known_seen.add((name, target))
                if kind == "refused":
                    reasons[(dialect, target)][detail] += 1
                if kind == "differing":
                    failures.append(f"{name} -> {target}: {detail}")
                if args.verbose:
                    print(f"{kind:10} {name} -> {target} {detail}")
    if args.table:
        print("| source → target | " + " | ".join(targets) + " |")
        print("|---|" + "---|" * len(targets))
    for dialect in args.dialects:
        cells = []
        for target in targets:
            t = totals[(dialect, target)]
            cells.append(f"{t['equivalent']} / {t['refused']} / {t['differing']}")
        if args.table:
            print(f"| {dialect} ({sum(totals[(dialect, targets[0])].values())} programs) | " + " | ".join(cells) + " |")
        else:
            unfit = sum(totals[(dialect, t)]["no machine"] for t in targets)
            print(f"{dialect}: " + ", ".join(f"{t} {c}" for t, c in zip(targets, cells)) +
                  f" (equivalent / refused / differing; {skipped[dialect]} goldens do not run or run too long; "
                  f"{unfit} translations have a machine profile the target cannot use)")
    if trips:
        print(f"round trips A -> B -> A -> B of the equivalent structured translations: {trips['round trip']} give the "
              f"same B, {trips['one way']} are refused on the way back or the second way there, {trips['known']} differ "
              f"as roundtrip_known.tsv says")
    # A listed pair must still differ: one that round-trips now (or no longer
    # translates) is taken off the list.
    if args.structured:
        for source, target in sorted(KNOWN):
            dialect = source.split("-")[0]
            if dialect in args.dialects and target in targets and (source, target) not in known_seen:
                failures.append(f"{source} -> {target}: listed in roundtrip_known.tsv, but its round trip is no longer "
                                f"a known difference (remove it)")
    for (dialect, target), counter in sorted(reasons.items()):
        for reason, n in counter.most_common():
            print(f"  refused {dialect} -> {target} x{n}: {reason}")
    for f in failures:
        print("DIFFERING " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
