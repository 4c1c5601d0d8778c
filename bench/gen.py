#!/usr/bin/env python3
"""Deterministic benchmark programs for ncc (and their LinuxCNC twins).

    bench/gen.py OUTDIR [--plain N] [--arcs N] [--cycles N] [--loop N]
                        [--dialects iso,gost,pp,nc110] [--kinds plain,arcs,cycles,loop]

Writes, for each dialect where the construct exists:

  plain   [N] G1 X Y Z F blocks: a bounded random walk (the bulk of CAM output)
  arcs    G2/G3 quarter and half circles with I J, chained end to start
  cycles  G81, G82 (dwell) and G83 (peck) drilling, a few holes per cycle, then G80
  loop    iso only: a Macro B `WHILE [#1 LT n] DO1 ... END1` loop computing SIN/COS
          for each move

and for iso the LinuxCNC twins `iso-<kind>.ngc`, the same motion in rs274's syntax:
plain, arcs and cycles are the same text (every mode stated in the first block, G80
alone in its block, P with a decimal point); the loop is `o100 while [...]` /
`o100 endwhile`. Sizes count the blocks of the body (plain, arcs, cycles) or the
loop's iterations. Everything is derived from fixed seeds: the same arguments give
the same bytes. `manifest.json` in OUTDIR lists each program with its dialect, size
in bytes, and the number of blocks a run executes. Every program runs cleanly (no
error, no warning) under `ncc run --dialect D --trace none`, GOST with
`--machine bench/gost-n8.toml` (8-digit block numbers). Python 3 standard library only.
"""

import argparse
import json
import random
import sys
from pathlib import Path

DIALECTS = ["iso", "gost", "pp", "nc110"]
KINDS = ["plain", "arcs", "cycles", "loop"]
EXT = {"iso": ".nc", "gost": ".nc", "pp": ".pp", "nc110": ".nc"}
SEEDS = {"plain": 20261121, "arcs": 4242, "cycles": 8180, "loop": 1000}   # per kind:
# every dialect gets the same path, so the dialects' rows compare like with like.

BOUND = 200_000          # µm: the walks stay within ±200 mm of the origin


def mm(um):
    """A length in µm (an int) as a decimal number with 3 decimals: 12.345, -0.500."""
    sign = "-" if um < 0 else ""
    um = abs(um)
    return f"{sign}{um // 1000}.{um % 1000:03d}"


class Writer:
    """Collects the lines of one program; counts the blocks a run executes."""

    def __init__(self):
        self.lines = []
        self.blocks = 0

    def block(self, text, runs=1):
        self.lines.append(text)
        self.blocks += runs

    def text(self):
        return "\n".join(self.lines) + "\n"


class Numbering:
    """Block numbers, each used once: pp needs one on every block (1..99999999) and
    GOST numbers every block (run with bench/gost-n8.toml, 8 digits: with the default
    N04 the numbers would wrap at 9999, and every repeated one is warning NC3007).
    ISO and LinuxCNC (N at most 99999 in rs274) and NC-110 (N at most 9999) blocks
    are not numbered, as much CAM output for them is not: a repeated N is a warning
    in ncc's ISO dialect (a jump would go to the first)."""

    def __init__(self, dialect):
        self.dialect = dialect
        self.n = 0

    def __call__(self):
        self.n += 1
        return f"N{self.n} " if self.dialect in ("pp", "gost") else ""


# ---------------------------------------------------------------- headers, trailers

def header(dialect, w, num, title):
    """The first blocks: program start and every mode stated; tool at X0 Y0 Z20."""
    if dialect == "gost":
        w.lines.append("%0001")
        w.block(f"{num()}G90 G17 G00 X0. Y0. Z20. S1000 M03")
    elif dialect == "pp":
        w.lines.append(f'%1 "{title}"')
        w.block(f"{num()}G90 G17 G0 X0 Y0 Z20. S1000 M03")
    elif dialect == "nc110":
        w.block(f"{num()}G17")                  # G17 stands alone (Table 2.4)
        w.block(f"{num()}G90 G0 X0 Y0 Z20 S1000 M3")
    else:  # iso and the LinuxCNC twin: the diff suite's rule, every mode in block one
        w.block(f"{num()}G17 G21 G90 G94 G40 G49 G80 G98")
        w.block(f"{num()}S1000 M03")
        w.block(f"{num()}G00 X0 Y0 Z20.")


