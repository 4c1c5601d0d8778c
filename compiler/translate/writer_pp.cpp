// Partprogram (pp) programs, as docs/dialects/pp.md reads them: `%n` and its title,
// blocks N10, N20... each beginning with its number, `*` at the physical end.
// Lines hold at most 80 characters: a block runs on to the next N, so a long block
// or comment goes on over the next lines (§2.2.1 d, f).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "frontend/limits.h"
#include "support/utf8.h"
#include "writer.h"

namespace ncc::translate {
namespace {

constexpr size_t kLine = 80;                // §2.2.1 f: characters a line
constexpr int kStep = 10;                   // N10, N20...: the manual's examples
constexpr std::string_view kIndent = "  ";  // a line that goes on with the block above

// The characters of UTF-8 text (a byte that is not UTF-8 counts as one).
size_t chars(std::string_view s) {
  size_t n = 0;
  for (char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

// The first `n` characters of `s` (bytes of whole characters).
size_t prefix_bytes(std::string_view s, size_t n) {
  size_t i = 0;
  while (i < s.size() && n > 0) {
    ++i;
    while (i < s.size() && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) ++i;
    --n;
  }
  return i;
}

class PpWriter final : public Writer {
 public:
  explicit PpWriter(std::unique_ptr<Frontend> target) : Writer(std::move(target)) {}

  std::string_view dialect() const override { return "pp"; }
  // §2.2, the maximum block format: lengths ±5.3.
  double resolution() const override { return 1e-3; }

  void begin(const Header& h) override {
    // §2.3.1: the program number, 1..999999; the comment after it is the title.
    const long number = h.number.empty() ? 0 : std::stol(h.number);  // the source's, where pp can say it
    comment_lines(fmt::format("%{}", number >= 1 && number <= 999999 ? number : 1), text(header_text(h)));
  }

  void block(const std::vector<OutWord>& words, std::string_view comment) override {
    // Operator text alone is a comment line of the block before it (§2.2.1 c, the
    // manual's %35), or of the program start: no block without words.
    if (words.empty()) {
      comment_lines({}, text(comment));
      return;
    }
    std::string line = next_number();
    // §2.2: the standard order of the maximum block format (the order is free).
    std::vector<OutWord> sorted = words;
    std::stable_sort(sorted.begin(), sorted.end(),
                     [&](const OutWord& a, const OutWord& b) { return order(a.letter) < order(b.letter); });
    for (const OutWord& w : sorted) {
      add(line, w.letter + number(w));
      if (w.kind == Value::Code && ends_program(w)) main_ended_ = true;
    }
    comment_lines(std::move(line), text(comment), kIndent);
  }

  // A structured translation's line: its own number or the next, words over lines
  // of 80 characters, its comments ("...") after them.
  void line(std::string_view text) override {
    const size_t quote = text.find('"');
    std::string_view words = text.substr(0, quote);
    while (!words.empty() && words.back() == ' ') words.remove_suffix(1);
    std::string comment;
    for (size_t at = quote; at != std::string_view::npos && at < text.size();) {
      const size_t close = text.find('"', at + 1);
      if (!comment.empty()) comment += ' ';
      comment += text.substr(at + 1, (close == std::string_view::npos ? text.size() : close) - at - 1);
      at = close == std::string_view::npos ? close : text.find('"', close + 1);
    }
    // The skip mark after the number (§2.2.1 i): "/N20 X2" is "N20 /X2".
    std::string moved;
    if (words.starts_with("/N") && words.size() > 2 && std::isdigit(static_cast<unsigned char>(words[2]))) {
      const size_t space = words.find(' ');
      moved = std::string(words.substr(1, space == std::string_view::npos ? words.size() : space - 1)) + " /" +
              std::string(space == std::string_view::npos ? "" : words.substr(space + 1));
      words = moved;
    }
    // Comments alone: comment lines of the block before, as pp reads them back (a
    // number of the writer's own would come back as the source's).
    if (words.empty()) return comment_lines({}, comment);
    std::string line;
    size_t at = 0;
    if (words.starts_with('N') && words.size() > 1 && std::isdigit(static_cast<unsigned char>(words[1]))) {
      at = words.find(' ');
      line = std::string(words.substr(0, at));
      take(std::stoul(line.substr(1)));
    } else {
      line = next_number();
    }
    for (at = at == std::string_view::npos ? words.size() : at; at < words.size();) {
      while (at < words.size() && words[at] == ' ') ++at;
      const size_t end = std::min(words.find(' ', at), words.size());
      if (end > at) {
        const std::string word(words.substr(at, end - at));
        add(line, word);
        main_ended_ |= word[0] == 'M' && word.size() > 1 && std::isdigit(static_cast<unsigned char>(word[1])) &&
                       ends_program({'M', static_cast<double>(std::stoi(word.substr(1))), Value::Code});
      }
      at = end;
    }
    comment_lines(std::move(line), comment, kIndent);
  }

  std::string inline_comment(std::string_view t) const override { return '"' + text(t) + '"'; }

  long fresh_number() override { return std::stol(next_number().substr(1)); }
  void reserve_number(long n) override { take(static_cast<unsigned long>(n)); }
  [[nodiscard]] bool claim_number(long n) override {
    const auto u = static_cast<unsigned long>(n);
    if (u < taken_.size() && taken_[u]) return false;
    take(u);
    return true;
  }

  void end() override {
    if (ended_) return;
    ended_ = true;
    // §2.3.2: the main part ends with M02 or M30, also when the source's run made no
    // end (a program that stops at its last block); `*` is the physical end.
    if (!main_ended_)
      if (auto m = end_code()) block({{'M', static_cast<double>(*m), Value::Code}}, {});
    out_ += "*\n";
  }

 private:
  // A word without dimension takes digits only: no sign, no decimal point (§2.1.3).
  // A length without a point is whole millimetres (§2.1.2 b), so none is needed.
  std::string number(const OutWord& w) const override {
    switch (w.kind) {
      case Value::Code: return fmt::format("{:02}", static_cast<int>(w.value));
      case Value::Count:
      case Value::Speed:
      case Value::Seconds: return decimal(w.value, 0, false);
      default: return decimal(w.value, 3, false);
    }
  }

  bool ends_program(const OutWord& w) const {
    const auto& table = w.letter == 'M' ? tables().m_codes : tables().g_codes;
    auto it = table.find(static_cast<int>(w.value));
    if (it == table.end()) return false;
    for (const FnCall& c : it->second.desc.calls)
      if (c.fn == Fn::ProgramEnd || c.fn == Fn::ProgramEndInformation) return true;
    return false;
  }

  int order(char letter) const {
    const auto& addresses = tables().addresses;
    auto it = addresses.find(letter);
    return it == addresses.end() ? 100 : it->second.order;
  }

  // §2.2.1 d: every block begins with N (8), each number once in the file.
  std::string next_number() {
    while (block_number_ < taken_.size() && taken_[block_number_])
      block_number_ += kStep;  // a structured translation's own
    std::string n = fmt::format("N{}", block_number_);
    take(block_number_);     // a source's number claimed later is not this one
    block_number_ += kStep;  // past 99999999 the program is no longer pp
    return n;
  }

  // One line. A block is read up to kMaxBlockBytes from its N to the next, comment
  // lines included (frontend/limits.h): more of them go to a block of their own,
  // a number alone (legal, "of no practical meaning", §2.2.1 e).
  void put(std::string_view line) {
    if (line.starts_with('N')) {
      open_ = 0;
    } else if (open_ && *open_ + line.size() + 1 > kMaxBlockBytes) {
      const std::string n = next_number();
      out_ += n + '\n';
      open_ = n.size() + 1;
    }
    out_ += line;
    out_ += '\n';
    if (open_) *open_ += line.size() + 1;
  }

  // A word after the others, on the next line when this one is full.
  void add(std::string& line, const std::string& word) {
    if (chars(line) + 1 + chars(word) > kLine) {
      put(line);
      line = std::string(kIndent) + word;
    } else {
      line += ' ';
      line += word;
    }
  }

  // `line` (a block, the program start, or nothing) and the comment, in closed pieces
  // that fill it and the lines after it; `indent` begins each line after it.
  void comment_lines(std::string line, std::string_view comment, std::string_view indent = {}) {
    constexpr size_t kLeast = 12;  // a shorter piece starts a line of its own
    auto has_text = [&] { return line.find_first_not_of(' ') != std::string::npos; };
    auto next_line = [&] {
      put(line);
      line = indent;
    };
    while (!comment.empty()) {
      const size_t used = chars(line) + (has_text() ? 1 : 0) + 2;  // a space, the quotes
      if (has_text() && (used >= kLine || kLine - used < kLeast)) {
        next_line();
        continue;
      }
      size_t take = prefix_bytes(comment, kLine - used);
      if (take < comment.size()) {
        // At the last space that fits, when there is one.
        const size_t space = comment.substr(0, take + 1).rfind(' ');
        if (space != std::string_view::npos && space > 0) take = space;
      }
      if (has_text()) line += ' ';
      line += '"';
      line += comment.substr(0, take);
      line += '"';
      next_line();
      comment.remove_prefix(take);
      while (!comment.empty() && comment.front() == ' ') comment.remove_prefix(1);
    }
    if (has_text()) put(line);
  }

  // §2.2.1 c: a comment holds any character but '"' and the end of a line. Others
  // that would end a line or fail the UTF-8 check are replaced too.
  static std::string text(std::string_view s) {
    std::string t;
    for (size_t i = 0; i < s.size();) {
      const Utf8Char c = decode_utf8(s, i);
      if (!c.length) {
        t += '?';
        ++i;
        continue;
      }
      const uint32_t cp = c.code_point;
      if (cp == '"')
        t += '\'';
      else if (cp < 0x20 || (cp >= 0x7F && cp < 0xA0) || cp == 0x2028 || cp == 0x2029)
        t += ' ';
      else
        t.append(s.substr(i, c.length));
      i += c.length;
    }
    while (!t.empty() && t.back() == ' ') t.pop_back();
    return t;
  }

  uint32_t block_number_ = kStep;
  // Numbers the lines gave themselves: a bit each, up to the highest (1 MB for N10^7).
  std::vector<bool> taken_;
  void take(unsigned long n) {
    if (n >= taken_.size()) taken_.resize(n + 1);
    taken_[n] = true;
  }
  std::optional<size_t> open_;  // the bytes of the block being written (none before the first)
  bool main_ended_ = false;     // a block with M02 or M30 is written
  bool ended_ = false;
};

}  // namespace

std::unique_ptr<Writer> make_pp_writer(std::unique_ptr<Frontend> target) {
  return std::make_unique<PpWriter>(std::move(target));
}

}  // namespace ncc::translate
