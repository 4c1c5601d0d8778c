#include "cycle_steps.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncc::cycle {

namespace {

// The steps written so far and where they leave the tool: go() makes no move to
// where it is already (ISO's rule), move() makes every one (GOST's).
struct Steps {
  std::vector<Step> out;
  double level = 0, shift = 0;

  void go(double to, bool feed, double by = 0) {
    if (to != level || by != shift) move(to, feed, by);
  }
  void move(double to, bool feed, double by = 0) { to_level(feed ? Step::Kind::Feed : Step::Kind::Rapid, to, by); }
  void to_level(Step::Kind kind, double to, double by = 0) {
    out.push_back({kind, to, by});
    level = to;
    shift = by;
  }
  void add(Step::Kind kind, double seconds = 0, Fn fn = Fn::SpindleStop, bool always = false) {
    out.push_back({kind, level, shift, seconds, fn, always});
  }
  // Up to R first where the tool starts below it; then over the hole.
  void start(double current, std::optional<double> up) {
    level = current;
    if (up) move(*up, false);
    add(Step::Kind::Over);
  }
  void spindle(Fn fn, bool always = false) { add(Step::Kind::Spindle, 0, fn, always); }
  void dwell(double seconds) { add(Step::Kind::Dwell, seconds); }
};

// A whole count up, not misled by rounding (25.999 / 0.001 is not 26000).
double up(double x) { return std::ceil(x - 1e-9 * std::max(1.0, x)); }

}  // namespace

std::optional<double> Pecks::count(double& stuck) const {
  if (!unloading()) return up((r1 - bottom) / step);
  double from = r1, peck = step;
  for (double n = 1;; ++n) {
    double reached = from - peck;
    if (reached <= bottom) return n;
    if (n > kMaxPecks) return std::numeric_limits<double>::infinity();  // how many more is not needed
    double following = next(peck);
    if (following <= clearance) {
      stuck = following;
      return std::nullopt;
    }
    // A steady peck gains peck - clearance each time: the rest by division.
    if (following == peck) return n + up((reached - bottom) / (peck - clearance));
    from = reached + clearance;
    peck = following;
  }
}

std::vector<Step> nc110_hole(const CyclePattern& pattern, const Nc110Hole& h) {
  using In = CyclePattern::In;
  const Pecks& pecks = h.pecks;
  Steps s;
  s.start(h.current, std::nullopt);
  s.go(pecks.r1, false);
  const Fn forward = h.direction > 0 ? Fn::SpindleCw : Fn::SpindleCcw;
  const Fn reverse = h.direction > 0 ? Fn::SpindleCcw : Fn::SpindleCw;
  const bool tapping = pattern.bottom == CyclePattern::Bottom::Reverse;
  if (pattern.in == In::SpindleFeed) s.spindle(forward);  // Table 2.6: where the spindle stands
  if (pattern.in == In::Peck && pecks.unloading()) {
    double from = pecks.r1, peck = pecks.step;
    while (true) {
      s.go(from, false);
      double reached = std::max(from - peck, pecks.bottom);
      s.move(reached, true);
      if (reached <= pecks.bottom) break;
      s.move(pecks.r1, false);
      from = reached + pecks.clearance;
      peck = pecks.next(peck);
    }
  } else if (pattern.in == In::Peck) {
    // Pecks of I with a dwell between them to break the chip.
    for (double reached = pecks.r1; reached > pecks.bottom;) {
      reached = std::max(reached - pecks.step, pecks.bottom);
      s.move(reached, true);
      if (reached > pecks.bottom) s.dwell(h.dwell);
    }
  } else {
    s.to_level(tapping ? Step::Kind::Tap : Step::Kind::Feed, pecks.bottom);
  }
  if (pattern.dwell) s.dwell(h.dwell);
  if (tapping) s.spindle(reverse, true);
  if (pattern.bottom == CyclePattern::Bottom::Stop) s.spindle(Fn::SpindleStop, true);
  if (pattern.out == CyclePattern::Out::Feed) {
    s.to_level(tapping ? Step::Kind::TapOut : Step::Kind::Feed, pecks.r1);
    if (h.r2 != pecks.r1) s.move(h.r2, false);
  } else {
    s.move(h.r2, false);
  }
  if (tapping) s.spindle(forward, true);
  return s.out;
}

