#!/usr/bin/env python3
"""Do two runs make the same motion? The judge of `ncc translate`.

Compares two traces of `ncc run --trace-format jsonl --trace-frame machine`, per
process, as sequences of observable items, every length in mm: moves (rapid, linear,
arc, parabola, spline, thread, operator_move: the end on every axis and the curve's
geometry, with the spindle, coolants, tool and tool length offset in force, and for a
fed move the feed mode and feed), probes, dwells, tool changes, stops, aux functions,
part changes, the end, and any event not known here. Other events only set state.
A move that goes nowhere is dropped. Lengths and angles agree within the tolerance,
feeds, speeds and dwells relatively within 1e-9. `--help` lists the options.

usage: equivalent.py [--tolerance MM] [--show] [--start X=..,Y=..]
                     [--initial-a KEY=VALUE,..] [--initial-b KEY=VALUE,..] A.jsonl B.jsonl
Exit status 0: equivalent ("equivalent: N moves"); 1: not (the first differences);
2: usage or input errors. Test scripts import compare(events_a, events_b, tolerance).
"""
import argparse
import json
import math
import sys

AXES = "XYZABCUVWPQD"
ANGULAR = "ABC"  # rotary axes (degrees); the others are lengths (an indexing axis: see --help)
MM_PER_INCH = 25.4
M_PER_FOOT = 0.3048
RELATIVE = 1e-9

MOVES = ("rapid", "linear", "arc", "parabola", "spline", "thread", "operator_move")
FED = ("linear", "arc", "parabola", "spline")  # the moves made at the programmed feed
META = ("seq", "file", "line", "col", "process", "block", "event")
# Events that only set state (or show something to the operator): never items.
STATE_ONLY = frozenset((
    "units", "plane", "feed_mode", "feed_rate", "spindle_mode", "spindle_speed", "spindle_on",
    "spindle_stop", "spindle_orient", "coolant", "tool_select", "tool_length_offset",
    "cutter_comp", "work_offset", "position_offset", "origin", "transform", "tolerance",
    "limits", "zone", "configuration", "comment", "message", "block", "path", "clamp",
    "override", "spindle_hold", "spindle_range", "diameter", "feed_reduction", "offset_load",
    "comp_load", "input", "screen", "sync", "asset", "graphic", "tooling", "virtual"))

POINT_FIELDS = ("end", "centre", "control", "control1", "control2", "tool_offset")
TOLERANCE_FIELDS = ("radius", "sweep", "pitch", "pitch_change", "phase", "orient")
RELATIVE_FIELDS = ("feed", "speed", "seconds")
STATE_FIELDS = ("feed_mode", "feed", "spindle", "spindle_mode", "speed", "orient", "coolant", "tool",
                "tool_offset")


class Item:
    """One observable thing a run does: kind, fields (name -> value) and where."""
    __slots__ = ("kind", "fields", "where")

    def __init__(self, kind, fields, where):
        self.kind, self.fields, self.where = kind, fields, where

    def __repr__(self):
        return f"Item({self.kind!r}, {self.fields!r}, {self.where!r})"

    def text(self):
        f = dict(self.fields)
        point = lambda p: " ".join(f"{a}{number(v)}" for a, v in p.items() if a in "XYZ" or v != 0) or "none"
        parts = [self.kind]
        if "end" in f:
            parts.append(point(f.pop("end")))
        if "kind" in f:
            parts.append(str(f.pop("kind")))
        for name, v in list(f.items()):
            if name not in STATE_FIELDS:
                parts.append(f"{name} {point(v) if isinstance(v, dict) else number(v)}")
        if "feed_mode" in f:
            mode, feed = f["feed_mode"], f["feed"]
            per = {"per_minute": "/min", "per_revolution": "/rev", "inverse_time": " inverse time"}
            parts.append(f"F{number(feed)}{per.get(mode, ' (no feed_mode yet)')}" if feed is not None else "F none")
        if "spindle" in f:
            s = f"spindle {f['spindle']}"
            if "speed" in f:
                unit = "m/min" if f["spindle_mode"] == "constant_surface" else "rpm"
                s += f" {number(f['speed'])} {unit}"
            if "orient" in f:
                s += f" {number(f['orient'])}"
            parts.append(s)
        if "coolant" in f:
            parts.append("coolant " + ("+".join(f["coolant"]) or "off"))
        if "tool" in f:
            parts.append(f"tool {'-' if f['tool'] is None else f['tool']}")
        if f.get("tool_offset"):
            parts.append(f"length offset {point(f['tool_offset'])}")
        return " ".join(parts)


