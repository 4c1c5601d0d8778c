#include "functions.h"

#include <array>

namespace ncc {

namespace {
struct FnInfo {
  std::string_view name;
  FnGroup group;
};
constexpr std::array<FnInfo, static_cast<size_t>(Fn::Count)> kFunctions = {{
#define FN(id, name, group, doc) {name, FnGroup::group},
#include "functions.def"
#undef FN
}};
}  // namespace

std::string_view fn_name(Fn fn) { return kFunctions[static_cast<size_t>(fn)].name; }
FnGroup fn_group(Fn fn) { return kFunctions[static_cast<size_t>(fn)].group; }

std::optional<Fn> fn_by_name(std::string_view name) {
  for (size_t i = 0; i < kFunctions.size(); ++i)
    if (kFunctions[i].name == name) return static_cast<Fn>(i);
  return std::nullopt;
}

}  // namespace ncc
