// Motions: rapid and feed moves, arcs and helices, parabolas, threads, splines,
// dwells, and the time they take.
#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

#include "block_rules.h"
#include "corner.h"
#include "machine.h"
#include "spline.h"
#include "support/text.h"

namespace ncc {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2 * std::numbers::pi;
// The interpolation parameter parallel to each linear axis (GOST Table 1).
constexpr char kParameterOf[3] = {'I', 'J', 'K'};
constexpr double kSamePoint = 1e-7;             // mm: end point equal to start point
constexpr double kMaxTurns = 1e6;               // of one helix
constexpr double kMaxDwellSeconds = 60;         // NC-110 TMR under G94 (§2.10.1)
constexpr double kMaxDwellRevolutions = 30000;  //              under G95

// The angle in [0, 2π).
double wrap(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}

}  // namespace

void Machine::move_to(const AxisValues& t) {
  if (t != kernel_.position()) (modal_.motion == Fn::MotionRapid ? block_.rapid_moved : block_.moved) = true;
  kernel_.move_to(t);
  // A block's work is bounded, whatever its holes and pecks: a repeat stops at the error.
  constexpr uint32_t kMaxMovesPerBlock = 1'000'000;
  if (block_.moves++ == 0) return;
  ++moves_beyond_first_;
  if (block_.moves == kMaxMovesPerBlock + 1) report(DiagId::BlockMoves, 0, kMaxMovesPerBlock);
}

MachineState Machine::state() const {
  MachineState s;
  s.position = motion_event(EventKind::Rapid, kernel_.position()).pos;
  s.machine = kernel_.position();
  s.inch = modal_.inch;
  s.absolute = modal_.absolute;
  s.plane = modal_.plane;
  s.feed_mode = modal_.feed_mode;
  s.feed = feed_;
  s.speed = speed_;
  s.spindle = modal_.spindle;
  s.tool = tool_loaded_;
  s.tool_selected = tool_selected_;
  s.work_offset = modal_.work_offset;
  s.cutter_comp = modal_.comp;
  s.cutter_radius = compensation().radius;
  s.length_offset = modal_.length;
  s.motion = motion_name_;
  s.mist = modal_.mist;
  s.flood = modal_.flood;
  s.clock = kernel_.clock();
  return s;
}

// ---- Time ---------------------------------------------------------------------------

double Machine::spindle_rpm() const {
  if (std::abs(modal_.spindle) != 1) return 0;
  if (!modal_.constant_surface) return speed_;
  // Constant cutting speed (G96): S in m/min (ft/min) at the diameter of the cross
  // axis, measured from the active origin (the spindle's axis): a diametral axis as
  // written, else twice X (NC-110 decision 49).
  const AxisValues at = to_frame(kernel_.position());
  double diameter = 2 * std::fabs(at[0]);
  for (int i = 0; i < kAxisCount; ++i)
    if (config_.axes[static_cast<size_t>(i)].diameter) diameter = std::fabs(at[i]);
  double surface = modal_.inch ? speed_ * 304.8 : speed_ * 1000;  // mm/min
  double rpm = diameter > 0 ? surface / (kPi * diameter) : config_.max_rpm;
  return config_.max_rpm > 0 ? std::min(rpm, config_.max_rpm) : rpm;
}

double Machine::feed_time(double length) {
  if (system_value(SysVar::AxesDisconnected) == 1) return 0;
  if (!feed_ || *feed_ <= 0) return 0;
  const double slow = modal_.feed_reduced ? 100 : 1;  // pp M37: the feed is F / 100
  switch (modal_.feed_mode) {
    case 0: return slow * 60 / *feed_;  // inverse time: the block takes 1/F minutes
    case 2: {
      double rpm = spindle_rpm();
      return rpm > 0 ? slow * 60 * length / (length_units(*feed_) * rpm) : 0;
    }
    default: return slow * 60 * length / length_units(*feed_);
  }
}

// ---- Straight moves -----------------------------------------------------------------

// NC-110 t: the block's own time in seconds under G94 (§2.7.5): its feed is the
// segment's length over t. 0 when the block has no t (or a wrong one, reported).
double Machine::block_seconds() {
  if (!has('t')) return 0;
  const double t = word('t');
  if (modal_.feed_mode != 1)
    report(DiagId::TimeWord, 't', "is for feed per minute (G94) only");
  else if (t <= 0)
    report(DiagId::TimeWord, 't', "must be greater than 0");
  return modal_.feed_mode == 1 && t > 0 ? t : 0;
}

bool Machine::need_feed(const char* what, const AxisValues& t) {
  if (modal_.feed_mode == 1 && has('t')) return true;  // the block's t gives its feed
  if (modal_.feed_mode == 0 && !has('F')) {
    report(DiagId::InverseTimeNoFeed, 0);
  } else if (!feed_) {
    // Once until an F or another feed mode: the blocks after it lack the same F.
    report_repeated(DiagId::NoFeed, what);
  } else if (modal_.feed_mode == 2 && spindle_rpm() <= 0) {
    report(DiagId::FeedNoSpindle, 0, what);
  } else {
    return true;
  }
  move_to(t);  // recover as if the move had been made
  return false;
}

