// Variable spaces a dialect declares (NC-110 E parameters, pp R parameters, Macro B
// # variables): their size and the value type of each index range.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ncc {

enum class VarType : uint8_t { LongReal, Real, Byte, Integer, Long, Count };

struct VarSpace {
  std::string name;  // "E", "R", "#"
  uint32_t size = 0;
  struct Range {
    uint32_t first = 0;
    VarType type = VarType::LongReal;
  };
  std::vector<Range> types;  // the type of index i is that of the last range with first <= i

  VarType type_of(uint32_t index) const {
    VarType t = VarType::LongReal;
    for (const Range& r : types)
      if (r.first <= index) t = r.type;
    return t;
  }
};

}  // namespace ncc
