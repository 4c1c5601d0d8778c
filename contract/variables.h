// Variable spaces a dialect declares: numbered parameters (NC-110 E, pp R, Macro B #)
// with a value type per index range, and byte-addressed memories (NC-110's PLC
// packets SA, SK and the SYVAR area) read and written in several formats.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ncc {

// What a store keeps: LongReal any finite double (below `limit` in magnitude when the
// space sets one), Real a float, Byte 0..255, Integer and Long 16 and 32 bits,
// Thousandths a LongReal rounded to 0.001 (pp R parameters, fixed point). Integer
// types and Thousandths round half away from zero; a value out of range is an error.
// Unavailable: no variable has these numbers (Macro B #34-#99); using one is an error.
enum class VarType : uint8_t { LongReal, Real, Byte, Integer, Long, Thousandths, Unavailable, Count };
// The types a value may be shown as (NC-110 DIS): those a variable holds.
constexpr uint32_t kShownTypes = static_cast<uint32_t>(VarType::Unavailable);

// The formats of a byte-addressed memory (NC-110 §2.10.5, Table 2.7): a bit, a byte,
// 16 and 32-bit integers, IEEE float and double, little-endian. The index of a
// reference counts in units of its format.
enum class MemFormat : uint8_t { Bit, Byte, Integer, Long, Real, LongReal, Count };

constexpr uint32_t mem_size(MemFormat f) {
  switch (f) {
    case MemFormat::Bit:
    case MemFormat::Byte: return 1;
    case MemFormat::Integer: return 2;
    case MemFormat::Long:
    case MemFormat::Real: return 4;
    default: return 8;
  }
}

struct VarSpace {
  std::string name;   // "E", "R", "#", "SA"
  uint32_t size = 0;  // variables, or bytes of a memory
  struct Range {
    uint32_t first = 0;
    VarType type = VarType::LongReal;
  };
  std::vector<Range> types;            // the type of index i is that of the last range with first <= i
  bool memory = false;                 // byte-addressed: read and written through a MemFormat
  MemFormat format = MemFormat::Byte;  // a memory's, where a reference names none (NC-110 SA: BL)
  // The first `locals` variables are local to a call: each call starts with them
  // reset, and the caller's values come back on return (pp: all; Macro B: #0-#33).
  uint32_t locals = 0;
  // Variables start vacant (Macro B <vacant>, a quiet NaN) rather than 0, and
  // variable 0 is always vacant (#0).
  bool vacant = false;
  double limit = 0;  // LongReal values must stay below this magnitude (0 = no limit)

  VarType type_of(uint32_t index) const {
    VarType t = VarType::LongReal;
    for (const Range& r : types)
      if (r.first <= index) t = r.type;
    return t;
  }
};

// Converts `v` to what a variable of `type` holds; false if it does not fit.
[[nodiscard]] bool convert_value(VarType type, double limit, double& v);

}  // namespace ncc
