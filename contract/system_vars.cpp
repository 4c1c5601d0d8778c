#include "system_vars.h"

#include <cmath>

#include <array>
#include <limits>

namespace ncc {

namespace {
struct SysInfo {
  std::string_view name;
  uint32_t indices;
  uint32_t writable;
};
constexpr std::array<SysInfo, static_cast<size_t>(SysVar::Count)> kSystemVars = {{
#define SYS(id, name, indices, writable, doc) {name, indices, writable},
#include "system_vars.def"
#undef SYS
}};
}  // namespace

std::string_view sys_name(SysVar v) { return kSystemVars[static_cast<size_t>(v)].name; }
uint32_t sys_indices(SysVar v) { return kSystemVars[static_cast<size_t>(v)].indices; }
bool sys_writable(SysRef ref) { return ref.index >= kSystemVars[static_cast<size_t>(ref.var)].writable; }

std::optional<SysVar> sys_by_name(std::string_view name) {
  for (size_t i = 0; i < kSystemVars.size(); ++i)
    if (kSystemVars[i].name == name) return static_cast<SysVar>(i);
  return std::nullopt;
}

std::optional<std::string_view> sys_value_error(SysRef ref, double value) {
  const bool flag = value == 0 || value == 1;
  switch (ref.var) {
    case SysVar::RemainingPath:
    case SysVar::ModalCode:
    case SysVar::ModalWord:
    case SysVar::Position: return "it is read-only";
    case SysVar::Timer:
      if (ref.index == 0) return "it is the clock, read-only";
      [[fallthrough]];
    case SysVar::TotalTime:
      if (!(std::fabs(value) <= std::numeric_limits<float>::max()))
        return "it is a real (RE), at most 3.4E38 in magnitude";
      break;
    case SysVar::AssetStatus: return "it is read-only";
    case SysVar::BlockEnable:
    case SysVar::AssetErrorMode:
    case SysVar::OptionalStop:
    case SysVar::FeedOverride:
    case SysVar::RapidRun:
    case SysVar::AxesDisconnected:
    case SysVar::PositionErrors:
      if (!flag) return "it is 0 or 1";
      break;
    case SysVar::AxisDisplay:
      // 3: the remaining path (§2.10.10, "after the command UCV=3").
      if (value != 0 && value != 1 && value != 2 && value != 3) return "it is 0, 1, 2 or 3";
      break;
    case SysVar::TapReturn:
      if (!(value >= 0 && value <= 255) || value != std::trunc(value)) return "it is a whole percentage 0..255";
      break;
    case SysVar::CornerDeviation:
      if (!(value >= 0 && value <= 2)) return "it lies between 0 and 2";
      break;
    case SysVar::DwellTime:
    case SysVar::FormTolerance:
      if (!(value >= 0)) return "it must not be negative";
      break;
    default: break;
  }
  return std::nullopt;
}

}  // namespace ncc
