// GOST 20999's canned cycles (Table 6), which pp's follow (§G81-G89): a hole a block,
// from the level the tool is at.
#include <cmath>

#include "cycle_engine.h"
#include "cycle_steps.h"
#include "support/text.h"

namespace ncc {

void Machine::GostCycles::drill() {
  Machine& m = m_;
  const CyclePattern& pattern = m.sem_.cycles[m.modal_.cycle];
  const std::string name = "canned cycle " + pattern.name;
  const int d = m.modal_.plane.w;  // the drilling axis: perpendicular to the plane
  const char depth_letter = kAxisLetters[d];
  registers();
  AxisValues hole = m.target();
  hole[d] = m.kernel_.position()[d];
  bool ok = true;
  if (!registers_.depth) {
    m.report(DiagId::CycleNoDepth, 0, pattern.name, std::string(1, depth_letter));
    ok = false;
  }
  if (!registers_.level) {
    m.report_repeated(DiagId::CycleNoRLevel, pattern.name);
    ok = false;
  }
  if (ok && pattern.in == CyclePattern::In::Peck) {
    if (!registers_.peck) {
      m.report(DiagId::CycleNoPeck, 0, pattern.name, m.conv_.peck_word ? std::string(1, m.conv_.peck_word) : "Q");
      ok = false;
    } else if (*registers_.peck <= 0) {
      m.report(DiagId::PeckNotPositive, m.conv_.peck_word, "peck increment", four_decimals(*registers_.peck),
               "greater than zero", pattern.name);
      ok = false;
    }
  }
  if (ok && pattern.dwell && !registers_.dwell) {
    m.report(DiagId::CycleNoDwell, 0, pattern.name, m.dwell_address());
    ok = false;
  } else if (ok && pattern.dwell && *registers_.dwell < 0) {
    m.report(DiagId::DwellNegative, m.conv_.dwell_word, four_decimals(*registers_.dwell));
    ok = false;
  }
  if (ok && pattern.in == CyclePattern::In::SpindleFeed && m.spindle_direction_ == 0) {
    m.report(DiagId::CycleNoSpindle, 0, pattern.name);
    ok = false;
  }
  if (!ok || !m.need_feed(name.c_str(), hole)) {
    m.move_to(hole);
    return;
  }
  // G90: R and the depth are coordinates; G91: R is measured from the initial level
  // and the depth from R.
  cycle::Hole h;
  h.initial = h.current = m.kernel_.position()[d];
  AxisValues off = m.target_frame();
  h.level =
      m.modal_.absolute ? m.length_units(*registers_.level) + off[d] : h.current + m.length_units(*registers_.level);
  h.bottom =
      m.modal_.absolute ? m.length_units(*registers_.depth) + off[d] : h.level + m.length_units(*registers_.depth);
  if (pattern.in == CyclePattern::In::Peck) {
    h.peck = m.length_units(*registers_.peck);
    double pecks = std::ceil(std::fabs(h.bottom - h.level) / *h.peck);
    if (pecks > cycle::kMaxPecks) {
      m.report(DiagId::CyclePecks, m.conv_.peck_word, pattern.name, four_decimals(pecks),
               four_decimals(*registers_.peck), cycle::kMaxPecks);
      return;
    }
  }
  if (pattern.dwell) h.dwell = *registers_.dwell * m.conv_.dwell_seconds_per_unit;
  h.direction = m.spindle_direction_;
  m.hole_steps(cycle::hole(pattern, h), hole, d, d, false);
}

}  // namespace ncc
