#include "builtins.h"

#include <array>
#include <cmath>
#include <numbers>

namespace ncc {

namespace {
constexpr std::array<BuiltinInfo, static_cast<size_t>(Builtin::Count)> kBuiltins = {{
    {"sin", 1},  {"cos", 1},      {"tan", 1},       {"asin", 1},       {"acos", 1},  {"atan", 1},     {"atan2", 2},
    {"sqrt", 1}, {"abs", 1},      {"trunc", 1},     {"round", 1},      {"floor", 1}, {"ceil", 1},     {"exp", 1},
    {"ln", 1},   {"gtl_line", 2}, {"gtl_point", 2}, {"gtl_circle", 2}, {"away", 1},  {"round_to", 2},
}};
constexpr double kDeg = std::numbers::pi / 180.0;

// Trigonometry in degrees, exact at the multiples of 90: SIN(180) is 0, not 1.2e-16,
// so a program that tests it against 0 works as on the machine.
double turn(double a) {
  double r = std::fmod(a, 360.0);
  return r < 0 ? r + 360.0 : r;
}
double sin_degrees(double a) {
  double r = turn(a);
  if (r == 0 || r == 180) return 0;
  if (r == 90 || r == 270) return r == 90 ? 1 : -1;
  return std::sin(r * kDeg);
}
double cos_degrees(double a) {
  double r = turn(a);
  if (r == 90 || r == 270) return 0;
  if (r == 0 || r == 180) return r == 0 ? 1 : -1;
  return std::cos(r * kDeg);
}
}  // namespace

const BuiltinInfo& builtin_info(Builtin b) { return kBuiltins[static_cast<size_t>(b)]; }

std::optional<Builtin> builtin_by_name(std::string_view name) {
  for (size_t i = 0; i < kBuiltins.size(); ++i)
    if (kBuiltins[i].name == name) return static_cast<Builtin>(i);
  return std::nullopt;
}

bool eval_builtin(Builtin b, const double* a, double& out, std::string_view& why) {
  switch (b) {
    case Builtin::Sin: out = sin_degrees(a[0]); break;
    case Builtin::Cos: out = cos_degrees(a[0]); break;
    case Builtin::Tan:
      // tan is undefined at odd multiples of 90 degrees.
      if (std::fmod(std::fabs(a[0]) - 90.0, 180.0) == 0.0) {
        why = "not defined at odd multiples of 90 degrees";
        return false;
      }
      out = sin_degrees(a[0]) / cos_degrees(a[0]);
      break;
    case Builtin::Asin:
    case Builtin::Acos:
      if (a[0] < -1.0 || a[0] > 1.0) {
        why = "[-1, 1]";
        return false;
      }
      out = (b == Builtin::Asin ? std::asin(a[0]) : std::acos(a[0])) / kDeg;
      break;
    case Builtin::Atan: out = std::atan(a[0]) / kDeg; break;
    case Builtin::Atan2:
      if (a[0] == 0.0 && a[1] == 0.0) {
        why = "a non-zero vector";
        return false;
      }
      out = std::atan2(a[0], a[1]) / kDeg;
      break;
    case Builtin::Sqrt:
      if (a[0] < 0.0) {
        why = "non-negative numbers";
        return false;
      }
      out = std::sqrt(a[0]);
      break;
    case Builtin::Abs: out = std::fabs(a[0]); break;
    case Builtin::Trunc: out = std::trunc(a[0]); break;
    case Builtin::Round: out = std::round(a[0]); break;
    case Builtin::Floor: out = std::floor(a[0]); break;
    case Builtin::Ceil: out = std::ceil(a[0]); break;
    case Builtin::Exp: out = std::exp(a[0]); break;
    case Builtin::Away: out = std::copysign(std::ceil(std::fabs(a[0])), a[0]); break;
    case Builtin::RoundTo: {
      const double scale = std::pow(10.0, a[1]);
      out = std::round(a[0] * scale) / scale;
      break;
    }
    case Builtin::Ln:
      if (a[0] <= 0.0) {
        why = "positive numbers";
        return false;
      }
      out = std::log(a[0]);
      break;
    case Builtin::GtlLine:
    case Builtin::GtlPoint:
    case Builtin::GtlCircle: {
      // Element numbers are whole numbers 0..255 (§2.11.2); the fields are 1..3 (a
      // point has 2). Their values are the runtime's: "undefined" asks it.
      int fields = b == Builtin::GtlPoint ? 2 : 3;
      if (!(a[0] >= 0 && a[0] <= 255 && a[0] == std::trunc(a[0]))) {
        why = "element numbers 0..255";
        return false;
      }
      if (!(a[1] >= 1 && a[1] <= fields && a[1] == std::trunc(a[1]))) {
        why = fields == 2 ? "fields 1 and 2 of a point" : "fields 1, 2 and 3";
        return false;
      }
      why = "undefined";
      return false;
    }
    case Builtin::Count: return false;
  }
  if (!std::isfinite(out)) {
    why = "finite results";
    return false;
  }
  return true;
}

}  // namespace ncc
