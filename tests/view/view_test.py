#!/usr/bin/env python3
"""Browser tests of `ncc view` (tests/view/CMakeLists.txt): pages ncc wrote, opened in
headless Chromium (Debian's `chromium`), WebGL through SwiftShader.

  view_test.py --ncc NCC --work DIR state PROGRAM [ncc options...]
      The page loads with no console message and no error; its canvas is drawn (the
      pixels that differ from the background, counted by the page); each block that
      moved ends, on the page, where the trace's events of that block end
      (`ncc run --trace-format jsonl --trace-frame machine`, less the page's origin);
      the page opened at block N and stepped back one (#block=N&step=-1) stands at
      block N-1's end; the height map is cut, not below the stock. With --measure A,B:
      clicks where the ends of records A and B are drawn pick those points, and the
      measure panel shows their dX dY dZ and distance.
  view_test.py ... errors PROGRAM [ncc options...]
      The same for a program with errors, and the page lists its diagnostics and ends
      at the trace's last move (the path up to the first error).
  view_test.py ... screenshot PROGRAM --reference PNG [ncc options...]
      A fixed view (#ui=0&view=iso, 640x480, opened at the last block) compared with a
      reviewed PNG within a tolerance: at most 0.5 % of the pixels differ by more than
      48 in a channel; the height map is cut.
      NCC_VIEW_UPDATE=1 writes the reference instead (look at it before committing).
  view_test.py ... size
      No browser: pages are the same bytes twice; a generated program of 20,000 blocks
      costs at most 48 bytes a block (besides its source); a parabola's chords merge within the tolerance.

Exit 77 (ctest's SKIP_RETURN_CODE) with a message when no Chromium is installed.
Only the standard library: PNGs are decoded with zlib.
"""
import argparse
import html
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

SKIP = 77
MOVES = {"rapid", "linear", "arc", "thread", "parabola", "spline", "probe", "operator_move"}


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def find_chromium():
    for name in [os.environ.get("NCC_CHROMIUM", ""), "chromium", "chromium-browser", "google-chrome",
                 "google-chrome-stable"]:
        if name and shutil.which(name):
            return shutil.which(name)
    return None


def chromium_command(chromium, profile, extra):
    # Debian's /usr/bin/chromium is a shell script; the binary it starts takes the same flags.
    binary = "/usr/lib/chromium/chromium" if chromium == "/usr/bin/chromium" and os.path.exists(
        "/usr/lib/chromium/chromium") else chromium
    # WebGL without a GPU: SwiftShader (the compositor stays as it is, faster).
    command = [binary, "--headless", "--enable-unsafe-swiftshader",
               "--user-data-dir=" + profile, "--no-first-run", "--no-default-browser-check",
               "--disable-extensions", "--disable-background-networking", "--disable-sync",
               "--disable-component-update", "--disable-default-apps", "--no-pings",
               "--enable-logging=stderr", "--v=0", "--virtual-time-budget=30000"]
    if os.geteuid() == 0:
        command.append("--no-sandbox")  # Chromium refuses to run as root with its sandbox
    return command + extra


def run_chromium(args, extra, url):
    with tempfile.TemporaryDirectory(prefix="ncc-view-chromium-") as profile:
        command = chromium_command(args.chromium, profile, extra) + [url]
        try:
            done = subprocess.run(command, capture_output=True, timeout=180,
                                  env=dict(os.environ, DBUS_SESSION_BUS_ADDRESS="disabled:"))
        except subprocess.TimeoutExpired:
            fail("chromium did not finish in 180 s: " + " ".join(command))
    stderr = done.stderr.decode("utf-8", "replace")
    # Chromium's own performance notes on WebGL (the page's pixel count stalls the GPU on
    # purpose) are not the page's messages.
    console = [line for line in stderr.splitlines()
               if ":CONSOLE" in line and "GL Driver Message (OpenGL, Performance" not in line]
    return done, console, stderr


def ncc_view(args, program, options, out):
    command = [args.ncc, "view", program, "-o", out] + options
    done = subprocess.run(command, capture_output=True, text=True)
    if not os.path.exists(out):
        fail("ncc view wrote no page (status %d): %s\n%s" % (done.returncode, " ".join(command), done.stderr))
    return done


