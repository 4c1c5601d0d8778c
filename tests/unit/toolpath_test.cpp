// The simulator's tool path from a run's events (sim/toolpath.h): the frame, the
// units, the feeds, the programmed path, the pauses, where it ends.
#include <gtest/gtest.h>

#include "sim/toolpath.h"

namespace ncc::sim {
namespace {

Event move(EventKind kind, double x, double y, double z, uint32_t source = 0) {
  Event e{kind};
  e.pos[0] = x, e.pos[1] = y, e.pos[2] = z;
  e.source = source;
  return e;
}

Event state(EventKind kind, int n, double a = 0) {
  Event e{kind};
  e.n = n;
  e.a = a;
  return e;
}

TEST(Toolpath, MeasuredFromTheFirstWorkZero) {
  MachineConfig machine;
  machine.initial_position[2] = 100;
  Toolpath path;
  ToolpathSink sink(path, machine);
  Event zero = state(EventKind::WorkOffset, 1);
  zero.pos[0] = -125, zero.pos[1] = -125;
  sink.event(zero);
  sink.event(move(EventKind::Rapid, -125, -125, 0));
  Event other = state(EventKind::WorkOffset, 2);
  other.pos[0] = -200;
  sink.event(other);  // the second zero moves nothing: the path stays in the first's
  sink.event(move(EventKind::Rapid, -200, 0, 0));
  sink.flush();
  ASSERT_EQ(path.moves.size(), 2u);
  EXPECT_EQ(path.moves[0].start[0], 125);  // machine zero, from the work zero
  EXPECT_EQ(path.moves[0].start[2], 100);
  EXPECT_EQ(path.moves[0].end[0], 0);
  EXPECT_EQ(path.moves[1].end[0], -75);
  EXPECT_EQ(path.moves[1].end[1], 125);
  ASSERT_EQ(path.offsets.size(), 2u);
  EXPECT_EQ(path.offsets[1].from, 1u);
  EXPECT_EQ(path.offsets[1].number, 2);
}

TEST(Toolpath, InchesFeedModesAndArcs) {
  MachineConfig machine;
  Toolpath path;
  ToolpathSink sink(path, machine);
  sink.event(state(EventKind::Units, 1));
  sink.event(state(EventKind::FeedRate, 0, 10));
  sink.event(move(EventKind::Linear, 1, 0, 0));  // 25.4 mm at 10 in/min
  Event arc = move(EventKind::Arc, 1, 2, 0);
  arc.centre[0] = 1, arc.centre[1] = 1;
  arc.rotation = -1, arc.a = 1, arc.b = 180;
  sink.event(arc);
  sink.event(state(EventKind::FeedMode, 0));  // inverse time: F10 = a tenth of a minute
  sink.event(move(EventKind::Linear, 1, 4, 0));
  Event turn = move(EventKind::Linear, 1, 4, 0);
  turn.pos[3] = 90;  // rotary alone: degrees per minute
  sink.event(turn);
  sink.event(state(EventKind::FeedMode, 2));  // per revolution at 500 rpm
  sink.event(state(EventKind::SpindleSpeed, 0, 500));
  sink.event(state(EventKind::FeedRate, 0, 0.01));
  sink.event(move(EventKind::Linear, 2, 4, 0));
  sink.flush();
  ASSERT_EQ(path.moves.size(), 5u);
  EXPECT_DOUBLE_EQ(path.moves[0].end[0], 25.4);
  EXPECT_DOUBLE_EQ(path.moves[0].feed, 254);
  const Move& a = path.moves[1];
  EXPECT_EQ(a.kind, MoveKind::Arc);
  EXPECT_DOUBLE_EQ(a.radius, 25.4);
  EXPECT_DOUBLE_EQ(a.centre[1], 25.4);
  EXPECT_EQ(a.sweep, -180);
  EXPECT_DOUBLE_EQ(path.moves[2].feed, 2 * 25.4 * 10);
  EXPECT_DOUBLE_EQ(path.moves[3].feed, 900);
  EXPECT_DOUBLE_EQ(path.moves[4].feed, 0.01 * 25.4 * 500);
}

TEST(Toolpath, ProgrammedPathPausesAndTools) {
  MachineConfig machine;
  machine.offsets[1].radius = 5;
  Toolpath path;
  ToolpathSink sink(path, machine);
  sink.event(state(EventKind::ChangeTool, 1));
  sink.event(state(EventKind::SpindleSpeed, 0, 1000));
  sink.event(state(EventKind::SpindleOn, 1));
  sink.event(move(EventKind::Rapid, 10, 0, 0));
  sink.event(state(EventKind::CutterComp, 1, 4));
  sink.programmed(move(EventKind::Linear, 20, 0, 0));
  sink.event(move(EventKind::Linear, 20, 4, 0));
  Event dwell{EventKind::Dwell};
  dwell.a = 1.5;
  sink.event(dwell);
  sink.event(state(EventKind::SpindleStop, 0));
  sink.flush();
  ASSERT_EQ(path.moves.size(), 3u);
  EXPECT_TRUE(path.moves[1].programmed);
  EXPECT_EQ(path.moves[1].start[0], 10);  // where the centre stood as compensation started
  EXPECT_EQ(path.moves[2].start[0], 10);
  EXPECT_EQ(path.moves[2].tool, 1);
  EXPECT_EQ(path.tool_radius(1), 4);  // the compensation's radius is the later word
  ASSERT_EQ(path.pauses.size(), 4u);
  EXPECT_EQ(path.pauses[0].kind, Pause::Kind::ToolChange);
  EXPECT_EQ(path.pauses[1].kind, Pause::Kind::Spindle);
  EXPECT_EQ(path.pauses[1].rpm_to, 1000);
  EXPECT_EQ(path.pauses[2].kind, Pause::Kind::Dwell);
  EXPECT_EQ(path.pauses[2].after, 3u);
  EXPECT_EQ(path.pauses[3].rpm_from, 1000);
  EXPECT_EQ(path.pauses[3].rpm_to, 0);
}

TEST(Toolpath, ParabolaChordsWithinTheTolerance) {
  MachineConfig machine;
  Toolpath path;
  ToolpathSink sink(path, machine, 0.001);
  Event p = move(EventKind::Parabola, 20, 0, 0);
  p.control[0] = 10, p.control[1] = 10;  // B(t) = (20t, 20t(1-t)): |B''| = 40
  sink.event(p);
  sink.flush();
  // n chords keep within |B''| / (8 n^2): n = ceil(sqrt(40 / 0.008)) = 71.
  ASSERT_EQ(path.moves.size(), 71u);
  EXPECT_EQ(path.moves.back().end[0], 20);
  for (const Move& m : path.moves) {
    const double t = (m.start[0] + m.end[0]) / 40;  // the chord's middle against the curve's
    EXPECT_LE(std::abs(20 * t * (1 - t) - (m.start[1] + m.end[1]) / 2), 0.001);
  }
}

TEST(Toolpath, EndsAtTheFirstBlockWithErrorsAndWhenFull) {
  MachineConfig machine;
  Toolpath path;
  ToolpathSink sink(path, machine);
  sink.stop_at({false, false, true, false});
  Event block{EventKind::Block};
  for (uint32_t b = 0; b < 4; ++b) {
    block.source = b;
    sink.event(block);
    sink.event(move(EventKind::Linear, b, 0, 0, b));
  }
  EXPECT_EQ(path.moves.size(), 2u);
  EXPECT_EQ(path.stopped_at, 2u);
  EXPECT_EQ(path.moves[1].run, 2u);  // the block events so far: a loop's iterations apart

  Toolpath small;
  ToolpathSink full(small, machine, 0.001, 3);
  for (uint32_t b = 0; b < 5; ++b) full.event(move(EventKind::Linear, b, 0, 0, b));
  EXPECT_EQ(small.moves.size(), 3u);
  EXPECT_EQ(small.full_at, 3u);
}

}  // namespace
}  // namespace ncc::sim
