// The GTL solvers on their own (§2.11): every definition form with the values the
// manual's figures and worked examples give (derived by hand in
// docs/dialects/nc110.md, GTL), both solutions where there are two, and the
// impossible cases; then profiles joined, filleted, chamfered and offset.
#include "runtime/gtl.h"
#include "runtime/gtl_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ncc::gtl {
namespace {

constexpr double kTol = 0.0005;  // the manual prints three decimals

// A definition as a program writes it: `Def(Kind::Line).xy(40, 20).xy(60, 70)`.
class Def {
 public:
  explicit Def(Kind k, int index = 99) {  // 99: a result the test does not name again
    shape_.target = k;
    values_ = {static_cast<double>(index), 0};
  }
  Def& xy(double x, double y, int origin = -1) { return add(Operand::Coordinates, {double(origin), 0, x, 1, y}); }
  Def& yx(double y, double x) { return add(Operand::Coordinates, {-1, 1, y, 0, x}); }
  Def& polar(double m, double a, int origin = -1) { return add(Operand::Polar, {double(origin), m, a}); }
  Def& centre(double i, double j, double r, int origin = -1) { return add(Operand::Centre, {double(origin), i, j, r}); }
  Def& p(int n) { return add(Operand::PointRef, {double(n), 0}); }
  Def& l(int n, bool rev = false) { return add(Operand::LineRef, {double(n), rev ? 1.0 : 0.0}); }
  Def& c(int n, bool rev = false) { return add(Operand::CircleRef, {double(n), rev ? 1.0 : 0.0}); }
  Def& a(double v) { return add(Operand::Angle, {v}); }
  Def& r(double v) { return add(Operand::Radius, {v}); }
  Def& d(double v) { return add(Operand::Distance, {v}); }
  Def& s2() {
    values_[1] = 1;
    return *this;
  }
  Result in(const Store& store) const { return define(shape_, values_, store, {}, "XYZABCUVWPQD", 0, 1); }
  // Defined into the store under its index; the test fails if it is not.
  Element into(Store& store) const {
    Result r = in(store);
    EXPECT_TRUE(r.element) << r.why;
    Element e = r.element.value_or(Element{});
    store.set(static_cast<int>(values_[0]), e);
    return e;
  }
  const Shape& shape() const { return shape_; }

