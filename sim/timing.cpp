// The cycle-time models (timing.h). The rules they share:
//
// * Length: a move's path length over the linear axes (an arc's exact helical length);
//   a move of rotary axes alone is measured in degrees (LinuxCNC's rule), and a move of
//   both by its linear axes, the rotary ones following along.
// * Speed: the feed (mm/min; degrees/min for a rotary-only move), or for a rapid the
//   axes' rapid rates, capped so that no axis exceeds its limit anywhere on the move:
//   for each axis, limit / (its largest share of the path speed along the move; for an
//   arc, over the angles it sweeps). Feeds use each axis's `max_feed`, rapids its
//   `rapid`; [motion] max_velocity caps both along the path (not rotary-only moves).
//   A feed move without a feed runs at the axes' limits. Acceleration and jerk along a
//   move are capped the same way from the axes' values.
// * Threads run at their feed throughout (the spindle leads; no acceleration) and the
//   machine stands before and after each.
// * Pauses: a dwell its seconds, a tool change [motion] tool_change, a spindle change
//   |Δrpm| / spindle_acceleration; a stop nothing. A pause has the process of the move
//   before it.
//
// trapezoid and scurve: the machine stands at the start and end of each process, at
// every pause, after an exact stop, and between a rapid and a feed move (a rapid ends
// in position before the tool cuts, as an ISO control's G00 does; rapids chain with
// rapids and feeds with feeds). Elsewhere it passes a corner at grbl's junction speed
// v² = a·δ·sin(θ/2) / (1 − sin(θ/2)), θ the angle between the reversed incoming and
// the outgoing direction (arcs: their tangents), a the acceleration along the change of
// direction, δ [motion] junction_deviation; never faster than either move's speed. An
// arc is no faster than its centripetal limit sqrt(a·r), a of its plane's axes. A
// backward pass (each move slow enough to stop, or to reach the next move's speed, in
// its length) and a forward one (fast only as far as it can accelerate) over each
// process give every junction its speed; each move then accelerates to its speed (or
// as far as its length allows), cruises, and slows to the next junction.
//
// scurve: the same, with every speed change limited in jerk J along the move:
// acceleration ramps up at J to at most A and back down, so a change Δv takes
// Δv/A + A/J (Δv ≥ A²/J) or 2·sqrt(Δv/J), covering the mean of the two speeds times
// that; a speed change runs on through the junctions it stays below, so a chain of
// short collinear moves takes what one long move does. Simplifications: acceleration
// returns to zero wherever the speed meets a limit (a junction's, a stop, a cruise) and
// between speeding up and slowing down; a stretch between two such junctions is timed
// at the lowest cruise, acceleration and jerk of its moves; the centripetal limit
// ignores jerk.
#include "timing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace ncc::sim {

