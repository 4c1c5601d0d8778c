// Coordinates: work offsets and origins, the NC-110 transforms (scale, mirror,
// rotation), the three-letter functions that set them, and the working limits and
// protected zones every move is checked against before it starts.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "machine.h"
#include "support/text.h"

namespace ncc {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

// Programmed positions live on a nanometre grid, so that increments add up exactly
// as decimals do (0.1 + 0.2 is 0.3) and traces stay bit-for-bit stable. Beyond 2^53
// nanometres (9 km) a double holds no finer grid.
double snap(double v) { return std::fabs(v) < 9e6 ? std::round(v * 1e9) / 1e9 : v; }

// A position no machine reaches (mm or degrees: 10,000 km, 28 million turns) is a
// value gone wrong: X1E300, a scale on a huge offset.
constexpr double kMaxPosition = 1e10;

}  // namespace

bool Machine::has_axis_word() const {
  for (char axis : conv_.axes)
    if (has(axis)) return true;
  return false;
}

AxisValues Machine::program_target() {
  // The words replace (G90, G79) or add to (G91) the current position in program
  // coordinates; an axis not written stays (NC-110 decision 5). Blocks 2 of a
  // three-point parabola measure from the intermediate point (GOST Appendix 5).
  const AxisValues base = to_frame(parabola_middle_ ? *parabola_middle_ : kernel_.position());
  AxisValues p = base;
  const bool absolute = modal_.absolute || block_.machine_frame;
  for (char letter : conv_.axes) {
    if (!has(letter)) continue;
    int i = axis_index(letter);
    double written = word(letter);
    if (config_.axes[static_cast<size_t>(i)].kind == AxisKind::Indexing &&
        (written != std::trunc(written) || std::fabs(written) > 99999)) {
      report(DiagId::IndexValue, letter, fmt::format("{}{}", letter, four_decimals(written)));
      continue;
    }
    double v = axis_units(i, written);
    p[i] = absolute ? v : base[i] + v;
  }
  // ISO §8.6 (G16): the plane's first word is a radius, its second an angle in
  // degrees from the first axis; about the work zero under G90, about the position
  // under G91. A word not written keeps the position's value (decision 25).
  const int u = modal_.plane.u, v = modal_.plane.v;
  const char lu = kAxisLetters[u], lv = kAxisLetters[v];
  if (modal_.polar && !block_.machine_frame && (has(lu) || has(lv))) {
    const double ou = absolute ? 0 : base[u], ov = absolute ? 0 : base[v];
    const double r = has(lu) ? axis_units(u, word(lu)) : absolute ? std::hypot(base[u], base[v]) : 0;
    const double a = has(lv) ? word(lv) : absolute ? std::atan2(base[v], base[u]) / kDegree : 0;
    p[u] = ou + r * std::cos(a * kDegree);
    p[v] = ov + r * std::sin(a * kDegree);
  }
  // NC-110 §2.9: u, v, w move the point the block programs on the plane's abscissa,
  // ordinate and normal by the tool's radius times the factor (action() checks them).
  for (int k = 0; k < 3; ++k) {
    const char factor = "uvw"[k];
    const int axis = k == 0 ? u : k == 1 ? v : modal_.plane.w;
    if (has(factor) && axis >= 0 && has(kAxisLetters[axis])) p[axis] += tool_radius() * word(factor);
  }
  return p;
}

double Machine::tool_radius() const { return offset_.radius; }

bool Machine::position_in_range(int axis, double v) {
  if (std::fabs(v) <= kMaxPosition) return true;
  const char letter = kAxisLetters[axis];
  report(DiagId::PositionRange, has(letter) ? letter : 0, letter,
         shortest(program_axis(axis, v - kernel_.origin(axis))), "10,000,000,000 mm (or degrees)");
  return false;
}

