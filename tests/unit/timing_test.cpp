// The cycle-time models (sim/timing.h) against times worked out here by hand, from the
// kinematics of each case, not from the code under test. Each check prints its
// expected and computed value and their relative difference.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "sim/timing.h"
#include "stdlib/profile.h"

namespace ncc::sim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kAccel = 1000;      // mm/s², every axis
constexpr double kJerk = 1e5;        // mm/s³, every axis
constexpr double kDeviation = 0.01;  // mm

MachineConfig test_machine() {
  MachineConfig m;
  for (AxisConfig& a : m.axes) {
    a.rapid = 12000;    // 200 mm/s
    a.max_feed = 6000;  // 100 mm/s
    a.acceleration = kAccel;
    a.jerk = kJerk;
  }
  m.motion.junction_deviation = kDeviation;
  m.motion.tool_change = 5;
  m.motion.spindle_acceleration = 1000;
  return m;
}

AxisValues at(double x, double y, double z = 0) {
  AxisValues p{};
  p[0] = x;
  p[1] = y;
  p[2] = z;
  return p;
}

Move line(AxisValues from, AxisValues to, double feed, MoveKind kind = MoveKind::Line) {
  Move m;
  m.kind = kind;
  m.start = from;
  m.end = to;
  m.feed = kind == MoveKind::Rapid ? 0 : feed;
  return m;
}

// An arc in XY about `centre` from `from`, sweeping `sweep` degrees, rising `dz`.
Move arc(AxisValues from, double cx, double cy, double sweep, double feed, double dz = 0) {
  Move m;
  m.kind = MoveKind::Arc;
  m.plane = kPlanes[0];
  m.start = from;
  m.centre[0] = cx;
  m.centre[1] = cy;
  m.radius = std::hypot(from[0] - cx, from[1] - cy);
  m.sweep = sweep;
  const double end_angle = std::atan2(from[1] - cy, from[0] - cx) + sweep * kPi / 180;
  m.end = at(cx + m.radius * std::cos(end_angle), cy + m.radius * std::sin(end_angle), from[2] + dz);
  m.feed = feed;
  return m;
}

Toolpath path_of(std::vector<Move> moves, std::vector<Pause> pauses = {}) {
  Toolpath p;
  p.moves = std::move(moves);
  p.pauses = std::move(pauses);
  return p;
}

// Time of a straight move at constant acceleration a from v0 through cruise v to v1
// (long enough to cruise): L/v plus, for each speed change, (v − vi)² / (2·a·v).
double trapezoid_time(double length, double v, double a, double v0, double v1) {
  return length / v + (v - v0) * (v - v0) / (2 * a * v) + (v - v1) * (v - v1) / (2 * a * v);
}

void check(const char* what, double computed, double expected, double tolerance = 1e-9) {
  const double error = std::abs(computed - expected) / std::abs(expected);
  fmt::print("[timing] {:<44} expected {:<22.17g} computed {:<22.17g} relative error {:.2e}\n", what, expected,
             computed, error);
  EXPECT_LE(error, tolerance) << what << ": expected " << expected << ", computed " << computed;
}

double total(const Toolpath& path, TimeModel model, const MachineConfig& m = test_machine()) {
  return cycle_time(path, m, model).total();
}

TEST(TimingTrapezoid, LineReachesCruise) {
  // 100 mm at 50 mm/s: speeding up and slowing down each cost v/(2a) over L/v.
  const double v = 50, length = 100;
  check("trapezoid line reaching cruise", total(path_of({line(at(0, 0), at(100, 0), 3000)}), TimeModel::Trapezoid),
        length / v + v / kAccel);
}

TEST(TimingTrapezoid, LineTooShortForCruise) {
  // 1 mm: a triangle peaking at sqrt(a·L) = 31.6 mm/s < 50, half the length each way.
  const double length = 1;
  ASSERT_LT(std::sqrt(kAccel * length), 50);
  check("trapezoid line too short to cruise", total(path_of({line(at(0, 0), at(1, 0), 3000)}), TimeModel::Trapezoid),
        2 * std::sqrt(length / kAccel));
}

