// The NC-110 G06 spline ("C-spline"): a curve through every programmed point with
// continuous curvature and a chosen condition at each end, in the plane of
// interpolation (abscissa, ordinate). Each coordinate is a C2 cubic in a chord-length
// parameter t; each span comes out as a cubic Bezier curve with its arc length, which
// is what the trace and the limit checks need.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace ncc {

// The condition at one end: natural (second derivative 0, "curvature 0") or clamped to
// a tangent direction. The module normalises the tangent; only its direction counts.
struct SplineEnd {
  bool clamped = false;
  Eigen::Vector2d tangent{1, 0};
};

// One span from p0 to p3 with control points p1, p2 and its arc length.
struct BezierSpan {
  Eigen::Vector2d p0, p1, p2, p3;
  double length = 0;
};

// The spline through points Q0..Qm: m spans, span i from Q_i to Q_{i+1}, t running over
// the chord h_i = |Q_{i+1} - Q_i| within it. A clamped end has dP/dt = the unit tangent,
// so t is close to arc length there. One span with natural ends is the straight line;
// with clamped ends the Hermite cubic.
// Empty if there are fewer than 2 points, two consecutive points coincide (within 1e-9),
// a point is not finite, or a clamped tangent is zero or not finite.
std::vector<BezierSpan> cubic_spline(const std::vector<Eigen::Vector2d>& points, SplineEnd start, SplineEnd end);

// The point at s in [0, 1] along a span's Bezier parameter (not its arc length).
Eigen::Vector2d point_at(const BezierSpan& span, double s);

}  // namespace ncc
