#include "svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>

#include "support/text.h"

namespace ncc::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMargin = 48;  // px round the drawing
constexpr double kTop = 72;     // px above it: the title, and room for the axes' letters
constexpr double kLegend = 40;  // px below it
// Okabe and Ito's colours that read on white, then two of Tol's: a colour a tool.
constexpr std::array<std::string_view, 8> kColours = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                                      "#e69f00", "#56b4e9", "#882255", "#44aa99"};

struct Point {
  double h = 0, v = 0;  // mm across and up the view
};

// Where an axis of X Y Z goes in the view (the others do not show).
Point axis_direction(View view, int axis) {
  static const double r2 = std::sqrt(0.5), r6 = std::sqrt(1.0 / 6);
  switch (view) {
    case View::XY: return axis == 0 ? Point{1, 0} : axis == 1 ? Point{0, 1} : Point{};
    case View::XZ: return axis == 0 ? Point{1, 0} : axis == 2 ? Point{0, 1} : Point{};
    case View::YZ: return axis == 1 ? Point{1, 0} : axis == 2 ? Point{0, 1} : Point{};
    case View::Iso:  // seen from the front, right and above: (1, -1, 1)
      return axis == 0 ? Point{r2, -r6} : axis == 1 ? Point{r2, r6} : axis == 2 ? Point{0, 2 * r6} : Point{};
  }
  return {};
}

class Projection {
 public:
  explicit Projection(View view) {
    for (int i = 0; i < 3; ++i) dir_[i] = axis_direction(view, i);
  }
  Point operator()(const AxisValues& p) const {
    Point q;
    for (int i = 0; i < 3; ++i) {
      q.h += dir_[i].h * p[i];
      q.v += dir_[i].v * p[i];
    }
    return q;
  }
  // +1 or -1 when the plane faces the view (its normal axis does not show), with the
  // sign of the turn from u to v on the view; 0 when the view sees it slanted.
  int facing(const Plane& pl) const {
    auto dir = [&](int axis) { return axis >= 0 && axis < 3 ? dir_[axis] : Point{}; };
    const Point w = dir(pl.w), u = dir(pl.u), v = dir(pl.v);
    if (pl.w < 0 || pl.w > 2 || w.h != 0 || w.v != 0) return 0;
    const double det = u.h * v.v - u.v * v.h;
    return det > 0.5 ? 1 : det < -0.5 ? -1 : 0;
  }

 private:
  Point dir_[3];
};

// "12.5", "-3", "0": four decimals at most, never "-0".
void number(std::string& out, double x) {
  double r = std::round(x * 1e4) / 1e4;
  if (r == 0) r = 0;
  char buffer[64];
  char* end = std::to_chars(buffer, buffer + sizeof buffer, r, std::chars_format::fixed, 4).ptr;
  while (end[-1] == '0') --end;
  if (end[-1] == '.') --end;
  out.append(buffer, end);
}

void point(std::string& out, char command, Point p) {
  out += command;
  number(out, p.h);
  out += ' ';
  number(out, p.v);
}

// An arc's point at fraction t of its sweep; the other axes go linearly (a helix).
AxisValues arc_point(const Move& m, double t) {
  AxisValues p;
  for (int i = 0; i < kAxisCount; ++i) p[i] = m.start[i] + t * (m.end[i] - m.start[i]);
  const double a0 = std::atan2(m.start[m.plane.v] - m.centre[1], m.start[m.plane.u] - m.centre[0]);
  const double a = a0 + t * m.sweep * kPi / 180;
  p[m.plane.u] = m.centre[0] + m.radius * std::cos(a);
  p[m.plane.v] = m.centre[1] + m.radius * std::sin(a);
  return p;
}

// Chords within `tolerance` of the arc: n of them, n >= 1.
int chords(const Move& m, double tolerance) {
  const double sweep = std::fabs(m.sweep) * kPi / 180;
  const double step = m.radius > tolerance ? 2 * std::acos(1 - tolerance / m.radius) : kPi / 2;
  return std::clamp(static_cast<int>(std::ceil(sweep / step)), 1, 1 << 16);
}

class Writer {
 public:
  Writer(const PlotInput& in) : in_(in), project_(in.view) {}

