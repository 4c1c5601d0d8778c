// The cycle time of a tool path (`ncc run --time`, `ncc view`): how long the machine
// of the profile takes to run it, as cutting and auxiliary time (rapids, tool
// changes, dwells, spindle ramps), by three models of its motion:
//
//   feed       length / min(feed, the axes' limits along the move): LinuxCNC AXIS's
//              estimate, no acceleration.
//   trapezoid  per-axis speed and acceleration limits, corners by junction deviation,
//              arcs below their centripetal limit, look-ahead over the whole program:
//              grbl's and Klipper's planner.
//   scurve     the same with each speed change limited in jerk.
//
// The rules, where the models stop and why, are in timing.cpp's head comment.
// Programmed moves (Move::programmed, drawings beside the compensated path) take no
// time and no length. Each NC-110 process is timed on its own clock, as if the
// processes never waited for each other; the cycle is the longest process, and its
// categories are that process's.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "contract/machine_config.h"
#include "sim/toolpath.h"

namespace ncc::sim {

enum class TimeModel : uint8_t { Feed, Trapezoid, SCurve };
std::string_view model_name(TimeModel);  // "feed", "trapezoid", "scurve"
inline constexpr TimeModel kTimeModels[] = {TimeModel::Feed, TimeModel::Trapezoid, TimeModel::SCurve};

struct CycleTime {
  TimeModel model = TimeModel::Feed;
  double cutting = 0;                              // s: lines, arcs, threads at feed
  double rapid = 0;                                // s
  double tool_change = 0, dwell = 0, spindle = 0;  // s
  double auxiliary() const { return rapid + tool_change + dwell + spindle; }
  double total() const { return cutting + auxiliary(); }
  // s from the start of its process to the end of each Toolpath::moves entry (a
  // programmed move: the end of the move of its process before it).
  std::vector<double> move_end;
  // mm travelled at feed and at rapid, every process together (a move of rotary axes
  // alone adds none): the same for every model.
  double cutting_length = 0, rapid_length = 0;
};

CycleTime cycle_time(const Toolpath& path, const MachineConfig& machine, TimeModel model);

// The summary `ncc run --time` prints after the trace, for `times` (one per model, as
// cycle_time made them from `path`); each ends with a newline.
//
// time_text: the moves and lengths, then a table of the models: each category as
// minutes:seconds.tenths, and the total also in seconds.
//
// time_json: one object, keys stable:
//   {"processes": N,                        the processes that moved
//    "moves": {"cutting": N, "rapid": N},   moves (programmed ones not counted)
//    "length_mm": {"cutting": X, "rapid": X},
//    "tool_changes": N, "dwells": N,
//    "models": {"feed": {"cutting": S, "rapid": S, "tool_change": S, "dwell": S,
//                        "spindle": S, "auxiliary": S, "total": S},
//               "trapezoid": {...}, "scurve": {...}}}    S in seconds; the models given, in order
std::string time_text(const Toolpath& path, const std::vector<CycleTime>& times);
std::string time_json(const Toolpath& path, const std::vector<CycleTime>& times);

}  // namespace ncc::sim