void Machine::rapid(const AxisValues& t) {
  if (!path_allowed({kernel_.position(), t})) return move_to(t);
  // An indexing table turns first, then the other axes move (NC-110 §2.8.3).
  for (int i = 0; i < kAxisCount; ++i)
    if (config_.axes[static_cast<size_t>(i)].kind == AxisKind::Indexing && t[i] != kernel_.position()[i]) {
      AxisValues first = kernel_.position();
      first[i] = t[i];
      if (first == t) break;
      emit(motion_event(EventKind::Rapid, first));
      kernel_.advance_clock(60 * std::fabs(t[i] - kernel_.position()[i]) / config_.axes[static_cast<size_t>(i)].rapid);
      kernel_.move_to(first);
    }
  double seconds = 0;
  for (int i = 0; i < kAxisCount; ++i)
    seconds =
        std::max(seconds, 60 * std::fabs(t[i] - kernel_.position()[i]) / config_.axes[static_cast<size_t>(i)].rapid);
  if (system_value(SysVar::AxesDisconnected) != 1) kernel_.advance_clock(seconds);
  if (kernel_.wanted(EventKind::Rapid)) emit(motion_event(EventKind::Rapid, t));
  move_to(t);
}

void Machine::linear(const AxisValues& t) {
  if (!need_feed("linear interpolation", t)) return;
  if (!path_allowed({kernel_.position(), t})) return move_to(t);
  double length = 0;
  for (int i = 0; i < kAxisCount; ++i) length += (t[i] - kernel_.position()[i]) * (t[i] - kernel_.position()[i]);
  length = std::sqrt(length);
  if (const double own = block_seconds()) {
    kernel_.advance_clock(own);
  } else if (system_value(SysVar::RapidRun) == 1) {
    double seconds = 0;
    for (int i = 0; i < kAxisCount; ++i)
      seconds =
          std::max(seconds, 60 * std::fabs(t[i] - kernel_.position()[i]) / config_.axes[static_cast<size_t>(i)].rapid);
    kernel_.advance_clock(seconds);
  } else {
    kernel_.advance_clock(feed_time(length));
  }
  if (kernel_.wanted(EventKind::Linear)) emit(motion_event(EventKind::Linear, t));
  move_to(t);
}

// ---- Arcs and helices ---------------------------------------------------------------

void Machine::arc(const AxisValues& t, bool clockwise) {
  if (!need_feed("circular interpolation", t)) return;
  const int u = modal_.plane.u, v = modal_.plane.v, w = modal_.plane.w;
  const bool plane_words = conv_.centre_words == CentreWords::Plane;
  // Per-axis centre words exist for X, Y, Z only: other planes take the plane's own.
  auto centre_word = [&](int axis, char plane_word) {
    return plane_words || axis < 0 || axis >= 3 ? plane_word : kParameterOf[axis];
  };
  const char pu = centre_word(u, 'I'), pv = centre_word(v, 'J');
  const char pw = conv_.helix_by_end ? 0 : plane_words ? 'K' : w >= 0 && w < 3 ? kParameterOf[w] : 0;
  const bool radius_form = conv_.radius_word && has(conv_.radius_word);
  auto fail = [&](const std::string& why) {
    report(DiagId::ArcForm, 0, why);
    move_to(t);
  };
  if (radius_form && (has(pu) || has(pv)))
    return fail("an arc is given by its centre I J or by its radius R, not both");
  if (!radius_form && (plane_words ? !(has(pu) && has(pv)) : !has(pu) && !has(pv))) {
    const char missing = has(pu) ? pv : has(pv) ? pu : 0;
    report(DiagId::ArcNoCentre, 0, clockwise ? "clockwise" : "counter-clockwise", plane_name(modal_.plane),
           fmt::format("{} {}", pu, pv),
           missing ? fmt::format("{} is not programmed", missing) : std::string("none of them is programmed"));
    move_to(t);
    return;
  }
  const Frame& frame = kernel_.frame();
  // NC-110 §2.13.1: the arc is computed where it is programmed, then the frame maps it;
  // a mirror on one axis of the plane turns it the other way (decision 2).
  // ISO §8.12: an arc by R under different factors keeps its shape, R scaled by the
  // larger one (decision 26); by I J K its end point leaves the circle (E-01).
  const bool unequal = frame.transformed() && !block_.machine_frame && frame.scale[u] != frame.scale[v];
  if (frame.transformed() && !block_.machine_frame) {
    if (unequal && !rules_->scales_arcs_unequally()) {
      report(DiagId::TransformArc, 0, four_decimals(frame.scale[u]), std::string(1, kAxisLetters[u]),
             four_decimals(frame.scale[v]), std::string(1, kAxisLetters[v]));
      move_to(t);
      return;
    }
    if (frame.mirror[u] != frame.mirror[v]) clockwise = !clockwise;
  }
  const bool programmed_clockwise =
      clockwise != (frame.transformed() && !block_.machine_frame && frame.mirror[u] != frame.mirror[v]);
  const AxisValues start_p = to_frame(kernel_.position());
  const AxisValues end_p = to_frame(t);
  const Eigen::Vector2d q0(start_p[u], start_p[v]), q1(end_p[u], end_p[v]);
  Eigen::Vector2d qc;
  if (radius_form) {
    // §2.8.1.4: R+ is the arc up to 180 degrees, R- the longer one; the centre lies
    // to the left of the chord for G03 R+ and G02 R-.
    double r = length_units(word(conv_.radius_word));
    double chord = (q1 - q0).norm();
    if (chord < kSamePoint) return fail("an arc by its radius cannot be a full circle: give its centre with I J");
    if (chord > 2 * std::fabs(r) + conv_.arc_tolerance)
      return fail(fmt::format("the end point is {} away, more than the diameter {} of R{}",
                              four_decimals(to_program(chord)), four_decimals(to_program(2 * std::fabs(r))),
                              four_decimals(to_program(r))));
    double h = std::sqrt(std::max(0.0, r * r - chord * chord / 4));
    Eigen::Vector2d along = (q1 - q0) / chord, left(-along.y(), along.x());
    double side = (programmed_clockwise == (r < 0)) ? 1 : -1;  // where it is programmed
    qc = (q0 + q1) / 2 + side * h * left;
  } else if (conv_.arc_centre == ArcCentre::Incremental || (!modal_.absolute && !block_.machine_frame)) {
    // Increments from the start point to the centre (GOST §4.3.3; NC-110 under G91).
    qc = q0 + Eigen::Vector2d(has(pu) ? length_units(word(pu)) : 0, has(pv) ? length_units(word(pv)) : 0);
  } else {
    qc = Eigen::Vector2d(has(pu) ? length_units(word(pu)) : q0.x(), has(pv) ? length_units(word(pv)) : q0.y());
  }
  AxisValues centre_p = start_p;
  centre_p[u] = qc.x();
  centre_p[v] = qc.y();
  const AxisValues centre_m = to_machine(centre_p);
  const Eigen::Vector2d p0(kernel_.position()[u], kernel_.position()[v]);
  const Eigen::Vector2d p1(t[u], t[v]);
  Eigen::Vector2d centre(centre_m[u], centre_m[v]);
  if (radius_form && unequal) {
    const double r = length_units(word(conv_.radius_word)) * std::max(frame.scale[u], frame.scale[v]);
    const double chord = (p1 - p0).norm();
    if (chord > 2 * std::fabs(r) + conv_.arc_tolerance)
      return fail(fmt::format("the scaled end point is {} away, more than the diameter {} of the scaled R",
                              four_decimals(to_program(chord)), four_decimals(to_program(2 * std::fabs(r)))));
    const double h = std::sqrt(std::max(0.0, r * r - chord * chord / 4));
    const Eigen::Vector2d along = (p1 - p0) / chord, left(-along.y(), along.x());
    centre = (p0 + p1) / 2 + ((clockwise == (r < 0)) ? 1 : -1) * h * left;
  }
  arc_move(t, centre.x(), centre.y(), clockwise, pu, pw);
}

