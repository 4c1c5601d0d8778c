#include "machine.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

#include "support/text.h"

namespace ncc {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2 * std::numbers::pi;
// The interpolation parameter parallel to each linear axis (Table 1).
constexpr char kParameterOf[3] = {'I', 'J', 'K'};
constexpr double kSamePoint = 1e-7;  // mm: end point equal to start point
constexpr int kMaxPecks = 10000;      // per hole
constexpr double kMaxTurns = 1e6;     // of one helix

bool is_linear_axis(int axis) { return axis < 3 || axis >= 6; }

// Programmed positions live on a nanometre grid, so that increments add up exactly
// as decimals do (0.1 + 0.2 is 0.3) and traces stay bit-for-bit stable.
double snap(double v) { return std::round(v * 1e9) / 1e9; }

// The angle in [0, 2π).
double wrap(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}

}  // namespace

Machine::Machine(const ProgramSemantics& semantics, const MachineConfig& config, TraceSink& trace,
                 RuntimeIssues& issues)
    : sem_(semantics), conv_(semantics.conventions), config_(config), trace_(trace), issues_(issues) {}

void Machine::power_on() {
  machine_ = config_.initial_position;
  tool_loaded_ = 0;
  block_skip_ = config_.block_skip;
  optional_stop_ = config_.optional_stop;
  reset_state();
}

void Machine::reset_state() {
  modal_ = Modal{};
  position_offset_ = {};
  feed_.reset();
  speed_ = 0;
  tool_selected_ = 0;
  offset_number_ = 0;
  spindle_direction_ = 0;
  cycle_ = {};
  parabola_middle_.reset();
  BlockState saved = block_;
  block_ = BlockState{};
  for (uint16_t index : sem_.power_on) {
    const CodeDesc& code = sem_.codes[index];
    for (const FnCall& call : code.calls) {
      if (fn_group(call.fn) == FnGroup::Motion) motion_name_ = code.name;
      apply(call, Scope::Modal, false);
    }
  }
  block_ = saved;
}

AxisValues Machine::target_frame() const {
  if (block_.block_offset == 0) return {};  // G53: the machine reference point
  return frame_offset(block_.block_offset > 0 ? block_.block_offset : modal_.work_offset);
}

AxisValues Machine::frame_offset(int work_offset) const {
  AxisValues off{};
  if (auto it = config_.work_offsets.find(work_offset); it != config_.work_offsets.end()) off = it->second;
  for (int i = 0; i < kAxisCount; ++i) off[i] += position_offset_[i];
  return off;
}

AxisValues Machine::in_program_units(AxisValues v) const {
  for (int i = 0; i < kAxisCount; ++i)
    if (is_linear_axis(i)) v[i] = to_program(v[i]);
  return v;
}

bool Machine::has_axis_word() const {
  for (char axis : conv_.axes)
    if (has(axis)) return true;
  return false;
}

AxisValues Machine::target() {
  // Blocks 2 of a three-point parabola measure from the intermediate point (Appendix 5).
  const AxisValues& base = parabola_middle_ ? *parabola_middle_ : machine_;
  AxisValues t = base;
  AxisValues off = target_frame();
  for (char letter : conv_.axes) {
    if (!has(letter)) continue;
    int i = axis_index(letter);
    double v = word(letter);
    v = is_linear_axis(i) ? length_units(v) : angle_degrees(v);
    t[i] = snap(modal_.absolute ? v + off[i] : base[i] + v);
  }
  return t;
}

double Machine::angle_degrees(double v) const {
  switch (conv_.angle_unit) {
    case AngleUnit::Degree: return v;
    case AngleUnit::Radian: return v * 180.0 / kPi;
    case AngleUnit::Revolution: return v * 360.0;
  }
  return v;
}

Event Machine::motion_event(EventKind kind, const AxisValues& t) const {
  // The trace shows positions in the active work coordinate system (docs/trace.md).
  Event e{kind};
  AxisValues off = frame_offset(modal_.work_offset);
  for (int i = 0; i < kAxisCount; ++i) e.pos[i] = t[i] - off[i];
  e.pos = in_program_units(e.pos);
  return e;
}

void Machine::plane_event() {
  Event e{EventKind::Plane};
  e.plane = modal_.plane;
  emit(e);
}

void Machine::emit(Event e) {
  e.source = block_.request ? block_.request->source : 0;
  trace_.event(e);
}

void Machine::move_to(const AxisValues& t) { machine_ = t; }

