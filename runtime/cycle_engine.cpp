// The choice of a program's cycle engine, and what the engines of one level R (GOST
// 20999, pp, ISO) share: a block's dispatch and the registers.
#include <memory>

#include "cycle_engine.h"
#include "cycle_steps.h"
#include "support/text.h"

namespace ncc {

std::unique_ptr<Machine::CycleEngine> Machine::CycleEngine::make(Machine& m, const Conventions& conv) {
  // NC-110's cycles have two levels, their own block defines them and a new one needs
  // the old one cancelled: the three flags come together (the verifier checks two).
  if (conv.cycle_two_levels || conv.cycle_defines_only || conv.cycle_needs_cancel)
    return std::make_unique<Nc110Cycles>(m);
  if (conv.fanuc_cycles) return std::make_unique<IsoCycles>(m);
  return std::make_unique<GostCycles>(m);
}

void Machine::OneLevelCycles::block(bool drills) {
  if (m_.modal_.plane.w < 0) {  // pp G14-G16 may select two axes with none along their normal
    if (drills) no_drilling_axis();
  } else if (drills) {
    drill();
  } else {
    registers();
  }
}

void Machine::OneLevelCycles::no_drilling_axis() {
  m_.report(DiagId::PlaneState, 0, "canned cycle " + m_.sem_.cycles[m_.modal_.cycle].name,
            fmt::format("plane {}, which has no axis along its normal to drill along,", plane_name(m_.modal_.plane)));
}

void Machine::OneLevelCycles::cancelled() {
  registers_ = {};
  m_.release(DiagId::CycleNoRLevel);
}

void Machine::OneLevelCycles::registers() {
  Machine& m = m_;
  // The cycle registers stay in force while the cycle is active (S-7.5); any block
  // may change them, the cycle runs only in blocks with a dimension word.
  const char depth_letter = kAxisLetters[m.modal_.plane.w];
  if (m.has(depth_letter)) registers_.depth = m.word(depth_letter);
  if (auto v = m.word_if(m.conv_.cycle_level_word)) {
    registers_.level = v;
    m.release(DiagId::CycleNoRLevel);
  }
  if (auto v = m.word_if(m.conv_.dwell_word)) registers_.dwell = v;
  if (auto v = m.word_if(m.conv_.peck_word)) registers_.peck = v;
}

}  // namespace ncc
