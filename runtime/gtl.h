// GTL, the NC-110 geometric language (§2.11): origins, points, lines and circles
// defined from drawing data, each from numbers or from elements defined before it.
// Plane geometry in the coordinates of the active plane (abscissa, ordinate), in
// program units; the runtime maps what it makes through its frame. Lines and circles
// are directed (§2.11.1): a line runs along `dir`, a circle counter-clockwise when its
// radius is positive, clockwise when negative; "-l4", "-c2" reverse them.
//
// A definition reaches the runtime as a Shape (contract/gtl_shape.h: its target and
// the kinds of its operands, packed into the argument of the gtl.define function) and
// the values of its operands in written order (value_count() each).
#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "contract/gtl_shape.h"

namespace ncc::gtl {

using Vec = Eigen::Vector2d;

struct Element {
  Kind kind = Kind::Point;
  Vec at{0, 0};   // the origin's zero, the point, the line's first point, the circle's centre
  Vec dir{1, 0};  // a line's direction and an origin's X axis: unit vectors
  double r = 0;   // a circle's signed radius
};

// The elements a program has defined, by kind and index.
// The elements a program has defined, by kind and index. One whose definition failed
// is marked: what is defined from it fails too, without a second message.
class Store {
 public:
  const Element* find(Kind kind, int index) const;
  void set(int index, const Element& e) {
    elements_[{e.kind, index}] = e;
    failed_.erase({e.kind, index});
  }
  void fail(Kind kind, int index) {
    elements_.erase({kind, index});
    failed_.insert({kind, index});
  }
  bool failed(Kind kind, int index) const { return failed_.count({kind, index}) != 0; }

 private:
  std::map<std::pair<Kind, int>, Element> elements_;
  std::set<std::pair<Kind, int>> failed_;
};

// The geometry's tolerance: how far apart two points may be and still be one point,
// and how far a circle may miss a line or another circle and still touch it.
struct Tolerance {
  double distance = 0.001;  // program units
};

// An element, or why there is none ("" when an element it is defined from failed
// before). `axis_letters` name the axes by number (kAxisLetters) in messages.
struct [[nodiscard]] Result {
  std::optional<Element> element;
  std::string why;
};
Result define(const Shape& shape, std::span<const double> values, const Store& store, Tolerance tol,
              std::string_view axis_letters, int abscissa, int ordinate);

// ---- The solvers, each on its own (unit-tested) ----------------------------------

Vec left(const Vec& u);  // u turned 90 degrees counter-clockwise
Vec direction(double degrees);
// Signed distance of p from a line: positive on its left.
double side_distance(const Element& line, const Vec& p);
// Where two elements meet, first solution first (§2.11.5, §2.11.9.1): a line and a
// circle in the line's direction; two circles, the point left of the line from the
// first centre to the second first. Two lines: one point. Tangent: the point twice.
std::vector<Vec> meet(const Element& a, const Element& b, Tolerance tol);
// The circle of signed radius r compatible-tangent to (or through, for a point) both
// elements, running from the first to the second along its shorter arc (§2.11.7).
Result tangent_circle(const Element& first, const Element& second, double r, Tolerance tol);
// Where a circle of centre `centre` and signed radius r touches the element.
Vec contact(const Element& e, const Vec& centre, double r);
// The sweep in degrees [0, 360) from a to b on a circle in its own direction.
double sweep(const Vec& centre, double r, const Vec& a, const Vec& b);
// The direction of travel along the element at p.
Vec tangent(const Element& e, const Vec& p);
// The element moved `distance` to its left (a negative distance: to its right).
Element offset(const Element& e, double distance);
Element reversed(const Element& e);

}  // namespace ncc::gtl
