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
  bool pedantic = false;            // report the recommended word order
  bool block_number_order = true;   // block numbers rise and are not used twice
  bool unique_labels = false;       // a label names one block of its unit
  uint32_t max_repeat_depth = 0;    // repeat loops that may nest (0: no limit)
  bool recursion = false;           // a unit may call itself (Macro B: a condition ends it)
};

// Reports every problem and marks the blocks that have one.
void check(ir::Program& program, const CheckRules& rules, Diagnostics& diags);

}  // namespace ncc