def number(v):
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "null"
    return format(v, ".12g") if isinstance(v, float) else str(v)


def value(v):
    """A JSON number (null: not finite) as a float."""
    return float("nan") if v is None else float(v)


def parse(events):
    """JSON objects, or JSON Lines strings (blank ones skipped), as dicts."""
    return [json.loads(e) if isinstance(e, (str, bytes)) else e for e in events
            if not isinstance(e, (str, bytes)) or e.strip()]


def load(path):
    """The events of a JSON Lines trace file (ValueError names the line that is not JSON)."""
    events = []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if line.strip():
                try:
                    events.append(json.loads(line))
                except json.JSONDecodeError as e:
                    raise ValueError(f"{path}:{n}: not JSON: {e}") from None
    return events


class Reducer:
    """Turns one process's events into items, keeping the state they carry.

    Items (lengths in mm, angles in degrees):
      rapid linear arc parabola spline thread operator_move: `end` (every axis traced);
        arc: plane, direction, centre, radius, sweep; parabola: control; spline:
        control1, control2; thread: pitch, pitch_change, phase. Each carries the
        spindle (stop/cw/ccw/orient; spindle_mode and speed while it turns, rpm or
        m/min; the angle when oriented), coolant (the set on), tool (loaded) and
        tool_offset; linear arc parabola spline also feed_mode and feed (mm/min,
        mm/rev, or 1/min inverse time; F/100 under feed_reduction; F read in the
        units in force at the move, as the runtime reads it). Dropped when it goes
        nowhere: the end within half the tolerance of the previous end, an arc's sweep
        ~0, a curve's controls there too (not the first move unless the start is
        known).
      probe: end, contact, and the state of a rapid. dwell: seconds, spindle, coolant.
      tool_change: tool (a change to the tool loaded is none), spindle and coolants then. stop, end: kind. aux: function. part_change.
      Any other event not in STATE_ONLY: all its fields, compared exactly.
    """

    def __init__(self, tolerance, start, initial, angular):
        initial = initial or {}
        self.tolerance = tolerance
        self.angular = angular
        self.pos = dict(start) if start is not None else None  # mm / degrees
        self.inch = initial.get("units") == "inch"
        self.feed_mode = initial.get("feed_mode")  # None: not traced yet
        self.feed = initial.get("feed")  # as programmed: read in the units in force at each move
        self.reduced = False
        self.spindle = "stop"
        self.spindle_mode = initial.get("spindle_mode", "rpm")
        self.speed = 0.0
        self.orient = 0.0
        self.coolant = set()
        self.tool = None
        self.tool_offset = {}
        self.items = []

    def length(self, v):
        return v * MM_PER_INCH if self.inch else v

    def point(self, e, keys=AXES):
        k = MM_PER_INCH if self.inch else 1.0
        p = {}
        for a in keys:
            v = e.get(a, self)
            if v is not self:
                v = float("nan") if v is None else float(v)
                p[a] = v if a in self.angular else v * k
        return p

    def near(self, p, q, share=1.0):
        if p is None or q is None:
            return False
        if p == q:
            return True
        return all(close(p.get(a, 0.0), q.get(a, 0.0), self.tolerance * share) for a in set(p) | set(q))

    def machine_state(self, fed):
        s = {}
        if fed:
            s["feed_mode"] = self.feed_mode
            f = None if self.feed is None else value(self.feed)
            if f is not None and self.feed_mode != "inverse_time":
                f = self.length(f)
            if f is not None and self.reduced:
                f /= 100
            s["feed"] = f
        s["spindle"] = self.spindle
        if self.spindle in ("cw", "ccw"):
            speed = value(self.speed)
            if self.spindle_mode == "constant_surface" and self.inch:
                speed *= M_PER_FOOT  # ft/min -> m/min, as the runtime reads S under G96
            s["spindle_mode"] = self.spindle_mode
            s["speed"] = speed
        elif self.spindle == "orient":
            s["orient"] = value(self.orient)
        s["coolant"] = tuple(sorted(self.coolant))
        return s

    def add(self, kind, fields, e):
        self.items.append(Item(kind, fields, (e.get("file", ""), e.get("line", 0), e.get("block"))))

    def event(self, e):
        name = e.get("event")
        if name == "units":
            self.inch = e.get("units") == "inch"
        elif name == "feed_mode":
            if self.feed_mode is not None and e.get("mode") != self.feed_mode:
                self.feed = None  # the runtime forgets F when the mode changes
            self.feed_mode = e.get("mode")
        elif name == "feed_rate":
            self.feed = e.get("value")
        elif name == "feed_reduction":
            self.reduced = bool(e.get("on"))
        elif name == "spindle_mode":
            self.spindle_mode = e.get("mode")
        elif name == "spindle_speed":
            self.speed = e.get("value")
        elif name == "spindle_on":
            self.spindle = e.get("direction")
        elif name == "spindle_stop":
            self.spindle = "stop"
        elif name == "spindle_orient":
            self.spindle, self.orient = "orient", e.get("angle", 0)
        elif name == "coolant":
            c = e.get("coolant")
            if c == "off":
                self.coolant -= {"mist", "flood"}
            elif c == "off_3_4":
                self.coolant -= {"3", "4"}
            else:
                self.coolant.add(c)
        elif name == "tool_length_offset":
            self.tool_offset = {a: v for a, v in self.point(e).items() if v != 0}
        elif name in MOVES or name == "probe":
            self.move(name, e)
        elif name == "tool_change":
            # A change to the tool in the spindle changes nothing (ISO's M06 ignores it).
            if e.get("tool") != self.tool:
                self.tool = e.get("tool")
                # With the spindle and coolants as they are then: a change while the
                # spindle turns is not the same change.
                state = self.machine_state(False)
                self.add("tool_change", {"tool": self.tool, "spindle": state["spindle"],
                                         "coolant": state["coolant"]}, e)
        elif name == "dwell":
            fields = {"seconds": value(e.get("seconds"))}
            fields.update(self.machine_state(False))
            self.add("dwell", fields, e)
        elif name in ("stop", "end"):
            self.add(name, {"kind": e.get("kind")}, e)
            if name == "end":
                self.feed = None  # M02/M30 reset the feed (to the profile's, not traced)
        elif name == "aux":
            self.add("aux", {"function": e.get("function")}, e)
        elif name in STATE_ONLY:
            pass
        else:  # an event this script does not know: compare all it says
            self.add(name, {k: v for k, v in e.items() if k not in META}, e)

    def move(self, kind, e):
        end = self.point(e)
        fields = {"end": end}
        if kind == "arc":
            plane = e.get("plane", "")
            fields["plane"] = plane
            fields["direction"] = e.get("direction")
            fields["centre"] = self.point(e.get("centre", {}), plane)
            fields["radius"] = self.length(value(e.get("radius")))
            fields["sweep"] = value(e.get("sweep"))
        elif kind == "parabola":
            fields["control"] = self.point(e.get("control", {}))
        elif kind == "spline":
            fields["control1"] = self.point(e.get("control1", {}))
            fields["control2"] = self.point(e.get("control2", {}))
        elif kind == "thread":
            fields["pitch"] = self.length(value(e.get("pitch", 0)))
            fields["pitch_change"] = self.length(value(e.get("pitch_change", 0)))
            fields["phase"] = value(e.get("phase", 0))
        elif kind == "probe":
            fields["contact"] = bool(e.get("contact"))
        # Nowhere: within half the tolerance, what rounding a point to the tolerance's step
        # can make of a move (a translation's 0.001 mm is the source's 0.001016).
        if kind != "probe" and self.near(end, self.pos, 0.5):
            curve = [fields[k] for k in ("control", "control1", "control2") if k in fields]
            flat = kind != "arc" or close(fields["sweep"], 0.0, self.tolerance)
            if flat and all(self.near(c, self.pos, 0.5) for c in curve):
                return  # goes nowhere: a translation may or may not write it
        self.pos = dict(end)
        fields.update(self.machine_state(kind in FED))
        fields["tool"] = self.tool
        fields["tool_offset"] = self.tool_offset
        self.add(kind, fields, e)


