// `ncc view`: one self-contained HTML page that shows a run's tool path in 3-D, block
// by block: three.js (Debian's libjs-three, compiled into ncc) draws the path, the
// tool, the stock and its machined surface; a source pane, the cycle times, the work
// offset and a measuring tool sit beside it. The page is sim/view/ (template, style,
// script); the data it reads, and the rules that bound its size, are in view.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "timing.h"
#include "toolpath.h"

namespace ncc::sim {

struct ViewBlock {  // of a Move::source (SourceMap block index)
  uint32_t file = 0, line = 0;
};
struct ViewSource {  // a source file as read
  std::string name;
  std::string text;
};
struct ViewDiagnostic {
  uint32_t file = 0, line = 0, column = 0;  // line 0: no place
  std::string severity, id, message;
};

struct ViewInput {
  const Toolpath* path = nullptr;
  std::vector<CycleTime> times;     // one per model, from cycle_time()
  std::vector<ViewBlock> blocks;    // indexed by Move::source and Pause::source
  std::vector<ViewSource> sources;  // indexed by ViewBlock::file
  std::vector<ViewDiagnostic> diagnostics;
  double stock_min[3] = {0, 0, 0}, stock_max[3] = {0, 0, 0};  // mm, the stock box (empty: none drawn)
  std::string title;                                          // the file name
  std::string dialect;
  double tolerance = 0.01;  // mm: straight moves of a block merge when no corner leaves their chord by more (0: none)
  double grid = 0;          // mm: height-map cell (0: from the stock's size; see view_grid)
};

// The height map's cell (mm) for a stock of `size_x` by `size_y` mm: `requested` if
// positive, else the smallest of 1, 2, 2.5, 5 times a power of ten that covers the
// longer side in 200 cells; in either case coarsened to the same steps until the map
// has at most 1,000,000 cells.
double view_grid(double size_x, double size_y, double requested);

// The whole page; the same input gives the same bytes.
void write_view(std::string& out, const ViewInput& in);

}  // namespace ncc::sim