std::vector<Step> iso_hole(const CyclePattern& pattern, const Hole& h, const Conventions& conv) {
  using In = CyclePattern::In;
  Steps s;
  const double down = h.bottom < h.level ? -1 : 1;  // the direction into the hole (G87: out of it)
  // A start below R goes up to R first, and R is the initial level then; G87 always
  // comes back to the initial level (decision 21).
  const bool below_level = pattern.in != In::Back && (down < 0 ? h.initial < h.level : h.initial > h.level);
  const double initial = below_level ? h.level : h.initial;
  const double back = h.return_level && pattern.in != In::Back ? h.level : initial;
  s.start(h.current, below_level && h.current != h.level ? std::optional(h.level) : std::nullopt);
  const Fn forward = h.direction > 0 ? Fn::SpindleCw : Fn::SpindleCcw;
  const bool pecks = pattern.in == In::Peck || pattern.in == In::ChipBreak;
  if (pattern.in == In::Back) {
    // §8.27 G87: oriented stop, shift, down to R, shift back, spindle on, bore up.
    s.spindle(Fn::SpindleOrient);
    s.go(initial, false, h.shift);
    s.go(h.level, false, h.shift);
    s.go(h.level, true);
    s.spindle(Fn::SpindleCw);
    s.go(h.bottom, true);
  } else {
    s.go(h.level, false);
    const bool tap = pattern.in == In::TapCw || pattern.in == In::TapCcw;
    const Fn tap_in = pattern.in == In::TapCw ? Fn::SpindleCw : Fn::SpindleCcw;
    const Fn tap_out = pattern.in == In::TapCw ? Fn::SpindleCcw : Fn::SpindleCw;
    if (tap) s.spindle(tap_in);
    if (pecks || (tap && h.peck)) {
      double reached = h.level;
      while (true) {
        double next = reached + down * *h.peck;
        if (next * down >= h.bottom * down) next = h.bottom;
        s.go(next, true);
        if (next == h.bottom) break;
        if (pattern.in == In::Peck) {
          // G83: out to R, back at rapid to just above the depth reached (decision 19).
          s.go(h.level, false);
          s.go(next - down * conv.peck_clearance, false);
        } else if (pattern.in == In::ChipBreak) {
          // G73 (§8.25): up to the depth of the pass before, or by the machine's retract.
          s.go(conv.chip_break_retract > 0 ? next - down * conv.chip_break_retract : reached, false);
        } else {
          // Peck tapping (decision 20): out to R reversed, back in to the depth reached.
          s.spindle(tap_out);
          s.go(h.level, true);
          s.spindle(tap_in);
          s.go(next, true);
        }
        reached = next;
      }
    } else {
      s.go(h.bottom, true);
    }
    if (h.dwell > 0) s.dwell(h.dwell);
    if (tap) {
      s.spindle(tap_out);
      s.go(h.level, true);
      s.spindle(tap_in);
      if (back != h.level) s.go(back, false);
      return s.out;
    }
  }
  if (pattern.in == In::Back && h.dwell > 0) s.dwell(h.dwell);
  switch (pattern.bottom) {
    case CyclePattern::Bottom::Stop: s.spindle(Fn::SpindleStop); break;
    case CyclePattern::Bottom::OrientShift:
      // §8.27 G76: oriented stop, shift off the wall at feed; G87 shifts at rapid.
      s.spindle(Fn::SpindleOrient);
      s.go(h.bottom, pattern.in != In::Back, h.shift);
      break;
    default: break;
  }
  const double sideways = pattern.bottom == CyclePattern::Bottom::OrientShift ? h.shift : 0;
  if (pattern.out == CyclePattern::Out::Feed) {
    s.go(h.level, true);  // §8.27 G85, G89: out to R at feed, then at rapid
    s.go(back, false);
  } else {
    s.go(back, pattern.in == In::Back, sideways);  // G87 withdraws at feed (§8.27 step 11)
  }
  if (sideways != 0) s.go(back, false);
  if (pattern.bottom != CyclePattern::Bottom::None) s.spindle(forward);  // restarted after the cycle
  return s.out;
}

std::vector<Step> hole(const CyclePattern& pattern, const Hole& h) {
  using In = CyclePattern::In;
  Steps s;
  // The tool never travels between holes on the work side of R: a start below R
  // first goes up to R, and R is then the initial level it returns to.
  const bool below_level = h.bottom < h.level ? h.current < h.level : h.current > h.level;
  const double initial = below_level ? h.level : h.current;
  s.start(h.current, below_level ? std::optional(h.level) : std::nullopt);
  s.go(h.level, false);
  if (pattern.in == In::SpindleFeed) s.spindle(h.direction > 0 ? Fn::SpindleCw : Fn::SpindleCcw);
  if (pattern.in == In::Peck) {
    // Pecks of the peck word, each followed by a rapid withdrawal to R and a rapid
    // return to the depth reached.
    const double step = *h.peck * (h.bottom < h.level ? -1 : 1);
    double reached = h.level;
    while (true) {
      double next = reached + step;
      if ((step < 0 && next <= h.bottom) || (step > 0 && next >= h.bottom)) next = h.bottom;
      s.move(next, true);
      if (next == h.bottom) break;
      s.move(h.level, false);
      s.move(next, false);
      reached = next;
    }
  } else {
    s.move(h.bottom, true);
  }
  if (pattern.dwell) s.dwell(h.dwell);
  const Fn forward = h.direction > 0 ? Fn::SpindleCw : Fn::SpindleCcw;
  const Fn reverse = h.direction > 0 ? Fn::SpindleCcw : Fn::SpindleCw;
  if (pattern.bottom == CyclePattern::Bottom::Reverse) s.spindle(reverse, true);
  if (pattern.bottom == CyclePattern::Bottom::Stop) s.spindle(Fn::SpindleStop, true);
  switch (pattern.out) {
    case CyclePattern::Out::Rapid: s.move(initial, false); break;
    case CyclePattern::Out::Feed: s.move(initial, true); break;
    case CyclePattern::Out::Manual: s.level = initial, s.add(Step::Kind::Manual); break;
  }
  if (pattern.bottom == CyclePattern::Bottom::Reverse) s.spindle(forward, true);
  return s.out;
}

}  // namespace ncc::cycle
