// The [gost] settings of a machine profile (docs/profile.md), validated, and the
// dialect tables adjusted by them (G04 grouping, G43/G44, unit codes, additions).
#pragma once

#include <optional>
#include <string>

#include "contract/program_semantics.h"
#include "format.h"
#include "stdlib/profile.h"
#include "stdlib/tables.h"

namespace ncc::gost {

struct Settings {
  Format format;
  DecodeOptions decode;
  std::string control_type = "contouring";
  int tool_digits = 0;  // tool_word_split: T = tool digits + offset digits
  int offset_digits = 0;
  Conventions conventions;
  stdlib::DialectTables tables;
};

// Reads and validates the settings; problems are reported at their place in the
// profile. Returns nothing if the profile cannot be used.
[[nodiscard]] std::optional<Settings> load_settings(const stdlib::Profile& profile, Diagnostics& diags);

}  // namespace ncc::gost