// Two 100 mm lines at 50 mm/s turning by `turn` degrees: the junction speed is grbl's,
// with sin(θ/2) = cos(turn/2) (θ between the reversed incoming and the outgoing
// direction) and the acceleration along the change of direction.
void check_corner(double turn_degrees) {
  const double turn = turn_degrees * kPi / 180, v = 50, length = 100;
  const double out_x = std::cos(turn), out_y = std::sin(turn);
  const double change_x = out_x - 1, change_y = out_y, change = std::hypot(change_x, change_y);
  const double junction_accel = kAccel / (std::max(std::abs(change_x), std::abs(change_y)) / change);
  const double sin_half = std::cos(turn / 2);
  const double junction = std::sqrt(junction_accel * kDeviation * sin_half / (1 - sin_half));
  ASSERT_LT(junction, v);
  const double second_accel = kAccel / std::max(std::abs(out_x), std::abs(out_y));  // the slower axis's share
  const double expected =
      trapezoid_time(length, v, kAccel, 0, junction) + trapezoid_time(length, v, second_accel, junction, 0);
  Toolpath p = path_of(
      {line(at(0, 0), at(length, 0), 3000), line(at(length, 0), at(length + length * out_x, length * out_y), 3000)});
  check(fmt::format("trapezoid corner {}° (junction {:.4f} mm/s)", turn_degrees, junction).c_str(),
        total(p, TimeModel::Trapezoid), expected);
}

TEST(TimingTrapezoid, Corner45) { check_corner(45); }
TEST(TimingTrapezoid, Corner90) { check_corner(90); }
TEST(TimingTrapezoid, Corner170) { check_corner(170); }

TEST(TimingTrapezoid, ReversalStops) {
  const double v = 50, length = 10;
  Toolpath p = path_of({line(at(0, 0), at(length, 0), 3000), line(at(length, 0), at(0, 0), 3000)});
  check("trapezoid reversal (180°) stops", total(p, TimeModel::Trapezoid), 2 * (length / v + v / kAccel));
}

TEST(TimingTrapezoid, ArcAtCentripetalLimit) {
  // A line runs tangentially into a half circle of radius 1 mm: the arc is held to
  // sqrt(a·r) = 31.6 mm/s, below the feed of 50; the line slows to it at the junction.
  const double v = 50, radius = 1, limit = std::sqrt(kAccel * radius), line_length = 10;
  ASSERT_LT(limit, v);
  Toolpath p =
      path_of({line(at(0, 0), at(line_length, 0), 3000), arc(at(line_length, 0), line_length, radius, 180, 3000)});
  const double expected =
      trapezoid_time(line_length, v, kAccel, 0, limit) + trapezoid_time(kPi * radius, limit, kAccel, limit, 0);
  check("trapezoid arc at the centripetal limit", total(p, TimeModel::Trapezoid), expected);
}

TEST(TimingTrapezoid, ChainOfShortSegmentsEqualsOneMove) {
  std::vector<Move> chain;
  for (int i = 0; i < 100; ++i) chain.push_back(line(at(i * 0.1, 0), at((i + 1) * 0.1, 0), 3000));
  const double v = 50, length = 10;
  const double one = total(path_of({line(at(0, 0), at(length, 0), 3000)}), TimeModel::Trapezoid);
  check("trapezoid one 10 mm move", one, length / v + v / kAccel);
  check("trapezoid 100 collinear 0.1 mm segments", total(path_of(chain), TimeModel::Trapezoid), one);
}

TEST(TimingTrapezoid, DiagonalLimitedByTheSlowerAxis) {
  // X 100, Y 50 at F10000: Y's 1200 mm/min (20 mm/s) and 200 mm/s² bind. With L the
  // length, Y's share is 50/L: v = 20·L/50, a = 200·L/50.
  MachineConfig m = test_machine();
  m.axes[1].max_feed = 1200;
  m.axes[1].acceleration = 200;
  m.axes[1].rapid = 3000;
  const double length = std::hypot(100.0, 50.0), v = 20 * length / 50, a = 200 * length / 50;
  Toolpath p = path_of({line(at(0, 0), at(100, 50), 10000)});
  check("feed diagonal, slower axis", total(p, TimeModel::Feed, m), length / v);
  check("trapezoid diagonal, slower axis", total(p, TimeModel::Trapezoid, m), length / v + v / a);
  // A rapid: X 200 mm/s, Y 50 mm/s → 50·L/50 mm/s along the diagonal.
  check("feed diagonal rapid, slower axis",
        total(path_of({line(at(0, 0), at(100, 50), 0, MoveKind::Rapid)}), TimeModel::Feed, m), 1.0);
}

