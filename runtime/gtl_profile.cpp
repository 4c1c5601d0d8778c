#include "gtl_profile.h"

#include <fmt/format.h>
#include <cmath>

#include "support/text.h"

namespace ncc::gtl {

namespace {

double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }
std::string at(const Vec& p) { return fmt::format("X{} Y{}", four_decimals(p.x()), four_decimals(p.y())); }

}  // namespace

std::string element_name(ElementId id) { return fmt::format("{}{}", letter(id.first), id.second); }

bool Profile::fail(size_t tag, std::string what) {
  if (!problem_) problem_ = Problem{tag, std::move(what)};
  failed_ = true;
  return false;
}

void Profile::reset() {
  active_ = failed_ = closed_ = false;
  last_.reset();
  closing_.reset();
  current_.reset();
  connector_ = {};
  held_.clear();
}

bool Profile::on(const Element& e, const Vec& p) const {
  if (e.kind == Kind::Line) return std::fabs(side_distance(e, p)) <= tol_.distance;
  return std::fabs((p - e.at).norm() - std::fabs(e.r)) <= tol_.distance;
}

void Profile::open_at(const Vec& start, size_t tag, int side, double radius, Tolerance tol) {
  reset();
  active_ = true;
  side_ = side;
  radius_ = radius;
  tol_ = tol;
  open_tag_ = tag;
  start_ = start;
}

void Profile::open_closed(const Element& last, ElementId id, bool s2, size_t tag, int side, double radius,
                          Tolerance tol) {
  open_at({0, 0}, tag, side, radius, tol);
  closed_ = true;
  last_ = call(last, id, s2, tag);
}

// The element as the tool's centre follows it: a circle whose offset shrinks to
// nothing is one the tool cannot follow.
std::optional<Profile::Call> Profile::call(const Element& e, ElementId id, bool s2, size_t tag) {
  Call c{e, offset(e, side_ * radius_), id, s2, tag};
  // (A tool of the circle's radius turns on its centre.)
  if (e.kind == Kind::Circle && std::fabs(c.path.r) >= tol_.distance && (c.path.r > 0) != (e.r > 0)) {
    fail(tag,
         fmt::format("the tool radius {} is larger than the radius {} of {} on its inside: the tool cannot follow it",
                     four_decimals(radius_), four_decimals(std::fabs(e.r)), element_name(id)));
    return std::nullopt;
  }
  return c;
}

