#include "flatten.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "support/numbers.h"
#include "support/text.h"

namespace ncc::translate {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kInch = 25.4;
constexpr double kSame = 1e-9;

// Functions a code may call besides the one wanted without changing what a flattened
// program relies on: it writes no cutter compensation and no canned cycle.
bool harmless(FnCall c) { return c.fn == Fn::CompOff || c.fn == Fn::CycleCancel || c.fn == Fn::DistanceAbsolute; }

// Whether the target has a code for a function at all, whatever else it calls.
bool any_fits(FnCall) { return true; }

// The index in kPlanes of an arc's plane; -1 for another pair of axes (NC-110 DPI).
int plane_index(const Plane& plane) {
  for (int p = 0; p < 3; ++p)
    if (kPlanes[p] == plane) return p;
  return -1;
}

Fn plane_fn(int plane) { return plane == 0 ? Fn::PlaneXY : plane == 1 ? Fn::PlaneZX : Fn::PlaneYZ; }
Fn feed_mode_fn(int mode) {
  return mode == 0 ? Fn::FeedInverseTime : mode == 2 ? Fn::FeedPerRevolution : Fn::FeedPerMinute;
}

}  // namespace

Flattener::Flattener(Writer& writer, const ProgramSemantics& source, const MachineConfig& target_machine,
                     std::function<void(const Refusal&)> report)
    : w_(writer), conv_(writer.conventions()), target_(target_machine), report_(std::move(report)), axes_(conv_.axes) {
  for (uint16_t i : source.power_on)
    for (const FnCall& c : source.codes[i].calls)
      if (c.fn == Fn::WorkOffset) want_.work_offset = c.arg;
  comp_path_ = source.conventions.comp_path();
  if (source.conventions.initial_feed > 0) feed_programmed_ = source.conventions.initial_feed;  // ISO iso.initial_feed
}

void Flattener::set_target_power_on(const std::vector<FnCall>& calls) {
  for (const FnCall& c : calls)
    if (fn_group(c.fn) == FnGroup::Dynamics) told_.dynamics = c.fn;
}

std::optional<Flattener::Code> Flattener::code_for(FnCall call, const std::function<bool(FnCall)>& fits) const {
  std::optional<Code> best;
  size_t best_rank = SIZE_MAX;
  const bool modal = fn_group(call.fn) != FnGroup::None;
  for (const auto* table : {&w_.tables().g_codes, &w_.tables().m_codes})
    for (const auto& [number, entry] : *table) {
      const std::vector<FnCall>& calls = entry.desc.calls;
      if (std::find(calls.begin(), calls.end(), call) == calls.end()) continue;
      if (modal && entry.desc.scope != Scope::Modal) continue;
      bool ok = true;
      for (const FnCall& c : calls)
        if (!(c == call) && !harmless(c) && !(fits && fits(c))) ok = false;
      // Fewest functions first; of equals, not one the table calls another's alias
      // (ISO M07 "Coolant on (as M08)": M08 is what a reader expects).
      const size_t rank = calls.size() * 2 + (entry.meaning.find("(as ") != std::string::npos);
      if (ok && rank < best_rank) {
        best = Code{entry.letter, number, &entry.desc};
        best_rank = rank;
      }
    }
  return best;
}

void Flattener::refuse(uint32_t source, std::string what) { report_({source, std::move(what)}); }
void Flattener::drop(uint32_t source, std::string what) { report_({source, std::move(what), Finding::Dropped}); }

bool Flattener::write_code(FnCall call, std::vector<OutWord>& words, uint32_t source, const char* what) {
  auto fits = [&](FnCall c) {
    switch (c.fn) {
      case Fn::SpindleRpm: return !want_.constant_surface;
      case Fn::SpindleConstantSurface: return want_.constant_surface;
      case Fn::FeedPerMinute: return want_.feed_mode == 1;
      case Fn::FeedPerRevolution: return want_.feed_mode == 2;
      case Fn::FeedInverseTime: return want_.feed_mode == 0;
      case Fn::CoolantOff:
      case Fn::CoolantFlood:
      case Fn::CoolantMist: return true;  // synced after
      case Fn::LengthOff: return want_.length_entry == 0;
      case Fn::LengthPlus: return conv_.corrector_in_tool_word;  // NC-110 M06 of T n.0: the corrector is synced after
      case Fn::ClampOff:
      case Fn::ClampRotaryOff: return true;  // NC-110 M11 unclamps every axis
      case Fn::DynamicsSmooth: return true;  // pp G09/G98: how blocks join, not where they go
      case Fn::HelixOn:
      case Fn::HelixOff: return true;  // pp G24: the helix mode follows (told_.helix)
      default: return false;
    }
  };
  auto code = code_for(call, fits);
  if (!code) {
    refuse(source, fmt::format("{} ({}): {} has no code for it", what, fn_name(call.fn), w_.dialect()));
    return false;
  }
  words.push_back({code->letter, code_value(code->number), Value::Code});
  applied(*code);
  return true;
}

// A code in a block of its own.
void Flattener::write_alone(uint32_t source, FnCall call, const char* what) {
  std::vector<OutWord> b;
  if (write_code(call, b, source, what)) emit_block(std::move(b));
}