TEST(TimingModels, PausesAddTheirTime) {
  // Two collinear lines with a dwell between them (the machine stops there), then a
  // tool change and a spindle start 0 → 3000 rpm at 1000 rpm/s.
  const double v = 50, length = 10, one = length / v + v / kAccel;
  Pause dwell{.kind = Pause::Kind::Dwell, .after = 1, .seconds = 2.5};
  Pause change{.kind = Pause::Kind::ToolChange, .after = 2, .tool = 2};
  Pause spindle{.kind = Pause::Kind::Spindle, .after = 2, .rpm_to = 3000};
  Toolpath p = path_of({line(at(0, 0), at(length, 0), 3000), line(at(length, 0), at(2 * length, 0), 3000)},
                       {dwell, change, spindle});
  for (TimeModel model : {TimeModel::Trapezoid, TimeModel::SCurve}) {
    CycleTime t = cycle_time(p, test_machine(), model);
    check(fmt::format("{} dwell", model_name(model)).c_str(), t.dwell, 2.5);
    check(fmt::format("{} tool change", model_name(model)).c_str(), t.tool_change, 5);
    check(fmt::format("{} spindle ramp", model_name(model)).c_str(), t.spindle, 3);
    check(fmt::format("{} cutting = two stops", model_name(model)).c_str(), t.cutting,
          2 * cycle_time(path_of({p.moves[0]}), test_machine(), model).cutting);
  }
  CycleTime t = cycle_time(p, test_machine(), TimeModel::Trapezoid);
  check("trapezoid pauses: total", t.total(), 2 * one + 2.5 + 5 + 3);
  check("trapezoid pauses: end of move 2", t.move_end[1], 2 * one + 2.5);
}

TEST(TimingModels, StopsAtExactStopAndBetweenRapidAndFeed) {
  const double length = 10;
  const double alone = total(path_of({line(at(0, 0), at(length, 0), 3000)}), TimeModel::Trapezoid);
  Move first = line(at(0, 0), at(length, 0), 3000);
  first.exact_stop = true;
  check("trapezoid exact stop",
        total(path_of({first, line(at(length, 0), at(2 * length, 0), 3000)}), TimeModel::Trapezoid), 2 * alone);
  Move rapid = line(at(0, 0), at(length, 0), 0, MoveKind::Rapid);
  const double rapid_alone = total(path_of({rapid}), TimeModel::Trapezoid);
  check("trapezoid rapid then feed",
        total(path_of({rapid, line(at(length, 0), at(2 * length, 0), 3000)}), TimeModel::Trapezoid),
        rapid_alone + alone);
}

TEST(TimingModels, ThreadRunsAtItsFeed) {
  // Pitch 1.5 at 1000 rpm: 1500 mm/min over 30 mm, no acceleration; the line before stops.
  const double v = 50, length = 10;
  Toolpath p = path_of(
      {line(at(0, 0, 0), at(0, 0, -length), 3000), line(at(0, 0, -length), at(0, 0, -40), 1500, MoveKind::Thread)});
  check("trapezoid thread", total(p, TimeModel::Trapezoid), length / v + v / kAccel + 30 / 25.0);
  check("scurve thread",
        cycle_time(p, test_machine(), TimeModel::SCurve).move_end[1] -
            cycle_time(p, test_machine(), TimeModel::SCurve).move_end[0],
        30 / 25.0);
}

TEST(TimingSCurve, LineReachesCruise) {
  // 0 → 50 mm/s with A = 1000, J = 1e5: 50 ≥ A²/J = 10, so the change takes
  // T = v/A + A/J and covers v/2·T; twice, with the rest at 50 mm/s.
  const double v = 50, length = 100, ramp = v / kAccel + kAccel / kJerk;
  ASSERT_GE(v, kAccel * kAccel / kJerk);
  check("scurve line reaching cruise", total(path_of({line(at(0, 0), at(length, 0), 3000)}), TimeModel::SCurve),
        2 * ramp + (length - 2 * (v / 2) * ramp) / v);
}

