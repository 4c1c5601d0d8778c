// Lowering: a checked IR program to a bytecode module (vm/opcodes.h).
#pragma once

#include <memory>

#include "ir/ir.h"
#include "stdlib/profile.h"
#include "vm/module.h"

namespace ncc {

// Blocks with errors lower without their faulty words, so that `ncc check` can
// still dry-run the rest of the program.
vm::Module lower(const ir::Program& program, const SourceManager& sources, const stdlib::Profile& profile);

// Lowering while the program is read: the leading blocks of its first unit that have
// no flow statement (nothing read later changes their code) as they come, the rest
// once it is read and checked. The module is the one lower() makes.
class StreamLowering {
 public:
  explicit StreamLowering(const SourceManager& sources);
  ~StreamLowering();
  // Room for the code and source map of `source_bytes` of source, so that they need
  // not move (and be held twice) while they grow: address space, not memory.
  void expect(size_t source_bytes);
  void block(const ir::Program& program, const ir::Unit& unit, const ir::Block& b);
  vm::Module finish(const ir::Program& program, const stdlib::Profile& profile);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ncc