FnCall Machine::current(FnGroup group) const {
  switch (group) {
    case FnGroup::Motion: return {modal_.motion};
    case FnGroup::Plane: return {modal_.plane == kPlanes[1] ? Fn::PlaneZX : modal_.plane == kPlanes[2] ? Fn::PlaneYZ : Fn::PlaneXY};
    case FnGroup::Distance: return {modal_.absolute ? Fn::DistanceAbsolute : Fn::DistanceIncremental};
    case FnGroup::Units: return {modal_.inch ? Fn::UnitsInch : Fn::UnitsMm};
    case FnGroup::FeedMode:
      return {modal_.feed_mode == 0 ? Fn::FeedInverseTime : modal_.feed_mode == 1 ? Fn::FeedPerMinute
                                                                                   : Fn::FeedPerRevolution};
    case FnGroup::SpindleMode: return {modal_.constant_surface ? Fn::SpindleConstantSurface : Fn::SpindleRpm};
    case FnGroup::CutterComp: return {modal_.comp == 0 ? Fn::CompOff : modal_.comp == 1 ? Fn::CompLeft : Fn::CompRight};
    case FnGroup::ToolLength:
      return {modal_.length == 0 ? Fn::LengthOff : modal_.length > 0 ? Fn::LengthPlus : Fn::LengthMinus};
    case FnGroup::WorkOffset: return {Fn::WorkOffset, static_cast<uint16_t>(modal_.work_offset)};
    case FnGroup::Cycle:
      return modal_.cycle < 0 ? FnCall{Fn::CycleCancel} : FnCall{Fn::Cycle, static_cast<uint16_t>(modal_.cycle)};
    case FnGroup::Spindle:
      return {modal_.spindle == 1 ? Fn::SpindleCw : modal_.spindle == -1 ? Fn::SpindleCcw
              : modal_.spindle == 2 ? Fn::SpindleOrient : Fn::SpindleStop};
    case FnGroup::Override: return {modal_.override_enabled ? Fn::OverrideEnable : Fn::OverrideDisable};
    case FnGroup::SpindleHold: return {modal_.spindle_hold ? Fn::SpindleHoldOn : Fn::SpindleHoldOff};
    default: return {Fn::Count};  // not restorable: the tables reject such block-only codes
  }
}

void Machine::tool_length_event() {
  Event e{EventKind::ToolLengthOffset};
  if (modal_.length != 0) {
    auto it = config_.offsets.find(offset_number_);
    double length = it == config_.offsets.end() ? 0 : it->second.length * modal_.length;
    for (char axis : conv_.tool_offset_axes) e.pos[axis_index(axis)] = to_program(length);
  }
  emit(e);
}

void Machine::cutter_comp_event() {
  Event e{EventKind::CutterComp};
  e.n = modal_.comp;
  if (auto it = config_.offsets.find(offset_number_); it != config_.offsets.end()) e.a = to_program(it->second.radius);
  emit(e);
}