def reduce(events, tolerance=1e-6, start=None, initial=None, angular=ANGULAR):
    """{process: [Item]} (process 0: a run of one), processes in order of appearance.
    initial: the state the run starts in that its trace does not show, e.g.
    {"units": "inch", "feed_mode": "per_minute", "spindle_mode": "rpm", "feed": 100}."""
    reducers = {}
    for e in parse(events):
        p = e.get("process", 0)
        if p not in reducers:
            reducers[p] = Reducer(tolerance, start, initial, angular)
        reducers[p].event(e)
    return {p: r.items for p, r in reducers.items()}


def close(a, b, tolerance):
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= tolerance


def relatively_close(a, b, relative=RELATIVE):
    if a is None or b is None:
        return a is None and b is None
    if math.isnan(a) or math.isnan(b):
        return math.isnan(a) and math.isnan(b)
    return abs(a - b) <= relative * max(abs(a), abs(b))


def field_differences(x, y, tolerance, relative=RELATIVE):
    """What differs between two items: ["X 60.8 / 60.81", ...]; [] when they agree."""
    if x.kind != y.kind:
        return [f"{x.kind} / {y.kind}"]
    if x.fields == y.fields:  # the same numbers (NaN never equals itself: looked at below)
        return []
    out = []
    for name in list(x.fields) + [n for n in y.fields if n not in x.fields]:
        a, b = x.fields.get(name), y.fields.get(name)
        if name in ("spindle_mode", "speed", "orient") and x.fields.get("spindle") != y.fields.get("spindle"):
            continue  # the spindle's direction differs: that says it
        if name in POINT_FIELDS and isinstance(a, dict) and isinstance(b, dict):
            for axis in [k for k in AXES if k in a or k in b]:
                u, v = a.get(axis, 0.0), b.get(axis, 0.0)
                if not close(u, v, tolerance):
                    label = axis if name == "end" else f"{name} {axis}"
                    out.append(f"{label} {number(u)} / {number(v)}{by(u, v)}")
        elif name == "sweep" and a is not None and b is not None:
            # Within the tolerance in degrees, or along the arc in mm: as the radius, by
            # twice as much (its ends and its centre each within the tolerance; a 0.3 mm
            # arc of a CAM program rounded to 0.0001 mm).
            r = max(x.fields.get("radius", 0.0), y.fields.get("radius", 0.0))
            if not (close(a, b, tolerance) or abs(a - b) * math.pi / 180 * r <= 2 * tolerance):
                out.append(f"sweep {number(a)} / {number(b)}{by(a, b)}")
        elif name in TOLERANCE_FIELDS and a is not None and b is not None:
            # An arc's radius comes from two points each within the tolerance: it may
            # move by twice as much (a 0.5 mm arc rounded to 0.0001 mm).
            if not close(a, b, 2 * tolerance if name == "radius" else tolerance):
                out.append(f"{name} {number(a)} / {number(b)}{by(a, b)}")
        elif name in RELATIVE_FIELDS:
            if not relatively_close(a, b, relative):
                out.append(f"{name} {number(a)} / {number(b)}")
        elif a != b:
            out.append(f"{name} {shown(name, a)} / {shown(name, b)}")
    return out


