// Canned cycles (GOST 20999 Table 6; NC-110 §2.8.9) and the NC-110 measuring cycles
// G72-G74 (§2.8.12) against a simulated probe.
#include <cmath>
#include <limits>

#include "machine.h"
#include "support/text.h"

namespace ncc {

namespace {

constexpr int kMaxPecks = 10000;  // per hole
constexpr double kUnloadClearance = 1;  // mm: G83 goes back to 1 mm above the last bottom (§2.8.9.2)

}  // namespace

// ---- GOST 20999 ---------------------------------------------------------------------

void Machine::cycle_registers() {
  // The cycle registers stay in force while the cycle is active (S-7.5); any block
  // may change them, the cycle runs only in blocks with a dimension word.
  const char depth_letter = kAxisLetters[modal_.plane.w];
  if (has(depth_letter)) cycle_.depth = word(depth_letter);
  if (auto v = word_if(conv_.cycle_level_word)) cycle_.level = v;
  if (auto v = word_if(conv_.dwell_word)) cycle_.dwell = v;
  if (auto v = word_if(conv_.peck_word)) cycle_.peck = v;
}

void Machine::repeat_cycle() {
  int count = 1;
  for (char letter : conv_.cycle_repeat_words) {
    if (!has(letter)) continue;
    const double v = word(letter);
    const std::optional<int> n = whole_in(v, 0, 9999);
    if (!n) {
      report(DiagId::RepeatCount, letter, shortest(v), 9999);
      return;
    }
    count = *n;
    break;
  }
  if (count == 0) cycle_registers();  // L0: the cycle's words are stored, no hole is made
  for (int i = 0; i < count && !block_.error; ++i) iso_cycle();
}

void Machine::iso_cycle() {
  const CyclePattern& pattern = sem_.cycles[modal_.cycle];
  using In = CyclePattern::In;
  const std::string name = "canned cycle " + pattern.name;
  const int d = modal_.plane.w;  // the drilling axis
  const int u = modal_.plane.u;  // G76/G87 shift along the plane's first axis
  cycle_registers();
  AxisValues hole = target();
  hole[d] = machine_[d];
  bool ok = true;
  if (!cycle_.depth) ok = (report(DiagId::CycleNoDepth, 0, pattern.name, std::string(1, kAxisLetters[d])), false);
  if (!cycle_.level) ok = (report(DiagId::CycleNoRLevel, 0, pattern.name), false);
  const bool pecks = pattern.in == In::Peck || pattern.in == In::ChipBreak;
  const bool shifts = pattern.bottom == CyclePattern::Bottom::OrientShift;
  if (ok && pecks && !cycle_.peck) ok = (report(DiagId::CycleNoPeck, 0, pattern.name, "Q"), false);
  if (ok && (pecks || (cycle_.peck && pattern.in != In::Feed && !shifts)) && cycle_.peck && *cycle_.peck <= 0)
    ok = (report(DiagId::PeckNotPositive, 'Q', "peck depth", four_decimals(*cycle_.peck), "greater than zero", pattern.name), false);
  if (ok && shifts && !cycle_.peck) ok = (report(DiagId::CycleNoPeck, 0, pattern.name, "Q (the shift off the wall)"), false);
  const double dwell = pattern.dwell && cycle_.dwell ? *cycle_.dwell : 0;
  if (ok && dwell < 0) ok = (report(DiagId::DwellNegative, 'P', four_decimals(dwell)), false);
  if (!ok || !need_feed(name.c_str(), hole)) {
    move_to(hole);
    return;
  }
  // G90: R and the bottom are coordinates; G91: R from the initial level, the bottom
  // from R (§8.23). The initial level is where the tool stood when the cycle mode
  // began (§8.21: "the position before the cycle").
  if (!initial_level_) initial_level_ = machine_[d];
  const double start = *initial_level_;
  const AxisValues off = target_frame();
  const double level = modal_.absolute ? length_units(*cycle_.level) + off[d] : start + length_units(*cycle_.level);
  const double bottom = modal_.absolute ? length_units(*cycle_.depth) + off[d] : level + length_units(*cycle_.depth);
  const double down = bottom < level ? -1 : 1;  // the direction into the hole (G87: out of it)
  if (pattern.in == In::Back && bottom < level) {
    // §8.27: G87 bores from R up to Z, so Z lies above R.
    report(DiagId::CycleDefinition, 0, fmt::format("canned cycle G87 bores upwards from R: the bottom {} must lie above R {}",
                                                   four_decimals(to_program(bottom - off[d])), four_decimals(to_program(level - off[d]))));
    move_to(hole);
    return;
  }
  // A start below R goes up to R first, and R is the initial level then; G87 always
  // comes back to the initial level (decision 21).
  const bool below_level = pattern.in != In::Back && (down < 0 ? start < level : start > level);
  const double initial = below_level ? level : start;
  const double back = modal_.cycle_return_level && pattern.in != In::Back ? level : initial;
  auto at = [&](double z, double shift = 0) {
    AxisValues p = hole;
    p[d] = z;
    p[u] += shift;
    return p;
  };
  auto go = [&](const AxisValues& p, bool feed) {
    if (p == machine_) return;
    feed ? linear(p) : rapid(p);
  };
  if (below_level) {
    AxisValues up = machine_;
    up[d] = level;
    go(up, false);
  }
  go(at(machine_[d]), false);
  const int direction = spindle_direction_ ? spindle_direction_ : 1;
  const double shift = shifts ? length_units(*cycle_.peck) * conv_.boring_shift : 0;
  auto spindle = [&](Fn fn) {
    if ((fn == Fn::SpindleCw && modal_.spindle == 1) || (fn == Fn::SpindleCcw && modal_.spindle == -1) ||
        (fn == Fn::SpindleStop && modal_.spindle == 0))
      return;
    apply({fn}, Scope::Modal, true);
  };
  const Fn forward = direction > 0 ? Fn::SpindleCw : Fn::SpindleCcw;
  if (pattern.in == In::Back) {
    // §8.27 G87: oriented stop, shift, down to R, shift back, spindle on, bore up.
    spindle(Fn::SpindleOrient);
    go(at(initial, shift), false);
    go(at(level, shift), false);
    go(at(level), true);
    spindle(Fn::SpindleCw);
    go(at(bottom), true);
  } else {
    go(at(level), false);
    const bool tap = pattern.in == In::TapCw || pattern.in == In::TapCcw;
    const Fn tap_in = pattern.in == In::TapCw ? Fn::SpindleCw : Fn::SpindleCcw;
    const Fn tap_out = pattern.in == In::TapCw ? Fn::SpindleCcw : Fn::SpindleCw;
    if (tap) spindle(tap_in);
    if (pecks || (tap && cycle_.peck)) {
      const double step = length_units(*cycle_.peck);
      const double count = std::ceil(std::fabs(bottom - level) / step - 1e-9);
      if (count > kMaxPecks) {
        report(DiagId::CyclePecks, 'Q', pattern.name, four_decimals(count), four_decimals(*cycle_.peck), kMaxPecks);
        return;
      }
      double reached = level;
      while (true) {
        double next = reached + down * step;
        if (next * down >= bottom * down) next = bottom;
        go(at(next), true);
        if (next == bottom) break;
        if (pattern.in == In::Peck) {
          // G83: out to R, back at rapid to just above the depth reached (decision 19).
          go(at(level), false);
          go(at(next - down * conv_.peck_clearance), false);
        } else if (pattern.in == In::ChipBreak) {
          // G73 (§8.25): up to the depth of the pass before, or by the machine's retract.
          go(at(conv_.chip_break_retract > 0 ? next - down * conv_.chip_break_retract : reached), false);
        } else {
          // Peck tapping (decision 20): out to R reversed, back in to the depth reached.
          spindle(tap_out);
          go(at(level), true);
          spindle(tap_in);
          go(at(next), true);
        }
        reached = next;
      }
    } else {
      go(at(bottom), true);
    }
    if (dwell > 0) dwell_seconds(dwell);
    if (tap) {
      spindle(tap_out);
      go(at(level), true);
      spindle(tap_in);
      if (back != level) go(at(back), false);
      return;
    }
  }
  if (pattern.in == In::Back && dwell > 0) dwell_seconds(dwell);
  switch (pattern.bottom) {
    case CyclePattern::Bottom::Stop: spindle(Fn::SpindleStop); break;
    case CyclePattern::Bottom::OrientShift:
      // §8.27 G76: oriented stop, shift off the wall at feed; G87 shifts at rapid.
      spindle(Fn::SpindleOrient);
      go(at(bottom, shift), pattern.in != In::Back);
      break;
    default: break;
  }
  const double sideways = pattern.bottom == CyclePattern::Bottom::OrientShift ? shift : 0;
  if (pattern.out == CyclePattern::Out::Feed) {
    go(at(level), true);  // §8.27 G85, G89: out to R at feed, then at rapid
    go(at(back), false);
  } else {
    // G87 withdraws at feed (§8.27 step 11).
    go(at(back, sideways), pattern.in == In::Back);
  }
  if (sideways != 0) go(at(back), false);
  if (pattern.bottom != CyclePattern::Bottom::None) spindle(forward);  // restarted after the cycle
}

void Machine::cycle() {
  const CyclePattern& pattern = sem_.cycles[modal_.cycle];
  const std::string name = "canned cycle " + pattern.name;
  const int d = modal_.plane.w;  // the drilling axis: perpendicular to the plane
  const char depth_letter = kAxisLetters[d];
  cycle_registers();
  AxisValues hole = target();
  hole[d] = machine_[d];
  bool ok = true;
  if (!cycle_.depth) {
    report(DiagId::CycleNoDepth, 0, pattern.name, std::string(1, depth_letter));
    ok = false;
  }
  if (!cycle_.level) {
    report(DiagId::CycleNoRLevel, 0, pattern.name);
    ok = false;
  }
  if (ok && pattern.in == CyclePattern::In::Peck) {
    if (!cycle_.peck) {
      report(DiagId::CycleNoPeck, 0, pattern.name, conv_.peck_word ? std::string(1, conv_.peck_word) : "Q");
      ok = false;
    } else if (*cycle_.peck <= 0) {
      report(DiagId::PeckNotPositive, conv_.peck_word, "peck increment", four_decimals(*cycle_.peck),
             "greater than zero", pattern.name);
      ok = false;
    }
  }
  if (ok && pattern.dwell && !cycle_.dwell) {
    report(DiagId::CycleNoDwell, 0, pattern.name, dwell_address());
    ok = false;
  } else if (ok && pattern.dwell && *cycle_.dwell < 0) {
    report(DiagId::DwellNegative, conv_.dwell_word, four_decimals(*cycle_.dwell));
    ok = false;
  }
  if (ok && pattern.in == CyclePattern::In::SpindleFeed && spindle_direction_ == 0) {
    report(DiagId::CycleNoSpindle, 0, pattern.name);
    ok = false;
  }
  if (!ok || !need_feed(name.c_str(), hole)) {
    move_to(hole);
    return;
  }
  // G90: R and the depth are coordinates; G91: R is measured from the initial level
  // and the depth from R.
  const double start = machine_[d];
  AxisValues off = target_frame();
  const double level = modal_.absolute ? length_units(*cycle_.level) + off[d] : start + length_units(*cycle_.level);
  const double bottom = modal_.absolute ? length_units(*cycle_.depth) + off[d] : level + length_units(*cycle_.depth);
  // The tool never travels between holes on the work side of R: a start below R
  // first goes up to R, and R is then the initial level it returns to.
  const bool below_level = (bottom < level) ? start < level : start > level;
  const double initial = below_level ? level : start;
  auto at = [&](double z) {
    AxisValues p = hole;
    p[d] = z;
    return p;
  };
  if (below_level) {
    AxisValues up = machine_;
    up[d] = level;
    rapid(up);
  }
  // Moves of zero length (already at the hole, R equal to the initial level) are
  // not made.
  if (hole != machine_) rapid(at(machine_[d]));
  if (level != machine_[d]) rapid(at(level));
  if (pattern.in == CyclePattern::In::SpindleFeed && modal_.spindle != spindle_direction_)
    apply({spindle_direction_ > 0 ? Fn::SpindleCw : Fn::SpindleCcw}, Scope::Modal, true);
  if (pattern.in == CyclePattern::In::Peck) {
    // Pecks of Q, each followed by a rapid withdrawal to R and a rapid return to the
    // depth reached.
    double pecks = std::ceil(std::fabs(bottom - level) / length_units(*cycle_.peck));
    if (pecks > kMaxPecks) {
      report(DiagId::CyclePecks, conv_.peck_word, pattern.name, four_decimals(pecks), four_decimals(*cycle_.peck),
             kMaxPecks);
      return;
    }
    const double step = length_units(*cycle_.peck) * (bottom < level ? -1 : 1);
    double reached = level;
    while (true) {
      double next = reached + step;
      if ((step < 0 && next <= bottom) || (step > 0 && next >= bottom)) next = bottom;
      linear(at(next));
      if (next == bottom) break;
      rapid(at(level));
      rapid(at(next));
      reached = next;
    }
  } else {
    linear(at(bottom));
  }
  if (pattern.dwell) dwell_seconds(*cycle_.dwell * conv_.dwell_seconds_per_unit);
  const int direction = spindle_direction_;
  if (pattern.bottom == CyclePattern::Bottom::Reverse)
    apply({direction > 0 ? Fn::SpindleCcw : Fn::SpindleCw}, Scope::Modal, true);
  if (pattern.bottom == CyclePattern::Bottom::Stop) apply({Fn::SpindleStop}, Scope::Modal, true);
  switch (pattern.out) {
    case CyclePattern::Out::Rapid: rapid(at(initial)); break;
    case CyclePattern::Out::Feed: linear(at(initial)); break;
    case CyclePattern::Out::Manual: {
      // The operator retracts by hand: the run stops; on resume the tool is at the
      // initial level (S-7.5).
      Event stop{EventKind::Stop};
      stop.n = 3;
      emit(stop);
      emit(motion_event(EventKind::OperatorMove, at(initial)));
      move_to(at(initial));
      break;
    }
  }
  if (pattern.bottom == CyclePattern::Bottom::Reverse)
    apply({direction > 0 ? Fn::SpindleCw : Fn::SpindleCcw}, Scope::Modal, true);
}

// ---- NC-110 -------------------------------------------------------------------------

void Machine::nc110_cycle_registers(bool definition) {
  // R words: R1 then R2; one R is both (§2.8.9.4). Levels become program coordinates
  // where they are written: G91 measures R from the axis' position, the depth from R1.
  const int d = cycle_.axis;
  const double here = to_frame(machine_)[d];
  const bool absolute = modal_.absolute;
  auto level = [&](double v) { return absolute ? axis_units(d, v) : here + axis_units(d, v); };
  if (auto r1 = word_if('R')) {
    cycle_.r1 = level(*r1);
    cycle_.r2 = has_slot(second_slot('R')) ? level(slot_value(second_slot('R'))) : *cycle_.r1;
  } else if (definition) {
    cycle_.r1 = cycle_.r2 = here;  // no R: the level the tool is at (decision 13)
  }
  if (has(kAxisLetters[d])) {
    double v = axis_units(d, word(kAxisLetters[d]));
    cycle_.bottom = absolute ? v : *cycle_.r1 + v;
  }
  const CyclePattern& pattern = sem_.cycles[modal_.cycle];
  if (pattern.in == CyclePattern::In::Peck) {
    if (auto v = word_if(conv_.peck_word)) cycle_.step = length_units(*v);
    if (auto v = word_if(conv_.peck_factor_word)) cycle_.factor = *v;
    if (auto v = word_if(conv_.peck_minimum_word)) cycle_.minimum = length_units(*v);
  }
  if (pattern.bottom == CyclePattern::Bottom::Reverse)
    if (auto v = word_if(conv_.tap_pitch_word)) cycle_.pitch = length_units(*v);
}

namespace {

// G83's pecks (NC-110 §2.8.9.2, decisions 21 and 53), program coordinates along the
// drilling axis. Without K and J each peck of I goes on from the depth reached; with
// them the tool unloads the chips at R1 after each peck, comes back to `clearance`
// above the depth reached, and the peck changes by the factor K down to J.
struct Pecks {
  double r1 = 0, bottom = 0, step = 0, clearance = 0;
  std::optional<double> factor, minimum;

