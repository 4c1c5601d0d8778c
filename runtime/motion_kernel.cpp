#include "motion_kernel.h"

#include <cmath>

namespace ncc {

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

}  // namespace ncc
