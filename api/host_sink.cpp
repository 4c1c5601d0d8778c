#include "host_sink.h"

#include <algorithm>

namespace ncc::api {

namespace {

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

}  // namespace

void HostSink::event(const Event& e) {
  if (!muted_) return calls_.event(e);
  ++seq_;
  if (e.kind == EventKind::Coolant) {
    if (e.n == 0) coolants_.clear();
    coolants_.push_back({seq_, e});
  } else if (const std::optional<int> mode = mode_of(e.kind)) {
    modes_[*mode] = {seq_, e};
  }
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
  calls_.forget_refusal();
  muted_ = false;
  modes_.clear();
  coolants_.clear();
}

}  // namespace ncc::api
