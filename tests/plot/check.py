#!/usr/bin/env python3
"""Checks `ncc plot` against the trace of the same run: one <path> per move of the
trace, in its order, each ending where the move ends (from the first work zero, in
mm) and titled with the move's file:line, in every view; and the same bytes twice.

usage: check.py NCC PROGRAM [ncc options...]   (run in the program's folder)
"""
import json
import math
import os
import re
import subprocess
import sys

MOVES = {"rapid", "linear", "arc", "thread"}
VIEWS = {"xy": ((1, 0, 0), (0, 1, 0)), "xz": ((1, 0, 0), (0, 0, 1)), "yz": ((0, 1, 0), (0, 0, 1)),
         "iso": ((math.sqrt(.5), math.sqrt(.5), 0), (-math.sqrt(1 / 6), math.sqrt(1 / 6), 2 * math.sqrt(1 / 6)))}


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def main():
    ncc, program, options = sys.argv[1], sys.argv[2], sys.argv[3:]
    run = subprocess.run([ncc, "run", program, *options, "--trace-frame", "machine", "--trace-format", "jsonl"],
                         capture_output=True, text=True)
    events = [json.loads(line) for line in run.stdout.splitlines()]
    scale, origin, moves = 1.0, (0.0, 0.0, 0.0), []
    for e in events:
        if e["event"] == "units":
            scale = 25.4 if e["units"] == "inch" else 1.0
        elif e["event"] == "work_offset" and not moves:
            origin = tuple(e.get(a, 0) * scale for a in "XYZ")
        elif e["event"] in ("parabola", "spline"):
            fail(f"{program}: a {e['event']} is drawn as chords: pick another program")
        elif e["event"] in MOVES:
            moves.append((tuple(e.get(a, 0) * scale - o for a, o in zip("XYZ", origin)), f"{os.path.basename(e['file'])}:{e['line']}"))
    if not moves:
        fail(f"{program}: the run made no move")
    for view, (h, v) in VIEWS.items():
        args = [ncc, "plot", program, *options, "--view", view, "-o", "-"]
        first = subprocess.run(args, capture_output=True, text=True)
        second = subprocess.run(args, capture_output=True, text=True)
        if first.stdout != second.stdout:
            fail(f"{program} {view}: two plots differ")
        body = first.stdout.split('<g id="path">', 1)[1].split("</g>", 1)[0]
        paths = re.findall(r'<path class="[^"]*" d="([^"]*)"><title>([^<]*)</title>', body)
        if len(paths) != len(moves):
            fail(f"{program} {view}: {len(paths)} paths for {len(moves)} moves")
        for i, ((d, title), (end, where)) in enumerate(zip(paths, moves)):
            numbers = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?", d)]
            want = (sum(a * b for a, b in zip(h, end)), sum(a * b for a, b in zip(v, end)))
            if abs(numbers[-2] - want[0]) > 6e-5 or abs(numbers[-1] - want[1]) > 6e-5:
                fail(f"{program} {view}: path {i + 1} ends at {numbers[-2:]}, the move at {want}")
            if not title.endswith(where):
                fail(f"{program} {view}: path {i + 1} is titled '{title}', the move is at {where}")
    print(f"{program}: {len(moves)} moves, 4 views: ok")


main()