void Flattener::applied(const Code& code) {
  for (const FnCall& c : code.desc->calls) {
    switch (c.fn) {
      case Fn::PlaneXY: told_.plane = 0; break;
      case Fn::PlaneZX: told_.plane = 1; break;
      case Fn::PlaneYZ: told_.plane = 2; break;
      case Fn::FeedInverseTime: told_.feed_mode = 0; break;
      case Fn::FeedPerMinute: told_.feed_mode = 1; break;
      case Fn::FeedPerRevolution: told_.feed_mode = 2; break;
      case Fn::SpindleRpm: told_.constant_surface = false; break;
      case Fn::SpindleConstantSurface: told_.constant_surface = true; break;
      case Fn::SpindleCw: told_.spindle = 1; break;
      case Fn::SpindleCcw: told_.spindle = -1; break;
      case Fn::SpindleStop:
      case Fn::SpindleOrient: told_.spindle = 0; break;
      case Fn::CoolantMist: told_.mist = true; break;
      case Fn::CoolantFlood: told_.flood = true; break;
      case Fn::Coolant3: told_.coolant3 = true; break;
      case Fn::Coolant4: told_.coolant4 = true; break;
      case Fn::CoolantOff34: told_.coolant3 = told_.coolant4 = false; break;
      case Fn::CoolantOff: told_.mist = told_.flood = false; break;
      case Fn::LengthOff: told_.length_entry = 0; break;
      case Fn::LengthPlus:
        if (conv_.corrector_in_tool_word) told_.length_entry = 0;  // the T word wrote corrector 0
        break;
      case Fn::HelixOn: told_.helix = true; break;
      case Fn::ClampOn: told_.clamp = true; break;
      case Fn::ClampOff: told_.clamp = false; break;
      case Fn::ClampRotaryOn: told_.rotary_clamp = true; break;
      case Fn::ClampRotaryOff: told_.rotary_clamp = false; break;
      case Fn::DynamicsCornerSlowdown:
      case Fn::DynamicsContinuous:
      case Fn::DynamicsPointToPoint:
      case Fn::DynamicsSmooth: told_.dynamics = c.fn; break;
      case Fn::HelixOff: told_.helix = false; break;
      case Fn::WorkOffset:
        if (target_offset_ != c.arg) told_.position.reset();  // the numbers written mean other points now
        target_offset_ = c.arg;
        break;
      case Fn::MotionRapid:
      case Fn::MotionLinear:
      case Fn::MotionArcCw:
      case Fn::MotionArcCcw: told_.motion = static_cast<int>(c.fn); break;
      case Fn::ToolChange:
        // ISO M06 (and machines like it) stops the spindle and the coolant, and ends
        // the length offset: the state is then written again.
        if (conv_.tool_change_iso || conv_.m06_stops_spindle) told_.spindle = 0;
        if (conv_.tool_change_iso) {
          told_.mist = told_.flood = false;
          told_.length_entry = 0;
        }
        break;
      default: break;
    }
  }
}

double Flattener::mm(double v, int axis) const {
  return inch_ && target_.axes[static_cast<size_t>(axis)].kind == AxisKind::Linear ? v * kInch : v;
}

double Flattener::written_length(double v) const {
  const double r = w_.resolution();
  return std::round(v / r) * r;
}

void Flattener::emit_block(std::vector<OutWord> words, std::string_view comment) {
  if (words.empty() && comment.empty()) return;
  if (!started_) start();
  for (const OutWord& w : words) {
    if (auto why = w_.unwritable(w)) return refuse(source_, "a value beyond the target's range: " + *why);
    if (w.kind != Value::Count && w_.rounded_rate(w))
      report_({source_, std::string(1, w.letter), Finding::RoundedRate});
  }
  w_.block(words, comment);
}

// Codes alone in blocks, those the target forbids together (NC-110 Table 2.4) apart.
void Flattener::emit_codes(const std::vector<OutWord>& words) {
  std::vector<std::vector<OutWord>> blocks;
  for (const OutWord& w : words) {
    auto fits = [&](const std::vector<OutWord>& b) {
      return std::none_of(b.begin(), b.end(), [&](const OutWord& o) {
        return o.letter == 'G' && w.letter == 'G' &&
               stdlib::has_pair(w_.tables().incompatible, static_cast<int>(o.value), static_cast<int>(w.value));
      });
    };
    auto it = std::find_if(blocks.begin(), blocks.end(), fits);
    if (it == blocks.end())
      blocks.push_back({w});
    else
      it->push_back(w);
  }
  for (auto& b : blocks) emit_block(std::move(b));
}

// The program's first blocks: the modes a flattened program relies on, where the
// target has codes for them. NC-110 powers on in G27, where M, S or T after a feed
// move is an error: point to point lets each block stand alone (the source's path
// modes follow).
void Flattener::start() {
  started_ = true;
  std::vector<OutWord> b;
  for (Fn fn : {Fn::UnitsMm, Fn::DistanceAbsolute, Fn::CompOff, Fn::CycleCancel, Fn::DynamicsPointToPoint})
    if (code_for({fn})) (void)write_code({fn}, b, source_, "the start");  // code_for found it
  emit_codes(b);
}

