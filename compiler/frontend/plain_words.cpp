#include "plain_words.h"

namespace ncc {

namespace {

bool blank(char c) { return c == ' ' || c == '\t'; }
bool digit(char c) { return c >= '0' && c <= '9'; }
bool capital(char c) { return c >= 'A' && c <= 'Z'; }

}  // namespace

bool scan_plain_words(std::string_view t, const PlainRules& rules, PlainBlock& out) {
  out.skip = false;
  out.words.clear();
  // A CR ending the text is what is left of a CRLF line end; any other is the
  // dialect's to judge (a line end in pp, an error in NC-110): the parser's.
  size_t n = t.size();
  while (n > 0 && t[n - 1] == '\r') --n;
  size_t i = 0;
  auto blanks = [&] {
    while (i < n && blank(t[i])) ++i;
  };
  blanks();
  if (rules.leading_skip && i < n && t[i] == '/') {
    out.skip = true;
    ++i;
  }
  while (true) {
    blanks();
    if (i == n) return true;
    PlainWord w;
    w.letter = t[i];
    if (!capital(w.letter) || rules.letters.find(w.letter) == std::string_view::npos) return false;
    if (w.letter == 'N' && !out.words.empty()) return false;
    w.from = static_cast<uint32_t>(i++);
    if (rules.blank_after_letter) blanks();
    w.value_from = static_cast<uint32_t>(i);
    if (i < n && (t[i] == '+' || t[i] == '-')) {
      w.sign = t[i++];
      if (rules.blank_after_sign) blanks();
    }
    const size_t number = i;
    while (i < n && digit(t[i])) ++i;
    w.before = t.substr(number, i - number);
    if (i < n && t[i] == '.') {
      w.point = true;
      const size_t fraction = ++i;
      while (i < n && digit(t[i])) ++i;
      w.after = t.substr(fraction, i - fraction);
    }
    if (w.before.empty() && w.after.empty()) return false;
    // A number ends at a blank, the next address or the end: `X1.2.3` is for the parser.
    if (i < n && !blank(t[i]) && !capital(t[i])) return false;
    w.number = t.substr(number, i - number);
    w.to = static_cast<uint32_t>(i);
    out.words.push_back(w);
  }
}

}  // namespace ncc
