// The machine as the run sees it: offsets, tools and limits from the machine profile.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>

namespace ncc {

constexpr int kAxisCount = 9;  // X Y Z A B C U V W, LinuxCNC's order
using AxisValues = std::array<double, kAxisCount>;
constexpr std::string_view kAxisLetters = "XYZABCUVW";
int axis_index(char letter);  // -1 if not an axis letter

struct ToolEntry {
  std::string description;
  double length = 0;
  double radius = 0;
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
  double rapid_rate = 10000;               // mm/min
  bool block_skip = false;                 // run-time switches
  bool optional_stop = false;
};

}  // namespace ncc
