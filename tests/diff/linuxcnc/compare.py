#!/usr/bin/env python3
"""Differential test of ncc's ISO dialect against LinuxCNC's interpreter rs274.

    compare.py --ncc PATH/TO/ncc [--rs274 rs274] [--update] PROGRAM.ngc|DIR ...

Each program runs under `rs274 -g` and `ncc run --dialect iso --trace-format canon`;
both lists of canonical calls are normalised (README.md says what is dropped or
folded, and why) and compared call by call. Without --ncc only the rs274 side is
checked: it must run cleanly and match the reviewed expected/<name>.canon.
Python 3 standard library only.
"""

import argparse
import difflib
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

SUITE = Path(__file__).resolve().parent
TOLERANCE = 1e-4          # absolute, for every numeric argument
TIMEOUT = 60              # seconds per tool run
CONTEXT = 3               # calls of context shown around a difference

# The machine both tools run on. rs274 (standalone, no INI) reads the tool table and
# the parameter file in inches; machine.toml gives ncc the same tools and offsets.
# Paths are relative to this directory. A program's (rs274-args: ...) or
# (ncc-args: ...) line adds options; one it repeats replaces the default.
RS274_DEFAULTS = [("-t", "tool.tbl"), ("-v", "offsets.var")]
NCC_DEFAULTS = [("--machine", "machine.toml")]

# Calls that are interpreter bookkeeping, not machining (README.md, "Dropped calls").
DROPPED = {
    "COMMENT",                   # interpreter notes and the program's own comments
    "ON_RESET",                  # rs274's start and end of a run
    "SET_FEED_REFERENCE",        # preamble only: feed measured along XYZ
    "SET_MOTION_CONTROL_MODE",   # G61/G64 path blending; rs274 wraps every cycle in it
    "SET_NAIVECAM_TOLERANCE",    # G64 Q; rs274 wraps every cycle in it
    "PALLET_SHUTTLE",            # rs274's M30 exchanges pallets; ISO has no pallets
    "START_CHANGE",              # announces the CHANGE_TOOL that always follows it
    "ENABLE_FEED_OVERRIDE",      # rs274 turns the overrides off and on around
    "DISABLE_FEED_OVERRIDE",     #   G84/G74 tapping; the subset has no M48/M49
    "ENABLE_SPEED_OVERRIDE",
    "DISABLE_SPEED_OVERRIDE",
}

# State-setting calls, by the state each sets. Between two actions only the net
# change of each state counts (README.md, "Folding"); this is the order it is shown in.
STATE_KEYS = {
    "USE_LENGTH_UNITS": "units",
    "SELECT_PLANE": "plane",
    "SET_G5X_OFFSET": "g5x",
    "SET_G92_OFFSET": "g92",
    "SET_XY_ROTATION": "rotation",
    "USE_TOOL_LENGTH_OFFSET": "tlo",
    "SET_FEED_MODE": "feed_mode",
    "SET_SPINDLE_MODE": "spindle_mode",
    "SET_SPINDLE_SPEED": "spindle_speed",
    "START_SPINDLE_CLOCKWISE": "spindle",
    "START_SPINDLE_COUNTERCLOCKWISE": "spindle",
    "STOP_SPINDLE_TURNING": "spindle",
    "MIST_ON": "mist",
    "MIST_OFF": "mist",
    "FLOOD_ON": "flood",
    "FLOOD_OFF": "flood",
    "SELECT_TOOL": "tool",
    "SET_FEED_RATE": "feed_rate",
}
STATE_ORDER = ["units", "plane", "g5x", "g92", "rotation", "tlo", "feed_mode", "spindle_mode",
               "spindle_speed", "spindle", "mist", "flood", "tool", "feed_rate"]

