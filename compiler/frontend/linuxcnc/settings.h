// The linuxcnc dialect as data: the tables of stdlib/dialects/linuxcnc/ and the
// [linuxcnc] settings of the machine profile (docs/profile.md), validated.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "contract/program_semantics.h"
#include "stdlib/profile.h"
#include "stdlib/tables.h"

namespace ncc::linuxcnc {

inline constexpr uint32_t kMaxParameter = 5602;   // #1-#5602 (RS274NGC_MAX_PARAMETERS)
inline constexpr uint32_t kLocalParameters = 30;  // #1-#30: local to a subroutine call

struct Settings {
  stdlib::DialectTables tables;
  std::vector<std::string> power_on;
  std::string library;  // where `o<name> call` finds name.ngc ("" = beside the program)
  // LinuxCNC codes and parameters ncc does not run ("G7", "G5.1", "M62", "#<_x>"),
  // each with what it is; and those it reads as nothing ("G91.1"), with the letters
  // of their words ("G64": "PQ").
  std::map<std::string, std::string> refused;
  std::map<std::string, std::string> ignored;
  Conventions conventions;
};

// Reads the tables and the profile's [linuxcnc] settings; problems are reported at
// their place. Returns nothing if the dialect cannot be used.
[[nodiscard]] std::optional<Settings> load_settings(const stdlib::Profile& profile, Diagnostics& diags);

}  // namespace ncc::linuxcnc
