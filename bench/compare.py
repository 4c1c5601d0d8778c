#!/usr/bin/env python3
"""ncc's speed and memory on generated programs, side by side with LinuxCNC's rs274.

    bench/compare.py [--quick] [--ncc PATH] [--rs274 PATH | --no-rs274] [--repeat N] [--keep DIR]
                     [--plain N] [--arcs N] [--cycles N] [--loop N] [--flat N]
                     [--dialects iso,gost,pp,nc110] [--kinds plain,arcs,cycles,loop]

Generates the programs of bench/gen.py (defaults: 10^6 plain blocks, 200,000 arc and
cycle blocks, a 200,000-iteration loop; --quick: small sizes for a smoke run), then
for each program measures, one process at a time:

  check    `ncc check` (front end, static checks and the dry run): s and source MB/s
  compile  `ncc compile -o X.ncb` (front end and lowering): s, MB/s, peak RSS and
           its ratio to the source size
  run      `ncc run --trace none` from source (compile and run): s, blocks run per
           second, peak RSS
  ncb      `ncc run X.ncb --trace none`: the VM and runtime alone, s and peak RSS
  canon    iso only: `ncc run --trace-format canon --trace /dev/null`, the output
           rs274 always produces (a fairer match for rs274's own work)
  rs274    iso only: `rs274 -g TWIN.ngc /dev/null` on the LinuxCNC twin (HOME and the
           working directory in a private temporary directory), its s and peak RSS,
           and rs274 s / ncc run s

then checks that a long loop runs in flat memory (iso loop of --flat iterations
against 1,000) and prints the machine, one table and the targets (reported, never
asserted). Wall time by time.perf_counter, peak RSS by GNU time (/usr/bin/time -f
%M; without it, os.wait4, whose figure has this script's own peak as a floor). A
program that fails (non-zero exit, or rs274 printing an error) is marked FAILED with
its first error line, and no number is shown for it; one that prints warnings gets
a NOTE under the table (its times include printing them). Progress goes to stderr,
the report to stdout. Python 3 standard library only.
"""

import argparse
import json
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
sys.path.insert(0, str(HERE))
import gen  # noqa: E402

QUICK = {"plain": 20_000, "arcs": 5_000, "cycles": 5_000, "loop": 5_000, "flat": 100_000}
DEFAULT_FLAT = 1_000_000
MACHINE = {"gost": ["--machine", str(HERE / "gost-n8.toml")]}   # gen.py: 8-digit N
TIMEOUT = 3600

# The targets of the performance issue; reported, not asserted.
T_FRONT_END_MBS = 100.0      # front end on plain blocks, MB/s
T_PLAIN_RATIO = 20.0         # rs274 -g / ncc run, 10^6 plain blocks
T_LOOP_RATIO = 50.0          # rs274 -g / ncc run, SIN/COS loop
T_COMPILE_RSS = 2.0          # peak RSS while compiling / source size
T_FLAT_MB = 1.0              # RSS growth allowed from 10^3 to 10^6 iterations, MB


def log(msg):
    print(msg, file=sys.stderr, flush=True)


# ---------------------------------------------------------------- measuring

class Result:
    def __init__(self, rc, wall, rss, err, out_tail):
        self.rc, self.wall, self.rss, self.err = rc, wall, rss, err   # rss in bytes
        self.out_tail = out_tail                                      # stdout's last 4 KB

    def warnings(self):
        """ncc check's summary line: the number of warnings (0 if none is printed)."""
        m = re.search(r"(\d+) errors?, (\d+) warnings?\s*$", self.out_tail)
        return int(m.group(2)) if m else 0

    def first_error(self):
        for line in self.err.splitlines():
            if line.strip() and line.strip() != "executing":
                return line.strip()[:120]
        return f"exit status {self.rc}"


def gnu_time():
    """GNU time measures a child it forks itself, so the peak RSS is the program's own.
    os.wait4 on a child of this script would not be: a child's peak RSS starts at the
    peak of the process it was forked from (the kernel keeps the larger of the two at
    exec), and this script's own peak, after generating 30 MB of programs, would be
    the floor of every number."""
    path = shutil.which("time") or "/usr/bin/time"
    try:
        p = subprocess.run([path, "--version"], capture_output=True, text=True, timeout=10)
        return path if "GNU" in p.stdout + p.stderr else None
    except (OSError, subprocess.SubprocessError):
        return None


