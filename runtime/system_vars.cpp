#include "system_vars.h"

#include <array>

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

}  // namespace ncc
