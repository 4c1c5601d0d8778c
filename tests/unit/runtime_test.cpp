// The motion runtime on its own: blocks of canonical functions and words go in,
// trace events come out, at full precision. The golden tests cover the same ground
// through GOST source at the trace's four decimals.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "collect_issues.h"

namespace ncc {
namespace {

// A machine with one code per canonical function it needs.
class Rig {
 public:
  Rig() {
    add("G00", {{Fn::MotionRapid}});
    add("G01", {{Fn::MotionLinear}});
    add("G02", {{Fn::MotionArcCw}});
    add("G03", {{Fn::MotionArcCcw}});
    add("G06", {{Fn::MotionParabola}});
    add("G17", {{Fn::PlaneXY}});
    add("G18", {{Fn::PlaneZX}});
    add("G19", {{Fn::PlaneYZ}});
    add("G90", {{Fn::DistanceAbsolute}});
    add("G91", {{Fn::DistanceIncremental}});
    add("G92", {{Fn::SetPosition}}, Scope::Block);
    add("G70", {{Fn::UnitsInch}});
    add("G81", {{Fn::Cycle, 0}});
    add("G83", {{Fn::Cycle, 1}});
    add("M03", {{Fn::SpindleCw}}, Scope::Modal, Timing::Before);
    add("M02", {{Fn::ProgramEnd}}, Scope::Block, Timing::After);
    sem.cycles = {{"G81", CyclePattern::In::Feed, false, CyclePattern::Bottom::None, CyclePattern::Out::Rapid},
                  {"G83", CyclePattern::In::Peck, false, CyclePattern::Bottom::None, CyclePattern::Out::Rapid}};
    sem.power_on = {code("G01"), code("G17"), code("G90")};
    sem.conventions.axes = "XYZ";
    machine.power_on();
  }

  // Runs "G01 X10 F100"-like blocks: codes by name, then letter/value pairs.
  BlockResult block(std::initializer_list<const char*> codes, std::initializer_list<std::pair<char, double>> words) {
    std::vector<uint16_t> indices;
    for (const char* c : codes) indices.push_back(code(c));
    BlockWords w;
    for (auto [letter, value] : words) w.set(letter - 'A', value);
    BlockRequest r{indices.data(), indices.size(), &w, 0};
    return machine.execute(r);
  }
  // A block the test only needs run: it must go through.
  void run(std::initializer_list<const char*> codes, std::initializer_list<std::pair<char, double>> words) {
    EXPECT_EQ(block(codes, words), BlockResult::Continue);
  }

  std::vector<Event> of(EventKind kind) const {
    std::vector<Event> out;
    for (const Event& e : trace.events)
      if (e.kind == kind) out.push_back(e);
    return out;
  }

  ProgramSemantics sem;
  MachineConfig config;
  CollectSink trace;
  CollectIssues issues;
  Machine machine{sem, config, trace, issues};

