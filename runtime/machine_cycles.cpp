// Canned cycles (GOST 20999 Table 6; NC-110 §2.8.9) and the NC-110 measuring cycles
// G72-G74 (§2.8.12) against a simulated probe.
#include <cmath>
#include <limits>

#include "cycle_steps.h"
#include "machine.h"
#include "support/text.h"

namespace ncc {

namespace {

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
    ok = (report(DiagId::PeckNotPositive, 'Q', "peck depth", four_decimals(*cycle_.peck), "greater than zero",
                 pattern.name),
          false);
  if (ok && shifts && !cycle_.peck)
    ok = (report(DiagId::CycleNoPeck, 0, pattern.name, "Q (the shift off the wall)"), false);
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
  cycle::Hole h;
  h.initial = *initial_level_;
  h.current = machine_[d];
  const AxisValues off = target_frame();
  h.level = modal_.absolute ? length_units(*cycle_.level) + off[d] : h.initial + length_units(*cycle_.level);
  h.bottom = modal_.absolute ? length_units(*cycle_.depth) + off[d] : h.level + length_units(*cycle_.depth);
  if (pattern.in == In::Back && h.bottom < h.level) {
    // §8.27: G87 bores from R up to Z, so Z lies above R.
    report(DiagId::CycleDefinition, 0,
           fmt::format("canned cycle G87 bores upwards from R: the bottom {} must lie above R {}",
                       four_decimals(to_program(h.bottom - off[d])), four_decimals(to_program(h.level - off[d]))));
    move_to(hole);
    return;
  }
  if (pecks || (pattern.in == In::TapCw || pattern.in == In::TapCcw)) {
    if (cycle_.peck) {
      h.peck = length_units(*cycle_.peck);
      const double count = std::ceil(std::fabs(h.bottom - h.level) / *h.peck - 1e-9);
      if (count > cycle::kMaxPecks) {
        report(DiagId::CyclePecks, 'Q', pattern.name, four_decimals(count), four_decimals(*cycle_.peck),
               cycle::kMaxPecks);
        return;
      }
    }
  }
  h.dwell = dwell;
  h.shift = shifts ? length_units(*cycle_.peck) * conv_.boring_shift : 0;
  h.return_level = modal_.cycle_return_level;
  h.direction = spindle_direction_ ? spindle_direction_ : 1;
  hole_steps(cycle::iso_hole(pattern, h, conv_), hole, d, u, false);
}

// A hole's steps (cycle_steps.h): `hole` is its position, `d` the drilling axis, `u`
// the axis of a shift; in the program's coordinates where `program` (NC-110's), else
// the machine's.
void Machine::hole_steps(const std::vector<cycle::Step>& steps, const AxisValues& hole, int d, int u, bool program,
                         std::optional<double> pitch) {
  using Kind = cycle::Step::Kind;
  auto here = [&] { return program ? to_frame(machine_) : machine_; };
  bool over = false;
  for (const cycle::Step& s : steps) {
    AxisValues p = over ? hole : here();
    p[d] = s.level;
    p[u] += s.shift;
    if (program) p = to_machine(p);
    switch (s.kind) {
      case Kind::Rapid: rapid(p); break;
      case Kind::Feed: linear(p); break;
      case Kind::Tap:
      case Kind::TapOut: tap_feed(p, s.kind == Kind::TapOut, d, pitch); break;
      case Kind::Over:
        over = true;
        p = hole;
        p[d] = here()[d];
        if (program) p = to_machine(p);
        if (p != machine_) rapid(p);
        break;
      case Kind::Dwell: dwell_seconds(s.seconds); break;
      case Kind::Spindle: {
        if (s.always || modal_.spindle != cycle::spindle_turns(s.spindle)) apply({s.spindle}, Scope::Modal, true);
        break;
      }
      case Kind::Manual: {
        // The operator retracts by hand: the run stops; on resume the tool is where
        // the step says (S-7.5).
        Event stop{EventKind::Stop};
        stop.n = 3;
        emit(stop);
        emit(motion_event(EventKind::OperatorMove, p));
        move_to(p);
        break;
      }
    }
  }
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
  cycle::Hole h;
  h.initial = h.current = machine_[d];
  AxisValues off = target_frame();
  h.level = modal_.absolute ? length_units(*cycle_.level) + off[d] : h.current + length_units(*cycle_.level);
  h.bottom = modal_.absolute ? length_units(*cycle_.depth) + off[d] : h.level + length_units(*cycle_.depth);
  if (pattern.in == CyclePattern::In::Peck) {
    h.peck = length_units(*cycle_.peck);
    double pecks = std::ceil(std::fabs(h.bottom - h.level) / *h.peck);
    if (pecks > cycle::kMaxPecks) {
      report(DiagId::CyclePecks, conv_.peck_word, pattern.name, four_decimals(pecks), four_decimals(*cycle_.peck),
             cycle::kMaxPecks);
      return;
    }
  }
  if (pattern.dwell) h.dwell = *cycle_.dwell * conv_.dwell_seconds_per_unit;
  h.direction = spindle_direction_;
  hole_steps(cycle::hole(pattern, h), hole, d, d, false);
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

bool Machine::nc110_cycle_definition(const CyclePattern& pattern, const std::vector<int>& written) {
  const std::string& name = pattern.name;
  if (written.size() != 1) {
    report(
        DiagId::CycleDefinition, 0,
        written.empty()
            ? fmt::format("{} needs the hole's depth: an axis word whose letter names the drilling axis", name)
            : fmt::format(
                  "the block of {} holds the depth and no other axis: the holes' positions come in the blocks after it",
                  name));
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
  const AxisValues position = to_machine(p);
  const bool tapping = pattern.bottom == CyclePattern::Bottom::Reverse;
  // The 1 mm G83 comes back is the machine's, whatever the scale (decision 53).
  cycle::Pecks pecks{*cycle_.r1,
                     *cycle_.bottom,
                     cycle_.step.value_or(0),
                     kUnloadClearance / (frame_.transformed() ? frame_.scale[d] : 1.0),
                     cycle_.factor,
                     cycle_.minimum};
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
      report(
          DiagId::CycleDefinition, 0,
          fmt::format(
              "{} would bring the tap out at {} = 0 % of the speed, so it would not come out: set it to 1..255 first",
              name, system_name({SysVar::TapReturn, 0})));
      return refuse();
    }
  }
  std::optional<double> n;  // G83's pecks
  if (pattern.in == CyclePattern::In::Peck) {
    double stuck = 0;
    n = pecks.count(stuck);
    if (!n) {
      report(DiagId::CycleNoProgress, conv_.peck_word, name, four_decimals(to_program(stuck)));
      return refuse();
    }
    if (*n > cycle::kMaxPecks) {
      report(DiagId::CyclePecks, conv_.peck_word, name,
             std::isinf(*n) ? fmt::format("more than {}", cycle::kMaxPecks) : shortest(*n),
             four_decimals(to_program(pecks.step)), cycle::kMaxPecks);
      return refuse();
    }
  }

  cycle::Nc110Hole h{to_frame(machine_)[d], *cycle_.r2, pecks, 0, spindle_direction_};
  if (pattern.dwell || (n && *n > 1 && !pecks.unloading())) h.dwell = timer_dwell();  // TMR's, read where it is used
  hole_steps(cycle::nc110_hole(pattern, h), p, d, d, true, cycle_.pitch);
}

void Machine::tap_feed(const AxisValues& t, bool out, int d, std::optional<double> pitch) {
  // G84: with a spindle encoder and K, a move synchronised with the spindle at the
  // pitch K; else at F. The way out runs at RMS percent of the speed (§2.10.3).
  // RMS 0 and K without an encoder were refused before the hole.
  double percent = system_value(SysVar::TapReturn);
  if (pitch) {
    double rpm = spindle_rpm();
    if (rpm <= 0) report(DiagId::ThreadNoSpindle, 0);
    if (!path_allowed({machine_, t})) return move_to(t);
    const double scale = out ? percent / 100 : 1;
    if (out && scale != 1) {
      Event e{EventKind::SpindleSpeed};
      e.a = speed_ * scale;
      emit(e);
    }
    if (rpm > 0) advance_clock(60 * std::fabs(t[d] - machine_[d]) / (*pitch * rpm * scale));
    Event e = motion_event(EventKind::Thread, t);
    e.a = to_program(*pitch);
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
  const ProbeConfig& probe = probe_;
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
  const double radius = fn == Fn::MeasureDeviation ? 0.0 : offset_.radius;
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
  if (distance < 1e-6)
    return setup(fmt::format("the nominal point {} is where the probe is: no direction to probe", where(nominal)));
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
