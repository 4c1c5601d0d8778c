// The simulator's commands on the pipeline: a run in machine coordinates becomes a
// Toolpath, which `ncc plot` draws, `ncc view` shows and `ncc run --time` times.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "driver/pipeline.h"
#include "sim/svg.h"
#include "sim/timing.h"
#include "sim/toolpath.h"
#include "sim/view.h"

namespace ncc {

struct Simulation {
  sim::Toolpath path;
  MachineConfig machine;
  RunResult result;
  std::vector<sim::CycleTime> times;  // feed, trapezoid, scurve
};

// Runs `m` for the simulator, in machine coordinates, the events going on to `trace`
// too if given. `progress`: what the progress line says; `output_on_terminal`: the
// command's output goes to the terminal (no progress line then).
[[nodiscard]] std::optional<Simulation> simulate(Session& s, const vm::Module& m, RunSettings settings,
                                                 const std::string& progress, bool output_on_terminal,
                                                 TraceSink* trace = nullptr);
// "N40 part.nc:12" for each block of the module's source map: a move's label.
std::vector<std::string> block_labels(const vm::Module& m);
// The page of `ncc view`: the run, the sources, the diagnostics so far.
sim::ViewInput view_input(Session& s, const vm::Module& m, const Simulation& sim);
// The stock: `text` ("X0:100,Y0:60,Z-20:0") if given, else the profile's [stock], else
// the box round the cutting moves (and the tool's radius) from their lowest point up to
// the work zero (or their highest point, when they stay above it). "" when good, else why not.
[[nodiscard]] std::string stock_box(const Simulation& sim, const std::string& text, double min[3], double max[3]);

}  // namespace ncc
