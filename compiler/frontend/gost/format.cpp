#include "format.h"

#include <charconv>

#include "support/text.h"

namespace ncc::gost {

namespace {

constexpr std::string_view kDimensionAddresses = "XYZUVWPQRABCIJKFE";
constexpr std::string_view kNonDimensionAddresses = "NGSTDHMLO";

bool all_digits(std::string_view s) {
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return !s.empty();
}

std::string_view strip_leading_zeros(std::string_view s) {
  size_t i = 0;
  while (i < s.size() && s[i] == '0') ++i;
  return s.substr(i);
}

std::string_view strip_trailing_zeros(std::string_view s) {
  size_t n = s.size();
  while (n > 0 && s[n - 1] == '0') --n;
  return s.substr(0, n);
}

// digits x 10^-scale, correctly rounded to the nearest double (from_chars).
double scaled(std::string_view digits, int scale) {
  std::string text = fmt::format("{}e{}", digits.empty() ? "0" : digits, -scale);
  double value = 0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

// The word as written, for messages; a very long one is abbreviated.
std::string written(char letter, const WrittenNumber& n) {
  std::string s(1, letter);
  if (n.has_sign) s += n.negative ? '-' : '+';
  s += n.before;
  if (n.has_point) s += '.' + n.after;
  return abbreviated(s);
}

}  // namespace

std::string_view format_line_of_file(std::string_view text) {
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    bool comment = !line.empty() && line.front() == '(' && line.back() == ')';
    if (!line.empty() && !comment) return line;
    pos = end + 1;
  }
  return {};
}

std::optional<Format> parse_format(std::string_view text, std::vector<FormatProblem>& problems) {
  Format f;
  f.text = std::string(text);
  bool ok = true;
  auto fail = [&](std::string_view item, std::string message) {
    problems.push_back({true, std::string(item), std::move(message)});
    ok = false;
  };
  size_t pos = 0;
  while (pos < text.size()) {
    if (text[pos] == ' ' || text[pos] == '\t') {
      ++pos;
      continue;
    }
    size_t end = text.find_first_of(" \t", pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view item = text.substr(pos, end - pos);
    pos = end;
    bool* flag = item == "%"    ? &f.program_start
                 : item == ":"  ? &f.main_block
                 : item == "/"  ? &f.block_skip
                 : item == "DS" ? &f.decimal_sign
                 : item == "."  ? &f.tab
                                : nullptr;
    if (flag) {
      if (*flag) fail(item, "the item is given twice");
      *flag = true;
    } else if (item == "*") {
      continue;
    } else {
      char letter = item[0];
      bool dim = kDimensionAddresses.find(letter) != std::string_view::npos;
      bool nondim = kNonDimensionAddresses.find(letter) != std::string_view::npos;
      if (!dim && !nondim) {
        fail(item, "not a format item: expected % : / DS . * or an address with its digits");
        continue;
      }
      if (f.words[letter - 'A']) {
        fail(item, fmt::format("address {} is described twice", letter));
        continue;
      }
      WordFormat w;
      w.text = std::string(item);
      w.dimension = dim;
      std::string_view rest = item.substr(1);
      if (!rest.empty() && rest[0] == '+') {
        if (!dim) {
          fail(item, "a non-dimension word has no sign");
          continue;
        }
        w.is_signed = true;
        rest.remove_prefix(1);
      }
      if (!all_digits(rest)) {
        fail(item, "the address must be followed by its digit counts");
        continue;
      }
      auto d = [&](size_t i) { return rest[i] - '0'; };
      if (dim) {
        if (rest.size() == 2) {
          w.int_digits = d(0);
          w.frac_digits = d(1);
          if (w.int_digits + w.frac_digits == 0) {
            fail(item, "a word needs at least one digit");
            continue;
          }
        } else if (rest.size() == 3) {
          if (rest == "000") {
            fail(item, "a word needs at least one digit");
            continue;
          }
          if (d(0) == 0) {  // 0ab: leading zeros may be omitted; 0a0 is read this way too
            w.suppress = Suppress::Leading;
            w.int_digits = d(1);
            w.frac_digits = d(2);
            if (d(2) == 0) problems.push_back({false, std::string(item), fmt::format("{}", d(1))});
          } else if (d(2) == 0) {  // ab0: trailing zeros may be omitted
            w.suppress = Suppress::Trailing;
            w.int_digits = d(0);
            w.frac_digits = d(1);
          } else {
            fail(item, "three digits need a 0 first (leading zeros omitted) or last (trailing zeros omitted)");
            continue;
          }
        } else {
          fail(item, "a dimension or feed word takes two digits (before and after the point) or three");
          continue;
        }
      } else {
        if (rest.size() == 1 && d(0) > 0) {
          w.int_digits = d(0);
        } else if (rest.size() == 2 && d(0) == 0 && d(1) > 0) {
          w.int_digits = d(1);
          w.suppress = Suppress::Leading;
        } else {
          fail(item, "a non-dimension word takes one digit (the digit count) or 0 and the digit count");
          continue;
        }
      }
      f.words[letter - 'A'] = std::move(w);
    }
  }
  if (!ok) return std::nullopt;
  return f;
}

std::optional<double> decode(char letter, const WordFormat& format, const WrittenNumber& n, const DecodeOptions& opts,
                             SourceRange range, Diagnostics& diags) {
  std::string word = written(letter, n);
  std::string digits = n.before + n.after;
  if (digits.empty()) {
    diags.report(DiagId::NoDigits, range, word);
    return std::nullopt;
  }
  if (n.has_sign && !format.is_signed) {
    diags.report(DiagId::SignNotAllowed, range, word,
                 format.dimension
                     ? fmt::format("format {} has no '+', so values are positive and unsigned", format.text)
                     : std::string("it is a non-dimension word"));
    return std::nullopt;
  }
  const int a = format.int_digits;
  const int b = format.frac_digits;
  double value = 0;
  if (!format.dimension) {
    if (n.has_point) {
      diags.report(DiagId::PointNotAllowed, range, word, "a non-dimension word is an integer (GOST 20999 §3.3)");
      return std::nullopt;
    }
    int count = static_cast<int>(digits.size());
    if (format.suppress == Suppress::None && count != a) {
      if (opts.mode == Mode::Lenient && count < a) {
        diags.report(DiagId::DigitCountLenient, range, word, count, format.text, a);
        return scaled(digits, 0);
      }
      diags.report(DiagId::DigitCount, range, word, a, format.text);
      return std::nullopt;
    }
    if (count > a) {
      diags.report(DiagId::TooManyDigits, range, word, count, format.text, a);
      return std::nullopt;
    }
    return scaled(digits, 0);
  }
  if (opts.decimal_sign && (n.has_point || !opts.ds_implied)) {
    // Explicit mode: a point marks the decimal position; a word without one is an
    // integer (§3.1.4). Insignificant zeros do not count (§3.1.5).
    std::string_view ip = strip_leading_zeros(n.before);
    std::string_view fp = strip_trailing_zeros(n.after);
    if (static_cast<int>(ip.size()) > a) {
      diags.report(DiagId::IntegerDigits, range, word, ip.size(), format.text, a);
      return std::nullopt;
    }
    if (static_cast<int>(fp.size()) > b) {
      diags.report(DiagId::FractionDigits, range, word, fp.size(), format.text, b);
      return std::nullopt;
    }
    value = scaled(std::string(ip) + std::string(fp), static_cast<int>(fp.size()));
  } else {
    if (n.has_point) {
      diags.report(DiagId::PointNotAllowed, range, word,
                   "the format descriptor has no DS, so the decimal point is implied (GOST 20999 §3.1.2, §9.2)");
      return std::nullopt;
    }
    const int w = a + b;
    const int count = static_cast<int>(digits.size());
    Suppress suppress = format.suppress;
    if (suppress == Suppress::None && count != w) {
      if (opts.mode == Mode::Lenient && count < w) {
        diags.report(DiagId::DigitCountLenient, range, word, count, format.text, w);
        suppress = Suppress::Leading;
      } else {
        diags.report(DiagId::DigitCount, range, word, w, format.text);
        return std::nullopt;
      }
    }
    if (count > w) {
      diags.report(DiagId::TooManyDigits, range, word, count, format.text, w);
      return std::nullopt;
    }
    // Leading suppression aligns the digits right (the last is the last fraction
    // digit); trailing suppression aligns them left (the first is the first integer digit).
    value = suppress == Suppress::Trailing ? scaled(digits, b - (w - count)) : scaled(digits, b);
  }
  if (n.negative && value != 0) value = -value;
  return value;
}

}  // namespace ncc::gost
