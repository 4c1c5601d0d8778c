#include "host_sink.h"

#include <algorithm>

namespace ncc::api {

namespace {

Axes axes_of(const AxisValues& v) {
  Axes a;
  std::copy(v.begin(), v.end(), a.begin());
  return a;
}

Plane plane_of(const ncc::Plane& p) { return {p.u, p.v, p.w}; }

// The events that set a mode a restart must tell the host, by the mode they set
// (the spindle's three share one).
std::optional<int> mode_of(EventKind k) {
  switch (k) {
    case EventKind::SpindleOn:
    case EventKind::SpindleStop:
    case EventKind::SpindleOrient: return static_cast<int>(EventKind::SpindleOn);
    case EventKind::Units:
    case EventKind::Plane:
    case EventKind::FeedMode:
    case EventKind::FeedRate:
    case EventKind::PathMode:
    case EventKind::SpindleMode:
    case EventKind::SpindleSpeed:
    case EventKind::SelectTool:
    case EventKind::ChangeTool:
    case EventKind::ToolLengthOffset:
    case EventKind::CutterComp:
    case EventKind::WorkOffset:
    case EventKind::PositionOffset: return static_cast<int>(k);
    default: return std::nullopt;
  }
}

// The MachineInterface call an event becomes (for a refusal's message).
std::string call_name(EventKind k) {
  switch (k) {
    case EventKind::Rapid: return "straight_traverse";
    case EventKind::Linear: return "straight_feed";
    case EventKind::Arc: return "arc_feed";
    case EventKind::SpindleOn: return "spindle_start";
    case EventKind::SelectTool: return "tool_select";
    case EventKind::ChangeTool: return "tool_change";
    case EventKind::CutterComp: return "cutter_compensation";
    case EventKind::PathMode: return "path_mode";
    case EventKind::End: return "program_end";
    case EventKind::Thread:
    case EventKind::Parabola:
    case EventKind::Spline:
    case EventKind::Probe:
    case EventKind::Dwell:
    case EventKind::Units:
    case EventKind::Plane:
    case EventKind::FeedMode:
    case EventKind::FeedRate:
    case EventKind::SpindleMode:
    case EventKind::SpindleSpeed:
    case EventKind::SpindleStop:
    case EventKind::SpindleOrient:
    case EventKind::ToolLengthOffset:
    case EventKind::WorkOffset:
    case EventKind::PositionOffset:
    case EventKind::Coolant:
    case EventKind::Comment:
    case EventKind::Message:
    case EventKind::Stop: return event_name(k);
    default: return "other (" + event_name(k) + ")";
  }
}

}  // namespace

FeedMode feed_mode_of(int n) {
  return n == 0 ? FeedMode::InverseTime : n == 2 ? FeedMode::PerRevolution : FeedMode::PerMinute;
}

CutterSide cutter_side_of(int n) { return n == 1 ? CutterSide::Left : n == 2 ? CutterSide::Right : CutterSide::Off; }

const Block& HostSink::block(const Event& e) {
  if (block_of_ && block_of_->first == e.source && block_of_->second == e.process) return block_;
  block_of_ = {e.source, e.process};
  block_ = Block{};
  block_.index = e.source;
  block_.process = e.process;
  if (e.source < map_.size()) {
    const SourceBlock b = map_.block(e.source);
    block_.file = b.file < map_.files.size() ? std::string_view(map_.files[b.file]) : std::string_view();
    block_.line = b.line;
    block_.column = b.col;
    if (b.has_number) block_.number = b.number;
    block_.main_block = b.main_block;
  }
  return block_;
}

void HostSink::event(const Event& e) {
  if (refusal_) return;
  if (muted_) {
    ++seq_;
    if (e.kind == EventKind::Coolant) {
      if (e.n == 0) coolants_.clear();
      coolants_.push_back({seq_, e});
    } else if (const std::optional<int> mode = mode_of(e.kind)) {
      modes_[*mode] = {seq_, e};
    }
    return;
  }
  const Reply reply = call(e, block(e));
  if (!reply.accepted()) refusal_ = Refusal{e.source, call_name(e.kind), reply.reason()};
}

void HostSink::mute() { muted_ = true; }

void HostSink::unmute() {
  muted_ = false;
  std::vector<std::pair<uint64_t, Event>> kept = coolants_;
  for (const auto& [mode, event] : modes_) kept.push_back(event);
  std::sort(kept.begin(), kept.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  modes_.clear();
  coolants_.clear();
  for (const auto& [seq, e] : kept) event(e);
}

void HostSink::reset() {
  refusal_.reset();
  muted_ = false;
  modes_.clear();
  coolants_.clear();
}

Reply HostSink::call(const Event& e, const Block& b) {
  MachineInterface& h = host_;
  switch (e.kind) {
    case EventKind::Rapid: return h.straight_traverse(b, axes_of(e.pos));
    case EventKind::Linear: return h.straight_feed(b, axes_of(e.pos));
    case EventKind::Arc: {
      Arc arc;
      arc.end = axes_of(e.pos);
      arc.plane = plane_of(e.plane);
      arc.centre_first = e.centre[0];
      arc.centre_second = e.centre[1];
      arc.rotation = e.rotation;
      arc.radius = e.a;
      arc.sweep = e.b;
      return h.arc_feed(b, arc);
    }
    case EventKind::Thread: return h.thread(b, axes_of(e.pos), e.a, e.b, e.c);
    case EventKind::Parabola: return h.parabola(b, axes_of(e.pos), axes_of(e.control));
    case EventKind::Spline: return h.spline(b, axes_of(e.pos), axes_of(e.control), axes_of(e.control2));
    case EventKind::Probe: return h.probe(b, axes_of(e.pos), e.n != 0);
    case EventKind::Dwell: return h.dwell(b, e.a);
    case EventKind::Units: return h.units(b, e.n ? Units::Inches : Units::Millimetres);
    case EventKind::Plane: return h.plane(b, plane_of(e.plane));
    case EventKind::FeedMode: return h.feed_mode(b, feed_mode_of(e.n));
    case EventKind::FeedRate: return h.feed_rate(b, e.a);
    case EventKind::PathMode: return h.path_mode(b, static_cast<PathMode>(e.n));
    case EventKind::SpindleMode: return h.spindle_mode(b, e.n ? SpindleMode::ConstantSurfaceSpeed : SpindleMode::Rpm);
    case EventKind::SpindleSpeed: return h.spindle_speed(b, e.a);
    case EventKind::SpindleOn: return h.spindle_start(b, e.n > 0 ? Direction::Clockwise : Direction::CounterClockwise);
    case EventKind::SpindleStop: return h.spindle_stop(b);
    case EventKind::SpindleOrient: return h.spindle_orient(b, e.a);
    case EventKind::SelectTool: return h.tool_select(b, e.n);
    case EventKind::ChangeTool: return h.tool_change(b, e.n);
    case EventKind::ToolLengthOffset: return h.tool_length_offset(b, axes_of(e.pos));
    case EventKind::CutterComp: return h.cutter_compensation(b, cutter_side_of(e.n), e.a);
    case EventKind::WorkOffset: return h.work_offset(b, e.n, axes_of(e.pos));
    case EventKind::PositionOffset: return h.position_offset(b, axes_of(e.pos));
    case EventKind::Coolant: return h.coolant(b, static_cast<Coolant>(e.n));
    case EventKind::Comment: return h.comment(b, e.text);
    case EventKind::Message: return h.message(b, e.text);
    case EventKind::Stop: return h.stop(b, static_cast<StopKind>(e.n));
    case EventKind::End: return h.program_end(b, e.n != 0);
    default: return h.other(b, event_name(e.kind), event_json(e, axes_));
  }
}

}  // namespace ncc::api
