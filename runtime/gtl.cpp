#include "gtl.h"

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "support/numbers.h"
#include "support/text.h"

namespace ncc::gtl {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }
double angle_of(const Vec& v) { return std::atan2(v.y(), v.x()) / kDegree; }

Element point(const Vec& p) { return {Kind::Point, p, {1, 0}, 0}; }
Element line(const Vec& a, const Vec& dir) { return {Kind::Line, a, dir.normalized(), 0}; }
Element circle(const Vec& c, double r) { return {Kind::Circle, c, {1, 0}, r}; }

}  // namespace

const Element* Store::find(Kind kind, int index) const {
  auto it = elements_.find({kind, index});
  return it == elements_.end() ? nullptr : &it->second;
}

// ---- Solvers --------------------------------------------------------------------------

Vec left(const Vec& u) { return {-u.y(), u.x()}; }
Vec direction(double degrees) { return {std::cos(degrees * kDegree), std::sin(degrees * kDegree)}; }
double side_distance(const Element& l, const Vec& p) { return left(l.dir).dot(p - l.at); }

Element reversed(const Element& e) {
  Element r = e;
  if (e.kind == Kind::Line) r.dir = -e.dir;
  if (e.kind == Kind::Circle) r.r = -e.r;
  return r;
}

Element offset(const Element& e, double distance) {
  Element o = e;
  if (e.kind == Kind::Line) o.at = e.at + distance * left(e.dir);
  if (e.kind == Kind::Circle) o.r = e.r - distance;  // left of a counter-clockwise circle is its inside
  return o;
}

Vec tangent(const Element& e, const Vec& p) {
  if (e.kind == Kind::Line) return e.dir;
  const Vec radial = (p - e.at).normalized();
  return e.r > 0 ? left(radial) : Vec(-left(radial));
}

double sweep(const Vec& centre, double r, const Vec& a, const Vec& b) {
  double d = r > 0 ? angle_of(b - centre) - angle_of(a - centre) : angle_of(a - centre) - angle_of(b - centre);
  d = std::fmod(d + 720, 360);
  return d >= 360 ? d - 360 : d;
}

Vec contact(const Element& e, const Vec& centre, double r) {
  switch (e.kind) {
    case Kind::Line: return centre - r * left(e.dir);
    case Kind::Circle: return centre + r * (e.at - centre) / (r - e.r);
    default: return e.at;
  }
}

std::vector<Vec> meet(const Element& a, const Element& b, Tolerance tol) {
  if (a.kind == Kind::Line && b.kind == Kind::Line) {
    const double d = cross(a.dir, b.dir);
    if (std::fabs(d) < 1e-12) return {};
    const double t = cross(b.at - a.at, b.dir) / d;
    return {a.at + t * a.dir};
  }
  if (a.kind == Kind::Circle && b.kind == Kind::Line) return meet(b, a, tol);
  if (a.kind == Kind::Line) {
    // Along the line: the foot of the centre, then either side by the half chord.
    const double d = side_distance(a, b.at);
    const double r = std::fabs(b.r);
    if (std::fabs(d) > r + tol.distance) return {};
    const Vec foot = b.at - d * left(a.dir);
    const double h = std::sqrt(std::max(0.0, r * r - d * d));
    return {foot - h * a.dir, foot + h * a.dir};
  }
  const Vec between = b.at - a.at;
  const double d = between.norm();
  const double r1 = std::fabs(a.r), r2 = std::fabs(b.r);
  if (d < tol.distance || d > r1 + r2 + tol.distance || d < std::fabs(r1 - r2) - tol.distance) return {};
  const Vec e = between / d;
  const double along = (d * d + r1 * r1 - r2 * r2) / (2 * d);
  const double h = std::sqrt(std::max(0.0, r1 * r1 - along * along));
  const Vec middle = a.at + along * e;
  return {middle + h * left(e), middle - h * left(e)};
}

