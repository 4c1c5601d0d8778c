#!/usr/bin/env python3
"""Parity of `ncc run --time`'s feed model with LinuxCNC AXIS's run-time estimate.

    cycle_time.py --ncc PATH/TO/ncc [--rs274 rs274] [--verbose] PROGRAM.ngc|DIR ...

For each program, rs274 -g gives the canonical calls (as compare.py runs it), and
from them this script computes what AXIS's "G-Code Properties" shows (axis.py
gcode_properties):

    Σ feed lengths / min(max velocity, feed) + Σ traverse lengths / max velocity + dwells

over X Y Z of the programmed point (work offsets and G92 applied, the tool length
not: a G43 or G49 moves no length), with each arc cut into AXIS's chords,
max(3, int(64·|sweep| / π)) of them (gcode.arc_to_segments with the default
[DISPLAY] ARCDIVISION = 64), and a max velocity of VELOCITY mm/min. ncc runs the
program on the suite's machine with every axis's rapid and max_feed and [motion]
max_velocity set to that velocity, so that its feed model's speed is min(feed,
velocity) too; its cutting + rapid + dwell seconds (`--time-format json`) must equal
AXIS's estimate within:

* the chords: a chord of angle φ is shorter than its arc by at most φ²/24 of it
  (1 − sin(φ/2)/(φ/2) ≤ φ²/24); with that many chords φ ≤ π/48, so an arc's time is
  at most 1.8e-4 short;
* rs274's printing: coordinates to 4 decimals, so each end of a move may be off by
  sqrt(3)·5e-5 program units and its length by twice that (an arc's also by its sweep
  times that), which ncc, reading the program itself, is not.

Where this estimate departs from AXIS itself, on purpose: every traverse counts (AXIS
skips those before the first feed move and after a tool change: its preview does
not know where the machine stands; here it starts at machine zero, as ncc does), and
a feed per revolution (G95) is F × S per minute (AXIS divides by F as if per minute).
Tool changes and spindle ramps are not in AXIS's estimate and not compared.
Python 3 standard library only.
"""

import argparse
import json
import math
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

SUITE = Path(__file__).resolve().parent
sys.path.insert(0, str(SUITE))
import compare  # noqa: E402  (the suite's rs274 runner and call parser)

VELOCITY = 1000.0          # mm/min: AXIS's max velocity, every axis's rapid and max_feed in ncc
ARC_DIVISION = 64          # AXIS's [DISPLAY] ARCDIVISION default: chords per half turn
PRINT_SLACK = 2 * math.sqrt(3) * 5e-5   # program units a move may be off by in rs274's 4-decimal output
MM = {"CANON_UNITS_MM": 1.0, "CANON_UNITS_INCHES": 25.4}

# The suite's machine for ncc, with the speeds above (appended to machine.toml).
TIMING_PROFILE = f"""
[axes]
X = {{ rapid = {VELOCITY}, max_feed = {VELOCITY} }}
Y = {{ rapid = {VELOCITY}, max_feed = {VELOCITY} }}
Z = {{ rapid = {VELOCITY}, max_feed = {VELOCITY} }}

[motion]
max_velocity = {VELOCITY}
"""


class Estimate:
    """AXIS's estimate of one program, and the tolerance ncc's exact arcs and
    rs274's rounded output leave it."""

    def __init__(self):
        self.seconds = 0.0
        self.tolerance = 0.0
        self.moves = 0
        self.arcs = 0

    def move(self, length_mm, speed_mm_s, slack_units, unit_mm):
        self.seconds += length_mm / speed_mm_s
        self.tolerance += slack_units * unit_mm / speed_mm_s
        self.moves += 1


