// GOST 20999-83 programs as ncc's gost front end reads them (docs/dialects/gost.md):
// '%' with the title, numbered blocks, and every word as the §9 format descriptor of
// the target's profile describes it.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "frontend/gost/settings.h"
#include "frontend/limits.h"
#include "support/utf8.h"
#include "writer.h"

namespace ncc::translate {
namespace {

class GostWriter final : public Writer {
 public:
  GostWriter(std::unique_ptr<Frontend> target, gost::Settings settings)
      : Writer(std::move(target)), s_(std::move(settings)) {
    // One step for every length: the coarsest of the linear axes' and I J K's. A rotary
    // axis with fewer decimals is rounded again to its own (§9.2).
    int decimals = -1;
    for (char letter : std::string_view("XYZUVWIJK"))
      if (const gost::WordFormat* f = s_.format.word(letter); f && f->dimension)
        decimals = decimals < 0 ? f->frac_digits : std::min(decimals, f->frac_digits);
    resolution_ = std::pow(10.0, -(decimals < 0 ? 3 : decimals));
    if (const gost::WordFormat* n = s_.format.word('N'))
      last_number_ = static_cast<long long>(std::pow(10.0, n->int_digits)) - 1;
  }

  std::string_view dialect() const override { return "gost"; }
  double resolution() const override { return resolution_; }

  void begin(const Header& h) override {
    // §1.4, §1.6: '%' starts the program; a comment on its line is the program's title.
    // Without '%' the program has no title: a comment block would be shown to the
    // operator, and translated again as one.
    begun_ = true;
    if (!s_.format.program_start) return;
    std::string line = "%" + h.number;            // §1.8: up to 8 digits (a name of more is no number)
    append_comment(line, header_text(h, " - "));  // GOST's comment takes no ':'
    out_ += line;
    out_ += '\n';
  }

  // §1.9: the next program starts with its '%'; its numbers and its end are its own.
  [[nodiscard]] bool next_program(std::string_view number, std::string_view title) override {
    if (!s_.format.program_start) return false;
    std::string line = "%" + std::string(number);
    append_comment(line, title);
    out_ += line + '\n';
    ended_ = false;
    next_number_ = 1;
    highest_ = 0;
    return true;
  }

  void block(const std::vector<OutWord>& words, std::string_view comment) override {
    // §2.2: the recommended word order (the address table's rank); G and M keep theirs.
    std::vector<OutWord> sorted = words;
    std::stable_sort(sorted.begin(), sorted.end(),
                     [&](const OutWord& a, const OutWord& b) { return rank(a.letter) < rank(b.letter); });
    std::string line = number_word();
    for (const OutWord& w : sorted) {
      // §2.1: with '.' in the format a tab stands before each word but N.
      if (s_.format.tab)
        line += '\t';
      else if (!line.empty())
        line += ' ';
      line += w.letter;
      line += number(w);
      note(w);
    }
    // A comment too long for one block goes on in the blocks after it; an empty
    // message stays one, "()".
    while (true) {
      const size_t taken = append_comment(line, comment, sorted.empty());
      out_ += line;
      out_ += '\n';
      comment.remove_prefix(taken);
      if (comment.empty() || taken == 0) break;
      line = number_word();
    }
  }

  // A structured translation's line: the first after the start carries N1 (§1.4);
  // with '.' in the format a tab stands before each word (§2.1).
  void line(std::string_view text) override {
    std::string head, body;
    if (begun_ && !numbered_) {
      numbered_ = true;
      if (text.empty() || text[0] != 'N') head = number_word();
    }
    int depth = 0;
    for (char c : text) {
      depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      body += c == ' ' && depth == 0 && s_.format.tab ? '\t' : c;
    }
    if (!head.empty() && !body.empty()) head += s_.format.tab ? '\t' : ' ';
    out_ += head + body + '\n';
    // A number the line has: the end's M02 comes after it.
    const size_t at = text.find_first_of("N:");
    if (at != std::string_view::npos && text.find_first_not_of("/ ") == at) {
      size_t end = at + 1;
      while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
      if (end > at + 1) highest_ = std::max(highest_, std::stoll(std::string(text.substr(at + 1, end - at - 1))));
    }
    // The end of the program: no M02 after it.
    for (size_t m = 0; (m = text.find('M', m)) != std::string_view::npos; ++m) {
      if (std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(m), '(') >
          std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(m), ')'))
        continue;  // in a comment
      if (m > 0 && text[m - 1] != ' ' && text[m - 1] != '\t') continue;
      size_t end = m + 1;
      while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
      if (end > m + 1)
        note({'M', static_cast<double>(std::stoi(std::string(text.substr(m + 1, end - m - 1)))), Value::Code});
    }
  }