def trailer(dialect, w, num):
    """Retract to Z20 at rapid (which also ends NC-110's G27 feed profile, inside
    which M05 is an error), spindle off, end."""
    w.block(f"{num()}{g(dialect, 0)} Z20.")
    if dialect == "gost":
        w.block(f"{num()}M05")
        w.block(f"{num()}M30")
    elif dialect == "pp":
        w.block(f"{num()}M05")
        w.block(f"{num()}M30")
        w.lines.append("*")
    elif dialect == "nc110":
        w.block(f"{num()}M5")
        w.block(f"{num()}M30")
    else:
        w.block(f"{num()}M05")
        w.block(f"{num()}M30")


def g(dialect, code):
    """G01 in GOST and ISO (and LinuxCNC twin) style, G1 in pp and NC-110 style."""
    return f"G{code:02d}" if dialect in ("gost", "iso", "ngc") else f"G{code}"


# ---------------------------------------------------------------- programs

def walk_step(rng, v, lo, hi, step):
    """One coordinate of a bounded random walk, in µm."""
    v += rng.randint(-step, step)
    return min(max(v, lo), hi)


def plain(dialect, blocks):
    rng = random.Random(SEEDS["plain"])
    w, num = Writer(), Numbering(dialect)
    header(dialect, w, num, "PLAIN")
    x = y = 0
    z = -1000
    feeds = [800, 1000, 1200, 1500, 2000]
    for i in range(blocks):
        nx = walk_step(rng, x, -BOUND, BOUND, 5000)
        ny = walk_step(rng, y, -BOUND, BOUND, 5000)
        z = walk_step(rng, z, -20000, -500, 300)
        if nx == x and ny == y:
            nx += 1                              # consecutive points always differ
        x, y = nx, ny
        f = feeds[rng.randrange(len(feeds))]
        feed = f"F{f}." if dialect == "gost" else f"F{f}"
        w.block(f"{num()}{g(dialect, 1)} X{mm(x)} Y{mm(y)} Z{mm(z)} {feed}")
    trailer(dialect, w, num)
    return w


def arcs(dialect, blocks):
    """Quarter and half circles with the centre on a parallel to an axis through the
    start, so every centre and end point lies on the 0.001 grid and the start and end
    radii agree exactly. I J are increments from the start (gost, pp, iso, LinuxCNC)
    or the centre's coordinates under G90 (NC-110, its decision 39)."""
    rng = random.Random(SEEDS["arcs"])
    w, num = Writer(), Numbering(dialect)
    header(dialect, w, num, "ARCS")
    x = y = 0
    feed = "F600." if dialect == "gost" else "F600"
    w.block(f"{num()}{g(dialect, 1)} Z-2. {feed}")
    for i in range(blocks):
        r = rng.randint(2000, 20000)
        if rng.random() < 0.5:                   # centre along X from the start
            s = -1 if x > 0 else 1
            if abs(x) < BOUND // 2 and rng.random() < 0.5:
                s = -s
            cx, cy = x + s * r, y
        else:
            s = -1 if y > 0 else 1
            if abs(y) < BOUND // 2 and rng.random() < 0.5:
                s = -s
            cx, cy = x, y + s * r
        vx, vy = x - cx, y - cy
        code = 2 if rng.random() < 0.5 else 3
        if rng.random() < 0.2:                   # half circle
            ex, ey = cx - vx, cy - vy
        elif code == 3:                          # quarter, counter-clockwise
            ex, ey = cx - vy, cy + vx
        else:                                    # quarter, clockwise
            ex, ey = cx + vy, cy - vx
        if dialect == "nc110":
            i_, j_ = cx, cy
        else:
            i_, j_ = cx - x, cy - y
        w.block(f"{num()}{g(dialect, code)} X{mm(ex)} Y{mm(ey)} I{mm(i_)} J{mm(j_)}")
        x, y = ex, ey
    trailer(dialect, w, num)
    return w