def shown(name, v):
    if name == "coolant" and isinstance(v, tuple):
        return "+".join(v) or "off"
    return "none" if v is None else number(v)


def by(a, b):
    return f" (by {number(b - a)})" if math.isfinite(a) and math.isfinite(b) else ""


def where(item, main):
    """`line N`; `FILE:N` in a trace of several files (main is None)."""
    file, line, block = item.where
    return (f"line {line}" if main is not None else f"{file}:{line}") + (f" {block}" if block else "")


# Rounding two points to a step moves each by half of it: a straight move of up to one
# step on each axis may come to nothing in one trace and be there in the other
# (X4.72637 after X4.725712 is X4.726 again in 0.001; Z0.859499 and Z0.8595 are Z0.859
# and Z0.86). The share of the tolerance, with room for the step's float error.
SHORT = 1 + 1e-9


def compare_items(xs, ys, tolerance, label="", mains=("", ""), limit=10, relative=RELATIVE):
    """Differences between two item sequences of one process."""
    out = []
    same = lambda i, j: not field_differences(xs[i], ys[j], tolerance, relative)

    def aligned(i, j):  # the next items (up to 3) agree from here on, short moves of either aside
        n = 0
        while n < 3 and i < len(xs) and j < len(ys):
            if same(i, j):
                i, j, n = i + 1, j + 1, n + 1
            elif short(xs, i, 1):
                i += 1
            elif short(ys, j, 1):
                j += 1
            else:
                return False
        return n > 0

    def short(items, n, count):  # straight moves of up to a step each: what rounding makes or unmakes
        return all(items[k].kind in ("linear", "rapid") and k > 0 and "end" in items[k - 1].fields and
                   all(close(items[k].fields["end"].get(a, 0.0), items[k - 1].fields["end"].get(a, 0.0), tolerance * SHORT)
                       for a in set(items[k].fields["end"]) | set(items[k - 1].fields["end"]))
                   for k in range(n, n + count))

    def show(side, n, item):
        return f"  {side} item {n + 1}, {where(item, mains[side == 'B'])}: {item.text()}"

    i = j = 0
    while i < len(xs) and j < len(ys) and len(out) < limit:
        diffs = field_differences(xs[i], ys[j], tolerance, relative)
        if not diffs:
            i, j = i + 1, j + 1
            continue
        skip = next(((s, 0) for s in (1, 2, 3) if aligned(i + s, j)), None) or \
            next(((0, s) for s in (1, 2, 3) if aligned(i, j + s)), None)
        if skip and (short(xs, i, skip[0]) if skip[0] else short(ys, j, skip[1])):
            i, j = i + skip[0], j + skip[1]  # a move of a step that one side's rounding made nothing, or something
        elif skip and skip[0]:
            extra = "\n".join(show("A", i + k, xs[i + k]) for k in range(skip[0]))
            out.append(f"{label}A has {skip[0]} item(s) more before item {j + 1} of B:\n{extra}")
            i += skip[0]
        elif skip:
            extra = "\n".join(show("B", j + k, ys[j + k]) for k in range(skip[1]))
            out.append(f"{label}B has {skip[1]} item(s) more before item {i + 1} of A:\n{extra}")
            j += skip[1]
        else:
            out.append(f"{label}item {i + 1}" + (f" (B: {j + 1})" if i != j else "") +
                       f": {'; '.join(diffs)}\n{show('A', i, xs[i])}\n{show('B', j, ys[j])}")
            i, j = i + 1, j + 1
    if len(out) < limit and (i < len(xs)) != (j < len(ys)):
        if i == len(xs):
            short, stop, side, items, n = "A", i, "B", ys, j
        else:
            short, stop, side, items, n = "B", j, "A", xs, i
        more = len(items) - n - 1
        out.append(f"{label}{short} stops after {stop} items, {side} goes on with item {n + 1}"
                   f"{f' and {more} more' if more else ''}:\n{show(side, n, items[n])}")
    return out


