// Where a program's coordinates are on the machine: per axis an origin (a work
// offset, a shift and a local zero), then scale and mirror about a centre, and a
// rotation in the plane about another (NC-110 §2.13.1 turns about the origin; ISO
// G51 and G68 have centres of their own).
#pragma once

#include <array>

#include "contract/machine_config.h"

namespace ncc {

struct Frame {
  std::array<int, kAxisCount> base{};  // the work offset (origin) of each axis
  AxisValues shift{};                  // G92, NC-110 UOT/UIO: mm, degrees
  AxisValues local{};                  // ISO G52: the local zero of the active work offset
  AxisValues scale;
  std::array<bool, kAxisCount> mirror{};
  double rotation = 0;  // degrees, counter-clockwise in the plane
  // The centres of scaling and rotation, program coordinates.
  AxisValues scale_centre{}, rotation_centre{};

  Frame() { scale.fill(1); }

  bool transformed() const {  // hot: every conversion asks
    if (rotation != 0) return true;
    for (int i = 0; i < kAxisCount; ++i)
      if (mirror[i] || scale[i] != 1) return true;
    return false;
  }
  // An axis' scale, negative when mirrored.
  double factor(int axis) const { return mirror[axis] ? -scale[axis] : scale[axis]; }
  // A program position scaled, mirrored and turned in `plane`, and back; origins are
  // not added (the block decides which apply).
  AxisValues transform(AxisValues p, const Plane& plane) const;
  AxisValues untransform(AxisValues q, const Plane& plane) const;
  void clear_scaling();   // no scale, no mirror
  void clear_rotation();  // no rotation
};

}  // namespace ncc
