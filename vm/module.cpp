#include "module.h"

#include <unistd.h>
#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <map>
#include <type_traits>

#include "contract/asset_files.h"
#include "contract/builtins.h"
#include "contract/machine_config.h"
#include "contract/system_vars.h"
#include "opcodes.h"
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

// --- conventions (contract/conventions.def) ----------------------------------

// A convention's bytes, by its C++ type: one byte, a float64, a string.
void put(ByteWriter& w, bool v) { w.u8(v); }
void put(ByteWriter& w, char v) { w.u8(static_cast<uint8_t>(v)); }
void put(ByteWriter& w, uint8_t v) { w.u8(v); }
void put(ByteWriter& w, int8_t v) { w.u8(static_cast<uint8_t>(v)); }
void put(ByteWriter& w, double v) { w.f64(v); }
void put(ByteWriter& w, const std::string& v) { w.str(v); }
template <typename E>
requires std::is_enum_v<E>
void put(ByteWriter& w, E v) { w.u8(static_cast<uint8_t>(v)); }
void put(ByteWriter& w, const FeedRanges& v) {
  for (const auto& range : v)
    for (double x : range) w.f64(x);
}

// And back; false when the bytes cannot be one (an enum beyond its last value).
template <typename T, typename Check>
bool get(ByteReader& r, T& out, Check) {
  if constexpr (std::is_same_v<T, std::string>)
    out = r.str();
  else if constexpr (std::is_same_v<T, double>)
    out = r.f64();
  else if constexpr (std::is_same_v<T, FeedRanges>)
    for (auto& range : out)
      for (double& x : range) x = r.f64();
  else
    out = static_cast<T>(r.u8());
  return true;
}
template <typename E>
bool get(ByteReader& r, E& out, convention::Enum<E> check) {
  const uint8_t v = r.u8();
  out = static_cast<E>(v);
  return v <= static_cast<uint8_t>(check.last);
}

// What is wrong with a convention's value by its check, or "".
bool letter(char c) { return c >= 'A' && c <= 'Z'; }
std::string problem(bool, convention::Flag) { return ""; }
std::string problem(uint8_t, convention::Count) { return ""; }
std::string problem(uint8_t, convention::Space) { return ""; }  // against the module's spaces: verify()
std::string shown(char c) { return printable(std::string(1, c)); }
std::string problem(char c, convention::Letter) {
  return c == 0 || letter(c) ? "" : fmt::format("'{}' is not an address letter", shown(c));
}
std::string problem(const std::string& s, convention::Letters) {
  return std::all_of(s.begin(), s.end(), letter) ? "" : "holds what is not an address letter";
}
std::string problem(char c, convention::Axis) {
  return c == 0 || (letter(c) && kAxisLetters.find(c) != std::string_view::npos)
             ? ""
             : fmt::format("'{}' is not an axis", shown(c));
}
std::string problem(const std::string& s, convention::Axes) {
  for (size_t i = 0; i < s.size(); ++i)
    if (!letter(s[i]) || kAxisLetters.find(s[i]) == std::string_view::npos || s.find(s[i]) != i)
      return fmt::format("holds '{}', which is not an axis or appears twice", printable(s.substr(i, 1)));
  return "";
}
std::string problem(int8_t v, convention::Sign) { return v == 1 || v == -1 ? "" : "is neither 1 nor -1"; }
std::string problem(double v, convention::Length) {
  return v >= 0 && std::isfinite(v) ? "" : "is negative or not finite";
}
std::string problem(double v, convention::Positive) {
  return v > 0 && std::isfinite(v) ? "" : "is not a finite number above 0";
}
std::string problem(const FeedRanges& v, convention::FeedLimits) {
  for (const auto& range : v)
    if (!(range[0] >= 0 && range[1] >= range[0] && std::isfinite(range[1])))
      return "holds what is not a range of feeds";
  return "";
}
template <typename E>
std::string problem(E v, convention::Enum<E> check) {
  return v <= check.last ? "" : "is beyond its last value";
}

void write_conventions(ByteWriter& w, const Conventions& c) {
#define NCC_CONVENTION_WRITE(name, type, init, check, doc) put(w, c.name);
  NCC_CONVENTIONS(NCC_CONVENTION_WRITE)
#undef NCC_CONVENTION_WRITE
}

