#include "module.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <map>

#include "opcodes.h"
#include "runtime/system_vars.h"
#include "stdlib/builtins.h"
#include "support/bytes.h"
#include "support/text.h"

namespace ncc::vm {

namespace {

constexpr std::string_view kMagic = "NCCB";
constexpr size_t kHeaderSize = 16;

constexpr uint32_t tag(const char (&s)[5]) {
  return uint32_t(uint8_t(s[0])) | uint32_t(uint8_t(s[1])) << 8 | uint32_t(uint8_t(s[2])) << 16 |
         uint32_t(uint8_t(s[3])) << 24;
}
constexpr uint32_t kMeta = tag("META"), kSema = tag("SEMA"), kNums = tag("NUMS"), kStrs = tag("STRS"),
                   kCode = tag("CODE"), kLine = tag("LINE"), kEntr = tag("ENTR"), kVars = tag("VARS"),
                   kSrcs = tag("SRCS");
constexpr std::array kSections = {kMeta, kSema, kNums, kStrs, kCode, kLine, kEntr, kVars, kSrcs};

std::string tag_name(uint32_t t) {
  std::string s;
  for (int i = 0; i < 4; ++i) {
    char c = static_cast<char>((t >> (8 * i)) & 0xFF);
    s += (c >= 0x20 && c < 0x7F) ? c : '?';
  }
  return s;
}

// --- writing ---------------------------------------------------------------

void write_semantics(ByteWriter& w, const ProgramSemantics& s) {
  w.str(s.dialect);
  const Conventions& c = s.conventions;
  w.u8(static_cast<uint8_t>(c.arc_centre));
  w.u8(static_cast<uint8_t>(c.helix_lead));
  w.u8(static_cast<uint8_t>(c.parabola_tangent));
  w.u8(static_cast<uint8_t>(c.angle_unit));
  w.u8(static_cast<uint8_t>(c.dwell_word));
  w.f64(c.dwell_seconds_per_unit);
  w.u8(static_cast<uint8_t>(c.peck_word));
  w.u8(static_cast<uint8_t>(c.cycle_level_word));
  w.u8(static_cast<uint8_t>(c.pitch_change_word));
  w.u8(c.thread_allow_j);
  w.u8(c.arc_single_quadrant);
  w.f64(c.arc_tolerance);
  w.f64(c.lead_resolution);
  w.u8(c.m06_stops_spindle);
  w.str(c.tool_offset_axes);
  w.str(c.axes);
  w.u8(c.max_call_depth);
  w.u8(c.result_space);
  w.u8(static_cast<uint8_t>(c.centre_words));
  w.u8(static_cast<uint8_t>(c.radius_word));
  w.u8(c.helix_by_end);
  w.u8(c.fanuc_cycles);
  w.str(c.cycle_repeat_words);
  w.f64(c.peck_clearance);
  w.f64(c.chip_break_retract);
  w.u8(static_cast<uint8_t>(c.boring_shift));
  w.u8(c.tool_change_iso);
  w.u8(c.tool_change_retract);
  w.f64(c.initial_feed);
  w.u8(c.fanuc_rules);
  w.u8(c.corners);
  w.u8(c.comp_path);
  w.u8(c.cycle_two_levels);
  w.u8(c.cycle_defines_only);
  w.u8(c.cycle_needs_cancel);
  w.u8(static_cast<uint8_t>(c.peck_factor_word));
  w.u8(static_cast<uint8_t>(c.peck_minimum_word));
  w.u8(static_cast<uint8_t>(c.tap_pitch_word));
  w.u8(c.corrector_in_tool_word);
  w.u8(c.mirror_toggles);
  w.u8(static_cast<uint8_t>(c.diameter_axis));
  w.str(c.link_axes);
  w.str(c.aux_words);
  w.u8(static_cast<uint8_t>(c.comp_length_word));
  w.u8(static_cast<uint8_t>(c.comp_radius_word));
  for (const auto& limits : c.feed_limits)
    for (double v : limits) w.f64(v);
  w.u32(static_cast<uint32_t>(s.codes.size()));
  for (const CodeDesc& code : s.codes) {
    w.str(code.name);
    w.u8(static_cast<uint8_t>(code.scope));
    w.u8(static_cast<uint8_t>(code.timing));
    w.u32(static_cast<uint32_t>(code.calls.size()));
    for (const FnCall& call : code.calls) {
      w.u16(static_cast<uint16_t>(call.fn));
      w.u16(call.arg);
    }
  }
  w.u32(static_cast<uint32_t>(s.cycles.size()));
  for (const CyclePattern& p : s.cycles) {
    w.str(p.name);
    w.u8(static_cast<uint8_t>(p.in));
    w.u8(p.dwell);
    w.u8(static_cast<uint8_t>(p.bottom));
    w.u8(static_cast<uint8_t>(p.out));
  }
  w.u32(static_cast<uint32_t>(s.power_on.size()));
  for (uint16_t i : s.power_on) w.u16(i);
  w.u32(static_cast<uint32_t>(s.system_names.size()));
  for (const std::string& name : s.system_names) w.str(name);
  w.u32(static_cast<uint32_t>(s.builtin_names.size()));
  for (const std::string& name : s.builtin_names) w.str(name);
  w.u32(static_cast<uint32_t>(s.numbered.size()));
  for (const NumberedCode& numbered : s.numbered) {
    w.u8(numbered.slot);
    w.u16(numbered.number);
    w.u16(numbered.code);
  }
  w.u32(static_cast<uint32_t>(s.incompatible.size()));
  for (const CodePair& p : s.incompatible) {
    w.u16(p.a);
    w.u16(p.b);
    w.str(p.function);
  }
  w.u32(static_cast<uint32_t>(s.value_rules.size()));
  for (const ValueRule& rule : s.value_rules) {
    w.str(rule.address);
    w.f64(rule.lo);
    w.f64(rule.hi);
    w.u8(rule.whole);
  }
}

void write_sources(ByteWriter& w, const SourceMap& m) {
  w.u32(static_cast<uint32_t>(m.files.size()));
  for (const std::string& f : m.files) w.str(f);
  w.u32(m.size());
  w.bytes(m.encoded());
}

void write_section(uint32_t t, ByteWriter& w, const Module& m) {
  if (t == kMeta) {
    w.str(m.dialect);
    w.str(m.profile_name);
    w.str(m.profile_text);
  } else if (t == kSema) {
    write_semantics(w, m.semantics);
  } else if (t == kNums) {
    w.u32(static_cast<uint32_t>(m.numbers.size()));
    for (double d : m.numbers) w.f64(d);
  } else if (t == kStrs) {
    w.u32(static_cast<uint32_t>(m.strings.size()));
    for (const std::string& str : m.strings) w.str(str);
  } else if (t == kCode) {
    w.bytes({reinterpret_cast<const char*>(m.code.data()), m.code.size()});
  } else if (t == kLine) {
    // Deltas: the next block starts a few bytes on and is the next source block.
    w.u32(static_cast<uint32_t>(m.lines.size()));
    LineEntry previous;
    for (const LineEntry& l : m.lines) {
      w.svar(int64_t(l.pc) - previous.pc);
      w.svar(int64_t(l.source) - previous.source);
      previous = l;
    }
  } else if (t == kEntr) {
    w.u32(static_cast<uint32_t>(m.entries.size()));
    for (const Entry& e : m.entries) {
      w.str(e.name);
      w.u8(static_cast<uint8_t>(e.kind));
      w.u32(e.pc);
      w.u8(e.processes);
    }
  } else if (t == kVars) {
    w.u32(static_cast<uint32_t>(m.spaces.size()));
    for (const VarSpace& space : m.spaces) {
      w.str(space.name);
      w.u32(space.size);
      w.u8(space.memory);
      w.u32(space.locals);
      w.u8(space.vacant);
      w.u8(static_cast<uint8_t>(space.format));
      w.f64(space.limit);
      w.u32(static_cast<uint32_t>(space.types.size()));
      for (const VarSpace::Range& r : space.types) {
        w.u32(r.first);
        w.u8(static_cast<uint8_t>(r.type));
      }
    }
  } else if (t == kSrcs) {
    write_sources(w, m.source_map);
  }
}

// --- reading ---------------------------------------------------------------

// Reads a count and checks that at least `min_size` bytes per item remain, so a
// corrupt count cannot make us allocate gigabytes.
bool count(ByteReader& r, size_t min_size, uint32_t& n) {
  n = r.u32();
  return !r.failed() && static_cast<uint64_t>(n) * min_size <= r.remaining();
}

template <typename E>
bool enum_value(ByteReader& r, E limit, E& out) {
  uint8_t v = r.u8();
  out = static_cast<E>(v);
  return v <= static_cast<uint8_t>(limit);
}

bool read_semantics(ByteReader& r, ProgramSemantics& s) {
  s.dialect = r.str();
  Conventions& c = s.conventions;
  bool ok = enum_value(r, ArcCentre::Absolute, c.arc_centre) && enum_value(r, HelixLead::PerRevolution, c.helix_lead) &&
            enum_value(r, ParabolaTangent::Incremental, c.parabola_tangent) &&
            enum_value(r, AngleUnit::Revolution, c.angle_unit);
  c.dwell_word = static_cast<char>(r.u8());
  c.dwell_seconds_per_unit = r.f64();
  c.peck_word = static_cast<char>(r.u8());
  c.cycle_level_word = static_cast<char>(r.u8());
  c.pitch_change_word = static_cast<char>(r.u8());
  c.thread_allow_j = r.u8();
  c.arc_single_quadrant = r.u8();
  c.arc_tolerance = r.f64();
  c.lead_resolution = r.f64();
  c.m06_stops_spindle = r.u8();
  c.tool_offset_axes = r.str();
  c.axes = r.str();
  c.max_call_depth = r.u8();
  c.result_space = r.u8();
  ok = ok && enum_value(r, CentreWords::Plane, c.centre_words);
  c.radius_word = static_cast<char>(r.u8());
  c.helix_by_end = r.u8();
  c.fanuc_cycles = r.u8();
  c.cycle_repeat_words = r.str();
  c.peck_clearance = r.f64();
  c.chip_break_retract = r.f64();
  c.boring_shift = static_cast<int8_t>(r.u8());
  c.tool_change_iso = r.u8();
  c.tool_change_retract = r.u8();
  c.initial_feed = r.f64();
  c.fanuc_rules = r.u8();
  c.corners = r.u8();
  c.comp_path = r.u8();
  c.cycle_two_levels = r.u8();
  c.cycle_defines_only = r.u8();
  c.cycle_needs_cancel = r.u8();
  c.peck_factor_word = static_cast<char>(r.u8());
  c.peck_minimum_word = static_cast<char>(r.u8());
  c.tap_pitch_word = static_cast<char>(r.u8());
  c.corrector_in_tool_word = r.u8();
  c.mirror_toggles = r.u8();
  c.diameter_axis = static_cast<char>(r.u8());
  c.link_axes = r.str();
  c.aux_words = r.str();
  c.comp_length_word = static_cast<char>(r.u8());
  c.comp_radius_word = static_cast<char>(r.u8());
  for (auto& limits : c.feed_limits)
    for (double& v : limits) v = r.f64();
  uint32_t n = 0;
  if (!ok || !count(r, 10, n)) return false;
  s.codes.resize(n);
  for (CodeDesc& code : s.codes) {
    code.name = r.str();
    uint32_t calls = 0;
    if (!enum_value(r, Scope::Block, code.scope) || !enum_value(r, Timing::After, code.timing) || !count(r, 4, calls))
      return false;
    code.calls.resize(calls);
    for (FnCall& call : code.calls) {
      call.fn = static_cast<Fn>(r.u16());
      call.arg = r.u16();
    }
  }
  if (!count(r, 8, n)) return false;
  s.cycles.resize(n);
  for (CyclePattern& p : s.cycles) {
    p.name = r.str();
    if (!enum_value(r, CyclePattern::In::Back, p.in)) return false;
    p.dwell = r.u8();
    if (!enum_value(r, CyclePattern::Bottom::OrientShift, p.bottom) || !enum_value(r, CyclePattern::Out::Manual, p.out))
      return false;
  }
  if (!count(r, 2, n)) return false;
  s.power_on.resize(n);
  for (uint16_t& i : s.power_on) i = r.u16();
  if (!count(r, 4, n) || n > static_cast<uint32_t>(SysVar::Count)) return false;
  s.system_names.resize(n);
  for (std::string& name : s.system_names) name = r.str();
  if (!count(r, 4, n) || n > static_cast<uint32_t>(Builtin::Count)) return false;
  s.builtin_names.resize(n);
  for (std::string& name : s.builtin_names) name = r.str();
  if (!count(r, 5, n)) return false;
  s.numbered.resize(n);
  for (NumberedCode& numbered : s.numbered) {
    numbered.slot = r.u8();
    numbered.number = r.u16();
    numbered.code = r.u16();
  }
  if (!count(r, 8, n)) return false;
  s.incompatible.resize(n);
  for (CodePair& p : s.incompatible) {
    p.a = r.u16();
    p.b = r.u16();
    p.function = r.str();
  }
  if (!count(r, 21, n) || n > 255) return false;  // Check names a rule by a byte
  s.value_rules.resize(n);
  for (ValueRule& rule : s.value_rules) {
    rule.address = r.str();
    rule.lo = r.f64();
    rule.hi = r.f64();
    rule.whole = r.u8();
  }
  return !r.failed();
}

bool read_sources(ByteReader& r, SourceMap& m) {
  uint32_t n = 0;
  if (!count(r, 4, n)) return false;
  m.files.resize(n);
  for (std::string& f : m.files) f = r.str();
  if (!count(r, 7, n)) return false;
  return m.read(r, n) && !r.failed();
}

bool read_section(uint32_t t, ByteReader& r, Module& m) {
  uint32_t n = 0;
  if (t == kMeta) {
    m.dialect = r.str();
    m.profile_name = r.str();
    m.profile_text = r.str();
  } else if (t == kSema) {
    return read_semantics(r, m.semantics);
  } else if (t == kNums) {
    if (!count(r, 8, n)) return false;
    m.numbers.resize(n);
    for (double& d : m.numbers) d = r.f64();
  } else if (t == kStrs) {
    if (!count(r, 4, n)) return false;
    m.strings.resize(n);
    for (std::string& s : m.strings) s = r.str();
  } else if (t == kCode) {
    std::string_view bytes = r.bytes(r.remaining());
    m.code.assign(bytes.begin(), bytes.end());
  } else if (t == kLine) {
    if (!count(r, 2, n)) return false;
    m.lines.resize(n);
    bool ok = true;
    LineEntry previous;
    for (LineEntry& l : m.lines) {
      l.pc = r.delta32(previous.pc, ok);
      l.source = r.delta32(previous.source, ok);
      if (!ok) return false;
      previous = l;
    }
  } else if (t == kEntr) {
    if (!count(r, 10, n)) return false;
    m.entries.resize(n);
    for (Entry& e : m.entries) {
      e.name = r.str();
      if (!enum_value(r, EntryKind::Process, e.kind)) return false;
      e.pc = r.u32();
      e.processes = r.u8();
    }
  } else if (t == kVars) {
    if (!count(r, 27, n)) return false;
    m.spaces.resize(n);
    for (VarSpace& s : m.spaces) {
      s.name = r.str();
      s.size = r.u32();
      s.memory = r.u8();
      s.locals = r.u32();
      s.vacant = r.u8();
      if (!enum_value(r, MemFormat::LongReal, s.format)) return false;
      s.limit = r.f64();
      uint32_t ranges = 0;
      if (!count(r, 5, ranges)) return false;
      s.types.resize(ranges);
      for (VarSpace::Range& range : s.types) {
        range.first = r.u32();
        if (!enum_value(r, VarType::Unavailable, range.type)) return false;
      }
    }
  } else if (t == kSrcs) {
    return read_sources(r, m.source_map);
  }
  return !r.failed();
}

}  // namespace

uint32_t Module::source_of(uint32_t pc) const {
  auto it = std::upper_bound(lines.begin(), lines.end(), pc, [](uint32_t p, const LineEntry& l) { return p < l.pc; });
  return it == lines.begin() ? 0 : std::prev(it)->source;
}

namespace {

// The header with the checksum left 0, then each section as (tag, size, bytes): the
// sizes come first, so the sections are measured by writing them to nowhere.
void write_header(ByteWriter& w) {
  w.bytes(kMagic);
  w.u16(kFormatVersion);
  w.u16(0);
  w.u32(static_cast<uint32_t>(kSections.size()));
  w.u32(0);  // checksum
}
void write_body(ByteWriter& w, const Module& m) {
  for (uint32_t t : kSections) {
    ByteWriter count(nullptr);
    write_section(t, count, m);
    count.finish();
    w.u32(t);
    w.u32(static_cast<uint32_t>(count.written()));
    write_section(t, w, m);
  }
}

}  // namespace

std::string write_module(const Module& m) {
  ByteWriter w;
  write_header(w);
  write_body(w, m);
  const std::string& b = w.data();
  w.patch_u32(12, crc32({reinterpret_cast<const uint8_t*>(b.data()) + kHeaderSize, b.size() - kHeaderSize}));
  return std::move(w.data());
}

bool write_module(const Module& m, std::FILE* out) {
  ByteWriter header;
  write_header(header);
  if (std::fwrite(header.data().data(), 1, kHeaderSize, out) != kHeaderSize) return false;
  ByteWriter body(out);
  write_body(body, m);
  if (!body.finish()) return false;
  header.patch_u32(12, body.crc());
  return std::fseek(out, 12, SEEK_SET) == 0 && std::fwrite(header.data().data() + 12, 1, 4, out) == 4 &&
         std::fseek(out, 0, SEEK_END) == 0;
}

std::optional<Module> read_module(std::string_view bytes, const std::string& name, Diagnostics& diags) {
  if (bytes.substr(0, 4) != kMagic) {
    diags.report(DiagId::BytecodeUnreadable, {}, name, "it does not start with the magic \"NCCB\"");
    return std::nullopt;
  }
  if (bytes.size() < kHeaderSize) {
    diags.report(DiagId::BytecodeUnreadable, {}, name, fmt::format("it is shorter than the {}-byte header", kHeaderSize));
    return std::nullopt;
  }
  ByteReader header(bytes.substr(4, kHeaderSize - 4));
  uint16_t version = header.u16();
  uint16_t flags = header.u16();
  uint32_t section_count = header.u32();
  uint32_t stored = header.u32();
  if (version != kFormatVersion) {
    diags.report(DiagId::BytecodeVersion, {}, name, version, kFormatVersion);
    return std::nullopt;
  }
  if (flags != 0) {
    diags.report(DiagId::BytecodeInvalid, {}, name, fmt::format("its header has unknown flags {:#06x}", flags));
    return std::nullopt;
  }
  std::string_view body = bytes.substr(kHeaderSize);
  uint32_t actual = crc32({reinterpret_cast<const uint8_t*>(body.data()), body.size()});
  if (actual != stored) {
    diags.report(DiagId::BytecodeChecksum, {}, name, stored, actual);
    return std::nullopt;
  }
  Module m;
  ByteReader r(body);
  std::map<uint32_t, bool> seen;
  auto invalid = [&](const std::string& why) {
    diags.report(DiagId::BytecodeInvalid, {}, name, why);
    return std::nullopt;
  };
  for (uint32_t i = 0; i < section_count; ++i) {
    uint32_t t = r.u32();
    uint32_t size = r.u32();
    if (r.failed() || size > r.remaining()) return invalid(fmt::format("section {} is truncated", i));
    if (std::find(kSections.begin(), kSections.end(), t) == kSections.end())
      return invalid(fmt::format("unknown section '{}'", tag_name(t)));
    if (seen[t]) return invalid(fmt::format("section '{}' appears twice", tag_name(t)));
    if (i >= kSections.size() || kSections[i] != t)
      return invalid(fmt::format("section '{}' is out of order", tag_name(t)));
    seen[t] = true;
    ByteReader section(r.bytes(size));
    if (!read_section(t, section, m) || !section.at_end())
      return invalid(fmt::format("section '{}' is malformed", tag_name(t)));
  }
  if (!r.at_end()) return invalid("bytes follow the last section");
  for (uint32_t t : kSections)
    if (!seen[t]) return invalid(fmt::format("section '{}' is missing", tag_name(t)));
  if (std::string problem = verify(m); !problem.empty()) return invalid(problem);
  return m;
}

std::string verify(const Module& m) {
  const ProgramSemantics& s = m.semantics;
  auto letter_ok = [](char c) { return c == 0 || (c >= 'A' && c <= 'Z'); };
  const Conventions& c = s.conventions;
  if (!letter_ok(c.dwell_word) || !letter_ok(c.peck_word) || !letter_ok(c.cycle_level_word) ||
      !letter_ok(c.pitch_change_word) || !letter_ok(c.radius_word) || !letter_ok(c.peck_factor_word) ||
      !letter_ok(c.peck_minimum_word) || !letter_ok(c.tap_pitch_word) || !letter_ok(c.comp_length_word) ||
      !letter_ok(c.comp_radius_word) ||
      !std::all_of(c.aux_words.begin(), c.aux_words.end(), letter_ok))
    return "a convention names an address that is not a letter";
  if (c.diameter_axis && kAxisLetters.find(c.diameter_axis) == std::string_view::npos)
    return "the diameter axis is not an axis";
  for (const auto& limits : c.feed_limits)
    if (!(limits[0] >= 0 && limits[1] >= limits[0] && std::isfinite(limits[1])))
      return "a feed range is not a range of feeds";
  for (const std::string* axes : {&c.axes, &c.tool_offset_axes, &c.link_axes})
    for (size_t i = 0; i < axes->size(); ++i)
      if (kAxisLetters.find((*axes)[i]) == std::string_view::npos || axes->find((*axes)[i]) != i)
        return fmt::format("'{}' in \"{}\" is not an axis, or appears twice", printable(axes->substr(i, 1)), printable(*axes));
  if (!(c.arc_tolerance >= 0 && std::isfinite(c.arc_tolerance)) ||
      !(c.lead_resolution >= 0 && std::isfinite(c.lead_resolution)) ||
      !(c.dwell_seconds_per_unit > 0 && std::isfinite(c.dwell_seconds_per_unit)))
    return "a convention holds a number that is negative or not finite";
  // Two-level cycles take their drilling axis from the block that defines them.
  if (c.cycle_two_levels && !c.cycle_defines_only) return "two-level cycles need cycles that their own block defines";
  for (const CodeDesc& code : s.codes)
    if (code.name.empty()) return "a code has no name";
  // Names reach terminals and messages: no control characters.
  std::vector<const std::string*> names = {&m.dialect, &m.profile_name, &s.dialect};
  for (const CodeDesc& code : s.codes) names.push_back(&code.name);
  for (const std::string& name : s.system_names) names.push_back(&name);
  for (const std::string& name : s.builtin_names) names.push_back(&name);
  for (const CodePair& p : s.incompatible) names.push_back(&p.function);
  for (const CyclePattern& p : s.cycles) names.push_back(&p.name);
  for (const Entry& e : m.entries) names.push_back(&e.name);
  for (const VarSpace& v : m.spaces) names.push_back(&v.name);
  for (const std::string& f : m.source_map.files) names.push_back(&f);
  for (const std::string* name : names)
    if (printable(*name) != *name) return fmt::format("the name \"{}\" holds control characters", printable(*name));
  for (double v : m.numbers)
    if (!std::isfinite(v)) return "a number constant is not finite";
  for (const CodeDesc& code : s.codes)
    for (const FnCall& call : code.calls) {
      if (call.fn >= Fn::Count) return fmt::format("code {} calls unknown function {}", code.name, int(call.fn));
      if (call.fn == Fn::Cycle && call.arg >= s.cycles.size())
        return fmt::format("code {} names cycle {} of {}", code.name, call.arg, s.cycles.size());
      if (call.fn == Fn::WorkOffset && call.arg > 99) return fmt::format("code {} names offset {}", code.name, call.arg);
    }
  for (uint16_t i : s.power_on)
    if (i >= s.codes.size()) return fmt::format("power-on state names code {} of {}", i, s.codes.size());
  for (const NumberedCode& n : s.numbered)
    if (n.code >= s.codes.size() || n.slot >= kWordSlots) return "a numbered code names a code that does not exist";
  for (const CodePair& p : s.incompatible)
    if (p.a >= s.codes.size() || p.b >= s.codes.size()) return "the compatibility matrix names a code that does not exist";
  for (const ValueRule& rule : s.value_rules)
    if (!(rule.lo <= rule.hi) || !std::isfinite(rule.lo) || !std::isfinite(rule.hi)) return "a value rule has no values";
  uint64_t variables = 0;
  for (const VarSpace& space : m.spaces) {
    variables += space.size;
    if (!(space.limit >= 0 && std::isfinite(space.limit))) return fmt::format("space {} has a bad limit", space.name);
    if (space.locals && space.memory) return fmt::format("memory {} cannot be local to a call", space.name);
    if (space.locals > space.size) return fmt::format("space {} has more local variables than variables", space.name);
    if (space.vacant && (space.memory || space.size == 0)) return fmt::format("space {} cannot start vacant", space.name);
  }
  if (variables > kMaxVariables) return fmt::format("the variable spaces hold more than {} values", kMaxVariables);
  if (c.result_space != kNoSpace && (c.result_space >= m.spaces.size() || m.spaces[c.result_space].memory))
    return "the space for measured values is not a space of numbered variables";

  // Source map.
  const SourceMap& map = m.source_map;
  std::string source_problem;
  map.visit([&](const SourceBlock& b, const std::vector<WordPosition>& words) {
    if (b.file >= map.files.size()) source_problem = "a source block names a file that is not listed";
    for (const WordPosition& w : words)
      if (w.slot >= kWordSlots || w.code < -1 || w.code >= static_cast<int>(s.codes.size()))
        source_problem = "the source map names a word that does not exist";
  });
  if (!source_problem.empty()) return source_problem;

  // Instructions: every opcode known, every operand in range.
  const std::vector<uint8_t>& code = m.code;
  std::vector<bool> boundary(code.size() + 1, false);
  std::vector<std::pair<uint32_t, uint32_t>> jumps;  // (pc, target)
  std::vector<uint32_t> range_ends;                   // second targets of CallRange
  for (size_t pc = 0; pc < code.size();) {
    boundary[pc] = true;
    if (code[pc] >= static_cast<uint8_t>(Op::Count)) return fmt::format("unknown opcode {} at {}", code[pc], pc);
    Op op = static_cast<Op>(code[pc]);
    const OpInfo& info = op_info(op);
    size_t size = static_cast<size_t>(instruction_size(op));
    if (pc + size > code.size()) return fmt::format("{} at {} is cut off by the end of the code", info.name, pc);
    size_t at = pc + 1;
    uint8_t space = 0;
    // Numbered variables go through Load/Store, memories through the others.
    const bool wants_memory =
        op != Op::Load && op != Op::LoadX && op != Op::Store && op != Op::StoreX && op != Op::Arg && op != Op::AssetBind;
    for (size_t i = 0; i < info.format.size(); ++i) {
      const char f = info.format[i];
      uint32_t v = read_operand(&code[at], operand_size(f));
      at += static_cast<size_t>(operand_size(f));
      bool ok = true;
      switch (f) {
        case 'k': ok = v < m.numbers.size(); break;
        case 's': ok = v < m.strings.size(); break;
        case 'c': ok = v < s.codes.size(); break;
        case 'w': ok = v < kWordSlots; break;
        case 'e': ok = v < m.entries.size() && (m.entries[v].kind == EntryKind::Process) == (op == Op::ProcStart); break;
        case 'v':
          ok = v < m.spaces.size() && m.spaces[v].memory == wants_memory;
          space = static_cast<uint8_t>(v);
          break;
        case 'i': ok = v < m.spaces[space].size; break;
        case 'b':
          ok = v < static_cast<uint32_t>(Builtin::Count) &&
               builtin_info(static_cast<Builtin>(v)).arity == (op == Op::Call1 ? 1 : 2);
          break;
        case 'f': ok = v < static_cast<uint32_t>(MemFormat::Count); break;
        case 't': ok = v < static_cast<uint32_t>(VarType::Count); break;
        case 'n': ok = v > 0; break;
        case 'd': ok = true; break;
        case 'r': ok = v < m.semantics.value_rules.size(); break;
        case 'p': ok = v <= kMaxDecimalPlaces; break;
        case 'm': ok = true; break;
        case 'y': ok = SysRef::unpack(static_cast<uint16_t>(v)).valid(); break;
        case 'j':
          if (op == Op::CallRange && i == 1) range_ends.push_back(v);
          else jumps.emplace_back(static_cast<uint32_t>(pc), v);
          break;
      }
      if (!ok) return fmt::format("{} at {} has an operand out of range ({})", info.name, pc, v);
    }
    pc += size;
  }
  // Every loop and every call passes a Step, so --max-steps bounds every run: a
  // jump backwards, and every entry point, lands on a Step.
  auto at_boundary = [&](uint32_t pc) { return pc < code.size() && boundary[pc]; };
  auto at_step = [&](uint32_t pc) { return at_boundary(pc) && code[pc] == static_cast<uint8_t>(Op::Step); };
  for (auto [from, to] : jumps) {
    if (!at_boundary(to)) return fmt::format("a jump goes to {}, which is not an instruction", to);
    if (to <= from && !at_step(to)) return fmt::format("the jump back from {} to {} does not land on a Step", from, to);
  }
  uint8_t started = 1;  // process 1 runs the programs of the medium
  for (const Entry& e : m.entries) {
    if (!at_step(e.pc)) return fmt::format("entry point {} does not start with a Step", printable(e.name));
    if ((e.processes & started) || e.processes >> kMaxProcesses || (e.processes && e.kind != EntryKind::Process))
      return fmt::format("entry point {} starts in processes {:#x}, one of them taken or none of a process entry's", printable(e.name), e.processes);
    started |= e.processes;
  }
  for (uint32_t end : range_ends)
    if (!at_boundary(end) || code[end] != static_cast<uint8_t>(Op::RangeEnd))
      return fmt::format("a range ends at {}, which is not a RangeEnd", end);
  for (size_t i = 0; i < m.lines.size(); ++i) {
    if (!at_boundary(m.lines[i].pc)) return "the line table points between instructions";
    if (i > 0 && m.lines[i].pc <= m.lines[i - 1].pc) return "the line table is not in code order";
    if (m.lines[i].source >= map.size()) return "the line table names a block that does not exist";
  }

  // The stack: each instruction is reached with one depth, never below its pops,
  // never above kMaxStack, and no path runs off the end of the code.
  static_assert(kMaxStack < INT16_MAX);
  std::vector<int16_t> depth(code.size(), -1);
  std::vector<uint32_t> work;
  for (const Entry& e : m.entries) {
    if (depth[e.pc] > 0) return fmt::format("entry point {} is reached with values on the stack", e.name);
    depth[e.pc] = 0;
    work.push_back(e.pc);
  }
  while (!work.empty()) {
    uint32_t pc = work.back();
    work.pop_back();
    Op op = static_cast<Op>(code[pc]);
    const OpInfo& info = op_info(op);
    int d = depth[pc];
    if (d < info.pop) return fmt::format("{} at {} pops more values than the stack holds", info.name, pc);
    d = d - info.pop + info.push;
    if (d > static_cast<int>(kMaxStack)) return fmt::format("the stack grows beyond {} at {}", kMaxStack, pc);
    if ((op == Op::Return || op == Op::End || op == Op::CallRange || op == Op::RangeEnd) && d != 0)
      return fmt::format("{} at {} leaves {} values on the stack", info.name, pc, d);
    const uint32_t next = pc + static_cast<uint32_t>(instruction_size(op));
    uint32_t successors[2];
    size_t count = 0;
    switch (op) {
      case Op::Jump: successors[count++] = read_operand(&code[pc + 1], 4); break;
      case Op::JumpIf:
      case Op::JumpIfNot:
      case Op::JumpSkip:
      case Op::Repeat:
      case Op::EndRepeat:
      case Op::CallRange:
        successors[count++] = read_operand(&code[pc + 1], 4);
        successors[count++] = next;
        break;
      case Op::Return:
      case Op::End:
      case Op::NoBlock: break;
      default: successors[count++] = next;
    }
    for (size_t i = 0; i < count; ++i) {
      const uint32_t to = successors[i];
      if (to >= code.size()) return fmt::format("execution can run past the end of the code after {}", pc);
      if (depth[to] == -1) {
        depth[to] = static_cast<int16_t>(d);
        work.push_back(to);
      } else if (depth[to] != d) {
        return fmt::format("the stack depth at {} differs between paths ({} and {})", to, depth[to], d);
      }
    }
  }
  return {};
}

}  // namespace ncc::vm
