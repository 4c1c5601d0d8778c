// `ncc regime`: the cutting conditions (sim/regime.h) from the command line: spindle
// speed and feed for a tool, from given values or the reference table
// stdlib/cutting_data.tsv, with a ready block ("S3183 M3 F764").
#pragma once

#include <string>
#include <vector>

namespace ncc {

extern const char* const kRegimeUsage;

// `args` after "regime"; prints its own --help; returns 0, or 2 for a usage error.
int regime_command(const std::vector<std::string>& args);

}  // namespace ncc