def compare(events_a, events_b, tolerance=1e-6, *, start=None, initial=(None, None),
            angular=ANGULAR, limit=10, relative=RELATIVE):
    """The differences between the motion of two traces (lists of event dicts or JSON
    Lines strings): [] when they make the same motion. At most `limit` of them. Feeds,
    speeds and dwells agree to `relative` of themselves."""
    events_a, events_b = parse(events_a), parse(events_b)
    a = reduce(events_a, tolerance, start, initial[0], angular)
    b = reduce(events_b, tolerance, start, initial[1], angular)
    return compare_reduced(a, b, tolerance, (main_file(events_a), main_file(events_b)), limit, relative)


def main_file(events):
    """The file of every event, or None when they come from several."""
    files = {e.get("file", "") for e in events}
    return files.pop() if len(files) == 1 else None if files else ""


def compare_reduced(a, b, tolerance=1e-6, mains=("", ""), limit=10, relative=RELATIVE):
    """compare() on the items of reduce()."""
    out = []
    for p in list(a) + [p for p in b if p not in a]:
        label = f"process {p}, " if p else ""
        out += compare_items(a.get(p, []), b.get(p, []), tolerance, label, mains, limit - len(out), relative)
        if len(out) >= limit:
            break
    return out


def move_count(items_by_process):
    return sum(1 for items in items_by_process.values() for it in items if it.kind in MOVES)


