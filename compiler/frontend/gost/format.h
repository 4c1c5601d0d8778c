// The GOST 20999 §9 format descriptor, e.g.
//   % : / DS N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02 *
// and the decoding of a written number by it (§3.1, §9.2; docs/dialects/gost.md).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "support/diagnostics.h"

namespace ncc::gost {

enum class Suppress : uint8_t { None, Leading, Trailing };

struct WordFormat {
  std::string text;        // "X+053", for messages
  bool dimension = false;  // dimension/feed form: [+]ab or [+]abc
  bool is_signed = false;
  int int_digits = 0;  // dimension: digits before the implied point; non-dimension: digit count
  int frac_digits = 0;
  Suppress suppress = Suppress::None;
};

struct Format {
  std::string text;
  bool program_start = false;  // %
  bool main_block = false;     // :
  bool block_skip = false;     // /
  bool decimal_sign = false;   // DS
  bool tab = false;            // .
  std::array<std::optional<WordFormat>, 26> words;

  const WordFormat* word(char letter) const {
    return letter >= 'A' && letter <= 'Z' && words[letter - 'A'] ? &*words[letter - 'A'] : nullptr;
  }
};

struct FormatProblem {
  bool error = true;
  std::string item;
  std::string message;
};

// Parses a descriptor. Problems are returned, not reported: the caller knows where
// the descriptor came from (a profile key, a .fmt file). `0a0` items read as
// leading suppression with `a` integer digits, with a warning.
[[nodiscard]] std::optional<Format> parse_format(std::string_view text, std::vector<FormatProblem>& problems);
// A .fmt file: lines that are only a parenthesised comment are skipped; the first
// other line is the descriptor.
std::string_view format_line_of_file(std::string_view file_text);

// A number as written after an address, with ignored characters already dropped.
struct WrittenNumber {
  bool has_sign = false;
  bool negative = false;
  std::string before;  // digits before the decimal sign (or all digits)
  bool has_point = false;
  std::string after;  // digits after the decimal sign
};

enum class Mode : uint8_t { Strict, Default, Lenient, Pedantic };

struct DecodeOptions {
  bool decimal_sign = false;  // the format has DS
  bool ds_implied = false;    // ds_integer_rule = implied
  Mode mode = Mode::Default;
};

// Decodes `n` for address `letter` by `format`. Problems are reported at `range`;
// returns the value unless the word is unusable.
[[nodiscard]] std::optional<double> decode(char letter, const WordFormat& format, const WrittenNumber& n,
                                           const DecodeOptions& opts, SourceRange range, Diagnostics& diags);

}  // namespace ncc::gost
