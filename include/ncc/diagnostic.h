// Diagnostics as values: what compiling, loading or running a program found, each
// with the place it concerns and its code (docs/diagnostics.md lists the codes).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "export.h"

namespace ncc::api {

enum class Severity { Note, Info, Warning, Error };

// A place in a source file; line 0: the diagnostic concerns no place in a source
// (a file that cannot be read, a profile setting).
struct Location {
  std::string file;
  uint32_t line = 0, column = 0;
};

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string code;  // "NC4001"
  std::string message;
  Location location;
  std::string text;  // as `ncc` prints it: "part.nc:12:5: error: ... [NC4001]", the line quoted, notes
};

// A value, or the diagnostics that say why there is none. With a value the
// diagnostics hold its warnings.
template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value, std::vector<Diagnostic> diagnostics)
      : value_(std::move(value)), diagnostics_(std::move(diagnostics)) {}
  explicit Result(std::vector<Diagnostic> diagnostics) : diagnostics_(std::move(diagnostics)) {}

  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  T& value() { return value_.value(); }
  const T& value() const { return value_.value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() { return value(); }
  const T& operator*() const { return value(); }
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::optional<T> value_;
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace ncc::api