// The spindle and the coolants as the source has them: before a move, and before a
// tool change (a change while the spindle turns is not the same change).
void Flattener::sync_spindle(uint32_t source) {
  if (!told_.spindle || *told_.spindle != want_.spindle)
    write_alone(source,
                {want_.spindle == 1    ? Fn::SpindleCw
                 : want_.spindle == -1 ? Fn::SpindleCcw
                                       : Fn::SpindleStop},
                "the spindle");
  const bool extra = (told_.mist.value_or(true) && !want_.mist) || (told_.flood.value_or(true) && !want_.flood);
  if (extra) write_alone(source, {Fn::CoolantOff}, "coolant off");
  if (want_.mist && !told_.mist.value_or(false)) write_alone(source, {Fn::CoolantMist}, "mist coolant");
  if (want_.flood && !told_.flood.value_or(false)) write_alone(source, {Fn::CoolantFlood}, "flood coolant");
  if (want_.coolant3 != told_.coolant3.value_or(false) || want_.coolant4 != told_.coolant4.value_or(false)) {
    if (told_.coolant3.value_or(false) || told_.coolant4.value_or(false))
      write_alone(source, {Fn::CoolantOff34}, "coolants 3 and 4 off");
    if (want_.coolant3) write_alone(source, {Fn::Coolant3}, "coolant 3");
    if (want_.coolant4) write_alone(source, {Fn::Coolant4}, "coolant 4");
  }
}

// The state the next move needs, in blocks of their own before it: an M code acts
// before or after the motion of its block, and some call several functions.
void Flattener::sync_state(uint32_t source) {
  if (!started_) start();  // first: it sets modes this compares with
  // The work offset: the source's where the target has it, else the target's first
  // (or none); its values are taken off the positions all the same.
  if (want_.work_offset != target_offset_) {
    if (code_for({Fn::WorkOffset, static_cast<uint16_t>(want_.work_offset)}) &&
        (want_.work_offset == 0 || target_.work_offsets.count(want_.work_offset))) {
      write_alone(source, {Fn::WorkOffset, static_cast<uint16_t>(want_.work_offset)}, "work offset");
    } else if (target_offset_ < 0) {
      for (const auto& [n, entry] : w_.tables().g_codes)
        if (target_offset_ < 0 && entry.desc.scope == Scope::Modal && entry.desc.calls.size() == 1 &&
            entry.desc.calls[0].fn == Fn::WorkOffset && target_.work_offsets.count(entry.desc.calls[0].arg))
          write_alone(source, entry.desc.calls[0], "work offset");
      if (target_offset_ < 0) target_offset_ = 0;
    }
  }
  if (want_.dynamics && told_.dynamics != want_.dynamics && dropped_dynamics_ != want_.dynamics) {
    // A mode the target cannot say leaves it in the one it was told (and a later
    // return to that one needs no code).
    if (code_for({*want_.dynamics}, any_fits)) {
      write_alone(source, {*want_.dynamics}, "the path mode");
      told_.dynamics = want_.dynamics;
    } else {
      drop(source, fmt::format("the path mode {}", fn_name(*want_.dynamics)));
      dropped_dynamics_ = want_.dynamics;
    }
  }
  if (want_.tool >= 0 && told_.tool != want_.tool) {  // a tool selected ahead of its change
    emit_block({{'T', static_cast<double>(want_.tool), Value::Count}});
    told_.tool = want_.tool;
  }
  // A target without codes for feed per minute or spindle rpm knows no other mode.
  if (!told_.feed_mode || *told_.feed_mode != want_.feed_mode) {
    if (want_.feed_mode == 1 && !code_for({Fn::FeedPerMinute}, any_fits))
      told_.feed_mode = 1;
    else
      write_alone(source, {feed_mode_fn(want_.feed_mode)}, "the feed mode");
  }
  if (!told_.constant_surface || *told_.constant_surface != want_.constant_surface) {
    if (!want_.constant_surface && !code_for({Fn::SpindleRpm}, any_fits))
      told_.constant_surface = false;
    else
      write_alone(source, {want_.constant_surface ? Fn::SpindleConstantSurface : Fn::SpindleRpm},
                  "the spindle speed mode");
  }
  if (want_.speed >= 0 && (!told_.speed || *told_.speed != want_.speed)) {
    emit_block({{'S', want_.speed, Value::Speed}});
    told_.speed = want_.speed;
  }
  sync_spindle(source);
  if (!told_.length_entry || *told_.length_entry != want_.length_entry) {
    std::vector<OutWord> b;
    const bool on_or_was = want_.length_entry != 0 || (told_.length_entry && *told_.length_entry != 0);
    if (conv_.corrector_in_tool_word && on_or_was) {
      corrector(source);
    } else if (!conv_.link_axes.empty() && on_or_was) {
      link(source);
    } else if (want_.length_entry == 0) {
      if (code_for({Fn::LengthOff}))
        (void)write_code({Fn::LengthOff}, b, source, "tool length offset off");  // code_for found it
      else
        told_.length_entry = 0;  // the target has none: never on
    } else if (write_code({want_.length_minus ? Fn::LengthMinus : Fn::LengthPlus}, b, source, "tool length offset")) {
      b.push_back({'H', static_cast<double>(want_.length_entry), Value::Count});
      told_.length_entry = want_.length_entry;
    }
    emit_block(std::move(b));
  }
}