# The state a run starts in, before rs274's preamble (which sets units and offsets)
# is applied: what rs274 assumes and what the programs state in their first block.
INITIAL_STATE = [
    "USE_LENGTH_UNITS(CANON_UNITS_MM)",
    "SELECT_PLANE(CANON_PLANE_XY)",
    "SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
    "SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
    "SET_XY_ROTATION(0.0000)",
    "USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000)",
    "SET_FEED_MODE(0, 0)",
    "SET_SPINDLE_MODE(0 0.0000)",
    "SET_SPINDLE_SPEED(0, 0.0000)",
    "STOP_SPINDLE_TURNING(0)",
    "MIST_OFF()",
    "FLOOD_OFF()",
    "SET_FEED_RATE(0.0000)",
]

MOTIONS = {"STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "ARC_FEED"}
FEED_MOTIONS = {"STRAIGHT_FEED", "ARC_FEED", "NURBS_FEED"}   # the only calls a feed rate matters to
# ncc's parabola (GOST 20999's G06) is LinuxCNC's quadratic spline G5.1, which rs274
# prints as NURBS_FEED(3, ...) without its points: the kind is compared, and where
# the tool ends is seen in the moves after it (a judge program follows each with an
# incremental move).
PARABOLA = "NURBS_FEED(3, ...)"


class Call:
    """One canonical call: its name, its argument tokens, and its text as printed."""

    def __init__(self, text):
        self.text = text.strip()
        m = re.fullmatch(r"([A-Z_0-9]+)\((.*)\)", self.text)
        if not m:
            raise ValueError(f"not a canonical call: {text!r}")
        self.name = m.group(1)
        self.args = tokens(m.group(2))

    def nums(self, start=0, count=None):
        vals = [float(t) for t in self.args[start:]]
        return vals if count is None else vals[:count]

    def scaled(self, first, factor):
        """The same call with its numeric arguments from `first` on multiplied
        (a length offset in other units; the offset tokens are all lengths)."""
        head = self.text.partition("(")[0]
        args = self.args[:first] + [f"{float(t) * factor:.4f}" for t in self.args[first:]]
        return Call(f"{head}({', '.join(args)})")

    def same(self, other):
        return self.name == other.name and len(self.args) == len(other.args) and all(
            same_token(a, b) for a, b in zip(self.args, other.args))


def tokens(argtext):
    """Arguments split at commas and blanks (rs274 separates some with blanks only,
    e.g. USE_TOOL_LENGTH_OFFSET's three groups); a quoted string stays whole."""
    out, i = [], 0
    while i < len(argtext):
        c = argtext[i]
        if c in ", \t":
            i += 1
        elif c == '"':
            j = i + 1
            while j < len(argtext) and argtext[j] != '"':
                j += 2 if argtext[j] == "\\" else 1
            out.append(argtext[i:j + 1])
            i = j + 1
        else:
            j = i
            while j < len(argtext) and argtext[j] not in ", \t":
                j += 1
            out.append(argtext[i:j])
            i = j
    return out


def number(token):
    try:
        return float(token)
    except ValueError:
        return None


def same_token(a, b):
    x, y = number(a), number(b)
    if x is not None and y is not None:
        return abs(x - y) <= TOLERANCE
    return a == b


def parse_output(text):
    """Canonical calls from a tool's stdout. rs274 prefixes each with a sequence
    number and the block's N word (or N.....); ncc prints the bare call."""
    calls = []
    for line in text.splitlines():
        line = line.strip()
        if not line:
            continue
        line = re.sub(r"^\d+\s+N\S*\s+", "", line)
        calls.append(Call(line))
    return calls


def split_preamble(calls):
    """rs274 prints its start-up state, ending with ON_RESET(), before the program's
    first call; ncc prints none. Returns (preamble, the program's calls)."""
    for i, c in enumerate(calls):
        if c.name == "ON_RESET":
            return calls[:i], calls[i + 1:]
    return [], calls


def initial_state(preamble):
    state = {}
    for text in INITIAL_STATE:
        c = Call(text)
        state[STATE_KEYS[c.name]] = c
    for c in preamble:
        if c.name in STATE_KEYS:
            state[STATE_KEYS[c.name]] = c
    return state


def normalise(calls, start_state):
    """The calls that describe what the machine does, in a form both tools agree on:
    bookkeeping dropped, no-ops dropped, state changes folded (README.md)."""
    state = dict(start_state)
    pending = {}            # state calls since the last action: key -> latest call
    out = []
    last_pos = None         # machine position after the last motion, when known

    def flush(for_feed):
        nonlocal last_pos
        for key in STATE_ORDER:
            c = pending.get(key)
            # A feed rate only matters to a feed move: it waits for one.
            if c is None or (key == "feed_rate" and not for_feed):
                continue
            del pending[key]
            prev = state.get(key)        # no tool is selected at the start
            if prev is None or not c.same(prev):
                if key == "units":
                    # Offsets and positions are printed in the program's unit.
                    factor = 25.4 if c.args[0] == "CANON_UNITS_MM" else 1 / 25.4
                    for k, first in (("g5x", 1), ("g92", 0), ("tlo", 0)):
                        state[k] = state[k].scaled(first, factor)
                    last_pos = None
                state[key] = c
                out.append(c)

    def machine_position(c, st):
        """Where a move ends, in machine coordinates: rs274 prints positions in the
        active work system with the tool length offset included, so machine =
        printed + G5x + G92 + tool offset. ARC_FEED gives its plane's axes first."""
        v = c.nums()
        if c.name == "ARC_FEED":
            first, second, axis = v[0], v[1], v[5]
            plane = st["plane"].args[0]
            if plane == "CANON_PLANE_XZ":
                v = [second, axis, first] + v[6:9]
            elif plane == "CANON_PLANE_YZ":
                v = [axis, first, second] + v[6:9]
            else:
                v = [first, second, axis] + v[6:9]
        offsets = zip(st["g5x"].nums(1, 6), st["g92"].nums(0, 6), st["tlo"].nums(0, 6))
        return [p + a + b + t for p, (a, b, t) in zip(v[:6], offsets)]

    for c in calls:
        if c.name in DROPPED:
            continue
        if c.name == "PARABOLA_FEED":
            c = Call(PARABOLA)
        if c.name == "DWELL" and abs(c.nums()[0]) <= TOLERANCE:
            continue                     # rs274's tapping cycles dwell 0 s
        if c.name in STATE_KEYS:
            pending[STATE_KEYS[c.name]] = c
            continue
        if c.name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED") and last_pos is not None:
            # A move to where the tool already is (rs274's G28 without axes, its
            # G85 retract to the R plane it is at, a G00 Z to where a cycle left
            # the tool) moves nothing: dropped, and the state changes before it
            # wait for the next action. A unit change always counts.
            after = {**state, **pending}
            if after["units"].same(state["units"]) and all(
                    abs(a - b) <= TOLERANCE for a, b in zip(machine_position(c, after), last_pos)):
                continue
        flush(c.name in FEED_MOTIONS)
        if c.name in MOTIONS:
            last_pos = machine_position(c, state)
        elif c.name == "NURBS_FEED":
            last_pos = None             # rs274 does not say where it ends
        out.append(c)
    pending.pop("feed_rate", None)       # no feed move follows it
    flush(False)
    return out


def directives(program):
    """The program's (rs274-args: ...) and (ncc-args: ...) lines."""
    found = {"rs274-args": [], "ncc-args": []}
    for line in program.read_text(errors="replace").splitlines():
        m = re.match(r"\s*\((rs274-args|ncc-args):(.*)\)\s*;?\s*$", line)
        if m:
            found[m.group(1)] += shlex.split(m.group(2))
    return found


def merge_args(defaults, extra):
    """Default (option, value) pairs, less those the program gives itself, then the
    program's options; relative paths of the defaults are the suite's files."""
    given = set(a for a in extra if a.startswith("-"))
    out = []
    for opt, val in defaults:
        if opt not in given:
            out += [opt, str(SUITE / val)]
    return out + extra


def run(cmd, cwd=None, env=None):
    try:
        p = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=TIMEOUT)
        return p.returncode, p.stdout, p.stderr
    except FileNotFoundError:
        return 127, "", f"cannot run {cmd[0]}\n"
    except subprocess.TimeoutExpired:
        return 124, "", f"timed out after {TIMEOUT} s\n"


