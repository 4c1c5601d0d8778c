#include "spline.h"

#include <array>
#include <cstddef>

namespace ncc {

namespace {

// Consecutive points closer than this make no span (program units).
constexpr double kMinChord = 1e-9;

// 16-point Gauss-Legendre on [-1, 1]: the nodes +-x with weight w. The speed of a
// smooth span is analytic, so 16 points give its length to rounding.
constexpr std::array<std::array<double, 2>, 8> kGauss16 = {{
    {0.09501250983763744, 0.18945061045506850},
    {0.28160355077925891, 0.18260341504492359},
    {0.45801677765722739, 0.16915651939500254},
    {0.61787624440264375, 0.14959598881657673},
    {0.75540440835500303, 0.12462897125553387},
    {0.86563120238783174, 0.09515851168249278},
    {0.94457502307323258, 0.06225352393864789},
    {0.98940093499164993, 0.02715245941175409},
}};

// dB/ds of a cubic Bezier curve.
Eigen::Vector2d derivative_at(const BezierSpan& b, double s) {
  double r = 1 - s;
  return 3 * (r * r * (b.p1 - b.p0) + 2 * r * s * (b.p2 - b.p1) + s * s * (b.p3 - b.p2));
}

double arc_length(const BezierSpan& b) {
  double sum = 0;
  for (const auto& [x, w] : kGauss16) {
    sum += w * (derivative_at(b, 0.5 * (1 - x)).norm() + derivative_at(b, 0.5 * (1 + x)).norm());
  }
  return 0.5 * sum;  // s in [0, 1] is half of [-1, 1]
}

}  // namespace

std::vector<BezierSpan> cubic_spline(const std::vector<Eigen::Vector2d>& points, SplineEnd start, SplineEnd end) {
  const size_t n = points.size();  // knots; n - 1 spans
  if (n < 2) return {};
  for (SplineEnd* e : {&start, &end}) {
    if (!e->clamped) continue;
    if (!e->tangent.allFinite() || e->tangent.norm() == 0) return {};
    e->tangent.normalize();
  }
  // Chords h and unit chord directions u, which make the right-hand sides below.
  std::vector<double> h(n - 1);
  std::vector<Eigen::Vector2d> u(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    if (!points[i].allFinite() || !points[i + 1].allFinite()) return {};
    Eigen::Vector2d d = points[i + 1] - points[i];
    h[i] = d.norm();
    if (!(h[i] >= kMinChord)) return {};
    u[i] = d / h[i];
  }

  // The first derivatives D_i at the knots, both coordinates at once (the matrix only
  // depends on h). On a span of length h from Q to Q' the Hermite cubic has
  //   P''(0) = 6(Q'-Q)/h^2 - (4D + 2D')/h,   P''(h) = -6(Q'-Q)/h^2 + (2D + 4D')/h.
  // An interior knot equates the two sides' P'' (halved); a natural end sets P'' = 0
  // (halved); a clamped end fixes D. Every row is strictly diagonally dominant, so the
  // Thomas algorithm needs no pivoting.
  std::vector<double> sub(n, 0), diag(n, 0), sup(n, 0);
  std::vector<Eigen::Vector2d> rhs(n);
  for (size_t i = 1; i + 1 < n; ++i) {
    sub[i] = 1 / h[i - 1];
    diag[i] = 2 / h[i - 1] + 2 / h[i];
    sup[i] = 1 / h[i];
    rhs[i] = 3 * (u[i - 1] / h[i - 1] + u[i] / h[i]);
  }
  if (start.clamped) {
    diag[0] = 1;
    rhs[0] = start.tangent;
  } else {
    diag[0] = 2 / h[0];
    sup[0] = 1 / h[0];
    rhs[0] = 3 * u[0] / h[0];
  }
  if (end.clamped) {
    diag[n - 1] = 1;
    rhs[n - 1] = end.tangent;
  } else {
    sub[n - 1] = 1 / h[n - 2];
    diag[n - 1] = 2 / h[n - 2];
    rhs[n - 1] = 3 * u[n - 2] / h[n - 2];
  }
  for (size_t i = 1; i < n; ++i) {
    double w = sub[i] / diag[i - 1];
    diag[i] -= w * sup[i - 1];
    rhs[i] -= w * rhs[i - 1];
  }
  std::vector<Eigen::Vector2d> d(n);
  d[n - 1] = rhs[n - 1] / diag[n - 1];
  for (size_t i = n - 1; i-- > 0;) d[i] = (rhs[i] - sup[i] * d[i + 1]) / diag[i];

  // Hermite to Bezier: the inner control points lie a third of the chord along D.
  std::vector<BezierSpan> spans(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    BezierSpan& b = spans[i];
    b.p0 = points[i];
    b.p1 = points[i] + h[i] * d[i] / 3;
    b.p2 = points[i + 1] - h[i] * d[i + 1] / 3;
    b.p3 = points[i + 1];
    b.length = arc_length(b);
  }
  return spans;
}

Eigen::Vector2d point_at(const BezierSpan& span, double s) {
  // de Casteljau; (1 - s) x + s y is exactly x at s = 0 and y at s = 1, so the ends
  // come out as the knots themselves.
  auto lerp = [s](const Eigen::Vector2d& x, const Eigen::Vector2d& y) -> Eigen::Vector2d {
    return (1 - s) * x + s * y;
  };
  Eigen::Vector2d a = lerp(span.p0, span.p1), b = lerp(span.p1, span.p2), c = lerp(span.p2, span.p3);
  return lerp(lerp(a, b), lerp(b, c));
}

}  // namespace ncc