// The arc from where the machine stands to t about the centre (machine coordinates of
// the plane); pu names the centre's word, pw the helix lead's, in messages.
void Machine::arc_move(const AxisValues& t, double centre_u, double centre_v, bool clockwise, char pu, char pw) {
  const int u = modal_.plane.u, v = modal_.plane.v, w = modal_.plane.w;
  const bool plane_words = conv_.centre_words == CentreWords::Plane;
  const Eigen::Vector2d p0(kernel_.position()[u], kernel_.position()[v]);
  const Eigen::Vector2d p1(t[u], t[v]);
  const Eigen::Vector2d centre(centre_u, centre_v);
  const double r0 = (p0 - centre).norm();
  const double r1 = (p1 - centre).norm();
  if (r0 < kSamePoint) {
    report(DiagId::ArcZeroRadius, pu);
    move_to(t);
    return;
  }
  if (std::fabs(r0 - r1) > conv_.arc_tolerance + kSamePoint) {
    report(DiagId::ArcRadiusMismatch, 0, four_decimals(to_program(r0)), four_decimals(to_program(r1)),
           four_decimals(to_program(std::fabs(r0 - r1))), four_decimals(to_program(conv_.arc_tolerance)));
    move_to(t);
    return;
  }
  const double a0 = std::atan2(p0.y() - centre.y(), p0.x() - centre.x());
  const double a1 = std::atan2(p1.y() - centre.y(), p1.x() - centre.x());
  // End point = start point: a full circle (S-9.4).
  double sweep = (p1 - p0).norm() < kSamePoint ? kTwoPi : wrap(clockwise ? a0 - a1 : a1 - a0);
  if (sweep == 0) sweep = kTwoPi;

  // Linear-circular interpolation (§4.3.4, Appendix 4; NC-110 §2.8.1.6): the
  // perpendicular axis moves and its parameter is the travel per radian (or per
  // revolution: the pitch).
  const double dw = w >= 0 ? t[w] - kernel_.position()[w] : 0;
  if (std::fabs(dw) > kSamePoint && !modal_.helix) {
    report(DiagId::ArcForm, kAxisLetters[w],
           fmt::format("{} is not in the {} plane of the arc, and the helix mode is off", kAxisLetters[w],
                       plane_name(modal_.plane)));
    move_to(t);
    return;
  }
  if (std::fabs(dw) > kSamePoint) {
    const bool per_revolution = conv_.helix_lead == HelixLead::PerRevolution;
    auto lead = word_if(pw);
    if (!lead) lead = helix_pitch_;  // pp G10 K
    if (lead) {
      // The lead selects the number of turns; the end point stays as programmed. It
      // must agree with the travel: lead x sweep = travel, within the arc tolerance
      // plus the rounding of the lead word over the sweep.
      double per_radian = length_units(*lead) / (per_revolution ? kTwoPi : 1);
      double candidate = sweep;
      if (per_radian != 0) {
        double lead_angle = std::fabs(dw / per_radian);
        candidate = sweep + kTwoPi * std::round((lead_angle - sweep) / kTwoPi);
        if (candidate <= 0) candidate = sweep;
      }
      double off = std::fabs(candidate * std::fabs(per_radian) - std::fabs(dw));
      double slack = conv_.arc_tolerance + kSamePoint +
                     candidate * length_units(conv_.lead_resolution) / 2 / (per_revolution ? kTwoPi : 1);
      if (per_radian <= 0 && plane_words) {  // NC-110: a pitch; the travel's sign comes from the axis word
        report(DiagId::ArcForm, pw, fmt::format("the helix pitch {}{} must be greater than zero", pw, shortest(*lead)));
        move_to(t);
        return;
      }
      if (per_radian == 0 || off > slack || (!plane_words && dw / per_radian <= 0)) {
        // In the unit of the lead: turns for a pitch, radians for a lead per radian.
        auto angle = [&](double radians) {
          return per_revolution ? fmt::format("{} turns", four_decimals(radians / kTwoPi))
                                : fmt::format("{} rad", four_decimals(radians));
        };
        report(DiagId::HelixLead, pw,
               plane_words ? fmt::format("helix pitch {}{}", pw, four_decimals(*lead))
                           : "helix lead " + four_decimals(*lead),
               four_decimals(to_program(dw)),
               per_radian == 0 ? std::string("infinitely many rad") : angle(std::fabs(dw / per_radian)), angle(sweep));
        move_to(t);
        return;
      }
      sweep = candidate;
    } else if (!plane_words && !conv_.helix_by_end) {
      report(DiagId::HelixNoLead, 0, std::string(1, pw), std::string(1, kAxisLetters[w]),
             per_revolution ? "revolution" : "radian");
    }
  }
  if (conv_.arc_single_quadrant) {
    // §4.3.5: the arc may not cross the lines through the centre parallel to u or v.
    // The angle from the start to the next boundary in the direction of travel.
    double into_quadrant = std::fmod(wrap(a0), kPi / 2);
    double to_boundary = clockwise ? into_quadrant : kPi / 2 - into_quadrant;
    if (to_boundary < 1e-12) to_boundary = kPi / 2;
    if (sweep > to_boundary + 1e-9) {
      report(DiagId::ArcQuadrant, 0, four_decimals(sweep * 180 / kPi));
      move_to(t);
      return;
    }
  }
  if (sweep / kTwoPi > kMaxTurns) {
    report(DiagId::HelixTurns, pw, four_decimals(sweep / kTwoPi), kMaxTurns);
    move_to(t);
    return;
  }
  // The path for the limit checks: chords no farther than kChord from the arc.
  if (virtual_axes_.mode == 1 || kernel_.envelope().any_limit() || kernel_.envelope().any_zone()) {
    double step = 2 * std::acos(std::max(0.0, 1 - kChord / r0));
    const int chords =
        whole_in(std::clamp(std::ceil(sweep / std::max(step, 1e-6)), 1.0, 100000.0), 1, 100000).value_or(1);
    // The fractions of the sweep: the chords' ends and where the arc is farthest
    // along u or v (the quarter turns from the start's angle, in the first and the
    // last turn: a helix repeats them in between).
    std::vector<double> fractions;
    for (int k = 0; k <= chords; ++k) fractions.push_back(static_cast<double>(k) / chords);
    const double to_quarter = clockwise ? std::fmod(wrap(a0), kPi / 2) : kPi / 2 - std::fmod(wrap(a0), kPi / 2);
    for (double s = to_quarter; s < sweep; s += kPi / 2) {
      if (s >= kTwoPi && s <= sweep - kTwoPi) s += std::floor((sweep - kTwoPi - s) / (kPi / 2)) * (kPi / 2);
      fractions.push_back(s / sweep);
    }
    std::sort(fractions.begin(), fractions.end());
    std::vector<AxisValues> path;
    for (double f : fractions) {
      double a = a0 + (clockwise ? -1 : 1) * sweep * f;
      AxisValues p = kernel_.position();
      for (int i = 0; i < kAxisCount; ++i) p[i] += (t[i] - kernel_.position()[i]) * f;
      double r = r0 + (r1 - r0) * f;
      p[u] = centre.x() + r * std::cos(a);
      p[v] = centre.y() + r * std::sin(a);
      path.push_back(p);
    }
    path.back() = t;
    if (!path_allowed(path)) return move_to(t);
  }
  double length = std::hypot((r0 + r1) / 2 * sweep, dw);
  const double own = block_seconds();
  kernel_.advance_clock(own ? own : system_value(SysVar::RapidRun) == 1 ? 0 : feed_time(length));
  if (kernel_.wanted(EventKind::Arc)) {
    Event e = motion_event(EventKind::Arc, t);
    e.plane = modal_.plane;
    AxisValues off = kernel_.shown_origins();
    e.centre[0] = program_axis(u, centre.x() - off[u]);
    e.centre[1] = program_axis(v, centre.y() - off[v]);
    e.a = to_program(r0);
    e.b = sweep * 180 / kPi;
    e.rotation = clockwise ? -corner::turns(e.b) : corner::turns(e.b);
    emit(e);
  }
  move_to(t);
}