bool read_conventions(ByteReader& r, Conventions& c) {
#define NCC_CONVENTION_READ(name, type, init, check, doc) \
  if (!get(r, c.name, convention::check)) return false;
  NCC_CONVENTIONS(NCC_CONVENTION_READ)
#undef NCC_CONVENTION_READ
  return true;
}

// Out of line: inlined, its 46 checks made GCC stop inlining verify()'s per-operand
// checks, +300 instructions a block on a module of plain blocks.
[[gnu::noinline]] std::string convention_problem(const Conventions& c) {
#define NCC_CONVENTION_CHECK(name, type, init, check, doc) \
  if (std::string why = problem(c.name, convention::check); !why.empty()) return "the convention " #name ": " + why;
  NCC_CONVENTIONS(NCC_CONVENTION_CHECK)
#undef NCC_CONVENTION_CHECK
  return "";
}

// --- writing ---------------------------------------------------------------

void write_semantics(ByteWriter& w, const ProgramSemantics& s) {
  w.str(s.dialect);
  write_conventions(w, s.conventions);
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
  uint32_t n = 0;
  if (!read_conventions(r, s.conventions) || !count(r, 10, n)) return false;
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

// The section's bytes: the files, then the blocks, which the map keeps as they are.
bool read_sources(std::string bytes, SourceMap& m) {
  ByteReader r(bytes);
  uint32_t n = 0;
  if (!count(r, 4, n)) return false;
  m.files.resize(n);
  for (std::string& f : m.files) f = r.str();
  if (!count(r, 7, n)) return false;
  bytes.erase(0, r.pos());
  return m.read(std::move(bytes), n);
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
  }
  return !r.failed();
}

// The range of each operand kind of opcodes.h (NCC_OPERANDS) in a module, one
// function a kind: `fits` calls them through the table, so a kind added there does not
// build until it has its rule here.
class OperandRanges {
 public:
  OperandRanges(const Module& m, Op op) : m_(m), op_(op) {}
  // A SERVICE's operands after its number: its service's rules. An ASSET service's
  // string names a file; a service's space is numbered when an index follows it
  // (asset.bind).
  void serve(Service s) {
    served_ = true;
    names_file_ = service_info(s).device == Device::Asset;
    numbered_space_ = service_info(s).format.find("vi") != std::string_view::npos;
  }
  bool fits(Operand kind, uint32_t v) {
    switch (kind) {
#define NCC_OPERAND_FITS(kind, letter, size, doc) \
  case Operand::kind: return fits_##kind(v);
      NCC_OPERANDS(NCC_OPERAND_FITS)
#undef NCC_OPERAND_FITS
      case Operand::Count: break;
    }
    return false;
  }
  int targets = 0;  // the Target operands seen so far

 private:
#define NCC_OPERAND_RULE(kind, letter, size, doc) bool fits_##kind(uint32_t v);
  NCC_OPERANDS(NCC_OPERAND_RULE)
#undef NCC_OPERAND_RULE

  const Module& m_;
  Op op_;
  bool served_ = false, names_file_ = false, numbered_space_ = false;  // a SERVICE's
  uint32_t space_ = 0;                                                 // the Space operand before an Index
};

