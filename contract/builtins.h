// Built-in functions programs call in expressions (NC-110 SIN/ARS..., Macro B
// SIN/ASIN/SQRT...). Angles are degrees, as every dialect here writes them. A
// domain error is reported by name, never a NaN passed on.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace ncc {

enum class Builtin : uint8_t {
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Atan2,
  Sqrt,
  Abs,
  Trunc,
  Round,
  Floor,
  Ceil,
  Exp,
  Ln,
  // NC-110 FEL, FEP, FEC (§2.12): field b of GTL line, point or circle a, which the
  // runtime holds: eval_builtin checks the arguments and answers "undefined".
  GtlLine,
  GtlPoint,
  GtlCircle,
  // Macro B FUP (away from zero: FUP[-1.2] = -2) and ROUND after an address: a to b
  // decimals, half away from zero.
  Away,
  RoundTo,
  Count
};

struct BuiltinInfo {
  std::string_view name;
  uint8_t arity;
};

const BuiltinInfo& builtin_info(Builtin b);
std::optional<Builtin> builtin_by_name(std::string_view name);

// Evaluates b on args; on a domain error returns false and names the rule in `why`
// ("undefined" for a GTL element that is not defined).
[[nodiscard]] bool eval_builtin(Builtin b, const double* args, double& out, std::string_view& why);

}  // namespace ncc
