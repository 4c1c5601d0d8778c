// Structured translation (the default of `ncc translate`): the program's IR written
// in the target's own constructs. Parameters become the target's variables through
// a fixed mapping, expressions its expressions, jumps and repeat loops its jumps,
// subprograms and macros its subprograms, each block's codes the target's codes of
// the same functions. What the target cannot say is refused at its block, once per
// construct; nothing is written then.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

#include "ir/ir.h"
#include "translate.h"

namespace ncc::translate {

// Reads, checks and dry-runs the source `file` of `dialect` as `ncc compile` does,
// translating the main program's leading plain blocks as they are streamed (a CAM
// program translates in the memory compiling it takes), and writes it in the
// request's target to `out`. False when the program has errors or something could
// not be written (reported); the caller then keeps no output.
[[nodiscard]] bool structured(Session& s, uint32_t file, const std::string& dialect, const Request& request,
                              std::FILE* out);

}  // namespace ncc::translate
