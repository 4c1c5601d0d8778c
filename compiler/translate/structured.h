// Structured translation (the default of `ncc translate`): the program's IR written
// in the target's own constructs. Parameters become the target's variables through
// a fixed mapping, expressions its expressions, jumps and repeat loops its jumps,
// subprograms and macros its subprograms, each block's codes the target's codes of
// the same functions. What the target cannot say is refused at its block, once per
// construct; nothing is written then.
#pragma once

#include <cstdio>
#include <string_view>

#include "ir/ir.h"
#include "translate.h"

namespace ncc::translate {

// The targets structured translation writes; the others take --flatten.
bool writes_structured(std::string_view target);

// Writes `program` (read and checked, without errors) in the request's target to
// `out`. False when something could not be written (reported); the caller then
// keeps no output.
bool structured(Session& s, const ir::Program& program, const Request& request, std::FILE* out);

}  // namespace ncc::translate