TEST(TimingSCurve, ShortLineBelowFullAcceleration) {
  // 0.1 mm: the peak vp covers L/2 = vp·sqrt(vp/J) on each ramp, vp = (L·sqrt(J)/2)^(2/3),
  // below A²/J, so each ramp takes 2·sqrt(vp/J).
  const double length = 0.1, peak = std::pow(length * std::sqrt(kJerk) / 2, 2.0 / 3);
  ASSERT_LT(peak, kAccel * kAccel / kJerk);
  check("scurve short line (no full acceleration)",
        total(path_of({line(at(0, 0), at(length, 0), 3000)}), TimeModel::SCurve), 4 * std::sqrt(peak / kJerk));
}

TEST(TimingSCurve, ShortLineReachingFullAcceleration) {
  // 1 mm: each ramp covers vp/2·(vp/A + A/J) = L/2, vp² + vp·A²/J − A·L = 0.
  const double length = 1, k = kAccel * kAccel / kJerk;
  const double peak = (-k + std::sqrt(k * k + 4 * kAccel * length)) / 2;
  ASSERT_GT(peak, k);
  ASSERT_LT(peak, 50);
  check("scurve short line (full acceleration)",
        total(path_of({line(at(0, 0), at(length, 0), 3000)}), TimeModel::SCurve), 2 * (peak / kAccel + kAccel / kJerk));
}

TEST(TimingSCurve, ChainOfShortSegmentsEqualsOneMove) {
  // The speed-up runs on through junctions it stays below (timing.cpp): 100 collinear
  // 0.1 mm segments take what one 10 mm move does.
  std::vector<Move> chain;
  for (int i = 0; i < 100; ++i) chain.push_back(line(at(i * 0.1, 0), at((i + 1) * 0.1, 0), 3000));
  const double v = 50, length = 10, ramp = v / kAccel + kAccel / kJerk;
  const double one = total(path_of({line(at(0, 0), at(length, 0), 3000)}), TimeModel::SCurve);
  check("scurve one 10 mm move", one, length / v + ramp);
  CycleTime t = cycle_time(path_of(chain), test_machine(), TimeModel::SCurve);
  check("scurve 100 collinear 0.1 mm segments", t.total(), one);
  // At 0.7 mm (the end of the 7th segment) the speed-up is past its rising
  // acceleration (A/J = 0.01 s, J/6·(A/J)³ mm) and at constant A for u more seconds:
  // J/6·(A/J)³ + A²/(2J)·u + A/2·u² = 0.7.
  const double rise = kAccel / kJerk, rise_length = kJerk / 6 * rise * rise * rise;
  const double b = kAccel * kAccel / (2 * kJerk), c = rise_length - 0.7;
  const double u = (-b + std::sqrt(b * b - 2 * kAccel * c)) / kAccel;
  ASSERT_LT(u, v / kAccel - rise);
  check("scurve chain: the clock at 0.7 mm", t.move_end[6], rise + u);
}

TEST(TimingFeed, ArcAndHelix) {
  // A quarter circle of radius 10 at 10 mm/s; a full turn of radius 5 rising 3 mm.
  check("feed quarter circle", total(path_of({arc(at(10, 0), 0, 0, 90, 600)}), TimeModel::Feed), (kPi / 2 * 10) / 10);
  check("feed helix", total(path_of({arc(at(5, 0), 0, 0, 360, 600, 3)}), TimeModel::Feed),
        std::hypot(2 * kPi * 5, 3.0) / 10);
  check("feed clockwise arc", total(path_of({arc(at(10, 0), 0, 0, -90, 600)}), TimeModel::Feed), (kPi / 2 * 10) / 10);
}

TEST(TimingFeed, RotaryAxesAndPathLimit) {
  MachineConfig m = test_machine();
  m.axes[3].rapid = 3600;  // A: 60 °/s
  m.axes[3].max_feed = 3600;
  AxisValues turned = at(0, 0);
  turned[3] = 90;
  // Rotary alone: degrees are the length.
  check("feed rotary-only rapid", total(path_of({line(at(0, 0), turned, 0, MoveKind::Rapid)}), TimeModel::Feed, m),
        1.5);
  // X 10 mm with A 90°: the length is 10 mm; A turns 9°/mm, at most 3600/9 = 400 mm/min.
  AxisValues both = turned;
  both[0] = 10;
  check("feed mixed linear and rotary", total(path_of({line(at(0, 0), both, 600)}), TimeModel::Feed, m),
        10 / (400 / 60.0));
  // [motion] max_velocity caps the path speed of a diagonal rapid.
  m.motion.max_velocity = 6000;
  check("feed rapid capped by max_velocity",
        total(path_of({line(at(0, 0), at(30, 40), 0, MoveKind::Rapid)}), TimeModel::Feed, m), 50 / 100.0);
}

