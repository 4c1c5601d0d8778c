// `ncc files`: the ASSET sandbox from the command line (docs/asset.md) — make one,
// create files, fill them from text, print them as text, check them.
#pragma once

#include <string>
#include <vector>

namespace ncc {

extern const char* const kFilesUsage;

// `args` after "files"; returns the exit status.
int files_command(const std::vector<std::string>& args);

}  // namespace ncc