std::optional<Profile::Junction> Profile::join(const Call& a, const Call& b, const Connector& c) {
  Junction j;
  const std::string names = fmt::format("{} and {}", element_name(a.id), element_name(b.id));
  if (c.kind == Connector::Kind::Chamfer) {
    // §2.11.9.3: b back from the corner along each line.
    if (a.nominal.kind != Kind::Line || b.nominal.kind != Kind::Line)
      return fail(c.tag, fmt::format("a chamfer b joins two lines; {} is a circle (§2.11.9.3)",
                                     element_name(a.nominal.kind == Kind::Circle ? a.id : b.id))),
             std::nullopt;
    auto corner = meet(a.nominal, b.nominal, tol_);
    if (corner.empty())
      return fail(c.tag, fmt::format("{} are parallel: there is no corner to chamfer", names)), std::nullopt;
    j.exit_nominal = corner[0] - c.size * a.nominal.dir;
    j.entry_nominal = corner[0] + c.size * b.nominal.dir;
    j.exit = j.exit_nominal;
    j.entry = j.entry_nominal;
    if ((j.entry_nominal - j.exit_nominal).norm() >= tol_.distance && side_ != 0) {
      const Element slope =
          offset({Kind::Line, j.exit_nominal, (j.entry_nominal - j.exit_nominal).normalized(), 0}, side_ * radius_);
      auto in = meet(a.path, slope, tol_), out = meet(slope, b.path, tol_);
      if (!in.empty()) j.exit = in[0];
      if (!out.empty()) j.entry = out[0];
    }
    j.between = Piece{c.tag, true, false, j.entry};
    return j;
  }
  if (c.kind == Connector::Kind::Fillet && c.size != 0) {
    // §2.11.9.2: the circle of radius r from one element to the other (§2.11.7).
    Result f = tangent_circle(a.nominal, b.nominal, c.size, tol_);
    if (!f.element)
      return fail(c.tag, fmt::format("no fillet r{} joins {}: {}", shortest(c.size), names, f.why)), std::nullopt;
    const Element fillet = *f.element;
    if (offset(fillet, side_ * radius_).r * fillet.r < -tol_.distance * tol_.distance)
      return fail(c.tag, fmt::format("the fillet r{} is smaller than the tool radius {}: the tool cannot follow it",
                                     shortest(c.size), four_decimals(radius_))),
             std::nullopt;
    j.exit_nominal = contact(a.nominal, fillet.at, fillet.r);
    j.entry_nominal = contact(b.nominal, fillet.at, fillet.r);
    j.exit = beside(a.nominal, j.exit_nominal);
    j.entry = beside(b.nominal, j.entry_nominal);
    if ((j.entry - j.exit).norm() >= tol_.distance)
      j.between = Piece{c.tag, true, true, j.entry, fillet.at, fillet.r > 0};
    return j;
  }
  // §2.11.9.1: where they meet, the second point with s2 on the first.
  auto points = meet(a.nominal, b.nominal, tol_);
  if (points.empty())
    return fail(b.tag, fmt::format("{} do not meet: join them with a fillet r (§2.11.9)", names)), std::nullopt;
  const Vec corner = points[a.s2 && points.size() > 1 ? 1 : 0];
  j.exit_nominal = j.entry_nominal = j.exit = j.entry = corner;
  if (side_ == 0) return j;
  // The offsets meet nearest the corner; an outside corner with r0 (or whose offsets
  // do not meet) has the tool roll round it (§2.8.7, figure 2.21).
  const Vec t1 = tangent(a.nominal, corner), t2 = tangent(b.nominal, corner);
  const bool outside = side_ * cross(t1, t2) < -1e-9;
  auto offsets = meet(a.path, b.path, tol_);
  const bool roll = outside && (c.kind == Connector::Kind::Fillet || offsets.empty());
  if (!roll && !offsets.empty()) {
    Vec best = offsets[0];
    for (const Vec& q : offsets)
      if ((q - corner).norm() < (best - corner).norm()) best = q;
    j.exit = j.entry = best;
    return j;
  }
  j.exit = beside(a.nominal, corner);
  j.entry = beside(b.nominal, corner);
  if ((j.exit - j.entry).norm() >= tol_.distance)
    j.between = Piece{c.kind == Connector::Kind::Fillet ? c.tag : b.tag, true, true, j.entry, corner, side_ < 0};
  return j;
}

void Profile::move(const Call& c, const Vec& exit_nominal, const Vec& exit) {
  if (c.nominal.kind == Kind::Line) {
    if ((exit_nominal - c.entry_nominal).dot(c.nominal.dir) < -tol_.distance) {
      fail(c.tag, fmt::format("{} would run against its direction, from {} back to {} (§2.11.1)", element_name(c.id),
                              at(c.entry_nominal), at(exit_nominal)));
      return;
    }
    if ((exit - c.entry).dot(c.nominal.dir) < -tol_.distance) {
      fail(c.tag, fmt::format("the tool radius {} is too large for {}: its offset path would run backwards",
                              four_decimals(radius_), element_name(c.id)));
      return;
    }
  }
  if ((exit - c.entry).norm() < tol_.distance) return;
  ready_.push_back({c.tag, true, c.nominal.kind == Kind::Circle, exit, c.path.at, c.path.r > 0});
}

void Profile::flush(size_t from, size_t to) {
  for (size_t i = from; i < to && i < held_.size(); ++i) ready_.push_back({held_[i], false});
}