std::string_view model_name(TimeModel model) {
  switch (model) {
    case TimeModel::Feed: return "feed";
    case TimeModel::Trapezoid: return "trapezoid";
    case TimeModel::SCurve: return "scurve";
  }
  return "?";
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;

// A move's path as the clock sees it.
struct Geometry {
  double length = 0;  // mm; degrees for a move of rotary axes alone
  bool rotary_only = false;
  AxisValues share{};                 // per axis: the largest |d axis / d length| on the move
  AxisValues start_dir{}, end_dir{};  // unit tangents over every axis (degrees as mm)
  double radius = 0;                  // an arc's (0: straight)
  double plane_share = 0;             // an arc: the part of the path speed in its plane
  int plane_u = 0, plane_v = 1;
};

double norm(const AxisValues& v) {
  double sum = 0;
  for (double x : v) sum += x * x;
  return std::sqrt(sum);
}

AxisValues unit(AxisValues v) {
  double n = norm(v);
  if (n > 0)
    for (double& x : v) x /= n;
  return v;
}

// The largest |sin φ| for φ from `from` to `to` (from ≤ to).
double max_abs_sin(double from, double to) {
  if (to - from >= kPi) return 1;
  double peak = kPi / 2 + std::ceil((from - kPi / 2) / kPi) * kPi;  // the first |sin| = 1 at or after `from`
  if (peak <= to) return 1;
  return std::max(std::abs(std::sin(from)), std::abs(std::sin(to)));
}

Geometry straight(const Move& m, const MachineConfig& machine) {
  Geometry g;
  AxisValues delta{};
  g.rotary_only = true;
  for (size_t i = 0; i < delta.size(); ++i) {
    delta[i] = m.end[i] - m.start[i];
    if (delta[i] != 0 && machine.axes[i].kind == AxisKind::Linear) g.rotary_only = false;
  }
  g.length = move_length(m, machine);
  if (g.length == 0) return g;
  for (size_t i = 0; i < delta.size(); ++i) g.share[i] = std::abs(delta[i]) / g.length;
  g.start_dir = g.end_dir = unit(delta);
  return g;
}

Geometry arc(const Move& m, const MachineConfig& machine) {
  const size_t u = static_cast<size_t>(m.plane.u), v = static_cast<size_t>(m.plane.v);
  const double sweep = m.sweep * kPi / 180;
  const double in_plane = m.radius * std::abs(sweep);
  if (!(in_plane > 0)) return straight(m, machine);
  Geometry g;
  AxisValues delta{};  // the axes other than the plane's move along linearly
  for (size_t i = 0; i < delta.size(); ++i)
    if (i != u && i != v) delta[i] = m.end[i] - m.start[i];
  g.length = move_length(m, machine);
  g.radius = m.radius;
  g.plane_share = in_plane / g.length;
  g.plane_u = m.plane.u;
  g.plane_v = m.plane.v;
  const double start = std::atan2(m.start[v] - m.centre[1], m.start[u] - m.centre[0]);
  const double lo = std::min(start, start + sweep), hi = std::max(start, start + sweep);
  for (size_t i = 0; i < delta.size(); ++i) g.share[i] = std::abs(delta[i]) / g.length;
  g.share[u] = g.plane_share * max_abs_sin(lo, hi);                      // u' = −sin φ
  g.share[v] = g.plane_share * max_abs_sin(lo + kPi / 2, hi + kPi / 2);  // v' = cos φ
  auto tangent = [&](double angle) {
    AxisValues t = delta;
    for (double& x : t) x /= g.length;
    const double sense = sweep > 0 ? 1 : -1;
    t[u] = -sense * g.plane_share * std::sin(angle);
    t[v] = sense * g.plane_share * std::cos(angle);
    return unit(t);
  };
  g.start_dir = tangent(start);
  g.end_dir = tangent(start + sweep);
  return g;
}

Geometry geometry(const Move& m, const MachineConfig& machine) {
  return m.kind == MoveKind::Arc ? arc(m, machine) : straight(m, machine);
}

// The most a quantity along the path may be when each axis's is capped: min over
// the moving axes of limit_i / share_i.
template <typename Limit>
double along_path(const AxisValues& share, const MachineConfig& machine, Limit limit) {
  double most = kInf;
  for (size_t i = 0; i < share.size(); ++i)
    if (share[i] > 0) most = std::min(most, limit(machine.axes[i]) / share[i]);
  return most;
}

// One move of a process, as the planner drives it.
struct Segment {
  double length = 0;                 // mm (degrees)
  double cruise = 0;                 // mm/s: the fastest it may go
  double accel = kInf, jerk = kInf;  // mm/s², mm/s³ along the path
  double entry_limit = 0;            // mm/s at its start: the junction's speed; 0 where the machine stands
  bool constant = false;             // a thread: at `cruise` throughout
};

// The speed a move may not exceed: the feed or the rapid rates, the axes' limits, and
// for an arc in the acceleration models its centripetal limit.
double cruise_speed(const Move& m, const Geometry& g, const MachineConfig& machine, TimeModel model) {
  const bool rapid = m.kind == MoveKind::Rapid;
  double per_minute = along_path(g.share, machine, [&](const AxisConfig& a) { return rapid ? a.rapid : a.max_feed; });
  if (!rapid && m.feed > 0) per_minute = std::min(per_minute, m.feed);
  if (!g.rotary_only) per_minute = std::min(per_minute, machine.motion.max_velocity);
  double speed = per_minute / 60;
  if (model != TimeModel::Feed && g.radius > 0) {
    const auto& axes = machine.axes;
    double plane_accel =
        std::min(axes[static_cast<size_t>(g.plane_u)].acceleration, axes[static_cast<size_t>(g.plane_v)].acceleration);
    speed = std::min(speed, std::sqrt(plane_accel * g.radius) / g.plane_share);
  }
  return speed;
}

// grbl's junction speed between two unit directions.
double junction_speed(const AxisValues& in, const AxisValues& out, const MachineConfig& machine) {
  double cos_theta = 0;  // θ: between the reversed incoming direction and the outgoing one
  AxisValues change{};
  for (size_t i = 0; i < in.size(); ++i) {
    cos_theta -= in[i] * out[i];
    change[i] = std::abs(out[i] - in[i]);
  }
  const double sin_half = std::sqrt(std::max(0.0, (1 - cos_theta) / 2));
  if (sin_half >= 1) return kInf;  // straight on
  const double accel = along_path(unit(change), machine, [](const AxisConfig& a) { return a.acceleration; });
  return std::sqrt(accel * machine.motion.junction_deviation * sin_half / (1 - sin_half));
}

// The trapezoidal profile: constant acceleration `accel` along the move.
struct Trapezoid {
  static double reach(double from, const Segment& s) { return std::sqrt(from * from + 2 * s.accel * s.length); }
  static double time(double v0, double v1, const Segment& s) {
    const double a = s.accel;
    double peak = std::min(s.cruise, std::sqrt((2 * a * s.length + v0 * v0 + v1 * v1) / 2));
    peak = std::max(peak, std::max(v0, v1));
    const double ramps = (2 * peak * peak - v0 * v0 - v1 * v1) / (2 * a);
    return (2 * peak - v0 - v1) / a + std::max(0.0, s.length - ramps) / peak;
  }
};

// Each move's duration, by the look-ahead passes over one process's segments.
std::vector<double> plan_trapezoid(const std::vector<Segment>& segments) {
  const size_t n = segments.size();
  std::vector<double> speed(n + 1, 0);  // at the start of each segment; speed[n] at the end
  for (size_t i = n; i-- > 0;)
    speed[i] =
        segments[i].constant ? 0 : std::min(segments[i].entry_limit, Trapezoid::reach(speed[i + 1], segments[i]));
  for (size_t i = 0; i < n; ++i)
    if (!segments[i].constant) speed[i + 1] = std::min(speed[i + 1], Trapezoid::reach(speed[i], segments[i]));
  std::vector<double> duration(n);
  for (size_t i = 0; i < n; ++i) {
    const Segment& s = segments[i];
    duration[i] = s.constant ? s.length / s.cruise : Trapezoid::time(speed[i], speed[i + 1], s);
  }
  return duration;
}

// Jerk-limited speed changes: the acceleration ramps at j up to at most a and back
// to zero, so each change is an S whose speed is point-symmetric about its middle.
namespace scurve {

// The time of a change by dv ≥ 0.
double ramp_time(double dv, double a, double j) { return dv * j >= a * a ? dv / a + a / j : 2 * std::sqrt(dv / j); }

// Its length: the mean of the two speeds times its time.
double ramp_length(double v0, double v1, double a, double j) {
  return (v0 + v1) / 2 * ramp_time(std::abs(v1 - v0), a, j);
}

// The highest speed reachable from `from` within `length`, starting without acceleration.
double reach(double from, double length, double a, double j) {
  const double full = a * a / j;  // the smallest change at which the acceleration reaches a
  if (length <= (2 * from + full) * a / j) {
    // (2·from + dv)·sqrt(dv/j) = length: with x = sqrt(dv), x³ + 2·from·x − length·sqrt(j) = 0,
    // solved by Cardano as q / (U² + UW + W²) (U³ − W³ = q), free of cancellation.
    const double p = 2 * from, q = length * std::sqrt(j);
    const double root = std::sqrt(q * q / 4 + p * p * p / 27);
    const double big = std::cbrt(root + q / 2), small = std::cbrt(root - q / 2);
    const double x = q / (big * big + big * small + small * small);
    return from + x * x;
  }
  // (2·from + dv)/2 · (dv/a + a/j) = length: a quadratic in dv with c < 0.
  const double b = 2 * from + full, c = 2 * a * (from * a / j - length);
  return from - 2 * c / (b + std::sqrt(b * b - 4 * c));
}

// The distance and the speed gained over the starting speed in the first t seconds of
// a speed-up by dv: jerk j up to acceleration a, constant, then the same mirrored.
struct Gain {
  double distance, speed;
};
Gain ramp_gain(double t, double dv, double a, double j) {
  const double total = ramp_time(dv, a, j);
  if (t > total / 2) {  // the second half mirrors the first about the middle
    const Gain early = ramp_gain(total - t, dv, a, j);
    return {dv * total / 2 - dv * (total - t) + early.distance, dv - early.speed};
  }
  const double edge = std::min(a / j, total / 2);  // while the acceleration rises
  if (t <= edge) return {j * t * t * t / 6, j * t * t / 2};
  const double u = t - edge;
  return {j * edge * edge * edge / 6 + j * edge * edge / 2 * u + a * u * u / 2, j * edge * edge / 2 + a * u};
}

// A stretch from v0 to v1: up to `peak`, cruise, down (peak ≥ both; a ramp may be nil).
struct Shape {
  double v0, v1, peak, a, j;
  double up_time = 0, up_length = 0, cruise_time = 0, cruise_length = 0, down_time = 0;
  double time() const { return up_time + cruise_time + down_time; }
};

Shape shape(double v0, double v1, double cruise, double length, double a, double j) {
  auto ramps = [&](double top) { return ramp_length(v0, top, a, j) + ramp_length(top, v1, a, j); };
  double peak = std::max({cruise, v0, v1});
  if (ramps(peak) > length) {  // no cruise: the peak whose ramps fill the stretch, by bisection
    double lo = std::max(v0, v1), hi = peak;
    for (int i = 0; i < 200 && hi - lo > hi * 1e-15; ++i) {
      const double mid = (lo + hi) / 2;
      (ramps(mid) > length ? hi : lo) = mid;
    }
    peak = lo;
  }
  Shape s{v0, v1, peak, a, j};
  s.up_time = ramp_time(peak - v0, a, j);
  s.up_length = ramp_length(v0, peak, a, j);
  s.down_time = ramp_time(peak - v1, a, j);
  s.cruise_length = std::max(0.0, length - s.up_length - ramp_length(peak, v1, a, j));
  s.cruise_time = peak > 0 ? s.cruise_length / peak : 0;
  return s;
}

// The t in [0, span] at which position(t) = target, position rising with speed(t):
// Newton's steps kept inside a shrinking bracket.
template <typename Motion>
double solve_time(Motion motion, double target, double span) {
  double lo = 0, hi = span, t = span / 2;
  for (int i = 0; i < 100; ++i) {
    const auto [position, speed] = motion(t);
    (position < target ? lo : hi) = t;
    double next = speed > 0 ? t - (position - target) / speed : lo - 1;
    if (!(next > lo && next < hi)) next = (lo + hi) / 2;
    if (std::abs(next - t) <= 1e-15 * span || hi - lo <= 1e-15 * span) return next;
    t = next;
  }
  return t;
}

// The time at which the stretch has covered `distance`.
double time_at(const Shape& s, double distance) {
  if (distance <= s.up_length) {
    auto rising = [&](double t) {
      const Gain g = ramp_gain(t, s.peak - s.v0, s.a, s.j);
      return std::pair{s.v0 * t + g.distance, s.v0 + g.speed};
    };
    return solve_time(rising, distance, s.up_time);
  }
  distance -= s.up_length;
  if (distance <= s.cruise_length) return s.up_time + distance / s.peak;
  distance -= s.cruise_length;
  auto falling = [&](double t) {
    const Gain g = ramp_gain(t, s.peak - s.v1, s.a, s.j);
    return std::pair{s.peak * t - g.distance, s.peak - g.speed};
  };
  return s.up_time + s.cruise_time + solve_time(falling, distance, s.down_time);
}

// The passes of plan_trapezoid, but a speed-up or slow-down runs on through junctions
// whose limit it stays below, as one S: the acceleration returns to zero where the
// speed meets a limit, at a cruise and between speeding up and slowing down, not at
// every junction. So the passes carry the point each ramp started from; a stretch
// between two junctions at their limits is one shape, at the lowest cruise,
// acceleration and jerk of its moves, and a move takes the time the shape spends on it.
std::vector<double> plan(const std::vector<Segment>& segments) {
  const size_t n = segments.size();
  std::vector<double> at(n + 1, 0);  // distance from the start to each junction
  for (size_t i = 0; i < n; ++i) at[i + 1] = at[i] + segments[i].length;
  auto limit = [&](size_t i) { return i < n ? segments[i].entry_limit : 0.0; };
  std::vector<double> speed(n + 1, 0);
  // Backward: no faster than a ramp down to the nearest limit ahead allows.
  double from = 0, where = at[n], a = kInf, j = kInf;
  for (size_t i = n; i-- > 0;) {
    a = std::min(a, segments[i].accel);
    j = std::min(j, segments[i].jerk);
    const double most = reach(from, where - at[i], a, j);
    if (limit(i) <= most) {
      speed[i] = from = limit(i);
      where = at[i];
      a = j = kInf;
    } else {
      speed[i] = most;
    }
  }
  // Forward: no faster than a ramp up from the last point held to its speed allows.
  from = speed[0], where = 0, a = j = kInf;
  for (size_t i = 1; i <= n; ++i) {
    a = std::min(a, segments[i - 1].accel);
    j = std::min(j, segments[i - 1].jerk);
    const double most = reach(from, at[i] - where, a, j);
    if (speed[i] <= most) {
      from = speed[i];
      where = at[i];
      a = j = kInf;
    } else {
      speed[i] = most;
    }
  }
  std::vector<double> duration(n);
  for (size_t first = 0, last = 1; last <= n; ++last) {
    if (last < n && speed[last] < limit(last)) continue;  // the ramp runs on through
    if (last - first == 1 && segments[first].constant) {
      duration[first] = segments[first].length / segments[first].cruise;
    } else {
      double length = 0, cruise = kInf;
      a = j = kInf;
      for (size_t i = first; i < last; ++i) {
        length += segments[i].length;
        cruise = std::min(cruise, segments[i].cruise);
        a = std::min(a, segments[i].accel);
        j = std::min(j, segments[i].jerk);
      }
      if (cruise < std::max(speed[first], speed[last])) {
        // A slower move inside (its feed lower than the ends' speeds): each move on its own.
        for (size_t i = first; i < last; ++i) {
          const Segment& m = segments[i];
          duration[i] = shape(speed[i], speed[i + 1], m.cruise, m.length, m.accel, m.jerk).time();
        }
      } else {
        const Shape s = shape(speed[first], speed[last], cruise, length, a, j);
        double before = 0;
        for (size_t i = first; i < last; ++i) {
          const double after = i + 1 == last ? s.time() : time_at(s, at[i + 1] - at[first]);
          duration[i] = after - before;
          before = after;
        }
      }
    }
    first = last;
  }
  return duration;
}

}  // namespace scurve

double pause_seconds(const Pause& pause, const MachineConfig& machine) {
  switch (pause.kind) {
    case Pause::Kind::Dwell: return std::max(0.0, pause.seconds);
    case Pause::Kind::ToolChange: return machine.motion.tool_change;
    case Pause::Kind::Spindle: return std::abs(pause.rpm_to - pause.rpm_from) / machine.motion.spindle_acceleration;
    case Pause::Kind::Stop: return 0;
  }
  return 0;
}

// One process's moves and clock.
struct Lane {
  std::vector<Segment> segments;
  std::vector<double> duration;
  AxisValues end_dir{};
  MoveKind last_kind = MoveKind::Rapid;
  bool standing = true;  // the machine stands before the next segment
  double clock = 0, last_end = 0;
  CycleTime sums;
};

// The pauses in the order they come (a path lists them so; sorting keeps it robust).
std::vector<const Pause*> ordered_pauses(const Toolpath& path) {
  std::vector<const Pause*> out;
  out.reserve(path.pauses.size());
  for (const Pause& p : path.pauses) out.push_back(&p);
  std::stable_sort(out.begin(), out.end(), [](const Pause* a, const Pause* b) { return a->after < b->after; });
  return out;
}

}  // namespace

