// Dialect-independent checks on the IR, driven by the dialect's tables: repeated
// words, two codes of one group, undefined codes, conflicting M codes, word order,
// block numbers. Checks that need the modal state run on the runtime (a dry run,
// see compiler/driver/pipeline.h), so they are written once.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "ir/ir.h"
#include "stdlib/tables.h"

namespace ncc {

struct CheckRules {
  const stdlib::DialectTables* tables = nullptr;
  bool pedantic = false;           // report the recommended word order
  bool block_number_order = true;  // block numbers rise and are not used twice
  bool unique_labels = false;      // a label names one block of its unit
  uint32_t max_repeat_depth = 0;   // repeat loops that may nest (0: no limit)
  bool recursion = false;          // a unit may call itself (Macro B: a condition ends it)
  bool block_ranges = false;       // a label may end a block range (NC-110 EPP): code follows its block
  uint8_t processes = 1;           // processes that run programs side by side (NC-110 chapter 4: 5)
  // A jump to a block number no block has is an alarm only when it is taken (Fanuc,
  // iso decision 73): a warning here, and the jump looks for its number at run time.
  bool absent_jump_runs = false;
  // Two codes of one modal group in a block: the last is in force and the others are
  // dropped with a warning (Fanuc, iso decision 75); one-shot codes (group "00") still
  // may not share a block. Else NC3002.
  bool group_last_wins = false;
};

// The block numbers of a unit in order: a number used again, or lower than the one
// before, is reported (when the dialect's rules ask for it).
class BlockNumbers {
 public:
  void add(const ir::Block& b, Diagnostics& diags);

 private:
  std::map<uint32_t, SourceRange> first_;  // each number's first use
  std::optional<uint32_t> last_;
};

struct BlockScratch;

// The checks of blocks compiled while the program is still being read (a stream:
// the leading blocks of its first unit that have no flow statement):
// each block's own checks now, and what the whole-unit checks need of it later (its
// block number, its main block as an entry point). What they find is held and
// reported by check(), where it would have reported it: the diagnostics and the
// error limit come out as without a stream.
class StreamChecks {
 public:
  explicit StreamChecks(const CheckRules& rules);
  ~StreamChecks();
  // Checks the block and marks it if it has an error.
  void block(const ir::Program& program, ir::Block& b);
  bool found_errors() const { return block_diags_.has_errors() || number_diags_.has_errors(); }
  const std::set<std::string>& entries() const { return entries_; }

 private:
  friend void check(ir::Program&, const CheckRules&, Diagnostics&, StreamChecks*);
  const CheckRules& rules_;
  std::unique_ptr<BlockScratch> scratch_;
  BlockNumbers numbers_;
  std::set<std::string> entries_;           // ":N" of the main blocks
  Diagnostics block_diags_, number_diags_;  // found, not yet reported
};

// Reports every problem and marks the blocks that have one; `streamed`: the checks
// of the first unit's blocks that were compiled and dropped while it was read.
void check(ir::Program& program, const CheckRules& rules, Diagnostics& diags, StreamChecks* streamed = nullptr);

}  // namespace ncc
