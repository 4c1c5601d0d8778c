// Dialect-independent checks on the IR, driven by the dialect's tables: repeated
// words, two codes of one group, undefined codes, conflicting M codes, word order,
// block numbers. Checks that need the modal state run on the runtime (a dry run,
// see compiler/driver/pipeline.h), so they are written once.
#pragma once

#include "ir/ir.h"
#include "stdlib/tables.h"

namespace ncc {

struct CheckRules {
  const stdlib::DialectTables* tables = nullptr;
  bool pedantic = false;  // report the recommended word order
};

void check(const ir::Program& program, const CheckRules& rules, Diagnostics& diags);

}  // namespace ncc