namespace {

// Where the centres of circles of signed radius r compatible with e lie: a line
// beside a line, a circle about a circle's centre or a point.
std::optional<Element> locus(const Element& e, double r) {
  switch (e.kind) {
    case Kind::Line: return offset(e, r);
    case Kind::Circle:
      if (std::fabs(r - e.r) < 1e-12) return std::nullopt;
      return circle(e.at, std::fabs(r - e.r));
    default: return circle(e.at, std::fabs(r));
  }
}

}  // namespace

Result tangent_circle(const Element& first, const Element& second, double r, Tolerance tol) {
  if (std::fabs(r) < tol.distance) return {std::nullopt, "a radius of 0 makes no circle"};
  auto l1 = locus(first, r), l2 = locus(second, r);
  if (!l1 || !l2) return {std::nullopt, "a circle of the same radius and direction touches it only as itself"};
  std::optional<Element> best;
  double best_sweep = 0;
  for (const Vec& c : meet(*l1, *l2, tol)) {
    const double s = sweep(c, r, contact(first, c, r), contact(second, c, r));
    if (!best || s < best_sweep - 1e-9) {
      best = circle(c, r);
      best_sweep = s;
    }
  }
  if (!best) return {std::nullopt, "no circle of that radius touches both"};
  return {best, ""};
}

// ---- Definitions ----------------------------------------------------------------------

namespace {

struct Reader {
  std::span<const double> values;
  const Store& store;
  std::string_view axis_letters;
  int abscissa = 0, ordinate = 1;
  size_t at = 2;
  std::string why;
  std::vector<std::string> names;  // of the operands, for messages: "l3", "-c1", "the point"
  bool silent = false;             // an operand failed before: no message

  double next() { return at < values.size() ? values[at++] : 0; }
  bool fail(std::string w) {
    if (why.empty()) why = std::move(w);
    return false;
  }
  static std::string name(Kind k, int index) { return fmt::format("{}{}", letter(k), index); }

  // An element named by its index; an index out of range or undefined is an error.
  std::optional<Element> ref(Kind kind) {
    const double index = next();
    const bool reverse = next() != 0;
    auto n = whole_in(index, 0, kMaxIndex);
    if (!n)
      return fail(fmt::format("{}{} is not an element: the index is a whole number 0..{}", letter(kind),
                              shortest(index), kMaxIndex)),
             std::nullopt;
    const Element* e = store.find(kind, *n);
    names.push_back((reverse ? "-" : "") + name(kind, *n));
    silent = silent || (!e && store.failed(kind, *n));
    if (!e) return fail(fmt::format("{} is not defined before this block", name(kind, *n))), std::nullopt;
    return reverse ? reversed(*e) : *e;
  }
  // An origin prefix applies to the coordinates after it (§2.11.4).
  bool origin(Eigen::Rotation2Dd& turn, Vec& zero) {
    const double index = next();
    turn = Eigen::Rotation2Dd(0);
    zero = {0, 0};
    if (index < 0) return true;
    auto n = whole_in(index, 0, kMaxIndex);
    const Element* o = n ? store.find(Kind::Origin, *n) : nullptr;
    if (!o)
      return fail(
          n ? fmt::format("{} is not defined before this block", name(Kind::Origin, *n))
            : fmt::format("o{} is not an origin: the index is a whole number 0..{}", shortest(index), kMaxIndex));
    turn = Eigen::Rotation2Dd(std::atan2(o->dir.y(), o->dir.x()));
    zero = o->at;
    return true;
  }
  std::optional<Vec> coordinates() {
    Eigen::Rotation2Dd turn(0);
    Vec zero;
    if (!origin(turn, zero)) return next(), next(), next(), next(), std::nullopt;
    Vec p{0, 0};
    bool seen[2] = {false, false};
    for (int i = 0; i < 2; ++i) {
      const int axis = static_cast<int>(next());
      const double v = next();
      const int k = axis == abscissa ? 0 : axis == ordinate ? 1 : -1;
      const char l =
          axis >= 0 && static_cast<size_t>(axis) < axis_letters.size() ? axis_letters[static_cast<size_t>(axis)] : '?';
      if (k < 0)
        return fail(fmt::format("{} is not an axis of the plane {}{}: a point is given by the plane's two axes", l,
                                axis_letters[static_cast<size_t>(abscissa)],
                                axis_letters[static_cast<size_t>(ordinate)])),
               std::nullopt;
      if (seen[k]) return fail(fmt::format("{} is written twice", l)), std::nullopt;
      seen[k] = true;
      p[k] = v;
    }
    return zero + turn * p;
  }
  std::optional<Vec> polar() {
    Eigen::Rotation2Dd turn(0);
    Vec zero;
    if (!origin(turn, zero)) return next(), next(), std::nullopt;
    const double m = next(), a = next();
    return zero + turn * (m * direction(a));
  }
  std::optional<Element> centre() {
    Eigen::Rotation2Dd turn(0);
    Vec zero;
    if (!origin(turn, zero)) return next(), next(), next(), std::nullopt;
    const double i = next(), j = next(), r = next();
    if (r == 0) return fail("a circle's radius r is not 0"), std::nullopt;
    return circle(zero + turn * Vec(i, j), r);
  }
  // The operand as an element: a point, a line or a circle.
  std::optional<Element> element(Operand op) {
    if (op == Operand::Coordinates || op == Operand::Polar) names.push_back("the point");
    if (op == Operand::Centre) names.push_back("the circle");
    switch (op) {
      case Operand::PointRef: return ref(Kind::Point);
      case Operand::LineRef: return ref(Kind::Line);
      case Operand::CircleRef: return ref(Kind::Circle);
      case Operand::Coordinates:
        if (auto p = coordinates()) return point(*p);
        return std::nullopt;
      case Operand::Polar:
        if (auto p = polar()) return point(*p);
        return std::nullopt;
      case Operand::Centre: return centre();
      default: return circle({0, 0}, next());  // a scalar: its value in r
    }
  }
};

}  // namespace

