// `ncc plot`: the tool path as an SVG drawing, in one of four views.
#pragma once

#include <string>
#include <vector>

#include "toolpath.h"

namespace ncc::sim {

enum class View : uint8_t { XY, XZ, YZ, Iso };
[[nodiscard]] bool parse_view(std::string_view name, View& out);  // "xy", "xz", "yz", "iso"

struct PlotInput {
  const Toolpath* path = nullptr;
  std::vector<std::string> labels;  // of each Move::source: "N40 part.nc:12", the move's <title>
  std::string title;                // the drawing's
  View view = View::XY;
  // mm: the largest distance between an arc and the chords that stand for it where
  // the view does not show it as an arc (a helix seen from its side, any arc in iso).
  double tolerance = 0.001;
  double size = 1000;  // px: the drawing's longer side
};

// Every move one <path> with a <title>, in the order they ran, the programmed path
// (under compensation) in a group of its own; the same input gives the same bytes.
std::string write_svg(const PlotInput& in);

}  // namespace ncc::sim
