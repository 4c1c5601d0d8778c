// What the API's classes hold: the compiler's module and the driver's session.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "driver/pipeline.h"
#include "ncc/diagnostic.h"
#include "ncc/program.h"

namespace ncc::api {

struct Program::Impl {
  vm::Module module;
  // The source files it was compiled from, (path, text): a run quotes their lines in
  // its diagnostics without reading them again.
  std::vector<std::pair<std::string, std::string>> sources;
};

struct ProgramAccess {
  static Program make(std::shared_ptr<const Program::Impl> impl) { return Program(std::move(impl)); }
  static const std::shared_ptr<const Program::Impl>& impl(const Program& p) { return p.impl_; }
};

// The session's diagnostics as values, in source order (as `ncc` prints them).
std::vector<Diagnostic> diagnostics_of(const Session& s);

}  // namespace ncc::api
