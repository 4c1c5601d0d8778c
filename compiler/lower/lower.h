// Lowering: a checked IR program to a bytecode module (vm/opcodes.h).
#pragma once

#include "ir/ir.h"
#include "stdlib/profile.h"
#include "vm/module.h"

namespace ncc {

// Blocks with errors lower without their faulty words, so that `ncc check` can
// still dry-run the rest of the program.
vm::Module lower(const ir::Program& program, const SourceManager& sources, const stdlib::Profile& profile);

}  // namespace ncc