Result define(const Shape& shape, std::span<const double> values, const Store& store, Tolerance tol,
              std::string_view axis_letters, int abscissa, int ordinate) {
  Reader in{values, store, axis_letters, abscissa, ordinate, 2, {}, {}, false};
  const bool s2 = values.size() > 1 && values[1] != 0;
  // The compiler checked the form; a bytecode file may hold any shape.
  if (std::string why = form_error(shape, s2); !why.empty()) return {std::nullopt, why};
  std::vector<Element> e;
  for (Operand op : shape.ops) {
    if (op == Operand::None) break;
    auto el = in.element(op);
    if (!el) return {std::nullopt, in.silent ? "" : in.why};
    e.push_back(*el);
  }
  auto fail = [](std::string why) { return Result{std::nullopt, std::move(why)}; };
  auto ok = [](Element el) { return Result{el, ""}; };
  const std::string sig = signature(shape);
  auto pick = [&](const std::vector<Vec>& points, const std::string& none) -> Result {
    if (points.empty()) return fail(none);
    return ok(point(points[s2 && points.size() > 1 ? 1 : 0]));
  };
  switch (shape.target) {
    case Kind::Origin: return ok({Kind::Origin, e[0].at, direction(e[1].r), 0});
    case Kind::Point:
      if (sig == "P") return ok(e[0]);
      return pick(meet(e[0], e[1], tol), fmt::format("{} and {} {}", in.names[0], in.names[1],
                                                     sig == "LL" ? "are parallel: they do not meet" : "do not meet"));
    case Kind::Line:
      if (sig == "PP") {
        const Vec d = e[1].at - e[0].at;
        if (d.norm() < tol.distance) return fail("a line through two points needs two different points");
        return ok(line(e[0].at, d));
      }
      if (sig == "Pa") return ok(line(e[0].at, direction(e[1].r)));
      if (sig == "Ca") {
        const Vec u = direction(e[1].r);
        return ok(line(e[0].at - e[0].r * left(u), u));
      }
      if (sig == "CC") {
        const Vec between = e[1].at - e[0].at;
        const double d = between.norm(), k = e[1].r - e[0].r;
        if (d < tol.distance) return fail("the two circles have one centre: no line touches both");
        if (std::fabs(k) > d + tol.distance)
          return fail("no line touches both circles in their directions: one lies inside the other's reach");
        const Vec u_c = between / d;
        const double c = std::clamp(k / d, -1.0, 1.0);
        const Vec n = c * u_c + std::sqrt(1 - c * c) * left(u_c);
        return ok(line(e[0].at - e[0].r * n, Vec(n.y(), -n.x())));
      }
      if (sig == "PC" || sig == "CP") {
        const bool point_first = sig == "PC";
        const Element& p = point_first ? e[0] : e[1];
        const Element& c = point_first ? e[1] : e[0];
        const Vec between = c.at - p.at;
        const double d = between.norm();
        if (d < std::fabs(c.r) - tol.distance)
          return fail("the point lies inside the circle: no line through it touches the circle");
        const double lambda = (point_first ? 1 : -1) * std::sqrt(std::max(0.0, d * d - c.r * c.r));
        const double alpha = angle_of(between) - std::atan2(c.r, lambda) / kDegree;
        return ok(line(p.at, direction(alpha)));
      }
      if (sig == "Ld") return ok(offset(e[0], e[1].r));
      break;
    case Kind::Circle:
      if (sig == "C") return ok(e[0]);
      if (sig == "Pr") {
        if (std::fabs(e[1].r) < tol.distance) return fail("a circle's radius r is not 0");
        return ok(circle(e[0].at, e[1].r));
      }
      if (sig == "PL") {
        const double r = side_distance(e[1], e[0].at);
        if (std::fabs(r) < tol.distance) return fail("the centre lies on the line: the circle would have radius 0");
        return ok(circle(e[0].at, r));
      }
      if (sig == "PC") {
        const double d = (e[0].at - e[1].at).norm();
        if (d < tol.distance) return fail("the centre is the circle's own centre: no circle about it touches it");
        std::vector<double> radii;
        for (double r : {e[1].r + d, e[1].r - d})
          if (std::fabs(r) >= tol.distance) radii.push_back(r);
        std::sort(radii.begin(), radii.end(), [](double a, double b) { return std::fabs(a) < std::fabs(b); });
        if (s2 && radii.size() < 2) return fail("only one circle about the centre touches it: s2 has no second");
        return ok(circle(e[0].at, radii[s2 ? 1 : 0]));
      }
      if (sig == "PPP") {
        const Vec a = e[0].at, b = e[1].at, c = e[2].at;
        const double d = 2 * cross(b - a, c - a);
        if (std::fabs(d) < tol.distance * tol.distance) return fail("the three points lie on one line");
        const Vec centre = a + Vec((c - a).y() * (b - a).squaredNorm() - (b - a).y() * (c - a).squaredNorm(),
                                   (b - a).x() * (c - a).squaredNorm() - (c - a).x() * (b - a).squaredNorm()) /
                                   d;
        const double r = (a - centre).norm();
        return ok(circle(centre, cross(b - a, c - b) > 0 ? r : -r));
      }
      if (sig == "Cd") {
        const double r = e[0].r - e[1].r;
        if (std::fabs(r) < tol.distance || (r > 0) != (e[0].r > 0))
          return fail(fmt::format("the distance {} is not less than the radius {}: no circle is left", shortest(e[1].r),
                                  shortest(std::fabs(e[0].r))));
        return ok(circle(e[0].at, r));
      }
      if (sig.size() == 3 && sig[2] == 'r') {
        Result c = tangent_circle(e[0], e[1], e[2].r, tol);
        if (!c.element)
          c.why = fmt::format("no circle of radius {} runs from {} to {}: {}", shortest(e[2].r), in.names[0],
                              in.names[1], c.why);
        return c;
      }
      break;
  }
  return fail(form_error(shape, s2));
}

}  // namespace ncc::gtl