// NC-110 applies a corrector at its M06 only (§2.7.7): the M06 of the tool in the
// spindle with the entry as its corrector (`T2.3 M06`; `T2 M06` ends it), which
// changes no tool.
void Flattener::corrector(uint32_t source) {
  const auto m06 = code_for({Fn::ToolChange}, [](FnCall c) { return c.fn == Fn::LengthPlus; });
  if (!m06 || loaded_ < 1) {
    refuse(source,
           fmt::format("a tool length offset (entry {}): {} applies one at its M06 with the corrector in the T word, "
                       "and no tool is in the spindle",
                       want_.length_entry, w_.dialect()));
    told_.length_entry = want_.length_entry;
    return;
  }
  OutWord t{'T', static_cast<double>(loaded_), Value::Count};
  if (want_.length_entry) t.offset = want_.length_entry;  // T2 M06: corrector 0
  emit_block({t, {m06->letter, code_value(m06->number), Value::Code}});
  told_.length_entry = want_.length_entry;
  told_.tool = loaded_;
  // The tool selected since, for the next change, selected again.
  if (want_.tool >= 0 && want_.tool != loaded_) emit_block({{'T', static_cast<double>(want_.tool), Value::Count}});
}

// pp has no G43: its length link '&' adds (1) or takes away (2) entry D's length on
// each of its axes, as the source's offset moves them (P-9.6): `D1 &10`, `&0` for none.
void Flattener::link(uint32_t source) {
  const auto entry = target_.offsets.find(want_.length_entry);
  const double length = entry != target_.offsets.end() ? entry->second.length : 0;
  std::string digits;
  for (char axis : conv_.link_axes) {
    const int i = axis_index(axis);
    const double v = i >= 0 ? want_.length_axes[static_cast<size_t>(i)] : 0;
    if (v != 0 && (i < 0 || length == 0 || std::fabs(std::fabs(mm(v, i)) - std::fabs(length)) > kSame)) {
      refuse(source, fmt::format("a tool length offset (entry {}) of another length than the target machine's entry {}",
                                 want_.length_entry, want_.length_entry));
      told_.length_entry = want_.length_entry;
      return;
    }
    digits += v == 0 ? '0' : (v > 0) == (length > 0) ? '1' : '2';
  }
  const size_t first = digits.find_first_not_of('0');
  const OutWord amp{'&', first == std::string::npos ? 0.0 : std::stod(digits.substr(first)), Value::Count};
  if (want_.length_entry == 0 || first == std::string::npos)
    emit_block({amp});
  else
    emit_block({{'D', static_cast<double>(want_.length_entry), Value::Count}, amp});
  told_.length_entry = want_.length_entry;
}

// F after the axis words, when the feed the move needs is not the one in force.
void Flattener::feed_word(std::vector<OutWord>& words) {
  // F is read in the units in force at the move (a unit code after F changes it).
  if (feed_programmed_) want_.feed = inch_ && want_.feed_mode != 0 ? *feed_programmed_ * kInch : *feed_programmed_;
  if (want_.feed < 0 || (told_.feed && *told_.feed == want_.feed)) return;
  words.push_back({'F', want_.feed, Value::Feed});
  told_.feed = want_.feed;
}

double Flattener::offset_mm(int axis) const {
  const auto it = target_.work_offsets.find(target_offset_);
  if (it == target_.work_offsets.end()) return 0;
  const double v = it->second.values[axis];
  return it->second.inch && target_.axes[static_cast<size_t>(axis)].kind == AxisKind::Linear ? v * kInch : v;
}

// A point of the trace (machine coordinates, source units) in the target's frame:
// mm, less the work offset the target has selected.
AxisValues Flattener::target_point(const AxisValues& pos) const {
  AxisValues p{};
  for (int i = 0; i < kAxisCount; ++i) p[i] = mm(pos[i], i) - offset_mm(i);
  return p;
}