// ---- Parabolas (GOST §4.4) ----------------------------------------------------------

void Machine::parabola(const AxisValues& t) {
  if (!need_feed("parabolic interpolation", t)) return;
  AxisValues off = target_frame();
  Eigen::Vector3d p0(kernel_.position()[0], kernel_.position()[1], kernel_.position()[2]);
  Eigen::Vector3d p2(t[0], t[1], t[2]);
  Eigen::Vector3d control;
  if (has('I') || has('J') || has('K')) {
    // §4.4.3, one block: I, J, K give the intersection of the end tangents.
    if (parabola_middle_) {
      report(DiagId::ParabolaPair, 0, "this block is a one-block parabola");
      parabola_middle_.reset();
      move_to(t);
      return;
    }
    for (int i = 0; i < 3; ++i) {
      char letter = kParameterOf[i];
      if (!has(letter)) {
        control[i] = p0[i];
        continue;
      }
      double v = length_units(word(letter));
      bool coordinates = conv_.parabola_tangent == ParabolaTangent::Coordinates && modal_.absolute;
      control[i] = coordinates ? v + off[i] : p0[i] + v;
    }
  } else if (!parabola_middle_) {
    // §4.4.2, first of two blocks: the intermediate point. Nothing moves yet.
    parabola_middle_ = t;
    return;
  } else {
    // Second block: the end point. The intermediate point is the curve at t = 1/2,
    // so the tangent intersection is 2*P1 - (P0 + P2)/2.
    Eigen::Vector3d p1((*parabola_middle_)[0], (*parabola_middle_)[1], (*parabola_middle_)[2]);
    control = 2 * p1 - (p0 + p2) / 2;
    parabola_middle_.reset();
  }
  Event e = motion_event(EventKind::Parabola, t);
  AxisValues shown = kernel_.shown_origins();
  for (int i = 0; i < 3; ++i) e.control[i] = to_program(control[i] - shown[i]);
  emit(e);
  move_to(t);
}