GNU_TIME = gnu_time()


def measure_once(cmd, cwd=None, env=None, timeout=TIMEOUT):
    """Runs cmd; its wall time, peak RSS, stderr and the end of its stdout."""
    with tempfile.TemporaryFile() as err, tempfile.TemporaryFile() as out, \
            tempfile.NamedTemporaryFile("r") as rss_file:
        full = ([GNU_TIME, "-f", "%M", "-o", rss_file.name, "--"] if GNU_TIME else []) + cmd
        t0 = time.perf_counter()
        p = subprocess.Popen(full, stdin=subprocess.DEVNULL, stdout=out,
                             stderr=err, cwd=cwd, env=env)
        timer = threading.Timer(timeout, p.kill)
        timer.start()
        _, status, ru = os.wait4(p.pid, 0)
        wall = time.perf_counter() - t0
        timer.cancel()
        p.returncode = os.waitstatus_to_exitcode(status)
        rss = ru.ru_maxrss * 1024
        if GNU_TIME:
            lines = rss_file.read().split()
            rss = int(lines[-1]) * 1024 if lines and lines[-1].isdigit() else 0
        err.seek(0)
        text = err.read(1 << 20).decode("utf-8", "replace")
        out.seek(max(0, out.seek(0, os.SEEK_END) - 4096))
        tail = out.read().decode("utf-8", "replace")
    return Result(p.returncode, wall, rss, text, tail)


SHORT = 1.0          # s: a run shorter than this is repeated (best of SHORT_REPEAT)
SHORT_REPEAT = 3


def measure(cmd, repeat, ok=lambda r: r.rc == 0, **kw):
    """Best (shortest) of `repeat` runs, and of at least SHORT_REPEAT when the first
    takes less than SHORT seconds (cheap, and a short run is the noisiest); stops at
    the first failing run."""
    best = None
    n = 0
    while n < repeat or (best is not None and best.wall < SHORT and n < SHORT_REPEAT):
        n += 1
        r = measure_once(cmd, **kw)
        r.ok = ok(r)
        if not r.ok:
            return r
        if best is None or r.wall < best.wall:
            best = r
    return best


def rs274_ok(r):
    """rs274 exits 0 after some errors: it must also print nothing but 'executing'."""
    return r.rc == 0 and all(l.strip() in ("", "executing") for l in r.err.splitlines())


def measure_rs274(rs274, program, repeat):
    """rs274 maps its tool table to $HOME/.tool.mmap and may write a parameter file
    in its working directory: both go to a private temporary directory."""
    with tempfile.TemporaryDirectory(prefix="bench-rs274-") as tmp:
        env = {**os.environ, "HOME": tmp}
        return measure([rs274, "-g", str(program), "/dev/null"], repeat, ok=rs274_ok,
                       cwd=tmp, env=env)


def verify_twins(ncc, rs274):
    """The iso programs and their LinuxCNC twins, at small sizes, must make the same
    moves: both canon outputs normalised as the differential suite does
    (tests/diff/linuxcnc/compare.py) and compared call by call. One line of text."""
    suite = REPO / "tests" / "diff" / "linuxcnc"
    if not (suite / "compare.py").exists():
        return "twins:   not verified (tests/diff/linuxcnc/compare.py not found)"
    sys.path.insert(0, str(suite))
    try:
        import compare as diff
    except ImportError as e:
        return f"twins:   not verified ({e})"
    small = {"plain": 300, "arcs": 300, "cycles": 120, "loop": 50}
    done = []
    with tempfile.TemporaryDirectory(prefix="ncc-bench-twins-") as tmp:
        for e in gen.generate(tmp, small, ["iso"], gen.KINDS):
            if e["dialect"] != "iso":
                continue
            twin = Path(e["path"]).with_suffix(".ngc")
            ok, out, err = diff.run_rs274(rs274, twin, [])
            if not ok:
                return f"twins:   {twin.name}: rs274 FAILED: {err.strip()[:200]}"
            pre, body = diff.split_preamble(diff.parse_output(out))
            start = diff.initial_state(pre)
            ref = diff.normalise(body, start)
            ok, out, err = diff.run_ncc(ncc, "iso", Path(e["path"]), [])
            if not ok:
                return f"twins:   {e['name']}: ncc FAILED: {err.strip()[:200]}"
            got = diff.normalise(diff.split_preamble(diff.parse_output(out))[1], start)
            if len(ref) != len(got) or not all(a.same(b) for a, b in zip(ref, got)):
                return f"twins:   {e['name']} and its twin DIFFER ({len(ref)} calls from rs274, {len(got)} from ncc)"
            done.append(f"{e['kind']} {len(ref)}")
    return ("twins:   the same moves at small sizes (tests/diff/linuxcnc normalisation, calls: "
            + ", ".join(done) + ")")


