// The machine as the run sees it: offsets, tools and limits from the machine profile.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace ncc {

// X Y Z A B C U V W in LinuxCNC's order, then NC-110's further axes P Q D.
constexpr int kAxisCount = 12;
using AxisValues = std::array<double, kAxisCount>;
constexpr std::string_view kAxisLetters = "XYZABCUVWPQD";
int axis_index(char letter);  // -1 if not an axis letter

// A plane of interpolation: its abscissa u, ordinate v and the axis w along u x v
// (-1 when no axis lies that way), so that "clockwise seen from +w" is the negative
// sense in (u, v) (GOST 20999 S-9.2, NC-110 §2.8.1.4). LinuxCNC orders its arcs' axes
// the same way.
struct Plane {
  int u = 0, v = 1, w = 2;
  bool operator==(const Plane&) const = default;
};
// G17, G18, G19: XY, ZX, YZ.
constexpr Plane kPlanes[3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};
// "XY", "ZU": the letters of abscissa and ordinate.
std::string plane_name(const Plane& p);

// Tools T selects; their length and radius are offsets, numbered by D/H (§3.3.5).
struct ToolEntry {
  std::string description;
};

struct OffsetEntry {
  double length = 0;
  double radius = 0;
};

struct MachineConfig {
  std::string name = "default";
  std::map<int, AxisValues> work_offsets;  // 1..6 for G54..G59 (GOST "preset offsets")
  std::map<int, ToolEntry> tools;
  std::map<int, OffsetEntry> offsets;      // D/H offset numbers
  AxisValues initial_position{};
  bool block_skip = false;                 // run-time switches
  bool optional_stop = false;
};

}  // namespace ncc
