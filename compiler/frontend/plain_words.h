// The fast path every front end shares: a hand-written scanner for the common block,
// made only of address words (`N10 G01 Y3 F200`), which CAM output is nearly
// all of. A front end tries it first and hands any block it declines to its ANTLR
// parser; what it accepts it decodes with the same rules the parser's words go
// through, so both paths give the same IR (tests/fastpath proves it). The dialects
// differ only in the PlainRules they pass.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace ncc {

struct PlainRules {
  std::string_view letters;         // the addresses it takes (capitals); any other is for the parser
  bool blank_after_letter = false;  // blanks may stand between an address and its value
  bool blank_after_sign = false;    // ... and between the sign and the digits
  bool leading_skip = false;        // a '/' may come first (block skip), blanks after it
};

// One address word as written: offsets into the scanned text.
struct PlainWord {
  char letter = 0;
  char sign = 0;                   // 0, '+' or '-'
  bool point = false;              // a decimal point is written
  std::string_view number;         // the unsigned number: "12.5", ".5", "12."
  std::string_view before, after;  // its digits before and after the point
  uint32_t from = 0;               // the address
  uint32_t value_from = 0;         // the sign, or the number
  uint32_t to = 0;                 // one past the number
};

struct PlainBlock {
  bool skip = false;             // a leading '/'
  std::vector<PlainWord> words;  // N, if written, is the first
};

// True if `text` is only blanks and address words of `rules`: each a letter, an
// optional sign and a number (`12`, `12.`, `12.5`, `.5`) that ends at a blank, the
// next address or the end; 'N' only first. Blanks are ' ' and '\t'; CRs may end the text.
[[nodiscard]] bool scan_plain_words(std::string_view text, const PlainRules& rules, PlainBlock& out);

}  // namespace ncc