 private:
  Def& add(Operand op, std::vector<double> v) {
    for (auto& slot : shape_.ops)
      if (slot == Operand::None) {
        slot = op;
        break;
      }
    values_.insert(values_.end(), v.begin(), v.end());
    return *this;
  }
  Shape shape_;
  std::vector<double> values_;
};

void expect_at(const Vec& p, double x, double y) {
  EXPECT_NEAR(p.x(), x, kTol);
  EXPECT_NEAR(p.y(), y, kTol);
}
double degrees(const Vec& u) { return std::atan2(u.y(), u.x()) * 180 / M_PI; }

TEST(GtlShape, PacksIntoTheFunctionArgument) {
  Shape s{Kind::Circle, {Operand::LineRef, Operand::Centre, Operand::Radius}};
  EXPECT_EQ(Shape::unpack(s.pack()), s);
  EXPECT_LT(s.pack(), 1u << 14);
  EXPECT_EQ(s.value_count(), 2u + 2 + 4 + 1);
}

TEST(GtlShape, AnyShapeOfAFileIsChecked) {
  // A bytecode file may hold any argument: every one gives an element or a reason.
  const Store store;
  for (unsigned arg = 0; arg < (1u << 14); arg += 7) {
    const Shape shape = Shape::unpack(static_cast<uint16_t>(arg));
    const std::vector<double> values(shape.value_count(), 1);
    const Result r = define(shape, values, store, {}, "XYZABCUVWPQD", 0, 1);
    EXPECT_TRUE(r.element || !r.why.empty()) << arg;
  }
}

TEST(GtlShape, FormsOfTheManual) {
  EXPECT_EQ(form_error(Def(Kind::Line).p(1).a(30).shape(), false), "");
  EXPECT_EQ(form_error(Def(Kind::Point).l(1).c(2).shape(), true), "");
  EXPECT_EQ(form_error(Def(Kind::Circle).p(1).c(2).shape(), true), "");
  EXPECT_EQ(form_error(Def(Kind::Line).p(1).r(5).shape(), false),
            "a line is not defined by a point and a radius (§2.11.6)");
  EXPECT_EQ(form_error(Def(Kind::Line).p(1).p(2).shape(), true),
            "s2 chooses the second of two solutions; a line defined by a point and a point has one (§2.11.6)");
  EXPECT_EQ(form_error(Def(Kind::Point).p(1).shape(), false), "a point is not defined by a point (§2.11.5)");
  EXPECT_EQ(form_error(Def(Kind::Origin).polar(5, 5).a(3).shape(), false),
            "an origin is given by its coordinates X.. Y.. and an angle a.. (§2.11.4)");
}

TEST(GtlPoint, CartesianPolarAndOrigins) {
  Store s;
  Def(Kind::Origin, 1).xy(30, 30).a(-20).into(s);
  expect_at(Def(Kind::Point).xy(20, 10, 1).into(s).at, 52.214, 32.557);
  expect_at(Def(Kind::Point).polar(55, 60).into(s).at, 27.5, 47.631);
  expect_at(Def(Kind::Point).xy(30, 160).into(s).at, 30, 160);
  // The plane's letters in any order: Y first.
  expect_at(Def(Kind::Point).yx(7, 3).into(s).at, 3, 7);
}

TEST(GtlPoint, LinesMeetOnce) {
  Store s;
  // §2.11.10 example 1: l1 = X70 Y40, a150; l2 = X8 Y8, a-95; p1 = l1, l2.
  Def(Kind::Line, 1).xy(70, 40).a(150).into(s);
  Def(Kind::Line, 2).xy(8, 8).a(-95).into(s);
  expect_at(Def(Kind::Point).l(1).l(2).into(s).at, 13.646, 72.536);
  Def(Kind::Line, 3).xy(0, 5).a(150).into(s);
  EXPECT_EQ(Def(Kind::Point).l(1).l(3).in(s).why, "l1 and l3 are parallel: they do not meet");
}

TEST(GtlPoint, LineAndCircleInTheLinesDirection) {
  Store s;
  Def(Kind::Line, 4).xy(0, 0).a(0).into(s);
  Def(Kind::Circle, 3).centre(10, 0, 5).into(s);
  expect_at(Def(Kind::Point).l(4).c(3).into(s).at, 5, 0);
  expect_at(Def(Kind::Point).l(4).c(3).s2().into(s).at, 15, 0);
  // Figure 2.55: the reversed line meets the other point first; the order of the
  // operands does not matter, the circle's direction neither.
  expect_at(Def(Kind::Point).l(4, true).c(3).into(s).at, 15, 0);
  expect_at(Def(Kind::Point).c(3, true).l(4).s2().into(s).at, 15, 0);
  // Tangent: one point, whichever is asked for.
  Def(Kind::Line, 5).xy(0, 5).a(0).into(s);
  expect_at(Def(Kind::Point).l(5).c(3).s2().into(s).at, 10, 5);
  Def(Kind::Line, 6).xy(0, 9).a(0).into(s);
  EXPECT_EQ(Def(Kind::Point).l(6).c(3).in(s).why, "l6 and c3 do not meet");
}

TEST(GtlPoint, TwoCirclesLeftOfTheCentresFirst) {
  Store s;
  // §2.11.10 example 3: p2 = c3, c4 = (-47.404, 52.109).
  Def(Kind::Circle, 3).centre(-65, 0, 55).into(s);
  Def(Kind::Circle, 4).centre(0, 80, 55).into(s);
  expect_at(Def(Kind::Point).c(3).c(4).into(s).at, -47.404, 52.109);
  const Vec other = Def(Kind::Point).c(3).c(4).s2().into(s).at;
  // Figure 2.56: swapping the circles swaps left and right.
  expect_at(Def(Kind::Point).c(4).c(3).s2().into(s).at, -47.404, 52.109);
  expect_at(Def(Kind::Point).c(4).c(3).into(s).at, other.x(), other.y());
  EXPECT_NEAR((other - Vec(-65, 0)).norm(), 55, 1e-9);
  Def(Kind::Circle, 5).centre(500, 0, 5).into(s);
  EXPECT_EQ(Def(Kind::Point).c(3).c(5).in(s).why, "c3 and c5 do not meet");
  EXPECT_EQ(Def(Kind::Point).c(3).c(9).in(s).why, "c9 is not defined before this block");
}

TEST(GtlLine, ThroughPointsAndAtAngles) {
  Store s;
  EXPECT_NEAR(degrees(Def(Kind::Line).xy(40, 20).xy(60, 70).into(s).dir), 68.199, kTol);  // figure 2.61
  Def(Kind::Point, 7).xy(1, 1).into(s);
  Def(Kind::Point, 8).xy(1, -4).into(s);
  EXPECT_NEAR(degrees(Def(Kind::Line).p(7).p(8).into(s).dir), -90, 1e-9);  // figure 2.69: p7 to p8
  EXPECT_EQ(Def(Kind::Line).p(7).p(7).in(s).why, "a line through two points needs two different points");
  EXPECT_NEAR(degrees(Def(Kind::Line).p(7).a(45).into(s).dir), 45, 1e-9);
}

TEST(GtlLine, TangentToACircle) {
  Store s;
  // Figure 2.62: from X10 Y15 to the circle about I45 J30, either direction.
  Element l1 = Def(Kind::Line).xy(10, 15).centre(45, 30, -15).into(s);
  EXPECT_NEAR(degrees(l1.dir), 46.397, kTol);
  Element l2 = Def(Kind::Line).xy(10, 15).centre(45, 30, 15).into(s);
  EXPECT_NEAR(degrees(l2.dir), 0, kTol);
  EXPECT_NEAR(side_distance(l2, {45, 30}), 15, 1e-9);  // the circle on its left: counter-clockwise
  // Contact points: where the circle touches the line.
  expect_at(contact(l1, {45, 30}, -15), 34.138, 40.345);
  expect_at(contact(l2, {45, 30}, 15), 45, 15);
  // From the circle to the point: the same line the other way round the circle.
  Def(Kind::Circle, 1).centre(45, 30, 15).into(s);
  Def(Kind::Point, 1).xy(10, 15).into(s);
  const Element back = Def(Kind::Line).c(1).p(1).into(s);
  EXPECT_NEAR(side_distance(back, {45, 30}), 15, 1e-9);
  EXPECT_GT(back.dir.dot(Vec(10, 15) - contact(back, {45, 30}, 15)), 0);  // from the contact to the point
  Def(Kind::Point, 2).xy(45, 31).into(s);
  EXPECT_EQ(Def(Kind::Line).p(2).c(1).in(s).why,
            "the point lies inside the circle: no line through it touches the circle");
  // Figure 2.65: a tangent at 45 degrees touches at (88.284, 51.716).
  const Element l = Def(Kind::Line).centre(60, 80, 40).a(45).into(s);
  EXPECT_NEAR(side_distance(l, {60, 80}), 40, 1e-9);
  expect_at(contact(l, {60, 80}, 40), 88.284, 51.716);
  // Figure 2.74: the reversed circle gives the tangent on the other side.
  const Element other = Def(Kind::Line).c(1, true).a(50).into(s);
  EXPECT_NEAR(side_distance(other, {45, 30}), -15, 1e-9);
}

TEST(GtlLine, TangentToTwoCircles) {
  Store s;
  // Figure 2.67: crossed tangent, figure 2.68: outer tangent.
  const Element crossed = Def(Kind::Line).centre(25, 35, -17).centre(70, 20, 13).into(s);
  EXPECT_NEAR(degrees(crossed.dir), -57.6665, 0.0001);  // the digest's -57.667 rounds -57.66647 up
  expect_at(contact(crossed, {25, 35}, -17), 39.364, 44.092);
  expect_at(contact(crossed, {70, 20}, 13), 59.016, 13.047);
  const Element outer = Def(Kind::Line).centre(25, 35, 17).centre(70, 20, 13).into(s);
  EXPECT_NEAR(degrees(outer.dir), -13.598, kTol);
  expect_at(contact(outer, {25, 35}, 17), 21.003, 18.476);
  expect_at(contact(outer, {70, 20}, 13), 66.944, 7.364);
  EXPECT_EQ(Def(Kind::Line).centre(0, 0, 5).centre(0, 0, 7).in(s).why,
            "the two circles have one centre: no line touches both");
  EXPECT_EQ(Def(Kind::Line).centre(0, 0, 10).centre(3, 0, -1).in(s).why,
            "no line touches both circles in their directions: one lies inside the other's reach");
}

TEST(GtlLine, Parallel) {
  Store s;
  Def(Kind::Line, 1).xy(0, 0).a(0).into(s);
  expect_at(Def(Kind::Line).l(1).d(20).into(s).at, 0, 20);    // figure 2.75: left
  expect_at(Def(Kind::Line).l(1).d(-15).into(s).at, 0, -15);  // figure 2.76: right
  const Element back = Def(Kind::Line).l(1, true).d(5).into(s);
  expect_at(back.at, 0, -5);
  expect_at(back.dir, -1, 0);
}

TEST(GtlCircle, ExplicitForms) {
  Store s;
  Def(Kind::Origin, 1).xy(20, 21).a(45).into(s);
  // §2.11.10 example 3: c6 = o1 I-38 J-35 r10.
  expect_at(Def(Kind::Circle).centre(-38, -35, 10, 1).into(s).at, 17.879, -30.619);
  expect_at(Def(Kind::Circle).polar(70, 30).r(15).into(s).at, 60.622, 35);  // figure 2.83
  EXPECT_EQ(Def(Kind::Circle).centre(1, 1, 0).in(s).why, "a circle's radius r is not 0");
  Def(Kind::Point, 1).xy(3, 4).into(s);
  EXPECT_NEAR(Def(Kind::Circle).p(1).r(-40).into(s).r, -40, 0);  // figure 2.96
}

TEST(GtlCircle, CentreAndTangent) {
  Store s;
  Def(Kind::Point, 1).xy(0, 10).into(s);
  Def(Kind::Line, 1).xy(0, 0).a(0).into(s);
  // A counter-clockwise circle has its centre left of its direction where it touches.
  EXPECT_NEAR(Def(Kind::Circle).p(1).l(1).into(s).r, 10, 1e-9);
  EXPECT_NEAR(Def(Kind::Circle).p(1).l(1, true).into(s).r, -10, 1e-9);
  Def(Kind::Circle, 2).centre(0, 30, 5).into(s);
  // Centre p1, tangent to c2 (20 away): radius 5 - 20 = -15 (smaller) or 25 (s2).
  EXPECT_NEAR(Def(Kind::Circle).p(1).c(2).into(s).r, -15, 1e-9);
  EXPECT_NEAR(Def(Kind::Circle).p(1).c(2).s2().into(s).r, 25, 1e-9);
  Def(Kind::Point, 2).xy(0, 0).into(s);
  EXPECT_EQ(Def(Kind::Circle).p(2).l(1).in(s).why, "the centre lies on the line: the circle would have radius 0");
}

TEST(GtlCircle, ThroughThreePointsAndConcentric) {
  Store s;
  Def(Kind::Point, 1).xy(10, 0).into(s);
  Def(Kind::Point, 2).xy(0, 10).into(s);
  Def(Kind::Point, 3).xy(-10, 0).into(s);
  Element c1 = Def(Kind::Circle, 1).p(1).p(2).p(3).into(s);
  expect_at(c1.at, 0, 0);
  EXPECT_NEAR(c1.r, 10, 1e-9);                                         // counter-clockwise: p1, p2, p3 turn left
  EXPECT_NEAR(Def(Kind::Circle).p(3).p(2).p(1).into(s).r, -10, 1e-9);  // figure 2.95
  Def(Kind::Point, 4).xy(20, 0).into(s);
  EXPECT_EQ(Def(Kind::Circle).p(1).p(4).p(3).in(s).why, "the three points lie on one line");
  EXPECT_NEAR(Def(Kind::Circle).c(1).d(4).into(s).r, 6, 1e-9);  // to the left of a counter-clockwise circle: inside
  EXPECT_NEAR(Def(Kind::Circle).c(1, true).d(4).into(s).r, -14, 1e-9);  // figure 2.97's form, reversed
  EXPECT_EQ(Def(Kind::Circle).c(1).d(12).in(s).why,
            "the distance 12 is not less than the radius 10: no circle is left");
}

TEST(GtlCircle, GivenRadiusSmallerArcFromFirstToSecond) {
  Store s;
  // §2.11.10 example 3: c2 = c1, p3, r40 lands on the helper circle c4's centre (0, 80).
  Def(Kind::Circle, 3).centre(-65, 0, 55).into(s);
  Def(Kind::Circle, 4).centre(0, 80, 55).into(s);
  Def(Kind::Point, 2).c(3).c(4).into(s);
  Def(Kind::Circle, 1).p(2).r(-15).into(s);
  Def(Kind::Point, 3).xy(40, 80).into(s);
  const Element c2 = Def(Kind::Circle, 2).c(1).p(3).r(40).into(s);
  expect_at(c2.at, 0, 80);
  // The storage example (§2.11.2): c1 = l1, l2, r15 about (29.046, 70.259).
  Store t;
  Def(Kind::Origin, 1).xy(30, 30).a(45).into(t);
  expect_at(Def(Kind::Point, 1).xy(15, 15, 1).into(t).at, 30, 51.213);
  Def(Kind::Point, 2).xy(60, 30).into(t);
  EXPECT_NEAR(degrees(Def(Kind::Line, 1).p(1).p(2).into(t).dir), -35.264, kTol);
  Def(Kind::Line, 2).xy(30, 50).a(45).into(t);
  expect_at(Def(Kind::Circle, 1).l(1).l(2).r(15).into(t).at, 29.046, 70.259);
  Def(Kind::Line, 3).xy(0, 0).xy(100, 60).into(t);
  EXPECT_EQ(Def(Kind::Point, 3).l(3).c(1).in(t).why, "l3 and c1 do not meet");
  // What is defined from an element whose definition failed fails without a message.
  t.fail(Kind::Point, 3);
  EXPECT_EQ(Def(Kind::Circle).p(3).r(8).in(t).why, "");
  EXPECT_EQ(Def(Kind::Circle).p(4).r(8).in(t).why, "p4 is not defined before this block");
  // Through two points: the shorter arc from the first to the second.
  Def(Kind::Point, 5).xy(0, 0).into(t);
  Def(Kind::Point, 6).xy(10, 0).into(t);
  expect_at(Def(Kind::Circle).p(5).p(6).r(10).into(t).at, 5, 8.660);
  expect_at(Def(Kind::Circle).p(6).p(5).r(10).into(t).at, 5, -8.660);
  EXPECT_EQ(Def(Kind::Circle).p(5).p(6).r(4).in(t).why,
            "no circle of radius 4 runs from p5 to p6: no circle of that radius touches both");
  // Two lines: one centre, on the left of both for a counter-clockwise circle.
  Def(Kind::Line, 7).xy(0, 0).a(0).into(t);
  Def(Kind::Line, 8).xy(50, 0).a(90).into(t);
  expect_at(Def(Kind::Circle).l(7).l(8).r(5).into(t).at, 45, 5);
}

// ---- Profiles -------------------------------------------------------------------------

struct Path {
  Profile profile;
  std::vector<Piece> pieces;
  void take() {
    for (const Piece& p : profile.take()) pieces.push_back(p);
  }
};

TEST(GtlProfile, Example1ClosedWithFillets) {
  // §2.11.10 example 1 without compensation: the nominal path of its derivation.
  Store s;
  Def(Kind::Line, 1).xy(70, 40).a(150).into(s);
  Def(Kind::Line, 2).xy(8, 8).a(-95).into(s);
  Def(Kind::Point, 1).l(1).l(2).into(s);
  Def(Kind::Line, 3).xy(8, 8).xy(70, 15).into(s);
  Def(Kind::Line, 4).xy(50, 0).a(90).into(s);
  Def(Kind::Circle, 1).centre(70, 40, -25).into(s);
  Def(Kind::Circle, 2).p(1).r(-20).into(s);
  Path run;
  auto el = [&](Kind k, int n, bool s2, size_t tag) { run.profile.element(*s.find(k, n), {k, n}, s2, tag); };
  run.profile.open_closed(*s.find(Kind::Line, 2), {Kind::Line, 2}, false, 12, 0, 0, {});
  el(Kind::Line, 3, false, 13);
  run.profile.fillet(3, 14);
  el(Kind::Line, 4, false, 15);
  run.profile.fillet(3, 16);
  el(Kind::Circle, 1, false, 17);
  run.profile.fillet(5, 18);
  el(Kind::Line, 1, false, 19);
  run.profile.fillet(5, 20);
  el(Kind::Circle, 2, true, 21);
  el(Kind::Line, 2, false, 22);
  run.profile.close_with({Kind::Line, 3}, 23);
  run.take();
  ASSERT_FALSE(run.profile.take_problem());
  const std::vector<std::pair<size_t, Vec>> expected = {{12, {8, 8}},
                                                        {13, {47.337, 12.441}},
                                                        {14, {50, 15.422}},
                                                        {15, {50, 24.031}},
                                                        {16, {49.464, 25.742}},
                                                        {17, {46.569, 48.717}},
                                                        {18, {44.383, 54.790}},
                                                        {19, {34.859, 60.288}},
                                                        {20, {28.617, 59.274}},
                                                        {21, {11.903, 52.612}},
                                                        {22, {8, 8}}};
  ASSERT_EQ(run.pieces.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(run.pieces[i].tag, expected[i].first) << i;
    expect_at(run.pieces[i].to, expected[i].second.x(), expected[i].second.y());
  }
  EXPECT_TRUE(run.pieces[2].arc);
  EXPECT_TRUE(run.pieces[2].ccw);
  expect_at(run.pieces[2].centre, 47, 15.422);
  EXPECT_FALSE(run.pieces[5].ccw);  // c1 clockwise
}

TEST(GtlProfile, OpenWithCompensationAndHeldBlocks) {
  // A square corner under G42 (tool right), radius 2: the offsets meet inside.
  Store s;
  Def(Kind::Line, 1).xy(0, 0).a(0).into(s);
  Def(Kind::Line, 2).xy(10, 0).a(90).into(s);
  Path run;
  run.profile.open_at({0, 0}, 1, -1, 2, {});
  run.profile.hold(2);  // Z-10
  run.profile.element(*s.find(Kind::Line, 1), {Kind::Line, 1}, false, 3);
  EXPECT_EQ(run.profile.take().size(), 2u);  // the approach, then Z
  run.profile.element(*s.find(Kind::Line, 2), {Kind::Line, 2}, false, 4);
  run.take();
  ASSERT_EQ(run.pieces.size(), 1u);
  expect_at(run.pieces[0].to, 12, -2);  // outside corner of a left turn under G42: the offsets meet
  run.profile.close_at({10, 20}, 5);
  run.take();
  ASSERT_EQ(run.pieces.size(), 2u);
  expect_at(run.pieces[1].to, 12, 20);
  EXPECT_FALSE(run.profile.take_problem());
}

TEST(GtlProfile, RollRoundAnOutsideCornerWithR0) {
  Store s;
  Def(Kind::Line, 1).xy(0, 0).a(0).into(s);
  Def(Kind::Line, 2).xy(10, 0).a(90).into(s);
  Path run;
  run.profile.open_at({0, 0}, 1, -1, 2, {});
  run.profile.element(*s.find(Kind::Line, 1), {Kind::Line, 1}, false, 2);
  run.profile.fillet(0, 3);
  run.profile.element(*s.find(Kind::Line, 2), {Kind::Line, 2}, false, 4);
  run.take();
  ASSERT_EQ(run.pieces.size(), 3u);
  expect_at(run.pieces[1].to, 10, -2);
  EXPECT_TRUE(run.pieces[2].arc);
  EXPECT_TRUE(run.pieces[2].ccw);  // beside a G42 path it turns counter-clockwise
  expect_at(run.pieces[2].centre, 10, 0);
  expect_at(run.pieces[2].to, 12, 0);
}

TEST(GtlProfile, Chamfer) {
  Store s;
  Def(Kind::Line, 1).xy(0, 0).a(0).into(s);
  Def(Kind::Line, 2).xy(10, 0).a(90).into(s);
  Path run;
  run.profile.open_at({0, 0}, 1, 0, 0, {});
  run.profile.element(*s.find(Kind::Line, 1), {Kind::Line, 1}, false, 2);
  run.profile.chamfer(3, 3);
  run.profile.element(*s.find(Kind::Line, 2), {Kind::Line, 2}, false, 4);
  run.profile.close_at({10, 10}, 5);
  run.take();
  ASSERT_EQ(run.pieces.size(), 4u);
  expect_at(run.pieces[1].to, 7, 0);
  expect_at(run.pieces[2].to, 10, 3);
  EXPECT_EQ(run.pieces[2].tag, 3u);
  expect_at(run.pieces[3].to, 10, 10);
}

TEST(GtlProfile, Problems) {
  Store s;
  Def(Kind::Line, 1).xy(0, 0).a(0).into(s);
  Def(Kind::Line, 2).xy(0, 5).a(0).into(s);
  Def(Kind::Circle, 1).centre(5, 0, 3).into(s);
  auto problem = [&](auto steps) {
    Profile p;
    steps(p);
    auto got = p.take_problem();
    return got ? std::to_string(got->tag) + ": " + got->what : std::string();
  };
  // An element of the store, called in the block `tag`.
  auto call = [&](Profile& p, Kind k, int n, size_t tag) { p.element(*s.find(k, n), {k, n}, false, tag); };
  EXPECT_EQ(problem([&](Profile& p) {
              p.open_at({0, 1}, 1, 0, 0, {});
              call(p, Kind::Line, 1, 2);
            }),
            "2: the profile's start point X0 Y1 does not lie on its first element l1 (§2.11.8.2)");
  EXPECT_EQ(problem([&](Profile& p) {
              p.open_at({0, 0}, 1, 0, 0, {});
              call(p, Kind::Line, 1, 2);
              call(p, Kind::Line, 2, 3);
            }),
            "3: l1 and l2 do not meet: join them with a fillet r (§2.11.9)");
  EXPECT_EQ(problem([&](Profile& p) {
              p.open_at({0, 0}, 1, 0, 0, {});
              p.fillet(2, 2);
            }),
            "2: a profile does not start with a fillet: r comes between two elements (§2.11.9.2)");
  EXPECT_EQ(problem([&](Profile& p) {
              p.open_at({0, 0}, 1, 0, 0, {});
              call(p, Kind::Line, 1, 2);
              p.chamfer(1, 3);
              call(p, Kind::Circle, 1, 4);
            }),
            "3: a chamfer b joins two lines; c1 is a circle (§2.11.9.3)");
  EXPECT_EQ(problem([&](Profile& p) {
              p.open_at({0, 0}, 1, 1, 4, {});
              call(p, Kind::Circle, 1, 2);
            }),
            "2: the tool radius 4 is larger than the radius 3 of c1 on its inside: the tool cannot follow it");
  EXPECT_EQ(problem([&](Profile& p) {
              p.open_at({9, 0}, 1, 0, 0, {});
              call(p, Kind::Line, 1, 2);
              p.close_at({3, 0}, 3);
            }),
            "2: l1 would run against its direction, from X9 Y0 back to X3 Y0 (§2.11.1)");
}

}  // namespace
}  // namespace ncc::gtl