def trace_blocks(args, program, options):
    """The blocks that moved, in order: (file name, line, X, Y, Z at the end of its events)."""
    command = [args.ncc, "run", program, "--trace-format", "jsonl", "--trace-frame", "machine"] + options
    done = subprocess.run(command, capture_output=True, text=True)
    groups, position, key, moved = [], [0.0, 0.0, 0.0], None, False
    for line in done.stdout.splitlines():
        if not line.startswith("{"):
            continue
        e = json.loads(line)
        k = (os.path.basename(e.get("file", "")), e.get("line", 0))
        if k != key:
            if moved:
                groups.append((key[0], key[1]) + tuple(position))
            key, moved = k, False
        if e.get("event") in MOVES:
            for i, axis in enumerate("XYZ"):
                if axis in e:
                    position[i] = float(e[axis])
            moved = True
    if moved:
        groups.append((key[0], key[1]) + tuple(position))
    return groups


def page_state(args, page, fragment, window="1280,800", extra=()):
    done, console, stderr = run_chromium(args, ["--window-size=" + window, "--dump-dom"] + list(extra),
                                         "file://" + os.path.abspath(page) + "#" + fragment)
    dom = done.stdout.decode("utf-8", "replace")
    m = re.search(r'<pre id="ncc-state"[^>]*>(.*?)</pre>', dom, re.S)
    if not m or not m.group(1).strip():
        fail("no state in the page (%s#%s); chromium said:\n%s" % (page, fragment, stderr[-3000:]))
    state = json.loads(html.unescape(m.group(1)))
    if console:
        fail("the console was not quiet:\n" + "\n".join(console))
    if not state.get("ready"):
        fail("the page is not ready: " + json.dumps(state)[:2000])
    if state.get("errors"):
        fail("the page has errors: %s" % state["errors"])
    if not state.get("webgl"):
        fail("the page got no WebGL context (SwiftShader): %s" % state.get("warnings"))
    canvas = state.get("canvas", {})
    if canvas.get("drawn", 0) < 0.01 * canvas.get("width", 0) * canvas.get("height", 0) or canvas.get("drawn", 0) == 0:
        fail("the canvas is blank: %s" % canvas)
    print("page %s#%s: ready in %d ms, %d blocks, canvas %dx%d with %d pixels drawn (%s)" %
          (os.path.basename(page), fragment, state.get("loadMs", 0), state["blocks"], canvas["width"],
           canvas["height"], canvas["drawn"], state.get("renderer")))
    return state, dom


def close(a, b, tolerance=1.1e-4):
    return all(abs(x - y) <= tolerance for x, y in zip(a, b))


def check_walk(args, program, options, state, names):
    """Every block that moved ends where the trace's events of that block end."""
    origin = state["origin"]
    page = [(names[w[0]], w[1], w[2] + origin[0], w[3] + origin[1], w[4] + origin[2])
            for w in state["walk"][1:] if w[5]]
    trace = trace_blocks(args, program, options)
    if not trace:
        fail("the trace has no moves")
    for i, (p, t) in enumerate(zip(page, trace)):
        if p[:2] != t[:2] or not close(p[2:], t[2:]):
            fail("block %d that moved: the page has %s:%d at %s, the trace %s:%d at %s" %
                 (i + 1, p[0], p[1], p[2:], t[0], t[1], t[2:]))
    if len(page) != len(trace):
        fail("the page has %d blocks that moved, the trace %d" % (len(page), len(trace)))
    print("%d blocks that moved end where the trace's do" % len(page))
    return trace


def data_of(page):
    text = open(page, encoding="utf-8").read()
    m = re.search(r'<script id="ncc-data" type="application/json">(.*?)</script>', text, re.S)
    return json.loads(m.group(1))


def data_steps(data):
    """The number of steps (blocks that ran) of a page's data: -n stands for n steps."""
    steps, at = 0, 0
    while at < len(data["steps"]):
        if data["steps"][at] < 0:
            steps, at = steps - data["steps"][at], at + 1
        else:
            steps, at = steps + 1, at + 2
    return steps


def check_stepping(state, n):
    """Opened at block n and stepped back one, the page stands where block n-1 ends."""
    want = state["walk"][n - 1]
    if state["block"] != n - 1 or state["line"] != want[1] or not close(state["position"], want[2:5], 1e-9):
        fail("#block=%d&step=-1: block %s line %s at %s, expected block %d line %d at %s" %
             (n, state["block"], state["line"], state["position"], n - 1, want[1], want[2:5]))
    print("#block=%d&step=-1 stands at block %d, line %d, %s" % (n, n - 1, want[1], want[2:5]))


