// The dialects' tool changes: GOST 20999 and pp (M06 loads the tool; a profile may have
// it stop the spindle), ISO (§8.31) and NC-110 (T tool.corrector, §2.7.7).
#include "tool_change.h"

#include "support/numbers.h"
#include "support/text.h"

namespace ncc {

class Machine::PlainToolChange final : public ToolChange {
 public:
  PlainToolChange(Machine& m, bool stops_spindle) : ToolChange(m), stops_spindle_(stops_spindle) {}
  void before(Scope scope, bool emit_events) override {
    if (stops_spindle_) stop_spindle_and_coolant(scope, emit_events);
  }

 private:
  bool stops_spindle_;  // gost.m06_stops_spindle
};

class Machine::IsoToolChange final : public ToolChange {
 public:
  IsoToolChange(Machine& m, bool retract) : ToolChange(m), retract_(retract) {}
  bool same_tool_ignored() const override { return true; }
  void before(Scope scope, bool emit_events) override;

 private:
  bool retract_;  // iso.tool_change_retract
};

class Machine::Nc110ToolChange final : public ToolChange {
 public:
  Nc110ToolChange(Machine& m, bool stops_spindle) : ToolChange(m), stops_spindle_(stops_spindle) {}
  void before(Scope scope, bool emit_events) override {
    if (stops_spindle_) stop_spindle_and_coolant(scope, emit_events);
  }
  void after() override;
  void tool_word(int programmed) override;
  bool corrector_in_tool() const override { return true; }

 private:
  bool stops_spindle_;
};

std::unique_ptr<Machine::ToolChange> Machine::ToolChange::make(Machine& m, const Conventions& conv) {
  if (conv.tool_change_iso) return std::make_unique<IsoToolChange>(m, conv.tool_change_retract);
  if (conv.corrector_in_tool_word) return std::make_unique<Nc110ToolChange>(m, conv.m06_stops_spindle);
  return std::make_unique<PlainToolChange>(m, conv.m06_stops_spindle);
}

void Machine::ToolChange::stop_spindle_and_coolant(Scope scope, bool emit_events) {
  if (m_.modal_.spindle != 0) m_.apply({Fn::SpindleStop}, scope, emit_events);
  if (m_.modal_.mist || m_.modal_.flood) m_.apply({Fn::CoolantOff}, scope, emit_events);
}

// ISO §8.31: no tool selected, or the one in the spindle: nothing happens; else the
// spindle and coolant stop, both compensations end for good, and the spindle goes up
// to the tool-change position along the tool axis (the reference point).
void Machine::IsoToolChange::before(Scope scope, bool emit_events) {
  stop_spindle_and_coolant(scope, emit_events);
  if (!emit_events) return;
  m_.modal_.comp = 0;
  m_.modal_.length = 0;
  m_.flush_compensation();
  AxisValues up = m_.kernel_.position();
  if (m_.modal_.plane.w >= 0) up[m_.modal_.plane.w] = m_.config_.reference_position[m_.modal_.plane.w];
  if (retract_ && up != m_.kernel_.position()) m_.rapid(up);
}

// NC-110 §2.7.7: M06 brings the corrector T selected into force.
void Machine::Nc110ToolChange::after() { m_.select_offset(m_.corrector_selected_); }

// NC-110 T tool.corrector: the corrector takes effect at M06 (§2.7.7).
void Machine::Nc110ToolChange::tool_word(int programmed) {
  const int slot = second_slot('T');
  const double corrector = m_.slot_if(slot).value_or(0);
  const std::optional<int> n = whole_in(corrector, 0, 999999999);
  if (!n || (*n != 0 && !m_.tool_offsets_.count(*n)))
    m_.report_slot(DiagId::OffsetUnknown, slot, "corrector", shortest(corrector), m_.config_.profile,
                   number_ranges(m_.tool_offsets_));
  else
    m_.corrector_selected_ = *n;
  // A sister in the programmed tool's place brings its own corrector, if it has one.
  if (auto sister = m_.config_.tools.find(m_.tool_selected_);
      m_.tool_selected_ != programmed && sister != m_.config_.tools.end() && sister->second.corrector)
    m_.corrector_selected_ = sister->second.corrector;
}

}  // namespace ncc
