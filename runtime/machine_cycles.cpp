// What every dialect's canned cycles share (a hole's steps, the tap's moves; each
// dialect family's engine is in cycle_engine.h) and the NC-110 measuring cycles
// G72-G74 (§2.8.12) against a simulated probe.
#include <cmath>
#include <limits>

#include "cycle_steps.h"
#include "machine.h"
#include "support/text.h"

namespace ncc {

// A hole's steps (cycle_steps.h): `hole` is its position, `d` the drilling axis, `u`
// the axis of a shift; in the program's coordinates where `program` (NC-110's), else
// the machine's.
void Machine::hole_steps(const std::vector<cycle::Step>& steps, const AxisValues& hole, int d, int u, bool program,
                         std::optional<double> pitch) {
  using Kind = cycle::Step::Kind;
  auto here = [&] { return program ? to_frame(kernel_.position()) : kernel_.position(); };
  bool over = false;
  for (const cycle::Step& s : steps) {
    AxisValues p = over ? hole : here();
    p[d] = s.level;
    p[u] += s.shift;
    if (program) p = to_machine(p);
    switch (s.kind) {
      case Kind::Rapid: rapid(p); break;
      case Kind::Feed: linear(p); break;
      case Kind::Tap:
      case Kind::TapOut: tap_feed(p, s.kind == Kind::TapOut, d, pitch); break;
      case Kind::Over:
        over = true;
        p = hole;
        p[d] = here()[d];
        if (program) p = to_machine(p);
        if (p != kernel_.position()) rapid(p);
        break;
      case Kind::Dwell: dwell_seconds(s.seconds); break;
      case Kind::Spindle: {
        if (s.always || modal_.spindle != cycle::spindle_turns(s.spindle)) apply({s.spindle}, Scope::Modal, true);
        break;
      }
      case Kind::Manual: {
        // The operator retracts by hand: the run stops; on resume the tool is where
        // the step says (S-7.5).
        Event stop{EventKind::Stop};
        stop.n = 3;
        emit(stop);
        emit(motion_event(EventKind::OperatorMove, p));
        move_to(p);
        break;
      }
    }
  }
}

void Machine::tap_feed(const AxisValues& t, bool out, int d, std::optional<double> pitch) {
  // G84: with a spindle encoder and K, a move synchronised with the spindle at the
  // pitch K; else at F. The way out runs at RMS percent of the speed (§2.10.3).
  // RMS 0 and K without an encoder were refused before the hole.
  double percent = system_value(SysVar::TapReturn);
  if (pitch) {
    double rpm = spindle_rpm();
    if (rpm <= 0) report(DiagId::ThreadNoSpindle, 0);
    if (!path_allowed({kernel_.position(), t})) return move_to(t);
    const double scale = out ? percent / 100 : 1;
    if (out && scale != 1) {
      Event e{EventKind::SpindleSpeed};
      e.a = speed_ * scale;
      emit(e);
    }
    if (rpm > 0) kernel_.advance_clock(60 * std::fabs(t[d] - kernel_.position()[d]) / (*pitch * rpm * scale));
    Event e = motion_event(EventKind::Thread, t);
    e.a = to_program(*pitch);
    emit(e);
    move_to(t);
    if (out && scale != 1) {
      Event back{EventKind::SpindleSpeed};
      back.a = speed_;
      emit(back);
    }
    return;
  }
  if (!out || percent == 100 || !feed_) return linear(t);
  double programmed = *feed_;
  feed_ = programmed * percent / 100;
  Event e{EventKind::FeedRate};
  e.a = *feed_;
  emit(e);
  linear(t);
  feed_ = programmed;
  e.a = programmed;
  emit(e);
}

// ---- Measuring cycles (NC-110 §2.8.12, §2.13.9) -------------------------------------

void Machine::measure() {
  const Fn fn = block_.measure;
  const std::string name = fn == Fn::MeasurePoint ? "G72" : fn == Fn::MeasureHole ? "G73" : "G74";
  const ProbeConfig& probe = probe_;
  const AxisValues start = kernel_.position();
  // Where the values go: the block's E word (a code chosen at run time has none).
  const std::optional<uint32_t> e = has('E') ? whole_in<uint32_t>(word('E'), 0, 65535) : std::nullopt;
  if (!e) {
    report(DiagId::ResultWord, 0, fmt::format("{} needs the E parameter its results go to, e.g. E40", name));
    return;
  }
  const uint32_t first = *e;
  // The next contact of the simulated probe, or the nominal one when the list has ended.
  const size_t index = next_contact_++;
  const ProbeContact* contact = index < probe.contacts.size() ? &probe.contacts[index] : nullptr;
  auto setup = [&](const std::string& why) { report(DiagId::ProbeSetup, 0, name, why); };
  auto probe_move = [&](const AxisValues& to, bool touched) {
    double length = 0;
    for (int i = 0; i < kAxisCount; ++i) length += (to[i] - kernel_.position()[i]) * (to[i] - kernel_.position()[i]);
    kernel_.advance_clock(60 * std::sqrt(length) / probe.feed);
    Event event = motion_event(EventKind::Probe, to);
    event.n = touched;
    emit(event);
    kernel_.move_to(to);
  };
  // Where a point is, in the program's frame, on the axes that move and X Y Z.
  auto where = [&](const AxisValues& p) {
    std::string s;
    AxisValues q = to_frame(p);
    for (char letter : conv_.axes)
      if (int i = axis_index(letter); p[i] != start[i] || i < 3)
        s += fmt::format("{}{}{}", s.empty() ? "" : " ", letter, four_decimals(program_axis(i, q[i])));
    return s;
  };
  auto no_contact = [&](const AxisValues& from, const AxisValues& to) {
    probe_move(to, false);
    rapid(start);
    report(DiagId::ProbeNoContact, 0, name, where(from), where(to));
  };
  const double radius = fn == Fn::MeasureDeviation ? 0.0 : offset_.radius;
  const std::string contact_name = fmt::format("the next probe contact (probe.contacts[{}])", index);

  if (fn == Fn::MeasureHole) {
    // G73 r: three probes from the centre at 0, 120 and 240 degrees in the plane.
    const int u = modal_.plane.u, v = modal_.plane.v;
    const double nominal = length_units(word('r')) * (kernel_.frame().transformed() ? kernel_.frame().scale[u] : 1.0);
    if (contact && contact->kind == ProbeContact::Kind::Point)
      return setup(contact_name + " is a point; G73 needs a circle");
    if (contact && contact->kind == ProbeContact::Kind::Circle && !((contact->axes >> u) & (contact->axes >> v) & 1))
      return setup(fmt::format("{} is a circle about a centre in other axes than the {} plane G73 measures in",
                               contact_name, plane_name(modal_.plane)));
    double cx = start[u], cy = start[v], r = nominal;
    if (contact && contact->kind == ProbeContact::Kind::Circle) {
      cx = contact->point[u];
      cy = contact->point[v];
      r = contact->radius;
    }
    for (int k = 0; k < 3; ++k) {
      const double a = k * 2 * std::numbers::pi / 3;
      const double dx = std::cos(a), dy = std::sin(a);
      AxisValues from = start, safety = start;
      from[u] += (nominal - probe.approach) * dx;
      from[v] += (nominal - probe.approach) * dy;
      safety[u] += (nominal + probe.safety) * dx;
      safety[v] += (nominal + probe.safety) * dy;
      rapid(from);
      // Where the ray from the start meets the hole's wall; the probe's centre stops
      // its radius before the wall, within the stroke from Qa before the nominal
      // radius to Qs past it.
      double reach = nominal - radius;
      if (contact) {
        double ox = start[u] - cx, oy = start[v] - cy;
        double b = ox * dx + oy * dy, c = ox * ox + oy * oy - r * r;
        double disc = b * b - c;
        reach = disc >= 0 ? -b + std::sqrt(disc) - radius : -1;
        if (contact->kind == ProbeContact::Kind::None || reach < nominal - probe.approach ||
            reach > nominal + probe.safety)
          return no_contact(from, safety);
      }
      AxisValues touch = start;
      touch[u] += reach * dx;
      touch[v] += reach * dy;
      probe_move(touch, true);
      rapid(start);
    }
    AxisValues centre = start;
    centre[u] = cx;
    centre[v] = cy;
    const AxisValues c = to_frame(centre);
    results_.push_back({first, program_axis(u, c[u])});
    results_.push_back({first + 1, program_axis(v, c[v])});
    results_.push_back({first + 2, to_program(r / (kernel_.frame().transformed() ? kernel_.frame().scale[u] : 1.0))});
    return;
  }

  // G72, G74: towards the nominal point P, from Qa before it to Qs past it.
  const AxisValues nominal = target();
  double distance = 0;
  for (int i = 0; i < kAxisCount; ++i) distance += (nominal[i] - start[i]) * (nominal[i] - start[i]);
  distance = std::sqrt(distance);
  if (distance < 1e-6)
    return setup(fmt::format("the nominal point {} is where the probe is: no direction to probe", where(nominal)));
  if (contact && contact->kind == ProbeContact::Kind::Circle)
    return setup(fmt::format("{} is a circle; {} needs a point", contact_name, name));
  AxisValues dir{};
  for (int i = 0; i < kAxisCount; ++i) dir[i] = (nominal[i] - start[i]) / distance;
  auto along = [&](double s) {
    AxisValues p = start;
    for (int i = 0; i < kAxisCount; ++i) p[i] += dir[i] * s;
    return p;
  };
  const double from_s = std::max(0.0, distance - probe.approach);
  const double safety_s = distance + probe.safety;
  // The contact: the surface point; the probe's centre stops its radius before it.
  AxisValues surface = nominal;
  if (contact && contact->kind == ProbeContact::Kind::Point)
    for (int i = 0; i < kAxisCount; ++i)
      if (contact->axes & (1u << i)) surface[i] = contact->point[i];
  double contact_s = 0;
  for (int i = 0; i < kAxisCount; ++i) contact_s += (surface[i] - start[i]) * dir[i];
  contact_s -= radius;
  if (from_s > 0) rapid(along(from_s));
  if ((contact && contact->kind == ProbeContact::Kind::None) || contact_s < from_s || contact_s > safety_s)
    return no_contact(along(from_s), along(safety_s));
  probe_move(along(contact_s), true);
  rapid(start);
  // The values in the order the axes were written (the front end says where each
  // goes), in the program's frame (§2.8.12.1: the position "on every coordinate of the
  // block"), whatever the origin, rotation, mirror or scale.
  const AxisValues measured = to_frame(surface), wanted = to_frame(nominal);
  for (char letter : conv_.axes) {
    int a = axis_index(letter);
    auto slot = slot_if(second_slot(letter));
    if (!slot || !has(letter)) continue;
    double value = fn == Fn::MeasurePoint ? measured[a] : wanted[a] - measured[a];
    // E<n>, which the front end writes (anything else: an index the VM's store refuses).
    results_.push_back({whole_in<uint32_t>(*slot, 0, 65535).value_or(UINT32_MAX), program_axis(a, value)});
  }
}

// Fanuc G31 (decision 66): a feed move at F towards the words' point, which the
// simulated probe's next contact (docs/profile.md [probe]) ends where the controlled
// point reaches it (at the end point when the list has run out); the skip position,
// in work coordinates, is #5061-#5066. A contact off the move (or "none") lets it run
// to its point, which is then the skip position, as on Fanuc (no alarm: the program
// tests the position).
void Machine::skip() {
  if (!has_axis_word())
    return report_code(DiagId::ProbeSetup, block_.code_name,
                       "the axis words of the point it moves towards are missing");
  const AxisValues start = kernel_.position(), end = target();
  if (!need_feed("the skip move (G31)", end)) return;
  const size_t index = next_contact_++;
  const ProbeContact* contact = index < probe_.contacts.size() ? &probe_.contacts[index] : nullptr;
  if (contact && contact->kind == ProbeContact::Kind::Circle)
    return report_code(
        DiagId::ProbeSetup, block_.code_name,
        fmt::format("the next probe contact (probe.contacts[{}]) is a circle; G31 needs a point", index));
  double length = 0;
  for (int i = 0; i < kAxisCount; ++i) length += (end[i] - start[i]) * (end[i] - start[i]);
  length = std::sqrt(length);
  // The contact: the point of the move nearest the contact's axes (the others at the
  // end point), when it lies on the move.
  AxisValues at = end;
  bool touched = !contact;  // the list has run out: contact at the end point
  if (contact && contact->kind == ProbeContact::Kind::Point && length > 0) {
    AxisValues surface = end;
    for (int i = 0; i < kAxisCount; ++i)
      if (contact->axes & (1u << i)) surface[i] = contact->point[i];
    double s = 0;
    for (int i = 0; i < kAxisCount; ++i) s += (surface[i] - start[i]) * (end[i] - start[i]) / length;
    if (s >= 0 && s <= length) {
      touched = true;
      for (int i = 0; i < kAxisCount; ++i) at[i] = start[i] + (end[i] - start[i]) * s / length;
    }
  }
  if (!path_allowed({start, at})) return move_to(at);
  double travel = 0;
  for (int i = 0; i < kAxisCount; ++i) travel += (at[i] - start[i]) * (at[i] - start[i]);
  kernel_.advance_clock(feed_time(std::sqrt(travel)));
  Event event = motion_event(EventKind::Probe, at);
  event.n = touched;
  emit(event);
  move_to(at);
  skip_position_ = motion_event(EventKind::Linear, at).pos;
}

}  // namespace ncc