void Machine::apply(FnCall call, Scope scope, bool emit_events) {
  auto event = [&](EventKind kind, int n = 0, double a = 0) {
    if (!emit_events) return;
    Event e{kind};
    e.n = n;
    e.a = a;
    emit(e);
  };
  switch (call.fn) {
    case Fn::MotionRapid:
    case Fn::MotionLinear:
    case Fn::MotionArcCw:
    case Fn::MotionArcCcw:
    case Fn::MotionParabola:
    case Fn::MotionThread:
    case Fn::MotionThreadIncreasing:
    case Fn::MotionThreadDecreasing:
    case Fn::MotionDwell:
      if (call.fn == Fn::MotionDwell) block_.dwell_code = true;
      if (parabola_middle_ && call.fn != Fn::MotionParabola) {
        report(DiagId::ParabolaPair, 0, "the motion mode changed");
        parabola_middle_.reset();
      }
      modal_.motion = call.fn;
      break;
    case Fn::Dwell: block_.dwell = true; break;
    case Fn::SetPosition: block_.set_position = true; break;
    case Fn::PathAccelerate: event(EventKind::PathMode, 0); break;
    case Fn::PathDecelerate: event(EventKind::PathMode, 1); break;
    case Fn::PathTapping: event(EventKind::PathMode, 2); break;
    case Fn::PlaneXY:
    case Fn::PlaneZX:
    case Fn::PlaneYZ:
      modal_.plane = kPlanes[call.fn == Fn::PlaneXY ? 0 : call.fn == Fn::PlaneZX ? 1 : 2];
      if (emit_events) plane_event();
      break;
    case Fn::DistanceAbsolute: modal_.absolute = true; break;
    case Fn::DistanceIncremental: modal_.absolute = false; break;
    case Fn::UnitsMm:
    case Fn::UnitsInch:
      modal_.inch = call.fn == Fn::UnitsInch;
      event(EventKind::Units, modal_.inch);
      break;
    case Fn::FeedInverseTime:
    case Fn::FeedPerMinute:
    case Fn::FeedPerRevolution: {
      int mode = call.fn == Fn::FeedInverseTime ? 0 : call.fn == Fn::FeedPerMinute ? 1 : 2;
      // F means something else in the new mode: it must be programmed again.
      if (mode != modal_.feed_mode) feed_.reset();
      modal_.feed_mode = mode;
      event(EventKind::FeedMode, modal_.feed_mode);
      break;
    }
    case Fn::SpindleConstantSurface:
    case Fn::SpindleRpm:
      modal_.constant_surface = call.fn == Fn::SpindleConstantSurface;
      event(EventKind::SpindleMode, modal_.constant_surface);
      break;
    case Fn::CompOff:
    case Fn::CompLeft:
    case Fn::CompRight:
      modal_.comp = call.fn == Fn::CompOff ? 0 : call.fn == Fn::CompLeft ? 1 : 2;
      break;
    case Fn::LengthOff:
    case Fn::LengthPlus:
    case Fn::LengthMinus:
      modal_.length = call.fn == Fn::LengthOff ? 0 : call.fn == Fn::LengthPlus ? 1 : -1;
      break;
    case Fn::WorkOffset:
      if (call.arg != 0 && !config_.work_offsets.count(call.arg)) {
        report_code(DiagId::WorkOffsetUnknown, block_.code_name, call.arg);
        break;
      }
      if (scope == Scope::Block) {
        block_.block_offset = call.arg;
      } else {
        modal_.work_offset = call.arg;
        if (emit_events) {
          Event e{EventKind::WorkOffset};
          e.n = call.arg;
          if (auto it = config_.work_offsets.find(call.arg); it != config_.work_offsets.end())
            e.pos = in_program_units(it->second);
          emit(e);
        }
      }
      break;
    case Fn::CycleCancel:
      modal_.cycle = -1;
      cycle_ = {};
      break;
    case Fn::Cycle: modal_.cycle = call.arg; break;
    // Stops come after everything else of the block (Table 8: "after the commands of
    // the block are executed").
    case Fn::ProgramStop: block_.stop = 1; break;
    case Fn::ProgramOptionalStop: block_.stop = optional_stop_ ? 2 : 3; break;
    case Fn::ProgramEnd: block_.end = true; break;
    case Fn::ProgramEndInformation: block_.end_information = true; break;
    case Fn::SpindleCw:
    case Fn::SpindleCcw:
      modal_.spindle = spindle_direction_ = call.fn == Fn::SpindleCw ? 1 : -1;
      event(EventKind::SpindleOn, modal_.spindle);
      break;
    case Fn::SpindleStop:
      modal_.spindle = 0;
      event(EventKind::SpindleStop);
      break;
    case Fn::SpindleOrient:
      modal_.spindle = 2;
      event(EventKind::SpindleOrient, 0, 0);
      break;
    case Fn::ToolChange:
      if (conv_.m06_stops_spindle) {
        if (modal_.spindle != 0) apply({Fn::SpindleStop}, scope, emit_events);
        if (modal_.mist || modal_.flood) apply({Fn::CoolantOff}, scope, emit_events);
      }
      tool_loaded_ = tool_selected_;
      event(EventKind::ChangeTool, tool_loaded_);
      break;
    case Fn::CoolantMist:
      modal_.mist = true;
      event(EventKind::Coolant, 1);
      break;
    case Fn::CoolantFlood:
      modal_.flood = true;
      event(EventKind::Coolant, 2);
      break;
    case Fn::CoolantOff:
      modal_.mist = modal_.flood = false;
      event(EventKind::Coolant, 0);
      break;
    case Fn::ClampOn:
    case Fn::ClampOff:
      modal_.clamp = call.fn == Fn::ClampOn;
      event(EventKind::Clamp, modal_.clamp);
      break;
    case Fn::OverrideEnable:
    case Fn::OverrideDisable:
      modal_.override_enabled = call.fn == Fn::OverrideEnable;
      event(EventKind::Override, modal_.override_enabled);
      break;
    case Fn::SpindleHoldOff:
    case Fn::SpindleHoldOn:
      modal_.spindle_hold = call.fn == Fn::SpindleHoldOn;
      event(EventKind::SpindleHold, modal_.spindle_hold);
      break;
    case Fn::Count: break;
  }
}