AxisValues Machine::target() {
  const AxisValues& from = parabola_middle_ ? *parabola_middle_ : kernel_.position();
  const AxisValues off = target_frame();
  AxisValues t = from;
  if (kernel_.transforms(block_origin())) {
    t = to_machine(program_target());
    for (double& v : t) v = snap(v);
  } else {
    // Untransformed: unwritten axes stay exactly where they are (under G16 a radius or
    // an angle moves both axes of the plane).
    AxisValues p = program_target();
    const int u = modal_.plane.u, v = modal_.plane.v;
    const bool polar = modal_.polar && !block_.machine_frame && (has(kAxisLetters[u]) || has(kAxisLetters[v]));
    for (char letter : conv_.axes) {
      const int i = axis_index(letter);
      if (has(letter) || (polar && (i == u || i == v))) t[i] = snap(p[i] + off[i]);
    }
  }
  // A position out of any machine's range is refused: the axis stays.
  for (int i = 0; i < kAxisCount; ++i)
    if (!position_in_range(i, t[i])) t[i] = from[i];
  // An endless rotary axis goes the way the target's sign says; 0 the short way
  // (NC-110 §2.8.4, decision 48), with or without a transform.
  if (!modal_.absolute && !block_.machine_frame) return t;
  for (char letter : conv_.axes) {
    int i = axis_index(letter);
    const AxisConfig& a = config_.axes[static_cast<size_t>(i)];
    if (!has(letter) || !a.endless || a.kind != AxisKind::Rotary) continue;
    double written = angle_degrees(word(letter));
    if (std::fabs(written) >= 360) {  // 0..359.9999, its sign the way round
      report(DiagId::ValueRange, letter, fmt::format("{}{}", letter, four_decimals(word(letter))),
             "an endless rotary axis under G90", "-359.9999", "359.9999");
      t[i] = from[i];
      continue;
    }
    double at = std::fmod(from[i] - off[i], 360.0);
    if (at < 0) at += 360;
    double to = std::fmod(std::fabs(written), 360.0);
    double ahead = std::fmod(to - at + 360.0, 360.0);
    double delta = written > 0   ? ahead
                   : written < 0 ? (ahead == 0 ? 0 : ahead - 360)
                                 : (ahead <= 180 ? ahead : ahead - 360);
    t[i] = snap(from[i] + delta);
  }
  return t;
}

void Machine::origin_event() {
  Event e{EventKind::Origin};
  e.pos = in_program_units(kernel_.origins());
  emit(e);
}

void Machine::transform_event() {
  Event e{EventKind::Transform};
  e.a = kernel_.frame().rotation;
  for (int i = 0; i < kAxisCount; ++i) {
    e.pos[i] = kernel_.frame().scale[i];
    if (kernel_.frame().mirror[i]) e.n |= 1 << i;
  }
  emit(e);
}

void Machine::set_position() {
  // The named axes take the programmed values as their current coordinates; nothing
  // moves (Table 5). Incremental values add to the current coordinates. ISO §8.19:
  // the G52 shifts end.
  // After a motion in its block (ISO §8.19) the values are the axes' second words.
  const bool after = block_.set_position_after;
  kernel_.local_offsets().clear();
  kernel_.frame().local.fill(0);
  for (char letter : conv_.axes) {
    const int slot = after ? second_slot(letter) : letter_slot(letter);
    if (!has_slot(slot)) continue;
    int i = axis_index(letter);
    double v = axis_units(i, slot_value(slot));
    double work = kernel_.offset_value(modal_.work_offset, i);
    double current = kernel_.position()[i] - work - kernel_.frame().shift[i];
    double wanted = modal_.absolute ? v : current + v;
    kernel_.frame().shift[i] = kernel_.position()[i] - work - wanted;
  }
  position_offset_event();
}

// The shift of the work zero beyond the work offset: G92 and G52 together, as
// LinuxCNC's G92 offset carries both.
void Machine::position_offset_event() {
  for (int i = 0; i < kAxisCount; ++i)
    kernel_.position_offset()[i] = kernel_.frame().shift[i] + kernel_.frame().local[i];
  Event e{EventKind::PositionOffset};
  e.pos = in_program_units(kernel_.position_offset());
  emit(e);
}

void Machine::set_local_offset() {
  // ISO §8.13: the axis words are the local zero in the work coordinate system (each
  // work offset keeps its own); an axis not written keeps its shift (decision 16).
  AxisValues& local = kernel_.local_offsets()[modal_.work_offset];
  for (char letter : conv_.axes)
    if (has(letter)) local[axis_index(letter)] = axis_units(axis_index(letter), word(letter));
  kernel_.frame().local = local;
  position_offset_event();
}

