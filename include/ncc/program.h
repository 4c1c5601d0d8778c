// A program compiled and verified, ready to run: from source text, a source file or a
// bytecode file (.ncb). A Program does not change; copies share it, and any number of
// runs may use it at once.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diagnostic.h"
#include "export.h"
#include "machine_interface.h"

namespace ncc::api {

struct CompileOptions {
  std::string dialect = "iso";  // gost, nc110, pp, iso
  std::string profile;          // a machine profile file (docs/profile.md); "": the built-in default
  std::string library;          // where called programs are found (ncc --lib)
};

class NCC_API Program {
 public:
  // As `ncc compile` does: front end, checks, lowering and a dry run; a program only
  // when none of them found an error. `name` is the file name diagnostics give.
  static Result<Program> compile(std::string_view text, const std::string& name, const CompileOptions& options = {});
  static Result<Program> compile_file(const std::string& path, const CompileOptions& options = {});
  // A bytecode file or its bytes, checked and verified before anything runs.
  static Result<Program> load(const std::string& path);
  static Result<Program> load_bytes(std::string_view bytes, const std::string& name);

  std::string bytes() const;  // the bytecode file (docs/bytecode.md)
  std::string dialect() const;
  uint32_t block_count() const;
  Block block(uint32_t index) const;  // index < block_count()
  // The first block that starts on `line` of the main file, or after it; none past its end.
  std::optional<uint32_t> block_at_line(uint32_t line) const;

  struct Impl;  // the library's

 private:
  friend struct ProgramAccess;
  explicit Program(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

}  // namespace ncc::api