void Machine::registers() {
  // F, S, T and the offset number are modal registers (§1.3); G00 ignores F but
  // keeps it (Table 5).
  if (has('F')) {
    feed_ = word('F');
    Event e{EventKind::FeedRate};
    e.a = *feed_;
    emit(e);
  }
  if (has('S')) {
    speed_ = word('S');
    Event e{EventKind::SpindleSpeed};
    e.a = speed_;
    emit(e);
  }
  if (auto tool = whole_number('T', "tool numbers")) {
    tool_selected_ = *tool;
    if (tool_selected_ != 0 && !config_.tools.count(tool_selected_)) report(DiagId::ToolUnknown, 'T', tool_selected_);
    Event e{EventKind::SelectTool};
    e.n = tool_selected_;
    emit(e);
  }
  for (char letter : {'D', 'H'}) {
    auto number = whole_number(letter, "offset numbers");
    if (!number) continue;
    if (*number != 0 && !config_.offsets.count(*number)) {
      report(DiagId::OffsetUnknown, letter, *number);
      continue;
    }
    offset_number_ = *number;  // takes effect at once on an active compensation
  }
}

std::optional<int> Machine::whole_number(char letter, const char* what) {
  if (!has(letter)) return std::nullopt;
  double v = word(letter);
  if (v >= 0 && v <= 999999999 && v == std::trunc(v)) return static_cast<int>(v);
  report(DiagId::DomainError, letter, fmt::format("{}{}", letter, four_decimals(v)), what);
  return std::nullopt;
}

Machine::Compensation Machine::compensation() const {
  auto it = config_.offsets.find(offset_number_);
  double radius = it == config_.offsets.end() ? 0 : it->second.radius;
  double length = it == config_.offsets.end() ? 0 : it->second.length;
  return {modal_.comp, modal_.comp ? radius : 0, modal_.length * length};
}

void Machine::flush_compensation() {
  // An event when the compensation in effect changes: one per block, with the
  // offset number the block ends with.
  Compensation now = compensation();
  if (now.side != block_.compensation.side || now.radius != block_.compensation.radius) cutter_comp_event();
  if (now.length != block_.compensation.length) tool_length_event();
  block_.compensation = now;
}

BlockResult Machine::execute(const BlockRequest& request) {
  block_ = BlockState{};
  block_.request = &request;
  block_.compensation = compensation();
  auto failed = [&] { return block_.error && stop_on_error_; };
  if (request.dynamic_codes) check_dynamic_codes();
  if (failed()) return BlockResult::Error;
  // 1. Preparatory functions in written order.
  apply_codes(Timing::None);
  // 2. Registers.
  registers();
  flush_compensation();
  if (failed()) return BlockResult::Error;
  // 3. Auxiliary functions that start before the motion (Table 7), in written order.
  apply_codes(Timing::Before);
  // 4. The action of the block.
  action();
  if (failed()) return BlockResult::Error;
  // 5. Auxiliary functions that start after the motion, then stops and ends.
  apply_codes(Timing::After);
  finish();
  if (failed()) return BlockResult::Error;
  if (block_.end_information) return BlockResult::EndOfInformation;
  if (block_.end) return BlockResult::ProgramEnd;
  return BlockResult::Continue;
}

void Machine::check_dynamic_codes() {
  const BlockRequest& r = *block_.request;
  for (size_t i = 0; i < r.code_count; ++i)
    for (size_t j = i + 1; j < r.code_count; ++j)
      for (const auto& [a, b] : sem_.incompatible)
        if (a == r.codes[i] && b == r.codes[j]) {
          block_.code = r.codes[j];
          report_code(DiagId::CodesIncompatible, sem_.codes[a].name, sem_.codes[b].name);
        }
  block_.code = -1;
}

void Machine::apply_codes(Timing timing) {
  const BlockRequest& request = *block_.request;
  for (size_t i = 0; i < request.code_count; ++i) {
    const CodeDesc& code = sem_.codes[request.codes[i]];
    if (code.timing != timing) continue;
    block_.code = request.codes[i];
    block_.code_name = code.name;
    for (const FnCall& call : code.calls) {
      // A block-only code's group comes back after the block (G53 works differently:
      // it only changes the frame of this block's words).
      FnGroup group = fn_group(call.fn);
      if (code.scope == Scope::Block && group != FnGroup::None && call.fn != Fn::WorkOffset)
        block_.restore.push_back(current(group));
      if (group == FnGroup::Motion) motion_name_ = code.name;
      apply(call, code.scope, true);
    }
  }
  block_.code = -1;
}