def cycles(dialect, blocks):
    """Groups of holes: G81, then G82 with a dwell, then G83 pecking, in turn; each
    group is its cycle's block (the first hole, except NC-110 where the cycle block
    only stores the cycle), 1-7 more holes by X Y, and G80. The tool starts at Z20
    (the initial level), R is 2, the bottom -5 to -12."""
    rng = random.Random(SEEDS["cycles"])
    w, num = Writer(), Numbering(dialect)
    header(dialect, w, num, "CYCLES")
    if dialect == "nc110":
        w.block(f"{num()}TMR=0.5")              # the G82 dwell and G83's pause (s)
    kinds = [81, 82, 83]
    group = 0
    while w.blocks < blocks:
        code = kinds[group % 3]
        group += 1
        holes = rng.randint(2, 8)
        depth = -rng.randint(5000, 12000)
        pts = [(rng.randint(0, 200) * 1000, rng.randint(0, 150) * 1000) for _ in range(holes)]
        x0, y0 = pts[0]
        if dialect in ("iso", "ngc", "gost"):
            f = "F100." if dialect == "gost" else "F100"
            extra = {81: "", 82: " P0.5", 83: " Q3."}[code]
            w.block(f"{num()}G{code} X{mm(x0)} Y{mm(y0)} Z{mm(depth)} R2.{extra} {f}")
            rest = pts[1:]
        elif dialect == "pp":
            extra = {81: "", 82: " Q50", 83: " I3."}[code]   # Q in 10 ms, I the peck
            w.block(f"{num()}G{code} X{mm(x0)} Y{mm(y0)} Z{mm(depth)} K2.{extra} F100")
            rest = pts[1:]
        else:  # nc110: the cycle block stores it; every later position drills
            extra = {81: "", 82: "", 83: " I3"}[code]
            w.block(f"{num()}G{code} R2 Z{mm(depth)}{extra} F100")
            rest = pts
        for (hx, hy) in rest:
            w.block(f"{num()}X{mm(hx)} Y{mm(hy)}")
        w.block(f"{num()}G80")
    trailer(dialect, w, num)
    return w


def loop(dialect, iterations):
    """iso: Macro B WHILE; ngc: LinuxCNC's o-word while. Five blocks run per
    iteration in both (the WHILE / o100 while line, two assignments, the move, and
    END1 / o100 endwhile)."""
    w = Writer()
    w.block("G17 G21 G90 G94 G40 G49 G80")
    w.block("S1000 M03")
    w.block("G00 X50. Y0 Z5.")
    w.block("G01 Z-1. F1000")
    w.block("#1=0")
    head = f"WHILE [#1 LT {iterations}] DO1" if dialect == "iso" else f"o100 while [#1 LT {iterations}]"
    tail = "END1" if dialect == "iso" else "o100 endwhile"
    w.block(head, iterations + 1)
    w.block("#2=[#1*0.7]", iterations)
    w.block("G01 X[50*COS[#2]+#1*0.001] Y[50*SIN[#2]] Z[-1-SIN[#2*3]]", iterations)
    w.block("#1=[#1+1]", iterations)
    w.block(tail, iterations)
    w.block("M05")
    w.block("M30")
    return w


MAKERS = {"plain": plain, "arcs": arcs, "cycles": cycles, "loop": loop}
DEFAULTS = {"plain": 1_000_000, "arcs": 200_000, "cycles": 200_000, "loop": 200_000}


def programs(dialects, kinds):
    """(name, dialect for ncc or 'ngc', kind) of every program to write."""
    out = []
    for kind in kinds:
        for d in dialects:
            if kind == "loop" and d != "iso":
                continue                         # the loop row is the LinuxCNC comparison
            out.append((f"{d}-{kind}", d, kind))
            if d == "iso":
                out.append((f"iso-{kind}", "ngc", kind))
    return out


def generate(outdir, sizes, dialects=DIALECTS, kinds=KINDS, log=None):
    """Writes the programs and manifest.json; returns the manifest entries."""
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    entries = []
    for name, d, kind in programs(dialects, kinds):
        n = sizes[kind]
        w = MAKERS[kind](d, n)
        path = outdir / (name + (".ngc" if d == "ngc" else EXT[d]))
        text = w.text()
        path.write_text(text, encoding="ascii")
        e = {"name": name, "dialect": d, "kind": kind, "path": str(path), "size": n,
             "bytes": len(text), "blocks_run": w.blocks}
        if kind == "loop":
            e["iterations"] = n
        entries.append(e)
        if log:
            log(f"  wrote {path.name}: {len(text) / 1e6:.2f} MB, {w.blocks} blocks run")
    (outdir / "manifest.json").write_text(json.dumps(entries, indent=1) + "\n")
    return entries


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir")
    for k in KINDS:
        ap.add_argument(f"--{k}", type=int, default=DEFAULTS[k],
                        help=f"{'iterations' if k == 'loop' else 'blocks'} (default {DEFAULTS[k]})")
    ap.add_argument("--dialects", default=",".join(DIALECTS))
    ap.add_argument("--kinds", default=",".join(KINDS))
    a = ap.parse_args(argv)
    sizes = {k: getattr(a, k) for k in KINDS}
    generate(a.outdir, sizes, [d for d in a.dialects.split(",") if d],
             [k for k in a.kinds.split(",") if k], log=print)


if __name__ == "__main__":
    sys.exit(main())