void Machine::data_set() {
  // ISO G10 (Fanuc, Haas; decision 61): L2 P1..P6 (G54..G59; ncc has no external
  // offset P0) and L20 P1.. load a work offset with the axis words; L10/L11
  // set the length, L12/L13 the radius of offset P, geometry or wear (an offset's
  // value is their sum). G90 gives the value, G91 adds it.
  const std::optional<int> l = has('L') ? whole_in(word('L'), 0, 99) : std::nullopt;
  if (!l || (*l != 2 && *l != 20 && (*l < 10 || *l > 13))) {
    report_code(DiagId::OperandValue, "G10 L", has('L') ? shortest(word('L')) : std::string("missing"),
                "L2 (work offsets G54-G59), L20 (extended work offsets), L10-L13 (tool offsets)");
    return;
  }
  if (!has('P')) {
    report_code(DiagId::OperandValue, fmt::format("G10 L{} P", *l), "missing", "the number of the offset to set");
    return;
  }
  const double written = word('P');
  if (*l == 2 || *l == 20) {
    const std::optional<int> p = whole_in(written, 1, *l == 2 ? 6 : kExtendedWorkOffsets);
    if (!p) {
      report(DiagId::OperandValue, 'P', fmt::format("G10 L{} P", *l), shortest(written),
             *l == 2 ? "1..6 (G54..G59; P0, the external work offset, is not modelled)"
                     : fmt::format("an extended work offset 1..{}", kExtendedWorkOffsets));
      return;
    }
    const int n = *l == 2 ? *p : kExtendedWorkOffset + *p;
    auto entry = kernel_.offsets().find(n);
    if (entry == kernel_.offsets().end()) {
      report(DiagId::WorkOffsetUnknown, 'P', fmt::format("G10 L{}", *l),
             fmt::format("work offset {}{}", *l == 2 ? "" : "P", *p), config_.profile,
             number_ranges(kernel_.offsets(), true));
      return;
    }
    for (char letter : conv_.axes) {
      if (!has(letter)) continue;
      const int i = axis_index(letter);
      const double value = axis_units(i, word(letter));
      double& stored = entry->second.values[i];
      const double mm = (modal_.absolute ? 0 : kernel_.offset_value(n, i)) + value;
      stored = entry->second.inch && is_linear(i) ? mm / 25.4 : mm;
      entry->second.axes |= 1u << i;
    }
    offset_loaded(n);
    return;
  }
  const std::optional<int> p = whole_in(written, 1, 9999);
  if (!p || !tool_offsets_.count(*p)) {
    report(DiagId::OffsetUnknown, 'P', fmt::format("G10 L{} offset", *l), shortest(written), config_.profile,
           number_ranges(tool_offsets_));
    return;
  }
  if (!has('R')) {
    report_code(DiagId::OperandValue, fmt::format("G10 L{} R", *l), "missing", "the value to set");
    return;
  }
  OffsetEntry& e = tool_offsets_[*p];
  const double value = length_units(word('R'));
  // The geometry is the value less the wear; wear_diameter keeps the radius's wear doubled.
  double& total = *l <= 11 ? e.length : e.radius;
  double& wear = *l <= 11 ? e.wear_length : e.wear_diameter;
  const double scale = *l <= 11 ? 1 : 0.5;
  const double old_wear = wear * scale;
  if (*l == 10 || *l == 12)
    total = (modal_.absolute ? value : total - old_wear + value) + old_wear;
  else {
    const double new_wear = modal_.absolute ? value : old_wear + value;
    total += new_wear - old_wear;
    wear = new_wear / scale;
  }
  if (e.radius < 0) {
    report(DiagId::OperandValue, 'R', fmt::format("G10 L{} R", *l), shortest(word('R')),
           fmt::format("a value that leaves offset {}'s radius not negative", *p));
    e.radius = 0;
  }
  comp_entry_loaded(*p);
}

void Machine::reference_return(const AxisValues& point) {
  // ISO §8.8: the named axes go at rapid through the point the words give (read in
  // G90/G91, in the work system) to the reference point; without words every axis
  // goes there directly. The length offset is zeroed on the way to the reference
  // point (G49 in the block: already on the way to the intermediate point). G30
  // goes so to its P-th point (decision 65).
  AxisValues t = kernel_.position();
  const bool offset = compensation().length != AxisValues{};
  if (!has_axis_word()) {
    intermediate_.reset();
    t = point;
  } else {
    const AxisValues mid = target();
    intermediate_ = mid;
    if (mid != kernel_.position()) rapid(mid);
    for (char letter : conv_.axes)
      if (has(letter)) t[axis_index(letter)] = point[axis_index(letter)];
  }
  if (offset) length_zeroed(true);
  if (t != kernel_.position()) rapid(t);
  if (offset) length_zeroed(false);
}

void Machine::length_zeroed(bool zero) {
  Event e{EventKind::ToolLengthOffset};
  if (!zero) {
    e.n = length_number_;  // the entry it comes from again (translation writes it)
    e.pos = in_program_units(compensation().length);
  }
  emit(e);
}

