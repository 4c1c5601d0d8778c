// Diagnostics: stable codes from diagnostics.def, a collector, and printers (text
// with caret, JSON, SARIF). Emitting and printing are separate.
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
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

// Diagnostic arguments checked at compile time, the way fmt checks a format string:
// a DiagId written at a call site converts to DiagIdFor<Args...> only in a constant
// expression that counts its message's placeholders, so a call with too few or too many
// arguments does not compile. An id known only at run time goes through runtime_diag().
namespace diag_check {

inline constexpr std::string_view kMessages[] = {
#define DIAG(id, number, name, severity, message) message,
#include "diagnostics.def"
#undef DIAG
};

inline constexpr int kMaxArgs = 8;
enum class ArgKind : uint8_t { Any, Integer, Floating };  // what a placeholder's presentation type asks for

struct Placeholders {
  int count = 0;                 // the arguments the message takes: its highest {N} + 1
  ArgKind kinds[kMaxArgs] = {};  // by argument
  const char* malformed = nullptr;
};

constexpr ArgKind kind_of_presentation(char type) {
  for (char c : std::string_view("bBcdoxX"))
    if (type == c) return ArgKind::Integer;
  for (char c : std::string_view("aAeEfFgG"))
    if (type == c) return ArgKind::Floating;
  return ArgKind::Any;
}

// fmt's replacement fields: "{}" or "{N}", either with ":spec"; "{{" and "}}" are braces.
constexpr Placeholders placeholders(std::string_view message) {
  Placeholders p;
  auto malformed = [&p](const char* why) {
    p.malformed = why;
    return p;
  };
  bool used[kMaxArgs] = {}, automatic = false, numbered = false;
  int next = 0;
  for (size_t i = 0; i < message.size(); ++i) {
    const char c = message[i];
    const bool doubled = i + 1 < message.size() && message[i + 1] == c;
    if (c == '}' && !doubled) return malformed("a '}' closes no placeholder (write '}}')");
    if ((c == '{' || c == '}') && doubled) ++i;
    if (c != '{' || doubled) continue;
    int index = 0;
    if (++i < message.size() && message[i] >= '0' && message[i] <= '9') {
      numbered = true;
      for (; i < message.size() && message[i] >= '0' && message[i] <= '9' && index < kMaxArgs; ++i)
        index = index * 10 + (message[i] - '0');
    } else {
      automatic = true;
      index = next++;
    }
    ArgKind kind = ArgKind::Any;
    if (i < message.size() && message[i] == ':') {
      const size_t spec = ++i;
      while (i < message.size() && message[i] != '}' && message[i] != '{') ++i;
      if (i > spec) kind = kind_of_presentation(message[i - 1]);
    }
    if (i >= message.size() || message[i] != '}') return malformed("a placeholder is not closed by '}'");
    if (automatic && numbered) return malformed("the message mixes {} and {N}");
    if (index >= kMaxArgs) return malformed("a placeholder's index is too high");
    if (kind != ArgKind::Any) p.kinds[index] = kind;
    used[index] = true;
    if (index >= p.count) p.count = index + 1;
  }
  for (int a = 0; a < p.count; ++a)
    if (!used[a]) return malformed("an argument below the highest {N} has no placeholder");
  return p;
}

template <typename Arg>
constexpr bool fits(ArgKind kind) {
  if (kind == ArgKind::Integer) return std::is_integral_v<Arg>;
  if (kind == ArgKind::Floating) return std::is_floating_point_v<Arg>;
  return true;
}

enum class Verdict : uint8_t { Fits, Malformed, WrongCount, WrongType };

template <typename... Args>
constexpr Verdict check(DiagId id) {
  const Placeholders p = placeholders(kMessages[static_cast<size_t>(id)]);
  if (p.malformed) return Verdict::Malformed;
  if (p.count != static_cast<int>(sizeof...(Args))) return Verdict::WrongCount;
  int a = 0;
  return (fits<Args>(p.kinds[a++]) && ...) ? Verdict::Fits : Verdict::WrongType;
}

// Not constexpr: a call in the compile-time check is the error, and its name says why.
void diagnostic_arguments_do_not_match_the_placeholders_of_its_message();
void diagnostic_message_in_diagnostics_def_is_malformed();
void diagnostic_format_spec_does_not_fit_the_argument_type();

}  // namespace diag_check

// A DiagId known only at run time (a variable): its arguments are checked when the
// message is made; a mismatch gives a message that says so instead of the diagnostic's.
struct RuntimeDiagId {
  DiagId id;
};
constexpr RuntimeDiagId runtime_diag(DiagId id) { return {id}; }

template <typename... Args>
class CheckedDiagId {
 public:
  consteval CheckedDiagId(DiagId id) : id_(id) {
    switch (diag_check::check<Args...>(id)) {
      case diag_check::Verdict::Fits: break;
      case diag_check::Verdict::Malformed: diag_check::diagnostic_message_in_diagnostics_def_is_malformed(); break;
      case diag_check::Verdict::WrongCount:
        diag_check::diagnostic_arguments_do_not_match_the_placeholders_of_its_message();
        break;
      case diag_check::Verdict::WrongType: diag_check::diagnostic_format_spec_does_not_fit_the_argument_type(); break;
    }
  }
  constexpr CheckedDiagId(RuntimeDiagId runtime)
      : id_(runtime.id), fits_(diag_check::check<Args...>(runtime.id) == diag_check::Verdict::Fits) {}

  constexpr DiagId id() const { return id_; }
  constexpr bool fits() const { return fits_; }

 private:
  DiagId id_;
  bool fits_ = true;
};

// The parameter type of every function that takes a DiagId and its message's
// arguments: Args are deduced from the arguments alone.
template <typename... Args>
using DiagIdFor = CheckedDiagId<std::type_identity_t<Args>...>;

// Says that a runtime id's arguments do not fit its message (an ncc bug).
std::string diag_mismatch_message(DiagId id, size_t given);

template <typename... Args>
std::string diag_message(DiagIdFor<Args...> id, const Args&... args) {
  if (!id.fits()) return diag_mismatch_message(id.id(), sizeof...(Args));
  return fmt::format(fmt::runtime(diag_info(id.id()).message), args...);
}

// Collects diagnostics in the order they are reported; stops accepting errors after
// `error_limit` (0 = no limit) with one NC1019, which error_count() does not count.
class Diagnostics {
 public:
  explicit Diagnostics(uint32_t error_limit = 0) : error_limit_(error_limit) {}

  template <typename... Args>
  Diagnostic* report(DiagIdFor<Args...> id, SourceRange range, const Args&... args) {
    return add({id.id(), diag_info(id.id()).severity, range, diag_message(id, args...), {}});
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