def check_measure(state):
    """Clicked where two record ends are drawn, the page picks them and shows dX dY dZ."""
    aimed, picks, text = state.get("aimed"), state.get("picks"), state.get("measured", "")
    if not picks or len(picks) != 2 or not all(close(p, a, 1e-4) for p, a in zip(picks, aimed)):
        fail("clicks at %s picked %s" % (aimed, picks))
    d = [b - a for a, b in zip(picks[0], picks[1])]
    want = "dX %.3f dY %.3f dZ %.3f" % tuple(x + 0.0 for x in d)
    want = want.replace("-0.000", "0.000")
    distance = "distance %.3f mm" % sum(x * x for x in d) ** 0.5
    if want not in text or distance not in text:
        fail("the measure panel says %r, not %r and %r" % (text, want, distance))
    print("two clicks picked %s and %s: %s, %s" % (picks[0], picks[1], want, distance))


def check_surface(state, data, must_cut):
    """The height map is that of the block shown, cut (when `must_cut`), not below the stock."""
    surface = state.get("surface")
    if not data.get("stock") or not surface:
        return
    if surface.get("block") != state["block"]:
        fail("the surface is not that of the block shown: %s" % surface)
    if must_cut and surface.get("cut", 0) == 0:
        fail("the height map is not cut: %s" % surface)
    if surface["lowest"] < data["stock"][2] - 1e-6:
        fail("the height map goes below the stock: %s" % surface)
    print("surface: %d of %d cells cut, the lowest at Z%s" % (surface["cut"], surface["nx"] * surface["ny"],
                                                              surface["lowest"]))


def command_state(args, errors):
    page = os.path.join(args.work, args.name + ".html")
    done = ncc_view(args, args.program, args.options, page)
    if errors and done.returncode == 0:
        fail("ncc view found no error in %s" % args.program)
    if not errors and done.returncode != 0:
        fail("ncc view failed (%d): %s" % (done.returncode, done.stderr))
    data = data_of(page)
    names = [s["name"] for s in data["sources"]]
    n = data_steps(data) // 2 + 1
    fragment = "walk=1&block=%d&step=-1" % n
    if args.measure:
        aims = [int(r) % data["counts"]["records"] for r in args.measure.split(",")]
        fragment += "&measure=%d,%d" % tuple(aims)
    state, dom = page_state(args, page, fragment)
    trace = check_walk(args, args.program, args.options, state, names)
    check_stepping(state, n)
    if args.measure:
        check_measure(state)
    if errors:
        diagnostics = re.search(r'<section id="diagnostics"([^>]*)>(.*?)</section>', dom, re.S)
        if not diagnostics or "hidden" in diagnostics.group(1) or diagnostics.group(2).count("<li") != len(data["diagnostics"]):
            fail("the page does not list its %d diagnostics" % len(data["diagnostics"]))
        last = [w for w in state["walk"] if w[5]][-1]
        origin = state["origin"]
        if not close([last[2] + origin[0], last[3] + origin[1], last[4] + origin[2]], trace[-1][2:]):
            fail("the page's path does not end where the run stopped: %s, %s" % (last, trace[-1]))
        print("the page lists %d diagnostics; its path ends where the run stopped" % len(data["diagnostics"]))
    else:
        check_surface(state, data, False)


# ---- PNG -------------------------------------------------------------------------------
def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail("%s is not a PNG" % path)
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        fail("%s: only 8-bit RGB(A), not interlaced, is read here" % path)
    channels = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), width * channels
    rows, previous, at = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[at], bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        previous = line
    pixels = [row[i:i + 3] for row in rows for i in range(0, stride, channels)]
    return width, height, pixels


