#include "frame.h"

#include <cmath>
#include <numbers>

namespace ncc {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

}  // namespace

AxisValues Frame::transform(AxisValues q, const Plane& plane) const {
  for (int i = 0; i < kAxisCount; ++i) q[i] = scale_centre[i] + (q[i] - scale_centre[i]) * factor(i);
  if (rotation != 0) {
    const double c = std::cos(rotation * kDegree), s = std::sin(rotation * kDegree);
    const double x = q[plane.u] - rotation_centre[plane.u], y = q[plane.v] - rotation_centre[plane.v];
    q[plane.u] = rotation_centre[plane.u] + x * c - y * s;
    q[plane.v] = rotation_centre[plane.v] + x * s + y * c;
  }
  return q;
}

AxisValues Frame::untransform(AxisValues q, const Plane& plane) const {
  if (rotation != 0) {
    const double c = std::cos(rotation * kDegree), s = std::sin(rotation * kDegree);
    const double x = q[plane.u] - rotation_centre[plane.u], y = q[plane.v] - rotation_centre[plane.v];
    q[plane.u] = rotation_centre[plane.u] + x * c + y * s;
    q[plane.v] = rotation_centre[plane.v] - x * s + y * c;
  }
  for (int i = 0; i < kAxisCount; ++i) q[i] = scale_centre[i] + (q[i] - scale_centre[i]) / factor(i);
  return q;
}

void Frame::clear_scaling() {
  scale.fill(1);
  mirror.fill(false);
  scale_centre = {};
}

void Frame::clear_rotation() {
  rotation = 0;
  rotation_centre = {};
}

}  // namespace ncc