def arc_chords(start, call, plane):
    """AXIS's chord points of an ARC_FEED from `start` (program units, X Y Z), and
    the chord angle. rs274 prints the plane's first and second axis, then the
    normal axis's end: XY (first X), XZ (first Z, second X), YZ (first Y)."""
    v = call.nums()
    first_end, second_end, first_c, second_c, turns, normal_end = v[0], v[1], v[2], v[3], int(v[4]), v[5]
    axes = {"CANON_PLANE_XY": (0, 1, 2), "CANON_PLANE_XZ": (2, 0, 1), "CANON_PLANE_YZ": (1, 2, 0)}[plane]
    a, b, n = axes
    end = [0.0, 0.0, 0.0]
    end[a], end[b], end[n] = first_end, second_end, normal_end
    theta1 = math.atan2(start[b] - second_c, start[a] - first_c)
    theta2 = math.atan2(end[b] - second_c, end[a] - first_c)
    closed = math.hypot(start[a] - end[a], start[b] - end[b]) < 1e-9
    if turns < 0:
        if theta1 < theta2 or closed:
            theta2 -= 2 * math.pi
        theta2 += 2 * math.pi * (turns + 1)
    else:
        if theta1 > theta2 or closed:
            theta2 += 2 * math.pi
        theta2 += 2 * math.pi * (turns - 1)
    sweep = theta2 - theta1
    steps = max(3, int(ARC_DIVISION * abs(sweep) / math.pi))
    radius = math.hypot(start[a] - first_c, start[b] - second_c)
    points = []
    for i in range(1, steps + 1):
        f = i / steps
        p = [0.0, 0.0, 0.0]
        p[a] = first_c + radius * math.cos(theta1 + sweep * f)
        p[b] = second_c + radius * math.sin(theta1 + sweep * f)
        p[n] = start[n] + (end[n] - start[n]) * f
        points.append(p)
    points[-1] = end
    return points, abs(sweep) / steps, abs(sweep)


def axis_estimate(calls, start_state):
    """AXIS's estimate from rs274's calls (after its preamble)."""
    state = dict(start_state)
    est = Estimate()
    machine = [0.0, 0.0, 0.0]     # mm: rs274 starts at machine zero
    feed_mode, feed, rpm = 0, 0.0, 0.0
    limit = VELOCITY / 60

    def unit():
        return MM[state["units"].args[0]]

    def offset():   # program units: work offset + G92, X Y Z (AXIS leaves the tool length out)
        return [a + b for a, b in zip(state["g5x"].nums(1, 3), state["g92"].nums(0, 3))]

    def to_program(p_mm):
        return [x / unit() - o for x, o in zip(p_mm, offset())]

    def to_machine(p):
        return [(x + o) * unit() for x, o in zip(p, offset())]

    for c in calls:
        if c.name in compare.STATE_KEYS:
            key = compare.STATE_KEYS[c.name]
            if key == "units" and not c.same(state["units"]):
                factor = MM[c.args[0]] / unit()      # offsets are printed in the program's unit
                for k, first in (("g5x", 1), ("g92", 0)):
                    state[k] = state[k].scaled(first, 1 / factor)
            state[key] = c
            if c.name == "SET_FEED_MODE":
                feed_mode = int(float(c.args[1]))
            elif c.name == "SET_FEED_RATE":
                feed = c.nums()[0]
            elif c.name == "SET_SPINDLE_SPEED":
                rpm = c.nums()[1]
            continue
        if c.name == "DWELL":
            est.seconds += c.nums()[0]
        elif c.name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED"):
            end = to_machine(c.nums(0, 3))
            length = math.dist(machine, end)
            if length > 0:
                if c.name == "STRAIGHT_TRAVERSE":
                    speed = limit
                else:
                    per_minute = feed * rpm if feed_mode == 1 else feed
                    speed = min(limit, per_minute * unit() / 60)
                est.move(length, speed, PRINT_SLACK, unit())
            machine = end
        elif c.name == "ARC_FEED":
            points, chord_angle, sweep = arc_chords(to_program(machine), c, state["plane"].args[0])
            per_minute = feed * rpm if feed_mode == 1 else feed
            speed = min(limit, per_minute * unit() / 60)
            before = est.seconds
            here = machine
            for p in points:
                there = to_machine(p)
                est.seconds += math.dist(here, there) / speed
                here = there
            # The chords' deficit (φ²/24 of the arc at most) and the printed radius and ends.
            est.tolerance += (est.seconds - before) * chord_angle ** 2 / 24 * 1.0001
            est.tolerance += PRINT_SLACK * (1 + sweep) * unit() / speed
            est.moves += 1
            est.arcs += 1
            machine = here
    return est


