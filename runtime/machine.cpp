// The block cycle and the modal functions.
#include "machine.h"

#include <algorithm>
#include <cmath>

#include "block_rules.h"
#include "cycle_engine.h"
#include "support/text.h"
#include "tool_change.h"

namespace ncc {

namespace {
constexpr const char* kFeedModes[] = {"inverse-time feeds", "feeds per minute (mm/min)",
                                      "feeds per revolution (mm/rev)"};
}  // namespace

Machine::Machine(const ProgramSemantics& semantics, const MachineConfig& config, TraceSink& trace,
                 RuntimeIssues& issues)
    : sem_(semantics), conv_(semantics.conventions), config_(config), trace_(trace), issues_(issues),
      kernel_(config, trace, cutter_path(trace)) {
  gtl_init();
  cycles_ = CycleEngine::make(*this, conv_);
  tool_change_ = ToolChange::make(*this, conv_);
  rules_ = BlockRules::make(*this, conv_);
}

Machine::~Machine() = default;

void Machine::cancel_cycle() {
  modal_.cycle = -1;
  cycles_->cancelled();
}

std::unique_ptr<CutterPath> Machine::cutter_path(TraceSink& trace) {
  // An error of the path stops the run at the block being run, as any error does.
  // ISO §8.10: Fanuc's type A.
  if (conv_.cutter == CutterStyle::FanucA)
    return std::make_unique<CutterPath>(
        trace,
        [](void* self, uint32_t source, const std::string& what) {
          static_cast<Machine*>(self)->issue({DiagId::ArcForm, diag_message(DiagId::ArcForm, what), source, -1, -1});
        },
        this);
  // NC-110 §2.8.7: outside corners where the offsets meet, G40 with the next block's
  // move, G41/G42 in a block of their own started by the next move.
  if (conv_.cutter == CutterStyle::Nc110)
    return std::make_unique<CutterPath>(
        trace,
        [](void* self, uint32_t source, const std::string& what) {
          static_cast<Machine*>(self)->issue({DiagId::CompPath, diag_message(DiagId::CompPath, what), source, -1, -1});
        },
        this, CompRules{false, true, true, false, false});
  return nullptr;
}

void Machine::release(DiagId id) {
  auto it = repeated_.find(id);
  if (it == repeated_.end()) return;
  RuntimeIssue i = std::move(it->second.issue);
  if (const uint32_t more = it->second.more)
    i.message += fmt::format(" (and {} more block{})", more, more == 1 ? "" : "s");
  repeated_.erase(it);
  issues_.issue(i);  // not the block's error: it belongs to the block it names
}

void Machine::release_repeated() {
  while (!repeated_.empty()) release(repeated_.begin()->first);
}

void Machine::end_run(bool stopped_by_error) {
  release_repeated();
  if (kernel_.holding()) release();
  if (kernel_.path()) kernel_.path()->finish(!stopped_by_error);
}

void Machine::power_on() {
  kernel_.move_to(config_.initial_position);
  kernel_.offsets() = config_.work_offsets;
  tool_offsets_ = config_.offsets;
  // Origin 0 is 0 on every axis the profile does not give it: (UAO,0) and RESET
  // select it on all axes (NC-110 §2.13.1.1).
  kernel_.offsets()[0].axes = (1u << kAxisCount) - 1;
  tool_loaded_ = 0;
  select_offset(0);
  probe_ = config_.probe;
  unusable_.clear();
  block_skip_ = config_.block_skip;
  optional_stop_ = config_.optional_stop;
  reset_state();
  // A trace to compare with another dialect's starts with the modes the power-on
  // state gives: one dialect's power-on G94 is another's written G94.
  if (config_.trace_machine_frame && trace_.wants_events()) {
    auto state = [&](EventKind kind, int n) {
      Event e{kind};
      e.n = n;
      e.plane = modal_.plane;
      trace_.event(e);
    };
    state(EventKind::Units, modal_.inch);
    state(EventKind::Plane, 0);
    state(EventKind::FeedMode, modal_.feed_mode);
    state(EventKind::SpindleMode, modal_.constant_surface);
    if (feed_) {
      Event e{EventKind::FeedRate};
      e.a = *feed_;
      trace_.event(e);
    }
    // And where the work zero is: the positions that follow do not say.
    if (modal_.work_offset != 0) {
      Event e{EventKind::WorkOffset};
      e.n = modal_.work_offset;
      for (int i = 0; i < kAxisCount; ++i) e.pos[i] = program_axis(i, kernel_.offset_value(modal_.work_offset, i));
      trace_.event(e);
    }
  }
}

void Machine::reset_state() {
  virtual_off();  // the end of the program cancels virtual axes
  // NC-110: the corrector of the tool in the spindle stays in force (§2.7.8, M30).
  const int length = tool_change_->corrector_in_tool() ? modal_.length : 0;
  modal_ = Modal{};
  modal_.length = length;
  kernel_.reset_coordinates();
  intermediate_.reset();
  feed_.reset();
  release_repeated();
  if (conv_.initial_feed > 0) feed_ = conv_.initial_feed;
  last_rotation_ = 0;
  helix_pitch_.reset();
  speed_ = 0;
  tool_selected_ = corrector_selected_ = 0;
  if (!tool_change_->corrector_in_tool()) select_offset(0);
  spindle_direction_ = 0;
  cycles_->cancelled();
  parabola_middle_.reset();
  kernel_.envelope() = {};
  tolerance_ = {};
  turning_ = false;
  locked_ = 0;
  profile_running_ = false;
  spline_ = {};
  // The power-on codes apply as a block with no words.
  BlockState saved = block_;
  BlockWords none;
  BlockRequest request{nullptr, 0, &none, 0};
  block_ = BlockState{};
  block_.request = &request;
  for (uint16_t index : sem_.power_on) {
    const CodeDesc& code = sem_.codes[index];
    for (const FnCall& call : code.calls) {
      if (fn_group(call.fn) == FnGroup::Motion) motion_name_ = code.name;
      apply(call, Scope::Modal, false);
    }
  }
  block_ = saved;
}

double Machine::angle_degrees(double v) const {
  switch (conv_.angle_unit) {
    case AngleUnit::Degree: return v;
    case AngleUnit::Radian: return v * 180.0 / std::numbers::pi;
    case AngleUnit::Revolution: return v * 360.0;
  }
  return v;
}

double Machine::axis_units(int axis, double v) const {
  const AxisConfig& a = config_.axes[static_cast<size_t>(axis)];
  switch (a.kind) {
    case AxisKind::Linear:
      return length_units(modal_.diameter && kAxisLetters[axis] == conv_.diameter_axis ? v / 2 : v);
    case AxisKind::Rotary: return angle_degrees(v);
    case AxisKind::Indexing: return v * a.index_step;
  }
  return v;
}

void Machine::plane_event() {
  Event e{EventKind::Plane};
  e.plane = modal_.plane;
  emit(e);
}

void Machine::path_event(int mode) {
  Event e{EventKind::PathMode};
  e.n = mode;
  emit(e);
}

void Machine::emit(Event e) {
  // A block stops doing things at its first error: what it did before shows, the
  // rest does not (the machine's state still follows it in a dry run).
  if (block_.error || !kernel_.wanted(e.kind)) return;
  e.source = source();
  kernel_.emit(e, modal_.inch);
}

bool Machine::block_has(Fn fn) const {
  for (size_t i = 0; i < block_.request->code_count; ++i)
    for (const FnCall& call : sem_.codes[block_.request->codes[i]].calls)
      if (call.fn == fn) return true;
  return false;
}

uint64_t Machine::held_bytes() const {
  return path_bytes() + kernel_.held().capacity() * sizeof(Event) + spline_bytes() + gtl_bytes();
}

uint64_t Machine::path_bytes() const { return kernel_.path() ? kernel_.path()->held_bytes() : 0; }

uint64_t Machine::spline_bytes() const {
  return spline_.points.capacity() * sizeof(AxisValues) + spline_.sources.capacity() * sizeof(uint32_t);
}

std::string Machine::held_what() const {
  if (spline_bytes() > path_bytes())
    return fmt::format("the spline holds {} points (G06 blocks since its BSP)", spline_.points.size());
  return fmt::format("cutter radius compensation holds {} events while its move waits for the next move in the plane",
                     kernel_.path() ? kernel_.path()->held_events() : 0);
}

FnCall Machine::current(FnGroup group) const {
  switch (group) {
    case FnGroup::Motion: return {modal_.motion};
    case FnGroup::Plane:
      return {modal_.plane == kPlanes[1] ? Fn::PlaneZX : modal_.plane == kPlanes[2] ? Fn::PlaneYZ : Fn::PlaneXY};
    case FnGroup::Distance: return {modal_.absolute ? Fn::DistanceAbsolute : Fn::DistanceIncremental};
    case FnGroup::Units: return {modal_.inch ? Fn::UnitsInch : Fn::UnitsMm};
    case FnGroup::FeedMode:
      return {modal_.feed_mode == 0   ? Fn::FeedInverseTime
              : modal_.feed_mode == 1 ? Fn::FeedPerMinute
                                      : Fn::FeedPerRevolution};
    case FnGroup::SpindleMode: return {modal_.constant_surface ? Fn::SpindleConstantSurface : Fn::SpindleRpm};
    case FnGroup::CutterComp: return {modal_.comp == 0 ? Fn::CompOff : modal_.comp == 1 ? Fn::CompLeft : Fn::CompRight};
    case FnGroup::ToolLength:
      return {modal_.length == 0 ? Fn::LengthOff : modal_.length > 0 ? Fn::LengthPlus : Fn::LengthMinus};
    case FnGroup::WorkOffset: return {Fn::WorkOffset, static_cast<uint16_t>(modal_.work_offset)};
    case FnGroup::Cycle:
      return modal_.cycle < 0 ? FnCall{Fn::CycleCancel} : FnCall{Fn::Cycle, static_cast<uint16_t>(modal_.cycle)};
    case FnGroup::Spindle:
      return {modal_.spindle == 1    ? Fn::SpindleCw
              : modal_.spindle == -1 ? Fn::SpindleCcw
              : modal_.spindle == 2  ? Fn::SpindleOrient
                                     : Fn::SpindleStop};
    case FnGroup::Override: return {modal_.override_enabled ? Fn::OverrideEnable : Fn::OverrideDisable};
    case FnGroup::SpindleHold: return {modal_.spindle_hold ? Fn::SpindleHoldOn : Fn::SpindleHoldOff};
    case FnGroup::Dynamics:
      if (modal_.dynamics < 0) break;  // never set: nothing to give back
      return {modal_.dynamics == 0   ? Fn::DynamicsCornerSlowdown
              : modal_.dynamics == 1 ? Fn::DynamicsContinuous
              : modal_.dynamics == 2 ? Fn::DynamicsPointToPoint
                                     : Fn::DynamicsSmooth};
    case FnGroup::Gtl: return {modal_.gtl ? Fn::GtlOpen : Fn::GtlClose};
    case FnGroup::SpindleRange:
      return modal_.spindle_range > 0
                 ? FnCall{Fn::SpindleRangeForce, static_cast<uint16_t>(modal_.spindle_range)}
                 : FnCall{modal_.spindle_range < 0 ? Fn::SpindleRangeAuto : Fn::SpindleRangeCancel};
    case FnGroup::Diameter: return {modal_.diameter ? Fn::DiameterOn : Fn::DiameterOff};
    case FnGroup::Helix: return {modal_.helix ? Fn::HelixOn : Fn::HelixOff};
    case FnGroup::FeedReduction: return {modal_.feed_reduced ? Fn::FeedReduced : Fn::FeedProgrammed};
    case FnGroup::CycleReturn: return {modal_.cycle_return_level ? Fn::CycleReturnLevel : Fn::CycleReturnInitial};
    case FnGroup::Polar: return {modal_.polar ? Fn::PolarOn : Fn::PolarOff};
    case FnGroup::Scaling: return {modal_.scaling ? Fn::ScalingOn : Fn::ScalingOff};
    case FnGroup::Rotation: return {modal_.rotation ? Fn::RotationOn : Fn::RotationOff};
    default: break;
  }
  return {Fn::Count};  // not restorable: the tables reject such block-only codes
}

void Machine::tool_length_event() {
  Event e{EventKind::ToolLengthOffset};
  e.n = length_number_;  // the entry it comes from (translation writes it again)
  e.pos = in_program_units(compensation().length);
  emit(e);
}

void Machine::cutter_comp_event() {
  Event e{EventKind::CutterComp};
  e.n = modal_.comp;
  // ISO §8.12: a mirror in one axis of the plane puts the tool on the other side.
  if (kernel_.path() && e.n != 0 && kernel_.frame().mirror[modal_.plane.u] != kernel_.frame().mirror[modal_.plane.v])
    e.n = 3 - e.n;
  e.a = to_program(offset_.radius);
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
  // NC-110 §2.8.9 note 4: with a canned cycle active, these need it cancelled first.
  auto cycle_active = [&] {
    if (modal_.cycle < 0 || !emit_events || !cycles_->needs_cancel()) return false;
    report_code(DiagId::CycleActive, block_.code_name, sem_.cycles[modal_.cycle].name);
    return true;
  };
  switch (call.fn) {
    case Fn::MotionArcCw:
    case Fn::MotionArcCcw:
    case Fn::MotionThreadVariable:
    case Fn::MotionSpline:
      if (cycle_active()) break;
      [[fallthrough]];
    case Fn::MotionRapid:
    case Fn::MotionLinear:
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
      // NC-110 §2.8.1.3: inside a spline only G06 and the lead-out's G00/G01.
      if (spline_.active && spline_.points.size() > 1 && call.fn != Fn::MotionSpline && call.fn != Fn::MotionRapid &&
          call.fn != Fn::MotionLinear && emit_events)
        report_code(DiagId::SplineStructure,
                    fmt::format("{} cannot stand inside a spline: only G06 points and the G00 or G01 lead-out",
                                block_.code_name));
      modal_.motion = call.fn;
      // A code of the motion group may end the canned cycle of an earlier block (ISO).
      if (modal_.cycle >= 0 && emit_events && !block_.cycle_set && cycles_->motion_ends_cycle()) cancel_cycle();
      break;
    case Fn::Dwell: block_.dwell = true; break;
    case Fn::SetPosition:
      if (emit_events && (!rules_->may_run_scaled_or_rotated() || !rules_->may_change_coordinates())) break;
      block_.set_position = true;
      break;
    case Fn::PathAccelerate: event(EventKind::PathMode, 0); break;
    case Fn::PathDecelerate:
      block_.decelerate = true;
      event(EventKind::PathMode, 1);
      break;
    case Fn::PathTapping: event(EventKind::PathMode, 2); break;
    case Fn::PlaneXY:
    case Fn::PlaneZX:
    case Fn::PlaneYZ: {
      const Plane& plane = kPlanes[call.fn == Fn::PlaneXY ? 0 : call.fn == Fn::PlaneZX ? 1 : 2];
      if (emit_events && !rules_->may_change_plane(plane)) break;
      modal_.plane = plane;
      if (emit_events) plane_event();
      break;
    }
    case Fn::DistanceAbsolute: modal_.absolute = true; break;
    case Fn::DistanceIncremental: modal_.absolute = false; break;
    case Fn::UnitsMm:
    case Fn::UnitsInch:
      if (emit_events && modal_.inch != (call.fn == Fn::UnitsInch) && !rules_->may_change_coordinates()) break;
      modal_.inch = call.fn == Fn::UnitsInch;
      event(EventKind::Units, modal_.inch);
      break;
    case Fn::FeedInverseTime:
    case Fn::FeedPerMinute:
    case Fn::FeedPerRevolution: {
      int mode = call.fn == Fn::FeedInverseTime ? 0 : call.fn == Fn::FeedPerMinute ? 1 : 2;
      // F means something else in the new mode: it must be programmed again.
      if (mode != modal_.feed_mode) {
        feed_.reset();
        release(DiagId::NoFeed);
      }
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
    case Fn::CompRight: modal_.comp = call.fn == Fn::CompOff ? 0 : call.fn == Fn::CompLeft ? 1 : 2; break;
    case Fn::LengthOff:
    case Fn::LengthPlus:
    case Fn::LengthMinus: modal_.length = call.fn == Fn::LengthOff ? 0 : call.fn == Fn::LengthPlus ? 1 : -1; break;
    case Fn::WorkOffset:
      // pp G92: a G5 code in its block names the offset to load; it selects nothing.
      if (block_.offset_load) {
        block_.load_entry = call.arg;
        break;
      }
      if (call.arg != 0 && !kernel_.offsets().count(call.arg)) {
        report_code(DiagId::WorkOffsetUnknown, block_.code_name,
                    call.arg > kExtendedWorkOffset ? fmt::format("work offset P{}", call.arg - kExtendedWorkOffset)
                                                   : fmt::format("work offset {}", call.arg),
                    config_.profile, number_ranges(kernel_.offsets(), true));
        break;
      }
      if (emit_events && !rules_->may_run_scaled_or_rotated()) break;
      if (emit_events && scope == Scope::Modal && call.arg != modal_.work_offset && !rules_->may_change_coordinates())
        break;
      // G53: the block's words are machine coordinates.
      if (emit_events && scope == Scope::Block && call.arg == 0 && !rules_->may_use_machine_coordinates()) break;
      if (scope == Scope::Block) {
        block_.block_offset = call.arg;
      } else {
        modal_.work_offset = call.arg;
        const AxisValues local_before = kernel_.frame().local;
        kernel_.select_work_offset(call.arg);
        if (emit_events) {
          Event e{EventKind::WorkOffset};
          e.n = call.arg;
          if (auto it = kernel_.offsets().find(call.arg); it != kernel_.offsets().end())
            for (int i = 0; i < kAxisCount; ++i) e.pos[i] = program_axis(i, kernel_.offset_value(call.arg, i));
          emit(e);
          if (kernel_.frame().local != local_before) position_offset_event();  // ISO G52: its own local shift
        }
      }
      break;
    case Fn::CycleCancel: cancel_cycle(); break;
    case Fn::Cycle:
      if (cycle_active()) break;
      modal_.cycle = call.arg;
      block_.cycle_set = true;
      cycles_->selected();  // NC-110: defined anew (§2.8.9 note 1); GOST: the registers stay (S-7.5)
      break;
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
      if (tool_change_->same_tool_ignored() && tool_selected_ == tool_loaded_) break;
      if (emit_events && !rules_->may_run_scaled_or_rotated()) break;
      tool_change_->before(scope, emit_events);
      tool_loaded_ = tool_selected_;
      tool_change_->after();
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
    case Fn::ClampRotaryOn:
    case Fn::ClampRotaryOff: {
      // NC-110 §2.8.15: M10 (M12) clamps the (rotary) axes its block does not move.
      bool rotary = call.fn == Fn::ClampRotaryOn || call.fn == Fn::ClampRotaryOff;
      bool on = call.fn == Fn::ClampOn || call.fn == Fn::ClampRotaryOn;
      (rotary ? modal_.rotary_clamp : modal_.clamp) = on;
      for (int i = 0; i < kAxisCount; ++i) {
        if (rotary && is_linear(i)) continue;
        bool named = block_.request && has(kAxisLetters[i]);
        if (on && !named) locked_ |= 1u << i;
        if (!on) locked_ &= ~(1u << i);
      }
      event(EventKind::Clamp, on + (rotary ? 2 : 0));
      break;
    }
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
    case Fn::DynamicsCornerSlowdown:
    case Fn::DynamicsContinuous:
    case Fn::DynamicsPointToPoint:
    case Fn::DynamicsSmooth: {
      int mode = call.fn == Fn::DynamicsCornerSlowdown ? 0
                 : call.fn == Fn::DynamicsContinuous   ? 1
                 : call.fn == Fn::DynamicsPointToPoint ? 2
                                                       : 3;
      if (mode >= 2) profile_running_ = false;
      if (mode != modal_.dynamics) event(EventKind::PathMode, 4 + mode);
      modal_.dynamics = mode;
      break;
    }
    case Fn::GtlOpen:
    case Fn::GtlClose: modal_.gtl = call.fn == Fn::GtlOpen; break;
    case Fn::GtlDefine: block_.gtl_define = call.arg; break;
    case Fn::OriginMachine:
      if (!cycle_active()) block_.machine_frame = true;
      break;
    case Fn::PathDwellEnd: block_.dwell_end = true; break;
    case Fn::PathSpindleSync: block_.spindle_sync = true; break;
    case Fn::MeasurePoint:
    case Fn::MeasureHole:
    case Fn::MeasureDeviation:
      if (!cycle_active()) block_.measure = call.fn;
      break;
    case Fn::MotionSkip:
      // Fanuc G31 (decision 66): alarm PS0035 under cutter compensation.
      if (modal_.comp != 0)
        report_code(DiagId::PlaneState, block_.code_name, "cutter radius compensation (G41/G42)");
      else if (!cycle_active())
        block_.measure = call.fn;
      break;
    case Fn::SpindleRangeForce:
    case Fn::SpindleRangeCancel:
    case Fn::SpindleRangeAuto:
      modal_.spindle_range = call.fn == Fn::SpindleRangeForce ? call.arg : call.fn == Fn::SpindleRangeAuto ? -1 : 0;
      event(EventKind::SpindleRange, modal_.spindle_range);
      break;
    case Fn::PartChange: event(EventKind::PartChange); break;
    case Fn::MotionReference: block_.reference = true; break;
    case Fn::ReferenceReturn:
    case Fn::ReferenceLeave:
      if (emit_events && !rules_->may_run_scaled_or_rotated()) break;
      block_.reference_trip = call.fn == Fn::ReferenceReturn ? 1 : 2;
      break;
    case Fn::ReferenceReturnNth: {
      // Fanuc G30 (decision 65): P2, P3 or P4 (P2 without P) names the reference point.
      if (emit_events && !rules_->may_run_scaled_or_rotated()) break;
      const int n = has('P') ? whole_in(word('P'), 2, 4).value_or(0) : 2;
      block_.used.set(letter_slot('P'));
      if (n == 0)
        report(DiagId::OperandValue, 'P', fmt::format("P of {}", block_.code_name), shortest(word('P')),
               "2, 3 or 4: the second, third or fourth reference point");
      else
        block_.reference_trip = n + 1;
      break;
    }
    case Fn::OffsetLocal:
      if (emit_events && (!rules_->may_run_scaled_or_rotated() || !rules_->may_change_coordinates())) break;
      block_.local_offset = true;
      break;
    case Fn::DataSet: block_.data_set = true; break;
    case Fn::WorkOffsetExtended: {
      // G54.1 P / G154 P: the extended work offset P, kept as kExtendedWorkOffset + P.
      if (!has('P')) {
        report_code(DiagId::OperandValue, block_.code_name, "without P",
                    fmt::format("written with the extended work offset's number P1..P{}", kExtendedWorkOffsets));
        break;
      }
      const std::optional<int> p = whole_in(word('P'), 1, kExtendedWorkOffsets);
      if (!p) {
        report(DiagId::OperandValue, 'P', fmt::format("{} P", block_.code_name), shortest(word('P')),
               fmt::format("an extended work offset P1..P{}", kExtendedWorkOffsets));
        break;
      }
      apply({Fn::WorkOffset, static_cast<uint16_t>(kExtendedWorkOffset + *p)}, scope, emit_events);
      break;
    }
    case Fn::CycleReturnInitial:
    case Fn::CycleReturnLevel: modal_.cycle_return_level = call.fn == Fn::CycleReturnLevel; break;
    case Fn::PolarOff:
    case Fn::PolarOn: modal_.polar = call.fn == Fn::PolarOn; break;
    case Fn::ScalingOn: block_.scaling_on = true; break;
    case Fn::RotationOn: block_.rotation_on = true; break;
    case Fn::ScalingOff:
      if (emit_events && modal_.scaling && !rules_->may_change_coordinates()) break;
      if (modal_.scaling) {
        modal_.scaling = false;
        kernel_.frame().clear_scaling();
        if (emit_events) transform_event();
      }
      break;
    case Fn::RotationOff:
      if (emit_events && modal_.rotation && !rules_->may_change_coordinates()) break;
      if (modal_.rotation) {
        modal_.rotation = false;
        kernel_.frame().clear_rotation();
        if (emit_events) transform_event();
      }
      break;
    case Fn::OffsetLoad:
    case Fn::CompLoad: break;  // found before the block's codes apply (execute)
    case Fn::DiameterOn:
    case Fn::DiameterOff:
      if (modal_.diameter != (call.fn == Fn::DiameterOn)) event(EventKind::Diameter, call.fn == Fn::DiameterOn);
      modal_.diameter = call.fn == Fn::DiameterOn;
      break;
    case Fn::HelixOn:
    case Fn::HelixOff: modal_.helix = call.fn == Fn::HelixOn; break;
    case Fn::HelixPitch:
      // pp G10 K: the pitch of the helices that follow (mm per turn).
      if (!emit_events) break;
      if (!has('K'))
        report_code(DiagId::ArcForm, fmt::format("{} defines the helix pitch: K is missing", block_.code_name));
      else if (word('K') <= 0)
        report(DiagId::ArcForm, 'K', fmt::format("the helix pitch K{} must be greater than zero", shortest(word('K'))));
      else
        helix_pitch_ = word('K');
      break;
    case Fn::TransformCancel: {
      const bool shifted = kernel_.frame().shift != AxisValues{};
      const bool transformed = kernel_.frame().transformed();
      kernel_.frame().mirror.fill(false);
      kernel_.frame().scale.fill(1);
      kernel_.frame().shift.fill(0);
      if (emit_events && transformed) transform_event();
      if (emit_events && shifted) origin_event();
      break;
    }
    case Fn::Coolant3:
      modal_.coolant3 = true;
      event(EventKind::Coolant, 3);
      break;
    case Fn::Coolant4:
      modal_.coolant4 = true;
      event(EventKind::Coolant, 4);
      break;
    case Fn::CoolantOff34:
      modal_.coolant3 = modal_.coolant4 = false;
      event(EventKind::Coolant, 5);
      break;
    case Fn::FeedReduced:
    case Fn::FeedProgrammed:
      if (modal_.feed_reduced != (call.fn == Fn::FeedReduced))
        event(EventKind::FeedReduction, call.fn == Fn::FeedReduced);
      modal_.feed_reduced = call.fn == Fn::FeedReduced;
      break;
    case Fn::Aux: {
      if (!emit_events) break;
      Event e{EventKind::Aux};
      e.text = block_.code_name;
      emit(e);
      break;
    }
    default:
      // The three-letter functions (origins, transforms, limits, zones...): their
      // axis words are operands, not a move.
      if (frame_function(call) || tooling_function(call) || virtual_function(call)) block_.operands = true;
      break;
  }
}

void Machine::registers() {
  // F, S, T and the offset number are modal registers (§1.3); G00 ignores F but
  // keeps it (Table 5).
  if (has('F')) {
    // pp: what F may be depends on the feed mode (mm/min or mm/rev).
    const auto& range = conv_.feed_limits[modal_.feed_mode];
    if (range[1] > 0 && !(word('F') >= range[0] && word('F') <= range[1]))
      report(DiagId::FeedRange, 'F', shortest(word('F')), kFeedModes[modal_.feed_mode], shortest(range[0]),
             shortest(range[1]));
    feed_ = word('F');
    release(DiagId::NoFeed);
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
    tool_selected_ = usable_tool(*tool);
    if (tool_selected_ != 0 && !config_.tools.count(tool_selected_))
      report(DiagId::ToolUnknown, 'T', tool_selected_, config_.profile, number_ranges(config_.tools));
    Event e{EventKind::SelectTool};
    e.n = tool_selected_;
    emit(e);
    tool_change_->tool_word(*tool);
  }
  // pp H, P: auxiliary functions the machine's logic carries out (H, then P).
  for (char letter : conv_.aux_words)
    if (auto n = whole_number(letter, "auxiliary functions")) {
      Event e{EventKind::Aux};
      e.text = fmt::format("{}{}", letter, *n);
      emit(e);
    }
  if (has_slot(kLinkSlot)) link();
  if (tool_change_->corrector_in_tool() || block_.comp_load) return;  // NC-110 D is an axis; pp G93 D names an entry
  for (char letter : {'D', 'H'}) {
    if (conv_.aux_words.find(letter) != std::string::npos) continue;
    auto number = whole_number(letter, "offset numbers");
    if (!number) continue;
    if (*number != 0 && !tool_offsets_.count(*number)) {
      report(DiagId::OffsetUnknown, letter, "offset number", *number, config_.profile, number_ranges(tool_offsets_));
      continue;
    }
    // Takes effect at once on an active compensation. ISO: H the length, D the radius.
    select_offset(*number, !conv_.length_word            ? OffsetUse::Both
                           : letter == conv_.length_word ? OffsetUse::Length
                                                         : OffsetUse::Radius);
  }
}

std::optional<int> Machine::whole_number(char letter, const char* what) {
  if (!has(letter)) return std::nullopt;
  const double v = word(letter);
  if (auto n = whole_in(v, 0, 999999999)) return n;
  report(DiagId::DomainError, letter, fmt::format("{}{}", letter, four_decimals(v)), what);
  return std::nullopt;
}

Machine::Compensation Machine::compensation() const {
  const double length = length_offset_.length;
  Compensation c{modal_.comp, modal_.comp ? offset_.radius : 0, {}};
  if (length == 0) return c;  // every block asks: keep the usual case short
  if (modal_.length != 0)
    for (char axis : length_offset_.axis ? std::string(1, length_offset_.axis) : conv_.tool_offset_axes)
      c.length[axis_index(axis)] = modal_.length * length;
  // pp '&': per axis, 1 adds the length, 2 subtracts it.
  for (size_t i = 0; i < conv_.link_axes.size() && i < modal_.link.size(); ++i)
    if (modal_.link[i]) c.length[axis_index(conv_.link_axes[i])] += (modal_.link[i] == 1 ? 1 : -1) * length;
  return c;
}

void Machine::link() {
  // pp '&' (docs/dialects/pp.md): a digit per axis of link_axes, right-aligned.
  const double v = slot_value(kLinkSlot);
  const size_t n = std::min(conv_.link_axes.size(), modal_.link.size());
  std::array<uint8_t, 4> digits{};
  const std::optional<uint32_t> all =
      whole_in<uint32_t>(v, 0, static_cast<uint32_t>(std::pow(10.0, static_cast<double>(n))) - 1);
  bool ok = all.has_value();
  for (uint32_t rest = all.value_or(0), i = static_cast<uint32_t>(n); ok && i-- > 0; rest /= 10) {
    digits[i] = static_cast<uint8_t>(rest % 10);
    ok = digits[i] <= 2;
  }
  if (!ok) {
    report_slot(
        DiagId::OperandValue, kLinkSlot, "the length link &", shortest(v),
        fmt::format(
            "at most {} digits, each 0, 1 or 2, for {} from the right (0 none, 1 plus, 2 minus the tool length)", n,
            conv_.link_axes));
    return;
  }
  modal_.link = digits;
}

void Machine::flush_compensation() {
  // An event when the compensation in effect changes: one per block, with the
  // offset number the block ends with.
  Compensation now = compensation();
  if (now.side != block_.compensation.side || now.radius != block_.compensation.radius) cutter_comp_event();
  if (now.length != block_.compensation.length) tool_length_event();
  block_.compensation = now;
}

// NC-110 §2.8.5: a G27/G28 profile runs as one block: M, S and T words cannot stand
// inside it, only after a G00 move, a G09 or G04 block, or before any feed move.
void Machine::check_profile_rules() {
  if (!profile_running_ || (modal_.dynamics != 0 && modal_.dynamics != 1)) return;
  if (modal_.motion == Fn::MotionRapid && has_axis_word()) return;  // a G00 move ends the profile
  const BlockRequest& r = *block_.request;
  std::vector<std::string> words;
  for (size_t i = 0; i < r.code_count; ++i) {
    const CodeDesc& code = sem_.codes[r.codes[i]];
    // M codes; a program stop or end ends the profile too.
    bool stops = std::any_of(code.calls.begin(), code.calls.end(), [](FnCall c) {
      return c.fn == Fn::ProgramStop || c.fn == Fn::ProgramOptionalStop || c.fn == Fn::ProgramEnd ||
             c.fn == Fn::ProgramEndInformation;
    });
    if (code.timing != Timing::None && !stops) words.push_back(code.name);
  }
  for (char letter : {'S', 'T'})
    if (has(letter))
      words.push_back(fmt::format("{}{}", letter, shortest(block_.request->words->value[letter_slot(letter)])));
  if (words.empty()) return;
  std::string list = words[0];  // "M13", "M13 and S1200", "M03, S600 and T1"
  for (size_t i = 1; i < words.size(); ++i) list += (i + 1 == words.size() ? " and " : ", ") + words[i];
  report(DiagId::ProfileRunning, 0, list, modal_.dynamics == 0 ? "G27" : "G28");
}

BlockResult Machine::execute(const BlockRequest& request) {
  if (!remaining_paths_) return run_block(request);
  const double from_t = kernel_.clock();
  const AxisValues from = kernel_.position();
  const BlockResult result = run_block(request);
  kernel_.record_move(from_t, from);
  return result;
}

BlockResult Machine::run_block(const BlockRequest& request) {
  block_ = BlockState{};
  block_.request = &request;
  block_.compensation = compensation();
  block_.comp_before = modal_.comp;
  block_.length_before = block_.compensation.length;
  block_.radius_before = block_.compensation.radius;
  auto failed = [&] { return block_.error && stop_on_error_; };
  if (request.dynamic_codes) check_dynamic_codes();
  if (failed()) return BlockResult::Error;
  for (size_t i = 0; i < request.code_count; ++i)
    for (const FnCall& call : sem_.codes[request.codes[i]].calls) {
      block_.offset_load |= call.fn == Fn::OffsetLoad;
      block_.comp_load |= call.fn == Fn::CompLoad;
    }
  // 1. Preparatory functions in written order.
  apply_codes(Timing::None);
  check_profile_rules();
  // 2. Registers.
  registers();
  // G20 G40: the profile's last moves come first, then the compensation ends.
  if (!(gtl_open() && block_has(Fn::GtlClose))) flush_compensation();
  if (failed()) return BlockResult::Error;
  // 3. Auxiliary functions that start before the motion (Table 7), in written order.
  apply_codes(Timing::Before);
  // 4. The action of the block; a corner before it is cut now, one after it waits.
  const bool corner_here = corner_requested();
  if (corner_) corner_codes();
  AxisValues start{};  // of this block's move, when a corner follows it
  if (corner_here) {
    start = motion_event(EventKind::Linear, kernel_.position()).pos;
    kernel_.hold(start);
  }
  const size_t block_from = kernel_.held().size();
  // §8.10: G28, G29, G53 and the cycles move with the compensation vector zeroed.
  const bool zeroed =
      kernel_.path() &&
      (has_axis_word() || (modal_.cycle >= 0 && conv_.cycle_level_word && has(conv_.cycle_level_word))) &&
      (block_.reference_trip || block_.block_offset == 0 || modal_.cycle >= 0);
  if (zeroed) kernel_.path()->suspend();
  action();
  if (zeroed) kernel_.path()->resume();
  if (block_.set_position_after && !block_.error) set_position();
  if (corner_) corner_finish(corner_here, block_from);
  if (corner_here) corner_begin(start);
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
  // The checks found the pairs of codes written as numbers; here those with a code
  // chosen at run time, reported at its word (GE1), as the checks do: at the later.
  const BlockRequest& r = *block_.request;
  auto dynamic = [&](size_t i) { return i < 64 && ((r.dynamic_codes >> i) & 1); };
  auto slot_of = [&](uint16_t code) {
    for (const NumberedCode& n : sem_.numbered)
      if (n.code == code) return static_cast<int>(n.slot);
    return -1;
  };
  for (size_t j = 1; j < r.code_count; ++j)
    for (size_t i = 0; i < j; ++i) {
      if (!dynamic(i) && !dynamic(j)) continue;
      for (const CodePair& p : sem_.incompatible) {
        if (p.a != r.codes[i] || p.b != r.codes[j]) continue;
        // At the later word: a code chosen at run time by its slot, else by its code.
        // A code chosen at run time is found among the words of its slot by its place.
        int nth = 0;
        for (size_t k = 0; k < j; ++k) nth += dynamic(k) && slot_of(r.codes[k]) == slot_of(r.codes[j]);
        RuntimeIssue issue{p.function.empty() ? DiagId::CodesIncompatible : DiagId::MCodeConflict,
                           "",
                           r.source,
                           dynamic(j) ? slot_of(r.codes[j]) : -1,
                           dynamic(j) ? -1 : r.codes[j],
                           dynamic(j) ? nth : 0};
        issue.message =
            p.function.empty()
                ? diag_message(DiagId::CodesIncompatible, sem_.codes[p.a].name, sem_.codes[p.b].name)
                : diag_message(DiagId::MCodeConflict, sem_.codes[p.a].name, sem_.codes[p.b].name, p.function);
        this->issue(issue);
        break;
      }
    }
}

void Machine::apply_codes(Timing timing) {
  const BlockRequest& request = *block_.request;
  for (size_t i = 0; i < request.code_count; ++i) {
    const CodeDesc& code = sem_.codes[request.codes[i]];
    if (code.timing != timing) continue;
    block_.code = request.codes[i];
    // Messages name a three-letter code as it is written: (DTL).
    block_.code_name = code.name;
    if (code.name.empty() || !std::isdigit(static_cast<unsigned char>(code.name.back())))
      block_.code_name = "(" + code.name + ")";
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
  if (block_.operands) return;
  if (block_.gtl_define >= 0) return gtl_define(static_cast<uint16_t>(block_.gtl_define));
  if (block_.comp_before != 0 && modal_.comp != 0 && !block_.error && !rules_->may_stand_in_compensated_path()) return;
  if (modal_.gtl || gtl_open() || block_has(Fn::GtlOpen) || block_has(Fn::GtlClose)) return gtl_block();
  // NC-110's lower-case words (most blocks have none): u v w, and a profile's outside one.
  static const std::bitset<kWordSlots> kLowerCase = [] {
    std::bitset<kWordSlots> b;
    for (char l : std::string_view("uvwplcsrb")) b.set(static_cast<size_t>(letter_slot(l)));
    return b;
  }();
  if ((block_.request->words->present & kLowerCase).any()) {
    // NC-110 §2.9: u v w correct the axis the block programs, not under G41/G42.
    for (int k = 0; k < 3; ++k) {
      const char factor = "uvw"[k];
      if (!has(factor)) continue;
      const int axis = k == 0 ? modal_.plane.u : k == 1 ? modal_.plane.v : modal_.plane.w;
      const std::string shown = std::string(1, factor) + shortest(word(factor));
      if (modal_.comp != 0)
        return report(DiagId::CompPath, factor,
                      fmt::format("{} corrects a point by the tool's radius; G41/G42 does that already: "
                                  "not both (§2.9)",
                                  shown));
      if (axis < 0 || !has(kAxisLetters[axis]))
        return report(DiagId::CompPath, factor,
                      fmt::format("{} corrects {}, the {} of the plane {}, which this block does not program (§2.9)",
                                  shown, axis < 0 ? std::string("the axis") : std::string(1, kAxisLetters[axis]),
                                  k == 0   ? "abscissa"
                                  : k == 1 ? "ordinate"
                                           : "normal",
                                  plane_name(modal_.plane)));
    }
    // Outside a profile (G21 ... G20): the words of its blocks (§2.11.8, §2.11.9).
    for (char l : {'p', 'l', 'c', 's', 'r', 'b'}) {
      if (!has(l) || (l == 'r' && block_has(Fn::MeasureHole))) continue;
      if (l == 'r' || l == 'b') {
        // §2.8.7: a corner of a compensated path, in a block of its own.
        const std::string shown = std::string(1, l) + shortest(word(l));
        if (!rules_->joins_path_corners() || modal_.comp == 0)
          return report(DiagId::CompPath, l,
                        fmt::format("{} joins two moves under G41/G42 or two elements of a GTL profile: "
                                    "neither is in force (§2.8.7)",
                                    shown));
        if (has_axis_word() || has('r') == has('b'))
          return report(DiagId::CompPath, l,
                        fmt::format("{} stands in a block of its own, between the two moves it joins (§2.8.7)", shown));
        if (l == 'b' && word('b') <= 0) return report(DiagId::CompPath, 'b', "a chamfer b is greater than 0 (§2.8.7)");
        return kernel_.path()->corner(l == 'r', word(l), block_.request->source);
      }
      return report(DiagId::GtlProfile, l,
                    fmt::format("{} belongs to a block of a GTL profile; none is open: G21 opens one (§2.11.8)",
                                l == 's' ? std::string("s2") : std::string(1, l) + shortest(word(l))));
    }
  }

  if (virtual_axes_.mode != 0 && virtual_axes_programmed()) return;
  const bool axes = has_axis_word();
  if (axes && (modal_.motion == Fn::MotionArcCw || modal_.motion == Fn::MotionArcCcw)) rules_->check_arc();
  if (block_.measure != Fn::Count) {
    block_.measure == Fn::MotionSkip ? skip() : measure();
    return;
  }
  // A dwell that shares its block with a move: after it (ISO §8.4), or instead of it.
  const bool dwell_after = block_.dwell && axes && rules_->dwells_after_move();
  if (!dwell_after &&
      (block_.dwell || block_.dwell_code || (modal_.motion == Fn::MotionDwell && has(conv_.dwell_word)))) {
    if (axes) report(DiagId::DwellWithMotion, 0);
    dwell();
    return;
  }
  if (block_.set_position) {
    // ISO §8.19: G92 written after a motion shifts once the motion is made.
    for (char letter : conv_.axes)
      block_.set_position_after = block_.set_position_after || has_slot(second_slot(letter));
    if (!block_.set_position_after) {
      set_position();
      return;
    }
  }
  if (block_.offset_load) {
    load_offset();
    return;
  }
  if (block_.comp_load) {
    load_compensation();
    return;
  }
  if (block_.reference) {
    reference_approach();
    return;
  }
  if (block_.reference_trip) {
    if (block_.reference_trip == 2)
      reference_leave();
    else
      reference_return(block_.reference_trip == 1
                           ? config_.reference_position
                           : config_.other_references[static_cast<size_t>(block_.reference_trip - 3)]);
    return;
  }
  if (block_.local_offset) {
    set_local_offset();
    return;
  }
  if (block_.data_set) {
    data_set();
    return;
  }
  if (block_.scaling_on || block_.rotation_on) {
    block_.scaling_on ? scaling_on() : rotation_on();
    return;
  }

  if (modal_.cycle >= 0) {
    const bool drills = axes || (conv_.cycle_level_word && has(conv_.cycle_level_word));
    cycles_->block(drills);
    if (block_.dwell_end) dwell_seconds(timer_dwell());
    return;
  }
  // An arc with its centre and no axis word is a full circle (NC-110 §2.8.1.4; GOST
  // S-9.4, ISO: the end point is the start point).
  const bool circle = (modal_.motion == Fn::MotionArcCw || modal_.motion == Fn::MotionArcCcw) &&
                      (has('I') || has('J') || (conv_.centre_words == CentreWords::PerAxis && has('K')));
  if (!axes && !circle) {
    if (parabola_middle_) {
      report(DiagId::ParabolaPair, 0, "this block has no dimension word");
      parabola_middle_.reset();
    }
    if (block_.spindle_sync) report(DiagId::SpindleSync, 0, "its block moves no axis");
    if (block_.dwell_end) dwell_seconds(timer_dwell());
    return;
  }
  // NC-110 §2.8.16: G35 starts the move at the spindle's zero mark.
  if (block_.spindle_sync) {
    if (modal_.motion == Fn::MotionRapid)
      report(DiagId::SpindleSync, 0, "G00 is the active motion");
    else if (std::abs(modal_.spindle) != 1)
      report(DiagId::SpindleSync, 0, "the spindle is not turning");
    else
      path_event(3);
  }
  AxisValues t = target();
  // NC-110 §2.8.15: under G27/G28 a clamped axis cannot move in a feed move.
  if ((modal_.dynamics == 0 || modal_.dynamics == 1) && modal_.motion != Fn::MotionRapid && locked_)
    for (int i = 0; i < kAxisCount; ++i)
      if ((locked_ & (1u << i)) && std::fabs(t[i] - kernel_.position()[i]) > 1e-9)
        report(DiagId::AxisClamped, kAxisLetters[i], std::string(1, kAxisLetters[i]));
  // NC-110 §2.8.1.3: after (BSP) the first G00/G01 block leads in to the spline's
  // start; one after G06 points leads out, and the spline is cut then.
  const bool straight = modal_.motion == Fn::MotionRapid || modal_.motion == Fn::MotionLinear;
  if (spline_.active && straight && !spline_.lead_in) {
    spline_.lead_in = true;
    spline_.lead_in_from = kernel_.position();
    spline_.sources = {block_.request->source};
    spline_.points = {t};
  } else if (spline_.active && straight && spline_.points.size() == 1) {
    report(DiagId::SplineStructure, 0, "the block after the lead-in is G06 with the spline's first point");
  } else if (spline_.active && straight && spline_.points.size() > 1) {
    spline_finish(t);
  }
  switch (modal_.motion) {
    case Fn::MotionRapid: rapid(t); break;
    case Fn::MotionLinear: linear(t); break;
    case Fn::MotionArcCw: arc(t, true); break;
    case Fn::MotionArcCcw: arc(t, false); break;
    case Fn::MotionParabola: parabola(t); break;
    case Fn::MotionThread:
    case Fn::MotionThreadIncreasing:
    case Fn::MotionThreadDecreasing: thread(t); break;
    case Fn::MotionThreadVariable: thread_variable(t); break;
    case Fn::MotionSpline: spline_point(t); break;
    default:
      report(DiagId::NoMotionMode, 0, motion_name_);
      move_to(t);
      break;
  }
  if (block_.dwell_end) dwell_seconds(timer_dwell());
  if (dwell_after) dwell();
}

void Machine::finish() {
  for (const FnCall& call : block_.restore) apply(call, Scope::Modal, true);
  flush_compensation();
  // A continuous profile runs until a G00 move, a G09 or G04 block or G29 (§2.8.5).
  if (block_.moved && (modal_.dynamics == 0 || modal_.dynamics == 1)) profile_running_ = true;
  // A G00 block ends it even where it does not move: the NC decelerates for it.
  const bool rapid_block = modal_.motion == Fn::MotionRapid && has_axis_word();
  if (block_.rapid_moved || rapid_block || block_.decelerate || block_.dwell_end) profile_running_ = false;
  if (block_.stop) {
    Event e{EventKind::Stop};
    e.n = block_.stop - 1;
    emit(e);
  }
  if (block_.end || block_.end_information) {
    // Table 8: M02/M30 stop the spindle and feed and switch coolant off, then the NC
    // returns to its initial state (§8), which the trace shows as it changes.
    if (parabola_middle_) report(DiagId::ParabolaPair, 0, "the program ended");
    if (spline_.active) report(DiagId::SplineStructure, 0, "the program ended inside a spline: (ESP) is missing");
    if (corner_) {
      issue({DiagId::CornerForm,
             diag_message(DiagId::CornerForm, "the program ends: a feed move must follow a chamfer or fillet (E-04)"),
             corner_->source, corner_->slot, -1});
      release();
    }
    if (kernel_.path()) kernel_.path()->finish();
    apply({Fn::SpindleStop}, Scope::Modal, true);
    apply({Fn::CoolantOff}, Scope::Modal, true);
    const ResetState before{modal_,     kernel_.frame(), kernel_.position_offset(), kernel_.envelope(),
                            tolerance_, turning_};
    reset_state();
    emit_reset(before);
    Event e{EventKind::End};
    e.n = block_.end_information;
    emit(e);
  }
  if (block_.error) return;
  std::bitset<kWordSlots> unused = block_.request->words->present & ~block_.used;
  for (int slot = 0; slot < kWordSlots && unused.any(); ++slot)
    if (unused.test(slot)) {
      report_slot(DiagId::WordUnused, slot, slot_text(slot));
      unused.reset(slot);
    }
}

void Machine::emit_reset(const ResetState& before) {
  auto changed = [&](EventKind kind, int n) {
    Event e{kind};
    e.n = n;
    emit(e);
  };
  const Modal& was = before.modal;
  if (before.turning) changed(EventKind::Configuration, 0);  // NC-110 §2.13.5.4: milling again
  if (was.inch != modal_.inch) changed(EventKind::Units, modal_.inch);
  if (was.plane != modal_.plane) plane_event();
  if (was.feed_mode != modal_.feed_mode) changed(EventKind::FeedMode, modal_.feed_mode);
  if (was.constant_surface != modal_.constant_surface) changed(EventKind::SpindleMode, modal_.constant_surface);
  if (was.dynamics != modal_.dynamics && modal_.dynamics >= 0) path_event(4 + modal_.dynamics);
  if (was.spindle_range != modal_.spindle_range) changed(EventKind::SpindleRange, modal_.spindle_range);
  if (was.coolant3 || was.coolant4) changed(EventKind::Coolant, 5);
  if (was.diameter != modal_.diameter) changed(EventKind::Diameter, modal_.diameter);
  if (was.feed_reduced != modal_.feed_reduced) changed(EventKind::FeedReduction, modal_.feed_reduced);
  flush_compensation();
  if (was.work_offset != modal_.work_offset)
    apply({Fn::WorkOffset, static_cast<uint16_t>(modal_.work_offset)}, Scope::Modal, true);
  if (before.position_offset != kernel_.position_offset()) {
    Event e{EventKind::PositionOffset};
    emit(e);
  }
  // Origins set per axis (NC-110) come back to origin 0; GOST shows its offsets' events.
  std::array<int, kAxisCount> uniform{};
  uniform.fill(was.work_offset);
  AxisValues shifted = before.frame.shift;  // G92 and (ISO) G52 make the position offset
  for (int i = 0; i < kAxisCount; ++i) shifted[i] += before.frame.local[i];
  if (before.frame.base != uniform || shifted != before.position_offset) origin_event();
  if (before.frame.transformed()) transform_event();
  // NC-110 §2.13.5: RESET cancels the working limits and the zones and gives the axes
  // the machine's tolerance again; no axis stays clamped.
  for (size_t z = 0; z < before.envelope.zones.size(); ++z)
    if (before.envelope.zones[z].active) {
      Event e{EventKind::Zone};
      e.rotation = static_cast<int>(z + 1);
      e.n = 0;
      emit(e);
    }
  if (before.envelope.any_limit()) emit(Event{EventKind::Limits});
  Event tolerance{EventKind::Tolerance};
  for (int a = 0; a < kAxisCount; ++a)
    if (before.tolerance[a] != 0) {
      tolerance.n |= 1 << a;
      tolerance.pos[a] = program_axis(a, config_.axes[static_cast<size_t>(a)].tolerance);
    }
  if (tolerance.n) emit(tolerance);
  if (was.clamp == 1) changed(EventKind::Clamp, 0);
  if (was.rotary_clamp == 1) changed(EventKind::Clamp, 2);
}

void Machine::end_of_unit(uint32_t source) {
  gtl_unit_end();
  if (corner_) {
    issues_.issue(
        {DiagId::CornerForm,
         diag_message(DiagId::CornerForm, "the program ends: a feed move must follow a chamfer or fillet (E-04)"),
         corner_->source, corner_->slot, -1});
    release();
  }
  if (!parabola_middle_ && !spline_.active) return;
  BlockWords none;
  BlockRequest request{nullptr, 0, &none, source};
  block_ = BlockState{};
  block_.request = &request;
  if (parabola_middle_) report(DiagId::ParabolaPair, 0, "the program ended");
  if (spline_.active) report(DiagId::SplineStructure, 0, "the program ended inside a spline: (ESP) is missing");
  parabola_middle_.reset();
  block_ = BlockState{};
}

// An event of text the program gave (a comment, a message, an ASSET statement...).
void Machine::text_event(EventKind kind, const std::string& text, uint32_t source, int n, double a) {
  Event e{kind};
  e.text = text;
  e.n = n;
  e.a = a;
  e.source = source;
  kernel_.out(e);
}

void Machine::comment(const std::string& text, uint32_t source) { text_event(EventKind::Comment, text, source); }

void Machine::block_start(uint32_t source) {
  Event e{EventKind::Block};
  e.source = source;
  kernel_.out(e);
}

bool Machine::asset_done(const std::string& what, int code, uint32_t source) {
  text_event(EventKind::Asset, what, source, code);
  system_[SysRef{SysVar::AssetStatus, 0}.packed()] = code;
  return code == 0 || system({SysVar::AssetErrorMode, 0}) == 1;
}

void Machine::operator_input(const std::string& shown, double answer, uint32_t source) {
  text_event(EventKind::Input, shown, source, 0, answer);
}

void Machine::operator_input(const std::string& shown, const std::string& answer, uint32_t source) {
  text_event(EventKind::Input, shown + '\n' + answer, source, 1);
}

void Machine::screen_event(const std::string& what, uint32_t source) { text_event(EventKind::Screen, what, source); }

void Machine::end_program(uint32_t source) {
  BlockWords none;
  BlockRequest request{nullptr, 0, &none, source};
  block_ = BlockState{};
  block_.request = &request;
  block_.end = true;
  finish();
  block_ = BlockState{};
}

void Machine::sync_event(const std::string& what, uint32_t source) { text_event(EventKind::Sync, what, source); }

void Machine::message(const std::string& text, uint32_t source) { text_event(EventKind::Message, text, source); }

}  // namespace ncc