void Machine::action() {
  const bool axes = has_axis_word();
  if (block_.dwell || block_.dwell_code || (modal_.motion == Fn::MotionDwell && has(conv_.dwell_word))) {
    if (axes) report(DiagId::DwellWithMotion, 0);
    dwell();
    return;
  }
  if (block_.set_position) {
    set_position();
    return;
  }
  if (modal_.cycle >= 0) {
    if (axes || (conv_.cycle_level_word && has(conv_.cycle_level_word))) cycle();
    else cycle_registers();
    return;
  }
  if (!axes) {
    if (parabola_middle_) {
      report(DiagId::ParabolaPair, 0, "this block has no dimension word");
      parabola_middle_.reset();
    }
    return;
  }
  AxisValues t = target();
  switch (modal_.motion) {
    case Fn::MotionRapid: rapid(t); break;
    case Fn::MotionLinear: linear(t); break;
    case Fn::MotionArcCw: arc(t, true); break;
    case Fn::MotionArcCcw: arc(t, false); break;
    case Fn::MotionParabola: parabola(t); break;
    case Fn::MotionThread:
    case Fn::MotionThreadIncreasing:
    case Fn::MotionThreadDecreasing: thread(t); break;
    default:
      report(DiagId::NoMotionMode, 0, motion_name_);
      move_to(t);
      break;
  }
}

void Machine::finish() {
  for (const FnCall& call : block_.restore) apply(call, Scope::Modal, true);
  flush_compensation();
  if (block_.stop) {
    Event e{EventKind::Stop};
    e.n = block_.stop - 1;
    emit(e);
  }
  if (block_.end || block_.end_information) {
    // Table 8: M02/M30 stop the spindle and feed and switch coolant off, then the NC
    // returns to its initial state (§8), which the trace shows as it changes.
    if (parabola_middle_) report(DiagId::ParabolaPair, 0, "the program ended");
    apply({Fn::SpindleStop}, Scope::Modal, true);
    apply({Fn::CoolantOff}, Scope::Modal, true);
    Modal before = modal_;
    AxisValues position_offset = position_offset_;
    reset_state();
    emit_reset(before, position_offset);
    Event e{EventKind::End};
    e.n = block_.end_information;
    emit(e);
  }
  if (block_.error) return;
  std::bitset<kWordSlots> unused = block_.request->words->present & ~block_.used;
  for (int slot = 0; slot < kWordSlots; ++slot)
    if (unused[slot]) issue({DiagId::WordUnused, diag_message(DiagId::WordUnused, slot_name(slot)), block_.request->source, slot, -1});
}

void Machine::emit_reset(const Modal& before, const AxisValues& position_offset) {
  auto changed = [&](EventKind kind, int n) {
    Event e{kind};
    e.n = n;
    emit(e);
  };
  if (before.inch != modal_.inch) changed(EventKind::Units, modal_.inch);
  if (before.plane != modal_.plane) plane_event();
  if (before.feed_mode != modal_.feed_mode) changed(EventKind::FeedMode, modal_.feed_mode);
  if (before.constant_surface != modal_.constant_surface) changed(EventKind::SpindleMode, modal_.constant_surface);
  flush_compensation();
  if (before.work_offset != modal_.work_offset) apply({Fn::WorkOffset, static_cast<uint16_t>(modal_.work_offset)}, Scope::Modal, true);
  if (position_offset != position_offset_) {
    Event e{EventKind::PositionOffset};
    emit(e);
  }
}

void Machine::end_of_unit(uint32_t source) {
  if (!parabola_middle_) return;
  BlockWords none;
  BlockRequest request{nullptr, 0, &none, source};
  block_ = BlockState{};
  block_.request = &request;
  report(DiagId::ParabolaPair, 0, "the program ended");
  parabola_middle_.reset();
  block_ = BlockState{};
}

void Machine::comment(const std::string& text, uint32_t source) {
  Event e{EventKind::Comment};
  e.text = text;
  e.source = source;
  trace_.event(e);
}

void Machine::message(const std::string& text, uint32_t source) {
  Event e{EventKind::Message};
  e.text = text;
  e.source = source;
  trace_.event(e);
}

bool Machine::need_feed(const char* what, const AxisValues& t) {
  if (modal_.feed_mode == 0 && !has('F')) {
    report(DiagId::InverseTimeNoFeed, 0);
  } else if (!feed_) {
    report(DiagId::NoFeed, 0, what);
  } else {
    return true;
  }
  move_to(t);  // recover as if the move had been made
  return false;
}