CycleTime cycle_time(const Toolpath& path, const MachineConfig& machine, TimeModel model) {
  const size_t n = path.moves.size();
  const std::vector<const Pause*> pauses = ordered_pauses(path);
  std::vector<Lane> lanes;
  auto lane = [&](uint8_t process) -> Lane& {
    if (process >= lanes.size()) lanes.resize(process + size_t{1});
    return lanes[process];
  };
  std::vector<int32_t> segment_of(n, -1);  // each move's index in its lane's segments
  CycleTime result;
  result.model = model;
  {
    std::vector<size_t> moves_of;  // per process: the moves to reserve room for
    for (const Move& m : path.moves) {
      if (m.process >= moves_of.size()) moves_of.resize(m.process + size_t{1});
      ++moves_of[m.process];
    }
    for (size_t p = 0; p < moves_of.size(); ++p) {
      Lane& l = lane(static_cast<uint8_t>(p));
      if (model == TimeModel::Feed)
        l.duration.reserve(moves_of[p]);
      else
        l.segments.reserve(moves_of[p]);
    }
  }

  // The segments, and where the machine must stand.
  size_t next_pause = 0;
  for (size_t k = 0; k < n; ++k) {
    for (; next_pause < pauses.size() && pauses[next_pause]->after <= k; ++next_pause)
      lane(pauses[next_pause]->process).standing = true;
    const Move& m = path.moves[k];
    if (m.programmed) continue;
    Lane& l = lane(m.process);
    const Geometry g = geometry(m, machine);
    if (!g.rotary_only) (m.kind == MoveKind::Rapid ? result.rapid_length : result.cutting_length) += g.length;
    if (g.length == 0) {
      l.standing = l.standing || m.exact_stop;
      continue;
    }
    if (model == TimeModel::Feed) {  // no acceleration: the time is known now
      segment_of[k] = static_cast<int32_t>(l.duration.size());
      l.duration.push_back(g.length / cruise_speed(m, g, machine, model));
      continue;
    }
    Segment s;
    s.length = g.length;
    s.cruise = cruise_speed(m, g, machine, model);
    s.constant = m.kind == MoveKind::Thread;
    s.accel = along_path(g.share, machine, [](const AxisConfig& a) { return a.acceleration; });
    s.jerk = along_path(g.share, machine, [](const AxisConfig& a) { return a.jerk; });
    const bool stops = l.standing || s.constant || l.last_kind == MoveKind::Thread ||
                       (m.kind == MoveKind::Rapid) != (l.last_kind == MoveKind::Rapid);
    if (!stops)
      s.entry_limit = std::min({junction_speed(l.end_dir, g.start_dir, machine), s.cruise, l.segments.back().cruise});
    segment_of[k] = static_cast<int32_t>(l.segments.size());
    l.segments.push_back(s);
    l.end_dir = g.end_dir;
    l.last_kind = m.kind;
    l.standing = m.exact_stop || s.constant;
  }

  for (Lane& l : lanes) {
    if (model == TimeModel::Trapezoid) l.duration = plan_trapezoid(l.segments);
    if (model == TimeModel::SCurve) l.duration = scurve::plan(l.segments);
  }

  // The clocks, in the order the moves and pauses came.
  result.move_end.resize(n);
  auto add_pause = [&](const Pause& p) {
    Lane& l = lane(p.process);
    const double seconds = pause_seconds(p, machine);
    l.clock += seconds;
    switch (p.kind) {
      case Pause::Kind::Dwell: l.sums.dwell += seconds; break;
      case Pause::Kind::ToolChange: l.sums.tool_change += seconds; break;
      case Pause::Kind::Spindle: l.sums.spindle += seconds; break;
      case Pause::Kind::Stop: break;
    }
  };
  next_pause = 0;
  for (size_t k = 0; k < n; ++k) {
    for (; next_pause < pauses.size() && pauses[next_pause]->after <= k; ++next_pause) add_pause(*pauses[next_pause]);
    const Move& m = path.moves[k];
    Lane& l = lane(m.process);
    if (!m.programmed) {
      const double seconds = segment_of[k] < 0 ? 0 : l.duration[static_cast<size_t>(segment_of[k])];
      l.clock += seconds;
      (m.kind == MoveKind::Rapid ? l.sums.rapid : l.sums.cutting) += seconds;
      l.last_end = l.clock;
    }
    result.move_end[k] = l.last_end;
  }
  for (; next_pause < pauses.size(); ++next_pause) add_pause(*pauses[next_pause]);

  const Lane* longest = nullptr;
  for (const Lane& l : lanes)
    if (!longest || l.sums.total() > longest->sums.total()) longest = &l;
  if (longest) {
    result.cutting = longest->sums.cutting;
    result.rapid = longest->sums.rapid;
    result.tool_change = longest->sums.tool_change;
    result.dwell = longest->sums.dwell;
    result.spindle = longest->sums.spindle;
  }
  return result;
}

