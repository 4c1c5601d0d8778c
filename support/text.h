// How ncc writes numbers and untrusted text, the same way everywhere.
#pragma once

#include <charconv>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ncc {

// The shortest text that reads back as the same double; never "-0".
std::string shortest(double v);
// At most four decimals, trailing zeros removed, never "-0": traces and messages.
std::string four_decimals(double v);
// Text from a file or a bytecode file, safe to print on a terminal: control
// characters become '?'.
std::string printable(std::string_view s);
// `s` for a message: one longer than 40 characters is cut to its first 16 and last
// 8 with "..." between, and says how long it is.
std::string abbreviated(std::string_view s);
// The pieces of `s` between the separators (empty ones too).
std::vector<std::string> split(std::string_view s, char sep);
// `s` without the blanks (space, tab, CR) around it.
std::string_view trim(std::string_view s);
// The number all of `s` is, in std::from_chars' syntax (no blanks, no '+'); nothing
// if it is not one or does not fit T.
template <typename T>
[[nodiscard]] std::optional<T> parse_number(std::string_view s) {
  T v{};
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

}  // namespace ncc