def run_rs274(rs274, program, extra):
    """rs274 -g: returns (ok, stdout, error text). rs274 rewrites its parameter
    file at exit (G92 offsets persist there), so it gets a private copy; and it
    maps the tool table to $HOME/.tool.mmap, truncating it first, so that runs in
    parallel (ctest -j) kill each other with SIGBUS unless each has its own HOME."""
    with tempfile.TemporaryDirectory(prefix="diff-rs274-") as tmp:
        args = merge_args(RS274_DEFAULTS, extra)
        for i, a in enumerate(args[:-1]):
            if a in ("-t", "-v", "-i"):       # files: relative to this directory
                args[i + 1] = str(SUITE / args[i + 1])
            if a == "-v":
                copy = Path(tmp) / Path(args[i + 1]).name
                shutil.copyfile(args[i + 1], copy)
                args[i + 1] = str(copy)
        # With no output file rs274 prints the calls on stdout; it always says
        # "executing" on stderr, and an error's message and block there too.
        code, out, err = run([rs274, "-g"] + args + [str(program.resolve())], cwd=tmp,
                             env={**os.environ, "HOME": tmp})
    err = "\n".join(l for l in err.splitlines() if l.strip() != "executing")
    if code != 0 and not err.strip():
        err = (f"rs274 was killed by signal {-code}" if code < 0
               else f"rs274 exited with status {code} and no message")
    return code == 0 and not err.strip(), out, err