TEST(TimingModels, ProgrammedMovesAndProcesses) {
  Move drawn = line(at(0, 0), at(100, 0), 3000);
  drawn.programmed = true;
  Move other = line(at(0, 0), at(20, 0), 600);  // process 1: 2 s
  other.process = 1;
  Toolpath p = path_of({drawn, line(at(0, 0), at(10, 0), 600), other});
  CycleTime t = cycle_time(p, test_machine(), TimeModel::Feed);
  check("feed: the longest process", t.total(), 2);
  check("feed: process 0's clock", t.move_end[1], 1);
  check("feed: process 1's clock", t.move_end[2], 2);
  EXPECT_EQ(t.move_end[0], 0);
  check("lengths skip programmed moves", t.cutting_length, 30);
}

TEST(TimingModels, DeterministicBitForBit) {
  std::vector<Move> moves;
  uint64_t state = 12345;
  auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  AxisValues here = at(0, 0);
  for (int i = 0; i < 2000; ++i) {
    AxisValues to = at(here[0] + next() * 10 - 5, here[1] + next() * 10 - 5, here[2] + next() - 0.5);
    if (i % 7 == 3) {
      moves.push_back(
          arc(here, here[0] + next() * 4 - 2, here[1] + next() * 4 - 2, next() * 540 - 270, 1200, next() - 0.5));
    } else {
      moves.push_back(line(here, to, 300 + next() * 5000, i % 5 == 0 ? MoveKind::Rapid : MoveKind::Line));
    }
    here = moves.back().end;
  }
  Toolpath p = path_of(moves, {Pause{.kind = Pause::Kind::Dwell, .after = 500, .seconds = 1.25}});
  for (TimeModel model : kTimeModels) {
    CycleTime a = cycle_time(p, test_machine(), model), b = cycle_time(p, test_machine(), model);
    EXPECT_EQ(std::memcmp(&a.cutting, &b.cutting, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&a.rapid, &b.rapid, sizeof(double)), 0);
    ASSERT_EQ(a.move_end.size(), b.move_end.size());
    EXPECT_EQ(std::memcmp(a.move_end.data(), b.move_end.data(), a.move_end.size() * sizeof(double)), 0);
    for (size_t i = 1; i < a.move_end.size(); ++i) ASSERT_GE(a.move_end[i], a.move_end[i - 1]);
    EXPECT_TRUE(std::isfinite(a.total()));
  }
  // The acceleration models are never faster than the feed model.
  EXPECT_GE(total(p, TimeModel::Trapezoid), total(p, TimeModel::Feed));
  EXPECT_GE(total(p, TimeModel::SCurve), total(p, TimeModel::Trapezoid));
}

TEST(TimingSummary, TextAndJson) {
  Toolpath p = path_of({line(at(0, 0), at(0, 0, 50), 0, MoveKind::Rapid), line(at(0, 0, 50), at(100, 0, 50), 60)},
                       {Pause{.kind = Pause::Kind::ToolChange, .after = 0, .tool = 1}});
  std::vector<CycleTime> times;
  for (TimeModel model : kTimeModels) times.push_back(cycle_time(p, test_machine(), model));
  const std::string json = time_json(p, times);
  EXPECT_EQ(json.rfind("{\"processes\": 1, \"moves\": {\"cutting\": 1, \"rapid\": 1}, "
                       "\"length_mm\": {\"cutting\": 100, \"rapid\": 50}, \"tool_changes\": 1, \"dwells\": 0, ",
                       0),
            0u)
      << json;
  EXPECT_NE(json.find("\"feed\": {\"cutting\": 100, \"rapid\": 0.25, \"tool_change\": 5, \"dwell\": 0, \"spindle\": 0, "
                      "\"auxiliary\": 5.25, \"total\": 105.25}"),
            std::string::npos)
      << json;
  const std::string text = time_text(p, times);
  EXPECT_NE(text.find("tool changes 1, dwells 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nfeed            1:40.0      0:00.3      0:05.0      0:00.0      0:00.0      0:05.3      1:45.3"
                      "      105.25\n"),
            std::string::npos)
      << text;
}