 private:
  void add(const char* name, std::vector<FnCall> calls, Scope scope = Scope::Modal, Timing timing = Timing::None) {
    sem.codes.push_back({name, scope, timing, std::move(calls)});
  }
  uint16_t code(std::string_view name) const {
    for (size_t i = 0; i < sem.codes.size(); ++i)
      if (sem.codes[i].name == name) return static_cast<uint16_t>(i);
    ADD_FAILURE() << name;
    return 0;
  }
};

constexpr double kPi = std::numbers::pi;

TEST(Runtime, ArcCentreRadiusAndSweepInEachPlane) {
  Rig r;
  // XY: from (10, 0) counter-clockwise to (0, 10) about (0, 0).
  r.run({"G00"}, {{'X', 10}});
  r.run({"G03"}, {{'X', 0}, {'Y', 10}, {'I', -10}, {'J', 0}, {'F', 100}});
  // ZX: from (X0, Z10) clockwise to (X10, Z0) about the origin: 270 degrees seen from +Y.
  r.run({"G18", "G00"}, {{'X', 0}, {'Y', 0}, {'Z', 10}});
  r.run({"G02"}, {{'X', 10}, {'Z', 0}, {'I', 0}, {'K', -10}});
  auto arcs = r.of(EventKind::Arc);
  ASSERT_EQ(arcs.size(), 2u);
  EXPECT_EQ(arcs[0].plane, kPlanes[0]);
  EXPECT_DOUBLE_EQ(arcs[0].centre[0], 0);
  EXPECT_DOUBLE_EQ(arcs[0].centre[1], 0);
  EXPECT_DOUBLE_EQ(arcs[0].a, 10);
  EXPECT_NEAR(arcs[0].b, 90, 1e-12);
  EXPECT_EQ(arcs[0].rotation, 1);
  EXPECT_EQ(arcs[1].plane, kPlanes[1]);
  EXPECT_NEAR(arcs[1].b, 270, 1e-12);
  EXPECT_EQ(arcs[1].rotation, -1);
  EXPECT_TRUE(r.issues.list.empty());
}

TEST(Runtime, FullCircleWhenEndEqualsStart) {
  Rig r;
  r.run({"G00"}, {{'X', 10}});
  r.run({"G02"}, {{'X', 10}, {'Y', 0}, {'I', -10}, {'F', 100}});
  auto arcs = r.of(EventKind::Arc);
  ASSERT_EQ(arcs.size(), 1u);
  EXPECT_NEAR(arcs[0].b, 360, 1e-12);
  EXPECT_EQ(arcs[0].rotation, -1);
}

TEST(Runtime, HelixLeadChoosesTheNumberOfTurns) {
  Rig r;
  r.sem.conventions.lead_resolution = 0.001;
  r.run({"G00"}, {{'X', 10}});
  // Three turns rising 30: K = 30 / 6π = 1.59155 per radian.
  r.run({"G03"}, {{'X', 10}, {'Y', 0}, {'Z', 30}, {'I', -10}, {'K', 30 / (6 * kPi)}, {'F', 100}});
  auto arcs = r.of(EventKind::Arc);
  ASSERT_EQ(arcs.size(), 1u);
  EXPECT_NEAR(arcs[0].b, 1080, 1e-9);
  EXPECT_EQ(arcs[0].rotation, 3);
  EXPECT_DOUBLE_EQ(arcs[0].pos[2], 30);
}

TEST(Runtime, ParabolaThroughThreePoints) {
  Rig r;
  r.run({"G06"}, {{'X', 5}, {'Y', 5}, {'F', 100}});
  EXPECT_TRUE(r.of(EventKind::Parabola).empty());  // the intermediate point: nothing moves yet
  r.run({}, {{'X', 10}, {'Y', 0}});
  auto p = r.of(EventKind::Parabola);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_DOUBLE_EQ(p[0].control[0], 5);
  EXPECT_DOUBLE_EQ(p[0].control[1], 10);
  EXPECT_DOUBLE_EQ(p[0].pos[0], 10);
}

TEST(Runtime, IncrementsAddUpAsDecimals) {
  Rig r;
  r.run({"G91", "G00"}, {{'X', 0.1}});
  r.run({}, {{'X', 0.2}});
  EXPECT_EQ(r.of(EventKind::Rapid).back().pos[0], 0.3);
}

TEST(Runtime, InchesConvertBothWays) {
  Rig r;
  r.run({"G70", "G00"}, {{'X', 1}});
  r.run({"G92"}, {{'X', 0}});
  auto offset = r.of(EventKind::PositionOffset);
  ASSERT_EQ(offset.size(), 1u);
  EXPECT_DOUBLE_EQ(offset[0].pos[0], 1);  // in inches, as the program writes them
  EXPECT_DOUBLE_EQ(r.of(EventKind::Rapid).back().pos[0], 1);
}

TEST(Runtime, PeckDrillingStepsDown) {
  Rig r;
  r.run({"G00"}, {{'Z', 10}});
  r.run({"G83"}, {{'Z', -7}, {'R', 2}, {'Q', 4}, {'F', 100}});
  std::vector<double> depths;
  for (const Event& e : r.trace.events)
    if (e.kind == EventKind::Linear) depths.push_back(e.pos[2]);
  EXPECT_EQ(depths, (std::vector<double>{-2, -6, -7}));
  EXPECT_DOUBLE_EQ(r.trace.events.back().pos[2], 10);  // back at the initial level
}

TEST(Runtime, ErrorsStopTheBlockOrRecover) {
  Rig stop;
  EXPECT_EQ(stop.block({"G01"}, {{'X', 10}}), BlockResult::Error);  // no F
  ASSERT_EQ(stop.issues.list.size(), 1u);
  EXPECT_EQ(stop.issues.list[0].id, DiagId::NoFeed);
  Rig recover;
  recover.machine.set_stop_on_error(false);
  EXPECT_EQ(recover.block({"G01"}, {{'X', 10}}), BlockResult::Continue);
  recover.run({"G00"}, {{'Y', 5}});
  // The dry run carries on from where the failed move would have ended.
  EXPECT_DOUBLE_EQ(recover.of(EventKind::Rapid).back().pos[0], 10);
}

TEST(Runtime, EndOfProgramResetsAndReports) {
  Rig r;
  r.run({"G18", "M03"}, {{'S', 100}});
  EXPECT_EQ(r.block({"M02"}, {}), BlockResult::ProgramEnd);
  std::vector<EventKind> tail;
  for (size_t i = r.trace.events.size() - 4; i < r.trace.events.size(); ++i) tail.push_back(r.trace.events[i].kind);
  EXPECT_EQ(tail,
            (std::vector<EventKind>{EventKind::SpindleStop, EventKind::Coolant, EventKind::Plane, EventKind::End}));
  EXPECT_EQ(r.trace.events[r.trace.events.size() - 2].n, 0);  // back to XY
}

TEST(Runtime, PecksAreBounded) {
  Rig r;
  r.run({"G00"}, {{'Z', 10}});
  EXPECT_EQ(r.block({"G83"}, {{'Z', -99999}, {'R', 2}, {'Q', 0.001}, {'F', 100}}), BlockResult::Error);
  ASSERT_EQ(r.issues.list.size(), 1u);
  EXPECT_EQ(r.issues.list[0].id, DiagId::CyclePecks);
  EXPECT_TRUE(r.of(EventKind::Linear).empty());
}

TEST(Runtime, ToolNumbersAreWholeNumbers) {
  Rig r;
  EXPECT_EQ(r.block({}, {{'T', 1.5}}), BlockResult::Error);
  ASSERT_EQ(r.issues.list.size(), 1u);
  EXPECT_EQ(r.issues.list[0].id, DiagId::DomainError);
  EXPECT_EQ(r.issues.list[0].slot, letter_slot('T'));
}

TEST(Runtime, UnusedWordIsAWarning) {
  Rig r;
  r.run({"G01"}, {{'X', 1}, {'I', 3}, {'F', 100}});
  ASSERT_EQ(r.issues.list.size(), 1u);
  EXPECT_EQ(r.issues.list[0].id, DiagId::WordUnused);
  EXPECT_EQ(r.issues.list[0].slot, letter_slot('I'));
}

}  // namespace
}  // namespace ncc