def ncc_seconds(ncc, program, profile, extra):
    """ncc's feed model: cutting + rapid + dwell seconds, or an error text."""
    cmd = [ncc, "run", "--dialect", "iso", "--machine", str(profile), "--trace", "none", "--time",
           "--time-format", "json"] + extra + [str(program.resolve())]
    try:
        p = subprocess.run(cmd, cwd=SUITE, capture_output=True, text=True, timeout=compare.TIMEOUT)
    except (OSError, subprocess.TimeoutExpired) as e:
        return None, str(e)
    if p.returncode != 0:
        return None, f"ncc exited with {p.returncode}:\n{p.stderr.strip()}"
    lines = [l for l in p.stdout.splitlines() if l.startswith("{")]
    if not lines:
        return None, f"ncc printed no JSON summary:\n{p.stdout[-2000:]}{p.stderr[-2000:]}"
    try:
        feed = json.loads(lines[-1])["models"]["feed"]
        return feed["cutting"] + feed["rapid"] + feed["dwell"], None
    except (ValueError, KeyError) as e:
        return None, f"ncc's summary lacks the feed model ({e}): {lines[-1]}"


def check(program, opts, profile):
    """(ok, AXIS seconds, ncc seconds, relative difference, message)."""
    d = compare.directives(program)
    ok, out, err = compare.run_rs274(opts.rs274, program, d["rs274-args"])
    if not ok:
        return False, None, None, None, f"rs274 rejected the program:\n{err.strip() or out[-2000:]}"
    preamble, body = compare.split_preamble(compare.parse_output(out))
    est = axis_estimate(body, compare.initial_state(preamble))
    got, error = ncc_seconds(opts.ncc, program, profile, d["ncc-args"])
    if error:
        return False, est.seconds, None, None, error
    diff = abs(got - est.seconds)
    rel = diff / est.seconds if est.seconds > 0 else diff
    allowed = est.tolerance + 1e-9
    msg = (f"AXIS {est.seconds:.6f} s, ncc {got:.6f} s, difference {diff:.3g} s "
           f"(relative {rel:.3g}; allowed {allowed:.3g} s; {est.moves} moves, {est.arcs} arcs)")
    return diff <= allowed, est.seconds, got, rel, msg


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ncc", required=True, help="the ncc executable")
    ap.add_argument("--rs274", default="rs274", help="LinuxCNC's rs274 (default: rs274 on PATH)")
    ap.add_argument("--verbose", action="store_true", help="print every program's numbers")
    ap.add_argument("programs", nargs="+", help="programs (.ngc) or directories of them")
    opts = ap.parse_args()
    for tool in ("ncc", "rs274"):
        path = getattr(opts, tool)
        if "/" in path:
            setattr(opts, tool, str(Path(path).resolve()))

    failed, worst = 0, (0.0, "")
    progs = list(compare.programs_of(opts.programs))
    with tempfile.TemporaryDirectory(prefix="cycle-time-") as tmp:
        profile = Path(tmp) / "machine.toml"
        profile.write_text((SUITE / "machine.toml").read_text() + TIMING_PROFILE)
        shutil.copy(SUITE / "codes.tsv", tmp)   # the machine's G codes (iso.tables)
        for program in progs:
            ok, axis, got, rel, msg = check(program, opts, profile)
            if rel is not None and rel > worst[0]:
                worst = (rel, program.stem)
            if not ok:
                failed += 1
                print(f"FAIL {program.stem}: " + msg.replace("\n", "\n  "))
            elif opts.verbose:
                print(f"ok   {program.stem}: {msg}")
    print(f"{len(progs) - failed} of {len(progs)} programs within tolerance; "
          f"largest relative difference {worst[0]:.3g} ({worst[1] or '-'})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