bool OperandRanges::fits_Number(uint32_t v) { return v < m_.numbers.size(); }
// The ASSET services name their file by a string: a name the store takes (the device
// prints it in the trace as it is).
bool OperandRanges::fits_String(uint32_t v) {
  return v < m_.strings.size() && (!names_file_ || asset::parse_file_name(m_.strings[v], 1));
}
bool OperandRanges::fits_Code(uint32_t v) { return v < m_.semantics.codes.size(); }
bool OperandRanges::fits_Slot(uint32_t v) { return v < kWordSlots; }
bool OperandRanges::fits_Target(uint32_t) {  // on an instruction: checked once every instruction is known
  ++targets;
  return true;
}
// A call names a program to call; a service (process.start) a process entry to start.
bool OperandRanges::fits_Entry(uint32_t v) {
  return v < m_.entries.size() && (m_.entries[v].kind == EntryKind::Process) == served_;
}
// Numbered variables go through Load/Store (and asset.bind), memories through the others.
bool OperandRanges::fits_Space(uint32_t v) {
  const bool numbered =
      op_ == Op::Load || op_ == Op::LoadX || op_ == Op::Store || op_ == Op::StoreX || op_ == Op::Arg || numbered_space_;
  space_ = v;
  return v < m_.spaces.size() && m_.spaces[v].memory != numbered;
}
bool OperandRanges::fits_Index(uint32_t v) { return space_ < m_.spaces.size() && v < m_.spaces[space_].size; }
bool OperandRanges::fits_Builtin(uint32_t v) {
  return v < static_cast<uint32_t>(Builtin::Count) &&
         builtin_info(static_cast<ncc::Builtin>(v)).arity == (op_ == Op::Call1 ? 1 : 2);
}
bool OperandRanges::fits_Format(uint32_t v) { return v < static_cast<uint32_t>(MemFormat::Count); }
bool OperandRanges::fits_Bytes(uint32_t v) { return v > 0; }
bool OperandRanges::fits_Relation(uint32_t v) { return v >= 1 && v <= 4; }
bool OperandRanges::fits_Type(uint32_t v) { return v < kShownTypes; }
bool OperandRanges::fits_SysVar(uint32_t v) { return SysRef::unpack(static_cast<uint16_t>(v)).valid(); }
bool OperandRanges::fits_LoopDepth(uint32_t) { return true; }  // the VM closes only the loops it has
bool OperandRanges::fits_Rule(uint32_t v) { return v < m_.semantics.value_rules.size(); }
bool OperandRanges::fits_Places(uint32_t v) { return v <= kMaxDecimalPlaces; }
bool OperandRanges::fits_Digits(uint32_t) { return true; }  // any i32
bool OperandRanges::fits_Service(uint32_t v) { return v < kServiceCount; }

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
    (void)count.finish();  // a counter writes nowhere: nothing can fail
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

// verify(), finding on its walk the devices whose services the code calls.
static std::string verify(const Module& m, uint8_t& devices);

namespace {

// The bytes of a bytecode file as read_module takes them, in order: all in memory, or
// from a file a section at a time (so that the file is never held beside the module).
// The checksum runs over every byte after the header.
class ModuleInput {
 public:
  virtual ~ModuleInput() = default;
  // The next n bytes into `out` (through the checksum unless `sum` is false); false
  // if fewer remain.
  bool take(size_t n, void* out, bool sum = true) {
    if (n > remaining() || !read(n, out)) return false;
    if (sum) crc_ = crc32({static_cast<const uint8_t*>(out), n}, crc_);
    return true;
  }
  // Whatever is left, through the checksum; false if it could not be read.
  bool skip_rest() {
    std::string piece(std::min<uint64_t>(remaining(), 1 << 16), '\0');  // on the heap: see read_file
    while (remaining() > 0)
      if (!take(std::min<uint64_t>(remaining(), piece.size()), piece.data())) return false;
    return true;
  }
  virtual uint64_t remaining() const = 0;
  uint32_t crc() const { return crc_; }

 private:
  virtual bool read(size_t n, void* out) = 0;
  uint32_t crc_ = 0;
};

class MemoryInput final : public ModuleInput {
 public:
  explicit MemoryInput(std::string_view bytes) : bytes_(bytes) {}
  uint64_t remaining() const override { return bytes_.size(); }

 private:
  bool read(size_t n, void* out) override {
    if (n > 0) std::memcpy(out, bytes_.data(), n);
    bytes_.remove_prefix(n);
    return true;
  }
  std::string_view bytes_;
};

class FileInput final : public ModuleInput {
 public:
  FileInput(int fd, uint64_t size) : fd_(fd), left_(size) {}
  uint64_t remaining() const override { return left_; }

