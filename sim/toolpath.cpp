#include "toolpath.h"

#include <algorithm>
#include <cmath>

namespace ncc::sim {
namespace {

constexpr double kInch = 25.4;
constexpr int kMaxChords = 4096;  // of one parabola or spline span: a bound on the path's size, far below any tolerance

bool is_linear(const MachineConfig& m, int axis) { return m.axes[static_cast<size_t>(axis)].kind == AxisKind::Linear; }

}  // namespace

double move_length(const Move& m, const MachineConfig& machine) {
  const bool arc = m.kind == MoveKind::Arc && m.radius * m.sweep != 0;
  double linear = 0, rotary = 0;
  for (int i = 0; i < kAxisCount; ++i) {
    if (arc && (i == m.plane.u || i == m.plane.v)) continue;
    const double d = m.end[i] - m.start[i];
    (is_linear(machine, i) ? linear : rotary) += d * d;
  }
  if (arc) {
    const double in_plane = m.radius * std::fabs(m.sweep * M_PI / 180);
    return std::sqrt(in_plane * in_plane + linear);
  }
  return std::sqrt(linear > 0 ? linear : rotary);
}

double Toolpath::tool_radius(int tool) const {
  for (auto it = tool_radii.rbegin(); it != tool_radii.rend(); ++it)
    if (it->first == tool) return it->second;
  return 0;
}

ToolpathSink::ToolpathSink(Toolpath& path, const MachineConfig& machine, double chord_tolerance, size_t max_moves)
    : path_(path), machine_(machine), chord_tolerance_(chord_tolerance), max_moves_(max_moves) {
  for (AxisValues& at : at_) at = machine.initial_position;
  for (AxisValues& at : programmed_at_) at = machine.initial_position;
}

void ToolpathSink::event(const Event& e) {
  if (path_.stopped_at || path_.full_at) return;
  switch (e.kind) {
    case EventKind::Block:
      if (e.source < errors_.size() && errors_[e.source]) path_.stopped_at = e.source;
      ++run_;
      break;
    case EventKind::Units: scale_ = e.n == 1 ? kInch : 1; break;
    case EventKind::FeedMode: feed_mode_ = e.n; break;
    case EventKind::FeedRate: feed_rate_ = e.a; break;
    case EventKind::FeedReduction: feed_reduced_ = e.n == 1; break;
    case EventKind::SpindleSpeed:
      if (spindle_on_ && e.a != rpm_)
        path_.pauses.push_back({Pause::Kind::Spindle, e.process, count(), e.source, run_, 0, 0, rpm_, e.a});
      rpm_ = e.a;
      break;
    case EventKind::SpindleOn:
      if (!spindle_on_)
        path_.pauses.push_back({Pause::Kind::Spindle, e.process, count(), e.source, run_, 0, 0, 0, rpm_});
      spindle_on_ = true;
      break;
    case EventKind::SpindleStop:
      if (spindle_on_)
        path_.pauses.push_back({Pause::Kind::Spindle, e.process, count(), e.source, run_, 0, 0, rpm_, 0});
      spindle_on_ = false;
      break;
    case EventKind::Dwell: path_.pauses.push_back({Pause::Kind::Dwell, e.process, count(), e.source, run_, e.a}); break;
    case EventKind::ChangeTool:
      tool_ = e.n;
      path_.pauses.push_back({Pause::Kind::ToolChange, e.process, count(), e.source, run_, 0, e.n});
      if (auto it = machine_.offsets.find(e.n); it != machine_.offsets.end() && it->second.radius > 0)
        path_.tool_radii.push_back({e.n, it->second.radius});
      break;
    case EventKind::CutterComp:
      // The programmed path starts where the tool centre stands as compensation starts.
      if (e.n != 0) programmed_at_[e.process & 7] = at_[e.process & 7];
      if (e.n != 0 && e.a > 0) path_.tool_radii.push_back({tool_, e.a * scale_});
      break;
    case EventKind::CompLoad:
      if (e.b > 0) path_.tool_radii.push_back({tool_, e.b * scale_});
      break;
    case EventKind::Stop:
    case EventKind::End:
      if (e.kind == EventKind::End || e.n != 2)
        path_.pauses.push_back({Pause::Kind::Stop, e.process, count(), e.source, run_});
      break;
    case EventKind::PathMode:
      // Modes 4-7 are modal (point-to-point: exact stop, G61); a decelerate (G09)
      // stops at the end of its own block's moves only.
      if (e.n >= 4) exact_stop_ = e.n == 6;
      if (e.n == 1) decelerate_run_ = run_;
      break;
    case EventKind::WorkOffset:
    case EventKind::Origin: {
      OffsetChange change{count(), e.kind == EventKind::Origin ? -1 : e.n, e.pos};
      for (int i = 0; i < kAxisCount; ++i)
        if (is_linear(machine_, i)) change.values[i] *= scale_;
      if (path_.moves.empty()) path_.origin = change.values;
      path_.offsets.push_back(change);
      break;
    }
    case EventKind::OperatorMove: at_[e.process & 7] = scaled(e.pos); break;
    case EventKind::Rapid:
    case EventKind::Linear:
    case EventKind::Arc:
    case EventKind::Parabola:
    case EventKind::Spline:
    case EventKind::Thread: add_move(e, false); break;
    default: break;
  }
}

void ToolpathSink::programmed(const Event& e) {
  if (!path_.stopped_at && !path_.full_at) add_move(e, true);
}

AxisValues ToolpathSink::scaled(const AxisValues& p) const {
  AxisValues q = p;
  for (int i = 0; i < kAxisCount; ++i)
    if (is_linear(machine_, i)) q[i] *= scale_;
  return q;
}

// The feed in mm/min a straight move or an arc of `length` mm asks for.
double ToolpathSink::feed(double length) const {
  const double slow = feed_reduced_ ? 100 : 1;  // pp M37: F / 100
  switch (feed_mode_) {
    case 0: return length * feed_rate_ / slow;  // inverse time: the move takes 1/F minutes
    case 2: return feed_rate_ * scale_ * rpm_ / slow;
    default: return feed_rate_ * scale_ / slow;
  }
}

void ToolpathSink::add_move(const Event& e, bool programmed) {
  if (path_.moves.size() >= max_moves_) {
    path_.full_at = e.source;
    return;
  }
  AxisValues& at = (programmed ? programmed_at_ : at_)[e.process & 7];
  Move m;
  m.programmed = programmed;
  m.process = e.process;
  m.tool = tool_;
  m.source = e.source;
  m.run = run_;
  m.start = at;
  m.end = scaled(e.pos);
  m.exact_stop = exact_stop_ || decelerate_run_ == run_;
  switch (e.kind) {
    case EventKind::Rapid: m.kind = MoveKind::Rapid; break;
    case EventKind::Linear:
      m.kind = MoveKind::Line;
      m.feed = feed(move_length(m, machine_));
      break;
    case EventKind::Thread:
      m.kind = MoveKind::Thread;
      m.feed = std::fabs(e.a) * scale_ * rpm_;
      break;
    case EventKind::Arc: {
      m.kind = MoveKind::Arc;
      m.plane = e.plane;
      const bool u_linear = is_linear(machine_, e.plane.u);
      m.centre[0] = e.centre[0] * (u_linear ? scale_ : 1);
      m.centre[1] = e.centre[1] * (is_linear(machine_, e.plane.v) ? scale_ : 1);
      m.radius = e.a * (u_linear ? scale_ : 1);
      m.sweep = e.rotation > 0 ? e.b : -e.b;
      m.feed = feed(move_length(m, machine_));
      break;
    }
    case EventKind::Parabola:
    case EventKind::Spline: {
      // Chords of the Bezier span (a parabola is quadratic, a spline span cubic): n of
      // them stay within the tolerance since a chord's error is at most |B''| h^2 / 8.
      const bool cubic = e.kind == EventKind::Spline;
      std::vector<AxisValues> p = {m.start, scaled(e.control)};
      if (cubic) p.push_back(scaled(e.control2));
      p.push_back(m.end);
      double bend = 0;
      for (size_t k = 0; k + 2 < p.size(); ++k) {
        double sum = 0;
        for (int i = 0; i < kAxisCount; ++i) {
          const double d = p[k][i] - 2 * p[k + 1][i] + p[k + 2][i];
          sum += d * d;
        }
        bend = std::max(bend, std::sqrt(sum) * (cubic ? 6 : 2));
      }
      const int n = std::clamp(static_cast<int>(std::ceil(std::sqrt(bend / (8 * chord_tolerance_)))), 1, kMaxChords);
      m.kind = MoveKind::Line;
      for (int k = 1; k <= n; ++k) {
        const double t = static_cast<double>(k) / n, s = 1 - t;
        Move chord = m;
        chord.start = at;
        for (int i = 0; i < kAxisCount; ++i)
          chord.end[i] =
              cubic ? s * s * s * p[0][i] + 3 * s * s * t * p[1][i] + 3 * s * t * t * p[2][i] + t * t * t * p[3][i]
                    : s * s * p[0][i] + 2 * s * t * p[1][i] + t * t * p[2][i];
        if (k == n) chord.end = m.end;
        chord.feed = feed(move_length(chord, machine_));
        path_.moves.push_back(chord);
        at = chord.end;
      }
      return;
    }
    default: return;
  }
  path_.moves.push_back(m);
  at = m.end;
}

void ToolpathSink::flush() {
  if (flushed_) return;
  flushed_ = true;
  // Positions from the work zero: the origin is in machine coordinates; an arc's
  // centre moves with its plane's axes.
  const AxisValues& o = path_.origin;
  for (Move& m : path_.moves) {
    for (int i = 0; i < kAxisCount; ++i) {
      m.start[i] -= o[i];
      m.end[i] -= o[i];
    }
    if (m.kind == MoveKind::Arc) {
      m.centre[0] -= o[m.plane.u];
      m.centre[1] -= o[m.plane.v];
    }
  }
}

}  // namespace ncc::sim