  std::string write() {
    const Toolpath& path = *in_.path;
    // The first move starts where the machine happened to stand (the profile's initial
    // position): it may leave the drawing rather than shrink the program to a corner.
    bool started[8] = {};
    for (const Move& m : path.moves) {
      extend(m, started[m.process & 7]);
      started[m.process & 7] = true;
    }
    if (!(lo_.h <= hi_.h)) lo_ = hi_ = {0, 0};  // nothing moved: the work zero alone
    extend_point({0, 0});
    const double span = std::max({hi_.h - lo_.h, hi_.v - lo_.v, 1e-3});
    scale_ = (in_.size - 2 * kMargin) / span;
    const double width = std::ceil((hi_.h - lo_.h) * scale_ + 2 * kMargin);
    const double height = std::ceil((hi_.v - lo_.v) * scale_ + kTop + kMargin + kLegend);
    out_ += fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
        "font-family=\"sans-serif\" font-size=\"12\">\n",
        width, height);
    out_ += "<title>" + xml(in_.title) + "</title>\n";
    out_ +=
        "<style>path{fill:none;vector-effect:non-scaling-stroke;stroke-width:1.2}"
        ".r{stroke-dasharray:5 4;stroke-width:.8;opacity:.7}.p{stroke:#444;stroke-width:.6;opacity:.6}"
        ".d{stroke-width:6;stroke-linecap:round}";
    for (size_t i = 0; i < kColours.size(); ++i) out_ += fmt::format(".c{}{{stroke:{}}}", i, kColours[i]);
    out_ += "</style>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    // The path in mm, y up: the numbers are the trace's.
    out_ += "<g transform=\"matrix(";
    number(out_, scale_);
    out_ += " 0 0 ";
    number(out_, -scale_);
    out_ += ' ';
    number(out_, kMargin - lo_.h * scale_);
    out_ += ' ';
    number(out_, kTop + hi_.v * scale_);
    out_ += ")\">\n<g id=\"path\">\n";
    for (const Move& m : path.moves)
      if (!m.programmed) move(m);
    out_ += "</g>\n<g id=\"programmed\">\n";
    for (const Move& m : path.moves)
      if (m.programmed) move(m);
    out_ += "</g>\n</g>\n";
    annotations(height);
    out_ += "</svg>\n";
    return std::move(out_);
  }

 private:
  void extend_point(Point p) {
    lo_.h = std::min(lo_.h, p.h);
    lo_.v = std::min(lo_.v, p.v);
    hi_.h = std::max(hi_.h, p.h);
    hi_.v = std::max(hi_.v, p.v);
  }

  void extend(const Move& m, bool with_start) {
    if (with_start) extend_point(project_(m.start));
    extend_point(project_(m.end));
    if (m.kind != MoveKind::Arc) return;
    const int n = std::min(chords(m, m.radius / 100), 4096);  // within 1 % of the radius: the margin takes the rest
    for (int k = 1; k < n; ++k) extend_point(project_(arc_point(m, static_cast<double>(k) / n)));
  }

  int colour(int tool) {
    auto [it, added] = colours_.try_emplace(tool, static_cast<int>(colours_.size() % kColours.size()));
    if (added) tools_.push_back(tool);
    return it->second;
  }

  void move(const Move& m) {
    out_ += "<path class=\"";
    const Point from = project_(m.start), to = project_(m.end);
    // A cut straight into the view (a drilled hole seen from above) shows as a dot.
    const bool into = m.kind != MoveKind::Arc && std::fabs(from.h - to.h) < 1e-9 && std::fabs(from.v - to.v) < 1e-9;
    if (m.programmed)
      out_ += 'p';
    else
      out_ += fmt::format("{}c{}", m.kind == MoveKind::Rapid ? "r " : into ? "d " : "", colour(m.tool));
    out_ += "\" d=\"";
    point(out_, 'M', from);
    const int facing = m.kind == MoveKind::Arc ? project_.facing(m.plane) : 0;
    if (m.kind != MoveKind::Arc) {
      point(out_, 'L', to);
    } else if (facing != 0) {
      // Seen face on, an arc (and a helix) is an arc: pieces of at most 180 degrees.
      const int pieces = std::max(1, static_cast<int>(std::ceil(std::fabs(m.sweep) / 180 - 1e-9)));
      const bool positive = (m.sweep > 0) == (facing > 0);
      for (int k = 1; k <= pieces; ++k) {
        out_ += 'A';
        number(out_, m.radius);
        out_ += ' ';
        number(out_, m.radius);
        out_ += positive ? " 0 0 1 " : " 0 0 0 ";
        const Point p = project_(k == pieces ? m.end : arc_point(m, static_cast<double>(k) / pieces));
        number(out_, p.h);
        out_ += ' ';
        number(out_, p.v);
      }
    } else {
      const int n = chords(m, in_.tolerance);
      for (int k = 1; k < n; ++k) point(out_, 'L', project_(arc_point(m, static_cast<double>(k) / n)));
      point(out_, 'L', project_(m.end));
    }
    out_ += "\"><title>";
    if (m.source < in_.labels.size()) out_ += xml(in_.labels[m.source]);
    out_ += "</title></path>\n";
  }

  Point screen(Point p) const { return {kMargin + (p.h - lo_.h) * scale_, kTop + (hi_.v - p.v) * scale_}; }

  // The work zero with the view's axes, the legend and the scale, in px.
  void annotations(double height) {
    const Point zero = screen({0, 0});
    out_ += "<g id=\"axes\" stroke=\"#000\" stroke-width=\"1\">\n";
    for (int i = 0; i < 3; ++i) {
      const Point d = axis_direction(in_.view, i);
      if (d.h == 0 && d.v == 0) continue;
      const Point end{zero.h + 40 * d.h, zero.v - 40 * d.v};
      out_ +=
          fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\"/>", zero.h, zero.v, end.h, end.v);
      out_ += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" stroke=\"none\" text-anchor=\"middle\">{}</text>\n",
                          zero.h + 50 * d.h, zero.v - 50 * d.v + 4, "XYZ"[i]);
    }
    out_ += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\" fill=\"none\"/></g>\n", zero.h, zero.v);
    // Other work zeros the program selected, where they are from this one.
    std::map<int, Point> zeros;
    for (const OffsetChange& c : in_.path->offsets) {
      AxisValues at{};
      for (int i = 0; i < kAxisCount; ++i) at[i] = c.values[i] - in_.path->origin[i];
      const Point p = project_(at);
      if (std::hypot(p.h, p.v) * scale_ > 1) zeros[c.number] = p;
    }
    for (const auto& [n, p] : zeros) {
      const Point s = screen(p);
      out_ += fmt::format(
          "<g stroke=\"#666\"><circle cx=\"{0:.1f}\" cy=\"{1:.1f}\" r=\"3\" fill=\"none\"/>"
          "<text x=\"{2:.1f}\" y=\"{3:.1f}\" stroke=\"none\" fill=\"#666\">zero {4}</text></g>\n",
          s.h, s.v, s.h + 6, s.v - 6, n < 0 ? std::string("of the program") : std::to_string(n));
    }
    // The legend: tools, then what the lines mean; the scale at the right.
    const double y = height - kLegend / 2;
    double x = kMargin;
    out_ += "<g id=\"legend\">\n";
    for (int tool : tools_) {
      out_ += fmt::format(
          "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" stroke-width=\"3\"/>", x, y - 4,
          x + 16, y - 4, kColours[static_cast<size_t>(colours_[tool])]);
      out_ += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n", x + 20, y,
                          tool ? fmt::format("T{}", tool) : "no tool");
      x += 64;
    }
    out_ += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#000\" "
        "stroke-dasharray=\"5 4\"/><text x=\"{3:.1f}\" y=\"{4:.1f}\">rapid</text>\n",
        x, y - 4, x + 24, x + 28, y);
    x += 72;
    if (std::any_of(in_.path->moves.begin(), in_.path->moves.end(), [](const Move& m) { return m.programmed; }))
      out_ += fmt::format(
          "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#444\" "
          "opacity=\".6\"/><text x=\"{3:.1f}\" y=\"{4:.1f}\">programmed path (the coloured one: the "
          "tool centre's)</text>\n",
          x, y - 4, x + 24, x + 28, y);
    // A scale of 1, 2 or 5 times a power of ten, 60 to 150 px long.
    double step = std::pow(10.0, std::floor(std::log10(60 / scale_)));
    for (double f : {1.0, 2.0, 5.0, 10.0})
      if (f * step * scale_ >= 60) {
        step *= f;
        break;
      }
    const double right = kMargin + (hi_.h - lo_.h) * scale_;
    out_ += fmt::format(
        "<g id=\"scale\"><line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#000\" "
        "stroke-width=\"2\"/><text x=\"{2:.1f}\" y=\"{3:.1f}\" text-anchor=\"end\">",
        std::max(kMargin, right - step * scale_), y + 6, std::max(kMargin + step * scale_, right), y - 2);
    number(out_, step);
    out_ += in_.view == View::Iso ? " mm in the view's plane</text></g>\n" : " mm</text></g>\n";
    out_ += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" font-weight=\"bold\">{}</text>\n</g>\n", kMargin, 24.0,
                        xml(fmt::format("{}, view {}", in_.title, view_name())));
  }

  std::string_view view_name() const {
    switch (in_.view) {
      case View::XY: return "XY (from above)";
      case View::XZ: return "XZ (from the front)";
      case View::YZ: return "YZ (from the right)";
      case View::Iso: return "isometric";
    }
    return "";
  }

  static std::string xml(std::string_view s) {
    std::string out;
    for (char c : s) {
      if (c == '<')
        out += "&lt;";
      else if (c == '>')
        out += "&gt;";
      else if (c == '&')
        out += "&amp;";
      else if (c == '"')
        out += "&quot;";
      else
        out += c;
    }
    return out;
  }

  const PlotInput& in_;
  Projection project_;
  Point lo_{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Point hi_{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  double scale_ = 1;            // px per mm
  std::map<int, int> colours_;  // tool -> colour, in the order tools appear
  std::vector<int> tools_;
  std::string out_;
};

}  // namespace

bool parse_view(std::string_view name, View& out) {
  if (name == "xy")
    out = View::XY;
  else if (name == "xz")
    out = View::XZ;
  else if (name == "yz")
    out = View::YZ;
  else if (name == "iso")
    out = View::Iso;
  else
    return false;
  return true;
}

std::string write_svg(const PlotInput& in) { return Writer(in).write(); }

}  // namespace ncc::sim
