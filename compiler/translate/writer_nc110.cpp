// NC-110 programs as ncc's nc110 front end reads them (docs/dialects/nc110.md,
// "Reading a program"): no header line and no block numbers (both optional), G words
// first, each number in its address' format, and comments as blocks of their own.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "support/utf8.h"
#include "writer.h"

namespace ncc::translate {
namespace {

constexpr size_t kLineLength = 128;  // characters a line, a comment's ';' included (§2.4.4)

class Nc110Writer final : public Writer {
 public:
  explicit Nc110Writer(std::unique_ptr<Frontend> target)
      : Writer(std::move(target)), resolution_(std::pow(10.0, -decimals('X'))) {}

  std::string_view dialect() const override { return "nc110"; }
  double resolution() const override { return resolution_; }

  // The manual gives a program no header or name line (its name is the file's, §2.13.2.2);
  // a '%' tape mark would only be skipped.
  void begin(const Header& h) override { comment(header_text(h)); }

  void block(const std::vector<OutWord>& words, std::string_view comment) override {
    // G before every other word (§2.8; `order` in addresses.tsv), the rest as given.
    std::vector<OutWord> ordered(words);
    std::stable_sort(ordered.begin(), ordered.end(),
                     [&](const OutWord& a, const OutWord& b) { return order(a.letter) < order(b.letter); });
    std::string spaced, packed;
    for (const OutWord& w : ordered) {
      const std::string word = w.letter + number(w);
      if (!spaced.empty()) spaced += ' ';
      spaced += word;
      packed += word;
    }
    // Blanks between words are optional (`/N100G00X100`): a block too long drops them.
    if (!ordered.empty()) {
      out_ += spaced.size() <= kLineLength ? spaced : packed;
      out_ += '\n';
    }
    // §2.5: a comment is a block of its own; a ';' after words is an error (decision 5).
    if (!comment.empty() || ordered.empty()) comment_lines(comment);
  }

  void end() override {}

  bool comments_apart() const override { return true; }

  // §2.4.3: a number is written as read, a decimal point only before decimals (X100 is
  // 100 mm); G and M with two digits (§2.8, §2.7.8); T is tool.corrector (decision
  // 11): a whole number is the tool with corrector 0.
  std::string number(const OutWord& w) const override {
    switch (w.kind) {
      case Value::Code: return fmt::format("{:02}", static_cast<int>(w.value));
      case Value::Count:  // T tool.corrector where the corrector is given
        return w.letter == 'T' && w.offset >= 0 ? fmt::format("{}.{}", static_cast<long long>(w.value), w.offset)
                                                : fmt::format("{}", static_cast<long long>(w.value));
      default: return decimal(w.value, decimals(w.letter), false);
    }
  }

 private:
  // The decimals of the address' format (§1.2.6: axes, I J K 5.4, F and S 5.2), from its
  // range in addresses.tsv; lengths get 4 where it has none.
  int decimals(char letter) const {
    auto a = tables().addresses.find(letter);
    return a != tables().addresses.end() && a->second.ranged ? a->second.decimals : 4;
  }
  int order(char letter) const {
    auto a = tables().addresses.find(letter);
    return a != tables().addresses.end() ? a->second.order : 2;
  }

  // Lines of "; text": a ';' first makes the whole line a comment (§2.5), so nothing in
  // the text is read as a code, whatever it holds ('(', three capitals, '%', '='). A
  // control character becomes a blank; long text goes on over several lines.
  void comment_lines(std::string_view text) {
    std::string clean;
    for (size_t i = 0; i < text.size();) {
      const Utf8Char c = decode_utf8(text, i);
      if (!c.length) {
        clean += '?';  // not UTF-8: the file would be refused whole (NC1035)
        ++i;
        continue;
      }
      const bool control = c.code_point < 0x20 || (c.code_point >= 0x7F && c.code_point < 0xA0);
      clean += control ? std::string_view(" ") : text.substr(i, c.length);
      i += c.length;
    }
    const size_t first = clean.find_first_not_of(' ');
    clean = first == std::string::npos ? std::string() : clean.substr(first, clean.find_last_not_of(' ') - first + 1);
    constexpr size_t kText = kLineLength - 2;  // after "; "
    size_t at = 0;
    do {
      // As many characters as fit, cut at the last blank if the text goes on.
      size_t end = at, chars = 0, blank = std::string::npos;
      while (end < clean.size() && chars < kText) {
        if (clean[end] == ' ') blank = end;
        end += std::max<size_t>(decode_utf8(clean, end).length, 1);
        ++chars;
      }
      if (end < clean.size() && clean[end] != ' ' && blank != std::string::npos && blank > at) end = blank;
      const std::string_view line = std::string_view(clean).substr(at, end - at);
      out_ += line.empty() ? ";" : fmt::format("; {}", line.substr(0, line.find_last_not_of(' ') + 1));
      out_ += '\n';
      at = end;
      while (at < clean.size() && clean[at] == ' ') ++at;
    } while (at < clean.size());
  }

  double resolution_;
};

}  // namespace

std::unique_ptr<Writer> make_nc110_writer(std::unique_ptr<Frontend> target) {
  return std::make_unique<Nc110Writer>(std::move(target));
}

}  // namespace ncc::translate
