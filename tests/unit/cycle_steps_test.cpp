// A canned cycle's hole as steps (runtime/cycle_steps.h), the moves the machine runs
// and a translation writes: each family's order, which moves it leaves out, and
// where the tool ends.
#include "runtime/cycle_steps.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace ncc {
namespace {

using Kind = cycle::Step::Kind;

// The steps as text: "over", "rapid 2", "feed -5", "dwell 0.5", "M04" (spindle),
// "X+1" (a shift off the hole), "manual 10", "tap -20", "tap out 5".
std::string text(const std::vector<cycle::Step>& steps) {
  std::string out;
  double shift = 0;
  for (const cycle::Step& s : steps) {
    std::string one;
    auto number = [](double v) {
      std::string t = std::to_string(v);
      t.erase(t.find_last_not_of('0') + 1);
      if (t.back() == '.') t.pop_back();
      return t;
    };
    if (s.shift != shift) one += "X+" + number(s.shift) + " ", shift = s.shift;
    switch (s.kind) {
      case Kind::Over: one += "over"; break;
      case Kind::Rapid: one += "rapid " + number(s.level); break;
      case Kind::Feed: one += "feed " + number(s.level); break;
      case Kind::Dwell: one += "dwell " + number(s.seconds); break;
      case Kind::Manual: one += "manual " + number(s.level); break;
      case Kind::Tap: one += "tap " + number(s.level); break;
      case Kind::TapOut: one += "tap out " + number(s.level); break;
      case Kind::Spindle:
        one += s.spindle == Fn::SpindleCw     ? "M03"
               : s.spindle == Fn::SpindleCcw  ? "M04"
               : s.spindle == Fn::SpindleStop ? "M05"
                                              : "M19";
        if (s.always) one += "!";
        break;
    }
    out += (out.empty() ? "" : ", ") + one;
  }
  return out;
}

CyclePattern pattern(CyclePattern::In in, CyclePattern::Out out = CyclePattern::Out::Rapid,
                     CyclePattern::Bottom bottom = CyclePattern::Bottom::None, bool dwell = false) {
  CyclePattern p;
  p.in = in;
  p.out = out;
  p.bottom = bottom;
  p.dwell = dwell;
  return p;
}

// A hole from `start` (the initial level and where the tool is), R `level`, `bottom`.
cycle::Hole from(double start, double level, double bottom) {
  cycle::Hole h;
  h.initial = h.current = start;
  h.level = level;
  h.bottom = bottom;
  return h;
}

TEST(CycleSteps, IsoPecksComeBackAboveTheDepthReached) {
  // G98 G83 R2 Z-10 Q4 from Z20, the clearance 0.254 (decision 19).
  cycle::Hole h = from(20, 2, -10);
  h.peck = 4;
  Conventions conv;
  conv.peck_clearance = 0.254;
  EXPECT_EQ(text(cycle::iso_hole(pattern(CyclePattern::In::Peck), h, conv)),
            "over, rapid 2, feed -2, rapid 2, rapid -1.746, feed -6, rapid 2, rapid -5.746, feed -10, rapid 20");
}

TEST(CycleSteps, IsoStartBelowRGoesUpFirstAndMakesNoMoveOfNothing) {
  // G99 G81 R2 Z-5 from Z0: up to R where the tool stands, over the hole at R (no
  // move down to R, it is there), back to R (no move either).
  cycle::Hole h = from(0, 2, -5);
  h.return_level = true;
  EXPECT_EQ(text(cycle::iso_hole(pattern(CyclePattern::In::Feed), h, {})), "rapid 2, over, feed -5, rapid 2");
}

TEST(CycleSteps, IsoTappingTurnsTheSpindleTheTapsWay) {
  // G98 G84 R2 Z-10 from Z20, the spindle ccw before (decision 20): cw in, ccw out,
  // cw again, then up to the initial level.
  cycle::Hole h = from(20, 2, -10);
  h.direction = -1;
  EXPECT_EQ(text(cycle::iso_hole(pattern(CyclePattern::In::TapCw), h, {})),
            "over, rapid 2, M03, feed -10, M04, feed 2, M03, rapid 20");
}

TEST(CycleSteps, IsoBoringShiftsOffTheWall) {
  // G76 R2 Z-5 Q1 under G99: an oriented stop at the bottom, a shift at feed, out
  // shifted, back over the hole, the spindle restarted.
  cycle::Hole h = from(20, 2, -5);
  h.shift = 1;
  h.return_level = true;
  EXPECT_EQ(text(cycle::iso_hole(
                pattern(CyclePattern::In::Feed, CyclePattern::Out::Rapid, CyclePattern::Bottom::OrientShift), h, {})),
            "over, rapid 2, feed -5, M19, X+1 feed -5, rapid 2, X+0 rapid 2, M03");
}

TEST(CycleSteps, GostMakesEveryMoveAndFeedsOutAllTheWay) {
  // GOST's G85 R1 Z-6 from Z10: every move made, out at feed to where it began; G86
  // stops the spindle at the bottom whatever it does, and restarts none.
  cycle::Hole h = from(10, 1, -6);
  EXPECT_EQ(text(cycle::hole(pattern(CyclePattern::In::Feed, CyclePattern::Out::Feed), h)),
            "over, rapid 1, feed -6, feed 10");
  EXPECT_EQ(text(cycle::hole(
                pattern(CyclePattern::In::SpindleFeed, CyclePattern::Out::Rapid, CyclePattern::Bottom::Stop), h)),
            "over, rapid 1, M03, feed -6, M05!, rapid 10");
  EXPECT_EQ(text(cycle::hole(pattern(CyclePattern::In::Feed, CyclePattern::Out::Manual), h)),
            "over, rapid 1, feed -6, manual 10");
}

TEST(CycleSteps, Nc110UnloadsTheChipsAndReturnsToR2) {
  // NC-110's G83 R2 R20 Z-25 I10 K1 from Z100 (cycles-g83-variants): each peck back
  // to R1, then to 1 mm above the depth reached; out to R2.
  cycle::Nc110Hole h;
  h.current = 100;
  h.r2 = 20;
  h.pecks = {2, -25, 10, 1, 1.0, std::nullopt};
  EXPECT_EQ(text(cycle::nc110_hole(pattern(CyclePattern::In::Peck), h)),
            "over, rapid 2, feed -8, rapid 2, rapid -7, feed -17, rapid 2, rapid -16, feed -25, rapid 20");
  // Without K and J: pecks of I, TMR's dwell between them.
  h.pecks.factor.reset();
  h.dwell = 0.5;
  EXPECT_EQ(text(cycle::nc110_hole(pattern(CyclePattern::In::Peck), h)),
            "over, rapid 2, feed -8, dwell 0.5, feed -18, dwell 0.5, feed -25, rapid 20");
}

TEST(CycleSteps, Nc110TapsItsOwnWay) {
  // G84 R5 R12 Z-20: the tap in and out are the machine's moves (a spindle-synchronised
  // move, RMS), the spindle reversed at the bottom and forward again after the return.
  cycle::Nc110Hole h;
  h.current = 100;
  h.r2 = 12;
  h.pecks.r1 = 5;
  h.pecks.bottom = -20;
  h.direction = -1;
  EXPECT_EQ(text(cycle::nc110_hole(
                pattern(CyclePattern::In::Feed, CyclePattern::Out::Feed, CyclePattern::Bottom::Reverse), h)),
            "over, rapid 5, tap -20, M03!, tap out 5, rapid 12, M04!");
}

}  // namespace
}  // namespace ncc