def command_screenshot(args):
    page = os.path.join(args.work, args.name + ".html")
    done = ncc_view(args, args.program, args.options, page)
    if done.returncode != 0:
        fail("ncc view failed (%d): %s" % (done.returncode, done.stderr))
    shot = os.path.join(args.work, args.name + ".png")
    if os.path.exists(shot):
        os.remove(shot)
    state, _ = page_state(args, page, "ui=0&view=iso", "640,480", ["--hide-scrollbars", "--screenshot=" + shot])
    if state["block"] != state["blocks"]:
        fail("the page opens at block %s, not at the last, %s" % (state["block"], state["blocks"]))
    check_surface(state, data_of(page), True)
    if not os.path.exists(shot):
        fail("chromium wrote no screenshot")
    if os.environ.get("NCC_VIEW_UPDATE") == "1":
        shutil.copyfile(shot, args.reference)
        print("wrote %s: look at it before committing it" % args.reference)
        return
    w1, h1, got = read_png(shot)
    w2, h2, want = read_png(args.reference)
    if (w1, h1) != (w2, h2):
        fail("the screenshot is %dx%d, the reference %dx%d" % (w1, h1, w2, h2))
    differ, total = 0, 0
    for p, q in zip(got, want):
        d = max(abs(p[0] - q[0]), abs(p[1] - q[1]), abs(p[2] - q[2]))
        total += d
        if d > 48:
            differ += 1
    share = differ / len(got)
    print("screenshot %s: %.3f %% of the pixels differ by more than 48, mean difference %.2f" %
          (shot, 100 * share, total / len(got) / 1.0))
    if share > 0.005:
        fail("the screenshot %s differs from %s in %.2f %% of its pixels" % (shot, args.reference, 100 * share))


# ---- Size and determinism (no browser) ------------------------------------------------
def command_size(args):
    program = os.path.join(args.work, "size.nc")
    with open(program, "w") as f:
        f.write("G17 G21 G90 G54\nG00 X0 Y0 Z5\nG01 Z-1 F500\n")
        for i in range(20000):
            y = (i // 2) * 0.5
            if i % 4 == 0:
                f.write("G01 X100 Y%.1f\n" % y)
            elif i % 4 == 1:
                f.write("G03 X100 Y%.1f R0.25\n" % (y + 0.5))
            elif i % 4 == 2:
                f.write("G01 X0 Y%.1f\n" % y)
            else:
                f.write("G02 X0 Y%.1f R0.25\n" % (y + 0.5))
        f.write("G00 Z5\nM30\n")
    a, b = os.path.join(args.work, "size-a.html"), os.path.join(args.work, "size-b.html")
    for out in (a, b):
        done = ncc_view(args, program, ["--dialect", "iso"], out)
        if done.returncode != 0:
            fail("ncc view failed: %s" % done.stderr)
    if open(a, "rb").read() != open(b, "rb").read():
        fail("two pages of the same program differ")
    empty = os.path.join(args.work, "size-empty.nc")
    with open(empty, "w") as f:
        f.write("M30\n")
    ncc_view(args, empty, ["--dialect", "iso"], os.path.join(args.work, "size-empty.html"))
    base = os.path.getsize(os.path.join(args.work, "size-empty.html"))
    source = os.path.getsize(program)
    per_block = (os.path.getsize(a) - base - source) / 20000
    print("page of 20,000 blocks: %d bytes, %d of them the page itself, %d the source: %.1f bytes a block more" %
          (os.path.getsize(a), base, source, per_block))
    if per_block > 48:
        fail("%.1f bytes a block" % per_block)
    # A parabola's chords (0.001 mm from the curve) merge into records within 0.01 mm.
    out = os.path.join(args.work, "size-parabola.html")
    parabola = os.path.join(args.source, "programs", "gost-parabola.nc")
    ncc_view(args, parabola, ["--dialect", "gost"], out)
    counts = data_of(out)["counts"]
    print("parabolas: %d moves drawn as %d records" % (counts["moves"], counts["records"]))
    if not counts["records"] < counts["moves"]:
        fail("no chords merged: %s" % counts)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ncc", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--source", default=os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("--name", default=None)
    parser.add_argument("--reference")
    parser.add_argument("--measure", help="state: click the ends of these two records (-1: the last)")
    parser.add_argument("command", choices=["state", "errors", "screenshot", "size"])
    parser.add_argument("program", nargs="?")
    parser.add_argument("options", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    if args.command == "size":
        return command_size(args)
    args.name = args.name or os.path.splitext(os.path.basename(args.program))[0]
    args.chromium = find_chromium()
    if not args.chromium:
        print("SKIP: no Chromium found (chromium, chromium-browser, google-chrome or $NCC_CHROMIUM): the browser "
              "tests of ncc view need one; on Debian `.ci/setup` installs the package chromium")
        sys.exit(SKIP)
    if args.command == "screenshot":
        command_screenshot(args)
    else:
        command_state(args, args.command == "errors")


if __name__ == "__main__":
    main()
