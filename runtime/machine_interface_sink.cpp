#include "machine_interface_sink.h"

#include <iterator>

namespace ncc {

namespace api {
// The key function: the interface's vtable and typeinfo are made here, in the
// runtime that libncc.so is built from and exports them.
MachineInterface::~MachineInterface() = default;
}  // namespace api

namespace {

api::Plane plane_of(const Plane& p) { return {p.u, p.v, p.w}; }

// The MachineInterface call an event becomes (for a refusal's message).
std::string call_name(const Event& e) {
  constexpr const char* names[] = {"units",
                                   "plane",
                                   "feed_mode",
                                   "feed_rate",
                                   "spindle_mode",
                                   "spindle_speed",
                                   "spindle_start",
                                   "spindle_stop",
                                   "spindle_orient",
                                   "straight_traverse",
                                   "straight_feed",
                                   "arc_feed",
                                   "parabola",
                                   "thread",
                                   "dwell",
                                   "tool_select",
                                   "tool_change",
                                   "tool_length_offset",
                                   "cutter_compensation",
                                   "work_offset",
                                   "position_offset",
                                   "coolant",
                                   "clamp",
                                   "override_enable",
                                   "spindle_hold",
                                   "path_mode",
                                   "comment",
                                   "message",
                                   "stop",
                                   "operator_move",
                                   "program_end",
                                   "origin",
                                   "transform",
                                   "tolerance",
                                   "limits",
                                   "zone",
                                   "configuration",
                                   "probe",
                                   "spline",
                                   "spindle_range",
                                   "part_change",
                                   "offset_load",
                                   "diameter",
                                   "feed_reduction",
                                   "aux",
                                   "block_start",
                                   "comp_load",
                                   "asset",
                                   "input",
                                   "screen",
                                   "sync",
                                   "graphic",
                                   "tooling",
                                   "virtual_axes"};
  static_assert(std::size(names) == static_cast<size_t>(EventKind::Virtual) + 1, "one call per event kind");
  if (e.kind == EventKind::Input && e.n) return "input_text";
  return names[static_cast<int>(e.kind)];
}

}  // namespace

api::FeedMode feed_mode_of(int n) {
  return n == 0 ? api::FeedMode::InverseTime : n == 2 ? api::FeedMode::PerRevolution : api::FeedMode::PerMinute;
}

api::CutterSide cutter_side_of(int n) {
  return n == 1 ? api::CutterSide::Left : n == 2 ? api::CutterSide::Right : api::CutterSide::Off;
}

api::Block block_of(const SourceMap& map, uint32_t source, uint8_t process) {
  api::Block b;
  b.index = source;
  b.process = process;
  const SourceBlock s = source < map.size() ? map.block(source) : SourceBlock{};
  if (s.file < map.files.size()) b.file = map.files[s.file];
  b.main_file = s.file == 0;
  b.line = s.line;
  b.column = s.col;
  if (s.has_number) b.number = s.number;
  b.main_block = s.main_block;
  return b;
}

const api::Block& MachineInterfaceSink::block(const Event& e) {
  if (block_of_ && block_of_->first == e.source && block_of_->second == e.process) return block_;
  block_of_ = {e.source, e.process};
  if (places_) {
    block_ = block_of(map_, e.source, e.process);
  } else {
    block_.index = e.source;
    block_.process = e.process;
  }
  return block_;
}

void MachineInterfaceSink::event(const Event& e) {
  if (refusal_) return;
  const api::Reply reply = call(e, block(e));
  if (!reply.accepted()) refusal_ = Refusal{e.source, call_name(e), reply.reason()};
}

api::Reply MachineInterfaceSink::call(const Event& e, const api::Block& b) {
  api::MachineInterface& m = machine_;
  const bool on = e.n != 0;
  switch (e.kind) {
    case EventKind::Units: return m.units(b, on ? api::Units::Inches : api::Units::Millimetres);
    case EventKind::Plane: return m.plane(b, plane_of(e.plane));
    case EventKind::FeedMode: return m.feed_mode(b, feed_mode_of(e.n));
    case EventKind::FeedRate: return m.feed_rate(b, e.a);
    case EventKind::SpindleMode:
      return m.spindle_mode(b, on ? api::SpindleMode::ConstantSurfaceSpeed : api::SpindleMode::Rpm);
    case EventKind::SpindleSpeed: return m.spindle_speed(b, e.a);
    case EventKind::SpindleOn:
      return m.spindle_start(b, e.n > 0 ? api::Direction::Clockwise : api::Direction::CounterClockwise);
    case EventKind::SpindleStop: return m.spindle_stop(b);
    case EventKind::SpindleOrient: return m.spindle_orient(b, e.a);
    case EventKind::Rapid: return m.straight_traverse(b, e.pos, e.moved);
    case EventKind::Linear: return m.straight_feed(b, e.pos, e.moved);
    case EventKind::Arc: {
      api::Arc arc;
      arc.end = e.pos;
      arc.moved = e.moved;
      arc.plane = plane_of(e.plane);
      arc.centre_first = e.centre[0];
      arc.centre_second = e.centre[1];
      arc.rotation = e.rotation;
      arc.radius = e.a;
      arc.sweep = e.b;
      return m.arc_feed(b, arc);
    }
    case EventKind::Parabola: return m.parabola(b, e.pos, e.control);
    case EventKind::Thread: return m.thread(b, e.pos, e.a, e.b, e.c);
    case EventKind::Dwell: return m.dwell(b, e.a);
    case EventKind::SelectTool: return m.tool_select(b, e.n);
    case EventKind::ChangeTool: return m.tool_change(b, e.n);
    case EventKind::ToolLengthOffset: return m.tool_length_offset(b, e.pos);
    case EventKind::CutterComp: return m.cutter_compensation(b, cutter_side_of(e.n), e.a);
    case EventKind::WorkOffset: return m.work_offset(b, e.n, e.pos);
    case EventKind::PositionOffset: return m.position_offset(b, e.pos);
    case EventKind::Coolant: return m.coolant(b, static_cast<api::Coolant>(e.n));
    case EventKind::Clamp: return m.clamp(b, static_cast<api::Clamp>(e.n));
    case EventKind::Override: return m.override_enable(b, on);
    case EventKind::SpindleHold: return m.spindle_hold(b, on);
    case EventKind::PathMode: return m.path_mode(b, static_cast<api::PathMode>(e.n));
    case EventKind::Comment: return m.comment(b, e.text);
    case EventKind::Message: return m.message(b, e.text);
    case EventKind::Stop: return m.stop(b, static_cast<api::StopKind>(e.n));
    case EventKind::OperatorMove: return m.operator_move(b, e.pos);
    case EventKind::End: return m.program_end(b, on);
    case EventKind::Origin: return m.origin(b, e.pos);
    case EventKind::Transform: return m.transform(b, e.a, static_cast<api::AxisMask>(e.n), e.pos);
    case EventKind::Tolerance: return m.tolerance(b, static_cast<api::AxisMask>(e.n), e.pos);
    case EventKind::Limits: return m.limits(b, static_cast<api::AxisMask>(e.n), e.pos, e.control);
    case EventKind::Zone:
      return m.zone(b, e.rotation, static_cast<api::ZoneState>(e.n), plane_of(e.plane), e.pos, e.control);
    case EventKind::Configuration:
      return m.configuration(b, on ? api::Configuration::Turning : api::Configuration::Milling);
    case EventKind::Probe: return m.probe(b, e.pos, on);
    case EventKind::Spline: return m.spline(b, e.pos, e.control, e.control2);
    case EventKind::SpindleRange: return m.spindle_range(b, e.n);
    case EventKind::PartChange: return m.part_change(b);
    case EventKind::OffsetLoad: return m.offset_load(b, e.n, e.pos);
    case EventKind::Diameter: return m.diameter(b, on);
    case EventKind::FeedReduction: return m.feed_reduction(b, on);
    case EventKind::Aux: return m.aux(b, e.text);
    case EventKind::Block: return m.block_start(b);
    case EventKind::CompLoad: return m.comp_load(b, e.n, e.a, e.b);
    case EventKind::Asset: return m.asset(b, e.text, e.n);
    case EventKind::Input: {
      // A text answer follows the prompt after a line break.
      if (!on) return m.input(b, e.text, e.a);
      const size_t cut = e.text.rfind('\n');
      const std::string_view text = e.text;
      return m.input_text(b, text.substr(0, cut), text.substr(cut + 1));
    }
    case EventKind::Screen: return m.screen(b, e.text);
    case EventKind::Sync: return m.sync(b, e.text);
    case EventKind::Graphic: return m.graphic(b, e.text);
    case EventKind::Tooling: return m.tooling(b, static_cast<api::ToolingChange>(e.n), e.text);
    case EventKind::Virtual: return m.virtual_axes(b, e.text);
  }
  return {};
}

}  // namespace ncc
