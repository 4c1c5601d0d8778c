// Diagnostics: stable codes from diagnostics.def, a collector, and printers (text
// with caret, JSON, SARIF). Emitting and printing are separate.
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "source.h"

namespace ncc {

enum class Severity : uint8_t { Note, Info, Warning, Error };

enum class DiagId : uint16_t {
#define DIAG(id, number, name, severity, message) id,
#include "diagnostics.def"
#undef DIAG
  Count
};

struct DiagInfo {
  DiagId id;
  uint16_t number;
  std::string_view name;
  Severity severity;
  std::string_view message;
};

const DiagInfo& diag_info(DiagId id);
std::string diag_code(DiagId id);  // "NC1001"
std::optional<DiagId> diag_by_name(std::string_view name);
std::string_view severity_name(Severity s);

struct Note {
  SourceRange range;
  std::string message;
};

struct Diagnostic {
  DiagId id;
  Severity severity;
  SourceRange range;  // may be invalid for diagnostics about no place in a source
  std::string message;
  std::vector<Note> notes;
};

template <typename... Args>
std::string diag_message(DiagId id, const Args&... args) {
  return fmt::format(fmt::runtime(diag_info(id).message), args...);
}

// Collects diagnostics in the order they are reported; stops accepting errors after
// `error_limit` (0 = no limit) with one NC1019, which error_count() does not count.
class Diagnostics {
 public:
  explicit Diagnostics(uint32_t error_limit = 0) : error_limit_(error_limit) {}

  template <typename... Args>
  Diagnostic* report(DiagId id, SourceRange range, const Args&... args) {
    return add({id, diag_info(id).severity, range, diag_message(id, args...), {}});
  }
  // The rule a dialect's manual gives for a diagnostic, appended to its message:
  // "... (GOST 20999 §7.3)". Loaded from stdlib/dialects/<dialect>/citations.tsv.
  void set_citations(std::map<DiagId, std::string> citations) { citations_ = std::move(citations); }
  Diagnostic* add(Diagnostic d);  // nullptr when dropped past the error limit

  const std::vector<Diagnostic>& all() const { return list_; }
  uint32_t error_count() const { return errors_; }
  uint32_t warning_count() const { return warnings_; }
  bool has_errors() const { return errors_ > 0; }  // the limit notice needs errors before it
  bool limit_reached() const { return limit_reached_; }
  void clear();

 private:
  std::vector<Diagnostic> list_;
  uint32_t error_limit_;
  uint32_t errors_ = 0;
  uint32_t warnings_ = 0;
  bool limit_reached_ = false;
  std::map<DiagId, std::string> citations_;
};

enum class DiagFormat { Text, Json, Sarif };

// GCC/Clang style: "file:line:col: error: message [NC1001]", the source line and a caret.
std::string format_text(const Diagnostic& d, const SourceManager& sources, bool color = false);
std::string format_all(const std::vector<Diagnostic>& list, const SourceManager& sources, DiagFormat format,
                       bool color = false);
// `s` as the inside of a JSON (and C) string literal: control characters and the
// backslash escaped, bytes that are not UTF-8 as \ufffd; `quotes` false leaves '"' as it
// is (a text no quotes delimit, read to the end of its line).
std::string json_escape(std::string_view s, bool quotes = true);

}  // namespace ncc