void Profile::element(const Element& e, ElementId id, bool s2, size_t tag) {
  if (!active_ || failed_) return;
  auto next = call(e, id, s2, tag);
  if (!next) return;
  if (!current_) {
    // The first element: the approach to its start (§2.11.8.2, §2.11.8.3).
    if (closed_) {
      if (!last_) return;
      auto j = join(*last_, *next, {});
      if (!j) return;
      closing_ = j;
      next->entry_nominal = j->entry_nominal;
      next->entry = j->entry;
      first_id_ = id;
    } else {
      if (!on(e, start_))
        return (void)fail(tag,
                          fmt::format("the profile's start point {} does not lie on its first element {} (§2.11.8.2)",
                                      at(start_), element_name(id)));
      next->entry_nominal = start_;
      next->entry = beside(e, start_);
    }
    ready_.push_back({open_tag_, true, false, next->entry});
    flush(0, held_.size());
    held_.clear();
    current_ = next;
    return;
  }
  auto j = join(*current_, *next, connector_);
  if (!j) return;
  move(*current_, j->exit_nominal, j->exit);
  if (failed_) return;
  const size_t before = connector_.kind == Connector::Kind::None ? held_.size() : connector_.queued;
  flush(0, before);
  if (j->between) ready_.push_back(*j->between);
  flush(before, held_.size());
  held_.clear();
  connector_ = {};
  next->entry_nominal = j->entry_nominal;
  next->entry = j->entry;
  current_ = next;
}

void Profile::fillet(double r, size_t tag) {
  if (!active_ || failed_) return;
  if (!current_)
    return (void)fail(tag, "a profile does not start with a fillet: r comes between two elements (§2.11.9.2)");
  if (connector_.kind != Connector::Kind::None)
    return (void)fail(tag, "two connections in a row: one r or b joins two elements");
  connector_ = {Connector::Kind::Fillet, r, tag, held_.size()};
}

void Profile::chamfer(double b, size_t tag) {
  if (!active_ || failed_) return;
  if (!current_)
    return (void)fail(tag, "a profile does not start with a chamfer: b comes between two lines (§2.11.9.3)");
  if (connector_.kind != Connector::Kind::None)
    return (void)fail(tag, "two connections in a row: one r or b joins two elements");
  connector_ = {Connector::Kind::Chamfer, b, tag, held_.size()};
}

void Profile::hold(size_t tag) {
  if (!active_ || failed_) return;
  held_.push_back(tag);
}

void Profile::close_at(const Vec& end, size_t tag) {
  if (active_ && !failed_) {
    if (closed_) {
      fail(tag, "a closed profile ends by naming its first element again, not a point (§2.11.8.3)");
    } else if (!current_) {
      fail(tag, "the profile has no element between G21 and G20");
    } else if (connector_.kind != Connector::Kind::None) {
      fail(connector_.tag, "a profile does not end with a fillet or a chamfer: an element comes after it (§2.11.9)");
    } else if (!on(current_->nominal, end)) {
      fail(tag, fmt::format("the profile's end point {} does not lie on its last element {} (§2.11.8.2)", at(end),
                            element_name(current_->id)));
    } else {
      // §2.11.8.2 wants another point than the first; the manual's own §2.17.1.1 ends
      // where it starts, and the path is as well defined: run it, and say so.
      if ((end - start_).norm() < tol_.distance && !problem_)
        problem_ =
            Problem{tag,
                    "the open profile ends at its start point, where §2.11.8.2 wants another: a closed profile names "
                    "its last element in G21 (§2.11.8.3)",
                    true};
      move(*current_, end, beside(current_->nominal, end));
      flush(0, held_.size());
    }
  }
  reset();
}

void Profile::close_with(ElementId first, size_t tag) {
  if (active_ && !failed_) {
    if (!closed_) {
      fail(tag, "an open profile ends at a point; only a closed one ends with its first element (§2.11.8.2)");
    } else if (!current_ || !closing_) {
      fail(tag, "the profile has no element between G21 and G20");
    } else if (connector_.kind != Connector::Kind::None) {
      fail(connector_.tag, "a profile does not end with a fillet or a chamfer: the closing corner is sharp (§2.11.9)");
    } else if (first != first_id_) {
      fail(tag, fmt::format("a closed profile ends with its first element {} again, not {} (§2.11.8.3)",
                            element_name(first_id_), element_name(first)));
    } else if (current_->id != last_->id) {
      fail(current_->tag, fmt::format("the profile's last element is {}, as its G21 block names it, not {} (§2.11.8.3)",
                                      element_name(last_->id), element_name(current_->id)));
    } else {
      move(*current_, closing_->exit_nominal, closing_->exit);
      flush(0, held_.size());
      if (!failed_ && closing_->between) {
        Piece round = *closing_->between;  // rolling round the closing corner: G20's block
        round.tag = tag;
        ready_.push_back(round);
      }
    }
  }
  reset();
}

}  // namespace ncc::gtl