// ---- Threads ------------------------------------------------------------------------

void Machine::thread(const AxisValues& t) {
  // GOST §7.1: the thread length in X and/or Z, the pitch in I or K (mm per
  // revolution), measured along the axis of the pitch word.
  std::string candidates = conv_.thread_allow_j ? "IJK" : "IK";
  std::string given;
  for (char c : candidates)
    if (has(c)) given += c;
  auto listed = [](const std::string& letters, const char* last) {
    std::string list;
    for (size_t i = 0; i < letters.size(); ++i)
      list += (i ? (i + 1 == letters.size() ? last : ", ") : "") + std::string(1, letters[i]);
    return list;
  };
  bool ok = true;
  if (given.size() != 1) {
    report(DiagId::ThreadPitch, 0, listed(candidates, " or "),
           given.empty()
               ? std::string("none is programmed")
               : fmt::format("{} {} programmed", listed(given, " and "), given.size() == 2 ? "are both" : "are all"));
    ok = false;
  }
  if (has('F')) {
    report(DiagId::ThreadFeed, 'F', motion_name_);
    ok = false;
  }
  const char pitch_word = ok ? given[0] : 0;
  const int pitch_axis = pitch_word ? pitch_word - 'I' : 0;
  double pitch = ok ? length_units(word(pitch_word)) : 0;
  if (ok && pitch <= 0) {
    report(DiagId::ThreadPitchSign, pitch_word, fmt::format("{}{}", pitch_word, four_decimals(word(pitch_word))));
    ok = false;
  }
  const double length = std::fabs(t[pitch_axis] - kernel_.position()[pitch_axis]);
  if (ok && length < kSamePoint) {
    report(DiagId::ThreadPitchAxis, pitch_word, std::string(1, pitch_word), std::string(1, kAxisLetters[pitch_axis]));
    ok = false;
  }
  double change = 0;
  if (modal_.motion != Fn::MotionThread && ok) {
    // §7.4: G34/G35 start from the initial pitch; how the change is given is the NC's.
    const bool decreasing = modal_.motion == Fn::MotionThreadDecreasing;
    if (!conv_.pitch_change_word) {
      report(DiagId::ThreadPitchChangeUndefined, 0, motion_name_);
      ok = false;
    } else if (!has(conv_.pitch_change_word)) {
      report(DiagId::ThreadNoPitchChange, 0, motion_name_, std::string(1, conv_.pitch_change_word));
      ok = false;
    } else if (double d = word(conv_.pitch_change_word); d <= 0) {
      report(DiagId::ThreadPitchChangeSign, conv_.pitch_change_word, four_decimals(d), motion_name_,
             decreasing ? "subtracts" : "adds");
      ok = false;
    } else {
      change = length_units(d) * (decreasing ? -1 : 1);
      // After n revolutions the pitch is p + n*change and the thread has advanced
      // p*n + change*n*n/2; a decreasing pitch must not reach zero before the end.
      double reach = decreasing ? pitch * pitch / (2 * -change) : INFINITY;
      if (length > reach) {
        report(DiagId::ThreadPitchZero, conv_.pitch_change_word, motion_name_, four_decimals(to_program(reach)),
               four_decimals(to_program(length)));
        ok = false;
      }
    }
  }
  if (ok && (std::abs(modal_.spindle) != 1 || speed_ <= 0)) {
    report(DiagId::ThreadNoSpindle, 0);
    ok = false;
  }
  if (ok) {
    Event e = motion_event(EventKind::Thread, t);
    e.a = to_program(pitch);
    e.b = to_program(change);
    emit(e);
  }
  move_to(t);
}