 private:
  bool read(size_t n, void* out) override {
    for (size_t got = 0; got < n;) {
      const ssize_t r = ::read(fd_, static_cast<char*>(out) + got, n - got);
      if (r < 0 && errno == EINTR) continue;
      if (r == 0) errno = EIO;  // the file is shorter than it was
      if (r <= 0) return false;
      got += static_cast<size_t>(r);
    }
    left_ -= n;
    return true;
  }
  int fd_;
  uint64_t left_;
};

std::optional<Module> read_module(ModuleInput& in, const std::string& name, Diagnostics& diags) {
  char head[kHeaderSize];
  const size_t have = static_cast<size_t>(std::min<uint64_t>(in.remaining(), kHeaderSize));
  if (!in.take(have, head, false)) {
    diags.report(DiagId::FileUnreadable, {}, name, std::strerror(errno));
    return std::nullopt;
  }
  const std::string_view bytes(head, have);
  if (bytes.substr(0, 4) != kMagic) {
    diags.report(DiagId::BytecodeUnreadable, {}, name, "it does not start with the magic \"NCCB\"");
    return std::nullopt;
  }
  if (bytes.size() < kHeaderSize) {
    diags.report(DiagId::BytecodeUnreadable, {}, name,
                 fmt::format("it is shorter than the {}-byte header", kHeaderSize));
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
  // The sections as they come; the first problem is reported once the checksum is
  // known, which takes precedence (a damaged file is damaged, whatever it looks like).
  Module m;
  std::string problem;
  std::map<uint32_t, bool> seen;
  std::string buffer;
  for (uint32_t i = 0; i < section_count && problem.empty(); ++i) {
    char tag_size[8];
    if (!in.take(sizeof tag_size, tag_size)) {
      problem = fmt::format("section {} is truncated", i);
      break;
    }
    ByteReader r({tag_size, sizeof tag_size});
    const uint32_t t = r.u32(), size = r.u32();
    if (size > in.remaining())
      problem = fmt::format("section {} is truncated", i);
    else if (std::find(kSections.begin(), kSections.end(), t) == kSections.end())
      problem = fmt::format("unknown section '{}'", tag_name(t));
    else if (seen[t])
      problem = fmt::format("section '{}' appears twice", tag_name(t));
    else if (i >= kSections.size() || kSections[i] != t)
      problem = fmt::format("section '{}' is out of order", tag_name(t));
    if (!problem.empty()) break;
    seen[t] = true;
    bool ok = false;
    if (t == kCode) {  // straight into the module
      m.code.resize(size);
      ok = in.take(size, m.code.data());
    } else {
      buffer.resize(size);
      ok = in.take(size, buffer.data());
      if (t == kSrcs) {
        ok = ok && read_sources(std::move(buffer), m.source_map);
      } else {
        ByteReader section(buffer);
        ok = ok && read_section(t, section, m) && section.at_end();
      }
    }
    if (!ok) problem = fmt::format("section '{}' is malformed", tag_name(t));
  }
  if (problem.empty() && in.remaining() > 0) problem = "bytes follow the last section";
  if (!in.skip_rest()) {
    diags.report(DiagId::FileUnreadable, {}, name, std::strerror(errno));
    return std::nullopt;
  }
  if (in.crc() != stored) {
    diags.report(DiagId::BytecodeChecksum, {}, name, stored, in.crc());
    return std::nullopt;
  }
  auto invalid = [&](const std::string& why) {
    diags.report(DiagId::BytecodeInvalid, {}, name, why);
    return std::nullopt;
  };
  if (!problem.empty()) return invalid(problem);
  for (uint32_t t : kSections)
    if (!seen[t]) return invalid(fmt::format("section '{}' is missing", tag_name(t)));
  if (std::string why = verify(m, m.devices); !why.empty()) return invalid(why);
  return m;
}

}  // namespace

std::optional<Module> read_module(std::string_view bytes, const std::string& name, Diagnostics& diags) {
  MemoryInput in(bytes);
  return read_module(in, name, diags);
}

std::optional<Module> read_module(int fd, uint64_t size, const std::string& name, Diagnostics& diags) {
  FileInput in(fd, size);
  return read_module(in, name, diags);
}

std::string verify(const Module& m) {
  uint8_t devices = 0;
  return verify(m, devices);
}

static std::string verify(const Module& m, uint8_t& devices) {
  const ProgramSemantics& s = m.semantics;
  const Conventions& c = s.conventions;
  if (std::string why = convention_problem(c); !why.empty()) return why;
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
      if (call.fn == Fn::WorkOffset && call.arg > kExtendedWorkOffset + kExtendedWorkOffsets)
        return fmt::format("code {} names offset {}", code.name, call.arg);
    }
  for (uint16_t i : s.power_on)
    if (i >= s.codes.size()) return fmt::format("power-on state names code {} of {}", i, s.codes.size());
  for (const NumberedCode& n : s.numbered)
    if (n.code >= s.codes.size() || n.slot >= kWordSlots) return "a numbered code names a code that does not exist";
  for (const CodePair& p : s.incompatible)
    if (p.a >= s.codes.size() || p.b >= s.codes.size())
      return "the compatibility matrix names a code that does not exist";
  for (const ValueRule& rule : s.value_rules)
    if (!(rule.lo <= rule.hi) || !std::isfinite(rule.lo) || !std::isfinite(rule.hi))
      return "a value rule has no values";
  uint64_t variables = 0;
  for (const VarSpace& space : m.spaces) {
    variables += space.size;
    if (!(space.limit >= 0 && std::isfinite(space.limit))) return fmt::format("space {} has a bad limit", space.name);
    if (space.locals && space.memory) return fmt::format("memory {} cannot be local to a call", space.name);
    if (space.locals > space.size) return fmt::format("space {} has more local variables than variables", space.name);
    if (space.vacant && (space.memory || space.size == 0))
      return fmt::format("space {} cannot start vacant", space.name);
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
  std::vector<std::pair<uint32_t, uint32_t>> jumps;  // (pc, target)
  std::vector<uint32_t> range_ends;                  // second targets of CallRange
  uint8_t called = 0;  // devices (a local: a write through `devices` could alias anything)
  for (size_t pc = 0; pc < code.size();) {
    if (code[pc] >= static_cast<uint8_t>(Op::Count)) return fmt::format("unknown opcode {} at {}", code[pc], pc);
    Op op = static_cast<Op>(code[pc]);
    const OpInfo* info = &op_info(op);
    size_t size = static_cast<size_t>(instruction_size(op));
    OperandRanges ranges(m, op);
    // A SERVICE is the instruction of its service: the catalogue gives its operands.
    if (op == Op::Service) {
      if (pc + 1 >= code.size()) return fmt::format("{} at {} is cut off by the end of the code", info->name, pc);
      if (code[pc + 1] >= kServiceCount)
        return fmt::format("{} at {} has an operand out of range ({})", info->name, pc, code[pc + 1]);
      const auto service = static_cast<Service>(code[pc + 1]);
      info = &service_op_info(service);
      size += static_cast<size_t>(service_operand_size(service));
      ranges.serve(service);
      called |= device_bit(service_info(service).device);
    }
    if (pc + size > code.size()) return fmt::format("{} at {} is cut off by the end of the code", info->name, pc);
    size_t at = pc + 1;
    for (char f : info->format) {
      const uint32_t v = read_operand(&code[at], operand_size(f));
      at += static_cast<size_t>(operand_size(f));
      if (!ranges.fits(operand_kind(f), v))
        return fmt::format("{} at {} has an operand out of range ({})", info->name, pc, v);
      if (operand_kind(f) == Operand::Target) {
        if (op == Op::CallRange && ranges.targets == 2)
          range_ends.push_back(v);
        else
          jumps.emplace_back(static_cast<uint32_t>(pc), v);
      }
    }
    pc += size;
  }
  for (size_t i = 0; i < m.lines.size(); ++i) {
    if (i > 0 && m.lines[i].pc <= m.lines[i - 1].pc) return "the line table is not in code order";
    if (m.lines[i].source >= map.size()) return "the line table names a block that does not exist";
  }

  // The landings: where control arrives other than from the instruction before (jump
  // targets, entry points, range ends), each once, in code order. The verifier keeps
  // what it knows of them alone, never a byte per byte of code: a second walk over
  // the code finds those that are not instructions, and the line table's.
  std::vector<uint32_t> landings;
  for (auto [from, to] : jumps) landings.push_back(to);
  for (const Entry& e : m.entries) landings.push_back(e.pc);
  landings.insert(landings.end(), range_ends.begin(), range_ends.end());
  std::sort(landings.begin(), landings.end());
  landings.erase(std::unique(landings.begin(), landings.end()), landings.end());
  std::vector<uint32_t> between;  // the landings inside an instruction or past the code, in order
  size_t next_landing = 0, next_line = 0;
  for (size_t pc = 0; pc < code.size(); pc += static_cast<size_t>(instruction_size(&code[pc]))) {
    for (; next_landing < landings.size() && landings[next_landing] <= pc; ++next_landing)
      if (landings[next_landing] < pc) between.push_back(landings[next_landing]);
    if (next_line < m.lines.size() && m.lines[next_line].pc < pc) return "the line table points between instructions";
    if (next_line < m.lines.size() && m.lines[next_line].pc == pc) ++next_line;
  }
  between.insert(between.end(), landings.begin() + static_cast<std::ptrdiff_t>(next_landing), landings.end());
  if (next_line < m.lines.size()) return "the line table points between instructions";

  // Every loop and every call passes a Step, so --max-steps bounds every run: a
  // jump backwards, and every entry point, lands on a Step.
  auto at_boundary = [&](uint32_t pc) {
    return pc < code.size() && !std::binary_search(between.begin(), between.end(), pc);
  };
  auto at_step = [&](uint32_t pc) { return at_boundary(pc) && code[pc] == static_cast<uint8_t>(Op::Step); };
  for (auto [from, to] : jumps) {
    if (!at_boundary(to)) return fmt::format("a jump goes to {}, which is not an instruction", to);
    if (to <= from && !at_step(to)) return fmt::format("the jump back from {} to {} does not land on a Step", from, to);
  }
  uint8_t started = 1;  // process 1 runs the programs of the medium
  for (const Entry& e : m.entries) {
    if (!at_step(e.pc)) return fmt::format("entry point {} does not start with a Step", printable(e.name));
    if ((e.processes & started) || e.processes >> kMaxProcesses || (e.processes && e.kind != EntryKind::Process))
      return fmt::format("entry point {} starts in processes {:#x}, one of them taken or none of a process entry's",
                         printable(e.name), e.processes);
    started |= e.processes;
  }
  for (uint32_t end : range_ends)
    if (!at_boundary(end) || code[end] != static_cast<uint8_t>(Op::RangeEnd))
      return fmt::format("a range ends at {}, which is not a RangeEnd", end);

  // The stack: each instruction is reached with one depth, never below its pops,
  // never above kMaxStack, and no path runs off the end of the code. The depth is
  // kept at the landings: from one to the next, control goes from each instruction to
  // the one after it, and each such stretch is walked once, from the landing that
  // starts it.
  static_assert(kMaxStack < INT16_MAX);
  std::vector<int16_t> depth(landings.size(), -1);
  std::vector<size_t> work;
  auto landing = [&](uint32_t pc) {
    return static_cast<size_t>(std::lower_bound(landings.begin(), landings.end(), pc) - landings.begin());
  };
  std::string problem;
  auto arrive = [&](size_t i, int d) {  // control arrives at landing i with d values
    if (depth[i] == -1) {
      depth[i] = static_cast<int16_t>(d);
      work.push_back(i);
    } else if (depth[i] != d) {
      problem = fmt::format("the stack depth at {} differs between paths ({} and {})", landings[i], depth[i], d);
    }
    return problem.empty();
  };
  for (const Entry& e : m.entries) {
    if (depth[landing(e.pc)] > 0) return fmt::format("entry point {} is reached with values on the stack", e.name);
    arrive(landing(e.pc), 0);
  }
  while (!work.empty()) {
    const size_t from = work.back();
    work.pop_back();
    uint32_t pc = landings[from];
    int d = depth[from];
    for (size_t after = from + 1;;) {  // after: the first landing after pc
      Op op = static_cast<Op>(code[pc]);
      const OpInfo& info = instruction_info(&code[pc]);
      if (d < info.pop) return fmt::format("{} at {} pops more values than the stack holds", info.name, pc);
      d = d - info.pop + info.push;
      if (d > static_cast<int>(kMaxStack)) return fmt::format("the stack grows beyond {} at {}", kMaxStack, pc);
      if ((op == Op::Return || op == Op::End || op == Op::CallRange || op == Op::RangeEnd) && d != 0)
        return fmt::format("{} at {} leaves {} values on the stack", info.name, pc, d);
      switch (op) {
        case Op::Jump:
        case Op::JumpIf:
        case Op::JumpIfNot:
        case Op::JumpSkip:
        case Op::Repeat:
        case Op::EndRepeat:
        case Op::CallRange:  // the first operand: a landing, checked above
          if (!arrive(landing(read_operand(&code[pc + 1], 4)), d)) return problem;
          break;
        default: break;
      }
      if (op == Op::Jump || op == Op::Return || op == Op::End || op == Op::NoBlock) break;
      const uint32_t next = pc + static_cast<uint32_t>(instruction_size(&code[pc]));
      if (next >= code.size()) return fmt::format("execution can run past the end of the code after {}", pc);
      while (after < landings.size() && landings[after] < next) ++after;
      if (after < landings.size() && landings[after] == next) {
        if (!arrive(after, d)) return problem;
        break;
      }
      pc = next;
    }
  }
  devices = called;
  return {};
}

}  // namespace ncc::vm
