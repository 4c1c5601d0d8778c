// A canned cycle's hole as steps along its drilling axis: pure, so that the machine
// runs them (machine_cycles.cpp) and a translation writes them as moves where the
// target has no cycle of the pattern (compiler/translate/structured_cycle.cpp).
#pragma once

#include <optional>
#include <vector>

#include "contract/program_semantics.h"

namespace ncc::cycle {

// What a spindle code leaves the spindle doing, as the machine keeps it (its modal
// spindle): 1 clockwise, -1 counter-clockwise, 0 stopped, 2 oriented.
constexpr int spindle_turns(Fn spindle) {
  return spindle == Fn::SpindleCw ? 1 : spindle == Fn::SpindleCcw ? -1 : spindle == Fn::SpindleStop ? 0 : 2;
}

struct Step {
  // Over: at rapid over the hole, at the level the tool is at, unless it is there
  // already; the moves before it (up to R first) are where the tool stands. Manual:
  // the operator takes the tool out by hand to `level` (GOST's G88). Tap, TapOut:
  // NC-110's tap in and out, moves the machine makes its own way (Machine::tap_feed()).
  enum class Kind : uint8_t { Rapid, Feed, Over, Dwell, Spindle, Manual, Tap, TapOut };
  Kind kind = Kind::Rapid;
  double level = 0;              // a move: where along the drilling axis
  double shift = 0;              // a move: off the hole along the plane's first axis (G76, G87)
  double seconds = 0;            // Dwell
  Fn spindle = Fn::SpindleStop;  // Spindle: the code the machine applies ...
  bool always = false;           // ... even where the spindle runs (or stands) so already
};

// One hole of a cycle of one level R (ISO, GOST 20999, pp), in the machine's
// coordinates along the drilling axis. The steps begin where the tool stands:
// `current` on the axis, not yet over the hole.
struct Hole {
  double initial = 0;  // the level the cycle mode began at (ISO) or the hole begins at (GOST, pp)
  double current = 0;
  double level = 0;  // R
  double bottom = 0;
  std::optional<double> peck;  // mm: ISO's Q, GOST's and pp's peck word
  double dwell = 0;            // seconds at the bottom
  double shift = 0;            // G76, G87: the shift off the wall, signed
  bool return_level = false;   // ISO's G99: back to R, not the initial level
  int direction = 1;           // the spindle's last direction (+1 cw, -1 ccw): a stopped spindle restarts so
};

constexpr int kMaxPecks = 10000;  // per hole

// G83's pecks (NC-110 §2.8.9.2, decisions 21 and 53), program coordinates along the
// drilling axis. Without K and J each peck of I goes on from the depth reached; with
// them the tool unloads the chips at R1 after each peck, comes back to `clearance`
// above the depth reached, and the peck changes by the factor K down to J.
struct Pecks {
  double r1 = 0, bottom = 0, step = 0, clearance = 0;
  std::optional<double> factor, minimum;

  bool unloading() const { return factor || minimum; }
  double next(double peck) const {
    double n = peck * factor.value_or(1);
    return minimum && n < *minimum ? *minimum : n;
  }
  // How many pecks reach the bottom; nullopt when a peck (`stuck`) would not get
  // deeper than the clearance it comes back (the hole would never end).
  [[nodiscard]] std::optional<double> count(double& stuck) const;
};

// One hole of NC-110's cycles (§2.8.9.4), in program coordinates along the drilling
// axis, downwards: over the hole where the tool is, R1, the hole, back to R2.
struct Nc110Hole {
  double current = 0, r2 = 0;
  Pecks pecks;        // r1, bottom; step and the rest for G83
  double dwell = 0;   // seconds: TMR's, at the bottom and between G83's pecks without unloading
  int direction = 1;  // the spindle's last direction
};
std::vector<Step> nc110_hole(const CyclePattern& pattern, const Nc110Hole& hole);

// ISO's cycles (§8.21-8.27, decisions 19-21); `conv` gives the peck clearance, the
// chip break retract. The moves of zero length are not made.
std::vector<Step> iso_hole(const CyclePattern& pattern, const Hole& hole, const Conventions& conv);

// GOST 20999's and pp's (Table 6; pp §G81-G89), from `current`, which is the
// initial level; `return_level` is not theirs.
std::vector<Step> hole(const CyclePattern& pattern, const Hole& hole);

}  // namespace ncc::cycle
