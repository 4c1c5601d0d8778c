// Chamfers and fillets between two moves (ISO ,C and ,R, §8.3): pure plane geometry on
// the two elements that meet at a corner, each a line or an arc.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace ncc::corner {

using Vec = Eigen::Vector2d;

// A move in the plane: from `a` to `b`, an arc about `c` when `arc` (`ccw` its way).
struct Element {
  Vec a, b;
  bool arc = false;
  Vec c{0, 0};
  bool ccw = false;
  double sweep = 0;  // radians, of an arc
};

// The corner: the incoming element ends at T1, the outgoing one starts at T2, and
// between them a straight chamfer or a fillet arc about `centre` (`ccw` its way).
struct Cut {
  Vec t1, t2;
  double in_cut = 0, out_cut = 0;  // radians an arc loses (0 for a line)
  bool fillet = false;
  Vec centre{0, 0};
  bool ccw = false;
  double fillet_sweep = 0;                   // radians
  double in_fraction = 1, out_fraction = 0;  // where T1 and T2 lie along their elements (0..1)
};

// The whole turns an arc of `degrees` sweep makes, at least 1 (an arc event's rotation).
int turns(double degrees);

// The direction of travel at point p of the element.
Vec tangent(const Element& e, const Vec& p);
// The points where the element's offset by `size` to `side` (+1 left of travel, -1
// right: a line shifted, an arc's circle grown or shrunk) meets the other's.
std::vector<Vec> offsets_meet(const Element& a, const Element& b, double size, int side);

// A chamfer whose ends lie at the straight distance `size` from the corner on each
// element, or a fillet of radius `size` tangent to both; the reason when there is none.
[[nodiscard]] std::optional<Cut> cut(const Element& in, const Element& out, bool fillet, double size, std::string& why);

}  // namespace ncc::corner