def run_ncc(ncc, dialect, program, extra):
    args = merge_args(NCC_DEFAULTS, extra)
    code, out, err = run([ncc, "run", "--dialect", dialect, "--trace-format", "canon"] + args
                         + [str(program.resolve())], cwd=SUITE)
    return code == 0, out, err


def render(calls):
    return [c.text for c in calls]


def show_difference(ref, got, index):
    """A unified-diff-like view around the first differing call."""
    lo = max(0, index - CONTEXT)
    lines = ["--- rs274 (LinuxCNC)", "+++ ncc",
             f"@@ calls {lo + 1}.. (first difference at call {index + 1}) @@"]
    lines += ["  " + c.text for c in ref[lo:index]]
    lines += ["- " + c.text for c in ref[index:index + CONTEXT + 1]]
    lines += ["+ " + c.text for c in got[index:index + CONTEXT + 1]]
    if index >= len(ref):
        lines.append("- (rs274 has no more calls)")
    if index >= len(got):
        lines.append("+ (ncc has no more calls)")
    return "\n".join(lines)


def expected_path(program):
    return SUITE / "expected" / (program.stem + ".canon")


def read_expected(path):
    return [l for l in path.read_text().splitlines() if l.strip() and not l.startswith("#")]


def check(program, opts, source=None, dialect=None, rs274_args=()):
    """Returns a list of failure messages (empty: the program passed). With `source`
    (a program of `dialect`), ncc runs the source and rs274 the program: a
    translation judged by LinuxCNC (tests/translate/judge_linuxcnc.py)."""
    name = program.stem
    d = directives(program)
    ok, out, err = run_rs274(opts.rs274, program, d["rs274-args"] + list(rs274_args))
    if not ok:
        return [f"rs274 rejected the program:\n{err.strip() or out[-2000:]}"]
    preamble, body = split_preamble(parse_output(out))
    start = initial_state(preamble)
    ref = normalise(body, start)

    failures = []
    exp = expected_path(program)
    if source:
        pass  # a translation: no reviewed output of its own
    elif opts.update:
        exp.parent.mkdir(exist_ok=True)
        first = program.read_text(errors="replace").splitlines()[0].strip()
        exp.write_text(f"# {name}: {first}\n# rs274 -g, normalised by compare.py (README.md); "
                       "regenerate with --update\n" + "".join(t + "\n" for t in render(ref)))
    elif exp.exists():
        want = read_expected(exp)
        if want != render(ref):
            diff = difflib.unified_diff(want, render(ref), "expected (reviewed)", "rs274 now",
                                        lineterm="", n=CONTEXT)
            failures.append(f"rs274's output differs from the reviewed {exp.relative_to(SUITE)}; "
                            "review it and rerun with --update:\n" + "\n".join(diff))
    if opts.show:
        print(f"== {name}: rs274\n" + "\n".join(render(ref)))

    if not opts.ncc:
        return failures
    if source:
        ok, out, err = run_ncc(opts.ncc, dialect, source, opts.ncc_arg + directives(source)["ncc-args"])
    else:
        ok, out, err = run_ncc(opts.ncc, opts.dialect, program, opts.ncc_arg + d["ncc-args"])
    if not ok:
        return failures + [f"ncc failed:\n{err.strip()}"]
    try:
        _, nbody = split_preamble(parse_output(out))
    except ValueError as e:
        return failures + [f"ncc printed {e}"]
    got = normalise(nbody, start)
    if opts.show:
        print(f"== {name}: ncc\n" + "\n".join(render(got)))
    if source:
        # A dialect with more axes than LinuxCNC's six (NC-110, GOST): theirs at 0.
        width = {c.name: len(c.args) for c in ref}
        for i, g in enumerate(got):
            n = width.get(g.name, len(g.args))
            if len(g.args) > n and all(number(t) == 0 for t in g.args[n:]):
                got[i] = Call(f"{g.name}({', '.join(g.args[:n])})")
    for i in range(max(len(ref), len(got))):
        if i >= len(ref) or i >= len(got) or not ref[i].same(got[i]):
            failures.append(f"{len(ref)} calls from rs274, {len(got)} from ncc\n"
                            + show_difference(ref, got, i))
            break
    return failures


