// Fuzz target of one front end (NCC_FUZZ_DIALECT: iso, gost, pp or nc110): the input
// is a program's text, and goes where `ncc check`, `ncc compile` and `ncc run` take it:
// the front end, the checks and the lowering (compile_source), the dry run, and, if it
// compiled without errors, the module written and read back (what ncc compile writes,
// ncc run must accept) and the run.
#include <string>

#include "fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ncc;
  Session s(100);  // ncc's default --error-limit
  fuzz::start_session(s);
  const uint32_t file = s.sources.add("fuzz.nc", std::string(reinterpret_cast<const char*>(data), size));
  if (auto m = compile_source(s, file, NCC_FUZZ_DIALECT)) {
    const bool compiled = !s.diags.has_errors();
    if (compiled) fuzz::round_trip(*m);
    if (!s.diags.limit_reached()) dry_run(s, *m, fuzz::run_settings());
    if (compiled) fuzz::run(s, *m);
  }
  fuzz::format_diagnostics(s);
  return 0;
}