void Machine::rapid(const AxisValues& t) {
  emit(motion_event(EventKind::Rapid, t));
  move_to(t);
}

void Machine::linear(const AxisValues& t) {
  if (!need_feed("linear interpolation", t)) return;
  emit(motion_event(EventKind::Linear, t));
  move_to(t);
}

void Machine::arc(const AxisValues& t, bool clockwise) {
  if (!need_feed("circular interpolation", t)) return;
  const int u = modal_.plane.u, v = modal_.plane.v, w = modal_.plane.w;
  const char pu = kParameterOf[u], pv = kParameterOf[v], pw = kParameterOf[w];
  if (!has(pu) && !has(pv)) {
    report(DiagId::ArcNoCentre, 0, clockwise ? "clockwise" : "counter-clockwise", plane_name(modal_.plane),
           fmt::format("{} {}", pu, pv));
    move_to(t);
    return;
  }
  const Eigen::Vector2d p0(machine_[u], machine_[v]);
  const Eigen::Vector2d p1(t[u], t[v]);
  Eigen::Vector2d centre;
  if (conv_.arc_centre == ArcCentre::Incremental || !modal_.absolute) {
    // §4.3.3: increments from the start point to the centre.
    centre = p0 + Eigen::Vector2d(has(pu) ? length_units(word(pu)) : 0, has(pv) ? length_units(word(pv)) : 0);
  } else {
    AxisValues off = target_frame();
    centre = Eigen::Vector2d(has(pu) ? length_units(word(pu)) + off[u] : p0.x(),
                             has(pv) ? length_units(word(pv)) + off[v] : p0.y());
  }
  const double r0 = (p0 - centre).norm();
  const double r1 = (p1 - centre).norm();
  if (r0 < kSamePoint) {
    report(DiagId::ArcZeroRadius, pu);
    move_to(t);
    return;
  }
  if (std::fabs(r0 - r1) > conv_.arc_tolerance + kSamePoint) {
    report(DiagId::ArcRadiusMismatch, 0, four_decimals(to_program(r0)), four_decimals(to_program(r1)),
           four_decimals(to_program(std::fabs(r0 - r1))), four_decimals(to_program(conv_.arc_tolerance)));
    move_to(t);
    return;
  }
  const double a0 = std::atan2(p0.y() - centre.y(), p0.x() - centre.x());
  const double a1 = std::atan2(p1.y() - centre.y(), p1.x() - centre.x());
  // End point = start point: a full circle (S-9.4).
  double sweep = (p1 - p0).norm() < kSamePoint ? kTwoPi : wrap(clockwise ? a0 - a1 : a1 - a0);
  if (sweep == 0) sweep = kTwoPi;

  // Linear-circular interpolation (§4.3.4, Appendix 4): the perpendicular axis moves
  // and its parameter is the travel per radian (or per revolution).
  const double dw = t[w] - machine_[w];
  if (std::fabs(dw) > kSamePoint) {
    const bool per_revolution = conv_.helix_lead == HelixLead::PerRevolution;
    if (auto lead = word_if(pw)) {
      // The lead selects the number of turns; the end point stays as programmed. It
      // must agree with the travel: lead x sweep = travel, within the arc tolerance
      // plus the rounding of the lead word over the sweep.
      double per_radian = length_units(*lead) / (per_revolution ? kTwoPi : 1);
      double candidate = sweep;
      if (per_radian != 0) {
        double lead_angle = dw / per_radian;
        candidate = sweep + kTwoPi * std::round((lead_angle - sweep) / kTwoPi);
        if (lead_angle <= 0 || candidate <= 0) candidate = sweep;
      }
      double off = std::fabs(candidate * per_radian - dw);
      double slack = conv_.arc_tolerance + kSamePoint +
                     candidate * length_units(conv_.lead_resolution) / 2 / (per_revolution ? kTwoPi : 1);
      if (off > slack) {
        report(DiagId::HelixLead, pw, four_decimals(*lead), four_decimals(to_program(dw)),
               per_radian == 0 ? std::string("infinitely many") : four_decimals(dw / per_radian), four_decimals(sweep));
        move_to(t);
        return;
      }
      sweep = candidate;
    } else {
      report(DiagId::HelixNoLead, 0, std::string(1, pw), std::string(1, kAxisLetters[w]),
             per_revolution ? "revolution" : "radian");
    }
  }
  if (conv_.arc_single_quadrant) {
    // §4.3.5: the arc may not cross the lines through the centre parallel to u or v.
    // The angle from the start to the next boundary in the direction of travel.
    double into_quadrant = std::fmod(wrap(a0), kPi / 2);
    double to_boundary = clockwise ? into_quadrant : kPi / 2 - into_quadrant;
    if (to_boundary < 1e-12) to_boundary = kPi / 2;
    if (sweep > to_boundary + 1e-9) {
      report(DiagId::ArcQuadrant, 0, four_decimals(sweep * 180 / kPi));
      move_to(t);
      return;
    }
  }
  if (sweep / kTwoPi > kMaxTurns) {
    report(DiagId::HelixTurns, pw, four_decimals(sweep / kTwoPi), kMaxTurns);
    move_to(t);
    return;
  }
  Event e = motion_event(EventKind::Arc, t);
  e.plane = modal_.plane;
  AxisValues off = frame_offset(modal_.work_offset);
  e.centre[0] = to_program(centre.x() - off[u]);
  e.centre[1] = to_program(centre.y() - off[v]);
  int turns = std::max(1, static_cast<int>(std::ceil(sweep / kTwoPi - 1e-9)));
  e.rotation = clockwise ? -turns : turns;
  e.a = to_program(r0);
  e.b = sweep * 180 / kPi;
  emit(e);
  move_to(t);
}

