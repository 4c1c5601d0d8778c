// The working limits and protected zones (NC-110 §2.13.5.3, §2.13.5.5): what the
// path of every move is checked against before the move starts, in machine
// coordinates.
#pragma once

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "contract/machine_config.h"

namespace ncc {

struct Envelope {
  // A protected zone (DSA): an open rectangle in two axes.
  struct Zone {
    bool defined = false, active = false;
    int axis[2] = {0, 1};
    double lo[2] = {0, 0}, hi[2] = {0, 0};
  };

  std::array<AxisValues, 2> limits{};  // DLO: lower and upper
  std::array<bool, kAxisCount> limited{};
  std::array<Zone, 3> zones;

  bool any_limit() const {
    return std::any_of(limited.begin(), limited.end(), [](bool b) { return b; });
  }
  bool any_zone() const {  // active
    return std::any_of(zones.begin(), zones.end(), [](const Zone& z) { return z.active; });
  }
  // A limit the path leaves: the first axis it goes farther outside on than it starts
  // (a tool outside the field may come back into it: decision 34), and the farthest
  // value it would reach there.
  struct Breach {
    int axis;
    double farthest;
  };
  std::optional<Breach> limit_left(const std::vector<AxisValues>& path) const;
  // The first active zone (its index) the path enters: some part of a segment lies
  // strictly inside; touching an edge does not.
  std::optional<size_t> zone_entered(const std::vector<AxisValues>& path) const;
};

}  // namespace ncc