void Machine::thread_variable(const AxisValues& t) {
  // NC-110 §2.8.1.7: K the pitch (in every block), I its change, R the spindle angle
  // the thread starts at. The pitch grows by I for every K of travel along the lead
  // axis: p(s) = K + I*s/K, so formula 2.1 (|I| <= K*K/L) is exactly "the pitch stays
  // above zero" (decision 9).
  bool ok = true;
  if (!has('K')) {
    report(DiagId::ThreadPitch, 0, "K", "none is programmed");
    ok = false;
  }
  const double pitch = ok ? length_units(word('K')) : 0;
  if (ok && pitch <= 0) {
    report(DiagId::ThreadPitchSign, 'K', fmt::format("K{}", four_decimals(word('K'))));
    ok = false;
  }
  const double change = has('I') ? length_units(word('I')) : 0;
  const double phase = has('R') ? word('R') : 0;
  // The lead axis: the longest travel, a diametral axis counting half.
  double length = 0;
  for (int i = 0; i < kAxisCount; ++i)
    if (is_linear(i))
      length = std::max(
          length, std::fabs(t[i] - kernel_.position()[i]) / (config_.axes[static_cast<size_t>(i)].diameter ? 2 : 1));
  if (ok && length < kSamePoint) {
    report(DiagId::ThreadNoTravel, 0, motion_name_);
    ok = false;
  }
  if (ok && change < 0 && -change * length >= pitch * pitch) {
    report(DiagId::ThreadPitchZero, 'I', motion_name_, four_decimals(to_program(pitch * pitch / -change)),
           four_decimals(to_program(length)));
    ok = false;
  }
  if (ok && !config_.spindle_encoder) {
    report(DiagId::ThreadEncoder, 0, motion_name_);
    ok = false;
  }
  double rpm = spindle_rpm();
  if (ok && rpm <= 0) {
    report(DiagId::ThreadNoSpindle, 0);
    ok = false;
  }
  if (!ok || !path_allowed({kernel_.position(), t})) return move_to(t);
  double turns = change == 0 ? length / pitch : pitch / change * std::log1p(change * length / (pitch * pitch));
  kernel_.advance_clock(60 * turns / rpm);
  Event e = motion_event(EventKind::Thread, t);
  e.a = to_program(pitch);
  e.b = to_program(change);
  e.c = phase;
  emit(e);
  move_to(t);
}

// ---- Splines (NC-110 G06, §2.8.1.3) -------------------------------------------------

void Machine::spline_point(const AxisValues& t) {
  if (!spline_.active || !spline_.lead_in || spline_.points.empty()) {
    report(DiagId::SplineStructure, 0,
           !spline_.active ? "G06 stands only between (BSP) and (ESP)"
           : spline_.lead_in
               ? "G06 after the spline's lead-out: (ESP) comes first"
               : "G06 needs the lead-in first: a G00 or G01 block after (BSP) goes to the spline's start");
    return move_to(t);
  }
  if (!need_feed("spline interpolation", t)) return;
  double gap = 0;
  for (int i = 0; i < kAxisCount; ++i) gap = std::max(gap, std::fabs(t[i] - spline_.points.back()[i]));
  if (gap < kSamePoint) {
    report(DiagId::SplineStructure, 0, "a spline point equal to the one before it");
    return;
  }
  spline_.points.push_back(t);
  spline_.sources.push_back(block_.request->source);
  kernel_.move_to(t);  // the spline is cut at its lead-out; the program goes on from here
}