void Machine::reference_leave() {
  // ISO §8.9: from the reference point through G28's intermediate point on the named
  // axes (all without words), then to the words' point, read from there (decision 17).
  if (!intermediate_) {
    report_code(DiagId::ReferenceNoIntermediate, block_.code_name);
    return;
  }
  AxisValues mid = kernel_.position();
  const bool words = has_axis_word();
  // §8.9: the length offset comes back at the end point.
  const bool offset = compensation().length != AxisValues{};
  if (offset) length_zeroed(true);
  for (char letter : conv_.axes)
    if (!words || has(letter)) mid[axis_index(letter)] = (*intermediate_)[axis_index(letter)];
  if (mid != kernel_.position()) rapid(mid);
  const AxisValues t = words ? target() : kernel_.position();
  if (t != kernel_.position()) rapid(t);
  if (offset) length_zeroed(false);
}

void Machine::load_offset() {
  // pp G92: offset n becomes what makes the named axes read as their values where
  // the tool stands (shift = position - value, the value through the G35-G37
  // transformations); the values are positions, G91 or not.
  const int n = block_.load_entry >= 0 ? block_.load_entry : modal_.work_offset;
  WorkOffset& entry = kernel_.offsets()[n];
  for (char letter : conv_.axes) {
    if (!has(letter)) continue;
    int i = axis_index(letter);
    double v =
        kernel_.position()[i] - kernel_.frame().shift[i] - kernel_.frame().factor(i) * axis_units(i, word(letter));
    entry.values[i] = entry.inch && is_linear(i) ? v / 25.4 : v;
    entry.axes |= 1u << i;
  }
  offset_loaded(n);
}

void Machine::offset_loaded(int n) {
  Event e{EventKind::OffsetLoad};
  e.n = n;
  for (int i = 0; i < kAxisCount; ++i) e.pos[i] = program_axis(i, kernel_.offset_value(n, i));
  kernel_.refresh_origins();
  emit(e);
  // The shift in force changed: the trace says so as a selection would.
  if (n == modal_.work_offset && n != 0) {
    Event in_force{EventKind::WorkOffset};
    in_force.n = n;
    in_force.pos = e.pos;
    emit(in_force);
  }
}

void Machine::load_compensation() {
  // pp G93 (decision 23): entry D takes the length and radius the block's words give.
  auto entry = whole_number('D', "compensation entries");
  if (!entry || *entry == 0) {
    if (!block_.error)
      report(DiagId::OperandValue, 'D', "the compensation entry D", "missing", "in the block that loads it");
    return;
  }
  OffsetEntry& e = tool_offsets_[*entry];
  if (auto v = word_if(conv_.comp_length_word)) e.length = length_units(*v);
  if (auto v = word_if(conv_.comp_radius_word)) e.radius = length_units(*v);
  comp_entry_loaded(*entry);
}

void Machine::reference_approach() {
  // pp G30: the named axes go at rapid to the reference point; the others stay.
  AxisValues t = kernel_.position();
  for (char letter : conv_.axes) {
    if (!has(letter)) continue;
    int i = axis_index(letter);
    if (double v = word(letter); v != 0) report(DiagId::ReferenceValue, letter, std::string(1, letter), shortest(v));
    t[i] = config_.reference_position[i];
  }
  if (t != kernel_.position()) rapid(t);
}

// ---- The three-letter functions (NC-110 §2.13) ---------------------------------------

