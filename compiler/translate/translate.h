// `ncc translate`: a program of one dialect written in another.
#pragma once

#include <cstdio>
#include <string>

#include "driver/pipeline.h"
#include "writer.h"

namespace ncc::translate {

struct Request {
  std::string to;                                   // the target dialect (is_target)
  Header header;                                    // what the leading comment says
  const stdlib::Profile* target_profile = nullptr;  // the machine the target runs on
  RunSettings run;                                  // the run that flattens (switches, limits, inputs)
};

// Flattened translation: runs the compiled program and writes the plain blocks its
// motion makes to `out`. False when the target cannot say something the run did
// (each construct reported once, at its first block, with how many more there are);
// the caller then keeps no output.
[[nodiscard]] bool flatten(Session& s, const vm::Module& module, const Request& request, std::FILE* out);

}  // namespace ncc::translate