# ---------------------------------------------------------------- the machine

def sh(cmd, cwd=None):
    try:
        return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=30).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return ""


def machine_lines(ncc, rs274):
    cpu, mhz, fam = "unknown CPU", "", ""
    try:
        info = Path("/proc/cpuinfo").read_text()
        m = re.search(r"^model name\s*:\s*(.+)$", info, re.M)
        cpu = m.group(1).strip() if m else cpu
        m = re.search(r"^cpu MHz\s*:\s*([\d.]+)", info, re.M)
        mhz = f" at {float(m.group(1)) / 1000:.2f} GHz" if m else ""
        f_ = re.search(r"^cpu family\s*:\s*(\d+)", info, re.M)
        md = re.search(r"^model\s*:\s*(\d+)", info, re.M)
        fam = f" (family {f_.group(1)} model {md.group(1)})" if f_ and md else ""
    except OSError:
        pass
    ram = ""
    try:
        kb = int(re.search(r"MemTotal:\s*(\d+)", Path("/proc/meminfo").read_text()).group(1))
        ram = f"{kb / 1024 / 1024:.1f} GiB RAM"
    except (OSError, AttributeError):
        pass
    osname = platform.system()
    try:
        m = re.search(r'^PRETTY_NAME="?([^"\n]+)', Path("/etc/os-release").read_text(), re.M)
        osname = m.group(1) if m else osname
    except OSError:
        pass
    virt = " (virtual machine)" if "hypervisor" in (Path("/proc/cpuinfo").read_text()
                                                    if Path("/proc/cpuinfo").exists() else "") else ""
    commit = sh(["git", "rev-parse", "--short", "HEAD"], cwd=REPO) or "unknown"
    dirty = sh(["git", "status", "--porcelain", "--untracked-files=no"], cwd=REPO)
    commit += " + uncommitted changes" if dirty else ""
    cache = {}
    try:
        for line in (REPO / "build" / "CMakeCache.txt").read_text().splitlines():
            m = re.match(r"(CMAKE_CXX_COMPILER|CMAKE_BUILD_TYPE|CMAKE_CXX_FLAGS_RELWITHDEBINFO"
                         r"|CMAKE_CXX_FLAGS_RELEASE):\w+=(.*)", line)
            if m:
                cache[m.group(1)] = m.group(2)
    except OSError:
        pass
    cxx = cache.get("CMAKE_CXX_COMPILER", "c++")
    cxx_version = (sh([cxx, "--version"]).splitlines() or ["unknown compiler"])[0]
    btype = cache.get("CMAKE_BUILD_TYPE", "?")
    flags = cache.get(f"CMAKE_CXX_FLAGS_{btype.upper()}", "")
    lcnc = sh(["dpkg-query", "-W", "-f", "${Version}", "linuxcnc-uspace"])
    load = Path("/proc/loadavg").read_text().split()[:3] if Path("/proc/loadavg").exists() else []
    return [
        f"machine: {cpu}{fam}{mhz}, {os.cpu_count()} cores{virt}, {ram}, {osname}, "
        f"Linux {platform.release()}",
        f"ncc:     {ncc} (commit {commit}), {cxx_version}, {btype} {flags}".rstrip(),
        f"rs274:   {shutil.which(rs274) or rs274}" + (f" (linuxcnc-uspace {lcnc})" if lcnc else ""),
        f"load:    {' '.join(load)} (1, 5, 15 min) at the start",   # the end is added later
    ]


# ---------------------------------------------------------------- the report

def fmt_s(r):
    return f"{r.wall:.2f}" if r and r.ok else "-"


def fmt_rate(x):
    if x >= 1e6:
        return f"{x / 1e6:.2f} M"
    if x >= 1e3:
        return f"{x / 1e3:.0f} k"
    return f"{x:.0f}"


def mb(n):
    return n / 1e6