void Machine::spline_finish(const AxisValues& lead_out_end) {
  // The points Q0..Qm, the entry tangent from the lead-in, the exit tangent to the
  // lead-out; each span a cubic Bezier curve (runtime/spline.h).
  const int u = spline_.u, v = spline_.v;
  std::vector<Eigen::Vector2d> points;
  for (const AxisValues& p : spline_.points) points.emplace_back(p[u], p[v]);
  Eigen::Vector2d in(points.front() - Eigen::Vector2d(spline_.lead_in_from[u], spline_.lead_in_from[v]));
  Eigen::Vector2d out(Eigen::Vector2d(lead_out_end[u], lead_out_end[v]) - points.back());
  SplineEnd start{spline_.ends == 1 || spline_.ends == 3, in};
  SplineEnd end{spline_.ends == 2 || spline_.ends == 3, out};
  if (start.clamped && in.norm() < kSamePoint) {
    // At the lead-in's block, where the tangent should come from.
    const BlockRequest* here = block_.request;
    BlockRequest lead_in{nullptr, 0, here->words, spline_.sources[0]};
    block_.request = &lead_in;
    report(DiagId::SplineStructure, 0, "a tangent start needs a lead-in of some length: this block does not move");
    block_.request = here;
    start.clamped = false;
  }
  if (end.clamped && out.norm() < kSamePoint) {
    report(DiagId::SplineStructure, 0, "a tangent end needs a lead-out of some length: this block does not move");
    end.clamped = false;
  }
  const std::vector<BezierSpan> spans = cubic_spline(points, start, end);
  const AxisValues off = kernel_.shown_origins();
  const BlockRequest* lead_out = block_.request;
  for (size_t i = 0; i < spans.size(); ++i) {
    const AxisValues& from = spline_.points[i];
    const AxisValues& to = spline_.points[i + 1];
    // Each span's events and problems belong to its G06 block.
    BlockRequest span{nullptr, 0, lead_out->words, spline_.sources[i + 1]};
    block_.request = &span;
    std::vector<AxisValues> path;
    for (int k = 0; k <= 32; ++k) {
      double s = k / 32.0;
      AxisValues p = from;
      for (int a = 0; a < kAxisCount; ++a) p[a] += (to[a] - from[a]) * s;
      Eigen::Vector2d q = point_at(spans[i], s);
      p[u] = q.x();
      p[v] = q.y();
      path.push_back(p);
    }
    if (path_allowed(path)) {
      // The axes outside the plane move linearly: their control points at 1/3, 2/3.
      Event e = motion_event(EventKind::Spline, to);
      AxisValues c1 = from, c2 = from;
      double other = 0;
      for (int a = 0; a < kAxisCount; ++a) {
        c1[a] += (to[a] - from[a]) / 3;
        c2[a] += (to[a] - from[a]) * 2 / 3;
        if (a != u && a != v) other += (to[a] - from[a]) * (to[a] - from[a]);
      }
      c1[u] = spans[i].p1.x();
      c1[v] = spans[i].p1.y();
      c2[u] = spans[i].p2.x();
      c2[v] = spans[i].p2.y();
      for (int a = 0; a < kAxisCount; ++a) {
        e.control[a] = program_axis(a, c1[a] - off[a]);
        e.control2[a] = program_axis(a, c2[a] - off[a]);
      }
      kernel_.advance_clock(feed_time(std::hypot(spans[i].length, std::sqrt(other))));
      emit(e);
    }
  }
  block_.request = lead_out;
  spline_.points.clear();
  spline_.sources.clear();
}

// ---- Dwells -------------------------------------------------------------------------

void Machine::dwell() {
  auto time = word_if(conv_.dwell_word);
  if (!time) {
    report(DiagId::DwellNoTime, 0, dwell_address());
    return;
  }
  if (*time < 0) {
    report(DiagId::DwellNegative, conv_.dwell_word, four_decimals(*time));
    return;
  }
  dwell_seconds(*time * conv_.dwell_seconds_per_unit);
}

void Machine::dwell_seconds(double seconds) {
  Event e{EventKind::Dwell};
  e.a = seconds;
  emit(e);
  kernel_.advance_clock(seconds);
}

double Machine::timer_dwell() {
  // NC-110 §2.10.1: TMR is seconds under G94 (at most 60) and spindle revolutions
  // under G95 (at most 30000), as the dwell runs.
  double value = system_value(SysVar::DwellTime);
  const std::string name = system_name({SysVar::DwellTime, 0});
  if (modal_.feed_mode == 2) {
    if (value > kMaxDwellRevolutions) {
      report(DiagId::DwellTime, 0, fmt::format("{}={}", name, shortest(value)), "exceeds 30000 revolutions (G95)");
      return 0;
    }
    double rpm = spindle_rpm();
    if (value > 0 && rpm <= 0) {
      report(DiagId::DwellTime, 0, fmt::format("{}={}", name, shortest(value)),
             "counts spindle revolutions (G95), and the spindle is not turning");
      return 0;
    }
    return value > 0 ? 60 * value / rpm : 0;
  }
  if (value > kMaxDwellSeconds) {
    report(DiagId::DwellTime, 0, fmt::format("{}={}", name, shortest(value)), "exceeds 60 s");
    return 0;
  }
  return value;
}

std::string Machine::dwell_address() const {
  return conv_.dwell_word ? std::string(1, conv_.dwell_word) : std::string("a dwell address, which this machine lacks");
}

}  // namespace ncc

// ---- Chamfers and fillets (ISO §8.3) ---------------------------------------------------

