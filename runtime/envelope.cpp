#include "envelope.h"

#include <algorithm>
#include <cmath>

namespace ncc {

std::optional<Envelope::Breach> Envelope::limit_left(const std::vector<AxisValues>& path) const {
  for (int a = 0; a < kAxisCount; ++a) {
    if (!limited[a]) continue;
    auto outside = [&](double v) { return std::max({limits[0][a] - v, v - limits[1][a], 0.0}); };
    const double allowed = outside(path.front()[a]) + 1e-9;
    const AxisValues* farthest = nullptr;
    for (const AxisValues& p : path)
      if (outside(p[a]) > allowed && (!farthest || outside(p[a]) > outside((*farthest)[a]))) farthest = &p;
    if (farthest) return Breach{a, (*farthest)[a]};
  }
  return std::nullopt;
}

std::optional<size_t> Envelope::zone_entered(const std::vector<AxisValues>& path) const {
  for (size_t z = 0; z < zones.size(); ++z) {
    const Zone& zone = zones[z];
    if (!zone.active) continue;
    // Clip each segment to the open interval of each axis.
    for (size_t i = 0; i + 1 < path.size(); ++i) {
      double t0 = 0, t1 = 1;
      bool outside = false;
      for (int k = 0; k < 2 && !outside; ++k) {
        double a = path[i][zone.axis[k]], b = path[i + 1][zone.axis[k]];
        double d = b - a;
        if (std::fabs(d) < 1e-12) {
          outside = !(a > zone.lo[k] && a < zone.hi[k]);
          continue;
        }
        double ta = (zone.lo[k] - a) / d, tb = (zone.hi[k] - a) / d;
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
      }
      if (!outside && t1 - t0 > 1e-12) return z;
    }
  }
  return std::nullopt;
}

}  // namespace ncc