void Flattener::move(const Event& e) {
  if (e.kind == EventKind::Arc) {
    const int plane = plane_index(e.plane);
    if (plane < 0) return refuse(e.source, "an arc in the " + plane_name(e.plane) + " plane");
    want_.plane = plane;
  }
  sync_state(e.source);
  if (!told_.position)  // where the target machine starts, in the frame now selected
    for (int i = 0; i < kAxisCount; ++i) start_[i] = target_.initial_position[i] - offset_mm(i);
  const AxisValues end = target_point(e.pos);
  if (e.kind == EventKind::Arc) return arc_to(e, end);
  std::vector<OutWord> words;
  const Fn motion = e.kind == EventKind::Rapid ? Fn::MotionRapid : Fn::MotionLinear;
  std::vector<OutWord> axes;
  for (int i = 0; i < kAxisCount; ++i) {
    const double v = written_length(end[i]);
    if (told_.position && std::fabs((*told_.position)[i] - v) < kSame) continue;
    if (!told_.position && v == 0 && axes_.find(kAxisLetters[i]) == std::string::npos) continue;
    if (axes_.find(kAxisLetters[i]) == std::string::npos)
      return refuse(e.source, fmt::format("a move of axis {}: the target machine has axes {}", kAxisLetters[i], axes_));
    axes.push_back({kAxisLetters[i], v, Value::Length});
  }
  // The first move names the axes beyond X Y Z only when they leave where the
  // machine starts (NC-110 takes 8 axis words a block).
  if (!told_.position)
    std::erase_if(axes, [&](const OutWord& a) {
      const int i = axis_index(a.letter);
      return i >= 3 && std::fabs(a.value - written_length(start_[i])) < kSame;
    });
  if (axes.empty()) return;  // no motion: nothing to write
  if (!told_.motion || *told_.motion != static_cast<int>(motion)) {
    std::vector<OutWord> code;
    if (!write_code({motion}, code, e.source, e.kind == EventKind::Rapid ? "rapid motion" : "linear motion")) return;
    words.insert(words.begin(), code.begin(), code.end());
  }
  words.insert(words.begin(), block_codes_.begin(), block_codes_.end());
  block_codes_.clear();
  words.insert(words.end(), axes.begin(), axes.end());
  if (e.kind != EventKind::Rapid) feed_word(words);
  AxisValues at = told_.position.value_or(start_);
  for (const OutWord& a : axes) at[axis_index(a.letter)] = a.value;
  told_.position = at;
  emit_block(std::move(words));
}

// An arc from the position written to `end` (target frame, mm), in pieces of a
// quadrant at most where the target wants them so.
void Flattener::arc_to(const Event& e, const AxisValues& end) {
  const int u = e.plane.u, v = e.plane.v, w = e.plane.w;
  const bool clockwise = e.rotation < 0;
  const AxisValues start = told_.position.value_or(start_);
  // The centre in the target's frame: moved as the end point was.
  const double cu = mm(e.centre[0], u) - (mm(e.pos[u], u) - end[u]),
               cv = mm(e.centre[1], v) - (mm(e.pos[v], v) - end[v]);
  const double sweep = e.b * kPi / 180;  // radians, positive
  // An end off the circle, as far as the source's tolerance let it be, may be beyond the target's.
  const double off = std::fabs(std::hypot(start[u] - cu, start[v] - cv) - std::hypot(end[u] - cu, end[v] - cv));
  if (off > conv_.arc_tolerance + w_.resolution())
    return refuse(e.source, fmt::format("an arc whose end is {} mm off its circle: {} takes {} mm", four_decimals(off),
                                        w_.dialect(), four_decimals(conv_.arc_tolerance)));
  // Along the normal as the numbers are written: a rounding residue is no helix.
  const double dw = w >= 0 ? written_length(end[w]) - written_length(start[w]) : 0;
  if (std::fabs(dw) > kSame && conv_.helix_by_end && e.b > 360 + 1e-6)
    return refuse(e.source, fmt::format("a helix of {} turns: {} writes a helix by its end point, one turn at most",
                                        four_decimals(e.b / 360), w_.dialect()));
  if (std::fabs(dw) > kSame && !told_.helix.value_or(false) &&
      code_for({Fn::HelixOn}, [](FnCall c) { return c.fn == Fn::DynamicsSmooth; })) {
    std::vector<OutWord> b;
    (void)write_code({Fn::HelixOn}, b, e.source, "helix mode");  // code_for found it
    emit_block(std::move(b));
  }
  // The pieces: one, or the arc cut at the lines through the centre parallel to u and v.
  std::vector<double> cuts;  // sweep at the end of each piece
  if (conv_.arc_single_quadrant) {
    const double a0 = std::atan2(start[v] - cv, start[u] - cu);
    double into = std::fmod(std::fmod(clockwise ? -a0 : a0, kPi / 2) + kPi / 2, kPi / 2);
    double next = kPi / 2 - into;
    if (next < 1e-9) next = kPi / 2;
    for (double s = next; s < sweep - 1e-9; s += kPi / 2) cuts.push_back(s);
  }
  cuts.push_back(sweep);
  const double radius = std::hypot(start[u] - cu, start[v] - cv);
  const double a0 = std::atan2(start[v] - cv, start[u] - cu);
  double done = 0;
  for (size_t k = 0; k < cuts.size(); ++k) {
    AxisValues to = end;
    if (k + 1 < cuts.size()) {
      const double a = a0 + (clockwise ? -cuts[k] : cuts[k]);
      to[u] = cu + radius * std::cos(a);
      to[v] = cv + radius * std::sin(a);
      if (w >= 0) to[w] = start[w] + dw * cuts[k] / sweep;
    }
    const AxisValues from = told_.position.value_or(start_);
    std::vector<OutWord> b;
    if (!told_.plane || *told_.plane != want_.plane) {
      std::vector<OutWord> pc;
      if (!write_code({plane_fn(want_.plane)}, pc, e.source, "the arc's plane")) return;
      emit_block(std::move(pc));
    }
    const Fn motion = clockwise ? Fn::MotionArcCw : Fn::MotionArcCcw;
    if (!told_.motion || *told_.motion != static_cast<int>(motion)) {
      std::vector<OutWord> code;
      if (!write_code({motion}, code, e.source, "circular motion")) return;
      b.insert(b.begin(), code.begin(), code.end());
    }
    AxisValues at = from;
    for (int i = 0; i < kAxisCount; ++i) {
      const double x = written_length(to[i]);
      if (i != u && i != v && std::fabs(from[i] - x) < kSame) continue;
      if (axes_.find(kAxisLetters[i]) == std::string::npos)
        return refuse(e.source,
                      fmt::format("a move of axis {}: the target machine has axes {}", kAxisLetters[i], axes_));
      b.push_back({kAxisLetters[i], x, Value::Length});
      at[i] = x;
    }
    const bool plane_words = conv_.centre_words == CentreWords::Plane;
    auto centre_letter = [&](int axis, char plane_word) { return plane_words || axis >= 3 ? plane_word : "IJK"[axis]; };
    const bool absolute = conv_.arc_centre == ArcCentre::Absolute;
    b.push_back({centre_letter(u, 'I'), written_length(absolute ? cu : cu - from[u]), Value::Length});
    b.push_back({centre_letter(v, 'J'), written_length(absolute ? cv : cv - from[v]), Value::Length});
    const double piece_dw = w >= 0 ? at[w] - from[w] : 0;
    const double piece_sweep = cuts[k] - done;
    if (std::fabs(piece_dw) > kSame && !conv_.helix_by_end) {
      const double per = conv_.helix_lead == HelixLead::PerRevolution ? piece_sweep / kTwoPi : piece_sweep;
      const char letter = plane_words ? 'K' : w < 3 ? "IJK"[w] : 0;
      if (!letter) return refuse(e.source, "a helix along " + std::string(1, kAxisLetters[w]));
      const double lead = piece_dw / per;
      b.push_back({letter, plane_words ? std::fabs(lead) : lead, Value::Length});
    }
    if (k == 0) {
      b.insert(b.begin(), block_codes_.begin(), block_codes_.end());
      block_codes_.clear();
    }
    feed_word(b);
    done = cuts[k];
    told_.position = at;
    emit_block(std::move(b));
  }
}