namespace ncc {

namespace {
bool is_move(const Event& e) { return e.kind == EventKind::Linear || e.kind == EventKind::Arc; }
}  // namespace

bool Machine::corner_requested() const {
  return conv_.corners && (has_slot(second_slot('C')) || has_slot(second_slot('R')));
}

void Machine::release() {
  corner_.reset();
  chained_start_.reset();
  kernel_.release();
}

void Machine::corner_codes() {
  // E-06: after a corner only G01-G03, G90/G91, G20/G21, G04 and M codes but M06.
  for (size_t i = 0; i < block_.request->code_count; ++i)
    for (const FnCall& call : sem_.codes[block_.request->codes[i]].calls) {
      const FnGroup g = fn_group(call.fn);
      const bool ok = call.fn == Fn::MotionLinear || call.fn == Fn::MotionArcCw || call.fn == Fn::MotionArcCcw ||
                      g == FnGroup::Distance || g == FnGroup::Units || call.fn == Fn::Dwell ||
                      (call.fn != Fn::ToolChange && sem_.codes[block_.request->codes[i]].name[0] == 'M');
      // A unit change would put the two moves in different units: ncc refuses it.
      if (!ok || (g == FnGroup::Units && (call.fn == Fn::UnitsInch) != corner_->inch))
        issue({DiagId::CornerForm,
               diag_message(
                   DiagId::CornerForm,
                   fmt::format("{} cannot stand in the block after it ({})", sem_.codes[block_.request->codes[i]].name,
                               g == FnGroup::Units ? "ncc: a unit change across a corner" : "E-06")),
               block_.request->source, -1, static_cast<int>(block_.request->codes[i])});
    }
}

void Machine::corner_begin(const AxisValues& start) {
  const bool fillet = has_slot(second_slot('R'));
  const int slot = second_slot(fillet ? 'R' : 'C');
  const double size = slot_value(slot);
  const bool feed =
      modal_.motion == Fn::MotionLinear || modal_.motion == Fn::MotionArcCw || modal_.motion == Fn::MotionArcCcw;
  if (block_.error) return release();  // its block failed: reported already
  const std::vector<Event>& held = kernel_.held();
  size_t incoming = held.size(), moves = 0;
  for (size_t i = 0; i < held.size(); ++i)
    if (is_move(held[i]) || held[i].kind == EventKind::Rapid) {
      incoming = i;
      ++moves;
    }
  std::string why = !feed || modal_.cycle >= 0     ? "it follows a feed move G01, G02 or G03 only (E-03)"
                    : moves > 1 && !chained_start_ ? "its block makes more than the one feed move it follows (E-03)"
                    : modal_.polar                 ? "it is not made in polar coordinates, G16 (E-07)"
                    : incoming == held.size()      ? "its block makes no feed move (E-03)"
                                                   : "";
  if (!why.empty()) {
    report_slot(DiagId::CornerForm, slot, why);
    release();
    return;
  }
  corner_ = Corner{fillet, size, block_.request->source, slot, incoming, chained_start_.value_or(start), modal_.inch};
  chained_start_.reset();
}

void Machine::corner_finish(bool another, size_t block_from) {
  Corner c = *corner_;
  std::vector<Event>& held = kernel_.held();
  size_t outgoing = c.incoming + 1;
  while (outgoing < held.size() && !is_move(held[outgoing]) && held[outgoing].kind != EventKind::Rapid) ++outgoing;
  auto fail = [&](const std::string& why) {
    issue({DiagId::CornerForm, diag_message(DiagId::CornerForm, why), c.source, c.slot, -1});
    if (!another) return release();
    // This block's own corner still waits: only what came before it goes out.
    kernel_.pass_on(block_from);
    corner_.reset();
  };
  if (block_.error) return release();  // reported already (E-06)
  const int pu = modal_.plane.u, pv = modal_.plane.v;
  if (outgoing == held.size() || !is_move(held[outgoing]) ||
      (held[outgoing].kind == EventKind::Linear &&
       std::hypot(held[outgoing].pos[pu] - held[c.incoming].pos[pu],
                  held[outgoing].pos[pv] - held[c.incoming].pos[pv]) < 1e-9))
    return fail("the next block must make a feed move in the plane (E-04)");
  const int u = modal_.plane.u, v = modal_.plane.v;
  auto in_plane = [&](const AxisValues& p) { return corner::Vec(p[u], p[v]); };
  auto element = [&](const AxisValues& from, const Event& e) {
    corner::Element el{in_plane(from), in_plane(e.pos)};
    if (e.kind == EventKind::Arc) {
      el.arc = true;
      el.c = {e.centre[0], e.centre[1]};
      el.ccw = e.rotation > 0;
      el.sweep = e.b * kPi / 180;
    }
    return el;
  };
  Event& in = held[c.incoming];
  Event& next = held[outgoing];
  const AxisValues corner_point = in.pos;
  std::string why;
  auto cut = corner::cut(element(c.start, in), element(corner_point, next), c.fillet, c.size, why);
  if (!cut) return fail(why + " (E-02)");
  // The other axes (a helix's) go along in proportion.
  auto point = [&](const AxisValues& from, const AxisValues& to, double f, const corner::Vec& q) {
    AxisValues p = from;
    for (int i = 0; i < kAxisCount; ++i) p[i] = from[i] + (to[i] - from[i]) * f;
    p[u] = q.x();
    p[v] = q.y();
    return p;
  };
  auto shorten = [&](Event& e, double radians) {
    e.b -= radians * 180 / kPi;
    e.rotation = e.rotation < 0 ? -corner::turns(e.b) : corner::turns(e.b);
  };
  const AxisValues t2 = point(corner_point, next.pos, cut->out_fraction, cut->t2);
  in.pos = point(c.start, corner_point, cut->in_fraction, cut->t1);
  if (in.kind == EventKind::Arc) shorten(in, cut->in_cut);
  if (next.kind == EventKind::Arc) shorten(next, cut->out_cut);
  Event joint{cut->fillet ? EventKind::Arc : EventKind::Linear};
  joint.source = c.source;
  joint.pos = t2;
  if (cut->fillet) {
    joint.plane = modal_.plane;
    joint.centre[0] = cut->centre.x();
    joint.centre[1] = cut->centre.y();
    joint.rotation = cut->ccw ? 1 : -1;
    joint.a = c.size;
    joint.b = cut->fillet_sweep * 180 / kPi;
  }
  held.insert(held.begin() + static_cast<std::ptrdiff_t>(c.incoming) + 1, joint);
  if (!another) {
    release();
    return;
  }
  // The outgoing move has a corner of its own: it stays held, starting at T2.
  corner_.reset();
  chained_start_ = t2;
}

}  // namespace ncc
