#include "limits.h"

#include <antlr4-runtime.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "support/utf8.h"

namespace ncc {

namespace {

constexpr size_t kBinaryProbe = 4096;  // the bytes a file is judged binary by

// A control character text does not hold. Tab, the line ends and NUL (tape leader,
// which GOST 20999 Table 2 has the NC ignore) do not count; DEL is above 0x1F.
bool binary_byte(unsigned char c) { return c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\0'; }

// The 8-bit Cyrillic code page whose letters the bytes above 0x7F read best as, by
// the frequency of Russian letters (per mille, а to я); nothing when there are too
// few such bytes or they read as no Russian text in any of them.
std::string_view guess_code_page(std::string_view text) {
  static constexpr std::array<int, 32> kFrequency = {80, 16, 45, 17, 30, 85, 9, 16, 74, 12, 35, 44, 32, 67, 110, 28,
                                                     47, 55, 63, 26, 3,  10, 5, 14, 7,  4,  0,  19, 17, 3,  6,   20};
  // KOI8-R orders its letters by their Latin twins (юабцдефгхийклмнопярстужвьызшэщчъ):
  // the index in а..я of each.
  static constexpr std::array<int, 32> kKoi8 = {30, 0,  1,  22, 4,  5,  20, 3, 21, 8,  9, 10, 11, 12, 13, 14,
                                                15, 31, 16, 17, 18, 19, 6,  2, 28, 27, 7, 24, 29, 25, 23, 26};
  // The letter a byte above 0x7F is in each page (Ё counts as Е), or -1.
  auto cp1251 = [](unsigned char b) { return b >= 0xC0 ? (b - 0xC0) % 32 : b == 0xA8 || b == 0xB8 ? 5 : -1; };
  auto cp866 = [](unsigned char b) {
    if (b < 0xA0) return b - 0x80;                    // А..Я
    if (b < 0xB0) return b - 0xA0;                    // а..п
    if (b >= 0xE0 && b < 0xF0) return b - 0xE0 + 16;  // р..я
    return b == 0xF0 || b == 0xF1 ? 5 : -1;
  };
  auto koi8 = [](unsigned char b) { return b >= 0xC0 ? kKoi8[(b - 0xC0) % 32] : b == 0xA3 || b == 0xB3 ? 5 : -1; };
  struct Candidate {
    std::string_view name;
    int (*letter)(unsigned char);
    long score = 0;
  };
  std::array<Candidate, 3> pages = {{{"CP1251", +cp1251}, {"CP866", +cp866}, {"KOI8-R", +koi8}}};
  size_t count = 0;
  for (unsigned char b : text) {
    if (b < 0x80) continue;
    ++count;
    for (Candidate& c : pages)
      if (int l = c.letter(b); l >= 0) c.score += kFrequency[static_cast<size_t>(l)];
  }
  std::sort(pages.begin(), pages.end(), [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
  // Russian text averages some 55 a letter in its code page, and a dozen letters tell
  // the pages apart; a few bytes (a Latin-1 sign, a fuzzed file) do not.
  constexpr size_t kFewest = 12;
  constexpr long kAverage = 40, kMargin = 5;
  const long n = static_cast<long>(count);
  if (count < kFewest || pages[0].score < kAverage * n || pages[0].score - pages[1].score < kMargin * n) return {};
  return pages[0].name;
}

// The 1-based line and column of byte `at` of the file.
std::pair<uint32_t, uint32_t> position(const SourceFile& source, size_t at) {
  uint32_t lo = 1, hi = source.line_count();
  while (lo < hi) {
    const uint32_t mid = (lo + hi + 1) / 2;
    if (source.line_offset(mid) <= at)
      lo = mid;
    else
      hi = mid - 1;
  }
  return {lo, static_cast<uint32_t>(at - source.line_offset(lo) + 1)};
}

}  // namespace

bool admit_text(const SourceFile& source, uint32_t file, Diagnostics& diags) {
  const std::string_view text = source.text();
  // Binary data: control characters no text holds, in more than 1 byte of 100.
  const std::string_view probe = text.substr(0, kBinaryProbe);
  const auto is_control = [](char c) { return binary_byte(static_cast<unsigned char>(c)); };
  const auto control = static_cast<size_t>(std::count_if(probe.begin(), probe.end(), is_control));
  if (control > 2 && control * 100 > probe.size()) {
    auto [line, col] =
        position(source, static_cast<size_t>(std::find_if(probe.begin(), probe.end(), is_control) - probe.begin()));
    diags.report(DiagId::BinaryFile, SourceRange::point(file, line, col), control, probe.size());
    return false;
  }
  const size_t first = find_invalid_utf8(text);
  if (first == std::string_view::npos) return true;
  // One message: where the first bad byte is, how many more there are, what to do.
  size_t more = 0, lines = 1;
  auto [line, col] = position(source, first);
  uint32_t last_line = line;
  for (size_t i = first + 1; i < text.size();) {
    const Utf8Char c = decode_utf8(text, i);
    if (c.length) {
      i += c.length;
      continue;
    }
    ++more;
    if (uint32_t l = position(source, i).first; l != last_line) ++lines, last_line = l;
    ++i;
  }
  const std::string bytes = more == 1 ? "is 1 more byte" : fmt::format("are {} more bytes", more);
  const std::string others = more == 0    ? std::string()
                             : lines == 1 ? fmt::format(", nor {} on its line", bytes)
                                          : fmt::format(", nor {} on {} lines", bytes, lines);
  const bool utf16 = text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF");  // its byte-order mark
  const std::string_view code = utf16 ? "UTF-16" : guess_code_page(text);
  const std::string looks = utf16          ? std::string("; it begins like UTF-16 text")
                            : code.empty() ? std::string()
                                           : fmt::format("; it reads as Cyrillic text in {}", code);
  diags.report(DiagId::TextEncoding, SourceRange::point(file, line, col), static_cast<unsigned char>(text[first]),
               others, looks, code.empty() ? "CP1251" : code);
  return false;
}

bool block_fits(size_t bytes, SourceRange at, Diagnostics& diags) {
  if (bytes <= kMaxBlockBytes) return true;
  diags.report(DiagId::BlockTooLarge, at, bytes, kMaxBlockBytes);
  return false;
}

bool expression_fits(antlr4::BufferedTokenStream& tokens, const ExpressionTokens& kinds, const TokenRange& range,
                     Diagnostics& diags) {
  auto is = [](const std::vector<size_t>& set, size_t type) {
    return std::find(set.begin(), set.end(), type) != set.end();
  };
  // The first place beyond each limit, by token index; the earliest is reported.
  constexpr size_t kNone = SIZE_MAX;
  size_t deep = kNone, run_at = kNone, beyond = kNone;
  size_t depth = 0, operators = 0;
  size_t run = 0, run_from = 0, run_last = 0;  // signs in a row
  size_t run_to = 0, run_length = 0;           // of the first run beyond the limit
  bool after_operand = false;
  const std::vector<antlr4::Token*>& all = tokens.getTokens();
  for (size_t i = 0; i < all.size(); ++i) {
    if (all[i]->getChannel() != antlr4::Token::DEFAULT_CHANNEL) continue;
    const size_t type = all[i]->getType();
    const bool sign = is(kinds.signs, type) && !after_operand;
    if (sign) {
      if (run++ == 0) run_from = i;
      run_last = i;
    } else {
      if (run > kMaxSignsInARow && run_at == kNone) run_at = run_from, run_to = run_last, run_length = run;
      run = 0;
    }
    if ((is(kinds.signs, type) && after_operand) || is(kinds.operators, type))
      if (++operators == kMaxOperators + 1) beyond = i;
    if (is(kinds.open, type) && ++depth == kMaxNesting + 1 && deep == kNone) deep = i;
    if (is(kinds.close, type) && depth > 0) --depth;
    after_operand = is(kinds.operand_ends, type);
  }
  const size_t first = std::min({deep, run_at, beyond});
  if (first == kNone) return true;
  antlr4::Token* t = all[first];
  if (first == deep)
    diags.report(DiagId::NestingTooDeep, range(t, t), t->getText(), kMaxNesting + 1, kMaxNesting);
  else if (first == run_at)
    diags.report(DiagId::SignsInARow, range(t, all[run_to]), run_length, kMaxSignsInARow);
  else
    diags.report(DiagId::ExpressionTooLong, range(t, t), operators, kMaxOperators);
  return false;
}

bool lex_block(const std::string& text, antlr4::ANTLRInputStream& input, antlr4::Lexer& lexer,
               antlr4::CommonTokenStream& tokens, const ExpressionTokens& kinds, const TokenRange& range,
               Diagnostics& diags) {
  input.load(text);
  lexer.setInputStream(&input);
  tokens.setTokenSource(&lexer);
  tokens.fill();
  return expression_fits(tokens, kinds, range, diags);
}

}  // namespace ncc