bool Machine::frame_function(FnCall call) {
  Frame& frame = kernel_.frame();
  // The operands: #1, #2... at the operand slots; axes at their letters' slots.
  auto operand = [&](int i) { return slot_if(operand_slot(i)); };
  auto whole = [&](int i, int lo, int hi, const char* what) { return whole_operand(i, lo, hi, what); };
  std::vector<int> listed;  // the axes the operands name, in canonical order
  for (char letter : conv_.axes)
    if (has(letter)) {
      listed.push_back(axis_index(letter));
      block_.used.set(letter_slot(letter));
    }
  auto value = [&](int axis) { return axis_units(axis, word(kAxisLetters[axis])); };
  const std::string code = block_.code_name;

  switch (call.fn) {
    case Fn::OriginSelect:
    case Fn::OriginTemporary:
    case Fn::OriginRequalify: {
      auto n = whole(0, 0, 99, "the origin");
      if (!n) break;
      auto record = kernel_.offsets().find(*n);
      if (*n != 0 && record == kernel_.offsets().end()) {
        report_slot(DiagId::WorkOffsetUnknown, operand_slot(0), code, fmt::format("origin {}", *n), config_.profile,
                    number_ranges(kernel_.offsets(), true));
        break;
      }
      // (UAO,n) without axes: every axis origin n declares (§2.13.1.1).
      if (listed.empty())
        for (int i = 0; i < kAxisCount; ++i)
          if (conv_.axes.find(kAxisLetters[i]) != std::string::npos &&
              (record == kernel_.offsets().end() || (record->second.axes & (1u << i))))
            listed.push_back(i);
      bool ok = true;
      for (int a : listed)
        if (record != kernel_.offsets().end() && !(record->second.axes & (1u << a))) {
          std::string declared;
          for (int i = 0; i < kAxisCount; ++i)
            if (record->second.axes & (1u << i)) declared += kAxisLetters[i];
          report(DiagId::OriginAxis, kAxisLetters[a], *n, std::string(1, kAxisLetters[a]),
                 declared.empty() ? "none" : declared);
          ok = false;
        }
      if (!ok) break;
      bool moved = false;
      for (int a : listed) {
        if (call.fn == Fn::OriginRequalify) {
          // §2.13.1.7: the correction goes into the origins table, in its unit.
          double v = value(a);
          kernel_.offsets()[*n].values[a] += kernel_.offsets()[*n].inch && is_linear(a) ? v / 25.4 : v;
          kernel_.offsets()[*n].axes |= 1u << a;
          moved = moved || frame.base[a] == *n;
          continue;
        }
        frame.base[a] = *n;
        frame.shift[a] = call.fn == Fn::OriginTemporary ? value(a) : 0;
        moved = true;
      }
      kernel_.refresh_origins();
      if (moved) origin_event();
      break;
    }
    case Fn::OriginIncremental:
      // Cumulative: the current origin moves by the values (decision 1).
      for (int a : listed) frame.shift[a] += value(a);
      origin_event();
      break;
    case Fn::Mirror:
      if (listed.empty()) frame.mirror.fill(false);
      for (int a : listed) {
        word(kAxisLetters[a]);
        frame.mirror[a] = conv_.mirror_toggles ? !frame.mirror[a] : true;
      }
      transform_event();
      break;
    case Fn::ScaleAxes:
    case Fn::ShiftAxes: {
      // pp G36, G37: the axes named get their factor or shift, the others none.
      const bool scale = call.fn == Fn::ScaleAxes;
      AxisValues values{};
      if (scale) values.fill(1);
      for (int a : listed) {
        double v = word(kAxisLetters[a]);
        if (scale && !(v > 0)) {
          report(DiagId::OperandValue, kAxisLetters[a], fmt::format("the scale factor of {}", kAxisLetters[a]),
                 shortest(v), "greater than 0");
          return true;
        }
        values[a] = scale ? v : axis_units(a, v);
      }
      (scale ? frame.scale : frame.shift) = values;
      if (scale)
        transform_event();
      else
        origin_event();
      break;
    }
    case Fn::Rotation:
      if (auto v = operand(0)) frame.rotation = *v;
      transform_event();
      break;
    case Fn::Scale: {
      auto factor = operand(0);
      if (factor && !(*factor >= 0.0001 && *factor <= 99999.9999)) {  // as a constant (Table 2.9)
        report_slot(DiagId::OperandValue, operand_slot(0), "the scale factor", shortest(*factor),
                    "from 0.0001 to 99999.9999");
        break;
      }
      // (SCF,n,axes): n on those, 1 on the others; (SCF,n): n on every linear axis of
      // the machine (an angle is not scaled); (SCF): 1.
      frame.scale.fill(1);
      if (factor && listed.empty())
        for (char c : conv_.axes)
          if (is_linear(axis_index(c))) frame.scale[axis_index(c)] = *factor;
      for (int a : listed) {
        word(kAxisLetters[a]);
        frame.scale[a] = factor.value_or(1);
      }
      transform_event();
      break;
    }
    case Fn::PlaneSelect: {
      // Axis numbers: the front end writes them; a hand-made .ncb could write anything.
      auto u = whole(0, 0, kAxisCount - 1, "the abscissa axis"), v = whole(1, 0, kAxisCount - 1, "the ordinate axis");
      if (!u || !v || *u == *v) break;
      if (modal_.comp || modal_.gtl || modal_.cycle >= 0) {
        report_code(DiagId::PlaneState, code,
                    modal_.comp  ? "cutter radius compensation"
                    : modal_.gtl ? "a GTL profile"
                                 : "a canned cycle");
        break;
      }
      // The normal: the axis along abscissa x ordinate, of the X/U, Y/V, Z/W family.
      auto family = [](int axis) { return axis < 3 ? axis : axis >= 6 && axis < 9 ? axis - 6 : -1; };
      int fu = family(*u), fv = family(*v);
      int w = fu >= 0 && fv >= 0 && fu != fv ? 3 - fu - fv : -1;
      if (w >= 0 && (fu + 1) % 3 != fv) w = -1;  // a left-handed pair has no axis along +normal
      modal_.plane = Plane{*u, *v, w};
      plane_event();
      break;
    }
    case Fn::Tolerance: {
      if (modal_.comp || modal_.gtl) {
        report_code(DiagId::PlaneState, code, modal_.comp ? "cutter radius compensation" : "a GTL profile");
        break;
      }
      // Every value is checked before any is set: a DTL with an error changes nothing.
      bool ok = true;
      for (int a : listed) {
        double v = value(a);
        const AxisConfig& cfg = config_.axes[static_cast<size_t>(a)];
        if (v < 0 || v > cfg.drive_error) {
          report(DiagId::ToleranceValue, kAxisLetters[a], four_decimals(program_axis(a, v)),
                 std::string(1, kAxisLetters[a]),
                 v < 0 ? std::string("must not be negative")
                       : fmt::format("exceeds the drive error {} the machine allows",
                                     four_decimals(program_axis(a, cfg.drive_error))));
          ok = false;
        }
      }
      if (!ok) break;
      Event e{EventKind::Tolerance};
      for (int a : listed) {
        double v = value(a);
        const AxisConfig& cfg = config_.axes[static_cast<size_t>(a)];
        tolerance_[a] = v;
        e.n |= 1 << a;
        e.pos[a] = program_axis(a, v == 0 ? cfg.tolerance : v);
      }
      emit(e);
      break;
    }
    case Fn::Limits: {
      // From the current origin, lower and upper in either order; a limit beyond the
      // machine's travel is the machine's (§2.13.5.3).
      Event e{EventKind::Limits};
      for (int a : listed) {
        double x = value(a) + kernel_.origin(a);
        double y = axis_units(a, slot_value(second_slot(kAxisLetters[a]))) + kernel_.origin(a);
        const AxisConfig& cfg = config_.axes[static_cast<size_t>(a)];
        kernel_.envelope().limits[0][a] = std::max(std::min(x, y), cfg.lower);
        kernel_.envelope().limits[1][a] = std::min(std::max(x, y), cfg.upper);
        kernel_.envelope().limited[a] = true;
        e.n |= 1 << a;
        e.pos[a] = program_axis(a, kernel_.envelope().limits[0][a] - kernel_.origin(a));
        e.control[a] = program_axis(a, kernel_.envelope().limits[1][a] - kernel_.origin(a));
      }
      emit(e);
      break;
    }
    case Fn::ZoneDefine: {
      auto n = whole(0, 1, 3, "the zone");
      if (!n || listed.size() != 2) break;
      Envelope::Zone& z = kernel_.envelope().zones[static_cast<size_t>(*n - 1)];
      z.defined = true;
      Event e{EventKind::Zone};
      e.rotation = *n;
      e.n = 2;
      e.plane = Plane{listed[0], listed[1], -1};
      for (int k = 0; k < 2; ++k) {
        int a = listed[k];
        double x = value(a) + kernel_.origin(a);
        double y = axis_units(a, slot_value(second_slot(kAxisLetters[a]))) + kernel_.origin(a);
        z.axis[k] = a;
        z.lo[k] = std::min(x, y);
        z.hi[k] = std::max(x, y);
        e.pos[a] = program_axis(a, z.lo[k] - kernel_.origin(a));
        e.control[a] = program_axis(a, z.hi[k] - kernel_.origin(a));
      }
      emit(e);
      break;
    }
    case Fn::ZoneOn:
    case Fn::ZoneOff: {
      auto n = whole(0, 1, 3, "the zone");
      if (!n) break;
      Envelope::Zone& z = kernel_.envelope().zones[static_cast<size_t>(*n - 1)];
      if (call.fn == Fn::ZoneOn && !z.defined) {
        report_slot(DiagId::ZoneUndefined, operand_slot(0), *n);
        break;
      }
      z.active = call.fn == Fn::ZoneOn;
      Event e{EventKind::Zone};
      e.rotation = *n;
      e.n = z.active;
      emit(e);
      break;
    }
    case Fn::Configuration: {
      // (CTL,T): the turning configuration the machine has; (CTL): milling.
      bool turning = operand(0).has_value();
      if (turning && !config_.turning_plane) {
        report_code(DiagId::ConfigurationMissing);
        break;
      }
      turning_ = turning;
      Event e{EventKind::Configuration};
      e.n = turning;
      emit(e);
      Plane plane = turning ? *config_.turning_plane : kPlanes[0];
      if (plane != modal_.plane) {
        modal_.plane = plane;
        plane_event();
      }
      break;
    }
    // §2.13.7: the graphic display, events a picture of the run can draw.
    case Fn::GraphicField: {
      auto mode = whole(0, 1, 3, "the display mode");
      // Two axes with their limits (pairs), and the third one, marked, alone.
      std::vector<int> pairs;
      std::optional<int> third;
      for (int a : listed) {
        if (has_slot(second_slot(kAxisLetters[a])))
          pairs.push_back(a);
        else
          third = a;
      }
      if (!mode || pairs.size() != 2) break;
      if (modal_.comp != 0) {
        report_code(DiagId::GraphicDisplay, "UCG comes before tool radius compensation is switched on");
        break;
      }
      std::string field = fmt::format("field mode {}", *mode);
      for (int a : pairs)
        field += fmt::format(" {}{}..{}", kAxisLetters[a], four_decimals(program_axis(a, value(a))),
                             four_decimals(program_axis(a, axis_units(a, slot_value(second_slot(kAxisLetters[a]))))));
      if (third) field += fmt::format(" marks {}", kAxisLetters[*third]);
      graphic_cleared_ = false;
      text_event(EventKind::Graphic, field, block_.request->source);
      break;
    }
    case Fn::GraphicClear:
      graphic_cleared_ = true;
      text_event(EventKind::Graphic, "clear", block_.request->source);
      break;
    case Fn::GraphicOff:
      if (!graphic_cleared_)
        report_code(DiagId::GraphicOrder, "DCG comes after CLG: the display is cleared before it is switched off");
      graphic_cleared_ = false;
      text_event(EventKind::Graphic, "off", block_.request->source);
      break;
    case Fn::DwellSeconds:
      if (auto t = operand(0)) {
        if (*t < 0 || *t > 32)
          report_slot(DiagId::DwellTime, operand_slot(0), shortest(*t), "must lie between 0 and 32 s");
        else
          dwell_seconds(*t);
      }
      break;
    case Fn::SplineBegin: {
      auto u = whole(0, 0, kAxisCount - 1, "the abscissa axis"), v = whole(1, 0, kAxisCount - 1, "the ordinate axis");
      auto ends = whole(2, 0, 3, "the end conditions");
      if (!u || !v || !ends) break;
      if (spline_.active) {
        report_code(DiagId::SplineStructure, "a spline is already open: end it with (ESP)");
        break;
      }
      if (*u != modal_.plane.u || *v != modal_.plane.v) {
        report_code(DiagId::SplineStructure, fmt::format("the spline's axes {}{} must be those of the plane {}",
                                                         kAxisLetters[*u], kAxisLetters[*v], plane_name(modal_.plane)));
        break;
      }
      spline_ = Spline{};
      spline_.active = true;
      spline_.u = *u;
      spline_.v = *v;
      spline_.ends = *ends;
      break;
    }
    case Fn::SplineEnd:
      if (!spline_.active)
        report_code(DiagId::SplineStructure, "(ESP) without (BSP)");
      else if (spline_.lead_in && !spline_.points.empty())
        report_code(DiagId::SplineStructure,
                    "the spline has no lead-out: a G00 or G01 block with G40 comes before (ESP)");
      spline_ = Spline{};
      break;
    default: return false;
  }
  return true;
}

