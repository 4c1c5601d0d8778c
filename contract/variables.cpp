#include "variables.h"

#include <cmath>
#include <limits>

namespace ncc {

bool convert_value(VarType type, double limit, double& v) {
  // Integers round half away from zero: 0.3 * 10 is 3, not 2 (NC-110 D8).
  auto integral = [&](double lo, double hi) {
    v = std::round(v);
    return v >= lo && v <= hi;
  };
  switch (type) {
    case VarType::Byte: return integral(0, 255);
    case VarType::Integer: return integral(-32768, 32767);
    case VarType::Long: return integral(-2147483647.0, 2147483647.0);
    case VarType::Real:
      if (!(std::fabs(v) <= std::numeric_limits<float>::max())) return false;
      v = static_cast<float>(v);
      return true;
    case VarType::Unavailable: return false;
    case VarType::Thousandths: v = std::round(v * 1000) / 1000; [[fallthrough]];
    default: return std::isfinite(v) && (limit == 0 || std::fabs(v) < limit);
  }
}

}  // namespace ncc