  bool unloading() const { return factor || minimum; }
  // A whole count up, not misled by rounding (25.999 / 0.001 is not 26000).
  static double up(double x) { return std::ceil(x - 1e-9 * std::max(1.0, x)); }
  double next(double peck) const {
    double n = peck * factor.value_or(1);
    return minimum && n < *minimum ? *minimum : n;
  }
  // How many pecks reach the bottom; nullopt when a peck (`stuck`) would not get
  // deeper than the clearance it comes back (the hole would never end).
  std::optional<double> count(double& stuck) const {
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
};

}  // namespace

bool Machine::nc110_cycle_definition(const CyclePattern& pattern, const std::vector<int>& written) {
  const std::string& name = pattern.name;
  if (written.size() != 1) {
    report(DiagId::CycleDefinition, 0,
           written.empty() ? fmt::format("{} needs the hole's depth: an axis word whose letter names the drilling axis", name)
                           : fmt::format("the block of {} holds the depth and no other axis: the holes' positions come in the blocks after it", name));
    return false;
  }
  cycle_.axis = written[0];
  nc110_cycle_registers(true);
  if (pattern.in == CyclePattern::In::Peck && !cycle_.step) {
    report(DiagId::CycleNoPeck, 0, name, std::string(1, conv_.peck_word));
    return false;
  }
  return nc110_levels_ok(pattern) && nc110_registers_ok(pattern);
}

bool Machine::nc110_registers_ok(const CyclePattern& pattern) {
  // Checked where they are written: in the cycle's block and in any hole's.
  auto wrong = [&](char letter, const char* what, double v, const char* must) {
    report(DiagId::PeckNotPositive, letter, fmt::format("the {} {}", what, letter), shortest(v), must, pattern.name);
    return false;
  };
  if (pattern.in == CyclePattern::In::Peck) {
    if (cycle_.step && *cycle_.step <= 0)
      return wrong(conv_.peck_word, "peck increment", to_program(*cycle_.step), "greater than zero");
    if (cycle_.factor && *cycle_.factor <= 0)
      return wrong(conv_.peck_factor_word, "peck factor", *cycle_.factor, "greater than zero");
    if (cycle_.minimum && *cycle_.minimum < 0)
      return wrong(conv_.peck_minimum_word, "minimum peck", to_program(*cycle_.minimum), "zero or more");
  }
  if (cycle_.pitch && *cycle_.pitch <= 0)
    return wrong(conv_.tap_pitch_word, "tapping pitch", to_program(*cycle_.pitch), "greater than zero");
  if (cycle_.pitch && !config_.spindle_encoder) {
    report(DiagId::ThreadEncoder, conv_.tap_pitch_word, pattern.name + " with K");
    return false;
  }
  return true;
}

bool Machine::nc110_levels_ok(const CyclePattern& pattern) {
  const int d = cycle_.axis;
  const char letter = kAxisLetters[d];
  if (*cycle_.bottom >= *cycle_.r1) {
    report(DiagId::CycleDefinition, letter,
           fmt::format("the hole's bottom {}{} is not below R1 {}: {} drills from R1 towards minus {}", letter,
                       four_decimals(program_axis(d, *cycle_.bottom)), four_decimals(program_axis(d, *cycle_.r1)),
                       pattern.name, letter));
    return false;
  }
  if (*cycle_.r2 < *cycle_.r1) {
    report_slot(DiagId::CycleDefinition, second_slot('R'),
                fmt::format("R2 {} lies below R1 {}: R2, the level the tool returns to, must not lie below R1",
                            four_decimals(program_axis(d, *cycle_.r2)), four_decimals(program_axis(d, *cycle_.r1))));
    return false;
  }
  return true;
}

void Machine::nc110_cycle() {
  const CyclePattern& pattern = sem_.cycles[modal_.cycle];
  const std::string& name = pattern.name;
  std::vector<int> written;
  for (char c : conv_.axes)
    if (has(c)) written.push_back(axis_index(c));

  // The cycle's block stores it; the depth word's letter names the drilling axis
  // (§2.8.9 note 1). A definition with an error leaves no cycle active.
  if (cycle_.defined_here) {
    cycle_.defined_here = false;
    if (!nc110_cycle_definition(pattern, written)) modal_.cycle = -1;
    return;
  }

  const int d = cycle_.axis;
  nc110_cycle_registers(false);
  bool hole = false;
  for (int a : written) hole = hole || a != d;
  if (!hole) return;  // new levels only

  // Per hole (§2.8.9.4): the position at the height the tool is at, R1, the hole, back.
  AxisValues p = program_target();
  p[d] = to_frame(machine_)[d];
  auto at = [&](double level) {
    AxisValues q = p;
    q[d] = level;
    return to_machine(q);
  };
  const AxisValues position = to_machine(p);
  const bool tapping = pattern.bottom == CyclePattern::Bottom::Reverse;
  // The 1 mm G83 comes back is the machine's, whatever the scale (decision 53).
  Pecks pecks{*cycle_.r1, *cycle_.bottom, cycle_.step.value_or(0),
              kUnloadClearance / (frame_.transformed() ? frame_.scale[d] : 1.0), cycle_.factor, cycle_.minimum};
  // Everything the hole needs is checked before the tool moves: a refused hole is
  // not drilled, and the tool is taken to be over it.
  auto refuse = [&] { move_to(position); };
  if (!nc110_levels_ok(pattern) || !nc110_registers_ok(pattern)) return refuse();
  if (!(tapping && cycle_.pitch) && !need_feed(("canned cycle " + name).c_str(), machine_)) return refuse();
  if (pattern.in == CyclePattern::In::SpindleFeed && std::abs(modal_.spindle) != 1 && spindle_direction_ == 0) {
    report(DiagId::CycleNoSpindle, 0, name);
    return refuse();
  }
  if (tapping) {
    if (std::fabs(*cycle_.bottom - *cycle_.r1) < config_.tap_min_travel) {
      report(DiagId::TapTravel, 0, name, four_decimals(to_program(std::fabs(*cycle_.bottom - *cycle_.r1))),
             four_decimals(to_program(config_.tap_min_travel)));
      return refuse();
    }
    if (pattern.out == CyclePattern::Out::Feed && system_value(SysVar::TapReturn) == 0) {
      report(DiagId::CycleDefinition, 0,
             fmt::format("{} would bring the tap out at {} = 0 % of the speed, so it would not come out: set it to 1..255 first",
                         name, system_name({SysVar::TapReturn, 0})));
      return refuse();
    }
  }
  if (pattern.in == CyclePattern::In::Peck) {
    double stuck = 0;
    auto n = pecks.count(stuck);
    if (!n) {
      report(DiagId::CycleNoProgress, conv_.peck_word, name, four_decimals(to_program(stuck)));
      return refuse();
    }
    if (*n > kMaxPecks) {
      report(DiagId::CyclePecks, conv_.peck_word, name, std::isinf(*n) ? fmt::format("more than {}", kMaxPecks) : shortest(*n),
             four_decimals(to_program(pecks.step)), kMaxPecks);
      return refuse();
    }
  }

  if (position != machine_) rapid(position);
  if (at(*cycle_.r1) != machine_) rapid(at(*cycle_.r1));
  if (pattern.in == CyclePattern::In::SpindleFeed && std::abs(modal_.spindle) != 1)
    apply({spindle_direction_ > 0 ? Fn::SpindleCw : Fn::SpindleCcw}, Scope::Modal, true);  // Table 2.6
  const int direction = spindle_direction_;

  if (pattern.in == CyclePattern::In::Peck && pecks.unloading()) {
    double from = pecks.r1, peck = pecks.step;
    while (true) {
      if (at(from) != machine_) rapid(at(from));
      double reached = std::max(from - peck, pecks.bottom);
      linear(at(reached));
      if (reached <= pecks.bottom) break;
      rapid(at(pecks.r1));
      from = reached + pecks.clearance;
      peck = pecks.next(peck);
    }
  } else if (pattern.in == CyclePattern::In::Peck) {
    // Pecks of I with a dwell between them to break the chip.
    for (double reached = pecks.r1; reached > pecks.bottom;) {
      reached = std::max(reached - pecks.step, pecks.bottom);
      linear(at(reached));
      if (reached > pecks.bottom) dwell_seconds(timer_dwell());
    }
  } else if (tapping) {
    tap_feed(at(*cycle_.bottom), false);
  } else {
    linear(at(*cycle_.bottom));
  }
  if (pattern.dwell) dwell_seconds(timer_dwell());
  if (tapping) apply({direction > 0 ? Fn::SpindleCcw : Fn::SpindleCw}, Scope::Modal, true);
  if (pattern.bottom == CyclePattern::Bottom::Stop) apply({Fn::SpindleStop}, Scope::Modal, true);
  if (pattern.out == CyclePattern::Out::Feed) {
    if (tapping) tap_feed(at(*cycle_.r1), true);
    else linear(at(*cycle_.r1));
    if (*cycle_.r2 != *cycle_.r1) rapid(at(*cycle_.r2));
  } else {
    rapid(at(*cycle_.r2));
  }
  if (tapping) apply({direction > 0 ? Fn::SpindleCw : Fn::SpindleCcw}, Scope::Modal, true);
}

void Machine::tap_feed(const AxisValues& t, bool out) {
  // G84: with a spindle encoder and K, a move synchronised with the spindle at the
  // pitch K; else at F. The way out runs at RMS percent of the speed (§2.10.3).
  // RMS 0 and K without an encoder were refused before the hole.
  double percent = system_value(SysVar::TapReturn);
  if (cycle_.pitch) {
    double rpm = spindle_rpm();
    if (rpm <= 0) report(DiagId::ThreadNoSpindle, 0);
    if (!path_allowed({machine_, t})) return move_to(t);
    const double scale = out ? percent / 100 : 1;
    if (out && scale != 1) {
      Event e{EventKind::SpindleSpeed};
      e.a = speed_ * scale;
      emit(e);
    }
    if (rpm > 0) advance_clock(60 * std::fabs(t[cycle_.axis] - machine_[cycle_.axis]) / (*cycle_.pitch * rpm * scale));
    Event e = motion_event(EventKind::Thread, t);
    e.a = to_program(*cycle_.pitch);
    emit(e);
    move_to(t);
    if (out && scale != 1) {
      Event back{EventKind::SpindleSpeed};
      back.a = speed_;
      emit(back);
    }
    return;
  }
  if (!out || percent == 100 || !feed_) return linear(t);
  double programmed = *feed_;
  feed_ = programmed * percent / 100;
  Event e{EventKind::FeedRate};
  e.a = *feed_;
  emit(e);
  linear(t);
  feed_ = programmed;
  e.a = programmed;
  emit(e);
}

// ---- Measuring cycles (NC-110 §2.8.12, §2.13.9) -------------------------------------

void Machine::measure() {
  const Fn fn = block_.measure;
  const std::string name = fn == Fn::MeasurePoint ? "G72" : fn == Fn::MeasureHole ? "G73" : "G74";
  const ProbeConfig& probe = config_.probe;
  const AxisValues start = machine_;
  // Where the values go: the block's E word (a code chosen at run time has none).
  const std::optional<uint32_t> e = has('E') ? whole_in<uint32_t>(word('E'), 0, 65535) : std::nullopt;
  if (!e) {
    report(DiagId::ResultWord, 0, fmt::format("{} needs the E parameter its results go to, e.g. E40", name));
    return;
  }
  const uint32_t first = *e;
  // The next contact of the simulated probe, or the nominal one when the list has ended.
  const size_t index = next_contact_++;
  const ProbeContact* contact = index < probe.contacts.size() ? &probe.contacts[index] : nullptr;
  auto setup = [&](const std::string& why) { report(DiagId::ProbeSetup, 0, name, why); };
  auto probe_move = [&](const AxisValues& to, bool touched) {
    double length = 0;
    for (int i = 0; i < kAxisCount; ++i) length += (to[i] - machine_[i]) * (to[i] - machine_[i]);
    advance_clock(60 * std::sqrt(length) / probe.feed);
    Event event = motion_event(EventKind::Probe, to);
    event.n = touched;
    emit(event);
    machine_ = to;
  };
  // Where a point is, in the program's frame, on the axes that move and X Y Z.
  auto where = [&](const AxisValues& p) {
    std::string s;
    AxisValues q = to_frame(p);
    for (char letter : conv_.axes)
      if (int i = axis_index(letter); p[i] != start[i] || i < 3)
        s += fmt::format("{}{}{}", s.empty() ? "" : " ", letter, four_decimals(program_axis(i, q[i])));
    return s;
  };
  auto no_contact = [&](const AxisValues& from, const AxisValues& to) {
    probe_move(to, false);
    rapid(start);
    report(DiagId::ProbeNoContact, 0, name, where(from), where(to));
  };
  const double radius = [&] {
    auto it = tool_offsets_.find(offset_number_);
    return it == tool_offsets_.end() || fn == Fn::MeasureDeviation ? 0.0 : it->second.radius;
  }();
  const std::string contact_name = fmt::format("the next probe contact (probe.contacts[{}])", index);

  if (fn == Fn::MeasureHole) {
    // G73 r: three probes from the centre at 0, 120 and 240 degrees in the plane.
    const int u = modal_.plane.u, v = modal_.plane.v;
    const double nominal = length_units(word('r')) * (frame_.transformed() ? frame_.scale[u] : 1.0);
    if (contact && contact->kind == ProbeContact::Kind::Point)
      return setup(contact_name + " is a point; G73 needs a circle");
    if (contact && contact->kind == ProbeContact::Kind::Circle && !((contact->axes >> u) & (contact->axes >> v) & 1))
      return setup(fmt::format("{} is a circle about a centre in other axes than the {} plane G73 measures in",
                               contact_name, plane_name(modal_.plane)));
    double cx = start[u], cy = start[v], r = nominal;
    if (contact && contact->kind == ProbeContact::Kind::Circle) {
      cx = contact->point[u];
      cy = contact->point[v];
      r = contact->radius;
    }
    for (int k = 0; k < 3; ++k) {
      const double a = k * 2 * std::numbers::pi / 3;
      const double dx = std::cos(a), dy = std::sin(a);
      AxisValues from = start, safety = start;
      from[u] += (nominal - probe.approach) * dx;
      from[v] += (nominal - probe.approach) * dy;
      safety[u] += (nominal + probe.safety) * dx;
      safety[v] += (nominal + probe.safety) * dy;
      rapid(from);
      // Where the ray from the start meets the hole's wall; the probe's centre stops
      // its radius before the wall, within the stroke from Qa before the nominal
      // radius to Qs past it.
      double reach = nominal - radius;
      if (contact) {
        double ox = start[u] - cx, oy = start[v] - cy;
        double b = ox * dx + oy * dy, c = ox * ox + oy * oy - r * r;
        double disc = b * b - c;
        reach = disc >= 0 ? -b + std::sqrt(disc) - radius : -1;
        if (contact->kind == ProbeContact::Kind::None || reach < nominal - probe.approach ||
            reach > nominal + probe.safety)
          return no_contact(from, safety);
      }
      AxisValues touch = start;
      touch[u] += reach * dx;
      touch[v] += reach * dy;
      probe_move(touch, true);
      rapid(start);
    }
    AxisValues centre = start;
    centre[u] = cx;
    centre[v] = cy;
    const AxisValues c = to_frame(centre);
    results_.push_back({first, program_axis(u, c[u])});
    results_.push_back({first + 1, program_axis(v, c[v])});
    results_.push_back({first + 2, to_program(r / (frame_.transformed() ? frame_.scale[u] : 1.0))});
    return;
  }

  // G72, G74: towards the nominal point P, from Qa before it to Qs past it.
  const AxisValues nominal = target();
  double distance = 0;
  for (int i = 0; i < kAxisCount; ++i) distance += (nominal[i] - start[i]) * (nominal[i] - start[i]);
  distance = std::sqrt(distance);
  if (distance < 1e-6) return setup(fmt::format("the nominal point {} is where the probe is: no direction to probe", where(nominal)));
  if (contact && contact->kind == ProbeContact::Kind::Circle)
    return setup(fmt::format("{} is a circle; {} needs a point", contact_name, name));
  AxisValues dir{};
  for (int i = 0; i < kAxisCount; ++i) dir[i] = (nominal[i] - start[i]) / distance;
  auto along = [&](double s) {
    AxisValues p = start;
    for (int i = 0; i < kAxisCount; ++i) p[i] += dir[i] * s;
    return p;
  };
  const double from_s = std::max(0.0, distance - probe.approach);
  const double safety_s = distance + probe.safety;
  // The contact: the surface point; the probe's centre stops its radius before it.
  AxisValues surface = nominal;
  if (contact && contact->kind == ProbeContact::Kind::Point)
    for (int i = 0; i < kAxisCount; ++i)
      if (contact->axes & (1u << i)) surface[i] = contact->point[i];
  double contact_s = 0;
  for (int i = 0; i < kAxisCount; ++i) contact_s += (surface[i] - start[i]) * dir[i];
  contact_s -= radius;
  if (from_s > 0) rapid(along(from_s));
  if ((contact && contact->kind == ProbeContact::Kind::None) || contact_s < from_s || contact_s > safety_s)
    return no_contact(along(from_s), along(safety_s));
  probe_move(along(contact_s), true);
  rapid(start);
  // The values in the order the axes were written (the front end says where each
  // goes), in the program's frame (§2.8.12.1: the position "on every coordinate of the
  // block"), whatever the origin, rotation, mirror or scale.
  const AxisValues measured = to_frame(surface), wanted = to_frame(nominal);
  for (char letter : conv_.axes) {
    int a = axis_index(letter);
    auto slot = slot_if(second_slot(letter));
    if (!slot || !has(letter)) continue;
    double value = fn == Fn::MeasurePoint ? measured[a] : wanted[a] - measured[a];
    // E<n>, which the front end writes (anything else: an index the VM's store refuses).
    results_.push_back({whole_in<uint32_t>(*slot, 0, 65535).value_or(UINT32_MAX), program_axis(a, value)});
  }
}

}  // namespace ncc