void Machine::parabola(const AxisValues& t) {
  if (!need_feed("parabolic interpolation", t)) return;
  AxisValues off = target_frame();
  Eigen::Vector3d p0(machine_[0], machine_[1], machine_[2]);
  Eigen::Vector3d p2(t[0], t[1], t[2]);
  Eigen::Vector3d control;
  if (has('I') || has('J') || has('K')) {
    // §4.4.3, one block: I, J, K give the intersection of the end tangents.
    if (parabola_middle_) {
      report(DiagId::ParabolaPair, 0, "this block is a one-block parabola");
      parabola_middle_.reset();
      move_to(t);
      return;
    }
    for (int i = 0; i < 3; ++i) {
      char letter = kParameterOf[i];
      if (!has(letter)) {
        control[i] = p0[i];
        continue;
      }
      double v = length_units(word(letter));
      bool coordinates = conv_.parabola_tangent == ParabolaTangent::Coordinates && modal_.absolute;
      control[i] = coordinates ? v + off[i] : p0[i] + v;
    }
  } else if (!parabola_middle_) {
    // §4.4.2, first of two blocks: the intermediate point. Nothing moves yet.
    parabola_middle_ = t;
    return;
  } else {
    // Second block: the end point. The intermediate point is the curve at t = 1/2,
    // so the tangent intersection is 2*P1 - (P0 + P2)/2.
    Eigen::Vector3d p1((*parabola_middle_)[0], (*parabola_middle_)[1], (*parabola_middle_)[2]);
    control = 2 * p1 - (p0 + p2) / 2;
    parabola_middle_.reset();
  }
  Event e = motion_event(EventKind::Parabola, t);
  AxisValues shown = frame_offset(modal_.work_offset);
  for (int i = 0; i < 3; ++i) e.control[i] = to_program(control[i] - shown[i]);
  emit(e);
  move_to(t);
}

