// The iso dialect as data: the tables of stdlib/dialects/iso/ and the [iso] settings
// of the machine profile (docs/profile.md), validated.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "contract/program_semantics.h"
#include "contract/system_vars.h"
#include "stdlib/profile.h"
#include "stdlib/tables.h"

namespace ncc::iso {

inline constexpr uint32_t kMaxBlockNumber = 99999;  // N, GOTO's and M97's block: 0 to 99999 (NC2014)

struct Settings {
  stdlib::DialectTables tables;
  std::vector<std::string> power_on;
  std::string library;                // where called O programs are ("" = beside the program)
  uint32_t program_digits = 4;        // of an O number (decision 53: iso.program_number_digits)
  uint32_t max_program = 9999;        // the largest O number
  bool semicolon_comments = false;    // ';' starts a comment to the line end (decision 54)
  std::map<uint32_t, SysRef> system;  // #3000...: the system variables (system_variables.tsv)
  Conventions conventions;
  std::string machine;  // how --machine named the profile, for messages
};

// Reads the tables and the profile's [iso] settings; problems are reported at their
// place. Returns nothing if the dialect cannot be used.
[[nodiscard]] std::optional<Settings> load_settings(const stdlib::Profile& profile, Diagnostics& diags);

}  // namespace ncc::iso
