#include "corner.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "support/numbers.h"

namespace ncc::corner {

namespace {

constexpr double kEps = 1e-9;
Vec left(const Vec& d) { return {-d.y(), d.x()}; }
double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }
double radius(const Element& e) { return (e.a - e.c).norm(); }

// The angle travelled along an arc from `from` to `to` (0..2pi in its direction).
double travelled(const Element& e, const Vec& from, const Vec& to) {
  double a = std::atan2(cross(from - e.c, to - e.c), (from - e.c).dot(to - e.c));
  if (!e.ccw) a = -a;
  if (a < -kEps) a += 2 * std::numbers::pi;
  return std::max(a, 0.0);
}

// The point of an arc at the straight distance d from its end (backwards) or start.
std::optional<Vec> along_arc(const Element& e, const Vec& from, double d, bool backwards, double& angle) {
  const double r = radius(e);
  if (d > 2 * r) return std::nullopt;
  angle = 2 * std::asin(d / (2 * r));
  const double turn = (e.ccw != backwards) ? angle : -angle;
  const Vec v = from - e.c;
  return Vec(e.c.x() + v.x() * std::cos(turn) - v.y() * std::sin(turn),
             e.c.y() + v.x() * std::sin(turn) + v.y() * std::cos(turn));
}

// The points at distance `size` on the side `side` (+1 left of travel) of an element:
// a line shifted, or the arc's circle grown or shrunk.
struct Offset {
  bool circle = false;
  Vec p, d;     // line: a point and its direction
  Vec c{0, 0};  // circle: centre and radius
  double r = 0;
};
Offset offset(const Element& e, double size, int side) {
  Offset o;
  if (!e.arc) {
    o.d = (e.b - e.a).normalized();
    o.p = e.a + side * size * left(o.d);
    return o;
  }
  o.circle = true;
  o.c = e.c;
  // Left of travel is towards the centre on a counter-clockwise arc.
  o.r = radius(e) + ((side > 0) == e.ccw ? -size : size);
  return o;
}

std::vector<Vec> intersect(const Offset& a, const Offset& b) {
  std::vector<Vec> out;
  if (!a.circle && !b.circle) {
    const double den = cross(a.d, b.d);
    if (std::fabs(den) < kEps) return out;
    out.push_back(a.p + a.d * (cross(b.p - a.p, b.d) / den));
  } else if (a.circle != b.circle) {
    const Offset& l = a.circle ? b : a;
    const Offset& c = a.circle ? a : b;
    const Vec f = l.p - c.c;
    const double bq = f.dot(l.d), cq = f.squaredNorm() - c.r * c.r, disc = bq * bq - cq;
    if (disc < -kEps || c.r <= 0) return out;
    const double s = std::sqrt(std::max(disc, 0.0));
    out.push_back(l.p + l.d * (-bq - s));
    out.push_back(l.p + l.d * (-bq + s));
  } else {
    const Vec d = b.c - a.c;
    const double dist = d.norm();
    if (dist < kEps || a.r <= 0 || b.r <= 0 || dist > a.r + b.r + kEps || dist < std::fabs(a.r - b.r) - kEps)
      return out;
    const double x = (dist * dist + a.r * a.r - b.r * b.r) / (2 * dist);
    const double h = std::sqrt(std::max(a.r * a.r - x * x, 0.0));
    const Vec m = a.c + d * (x / dist), n = left(d / dist);
    out.push_back(m + n * h);
    out.push_back(m - n * h);
  }
  return out;
}

// The point of an element nearest to `p` (a line's foot, or the arc's radial point).
Vec foot(const Element& e, const Vec& p) {
  if (e.arc) return e.c + (p - e.c).normalized() * radius(e);
  const Vec d = (e.b - e.a).normalized();
  return e.a + d * (p - e.a).dot(d);
}

// Where p lies along the element: 0 at its start, 1 at its end.
double fraction(const Element& e, const Vec& p) {
  if (e.arc) return e.sweep > 0 ? travelled(e, e.a, p) / e.sweep : 0;
  const double len2 = (e.b - e.a).squaredNorm();
  return len2 > 0 ? (p - e.a).dot(e.b - e.a) / len2 : 0;
}

}  // namespace

int turns(double degrees) { return whole_in(std::ceil(degrees / 360 - 1e-9), 1, INT32_MAX).value_or(1); }

Vec tangent(const Element& e, const Vec& p) {
  if (!e.arc) return (e.b - e.a).normalized();
  Vec t = left((p - e.c).normalized());
  return e.ccw ? t : Vec(-t);
}

std::vector<Vec> offsets_meet(const Element& a, const Element& b, double size, int side) {
  return intersect(offset(a, size, side), offset(b, size, side));
}

std::optional<Cut> cut(const Element& in, const Element& out, bool fillet, double size, std::string& why) {
  const Vec p = in.b;
  const Vec din = tangent(in, p), dout = tangent(out, p);
  const double turn = cross(din, dout);
  if (std::fabs(turn) < 1e-9 && din.dot(dout) > 0) {
    why = "the two moves meet in a straight line: there is no corner";
    return std::nullopt;
  }
  if (!(size > 0)) {
    why = "its size must be greater than zero";
    return std::nullopt;
  }
  Cut c;
  c.fillet = fillet;
  if (!fillet) {
    double angle = 0;
    auto t1 = in.arc ? along_arc(in, p, size, true, angle) : std::optional<Vec>(p - din * size);
    c.in_cut = angle;
    auto t2 = out.arc ? along_arc(out, p, size, false, angle) : std::optional<Vec>(p + dout * size);
    c.out_cut = out.arc ? angle : 0;
    if (!t1 || !t2) {
      why = "the chamfer is larger than the arc's diameter";
      return std::nullopt;
    }
    c.t1 = *t1;
    c.t2 = *t2;
  } else {
    // The centre lies on the inside of the turn, at the radius from both elements.
    const int side = turn > 0 ? 1 : -1;
    std::vector<Vec> centres = offsets_meet(in, out, size, side);
    if (centres.empty()) {
      why = "no circle of that radius touches both moves";
      return std::nullopt;
    }
    Vec best = centres.front();
    for (const Vec& v : centres)
      if ((v - p).norm() < (best - p).norm()) best = v;
    c.centre = best;
    c.t1 = foot(in, best);
    c.t2 = foot(out, best);
    c.ccw = turn > 0;
    Element f{c.t1, c.t2, true, best, c.ccw, 0};
    c.fillet_sweep = travelled(f, c.t1, c.t2);
    if (in.arc) c.in_cut = travelled(in, c.t1, p);
    if (out.arc) c.out_cut = travelled(out, p, c.t2);
  }
  // §8.3 (E-02): both ends lie on their moves.
  c.in_fraction = fraction(in, c.t1);
  c.out_fraction = fraction(out, c.t2);
  if (c.in_fraction < -kEps || c.in_fraction > 1 + kEps || c.out_fraction < -kEps || c.out_fraction > 1 + kEps ||
      (in.arc && c.in_cut > in.sweep + kEps) || (out.arc && c.out_cut > out.sweep + kEps)) {
    why = "its end falls outside the moves it joins";
    return std::nullopt;
  }
  return c;
}

}  // namespace ncc::corner
