#include "fuzz.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace ncc::fuzz {

void start_session(Session& s) {
  static const Session loaded = [] {
    Session t;
    if (!load_profile(t, "")) fail("the built-in profile does not load");
    return t;
  }();
  // The profile's ranges name its files by their place in the session's sources.
  for (size_t i = 0; i < loaded.sources.size(); ++i)
    s.sources.add(loaded.sources.file(i).path(), std::string(loaded.sources.file(i).text()));
  s.profile = loaded.profile;
  s.library = "/nonexistent/ncc-fuzz-library";
}

RunSettings run_settings() {
  RunSettings settings;
  settings.max_steps = 2'000;
  return settings;
}

void round_trip(const vm::Module& m) {
  const std::string bytes = vm::write_module(m);
  Diagnostics diags;
  auto back = vm::read_module(bytes, "round-trip.ncb", diags);
  if (!back) fail("a module does not load once written: " + (diags.all().empty() ? "" : diags.all().front().message));
  if (vm::disassemble(*back) != vm::disassemble(m)) fail("a module written and read back disassembles to other text");
}

void run(Session& s, const vm::Module& m) {
  NullSink none;
  (void)run_module(s, m, run_settings(), none);  // any outcome will do: a fuzzer looks for crashes
}

void format_diagnostics(const Session& s) {
  for (DiagFormat format : {DiagFormat::Text, DiagFormat::Json, DiagFormat::Sarif})
    format_all(s.diags.all(), s.sources, format);
}

void fail(const std::string& what) {
  std::fprintf(stderr, "ncc fuzz target: %s\n", what.c_str());
  std::abort();
}

int replay(int argc, char** argv) {
  std::vector<std::filesystem::path> inputs;
  for (int i = 1; i < argc; ++i) {
    if (argv[i][0] == '-') continue;
    std::filesystem::path path = argv[i];
    if (!std::filesystem::is_directory(path)) {
      inputs.push_back(path);
      continue;
    }
    std::vector<std::filesystem::path> found;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(path))
      if (entry.is_regular_file()) found.push_back(entry.path());
    std::sort(found.begin(), found.end());
    inputs.insert(inputs.end(), found.begin(), found.end());
  }
  for (const auto& path : inputs) {
    int error = 0;
    auto bytes = read_file(path.string(), kProgramFile, error);
    if (!bytes) {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), read_error(error, kProgramFile).c_str());
      return 2;
    }
    std::fprintf(stderr, "%s\n", path.c_str());  // the input a crash belongs to
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes->data()), bytes->size());
  }
  std::fprintf(stderr, "%zu inputs ran\n", inputs.size());
  return 0;
}

}  // namespace ncc::fuzz
