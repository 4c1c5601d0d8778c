// The pp dialect as data: the tables of stdlib/dialects/pp/ and the [pp] settings of
// the machine profile (docs/profile.md), validated.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "contract/program_semantics.h"
#include "stdlib/profile.h"
#include "stdlib/tables.h"

namespace ncc::pp {

// What the front end does with a code itself (control_codes.tsv).
enum class Control : uint8_t { Formula, Entry, End, CallSubprogram, CallMacro, Jump, Dwell, Plane, Unsupported };

struct ControlCode {
  Control action = Control::Unsupported;
  char op = 0;        // Formula: + - * /
  std::string plane;  // Plane: two axes, "Z4"
  std::string note;   // Unsupported: why
};

struct Settings {
  stdlib::DialectTables tables;
  std::map<std::string, ControlCode> control;  // "G71" -> its action
  std::string axis_letters = "ABC";            // the letters of axes 4. 5. 6. (§2.2.1 a, b)
  std::string library;                         // where macro files are ("" = the program's folder)
  bool require_star = false;                   // '*' must end the program (serial input, §2.3.2)
  std::vector<std::string> power_on;
  Conventions conventions;
};

// Reads the tables and the profile's [pp] settings; problems are reported at their
// place. Returns nothing if the dialect cannot be used.
[[nodiscard]] std::optional<Settings> load_settings(const stdlib::Profile& profile, Diagnostics& diags);

}  // namespace ncc::pp
