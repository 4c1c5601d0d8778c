// The G06 spline on its own: interpolation, continuity, end conditions, and curves
// with a known shape (a line, a circle).
#include "runtime/spline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace ncc {
namespace {

using Eigen::Vector2d;

// Derivatives w.r.t. the chord parameter t = h s at the ends of a span, from its
// control points: dB/ds = 3(p1 - p0) at s = 0, d2B/ds2 = 6(p2 - 2p1 + p0), and so on.
double chord(const BezierSpan& b) { return (b.p3 - b.p0).norm(); }
Vector2d d1_start(const BezierSpan& b) { return 3 * (b.p1 - b.p0) / chord(b); }
Vector2d d1_end(const BezierSpan& b) { return 3 * (b.p3 - b.p2) / chord(b); }
Vector2d d2_start(const BezierSpan& b) { return 6 * (b.p2 - 2 * b.p1 + b.p0) / std::pow(chord(b), 2); }
Vector2d d2_end(const BezierSpan& b) { return 6 * (b.p3 - 2 * b.p2 + b.p1) / std::pow(chord(b), 2); }

void expect_near(const Vector2d& a, const Vector2d& b, double tol) {
  EXPECT_NEAR(a.x(), b.x(), tol);
  EXPECT_NEAR(a.y(), b.y(), tol);
}

// Irregular spacing and turns both ways, so no symmetry hides a wrong row.
const std::vector<Vector2d> kZigzag = {{0, 0}, {3, 1}, {4, 5}, {8, 4.5}, {8.5, 0.5}, {15, 2}};

const SplineEnd kNatural;
SplineEnd clamped(double x, double y) { return {true, {x, y}}; }

// A polyline of many chords through the curve: its length approaches the arc length
// from below, the shortfall about L (kappa ds)^2 / 24.
double polyline_length(const BezierSpan& b, int chords) {
  double sum = 0;
  for (int k = 0; k < chords; ++k) sum += (point_at(b, (k + 1.0) / chords) - point_at(b, double(k) / chords)).norm();
  return sum;
}

TEST(Spline, PassesThroughEveryPoint) {
  for (auto [start, end] : {std::pair{kNatural, kNatural}, std::pair{clamped(1, 0), clamped(0, -1)}}) {
    auto spans = cubic_spline(kZigzag, start, end);
    ASSERT_EQ(spans.size(), kZigzag.size() - 1);
    for (size_t i = 0; i < spans.size(); ++i) {
      EXPECT_EQ(spans[i].p0, kZigzag[i]);
      EXPECT_EQ(spans[i].p3, kZigzag[i + 1]);
      EXPECT_EQ(point_at(spans[i], 0), kZigzag[i]);
      EXPECT_EQ(point_at(spans[i], 1), kZigzag[i + 1]);
      EXPECT_GT(spans[i].length, chord(spans[i]));  // no span here is straight
    }
  }
}

TEST(Spline, FirstAndSecondDerivativesContinuousAtInteriorKnots) {
  for (auto [start, end] :
       {std::pair{kNatural, kNatural}, std::pair{clamped(0, 1), kNatural}, std::pair{clamped(-1, 1), clamped(1, 1)}}) {
    auto spans = cubic_spline(kZigzag, start, end);
    ASSERT_EQ(spans.size(), kZigzag.size() - 1);
    for (size_t i = 0; i + 1 < spans.size(); ++i) {
      SCOPED_TRACE(i);
      expect_near(d1_end(spans[i]), d1_start(spans[i + 1]), 1e-9);
      expect_near(d2_end(spans[i]), d2_start(spans[i + 1]), 1e-9);
    }
  }
}

TEST(Spline, NaturalEndsHaveNoCurvature) {
  auto spans = cubic_spline(kZigzag, kNatural, kNatural);
  ASSERT_EQ(spans.size(), 5u);
  expect_near(d2_start(spans.front()), {0, 0}, 1e-12);
  expect_near(d2_end(spans.back()), {0, 0}, 1e-12);
  // Not trivially: the curve does bend inside.
  EXPECT_GT(d2_end(spans.front()).norm(), 0.1);
}

TEST(Spline, ClampedEndsTakeTheUnitTangent) {
  // The tangents' lengths do not matter: (0, 5) is (0, 1), (3, -4) is (0.6, -0.8).
  auto spans = cubic_spline(kZigzag, clamped(0, 5), clamped(3, -4));
  ASSERT_EQ(spans.size(), 5u);
  expect_near(d1_start(spans.front()), {0, 1}, 1e-12);
  expect_near(d1_end(spans.back()), {0.6, -0.8}, 1e-12);

  // One end clamped, the other natural.
  spans = cubic_spline(kZigzag, kNatural, clamped(-2, 0));
  ASSERT_EQ(spans.size(), 5u);
  expect_near(d2_start(spans.front()), {0, 0}, 1e-12);
  expect_near(d1_end(spans.back()), {-1, 0}, 1e-12);
}

TEST(Spline, OneSpan) {
  const std::vector<Vector2d> pts = {{1, 2}, {4, 6}};  // chord 5

  // Natural ends: the straight line at constant speed.
  auto line = cubic_spline(pts, kNatural, kNatural);
  ASSERT_EQ(line.size(), 1u);
  expect_near(line[0].p1, {2, 10.0 / 3}, 1e-12);
  expect_near(line[0].p2, {3, 14.0 / 3}, 1e-12);
  EXPECT_NEAR(line[0].length, 5, 1e-12);
  expect_near(point_at(line[0], 0.25), {1.75, 3}, 1e-12);

  // Clamped ends: the Hermite cubic, control points a third of the chord along each tangent.
  auto hermite = cubic_spline(pts, clamped(1, 0), clamped(0, 2));
  ASSERT_EQ(hermite.size(), 1u);
  expect_near(hermite[0].p1, {1 + 5.0 / 3, 2}, 1e-12);
  expect_near(hermite[0].p2, {4, 6 - 5.0 / 3}, 1e-12);
  EXPECT_NEAR(hermite[0].length, polyline_length(hermite[0], 20000), 1e-8);
}

TEST(Spline, CollinearPointsMakeAStraightLine) {
  // Uneven spacing along the direction (1, 2); the total is |(10, 20)|.
  const std::vector<Vector2d> pts = {{0, 0}, {1, 2}, {4, 8}, {4.5, 9}, {10, 20}};
  const Vector2d dir = Vector2d(1, 2).normalized();
  auto off_line = [&](const Vector2d& p) { return std::abs(dir.x() * p.y() - dir.y() * p.x()); };
  // Clamped along the line is the same curve as natural ends.
  for (auto [start, end] : {std::pair{kNatural, kNatural}, std::pair{clamped(1, 2), clamped(2, 4)}}) {
    auto spans = cubic_spline(pts, start, end);
    ASSERT_EQ(spans.size(), 4u);
    double total = 0;
    for (const BezierSpan& b : spans) {
      EXPECT_LT(off_line(b.p1), 1e-12);
      EXPECT_LT(off_line(b.p2), 1e-12);
      // The speed is 1 throughout, so the controls sit at the thirds of each chord.
      expect_near(b.p1, b.p0 + (b.p3 - b.p0) / 3, 1e-12);
      expect_near(b.p2, b.p0 + 2 * (b.p3 - b.p0) / 3, 1e-12);
      EXPECT_NEAR(b.length, chord(b), 1e-12);
      total += b.length;
    }
    EXPECT_NEAR(total, std::sqrt(500.0), 1e-12);
  }
}

TEST(Spline, HalfCircleThroughSevenPoints) {
  // Radius 10 at 0, 30, ..., 180 degrees, counter-clockwise: tangent (0, 1) at the
  // start and (0, -1) at the end, as on the circle.
  constexpr double r = 10;
  std::vector<Vector2d> pts;
  for (int k = 0; k <= 6; ++k) {
    double a = k * std::numbers::pi / 6;
    pts.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  auto spans = cubic_spline(pts, clamped(0, 1), clamped(0, -1));
  ASSERT_EQ(spans.size(), 6u);

  // The midpoints' distance from the circle (negative: inside), end spans first. The same
  // numbers come from an independent solve for the second derivatives at the knots.
  const double expected_mid[6] = {-0.004440813, -0.000404783, -0.002556173, -0.002556173, -0.000404783, -0.004440813};
  double max_mid = 0, max_any = 0, total = 0;
  for (size_t i = 0; i < spans.size(); ++i) {
    const BezierSpan& b = spans[i];
    double mid = point_at(b, 0.5).norm() - r;
    EXPECT_NEAR(mid, expected_mid[i], 1e-9);
    max_mid = std::max(max_mid, std::abs(mid));
    for (int k = 0; k <= 100; ++k) max_any = std::max(max_any, std::abs(point_at(b, k / 100.0).norm() - r));
    // The quadrature against a fine polyline (its shortfall is about 1e-10 relative here).
    EXPECT_NEAR(b.length, polyline_length(b, 20000), 1e-9 * b.length);
    total += b.length;
  }
  // Measured: 0.00444 at the midpoints of the end spans, 0.00447 anywhere (at s = 0.53).
  EXPECT_LT(max_mid, 0.005);
  EXPECT_LT(max_any, 0.005);
  // 31.41183, 1.3e-4 short of pi r: the curve runs a little inside the circle.
  EXPECT_NEAR(total, r * std::numbers::pi, 1e-3 * r * std::numbers::pi);
}

TEST(Spline, DegenerateInputsGiveNoSpans) {
  EXPECT_TRUE(cubic_spline({}, kNatural, kNatural).empty());
  EXPECT_TRUE(cubic_spline({{1, 2}}, kNatural, kNatural).empty());
  EXPECT_TRUE(cubic_spline({{0, 0}, {1, 1}, {1, 1}, {2, 0}}, kNatural, kNatural).empty());
  EXPECT_TRUE(cubic_spline({{0, 0}, {1, 1}, {1 + 1e-10, 1}, {2, 0}}, kNatural, kNatural).empty());
  EXPECT_TRUE(cubic_spline({{0, 0}, {1, 1}}, clamped(0, 0), kNatural).empty());
  EXPECT_TRUE(cubic_spline({{0, 0}, {1, 1}}, kNatural, clamped(0, 0)).empty());
  EXPECT_TRUE(cubic_spline({{0, 0}, {NAN, 1}}, kNatural, kNatural).empty());
  // A natural end ignores its tangent, zero or not.
  EXPECT_EQ(cubic_spline({{0, 0}, {1, 1}}, {false, {0, 0}}, kNatural).size(), 1u);
  // Just above the threshold is a span.
  EXPECT_EQ(cubic_spline({{0, 0}, {2e-9, 0}}, kNatural, kNatural).size(), 1u);
}

}  // namespace
}  // namespace ncc