// ---- Working limits and protected zones (NC-110 §2.13.5.3, §2.13.5.5) --------------

bool Machine::path_allowed(const std::vector<AxisValues>& path) {
  if (!virtual_path(path)) return false;
  // What target() has not refused (a cycle's levels, an arc's centre) is refused here.
  for (const AxisValues& p : path)
    for (int a = 0; a < kAxisCount; ++a)
      if (!position_in_range(a, p[a])) return false;
  if (!kernel_.envelope().any_limit() && !kernel_.envelope().any_zone()) return true;
  if (const std::optional<Envelope::Breach> breach = kernel_.envelope().limit_left(path)) {
    const int a = breach->axis;
    report(DiagId::LimitExceeded, 0, std::string(1, kAxisLetters[a]),
           four_decimals(program_axis(a, kernel_.envelope().limits[0][a] - kernel_.origin(a))),
           four_decimals(program_axis(a, kernel_.envelope().limits[1][a] - kernel_.origin(a))),
           four_decimals(program_axis(a, breach->farthest - kernel_.origin(a))));
    return false;
  }
  if (const std::optional<size_t> z = kernel_.envelope().zone_entered(path)) {
    const Envelope::Zone& zone = kernel_.envelope().zones[*z];
    std::string box;
    for (int k = 0; k < 2; ++k) {
      int a = zone.axis[k];
      box += fmt::format("{}{}{}..{}", k ? " " : "", kAxisLetters[a],
                         four_decimals(program_axis(a, zone.lo[k] - kernel_.origin(a))),
                         four_decimals(program_axis(a, zone.hi[k] - kernel_.origin(a))));
    }
    report(DiagId::ZoneEntered, 0, *z + 1, box);
    return false;
  }
  return true;
}

}  // namespace ncc

