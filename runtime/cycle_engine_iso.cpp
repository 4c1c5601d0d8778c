// ISO/Fanuc's canned cycles (§8.21-8.27, decisions 18-21): L (or K) holes a block,
// back to the initial level (G98) or R (G99); a code of the motion group ends them.
#include <cmath>

#include "cycle_engine.h"
#include "cycle_steps.h"
#include "support/text.h"

namespace ncc {

void Machine::IsoCycles::drill() {
  Machine& m = m_;
  int count = 1;
  for (char letter : m.conv_.cycle_repeat_words) {
    if (!m.has(letter)) continue;
    const double v = m.word(letter);
    const std::optional<int> n = whole_in(v, 0, 9999);
    if (!n) {
      m.report(DiagId::RepeatCount, letter, shortest(v), 9999);
      return;
    }
    count = *n;
    break;
  }
  if (count == 0) registers();  // L0: the cycle's words are stored, no hole is made
  for (int i = 0; i < count && !m.block_.error; ++i) drill_one();
}

void Machine::IsoCycles::drill_one() {
  Machine& m = m_;
  const CyclePattern& pattern = m.sem_.cycles[m.modal_.cycle];
  using In = CyclePattern::In;
  const std::string name = "canned cycle " + pattern.name;
  const int d = m.modal_.plane.w;  // the drilling axis
  const int u = m.modal_.plane.u;  // G76/G87 shift along the plane's first axis
  registers();
  AxisValues hole = m.target();
  hole[d] = m.kernel_.position()[d];
  bool ok = true;
  if (!registers_.depth) ok = (m.report(DiagId::CycleNoDepth, 0, pattern.name, std::string(1, kAxisLetters[d])), false);
  if (!registers_.level) ok = (m.report_repeated(DiagId::CycleNoRLevel, pattern.name), false);
  const bool pecks = pattern.in == In::Peck || pattern.in == In::ChipBreak;
  const bool shifts = pattern.bottom == CyclePattern::Bottom::OrientShift;
  if (ok && pecks && !registers_.peck) ok = (m.report(DiagId::CycleNoPeck, 0, pattern.name, "Q"), false);
  if (ok && (pecks || (registers_.peck && pattern.in != In::Feed && !shifts)) && registers_.peck &&
      *registers_.peck <= 0)
    ok = (m.report(DiagId::PeckNotPositive, 'Q', "peck depth", four_decimals(*registers_.peck), "greater than zero",
                   pattern.name),
          false);
  if (ok && shifts && !registers_.peck)
    ok = (m.report(DiagId::CycleNoPeck, 0, pattern.name, "Q (the shift off the wall)"), false);
  const double dwell = pattern.dwell && registers_.dwell ? *registers_.dwell : 0;
  if (ok && dwell < 0) ok = (m.report(DiagId::DwellNegative, 'P', four_decimals(dwell)), false);
  if (!ok || !m.need_feed(name.c_str(), hole)) {
    m.move_to(hole);
    return;
  }
  // G90: R and the bottom are coordinates; G91: R from the initial level, the bottom
  // from R (§8.23). The initial level is where the tool stood when the cycle mode
  // began (§8.21: "the position before the cycle").
  if (!initial_level_) initial_level_ = m.kernel_.position()[d];
  cycle::Hole h;
  h.initial = *initial_level_;
  h.current = m.kernel_.position()[d];
  const AxisValues off = m.target_frame();
  h.level =
      m.modal_.absolute ? m.length_units(*registers_.level) + off[d] : h.initial + m.length_units(*registers_.level);
  h.bottom =
      m.modal_.absolute ? m.length_units(*registers_.depth) + off[d] : h.level + m.length_units(*registers_.depth);
  if (pattern.in == In::Back && h.bottom < h.level) {
    // §8.27: G87 bores from R up to Z, so Z lies above R.
    m.report(
        DiagId::CycleDefinition, 0,
        fmt::format("canned cycle G87 bores upwards from R: the bottom {} must lie above R {}",
                    four_decimals(m.to_program(h.bottom - off[d])), four_decimals(m.to_program(h.level - off[d]))));
    m.move_to(hole);
    return;
  }
  if (pecks || (pattern.in == In::TapCw || pattern.in == In::TapCcw)) {
    if (registers_.peck) {
      h.peck = m.length_units(*registers_.peck);
      const double count = std::ceil(std::fabs(h.bottom - h.level) / *h.peck - 1e-9);
      if (count > cycle::kMaxPecks) {
        m.report(DiagId::CyclePecks, 'Q', pattern.name, four_decimals(count), four_decimals(*registers_.peck),
                 cycle::kMaxPecks);
        return;
      }
    }
  }
  h.dwell = dwell;
  h.shift = shifts ? m.length_units(*registers_.peck) * m.conv_.boring_shift : 0;
  h.return_level = m.modal_.cycle_return_level;
  h.direction = m.spindle_direction_ ? m.spindle_direction_ : 1;
  m.hole_steps(cycle::iso_hole(pattern, h, m.conv_), hole, d, u, false);
}

}  // namespace ncc