void Machine::thread(const AxisValues& t) {
  // §7.1: the thread length in X and/or Z, the pitch in I or K (mm per revolution),
  // measured along the axis of the pitch word.
  std::string candidates = conv_.thread_allow_j ? "IJK" : "IK";
  std::string given;
  for (char c : candidates)
    if (has(c)) given += c;
  auto listed = [](const std::string& letters, const char* last) {
    std::string list;
    for (size_t i = 0; i < letters.size(); ++i)
      list += (i ? (i + 1 == letters.size() ? last : ", ") : "") + std::string(1, letters[i]);
    return list;
  };
  bool ok = true;
  if (given.size() != 1) {
    report(DiagId::ThreadPitch, 0, listed(candidates, " or "),
           given.empty() ? std::string("none is programmed")
                         : fmt::format("{} {} programmed", listed(given, " and "), given.size() == 2 ? "are both" : "are all"));
    ok = false;
  }
  if (has('F')) {
    report(DiagId::ThreadFeed, 'F', motion_name_);
    ok = false;
  }
  const char pitch_word = ok ? given[0] : 0;
  const int pitch_axis = pitch_word ? pitch_word - 'I' : 0;
  double pitch = ok ? length_units(word(pitch_word)) : 0;
  if (ok && pitch <= 0) {
    report(DiagId::ThreadPitchSign, pitch_word, fmt::format("{}{}", pitch_word, four_decimals(word(pitch_word))));
    ok = false;
  }
  const double length = std::fabs(t[pitch_axis] - machine_[pitch_axis]);
  if (ok && length < kSamePoint) {
    report(DiagId::ThreadPitchAxis, pitch_word, std::string(1, pitch_word), std::string(1, kAxisLetters[pitch_axis]));
    ok = false;
  }
  double change = 0;
  if (modal_.motion != Fn::MotionThread && ok) {
    // §7.4: G34/G35 start from the initial pitch; how the change is given is the NC's.
    const bool decreasing = modal_.motion == Fn::MotionThreadDecreasing;
    if (!conv_.pitch_change_word) {
      report(DiagId::ThreadPitchChangeUndefined, 0, motion_name_);
      ok = false;
    } else if (!has(conv_.pitch_change_word)) {
      report(DiagId::ThreadNoPitchChange, 0, motion_name_, std::string(1, conv_.pitch_change_word));
      ok = false;
    } else if (double d = word(conv_.pitch_change_word); d <= 0) {
      report(DiagId::ThreadPitchChangeSign, conv_.pitch_change_word, four_decimals(d), motion_name_,
             decreasing ? "subtracts" : "adds");
      ok = false;
    } else {
      change = length_units(d) * (decreasing ? -1 : 1);
      // After n revolutions the pitch is p + n*change and the thread has advanced
      // p*n + change*n*n/2; a decreasing pitch must not reach zero before the end.
      double reach = decreasing ? pitch * pitch / (2 * -change) : INFINITY;
      if (length > reach) {
        report(DiagId::ThreadPitchZero, conv_.pitch_change_word, motion_name_, four_decimals(to_program(reach)),
               four_decimals(to_program(length)));
        ok = false;
      }
    }
  }
  if (ok && (std::abs(modal_.spindle) != 1 || speed_ <= 0)) {
    report(DiagId::ThreadNoSpindle, 0);
    ok = false;
  }
  if (ok) {
    Event e = motion_event(EventKind::Thread, t);
    e.a = to_program(pitch);
    e.b = to_program(change);
    emit(e);
  }
  move_to(t);
}

void Machine::dwell() {
  auto time = word_if(conv_.dwell_word);
  if (!time) {
    report(DiagId::DwellNoTime, 0, dwell_address());
    return;
  }
  if (*time < 0) {
    report(DiagId::DwellNegative, conv_.dwell_word, four_decimals(*time));
    return;
  }
  Event e{EventKind::Dwell};
  e.a = *time * conv_.dwell_seconds_per_unit;
  emit(e);
}

std::string Machine::dwell_address() const {
  return conv_.dwell_word ? std::string(1, conv_.dwell_word) : std::string("a dwell address, which this machine lacks");
}

void Machine::set_position() {
  // The named axes take the programmed values as their current coordinates; nothing
  // moves (Table 5). Incremental values add to the current coordinates.
  AxisValues work{};
  if (auto it = config_.work_offsets.find(modal_.work_offset); it != config_.work_offsets.end()) work = it->second;
  for (char letter : conv_.axes) {
    if (!has(letter)) continue;
    int i = axis_index(letter);
    double v = word(letter);
    v = is_linear_axis(i) ? length_units(v) : angle_degrees(v);
    double current = machine_[i] - work[i] - position_offset_[i];
    double wanted = modal_.absolute ? v : current + v;
    position_offset_[i] = machine_[i] - work[i] - wanted;
  }
  Event e{EventKind::PositionOffset};
  e.pos = in_program_units(position_offset_);
  emit(e);
}

void Machine::cycle_registers() {
  // The cycle registers stay in force while the cycle is active (S-7.5); any block
  // may change them, the cycle runs only in blocks with a dimension word.
  const char depth_letter = kAxisLetters[modal_.plane.w];
  if (has(depth_letter)) cycle_.depth = word(depth_letter);
  if (auto v = word_if(conv_.cycle_level_word)) cycle_.level = v;
  if (auto v = word_if(conv_.dwell_word)) cycle_.dwell = v;
  if (auto v = word_if(conv_.peck_word)) cycle_.peck = v;
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
      report(DiagId::PeckNotPositive, conv_.peck_word, four_decimals(*cycle_.peck), pattern.name);
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
  if (pattern.dwell) {
    Event e{EventKind::Dwell};
    e.a = *cycle_.dwell * conv_.dwell_seconds_per_unit;
    emit(e);
  }
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

}  // namespace ncc
