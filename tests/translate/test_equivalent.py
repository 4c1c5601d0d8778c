#!/usr/bin/env python3
"""Unit tests of equivalent.py, the judge of `ncc translate`, on small synthetic traces.

usage: python3 -m unittest tests/translate/test_equivalent.py   (or run it)
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import equivalent  # noqa: E402
from equivalent import compare  # noqa: E402

_line = [0]


def ev(event, **fields):
    """One JSON Lines event as `ncc run --trace-format jsonl` writes it."""
    _line[0] += 1
    e = {"seq": _line[0], "file": "p.nc", "line": _line[0], "col": 1, "event": event}
    e.update(fields)
    return e


def pos(x=0.0, y=0.0, z=0.0, **more):
    return dict(X=x, Y=y, Z=z, **more)


def rapid(x=0.0, y=0.0, z=0.0, **more):
    return ev("rapid", **pos(x, y, z, **more))


def linear(x=0.0, y=0.0, z=0.0, **more):
    return ev("linear", **pos(x, y, z, **more))


def arc(x, y, z, cx, cy, radius, sweep, direction="ccw"):
    return ev("arc", **pos(x, y, z), plane="XY", direction=direction, centre={"X": cx, "Y": cy},
              radius=radius, sweep=sweep, rotation=1 if direction == "ccw" else -1)


def program(*body, units="mm"):
    """A run: units, a feed, a spindle, the body, the end."""
    return [ev("units", units=units), ev("feed_mode", mode="per_minute"), ev("spindle_speed", value=1000),
            ev("spindle_on", direction="cw"), *body, ev("spindle_stop"), ev("end", kind="information")]


BASE = [rapid(0, 0, 5), ev("feed_rate", value=500), linear(10, 0, -1), arc(0, 10, -1, 0, 0, 10, 90),
        ev("dwell", seconds=0.5), rapid(0, 10, 5)]


class Equal(unittest.TestCase):
    def test_same_trace(self):
        self.assertEqual(compare(program(*BASE), program(*BASE)), [])

    def test_state_events_are_not_items(self):
        noisy = [ev("comment", text="x"), ev("work_offset", index=2, **pos(5, 5, 0)), ev("plane", plane="XY"),
                 ev("tool_select", tool=3), ev("cutter_comp", side="left", radius=2), ev("message", text="m"),
                 ev("block"), ev("path", mode="accelerate"), ev("position_offset", **pos(1, 2, 3))]
        b = program(*noisy[:4], *BASE[:2], *noisy[4:], *BASE[2:])
        self.assertEqual(compare(program(*BASE), b), [])

    def test_feed_restated_or_moved_before_rapid(self):
        # F written again, or written before a rapid it does not apply to: the same motion.
        a = program(rapid(0, 0, 5), ev("feed_rate", value=500), linear(10, 0, -1), linear(20, 0, -1))
        b = program(ev("feed_rate", value=900), rapid(0, 0, 5), ev("feed_rate", value=500),
                    linear(10, 0, -1), ev("feed_rate", value=500), linear(20, 0, -1))
        self.assertEqual(compare(a, b), [])

    def test_rates_to_a_relative_tolerance(self):
        # A feed rounded to the target's decimals (NC4099): within 1 % where the caller says so.
        a = program(rapid(0, 0, 5), ev("feed_rate", value=369.752387), linear(10, 0, -1))
        b = program(rapid(0, 0, 5), ev("feed_rate", value=369.75), linear(10, 0, -1))
        self.assertEqual(compare(a, b, relative=1e-2), [])
        self.assertEqual(len(compare(a, b)), 1)
        c = program(rapid(0, 0, 5), ev("feed_rate", value=380.0), linear(10, 0, -1))
        self.assertEqual(len(compare(a, c, relative=1e-2)), 1)

    def test_jsonl_strings(self):
        a = [json.dumps(e) for e in program(*BASE)] + [""]
        self.assertEqual(compare(a, program(*BASE)), [])

    def test_empty(self):
        self.assertEqual(compare([], []), [])

    def test_move_count(self):
        items = equivalent.reduce(program(*BASE))
        self.assertEqual(equivalent.move_count(items), 4)


class Positions(unittest.TestCase):
    def test_position_differs(self):
        b = [*BASE]
        b[2] = linear(10.01, 0, -1)
        d = compare(program(*BASE), program(*b))
        self.assertEqual(len(d), 1)
        self.assertIn("item 2: X 10 / 10.01", d[0])
        self.assertIn("line", d[0])

    def test_within_tolerance(self):
        b = [*BASE]
        b[2] = linear(10 + 5e-7, 0, -1)
        self.assertEqual(compare(program(*BASE), program(*b)), [])
        b[2] = linear(10.01, 0, -1)
        self.assertEqual(compare(program(*BASE), program(*b), 0.02), [])

    def test_step_rounded_away_or_into_being(self):
        # 0.001 mm steps: the source's 0.0007/0.0009 move is nothing after rounding,
        # and a nothing of 0.000001 is a step of 0.001 at a rounding boundary.
        feed = ev("feed_rate", value=500)
        square = [linear(6, 6, -1), linear(7, 6, -1), linear(7, 7, -1), linear(6, 7, -1)]
        a = program(rapid(0, 0, 5), feed, linear(4.725712, 5.757432, -1), linear(4.72637, 5.756509, -1), *square,
                    linear(6, 7, -0.859499), linear(6, 7, -0.8595), *square, rapid(6, 7, 5))
        b = program(rapid(0, 0, 5), feed, linear(4.726, 5.757, -1), *square, linear(6, 7, -0.859), linear(6, 7, -0.86),
                    *square, rapid(6, 7, 5))
        self.assertEqual(compare(a, b, 1e-3), [])
        # A move of more than a step is a move.
        self.assertNotEqual(compare(program(rapid(0, 0, 5), feed, linear(0, 0, -1), rapid(0, 0, 5)),
                                    program(rapid(0, 0, 5), feed, linear(0, 0, -1), linear(0, 0, -1.002), rapid(0, 0, 5)), 1e-3), [])

    def test_extra_axis_at_zero(self):
        b = [*BASE]
        b[0] = rapid(0, 0, 5, A=0.0, U=0.0)
        self.assertEqual(compare(program(*BASE), program(*b)), [])

    def test_rotary_axis_not_converted(self):
        a = program(rapid(0, 0, 1, A=90.0), units="inch")
        b = program(rapid(0, 0, 25.4, A=90.0))
        self.assertEqual(compare(a, b), [])
        self.assertEqual(len(compare(a, program(rapid(0, 0, 25.4, A=90.0 * 25.4)))), 1)

    def test_null_number(self):
        a = program(rapid(None, 0, 0))
        self.assertEqual(compare(a, a), [])
        self.assertEqual(len(compare(a, program(rapid(0, 0, 0)))), 1)


class State(unittest.TestCase):
    def test_feed_differs(self):
        b = [*BASE]
        b[1] = ev("feed_rate", value=510)
        d = compare(program(*BASE), program(*b))
        self.assertIn("item 2: feed 500 / 510", d[0])
        self.assertIn("item 3: feed 500 / 510", d[1])

    def test_feed_relative(self):
        b = [*BASE]
        b[1] = ev("feed_rate", value=500 * (1 + 1e-12))
        self.assertEqual(compare(program(*BASE), program(*b)), [])

    def test_feed_mode_differs(self):
        a = program(ev("feed_rate", value=0.1), linear(1))
        b = program(ev("feed_mode", mode="per_revolution"), ev("feed_rate", value=0.1), linear(1))
        self.assertIn("feed_mode per_minute / per_revolution", compare(a, b)[0])

    def test_feed_reduction(self):
        a = program(ev("feed_reduction", on=True), ev("feed_rate", value=1000), linear(1))
        b = program(ev("feed_rate", value=10), linear(1))
        self.assertEqual(compare(a, b), [])

    def test_spindle_speed_only_while_turning(self):
        a = [ev("spindle_speed", value=100), rapid(1), ev("spindle_on", direction="cw"), rapid(2)]
        b = [ev("spindle_speed", value=300), rapid(1), ev("spindle_speed", value=100),
             ev("spindle_on", direction="cw"), rapid(2)]
        self.assertEqual(compare(a, b), [])
        c = [ev("spindle_speed", value=300), rapid(1), ev("spindle_on", direction="cw"), rapid(2)]
        self.assertIn("item 2: speed 100 / 300", compare(a, c)[0])
        d = [ev("spindle_speed", value=300), ev("spindle_on", direction="cw"), rapid(1),
             ev("spindle_speed", value=100), rapid(2)]
        self.assertEqual(compare(a, d)[0].splitlines()[0], "item 1: spindle stop / cw")

    def test_spindle_direction(self):
        a = program(rapid(1))
        b = program(ev("spindle_on", direction="ccw"), rapid(1))
        self.assertIn("spindle cw / ccw", compare(a, b)[0])

    def test_coolant(self):
        a = program(ev("coolant", coolant="flood"), rapid(1), ev("coolant", coolant="off"), rapid(2))
        b = program(ev("coolant", coolant="flood"), rapid(1), rapid(2))
        d = compare(a, b)
        self.assertEqual(len(d), 1)
        self.assertIn("item 2: coolant off / flood", d[0])

    def test_tool_and_length_offset(self):
        a = program(ev("tool_change", tool=1), ev("tool_length_offset", **pos(0, 0, 25.4)), rapid(1))
        b = program(ev("tool_change", tool=1), ev("tool_length_offset", **pos(0, 0, 1)), rapid(1), units="inch")
        # B's rapid is X1 inch: a different point; its offset is the same.
        d = compare(a, b)
        self.assertEqual(len(d), 1)
        self.assertIn("X 1 / 25.4", d[0])
        c = program(ev("tool_change", tool=1), rapid(1))
        self.assertIn("tool_offset Z 25.4 / 0", compare(a, c)[0])
        e = program(ev("tool_change", tool=2), ev("tool_length_offset", **pos(0, 0, 25.4)), rapid(1))
        self.assertIn("item 1: tool 1 / 2", compare(a, e)[0])

    def test_cutter_comp_not_compared(self):
        a = program(ev("cutter_comp", side="left", radius=3), rapid(1))
        self.assertEqual(compare(a, program(rapid(1))), [])


class Units(unittest.TestCase):
    def test_inch_against_mm(self):
        a = program(rapid(1, 0.5, 0.2), ev("feed_rate", value=12), linear(2.25, 0.5, -0.125),
                    ev("tool_length_offset", **pos(0, 0, 0.5)),
                    arc(3.25, 1.5, -0.125, 2.25, 1.5, 1, 90, "cw"), ev("thread", **pos(3.25, 1.5, -1), pitch=0.0625,
                                                                   pitch_change=0), ev("dwell", seconds=0.75),
                    units="inch")
        b = program(rapid(25.4, 12.7, 5.08), ev("feed_rate", value=304.8), linear(57.15, 12.7, -3.175),
                    ev("tool_length_offset", **pos(0, 0, 12.7)),
                    arc(82.55, 38.1, -3.175, 57.15, 38.1, 25.4, 90, "cw"), ev("thread", **pos(82.55, 38.1, -25.4),
                                                                       pitch=1.5875, pitch_change=0),
                    ev("dwell", seconds=0.75))
        self.assertEqual(compare(a, b), [])

    def test_feed_read_in_the_units_of_the_move(self):
        # F10 under G20, then G21: the runtime reads F in the units in force at the move.
        a = [ev("units", units="inch"), ev("feed_rate", value=10), ev("units", units="mm"), linear(1)]
        b = [ev("feed_rate", value=10), linear(1)]
        self.assertEqual(compare(a, b), [])

    def test_constant_surface_speed(self):
        a = [ev("units", units="inch"), ev("spindle_mode", mode="constant_surface"), ev("spindle_speed", value=100),
             ev("spindle_on", direction="cw"), rapid(1)]
        b = [ev("spindle_mode", mode="constant_surface"), ev("spindle_speed", value=30.48),
             ev("spindle_on", direction="cw"), rapid(25.4)]
        self.assertEqual(compare(a, b), [])

    def test_start_units(self):
        a = [rapid(1)]
        b = [rapid(25.4)]
        self.assertEqual(len(compare(a, b)), 1)
        self.assertEqual(compare(a, b, initial=({"units": "inch"}, None)), [])

    def test_initial_feed_mode(self):
        a = [ev("feed_rate", value=100), linear(1)]
        b = [ev("feed_mode", mode="per_minute"), ev("feed_rate", value=100), linear(1)]
        self.assertIn("feed_mode none / per_minute", compare(a, b)[0])
        self.assertEqual(compare(a, b, initial=({"feed_mode": "per_minute"}, None)), [])


class Dropped(unittest.TestCase):
    def test_zero_length_move_dropped(self):
        a = program(*BASE)
        # A zero-length move at another feed, and the feed back: nothing to see.
        b = program(*BASE[:3], linear(10, 0, -1), ev("feed_rate", value=100), linear(10, 0, -1),
                    ev("feed_rate", value=500), rapid(10, 0, -1), *BASE[3:])
        self.assertEqual(compare(a, b), [])

    def test_zero_length_within_tolerance(self):
        b = program(*BASE[:3], linear(10 + 1e-9, 0, -1), *BASE[3:])
        self.assertEqual(compare(program(*BASE), b), [])

    def test_first_move_needs_the_start(self):
        a = program(rapid(0, 0, 0), rapid(1))
        b = program(rapid(1))
        self.assertIn("A has 1 item(s) more", compare(a, b)[0])
        self.assertEqual(compare(a, b, start={"X": 0, "Y": 0, "Z": 0}), [])

    def test_full_circle_is_not_zero(self):
        a = program(*BASE[:3], arc(10, 0, -1, 5, 0, 5, 360), *BASE[3:])
        d = compare(a, program(*BASE))
        self.assertEqual(len(d), 1)
        self.assertIn("A has 1 item(s) more", d[0])
        self.assertIn("sweep 360", d[0])

    def test_zero_arc_dropped(self):
        a = program(*BASE[:3], arc(10, 0, -1, 5, 0, 5, 0), *BASE[3:])
        self.assertEqual(compare(a, program(*BASE)), [])

    def test_parabola_out_and_back_is_not_zero(self):
        a = program(*BASE[:3], ev("parabola", **pos(10, 0, -1), control=pos(20, 0, -1)), *BASE[3:])
        self.assertEqual(len(compare(a, program(*BASE))), 1)

    def test_probe_kept(self):
        a = program(*BASE[:3], ev("probe", **pos(10, 0, -1), contact=False), *BASE[3:])
        self.assertEqual(len(compare(a, program(*BASE))), 1)


class Arcs(unittest.TestCase):
    def test_direction_differs(self):
        b = [*BASE]
        b[3] = arc(0, 10, -1, 0, 0, 10, 90, "cw")
        d = compare(program(*BASE), program(*b))
        self.assertEqual(len(d), 1)
        self.assertIn("item 3: direction ccw / cw", d[0])

    def test_centre_and_sweep(self):
        b = [*BASE]
        b[3] = arc(0, 10, -1, 0.5, 0, 10, 270)
        d = compare(program(*BASE), program(*b))
        self.assertIn("centre X 0 / 0.5", d[0])
        self.assertIn("sweep 90 / 270", d[0])

    def test_sweep_noise(self):
        b = [*BASE]
        b[3] = arc(0, 10, -1, 0, 0, 10, 90 + 5e-7)
        self.assertEqual(compare(program(*BASE), program(*b)), [])

    def test_sweep_along_a_small_arc(self):
        # A 0.3 mm arc rounded to 0.0001 mm: its ends and centre each move by half a step,
        # its sweep by up to twice the tolerance along it, as its radius.
        a = program(rapid(0, 0, 5), ev("feed_rate", value=500), arc(0, 0.3, 0, 0, 0, 0.3, 154.0))
        near = program(rapid(0, 0, 5), ev("feed_rate", value=500), arc(0, 0.3, 0, 0, 0, 0.3, 153.9766))  # 0.000123 mm
        far = program(rapid(0, 0, 5), ev("feed_rate", value=500), arc(0, 0.3, 0, 0, 0, 0.3, 153.95))  # 0.00026 mm
        self.assertEqual(compare(a, near, 1e-4), [])
        self.assertIn("sweep 154 / 153.95", compare(a, far, 1e-4)[0])

    def test_plane(self):
        b = [*BASE]
        b[3] = dict(BASE[3], plane="ZX", centre={"Z": 0, "X": 0})
        self.assertIn("plane XY / ZX", compare(program(*BASE), program(*b))[0])


class Items(unittest.TestCase):
    def test_extra_dwell(self):
        b = program(*BASE[:3], ev("dwell", seconds=2), *BASE[3:])
        d = compare(program(*BASE), b)
        self.assertEqual(len(d), 1)
        self.assertIn("B has 1 item(s) more before item 3 of A", d[0])
        self.assertIn("dwell seconds 2", d[0])

    def test_dwell_differs(self):
        b = [*BASE]
        b[4] = ev("dwell", seconds=0.6)
        self.assertIn("seconds 0.5 / 0.6", compare(program(*BASE), program(*b))[0])

    def test_ends_early(self):
        a = program(*BASE)
        b = a[:7]  # the run stopped after the linear move
        d = compare(a, b)
        self.assertEqual(len(d), 1)
        self.assertIn("B stops after 2 items, A goes on with item 3 and 3 more", d[0])
        self.assertIn("A item 3", d[0])
        d = compare([], a)
        self.assertIn("A stops after 0 items, B goes on with item 1", d[0])

    def test_stops_and_end(self):
        a = program(ev("stop", kind="program"), rapid(1))
        b = program(ev("stop", kind="optional"), rapid(1))
        self.assertIn("kind program / optional", compare(a, b)[0])
        c = program(rapid(1))
        c[-1] = ev("end", kind="program")
        self.assertIn("kind information / program", compare(program(rapid(1)), c)[0])

    def test_tool_change_item(self):
        a = program(ev("tool_change", tool=1), ev("tool_change", tool=2))
        self.assertEqual(len(compare(a, program(ev("tool_change", tool=2)))), 1)

    def test_unknown_event_compared(self):
        a = program(ev("laser", power=3))
        self.assertEqual(compare(a, a), [])
        self.assertIn("power 3 / 4", compare(a, program(ev("laser", power=4)))[0])

    def test_limit(self):
        a = program(*[rapid(i) for i in range(1, 40)])
        b = program(*[rapid(i + 0.5) for i in range(1, 40)])
        self.assertEqual(len(compare(a, b)), 10)
        self.assertEqual(len(compare(a, b, limit=3)), 3)


class Processes(unittest.TestCase):
    def proc(self, p, e):
        return dict(e, process=p)

    def test_interleaving_does_not_matter(self):
        one = [rapid(1), rapid(2), ev("end", kind="program")]
        two = [rapid(5), ev("dwell", seconds=1), ev("end", kind="program")]
        a = [self.proc(1, one[0]), self.proc(2, two[0]), self.proc(1, one[1]), self.proc(2, two[1]),
             self.proc(2, two[2]), self.proc(1, one[2])]
        b = [self.proc(2, e) for e in two] + [self.proc(1, e) for e in one]
        self.assertEqual(compare(a, b), [])

    def test_difference_names_the_process(self):
        a = [self.proc(1, rapid(1)), self.proc(2, rapid(5))]
        b = [self.proc(1, rapid(1)), self.proc(2, rapid(6))]
        d = compare(a, b)
        self.assertEqual(len(d), 1)
        self.assertTrue(d[0].startswith("process 2, item 1: X 5 / 6"), d[0])

    def test_state_is_per_process(self):
        a = [self.proc(1, ev("units", units="inch")), self.proc(1, rapid(1)), self.proc(2, rapid(25.4))]
        b = [self.proc(1, rapid(25.4)), self.proc(2, rapid(25.4))]
        self.assertEqual(compare(a, b), [])

    def test_process_only_in_one(self):
        a = [self.proc(1, rapid(1)), self.proc(2, rapid(5))]
        b = [self.proc(1, rapid(1))]
        self.assertIn("process 2, B stops after 0 items", compare(a, b)[0])


class CommandLine(unittest.TestCase):
    def run_judge(self, a, b, *options):
        with tempfile.TemporaryDirectory() as d:
            paths = []
            for name, events in (("a.jsonl", a), ("b.jsonl", b)):
                paths.append(os.path.join(d, name))
                with open(paths[-1], "w", encoding="utf-8") as f:
                    f.write(events if isinstance(events, str) else "".join(json.dumps(e) + "\n" for e in events))
            return subprocess.run([sys.executable, os.path.join(HERE, "equivalent.py"), *options, *paths],
                                  capture_output=True, text=True)

    def test_equivalent(self):
        r = self.run_judge(program(*BASE), program(*BASE))
        self.assertEqual((r.returncode, r.stdout), (0, "equivalent: 4 moves\n"))

    def test_not_equivalent(self):
        b = [*BASE]
        b[2] = linear(10.01, 0, -1)
        r = self.run_judge(program(*BASE), program(*b))
        self.assertEqual(r.returncode, 1)
        self.assertIn("item 2: X 10 / 10.01", r.stdout)
        self.assertEqual(self.run_judge(program(*BASE), program(*b), "--tolerance", "0.1").returncode, 0)

    def test_show(self):
        r = self.run_judge(program(*BASE), program(*BASE), "--show")
        self.assertIn("A ", r.stdout)
        self.assertIn("arc X0 Y10 Z-1 plane XY direction ccw centre X0 Y0 radius 10 sweep 90 F500/min", r.stdout)

    def test_bad_input(self):
        r = self.run_judge("{not json\n", program(*BASE))
        self.assertEqual(r.returncode, 2)
        self.assertIn("a.jsonl:1: not JSON", r.stderr)

    def test_initial_option(self):
        a, b = [rapid(1)], [ev("units", units="mm"), rapid(25.4)]
        self.assertEqual(self.run_judge(a, b).returncode, 1)
        self.assertEqual(self.run_judge(a, b, "--initial-a", "units=inch").returncode, 0)
        self.assertEqual(self.run_judge(a, b, "--initial-a", "units=cm").returncode, 2)

    def test_start_option(self):
        a, b = program(rapid(1, 2, 3), rapid(4)), program(rapid(4))
        self.assertEqual(self.run_judge(a, b).returncode, 1)
        self.assertEqual(self.run_judge(a, b, "--start", "X=1,Y=2,Z=3").returncode, 0)


if __name__ == "__main__":
    unittest.main()