  void reserve_number(long n) override { highest_ = std::max(highest_, static_cast<long long>(n)); }

  std::string inline_comment(std::string_view text) const override {
    std::string out;
    append_comment(out, text);
    return out;
  }

  void end() override {
    // §1.9: a program ends with M02 or M30; a run that stopped without either gets one.
    if (ended_) return;
    next_number_ = std::max(next_number_, highest_ + 1);
    if (auto m = end_code()) block({{'M', static_cast<double>(*m), Value::Code}}, {});
  }

 private:
  int rank(char letter) const {
    auto it = tables().addresses.find(letter);
    return it == tables().addresses.end() ? 99 : it->second.order;
  }

  // §1.4: the first block carries its number; the others do while the format's N
  // digits last (numbers rise: a repeated or lower one is NC3007).
  std::string number_word() {
    const gost::WordFormat* f = s_.format.word('N');
    if (!f || next_number_ > last_number_) return {};
    return "N" + digits(*f, static_cast<double>(next_number_++));
  }

  // Words that change what a later word means: the end of the program, the offset
  // number a split T word repeats (§3.3.5).
  void note(const OutWord& w) {
    if (w.letter == 'D' || w.letter == 'H') offset_ = std::llround(w.value);
    if (w.kind != Value::Code) return;
    const auto& codes = w.letter == 'G' ? tables().g_codes : tables().m_codes;
    auto it = codes.find(static_cast<int>(w.value));
    if (it == codes.end()) return;
    for (const FnCall& c : it->second.desc.calls)
      ended_ = ended_ || c.fn == Fn::ProgramEnd || c.fn == Fn::ProgramEndInformation;
  }

  // §9.2: a word the format cannot hold: an address it lacks, more digits than it
  // has, a sign it has no '+' for, decimals it would drop.
  [[nodiscard]] std::optional<std::string> unwritable(const OutWord& w) const override {
    if (w.kind == Value::Code) return std::nullopt;
    const gost::WordFormat* f = s_.format.word(w.letter);
    if (!f)
      return fmt::format("{}{}: the format {} has no {}", w.letter, decimal(w.value, 4, false), s_.format.text,
                         w.letter);
    const int b = rate_decimals(w.letter);
    const double scale = std::pow(10.0, b);
    const double r = std::round(w.value * scale) / scale;
    // A length is rounded to resolution(); a feed, a speed or a dwell by a hundredth
    // of itself at most; a count not at all.
    if (auto rate = rounded_rate(w);
        rate && (w.kind == Value::Count || std::fabs(*rate - w.value) > kRateRounding * std::fabs(w.value)))
      return fmt::format("{}{}: {} writes {} decimals", w.letter, decimal(w.value, 6, false), f->text, b);
    if (w.letter == 'T' && s_.tool_digits > 0) return std::nullopt;  // tool and offset digits: the reader's rule
    const int digits = static_cast<int>(fmt::format("{:.0f}", std::floor(std::fabs(r))).size());
    if (digits > f->int_digits && std::floor(std::fabs(r)) != 0)
      return fmt::format("{}{}: {} holds {} digits before the point", w.letter, decimal(w.value, 4, false), f->text,
                         f->int_digits);
    if (r < 0 && !f->is_signed)
      return fmt::format("{}{}: {} has no sign", w.letter, decimal(w.value, 4, false), f->text);
    return std::nullopt;
  }

  int rate_decimals(char letter) const override {
    const gost::WordFormat* f = s_.format.word(letter);
    return !f ? 3 : f->dimension ? f->frac_digits : 0;
  }