// The profile keys the models read (docs/profile.md [axes], [motion], [stock]).
MachineConfig profile_machine(const std::string& text, Diagnostics& diags) {
  SourceManager sources;
  auto p = stdlib::Profile::parse(sources, "m.toml", text, diags);
  EXPECT_TRUE(p);
  MachineConfig m = stdlib::load_machine_config(*p, diags);
  p->report_unused(diags);
  return m;
}

TEST(TimingProfile, KeysAndDefaults) {
  Diagnostics diags;
  MachineConfig m = profile_machine(
      "[axes]\nX = { rapid = 20000.0, acceleration = 3000.0, jerk = 80000.0 }\nY = { max_feed = 8000.0 }\n"
      "[motion]\njunction_deviation = 0.02\ntool_change = 3.5\nspindle_acceleration = 2500.0\nmax_velocity = 15000.0\n"
      "[stock]\nmin = { X = 0.0, Y = 0.0, Z = -20.0 }\nmax = { X = 100.0, Y = 60.0, Z = 0.0 }\n",
      diags);
  EXPECT_TRUE(diags.all().empty()) << diags.all()[0].message;
  EXPECT_EQ(m.axes[0].max_feed, 20000);  // the rapid rate unless given
  EXPECT_EQ(m.axes[0].acceleration, 3000);
  EXPECT_EQ(m.axes[0].jerk, 80000);
  EXPECT_EQ(m.axes[1].max_feed, 8000);
  EXPECT_EQ(m.axes[1].acceleration, 2000);  // the defaults
  EXPECT_EQ(m.axes[1].jerk, 50000);
  EXPECT_EQ(m.motion.junction_deviation, 0.02);
  EXPECT_EQ(m.motion.tool_change, 3.5);
  EXPECT_EQ(m.motion.spindle_acceleration, 2500);
  EXPECT_EQ(m.motion.max_velocity, 15000);
  ASSERT_TRUE(m.stock.set);
  EXPECT_EQ(m.stock.min[2], -20);
  EXPECT_EQ(m.stock.max[1], 60);
  MachineConfig plain = profile_machine("", diags);
  EXPECT_FALSE(plain.stock.set);
  EXPECT_EQ(plain.motion.junction_deviation, 0.01);
  EXPECT_EQ(plain.motion.tool_change, 5);
  EXPECT_EQ(plain.motion.spindle_acceleration, 4000);
  EXPECT_TRUE(std::isinf(plain.motion.max_velocity));
}

TEST(TimingProfile, BadValuesAreReported) {
  Diagnostics diags;
  profile_machine(
      "[axes]\nX = { acceleration = 0.0, jerk = -1.0 }\n[motion]\ntool_change = nan\njunction_devation = 0.1\n"
      "[stock]\nmin = { X = 0.0, Y = 0.0 }\nmax = { X = 1.0, Y = 1.0, Z = 1.0 }\n",
      diags);
  std::vector<std::string> messages;
  for (const auto& d : diags.all()) messages.push_back(d.message);
  ASSERT_EQ(messages.size(), 5u) << fmt::format("{}", fmt::join(messages, "\n"));
  EXPECT_EQ(messages[0], "machine profile: 'axes.X.acceleration' must be greater than zero");
  EXPECT_EQ(messages[1], "machine profile: 'axes.X.jerk' must be greater than zero");
  EXPECT_EQ(messages[2], "machine profile: 'motion.tool_change' must be a finite number");
  EXPECT_EQ(messages[3],
            "machine profile: 'stock.min' must give X, Y and Z in mm and no other axis, e.g. { X = 0.0, Y = 0.0, Z = "
            "-20.0 }");
  EXPECT_EQ(diags.all()[4].id, DiagId::ProfileUnknownKey);  // motion.junction_devation
  diags = Diagnostics{};
  profile_machine("[stock]\nmin = { X = 0.0, Y = 0.0, Z = 0.0 }\nmax = { X = 1.0, Y = 1.0, Z = 0.0 }\n", diags);
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].message,
            "machine profile: 'stock.max' must be above stock.min on every axis (Z: 0 is not above 0)");
}

}  // namespace
}  // namespace ncc::sim
