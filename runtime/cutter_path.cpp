#include "cutter_path.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "corner.h"
#include "support/text.h"

#include <fmt/format.h>

namespace ncc {

namespace {

constexpr double kPi = std::numbers::pi;
bool is_move(const Event& e) { return is_move(e.kind); }
double cross(const corner::Vec& a, const corner::Vec& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

struct CutterPath::State {
  using Vec = corner::Vec;
  State(TraceSink& o, Report r, void* c, CompRules rules) : out_(o), report_(r), context_(c), rules_(rules) {}
  void send(const Event& e);
  void event(const Event& e, const AxisValues* start);
  void begin(const Event& move, const corner::Element& el, const AxisValues& from);
  void join(const Event& move, const corner::Element& el);
  void leave(bool right_angle);
  void abandon();
  void end_waiting(const Vec& end);
  Vec normal(const corner::Element& el, const Vec& at, int side) const;

  TraceSink& out_;
  Report report_;
  void* context_;
  CompRules rules_;
  struct Corner {
    bool fillet = true;
    double size = 0;  // signed radius of a fillet, set-back of a chamfer
    uint32_t source = 0;
  };
  std::optional<Corner> corner_;    // asked for between the waiting move and the next
  std::optional<uint32_t> off_in_;  // NC-110: the block whose G40 the next block's move makes good
  bool cut(corner::Element& el, Vec& end, Vec& next, std::optional<Event>& between);
  // No compensation: G40, or (ISO D0) a radius of 0; NC-110's path with a radius of 0
  // still cuts its corners r and b.
  bool off(int side, double radius) const { return side == 0 || (radius <= 0 && rules_.zero_radius_off); }
  // " (E-12)": the ISO alarm a rule is, where the dialect numbers them.
  std::string alarm(const char* code) const { return rules_.alarm_codes ? fmt::format(" ({})", code) : std::string(); }
  int side_ = 0;               // 1 left (G41), 2 right (G42), 0 off
  double radius_ = 0;          // program units
  uint32_t switched_at_ = 0;   // the block whose CutterComp event set side_
  uint32_t leave_source_ = 0;  // the block a right-angle leave belongs to
  bool leaving_ = false;       // compensation went off; the waiting move has not left yet
  bool suspended_ = false;     // G28, G29, G53, a cycle: moves go as programmed
  bool in_plane(const Event& e, const AxisValues& start) const {
    const int u = e.kind == EventKind::Arc ? e.plane.u : plane_.u, v = e.kind == EventKind::Arc ? e.plane.v : plane_.v;
    return e.kind == EventKind::Arc || std::hypot(e.pos[u] - start[u], e.pos[v] - start[v]) > 1e-9;
  }
  // The last held move: where the tool stands on the axes outside the plane.
  const Event& last_move() const {
    for (size_t i = held_.size(); i-- > 0;)
      if (is_move(held_[i])) return held_[i];
    return held_[*waiting_];
  }
  bool right_angle_ = false;  // compensation started in a block of its own
  Plane plane_;
  // The move waiting for the next one, and what came after it, with their bytes (the
  // run's memory budget: a loop that never moves in the plane makes them grow).
  std::vector<Event> held_;
  uint64_t held_text_ = 0;  // bytes of their texts
  void hold(const Event& e) {
    held_text_ += e.text.capacity();
    held_.push_back(e);
  }
  void drop_held() {
    held_.clear();
    held_text_ = 0;
  }
  void send_held() {
    for (const Event& e : held_) out_.event(e);
    drop_held();
  }
  std::optional<size_t> waiting_;
  corner::Element element_;  // its programmed element
  int waiting_side_ = 0;
  double waiting_radius_ = 0;
  bool startup_ = false;    // the start-up line: it ends beside the next move's start
  bool abandoned_ = false;  // the path was given up at an error: the next move restarts it, no start-up
  Vec from_{0, 0};          // where its offset path starts
};

CutterPath::CutterPath(TraceSink& out, Report report, void* context, CompRules rules)
    : s_(std::make_unique<State>(out, report, context, rules)) {}
CutterPath::~CutterPath() = default;
void CutterPath::event(const Event& e, const AxisValues* start) { s_->event(e, start); }

uint64_t CutterPath::held_bytes() const { return s_->held_.capacity() * sizeof(Event) + s_->held_text_; }
size_t CutterPath::held_events() const { return s_->held_.size(); }

bool CutterPath::passes_moves() const { return !s_->waiting_ && s_->off(s_->side_, s_->radius_); }

void CutterPath::State::send(const Event& e) {
  if (waiting_)
    hold(e);
  else
    out_.event(e);
}

corner::Vec CutterPath::State::normal(const corner::Element& el, const Vec& at, int side) const {
  const Vec t = corner::tangent(el, at);
  const Vec left(-t.y(), t.x());
  return side == 1 ? left : Vec(-left);
}

void CutterPath::State::event(const Event& e, const AxisValues* start) {
  // G40 in a block of its own: the first event of a later block (or a move of its own
  // block along the normal) shows that no move of the G40 block leaves the path, so
  // the tool leaves at a right angle first (§8.10, figure 33).
  if (leaving_ && waiting_ && (e.source != leave_source_ || (is_move(e) && start && !in_plane(e, *start)))) leave(true);
  if (e.kind == EventKind::Plane) {
    // A plane change comes with G40 in its block (E-10 refuses it otherwise): the path
    // leaves in its own plane first, at a right angle.
    if (waiting_ && !(e.plane == plane_)) {
      leaving_ = true;
      leave_source_ = e.source;
      leave(true);
    }
    plane_ = e.plane;
  }
  if (e.kind == EventKind::CutterComp) {
    // NC-110 §2.8.7: G40 stands in the profile's last block, whose move is still
    // offset; the first move of a block after it leaves the path.
    if (rules_.cancel_after && off(e.n, e.a) && side_ != 0 && waiting_) {
      off_in_ = e.source;
      send(e);
      return;
    }
    if (e.n != side_ || e.a != radius_) {
      if (side_ == 0) right_angle_ = !rules_.start_along;  // until a move of the same block shows otherwise
      leaving_ = off(e.n, e.a);
      if (leaving_) leave_source_ = e.source;
      side_ = e.n;
      radius_ = e.a;
      switched_at_ = e.source;
      abandoned_ = false;
    }
    send(e);
    return;
  }
  if (!is_move(e) || !start || suspended_) {
    send(e);
    return;
  }
  const int u = e.kind == EventKind::Arc ? e.plane.u : plane_.u, v = e.kind == EventKind::Arc ? e.plane.v : plane_.v;
  corner::Element el{Vec((*start)[u], (*start)[v]), Vec(e.pos[u], e.pos[v])};
  if (e.kind == EventKind::Arc) {
    el.arc = true;
    el.c = {e.centre[0], e.centre[1]};
    el.ccw = e.rotation > 0;
    el.sweep = e.b * kPi / 180;
  }
  if (off_in_ && e.source != *off_in_ && in_plane(e, *start)) {
    side_ = 0;
    radius_ = 0;
    switched_at_ = leave_source_ = *off_in_;
    off_in_.reset();
  }
  if (!in_plane(e, *start)) {
    // A move along the plane's normal keeps the offset it stands at.
    if (waiting_)
      hold(e);
    else
      out_.event(e);
    return;
  }
  if (off(side_, radius_)) {
    // G40 (or D0) with this move: it leaves from beside the last end (figure 32).
    if (waiting_) {
      if (e.kind == EventKind::Arc &&
          (rules_.cancel_after || e.source != leave_source_))  // in G40's own block: the runtime's check
        report_(context_, e.source,
                rules_.cancel_after ? "the move after G40 leaves the compensated path: a G00 or G01 move (§2.8.7)"
                                    : "cutter radius compensation cannot end on an arc (E-13): use a G00 or G01 move");
      leave(false);
    }
    out_.event(e);
    return;
  }
  if (!waiting_) {
    begin(e, el, *start);
    return;
  }
  join(e, el);
}

void CutterPath::State::begin(const Event& move, const corner::Element& el, const AxisValues& from) {
  // Type A (§8.10): with G41/G42 in this move's block the move is the start-up line and
  // ends beside the next move's start; in a block of its own the tool first goes at a
  // right angle to the offset of this move's start.
  if (move.source == switched_at_) right_angle_ = false;
  // In G41/G42's own block the runtime checks it; after an error (E-12) the arc is no
  // start-up of the program's, and one cause gets one message (iso decision 74).
  const bool restart = std::exchange(abandoned_, false);
  if (move.kind == EventKind::Arc && move.source != switched_at_ && !restart)
    report_(context_, move.source,
            rules_.alarm_codes ? "cutter radius compensation cannot start on an arc (E-11): use a G00 or G01 move"
                               : "cutter radius compensation starts with a G00 or G01 move, not an arc (§2.8.7)");
  if (right_angle_) {
    const Vec entry = el.a + radius_ * normal(el, el.a, side_);
    const Plane p = move.kind == EventKind::Arc ? move.plane : plane_;
    Event in{EventKind::Linear};
    in.source = move.source;
    in.pos = from;  // the other axes stay where the move starts
    in.pos[p.u] = entry.x();
    in.pos[p.v] = entry.y();
    out_.event(in);
    from_ = entry;
    startup_ = false;
    right_angle_ = false;
  } else {
    from_ = el.a;
    startup_ = move.kind != EventKind::Arc;  // an arc cannot start it (E-11, reported by the runtime)
  }
  hold(move);
  waiting_ = held_.size() - 1;
  element_ = el;
  waiting_side_ = side_;
  waiting_radius_ = radius_;
}

void CutterPath::State::end_waiting(const Vec& end) {
  Event& w = held_[*waiting_];
  const int u = w.kind == EventKind::Arc ? w.plane.u : plane_.u, v = w.kind == EventKind::Arc ? w.plane.v : plane_.v;
  w.pos[u] = end.x();
  w.pos[v] = end.y();
  if (w.kind == EventKind::Arc) {
    // The same centre; the radius and the sweep of the offset arc.
    const Vec c = element_.c;
    w.a = (end - c).norm();
    double sweep = std::atan2(cross(from_ - c, end - c), (from_ - c).dot(end - c));
    if (!element_.ccw) sweep = -sweep;
    if (sweep <= 1e-12) sweep += 2 * kPi;
    // Whole turns as the programmed arc has them (a full circle, a helix).
    while (sweep + 2 * kPi - element_.sweep < element_.sweep - sweep) sweep += 2 * kPi;
    w.b = sweep * 180 / kPi;
    w.rotation = w.rotation < 0 ? -corner::turns(w.b) : corner::turns(w.b);
  }
  // Moves along the normal after it stand at its end.
  for (size_t i = *waiting_ + 1; i < held_.size(); ++i)
    if (is_move(held_[i])) {
      held_[i].pos[u] = end.x();
      held_[i].pos[v] = end.y();
    }
}

namespace {

corner::Vec nearest(const std::vector<corner::Vec>& points, const corner::Vec& to) {
  corner::Vec best = points.front();
  for (const corner::Vec& q : points)
    if ((q - to).norm() < (best - to).norm()) best = q;
  return best;
}

}  // namespace

// The corner a fillet or chamfer of its own block cuts (NC-110 r, b): the waiting move
// ends and the next starts where the cut does, and the cut moves between them,
// offset like them.
bool CutterPath::State::cut(corner::Element& el, Vec& end, Vec& next, std::optional<Event>& between) {
  const Corner c = *corner_;
  const int side = waiting_side_;
  const double r = waiting_radius_;
  const std::string what = fmt::format("{}{}", c.fillet ? "the fillet r" : "the chamfer b", shortest(c.size));
  std::string why;
  auto k = corner::cut(element_, el, c.fillet, std::fabs(c.size), why);
  if (!k) {
    report_(context_, c.source, fmt::format("{} cannot join the moves before and after it: {}", what, why));
    return false;
  }
  if (c.fillet && k->ccw != (c.size > 0)) {
    report_(context_, c.source,
            fmt::format("{}: the path turns {} there, so its fillet is r{} (§2.8.7)", what,
                        k->ccw ? "counter-clockwise" : "clockwise", shortest(-c.size)));
    return false;
  }
  element_.b = k->t1;
  if (element_.arc) element_.sweep -= k->in_cut;
  el.a = k->t2;
  if (el.arc) el.sweep -= k->out_cut;
  Event e{c.fillet ? EventKind::Arc : EventKind::Linear};
  e.source = c.source;
  if (c.fillet) {
    // Tangent to both: square to them at its ends, about its own centre.
    if ((side == 1) == k->ccw && std::fabs(c.size) < r - 1e-9) {
      report_(context_, c.source,
              fmt::format("{} is smaller than the tool radius {}: the tool cannot follow it", what, shortest(r)));
      return false;
    }
    end = k->t1 + r * normal(element_, k->t1, side);
    next = k->t2 + r * normal(el, k->t2, side);
    e.plane = plane_;
    e.centre[0] = k->centre.x();
    e.centre[1] = k->centre.y();
    e.a = (end - k->centre).norm();
    e.b = k->fillet_sweep * 180 / kPi;
    e.rotation = k->ccw ? 1 : -1;
    if (e.a > 1e-9) between = e;  // a tool as large as the fillet turns on its centre
    return true;
  }
  const corner::Element slope{k->t1, k->t2};
  const int s = side == 1 ? 1 : -1;
  auto in = corner::offsets_meet(element_, slope, r, s), out = corner::offsets_meet(slope, el, r, s);
  end = in.empty() ? Vec(k->t1 + r * normal(element_, k->t1, side)) : nearest(in, k->t1);
  next = out.empty() ? Vec(k->t2 + r * normal(el, k->t2, side)) : nearest(out, k->t2);
  between = e;
  return true;
}

void CutterPath::State::join(const Event& move, const corner::Element& programmed) {
  corner::Element el = programmed;
  const Vec p = el.a;  // the programmed corner
  const int side = waiting_side_;
  const double r = waiting_radius_;
  const Vec n1 = normal(element_, p, side);
  Vec end = p + r * n1, next = end;
  std::optional<Event> around;  // what joins the two offset moves at the corner
  const int u = plane_.u, v = plane_.v;
  const bool same = side_ == side && radius_ == r;
  if (startup_) {
    // Start-up (Fanuc type A, NC-110 rule 6): beside the next move's start.
    end = next = p + radius_ * normal(el, p, side_);
    if (corner_)
      report_(context_, corner_->source,
              "a corner r or b joins two moves of the compensated path, not the approach to it (§2.8.7)");
  } else if (same && corner_ && corner_->size != 0) {
    if (!cut(el, end, next, around)) {
      corner_.reset();
      return abandon();
    }
  } else if (same) {
    const Vec d1 = corner::tangent(element_, p), d2 = corner::tangent(el, p);
    const double turn = cross(d1, d2);
    const bool inside = side == 1 ? turn > 1e-9 : turn < -1e-9;
    const bool straight = std::fabs(turn) <= 1e-9 && d1.dot(d2) > 0;
    // Outside: round the corner (Fanuc type A; NC-110 r0), or where the offsets meet.
    const auto points = straight ? std::vector<Vec>{} : corner::offsets_meet(element_, el, r, side == 1 ? 1 : -1);
    const bool round = !straight && !inside && (rules_.round_outside || (corner_ && corner_->fillet) || points.empty());
    if (straight) {
      end = next = p + r * n1;
    } else if (inside || !round) {
      // The offset moves meet at their intersection nearest the corner.
      if (points.empty()) {
        report_(context_, move.source,
                fmt::format("cutter compensation: the offset paths of this move and the one before do not meet: "
                            "a move shorter than the tool radius or an arc smaller than it{}",
                            alarm("E-12")));
        corner_.reset();
        return abandon();
      }
      end = next = nearest(points, p);
    } else {
      // Round the corner at the radius (§8.10, figure 31; NC-110 figure 2.21).
      end = p + r * n1;
      next = p + r * normal(el, p, side);
      // It turns the way the path turns away from the tool: clockwise beside a G41
      // path, counter-clockwise beside a G42 one (a reversal included).
      Event arc{EventKind::Arc};
      arc.source = corner_ ? corner_->source : move.source;
      arc.plane = plane_;
      arc.centre[0] = p.x();
      arc.centre[1] = p.y();
      arc.a = r;
      const bool ccw = side == 2;
      double sweep = std::atan2(cross(end - p, next - p), (end - p).dot(next - p));
      if (!ccw) sweep = -sweep;
      if (sweep < 0) sweep += 2 * kPi;
      arc.rotation = ccw ? 1 : -1;
      arc.b = sweep * 180 / kPi;
      around = arc;
    }
  }
  corner_.reset();
  // A side or radius change (G41 <-> G42, a new D): the move ends beside its own end
  // and the next one starts there (§8.10, figure 34: only on straight moves, E-14).
  if (el.arc && el.ccw == (side_ == 1) && (el.a - el.c).norm() <= radius_ + 1e-9) {
    // An arc turning towards the tool: its offset radius shrinks to nothing (E-12).
    report_(context_, move.source,
            fmt::format("cutter compensation: the arc's radius is not larger than the tool radius on its inside{}",
                        alarm("E-12")));
    return abandon();
  }
  // §8.10 (E-12): an offset line that would run backwards cuts into the part.
  if (!element_.arc && !startup_ && (end - from_).dot(element_.b - element_.a) <= 0) {
    report_(context_, move.source,
            fmt::format("cutter compensation: the move before is shorter than the tool radius allows: its offset "
                        "runs backwards{}",
                        alarm("E-12")));
    return abandon();
  }
  end_waiting(end);
  if (around) {
    around->pos = last_move().pos;
    around->pos[u] = next.x();
    around->pos[v] = next.y();
    // A corner of its own block (NC-110 r, b) comes before what the blocks after it
    // did; ISO's arc round a corner is the next move's.
    size_t at = held_.size();
    if (around->source != move.source)
      for (size_t i = *waiting_ + 1; i < held_.size(); ++i)
        if (held_[i].source != held_[*waiting_].source && held_[i].source != around->source) {
          at = i;
          break;
        }
    held_text_ += around->text.capacity();
    held_.insert(held_.begin() + static_cast<std::ptrdiff_t>(at), *around);
  }
  send_held();
  waiting_.reset();
  from_ = next;
  hold(move);
  waiting_ = 0;
  element_ = el;
  waiting_side_ = side_;
  waiting_radius_ = radius_;
  startup_ = false;
}

// A path that would cut into the part (reported): nothing of it goes on.
void CutterPath::State::abandon() {
  abandoned_ = true;
  drop_held();
  waiting_.reset();
  startup_ = false;
}

void CutterPath::State::leave(bool right_angle) {
  const Vec p = element_.b;
  const Vec end = p + waiting_radius_ * normal(element_, p, waiting_side_);
  end_waiting(startup_ ? p : end);
  if (right_angle && !startup_) {
    // Back to the programmed end at a right angle (§8.10, figure 33), at the height
    // the tool stands at now.
    Event back{EventKind::Linear};
    back.source = leaving_ ? leave_source_ : held_[*waiting_].source;
    back.pos = last_move().pos;
    back.pos[plane_.u] = p.x();
    back.pos[plane_.v] = p.y();
    hold(back);
  }
  leaving_ = false;
  send_held();
  waiting_.reset();
  startup_ = false;
}

void CutterPath::suspend() {
  if (s_->waiting_) s_->leave(false);
  s_->suspended_ = true;
}

void CutterPath::resume() {
  s_->suspended_ = false;
  s_->right_angle_ = false;  // the next move starts up again along itself
}

void CutterPath::finish(bool exit) {
  // NC-110: a path that ends compensated stays beside its last point.
  if (s_->waiting_) s_->leave(exit && !s_->rules_.cancel_after);
}

void CutterPath::leave() {
  if (s_->waiting_) s_->leave(true);
}

void CutterPath::corner(bool fillet, double size, uint32_t source) {
  s_->corner_ = State::Corner{fillet, size, source};
}

}  // namespace ncc