  // §3.1, §9.2: each word as its format says (unwritable says what it cannot hold).
  std::string number(const OutWord& w) const override {
    const gost::WordFormat* f = s_.format.word(w.letter);
    if (!f) return w.kind == Value::Code || w.kind == Value::Count ? whole(w.value) : decimal(w.value, 3, true);
    if (!f->dimension) {
      double v = w.value;
      // §3.3.5: T written as tool digits and offset digits repeats the offset in force.
      if (w.letter == 'T' && s_.tool_digits > 0)
        v = v * std::pow(10.0, s_.offset_digits) + static_cast<double>(w.offset >= 0 ? w.offset : offset_);
      return digits(*f, v);
    }
    const int b = f->frac_digits;
    // §3.1.4, §3.1.5: with DS a point, at most b decimals; a word without one would be an integer.
    if (s_.format.decimal_sign) return decimal(w.value, b, true);
    // §3.1.6: the implied point: the value in units of its last digit, zeros omitted
    // on the side the format says (leading: right-aligned; trailing: left-aligned).
    const double scaled = std::round(std::fabs(w.value) * std::pow(10.0, b));
    std::string d = fmt::format("{:.0f}", scaled);
    const size_t width = static_cast<size_t>(f->int_digits + b);
    if (f->suppress != gost::Suppress::Leading && d.size() < width) d.insert(0, width - d.size(), '0');
    if (f->suppress == gost::Suppress::Trailing)
      while (d.size() > 1 && d.back() == '0') d.pop_back();
    return (w.value < 0 && scaled != 0 ? "-" : "") + d;
  }

  // A non-dimension word (§3.3, §9.2): n digits exactly, or 1 to n with `0n`; G and M
  // are written with all n (G01, M03), which both read.
  static std::string digits(const gost::WordFormat& f, double v) {
    std::string d = whole(v);
    const size_t n = static_cast<size_t>(f.int_digits);
    const bool all = f.suppress == gost::Suppress::None || f.text[0] == 'G' || f.text[0] == 'M';
    if (all && d.size() < n && d[0] != '-') d.insert(0, n - d.size(), '0');
    return d;
  }

  static std::string whole(double v) {
    const double r = std::round(v);
    return fmt::format("{:.0f}", r == 0 ? 0.0 : r);
  }

  // Appends " (text)" as much of it as fits in a block; returns the bytes of `text`
  // taken. §1.5: no '%' or ':' in a comment, and ')' would close it; a control
  // character would end the block or the text. With `empty`, no text is "()".
  static size_t append_comment(std::string& line, std::string_view text, bool empty = false) {
    if (text.empty() && !empty) return 0;
    if (!line.empty()) line += ' ';
    line += '(';
    size_t at = 0;
    while (at < text.size() && line.size() + 8 < kMaxBlockBytes) {
      const Utf8Char c = decode_utf8(text, at);
      const unsigned char byte = static_cast<unsigned char>(text[at]);
      if (!c.length) {
        line += '?';  // not UTF-8 (a file name): the whole file would be refused
        ++at;
        continue;
      }
      switch (byte) {
        case '(': line += '['; break;
        case ')': line += ']'; break;
        case ':': line += '.'; break;
        case '%': line += "pct"; break;
        default:
          if ((byte < 0x20 && byte != '\t') || byte == 0x7F)
            line += ' ';
          else
            line += text.substr(at, c.length);
      }
      at += c.length;
    }
    line += ')';
    return at;
  }

  gost::Settings s_;
  double resolution_ = 1e-3;
  long long next_number_ = 1;
  long long last_number_ = -1;  // no N in the format: no numbers
  long long offset_ = 0;
  bool ended_ = false;
  bool begun_ = false, numbered_ = false;  // the program start written; its first block numbered
  long long highest_ = 0;                  // the highest number of a structured translation's lines
};

}  // namespace

std::unique_ptr<Writer> make_gost_writer(std::unique_ptr<Frontend> target, const stdlib::Profile& profile) {
  // The target front end has read these settings already and reported any problem.
  Diagnostics quiet;
  auto settings = gost::load_settings(profile, quiet);
  if (!settings) return nullptr;
  return std::make_unique<GostWriter>(std::move(target), std::move(*settings));
}

}  // namespace ncc::translate
