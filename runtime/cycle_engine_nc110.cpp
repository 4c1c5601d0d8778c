// NC-110's canned cycles (§2.8.9): the cycle's block stores it, the blocks after it
// drill between the levels R1 and R2.
#include <cmath>

#include "cycle_engine.h"
#include "cycle_steps.h"
#include "support/text.h"

namespace ncc {

namespace {

constexpr double kUnloadClearance = 1;  // mm: G83 goes back to 1 mm above the last bottom (§2.8.9.2)

}  // namespace

void Machine::Nc110Cycles::registers(bool definition) {
  Machine& m = m_;
  // R words: R1 then R2; one R is both (§2.8.9.4). Levels become program coordinates
  // where they are written: G91 measures R from the axis' position, the depth from R1.
  const int d = registers_.axis;
  const double here = m.to_frame(m.kernel_.position())[d];
  const bool absolute = m.modal_.absolute;
  auto level = [&](double v) { return absolute ? m.axis_units(d, v) : here + m.axis_units(d, v); };
  if (auto r1 = m.word_if('R')) {
    registers_.r1 = level(*r1);
    registers_.r2 = m.has_slot(second_slot('R')) ? level(m.slot_value(second_slot('R'))) : *registers_.r1;
  } else if (definition) {
    registers_.r1 = registers_.r2 = here;  // no R: the level the tool is at (decision 13)
  }
  if (m.has(kAxisLetters[d])) {
    double v = m.axis_units(d, m.word(kAxisLetters[d]));
    registers_.bottom = absolute ? v : *registers_.r1 + v;
  }
  const CyclePattern& pattern = m.sem_.cycles[m.modal_.cycle];
  if (pattern.in == CyclePattern::In::Peck) {
    if (auto v = m.word_if(m.conv_.peck_word)) registers_.step = m.length_units(*v);
    if (auto v = m.word_if(m.conv_.peck_factor_word)) registers_.factor = *v;
    if (auto v = m.word_if(m.conv_.peck_minimum_word)) registers_.minimum = m.length_units(*v);
  }
  if (pattern.bottom == CyclePattern::Bottom::Reverse)
    if (auto v = m.word_if(m.conv_.tap_pitch_word)) registers_.pitch = m.length_units(*v);
}

bool Machine::Nc110Cycles::define(const CyclePattern& pattern, const std::vector<int>& written) {
  Machine& m = m_;
  const std::string& name = pattern.name;
  if (written.size() != 1) {
    m.report(
        DiagId::CycleDefinition, 0,
        written.empty()
            ? fmt::format("{} needs the hole's depth: an axis word whose letter names the drilling axis", name)
            : fmt::format(
                  "the block of {} holds the depth and no other axis: the holes' positions come in the blocks after it",
                  name));
    return false;
  }
  registers_.axis = written[0];
  registers(true);
  if (pattern.in == CyclePattern::In::Peck && !registers_.step) {
    m.report(DiagId::CycleNoPeck, 0, name, std::string(1, m.conv_.peck_word));
    return false;
  }
  return levels_ok(pattern) && registers_ok(pattern);
}

bool Machine::Nc110Cycles::registers_ok(const CyclePattern& pattern) {
  Machine& m = m_;
  // Checked where they are written: in the cycle's block and in any hole's.
  auto wrong = [&](char letter, const char* what, double v, const char* must) {
    m.report(DiagId::PeckNotPositive, letter, fmt::format("the {} {}", what, letter), shortest(v), must, pattern.name);
    return false;
  };
  if (pattern.in == CyclePattern::In::Peck) {
    if (registers_.step && *registers_.step <= 0)
      return wrong(m.conv_.peck_word, "peck increment", m.to_program(*registers_.step), "greater than zero");
    if (registers_.factor && *registers_.factor <= 0)
      return wrong(m.conv_.peck_factor_word, "peck factor", *registers_.factor, "greater than zero");
    if (registers_.minimum && *registers_.minimum < 0)
      return wrong(m.conv_.peck_minimum_word, "minimum peck", m.to_program(*registers_.minimum), "zero or more");
  }
  if (registers_.pitch && *registers_.pitch <= 0)
    return wrong(m.conv_.tap_pitch_word, "tapping pitch", m.to_program(*registers_.pitch), "greater than zero");
  if (registers_.pitch && !m.config_.spindle_encoder) {
    m.report(DiagId::ThreadEncoder, m.conv_.tap_pitch_word, pattern.name + " with K");
    return false;
  }
  return true;
}

bool Machine::Nc110Cycles::levels_ok(const CyclePattern& pattern) {
  Machine& m = m_;
  const int d = registers_.axis;
  const char letter = kAxisLetters[d];
  if (*registers_.bottom >= *registers_.r1) {
    m.report(DiagId::CycleDefinition, letter,
             fmt::format("the hole's bottom {}{} is not below R1 {}: {} drills from R1 towards minus {}", letter,
                         four_decimals(m.program_axis(d, *registers_.bottom)),
                         four_decimals(m.program_axis(d, *registers_.r1)), pattern.name, letter));
    return false;
  }
  if (*registers_.r2 < *registers_.r1) {
    m.report_slot(DiagId::CycleDefinition, second_slot('R'),
                  fmt::format("R2 {} lies below R1 {}: R2, the level the tool returns to, must not lie below R1",
                              four_decimals(m.program_axis(d, *registers_.r2)),
                              four_decimals(m.program_axis(d, *registers_.r1))));
    return false;
  }
  return true;
}

void Machine::Nc110Cycles::block(bool) {
  Machine& m = m_;
  const CyclePattern& pattern = m.sem_.cycles[m.modal_.cycle];
  const std::string& name = pattern.name;
  std::vector<int> written;
  for (char c : m.conv_.axes)
    if (m.has(c)) written.push_back(axis_index(c));

  // The cycle's block stores it; the depth word's letter names the drilling axis
  // (§2.8.9 note 1). A definition with an error leaves no cycle active.
  if (registers_.defined_here) {
    registers_.defined_here = false;
    if (!define(pattern, written)) m.modal_.cycle = -1;
    return;
  }

  const int d = registers_.axis;
  registers(false);
  bool hole = false;
  for (int a : written) hole = hole || a != d;
  if (!hole) return;  // new levels only

  // Per hole (§2.8.9.4): the position at the height the tool is at, R1, the hole, back.
  AxisValues p = m.program_target();
  p[d] = m.to_frame(m.kernel_.position())[d];
  const AxisValues position = m.to_machine(p);
  const bool tapping = pattern.bottom == CyclePattern::Bottom::Reverse;
  // The 1 mm G83 comes back is the machine's, whatever the scale (decision 53).
  cycle::Pecks pecks{*registers_.r1,
                     *registers_.bottom,
                     registers_.step.value_or(0),
                     kUnloadClearance / (m.kernel_.frame().transformed() ? m.kernel_.frame().scale[d] : 1.0),
                     registers_.factor,
                     registers_.minimum};
  // Everything the hole needs is checked before the tool moves: a refused hole is
  // not drilled, and the tool is taken to be over it.
  auto refuse = [&] { m.move_to(position); };
  if (!levels_ok(pattern) || !registers_ok(pattern)) return refuse();
  if (!(tapping && registers_.pitch) && !m.need_feed(("canned cycle " + name).c_str(), m.kernel_.position()))
    return refuse();
  if (pattern.in == CyclePattern::In::SpindleFeed && std::abs(m.modal_.spindle) != 1 && m.spindle_direction_ == 0) {
    m.report(DiagId::CycleNoSpindle, 0, name);
    return refuse();
  }
  if (tapping) {
    if (std::fabs(*registers_.bottom - *registers_.r1) < m.config_.tap_min_travel) {
      m.report(DiagId::TapTravel, 0, name, four_decimals(m.to_program(std::fabs(*registers_.bottom - *registers_.r1))),
               four_decimals(m.to_program(m.config_.tap_min_travel)));
      return refuse();
    }
    if (pattern.out == CyclePattern::Out::Feed && m.system_value(SysVar::TapReturn) == 0) {
      m.report(
          DiagId::CycleDefinition, 0,
          fmt::format(
              "{} would bring the tap out at {} = 0 % of the speed, so it would not come out: set it to 1..255 first",
              name, m.system_name({SysVar::TapReturn, 0})));
      return refuse();
    }
  }
  std::optional<double> n;  // G83's pecks
  if (pattern.in == CyclePattern::In::Peck) {
    double stuck = 0;
    n = pecks.count(stuck);
    if (!n) {
      m.report(DiagId::CycleNoProgress, m.conv_.peck_word, name, four_decimals(m.to_program(stuck)));
      return refuse();
    }
    if (*n > cycle::kMaxPecks) {
      m.report(DiagId::CyclePecks, m.conv_.peck_word, name,
               std::isinf(*n) ? fmt::format("more than {}", cycle::kMaxPecks) : shortest(*n),
               four_decimals(m.to_program(pecks.step)), cycle::kMaxPecks);
      return refuse();
    }
  }

  cycle::Nc110Hole h{m.to_frame(m.kernel_.position())[d], *registers_.r2, pecks, 0, m.spindle_direction_};
  if (pattern.dwell || (n && *n > 1 && !pecks.unloading())) h.dwell = m.timer_dwell();  // TMR's, read where it is used
  m.hole_steps(cycle::nc110_hole(pattern, h), p, d, d, true, registers_.pitch);
}

}  // namespace ncc