namespace ncc {

// ---- ISO scaling and rotation (§8.12, §8.17) -------------------------------------------

void Machine::scaling_on() {
  // E-17, E-18: not under cutter compensation, nor under rotation.
  if (modal_.comp != 0 || modal_.rotation) {
    report_code(DiagId::PlaneState, block_.code_name,
                modal_.comp != 0 ? "cutter radius compensation" : "coordinate rotation (G68)");
    return;
  }
  // The centre: the axis words (G91: from the position), the position on the others.
  const AxisValues here = to_frame(kernel_.position());
  AxisValues centre = here;
  for (char letter : conv_.axes)
    if (has(letter)) {
      const int i = axis_index(letter);
      const double v = axis_units(i, word(letter));
      centre[i] = modal_.absolute ? v : here[i] + v;
    }
  // P for every axis; I J K for X Y Z (an integer is thousandths: the front end).
  std::optional<double> all = word_if('P');
  AxisValues factor;
  factor.fill(1);
  bool any = all.has_value();
  for (char letter : conv_.axes)
    if (is_linear(axis_index(letter))) factor[axis_index(letter)] = all.value_or(1);
  for (char letter : std::string("XYZ")) {
    const char word_letter = static_cast<char>('I' + (letter - 'X'));
    if (auto f = word_if(word_letter); f && conv_.axes.find(letter) != std::string::npos) {
      factor[axis_index(letter)] = *f;
      any = true;
    }
  }
  if (!any) {
    report_code(DiagId::OperandValue, block_.code_name, "without a factor", "given by P, or by I J K per axis");
    return;
  }
  for (int i = 0; i < kAxisCount; ++i)
    if (!(std::fabs(factor[i]) >= 0.00001 && std::fabs(factor[i]) <= 99999)) {
      report_code(DiagId::OperandValue, fmt::format("the scale factor of {}", kAxisLetters[i]), shortest(factor[i]),
                  "from 0.00001 to 99999 in size (negative mirrors)");
      return;
    }
  for (int i = 0; i < kAxisCount; ++i) {
    kernel_.frame().scale[i] = std::fabs(factor[i]);
    kernel_.frame().mirror[i] = factor[i] < 0;
  }
  kernel_.frame().scale_centre = centre;
  modal_.scaling = true;
  transform_event();
}

void Machine::rotation_on() {
  if (modal_.comp != 0) {  // E-24
    report_code(DiagId::PlaneState, block_.code_name, "cutter radius compensation");
    return;
  }
  const int u = modal_.plane.u, v = modal_.plane.v;
  const AxisValues here = to_frame(kernel_.position());
  // The centre in the plane: the words (G91: from the position), else the position.
  AxisValues centre = here;
  for (int axis : {u, v})
    if (has(kAxisLetters[axis])) {
      const double value = axis_units(axis, word(kAxisLetters[axis]));
      centre[axis] = modal_.absolute ? value : here[axis] + value;
    }
  if (has('Z') && u != axis_index('Z') && v != axis_index('Z'))
    word('Z');  // §8.17 lists Z; the plane's normal has no use
  if (!has('R')) {
    report_code(DiagId::OperandValue, block_.code_name, "without R", "the angle in degrees");
    return;
  }
  // §8.17: under G91 the angle adds to the last one, which G69 does not forget
  // (decision 24).
  const double angle = modal_.absolute ? word('R') : last_rotation_ + word('R');
  // The centre is a programmed point: under scaling it is scaled as the path is.
  Frame& frame = kernel_.frame();
  for (int i = 0; i < kAxisCount; ++i)
    centre[i] = frame.scale_centre[i] + (centre[i] - frame.scale_centre[i]) * frame.factor(i);
  frame.rotation = angle;
  frame.rotation_centre = centre;
  last_rotation_ = angle;
  modal_.rotation = true;
  transform_event();
}

// Offset entry n changed (G10 L10-L13, pp G93): the entries in force take it at once,
// and the trace shows it.
void Machine::comp_entry_loaded(int n) {
  const OffsetEntry& e = tool_offsets_.at(n);
  if (n == offset_number_) offset_ = e;
  if (n == length_number_) length_offset_ = e;
  Event ev{EventKind::CompLoad};
  ev.n = n;
  ev.a = to_program(e.length);
  ev.b = to_program(e.radius);
  emit(ev);
}

}  // namespace ncc