// A parabola, where the target writes one by its end and control point (LinuxCNC's
// G5.1, in the XY plane: X and Y move, and the control point's offset from the start
// is I J). Else refused: flattening writes no chords.
void Flattener::parabola(const Event& e) {
  const auto code = w_.parabola_code();
  if (!code) return refuse(e.source, "a parabola (G06): flattening writes straight lines and arcs");
  want_.plane = 0;  // G5.1 is XY's
  sync_state(e.source);
  if (!told_.position)
    for (int i = 0; i < kAxisCount; ++i) start_[i] = target_.initial_position[i] - offset_mm(i);
  const AxisValues from = told_.position.value_or(start_);
  const AxisValues end = target_point(e.pos);
  AxisValues control = e.pos;
  for (int i = 0; i < 3; ++i) control[i] = e.control[i];
  control = target_point(control);
  for (int i = 2; i < kAxisCount; ++i)
    if (std::fabs(written_length(end[i]) - from[i]) > kSame ||
        (i == 2 && std::fabs(written_length(control[i]) - from[i]) > kSame))
      return refuse(e.source,
                    fmt::format("a parabola out of the XY plane: {}'s G5.1 moves X and Y only", w_.dialect()));
  const double i = written_length(control[0] - from[0]), j = written_length(control[1] - from[1]);
  if (std::fabs(i) < kSame && std::fabs(j) < kSame)
    return refuse(e.source,
                  fmt::format("a parabola whose control point is its start: {}'s G5.1 takes none", w_.dialect()));
  if (!told_.plane || *told_.plane != want_.plane) {
    std::vector<OutWord> pc;
    if (!write_code({plane_fn(want_.plane)}, pc, e.source, "the parabola's plane")) return;
    emit_block(std::move(pc));
  }
  std::vector<OutWord> b = block_codes_;
  block_codes_.clear();
  b.push_back({'G', *code, Value::Code});
  AxisValues at = from;
  for (int a = 0; a < 2; ++a) {
    at[a] = written_length(end[a]);
    b.push_back({kAxisLetters[a], at[a], Value::Length});
  }
  b.push_back({'I', i, Value::Length});
  b.push_back({'J', j, Value::Length});
  feed_word(b);
  told_.motion = static_cast<int>(Fn::MotionParabola);  // G5.1 is modal: the next move writes its code
  told_.position = at;
  emit_block(std::move(b));
}

