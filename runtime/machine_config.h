// The machine as the run sees it: offsets, tools and limits from the machine profile.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace ncc {

constexpr int kAxisCount = 9;  // X Y Z A B C U V W, LinuxCNC's order
using AxisValues = std::array<double, kAxisCount>;
constexpr std::string_view kAxisLetters = "XYZABCUVW";
int axis_index(char letter);  // -1 if not an axis letter

// The planes 0 XY, 1 ZX, 2 YZ: their in-plane axes (u, v) and the perpendicular axis w,
// ordered so that u x v = +w (GOST 20999 S-9.2): "clockwise seen from +w" is then the
// negative sense in (u, v). LinuxCNC orders its arcs' axes the same way.
constexpr int kPlaneAxes[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};
constexpr const char* kPlaneNames[3] = {"XY", "ZX", "YZ"};

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