def table(header, rows):
    """Right-aligned columns, the first one left-aligned."""
    widths = [max(len(str(r[i])) for r in [header] + rows) for i in range(len(header))]
    out = []
    for k, r in enumerate([header] + rows):
        cells = [str(c).ljust(widths[i]) if i == 0 else str(c).rjust(widths[i])
                 for i, c in enumerate(r)]
        out.append("  ".join(cells).rstrip())
        if k == 0:
            out.append("  ".join("-" * w for w in widths))
    return out


def verdict(ok, short):
    return "ok" if ok else f"MISSED ({short})"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ncc", default=str(REPO / "build" / "compiler" / "ncc"))
    ap.add_argument("--rs274", default="rs274")
    ap.add_argument("--no-rs274", action="store_true", help="ncc only")
    ap.add_argument("--quick", action="store_true", help="small sizes: " +
                    ", ".join(f"{k} {v}" for k, v in QUICK.items()))
    ap.add_argument("--repeat", type=int, default=1, help="best of N runs (default 1)")
    ap.add_argument("--keep", metavar="DIR", help="generate into DIR and keep the programs")
    for k in gen.KINDS:
        ap.add_argument(f"--{k}", type=int, help=f"default {gen.DEFAULTS[k]}")
    ap.add_argument("--flat", type=int, help=f"iterations of the flat-memory loop (default {DEFAULT_FLAT})")
    ap.add_argument("--dialects", default=",".join(gen.DIALECTS))
    ap.add_argument("--kinds", default=",".join(gen.KINDS))
    a = ap.parse_args(argv)

    sizes = {k: QUICK[k] if a.quick else gen.DEFAULTS[k] for k in gen.KINDS}
    for k in gen.KINDS:
        if getattr(a, k) is not None:
            sizes[k] = getattr(a, k)
    flat = a.flat or (QUICK["flat"] if a.quick else DEFAULT_FLAT)
    ncc = str(Path(a.ncc).resolve())
    if not os.access(ncc, os.X_OK):
        sys.exit(f"compare.py: no ncc at {ncc} (build it, or give --ncc)")
    have_rs274 = shutil.which(a.rs274) is not None and not a.no_rs274
    if not have_rs274 and not a.no_rs274:
        log(f"compare.py: {a.rs274} not found: the LinuxCNC columns stay empty")

    started = time.perf_counter()
    header_lines = machine_lines(ncc, a.rs274)
    if have_rs274 and "iso" in a.dialects.split(","):
        log("verifying the LinuxCNC twins at small sizes ...")
        header_lines.append(verify_twins(ncc, a.rs274))
    tmp = None
    if a.keep:
        outdir = Path(a.keep)
    else:
        tmp = tempfile.TemporaryDirectory(prefix="ncc-bench-")
        outdir = Path(tmp.name)
    log(f"generating into {outdir}: {sizes}")
    t0 = time.perf_counter()
    entries = gen.generate(outdir, sizes, [d for d in a.dialects.split(",") if d],
                           [k for k in a.kinds.split(",") if k], log=log)
    gen_s = time.perf_counter() - t0
    twins = {e["name"]: e for e in entries if e["dialect"] == "ngc"}
    progs = [e for e in entries if e["dialect"] != "ngc"]

    rows, notes, res = [], [], {}
    for n, e in enumerate(progs, 1):
        name, d, path = e["name"], e["dialect"], e["path"]
        args = ["--dialect", d] + MACHINE.get(d, [])
        ncb = str(outdir / (name + ".ncb"))
        log(f"[{n}/{len(progs)}] {name} ({mb(e['bytes']):.1f} MB, {e['blocks_run']} blocks run)")
        r = {}
        steps = [("check", [ncc, "check", path] + args),
                 ("compile", [ncc, "compile", path] + args + ["-o", ncb]),
                 ("run", [ncc, "run", path] + args + ["--trace", "none"]),
                 ("ncb", [ncc, "run", ncb] + MACHINE.get(d, []) + ["--trace", "none"])]
        if d == "iso":
            steps.append(("canon", [ncc, "run", path] + args
                          + ["--trace-format", "canon", "--trace", "/dev/null"]))
        for step, cmd in steps:
            if step == "ncb" and not (r.get("compile") and r["compile"].ok):
                continue
            log(f"    ncc {step} ...")
            r[step] = measure(cmd, a.repeat)
            log(f"    ncc {step}: {r[step].wall:.2f} s, {mb(r[step].rss):.0f} MB"
                + ("" if r[step].ok else f"  FAILED: {r[step].first_error()}"))
            if not r[step].ok:
                notes.append(f"{name}: ncc {step} FAILED: {r[step].first_error()}")
            elif step == "check" and r[step].warnings():
                notes.append(f"{name}: ncc check reports {r[step].warnings()} warnings: the times "
                             "include printing them (gen.py should write clean programs)")
            elif step != "check" and r[step].err.strip():
                notes.append(f"{name}: ncc {step} printed diagnostics: {r[step].first_error()}")
        twin = twins.get(name)
        if twin and have_rs274:
            log(f"    rs274 -g {Path(twin['path']).name} ...")
            r["rs274"] = measure_rs274(a.rs274, twin["path"], a.repeat)
            log(f"    rs274: {r['rs274'].wall:.2f} s, {mb(r['rs274'].rss):.0f} MB"
                + ("" if r["rs274"].ok else f"  FAILED: {r['rs274'].first_error()}"))
            if not r["rs274"].ok:
                notes.append(f"{name}: rs274 FAILED: {r['rs274'].first_error()}")
        if os.path.exists(ncb):
            os.remove(ncb)
        res[name] = (e, r)

        def ok(step):
            return r.get(step) is not None and r[step].ok
        size = e["bytes"]
        blocks = e["blocks_run"]
        ratio = (r["rs274"].wall / r["run"].wall) if ok("rs274") and ok("run") else None
        per_byte = e["kind"] != "loop"          # the loop's source is a few hundred bytes
        rows.append([
            name, f"{mb(size):.1f}", fmt_rate(blocks),
            fmt_s(r.get("check")), f"{mb(size) / r['check'].wall:.2f}" if ok("check") and per_byte else "-",
            fmt_s(r.get("compile")),
            f"{mb(size) / r['compile'].wall:.2f}" if ok("compile") and per_byte else "-",
            f"{mb(r['compile'].rss):.0f}" if ok("compile") else "-",
            f"{r['compile'].rss / size:.1f}x" if ok("compile") and per_byte else "-",
            fmt_s(r.get("run")), fmt_rate(blocks / r["run"].wall) if ok("run") else "-",
            f"{mb(r['run'].rss):.0f}" if ok("run") else "-",
            fmt_s(r.get("ncb")),
            f"{mb(r['ncb'].rss):.0f}" if ok("ncb") else "-",
            fmt_s(r.get("canon")) if d == "iso" else "",
            fmt_s(r.get("rs274")) if twin else "",
            f"{mb(r['rs274'].rss):.0f}" if ok("rs274") else ("-" if twin else ""),
            f"{ratio:.2f}x" if ratio else ("-" if twin else ""),
        ])

    # Flat memory: the same loop with 1,000 and `flat` iterations (the source differs
    # only in the count), ncc run without a trace.
    flat_res = None
    if "iso" in a.dialects.split(","):
        small = outdir / "iso-loop-1000.nc"
        large = outdir / f"iso-loop-{flat}.nc"
        small.write_text(gen.loop("iso", 1000).text())
        large.write_text(gen.loop("iso", flat).text())
        log(f"flat memory: iso loop of 1000 and {flat} iterations ...")
        rs = [measure([ncc, "run", str(p), "--dialect", "iso", "--trace", "none"], a.repeat)
              for p in (small, large)]
        if all(x.ok for x in rs):
            flat_res = rs
        else:
            notes.append("flat-memory loop FAILED: " + "; ".join(x.first_error() for x in rs if not x.ok))
        log("    " + ", ".join(f"{x.wall:.2f} s {mb(x.rss):.1f} MB" for x in rs))
    total_s = time.perf_counter() - started
    load_end = " ".join(Path("/proc/loadavg").read_text().split()[:3]) if Path("/proc/loadavg").exists() else "?"
    header_lines = [l + f", {load_end} at the end" if l.startswith("load:") else l for l in header_lines]

    # ------------------------------------------------------------ print
    out = []
    out += header_lines
    out.append(f"sizes:   plain {sizes['plain']:,} blocks, arcs {sizes['arcs']:,}, cycles "
               f"{sizes['cycles']:,} (blocks of the body), loop {sizes['loop']:,} iterations; "
               f"best of {a.repeat} ({max(a.repeat, SHORT_REPEAT)} for runs under {SHORT:.0f} s); generated in {gen_s:.1f} s, whole run {total_s / 60:.1f} min")
    out.append("")
    hdr = ["program", "MB", "blocks", "check s", "MB/s", "compile s", "MB/s", "RSS MB", "RSS/src",
           "run s", "blocks/s", "RSS MB", "ncb s", "RSS MB", "canon s", "rs274 s", "RSS MB", "rs274/ncc"]
    out += table(hdr, rows)
    out.append("")
    out.append("check = ncc check (front end + checks + dry run); compile = ncc compile -o .ncb; run = ncc run "
               "--trace none from source (compile + run);")
    out.append("ncb = ncc run of the compiled .ncb (VM + runtime alone); canon = ncc run with the canon trace "
               "to /dev/null (iso);")
    out.append("rs274 = rs274 -g TWIN.ngc /dev/null (LinuxCNC twin); rs274/ncc = rs274 s / run s; "
               "blocks = blocks run (loop: 5 per iteration).")
    if not GNU_TIME:
        out.append("peak RSS by os.wait4 (no GNU time): each figure has this script's own peak as a floor.")

    # Targets.
    out.append("")
    out.append("targets (reported, not asserted):")
    tl = []
    for d in a.dialects.split(","):
        e_r = res.get(f"{d}-plain")
        if e_r and e_r[1].get("check") and e_r[1]["check"].ok:
            e, r = e_r
            v = mb(e["bytes"]) / r["check"].wall
            tl.append([f"front end, {d} plain blocks (ncc check)", f">= {T_FRONT_END_MBS:.0f} MB/s",
                       f"{v:.2f} MB/s", verdict(v >= T_FRONT_END_MBS, f"{T_FRONT_END_MBS / v:.1f}x short")])
    for kind, target, what in (("plain", T_PLAIN_RATIO, f"{sizes['plain']:,} plain blocks"),
                               ("loop", T_LOOP_RATIO, f"{sizes['loop']:,}-iteration SIN/COS loop")):
        e_r = res.get(f"iso-{kind}")
        if e_r and e_r[1].get("rs274") and e_r[1]["rs274"].ok and e_r[1]["run"].ok:
            e, r = e_r
            v = r["rs274"].wall / r["run"].wall
            tl.append([f"ncc run vs rs274 -g, {what}", f">= {target:.0f}x faster", f"{v:.2f}x",
                       verdict(v >= target, f"{target / v:.1f}x short" if v < target else "")])
    for d in a.dialects.split(","):
        e_r = res.get(f"{d}-plain")
        if e_r and e_r[1].get("compile") and e_r[1]["compile"].ok:
            e, r = e_r
            v = r["compile"].rss / e["bytes"]
            tl.append([f"peak RSS compiling {d} plain / source size", f"<= {T_COMPILE_RSS:.0f}x",
                       f"{v:.1f}x ({mb(r['compile'].rss):.0f} MB for {mb(e['bytes']):.1f} MB)",
                       verdict(v <= T_COMPILE_RSS, f"{v / T_COMPILE_RSS:.1f}x over")])
    for d in a.dialects.split(","):
        e_r = res.get(f"{d}-plain")
        if e_r and all(e_r[1].get(step) and e_r[1][step].ok for step in ("compile", "ncb")):
            e, r = e_r
            tl.append([f"peak RSS running {d} plain .ncb / compiling", "< 1x",
                       f"{r['ncb'].rss / r['compile'].rss:.2f}x ({mb(r['ncb'].rss):.0f} MB)",
                       verdict(r["ncb"].rss < r["compile"].rss, "more")])
    if flat_res:
        grow = mb(flat_res[1].rss - flat_res[0].rss)
        tl.append([f"iso loop of {flat:,} iterations in flat memory", f"<= +{T_FLAT_MB:.0f} MB over 1,000",
                   f"{mb(flat_res[0].rss):.1f} -> {mb(flat_res[1].rss):.1f} MB ({flat_res[1].wall:.2f} s, "
                   f"{fmt_rate(5 * flat / flat_res[1].wall)} blocks/s)",
                   verdict(grow <= T_FLAT_MB, f"+{grow:.1f} MB")])
    out += ["  " + line for line in table(["target", "wanted", "measured", ""], tl)]
    if notes:
        out.append("")
        out += ["NOTE: " + n for n in notes]
    print("\n".join(out))
    if tmp:
        tmp.cleanup()
    return 1 if notes else 0


if __name__ == "__main__":
    sys.exit(main())