def parse_start(text):
    start = {}
    for part in filter(None, text.replace(" ", ",").split(",")):
        axis, _, v = part.partition("=")
        if axis.upper() not in AXES or not v:
            raise argparse.ArgumentTypeError(f"--start: '{part}' is not AXIS=VALUE")
        start[axis.upper()] = float(v)
    return start


INITIAL = {"units": ("mm", "inch"), "feed_mode": ("per_minute", "per_revolution", "inverse_time"),
           "spindle_mode": ("rpm", "constant_surface"), "feed": None}


def parse_initial(text):
    initial = {}
    for part in filter(None, text.split(",")):
        key, _, v = part.strip().partition("=")
        if key not in INITIAL or not v or (INITIAL[key] and v not in INITIAL[key]):
            raise argparse.ArgumentTypeError(f"'{part}': units=mm|inch, feed_mode=per_minute|per_revolution|"
                                             "inverse_time, spindle_mode=rpm|constant_surface or feed=F")
        initial[key] = float(v) if key == "feed" else v
    return initial


def main(argv=None):
    ap = argparse.ArgumentParser(description="Do two runs (ncc run --trace-format jsonl "
                                 "--trace-frame machine) make the same motion?")
    ap.add_argument("--tolerance", type=float, default=1e-6, metavar="MM",
                    help="positions in mm, angles in degrees (default 1e-6)")
    ap.add_argument("--show", action="store_true", help="print both reduced sequences")
    ap.add_argument("--start", type=parse_start, metavar="X=..,Y=..",
                    help="where both runs start, machine coordinates in mm")
    for side in "ab":
        ap.add_argument(f"--initial-{side}", type=parse_initial, default={}, metavar="KEY=VALUE,..",
                        help=f"the state run {side.upper()} starts in that its trace does not show: units=mm|inch, "
                        "feed_mode=per_minute|per_revolution|inverse_time, spindle_mode=rpm|constant_surface, "
                        "feed=F (default: units=mm,spindle_mode=rpm; the feed and its mode unknown)")
    ap.add_argument("--angular", default=ANGULAR, metavar="AXES",
                    help="the axes whose positions are angles or index counts, not lengths (default ABC)")
    ap.add_argument("a", metavar="A.jsonl")
    ap.add_argument("b", metavar="B.jsonl")
    args = ap.parse_args(argv)
    try:
        events_a, events_b = load(args.a), load(args.b)
    except (OSError, ValueError) as e:
        print(f"equivalent.py: {e}", file=sys.stderr)
        return 2
    angular = args.angular.upper()
    mains = (main_file(events_a), main_file(events_b))
    a = reduce(events_a, args.tolerance, args.start, args.initial_a, angular)
    b = reduce(events_b, args.tolerance, args.start, args.initial_b, angular)
    if args.show:
        for side, path, items_by_process, main in (("A", args.a, a, mains[0]), ("B", args.b, b, mains[1])):
            for p, items in items_by_process.items():
                print(f"{side} {path}{f' process {p}' if p else ''}: {len(items)} items")
                for n, item in enumerate(items, 1):
                    print(f"  {n:4} {where(item, main):>10}  {item.text()}")
    for side, events, items_by_process in (("A", events_a, a), ("B", events_b, b)):
        if not any(it.kind == "end" for items in items_by_process.values() for it in items):
            print(f"note: {side} has {'no events' if not events else 'no end'}: did its run stop on an error?",
                  file=sys.stderr)
    differences = compare_reduced(a, b, args.tolerance, mains)
    if differences:
        for d in differences:
            print(d)
        print(f"not equivalent: {args.a} and {args.b}")
        return 1
    print(f"equivalent: {move_count(a)} moves")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except BrokenPipeError:  # | head
        sys.exit(1)