namespace {

// What the summary says of the path besides the times.
struct PathCounts {
  size_t cutting = 0, rapid = 0, tool_changes = 0, dwells = 0, processes = 0;
};

PathCounts count(const Toolpath& path) {
  PathCounts c;
  std::vector<bool> moved;
  for (const Move& m : path.moves) {
    if (m.programmed) continue;
    ++(m.kind == MoveKind::Rapid ? c.rapid : c.cutting);
    if (m.process >= moved.size()) moved.resize(m.process + size_t{1});
    moved[m.process] = true;
  }
  c.processes = static_cast<size_t>(std::count(moved.begin(), moved.end(), true));
  for (const Pause& p : path.pauses) {
    c.tool_changes += p.kind == Pause::Kind::ToolChange;
    c.dwells += p.kind == Pause::Kind::Dwell;
  }
  return c;
}

// 83.46 s → "1:23.5".
std::string minutes(double seconds) {
  const long long tenths = std::llround(seconds * 10);
  return fmt::format("{}:{:02}.{}", tenths / 600, tenths % 600 / 10, tenths % 10);
}

}  // namespace

std::string time_text(const Toolpath& path, const std::vector<CycleTime>& times) {
  const PathCounts c = count(path);
  const double cutting_length = times.empty() ? 0 : times[0].cutting_length;
  const double rapid_length = times.empty() ? 0 : times[0].rapid_length;
  std::string out = fmt::format("cutting {:>8} moves {:>12.3f} mm\nrapid   {:>8} moves {:>12.3f} mm\n", c.cutting,
                                cutting_length, c.rapid, rapid_length);
  out += fmt::format("tool changes {}, dwells {}", c.tool_changes, c.dwells);
  if (c.processes > 1) out += fmt::format(", processes {} (the cycle is the longest)", c.processes);
  out += fmt::format("\n\n{:<10}{:>12}{:>12}{:>12}{:>12}{:>12}{:>12}{:>12}{:>12}\n", "model", "cutting", "rapid",
                     "tool change", "dwell", "spindle", "auxiliary", "total", "seconds");
  for (const CycleTime& t : times)
    out += fmt::format("{:<10}{:>12}{:>12}{:>12}{:>12}{:>12}{:>12}{:>12}{:>12.2f}\n", model_name(t.model),
                       minutes(t.cutting), minutes(t.rapid), minutes(t.tool_change), minutes(t.dwell),
                       minutes(t.spindle), minutes(t.auxiliary()), minutes(t.total()), t.total());
  return out;
}

std::string time_json(const Toolpath& path, const std::vector<CycleTime>& times) {
  const PathCounts c = count(path);
  const double cutting_length = times.empty() ? 0 : times[0].cutting_length;
  const double rapid_length = times.empty() ? 0 : times[0].rapid_length;
  std::string out = fmt::format(
      "{{\"processes\": {}, \"moves\": {{\"cutting\": {}, \"rapid\": {}}}, "
      "\"length_mm\": {{\"cutting\": {}, \"rapid\": {}}}, \"tool_changes\": {}, \"dwells\": {}, \"models\": {{",
      c.processes, c.cutting, c.rapid, cutting_length, rapid_length, c.tool_changes, c.dwells);
  for (size_t i = 0; i < times.size(); ++i) {
    const CycleTime& t = times[i];
    out += fmt::format(
        "{}\"{}\": {{\"cutting\": {}, \"rapid\": {}, \"tool_change\": {}, \"dwell\": {}, \"spindle\": {}, "
        "\"auxiliary\": {}, \"total\": {}}}",
        i ? ", " : "", model_name(t.model), t.cutting, t.rapid, t.tool_change, t.dwell, t.spindle, t.auxiliary(),
        t.total());
  }
  return out + "}}\n";
}

}  // namespace ncc::sim
