// A dialect front end: source text to IR, plus the tables the checker reads.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "check/check.h"
#include "ir/ir.h"
#include "stdlib/profile.h"

namespace ncc {

class Frontend {
 public:
  virtual ~Frontend() = default;
  // Reads one source file into IR; every problem found on the way is reported.
  virtual ir::Program read(const SourceManager& sources, uint32_t file, Diagnostics& diags) = 0;
  // What the dialect-independent checks need to know about this dialect.
  virtual const CheckRules& rules() const = 0;
};

std::vector<std::string_view> dialect_names();
// Builds the front end of `dialect` configured by `profile`; nullptr when the
// dialect is unknown or its profile settings are invalid (reported).
std::unique_ptr<Frontend> make_frontend(std::string_view dialect, const stdlib::Profile& profile, Diagnostics& diags);

}  // namespace ncc
