#include "motion_kernel.h"

#include <cmath>

namespace ncc {

MotionKernel::MotionKernel(const MachineConfig& config, TraceSink& trace, std::unique_ptr<CutterPath> path)
    : config_(config), trace_(trace), events_wanted_(trace.wants_events()), path_(std::move(path)) {}

MotionKernel::~MotionKernel() = default;

void MotionKernel::record_move(double from_t, const AxisValues& from) {
  if (clock_ <= from_t) return;
  constexpr size_t kMoves = 256;  // more than the look-ahead runs ahead
  if (moves_.size() == kMoves) moves_.pop_front();
  moves_.push_back({from_t, clock_, from, position_});
}

double MotionKernel::remaining_at(int axis, double seconds) const {
  for (auto it = moves_.rbegin(); it != moves_.rend(); ++it) {
    if (seconds >= it->to_t) return 0;
    if (seconds >= it->from_t) {
      const double done = (seconds - it->from_t) / (it->to_t - it->from_t);
      return std::fabs(it->to[axis] - it->from[axis]) * (1 - done);
    }
  }
  return 0;
}

double MotionKernel::offset_value(int offset, int axis) const {
  auto it = offsets_.find(offset);
  if (it == offsets_.end()) return 0;
  double v = it->second.values[axis];
  const bool linear = config_.axes[static_cast<size_t>(axis)].kind == AxisKind::Linear;
  return it->second.inch && linear ? v * 25.4 : v;
}

void MotionKernel::refresh_origins() {
  for (int i = 0; i < kAxisCount; ++i) base_origin_[i] = offset_value(frame_.base[i], i);
}

void MotionKernel::reset_coordinates() {
  frame_ = Frame{};
  refresh_origins();
  position_offset_ = {};
  local_offsets_.clear();
}

void MotionKernel::select_work_offset(int n) {
  frame_.base.fill(n);
  const auto local = local_offsets_.find(n);
  frame_.local = local != local_offsets_.end() ? local->second : AxisValues{};
  refresh_origins();
}

AxisValues MotionKernel::origins() const {
  AxisValues o{};
  for (int i = 0; i < kAxisCount; ++i) o[i] = origin(i);
  return o;
}

AxisValues MotionKernel::shown_origins() const { return config_.trace_machine_frame ? AxisValues{} : origins(); }

AxisValues MotionKernel::frame_offset(int work_offset) const {
  AxisValues off{};
  for (int i = 0; i < kAxisCount; ++i) off[i] = offset_value(work_offset, i) + frame_.shift[i] + frame_.local[i];
  return off;
}

AxisValues MotionKernel::block_origins(int origin) const {
  if (origin == kMachineZero) return {};
  if (origin > 0) return frame_offset(origin);
  return origins();
}

AxisValues MotionKernel::to_machine(const AxisValues& p, const Plane& plane, int origin) const {
  AxisValues q = transforms(origin) ? frame_.transform(p, plane) : p;
  const AxisValues off = block_origins(origin);
  for (int i = 0; i < kAxisCount; ++i) q[i] += off[i];
  return q;
}

AxisValues MotionKernel::to_frame(const AxisValues& m, const Plane& plane, int origin) const {
  const AxisValues off = block_origins(origin);
  AxisValues q{};
  for (int i = 0; i < kAxisCount; ++i) q[i] = m[i] - off[i];
  return transforms(origin) ? frame_.untransform(q, plane) : q;
}

double MotionKernel::in_units(int axis, double v, bool inch) const {
  const AxisConfig& a = config_.axes[static_cast<size_t>(axis)];
  switch (a.kind) {
    case AxisKind::Linear: return inch ? v / 25.4 : v;
    case AxisKind::Indexing: return v / a.index_step;
    default: return v;
  }
}

AxisValues MotionKernel::in_units(AxisValues v, bool inch) const {
  for (int i = 0; i < kAxisCount; ++i) v[i] = in_units(i, v[i], inch);
  return v;
}

Event MotionKernel::motion_event(EventKind kind, const AxisValues& t, bool inch) const {
  // The trace shows positions from the active origin (docs/trace.md).
  Event e{kind};
  AxisValues off = shown_origins();
  for (int i = 0; i < kAxisCount; ++i) e.pos[i] = t[i] - off[i];
  for (int i = 0; i < kAxisCount; ++i)
    if (t[i] != position_[i]) e.moved |= static_cast<uint16_t>(1u << i);
  e.pos = in_units(e.pos, inch);
  // An endless rotary axis shows 0..359.9999 however far it has turned (NC-110 §2.8.4).
  for (int i = 0; i < kAxisCount; ++i)
    if (config_.axes[static_cast<size_t>(i)].endless && config_.axes[static_cast<size_t>(i)].kind == AxisKind::Rotary) {
      e.pos[i] = std::fmod(e.pos[i], 360.0);
      if (e.pos[i] < 0) e.pos[i] += 360;
      if (e.pos[i] >= 359.99995) e.pos[i] = 0;  // shows as 0, not 360.0000
    }
  return e;
}

void MotionKernel::to_path(const Event& e, const AxisValues* start) {
  if (!path_) return trace_.event(e);
  if (is_move(e.kind) && !path_->passes_moves() && trace_.wants_programmed()) trace_.programmed(e);
  path_->event(e, start);
}

void MotionKernel::pass_on(size_t count) {
  // Each held move starts where the one before it ends.
  AxisValues at = hold_start_;
  for (size_t i = 0; i < count; ++i) {
    const Event& e = held_[i];
    const bool move = is_move(e.kind);
    to_path(e, move ? &at : nullptr);
    if (move) at = e.pos;
  }
  hold_start_ = at;
  held_.erase(held_.begin(), held_.begin() + static_cast<std::ptrdiff_t>(count));
}

void MotionKernel::release() {
  holding_ = false;
  pass_on(held_.size());
}

}  // namespace ncc