void Flattener::event(const Event& e) {
  source_ = e.source;
  if (ended_ && e.kind != EventKind::Block) {
    if (!after_end_) refuse(e.source, "a second program after the end of the first: translate each program on its own");
    after_end_ = true;
    return;
  }
  switch (e.kind) {
    case EventKind::Units: inch_ = e.n == 1; break;
    case EventKind::Plane: {
      const int plane = plane_index(e.plane);
      if (plane >= 0) want_.plane = plane;  // an arc in another plane is refused when it comes
      break;
    }
    case EventKind::FeedMode: want_.feed_mode = e.n; break;
    case EventKind::FeedRate: feed_programmed_ = e.a; break;
    case EventKind::SpindleMode: want_.constant_surface = e.n == 1; break;
    case EventKind::SpindleSpeed: want_.speed = inch_ && want_.constant_surface ? e.a * 0.3048 : e.a; break;
    case EventKind::SpindleOn: want_.spindle = e.n; break;
    case EventKind::SpindleStop: want_.spindle = 0; break;
    case EventKind::Rapid:
    case EventKind::Linear:
    case EventKind::Arc: move(e); break;
    case EventKind::Dwell: {
      std::vector<OutWord> words;
      sync_state(e.source);
      if (!conv_.dwell_word) return refuse(e.source, fmt::format("a dwell: {} gives a dwell no word", w_.dialect()));
      if (!write_code({Fn::Dwell}, words, e.source, "dwell")) return;
      words.push_back({conv_.dwell_word, e.a / conv_.dwell_seconds_per_unit, Value::Seconds});
      emit_block(std::move(words));
      break;
    }
    case EventKind::SelectTool: want_.tool = e.n; break;  // written with the change, or before the next move
    case EventKind::ChangeTool: {
      // ISO's M06 ignores the tool in the spindle, NC-110's changes it for none: such a
      // change is not written (NC-110's corrector is, when it changes: corrector()).
      if ((conv_.tool_change_iso || conv_.corrector_in_tool_word) && loaded_ == e.n) break;
      loaded_ = e.n;
      // A target whose M06 first takes the tool axis to the reference point moves
      // where the source did not, unless the tool is there already.
      if (conv_.tool_change_retract && !conv_.tool_offset_axes.empty()) {
        const int axis = axis_index(conv_.tool_offset_axes[0]);
        const double reference = target_.reference_position[axis] - offset_mm(axis);
        const double at = told_.position ? (*told_.position)[axis] : target_.initial_position[axis] - offset_mm(axis);
        if (std::fabs(written_length(at) - written_length(reference)) > kSame)
          return refuse(e.source,
                        fmt::format("a tool change where the tool stands: {}'s M06 first takes {} to the reference "
                                    "point (a machine that changes tools in place says iso.tool_change_retract = "
                                    "false in --target-machine)",
                                    w_.dialect(), conv_.tool_offset_axes[0]));
      }
      if ((conv_.tool_change_iso || conv_.m06_stops_spindle) && (want_.spindle != 0 || want_.mist || want_.flood))
        return refuse(
            e.source,
            fmt::format("a tool change with the spindle or the coolant on: {}'s M06 stops them first", w_.dialect()));
      sync_spindle(e.source);
      std::vector<OutWord> words{{'T', static_cast<double>(e.n), Value::Count}};
      if (write_code({Fn::ToolChange}, words, e.source, "tool change")) emit_block(std::move(words));
      told_.tool = want_.tool = e.n;
      break;
    }
    case EventKind::ToolLengthOffset: {
      bool any = false;
      double sum = 0;
      for (double v : e.pos) {
        any |= v != 0;
        sum += v;
      }
      want_.length_entry = any ? e.n : 0;
      want_.length_axes = e.pos;
      want_.length_minus = sum < 0 && target_.offsets.count(e.n) && target_.offsets.at(e.n).length > 0;
      break;
    }
    case EventKind::CutterComp:
      if (e.n != 0 && !comp_path_)
        refuse(e.source,
               "cutter radius compensation: the source's run shows the programmed contour, not the tool centre's path");
      break;
    case EventKind::WorkOffset: want_.work_offset = e.n; break;
    // In the positions already (machine coordinates).
    case EventKind::PositionOffset:
    case EventKind::Origin:
    case EventKind::Transform:
    case EventKind::OffsetLoad:
    case EventKind::Block: break;
    case EventKind::Coolant:
      switch (e.n) {
        case 0: want_.mist = want_.flood = false; break;
        case 1: want_.mist = true; break;
        case 2: want_.flood = true; break;
        case 3: want_.coolant3 = true; break;
        case 4: want_.coolant4 = true; break;
        default: want_.coolant3 = want_.coolant4 = false; break;
      }
      break;
    case EventKind::Comment:
    case EventKind::Message: w_.comment(e.text); break;
    case EventKind::Stop: {
      if (e.n == 3) return refuse(e.source, "a manual retract (G87/G88): the operator moves the tool");
      std::vector<OutWord> words;
      if (write_code({e.n == 0 ? Fn::ProgramStop : Fn::ProgramOptionalStop}, words, e.source,
                     e.n == 0 ? "program stop" : "optional stop"))
        emit_block(std::move(words));
      break;
    }
    case EventKind::End: {
      std::vector<OutWord> words;
      // A target with no end code refuses it (reported): the translation then writes nothing.
      if (!code_for({e.n == 1 ? Fn::ProgramEndInformation : Fn::ProgramEnd}) && code_for({Fn::ProgramEndInformation}))
        (void)write_code({Fn::ProgramEndInformation}, words, e.source, "end of program");
      else
        (void)write_code({e.n == 1 ? Fn::ProgramEndInformation : Fn::ProgramEnd}, words, e.source, "end of program");
      emit_block(std::move(words));
      w_.end();
      ended_ = true;
      break;
    }
    case EventKind::PathMode: {
      static constexpr Fn kModes[] = {Fn::PathAccelerate,       Fn::PathDecelerate,         Fn::PathTapping,
                                      Fn::PathSpindleSync,      Fn::DynamicsCornerSlowdown, Fn::DynamicsContinuous,
                                      Fn::DynamicsPointToPoint, Fn::DynamicsSmooth};
      if (e.n < 0 || e.n >= 8) break;
      if (e.n >= 4) {  // a mode: written before the next move that needs it
        want_.dynamics = kModes[e.n];
        break;
      }
      // A function of one block (G09, NC-110 G35) goes with the next move.
      std::vector<OutWord> words;
      if (!code_for({kModes[e.n]}, any_fits))
        drop(e.source, fmt::format("the path mode {}", fn_name(kModes[e.n])));
      else if (write_code({kModes[e.n]}, words, e.source, "the path mode"))
        block_codes_.insert(block_codes_.end(), words.begin(), words.end());
      break;
    }
    case EventKind::SpindleOrient: {
      std::vector<OutWord> words;
      sync_state(e.source);
      if (write_code({Fn::SpindleOrient}, words, e.source, "an oriented spindle stop")) emit_block(std::move(words));
      want_.spindle = 0;
      break;
    }
    case EventKind::Clamp:
    case EventKind::Override:
    case EventKind::SpindleHold: {
      Fn fn = e.kind == EventKind::Clamp      ? (e.n == 1   ? Fn::ClampOn
                                                 : e.n == 0 ? Fn::ClampOff
                                                 : e.n == 3 ? Fn::ClampRotaryOn
                                                            : Fn::ClampRotaryOff)
              : e.kind == EventKind::Override ? (e.n ? Fn::OverrideEnable : Fn::OverrideDisable)
                                              : (e.n ? Fn::SpindleHoldOn : Fn::SpindleHoldOff);
      // The overrides and the constant spindle speed are the operator's: a target
      // without them runs the same path. A clamp is not: a move while clamped is wrong.
      // A clamp already so (NC-110 M11 unclamps both kinds: two events) is not written again.
      auto& told = fn == Fn::ClampOn || fn == Fn::ClampOff ? told_.clamp : told_.rotary_clamp;
      if (e.kind == EventKind::Clamp && told == (fn == Fn::ClampOn || fn == Fn::ClampRotaryOn)) break;
      if (e.kind != EventKind::Clamp && !code_for({fn}, any_fits)) {
        drop(e.source, fmt::format("the machine function {}", fn_name(fn)));
        break;
      }
      std::vector<OutWord> words;
      if (write_code({fn}, words, e.source, "a machine function")) emit_block(std::move(words));
      break;
    }
    case EventKind::Parabola: parabola(e); break;
    case EventKind::Thread:
      refuse(e.source, "a threading move: flattening writes no spindle-synchronised motion yet");
      break;
    case EventKind::Spline: refuse(e.source, "a spline: flattening writes straight lines and arcs"); break;
    case EventKind::Probe: refuse(e.source, "a probing move: its end depends on the part"); break;
    case EventKind::OperatorMove: refuse(e.source, "a move the operator makes"); break;
    case EventKind::Asset: refuse(e.source, "an ASSET file statement"); break;
    case EventKind::Input: refuse(e.source, "operator input (INP)"); break;
    case EventKind::Screen: refuse(e.source, "the user screen (SCR, DEF, OUT)"); break;
    case EventKind::Sync: refuse(e.source, "a process statement (EXE, REL, WAI, SND)"); break;
    case EventKind::Graphic: drop(e.source, "the graphic display of the path (UCG, CLG, DCG)"); break;
    case EventKind::Tooling:
      // A corrector changed is the target's offset table changed: it has no such statement.
      if (e.n == kToolingCorrector)
        refuse(e.source, "a change to a tool corrector (RQU, RQP)");
      else
        drop(e.source, "a tool declared unusable or the probe's settings (TOF, DPT)");
      break;
    case EventKind::Virtual: refuse(e.source, "virtual axes (UAV): the moves are the virtual axes'"); break;
    case EventKind::Aux: refuse(e.source, "auxiliary function " + e.text + " of the machine's logic"); break;
    case EventKind::CompLoad: refuse(e.source, "loading a compensation entry (G93)"); break;
    case EventKind::Tolerance: refuse(e.source, "an in-position tolerance (DTL)"); break;
    case EventKind::Limits: refuse(e.source, "working limits (DLO)"); break;
    case EventKind::Zone: refuse(e.source, "a protected zone (DSA, ASC, DSC)"); break;
    case EventKind::Configuration:
      if (e.n) refuse(e.source, "the turning configuration (CTL)");
      break;
    case EventKind::SpindleRange:
      if (e.n) refuse(e.source, "a forced spindle range (M41-M45)");
      break;
    case EventKind::PartChange: refuse(e.source, "a part change (M60)"); break;
    case EventKind::Diameter:
      if (e.n) refuse(e.source, "diameter programming (G74)");
      break;
    case EventKind::FeedReduction:
      if (e.n) refuse(e.source, "the feed reduced to F / 100 (M37)");
      break;
  }
}

void Flattener::finish() {
  if (!started_) start();  // a program without a block of its own still has its start
  if (!ended_) w_.end();
}

}  // namespace ncc::translate