def programs_of(paths):
    for p in map(Path, paths):
        if p.is_dir():
            yield from sorted(p.glob("*.ngc"))
        else:
            yield p


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ncc", help="the ncc executable; without it only rs274's side is checked")
    ap.add_argument("--rs274", default="rs274", help="LinuxCNC's rs274 (default: rs274 on PATH)")
    ap.add_argument("--dialect", default="iso", help="ncc's dialect (default iso)")
    ap.add_argument("--ncc-arg", action="append", default=[], metavar="ARG",
                    help="an extra argument for every ncc run (repeatable)")
    ap.add_argument("--update", action="store_true",
                    help="write rs274's normalised output to expected/<name>.canon")
    ap.add_argument("--show", action="store_true", help="print both normalised outputs")
    ap.add_argument("programs", nargs="+", help="programs (.ngc) or directories of them")
    opts = ap.parse_args()
    # The tools run in other directories: a path (not a name looked up in PATH)
    # is made absolute first.
    for tool in ("ncc", "rs274"):
        path = getattr(opts, tool)
        if path and "/" in path:
            setattr(opts, tool, str(Path(path).resolve()))

    failed = 0
    progs = list(programs_of(opts.programs))
    for program in progs:
        if not program.exists():
            print(f"FAIL {program}: no such file")
            failed += 1
            continue
        failures = check(program, opts)
        if failures:
            failed += 1
            print(f"FAIL {program.stem} ({program})")
            for f in failures:
                print("  " + f.replace("\n", "\n  "))
        else:
            print(f"ok   {program.stem}")
    print(f"{len(progs) - failed} of {len(progs)} programs passed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
