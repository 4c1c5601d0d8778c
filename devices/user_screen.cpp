#include "user_screen.h"

#include <cmath>

#include <fmt/format.h>

#include "support/numbers.h"

namespace ncc::screen {

namespace {

constexpr const char* kFormatNames[] = {"", "BL", "BY", "IN", "LI", "RE", "LR", "CH"};

bool numeric(Format f) { return f != Format::Chars; }

// The UTF-8 characters of `s`, one a string.
std::vector<std::string> characters(const std::string& s) {
  std::vector<std::string> out;
  for (size_t i = 0; i < s.size(); ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80 || out.empty()) out.emplace_back();
    out.back() += s[i];
  }
  return out;
}

}  // namespace

size_t utf8_length(const std::string& s) {
  size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

// Table 5.3; BY takes three characters, as its mask XXX (the table's 1 cannot show 255).
int format_width(Format f) {
  switch (f) {
    case Format::Bool: return 1;
    case Format::Byte: return 3;
    case Format::Integer: return 6;
    case Format::Long: return 9;
    case Format::Real:
    case Format::LongReal: return 11;
    case Format::Chars: return 0;
  }
  return 0;
}

// Table 5.5's masks: integers as integers, RE and LR with at most four decimals and
// no trailing zeros (figure 5.2 shows 0 as "0"), from the field's first column.
std::string show_value(Format f, double value, int width) {
  std::string s;
  switch (f) {
    case Format::Bool: s = value != 0 ? "1" : "0"; break;
    case Format::Byte:
    case Format::Integer:
    case Format::Long: {
      const auto n = whole_in<int64_t>(std::round(value), INT64_MIN, INT64_MAX);
      if (!n) return std::string(static_cast<size_t>(width), '*');  // more digits than any mask holds
      s = fmt::format("{}", *n);
      break;
    }
    default: {
      s = fmt::format("{:.4f}", value);
      while (s.back() == '0') s.pop_back();
      if (s.back() == '.') s.pop_back();
      if (s == "-0") s = "0";
    }
  }
  // The mask's digits before the point: BY 3, IN and RE/LR 5, LI 8; more show as stars.
  static constexpr size_t kDigits[] = {0, 1, 3, 5, 8, 5, 5, 0};
  const size_t digits = s.find('.') == std::string::npos ? s.size() : s.find('.');
  const size_t sign = s[0] == '-';
  if (!std::isfinite(value) || digits - sign > kDigits[static_cast<int>(f)] || static_cast<int>(s.size()) > width ||
      (f == Format::Byte && value < 0))
    return std::string(static_cast<size_t>(width), '*');
  return s + std::string(static_cast<size_t>(width) - s.size(), ' ');
}

void UserScreen::switch_on() {
  on_ = true;
  fields_.clear();
  cells_.assign(kRows, std::vector<std::string>(kColumns, " "));
}

std::string UserScreen::define(uint32_t field, int row, int column, const std::optional<Content>& init,
                               std::optional<Format> format, Attributes attributes) {
  if (field < 1) return fmt::format("field {} does not exist: fields are numbered from 1", field);
  if (row < 1 || row > kRows) return fmt::format("row {} is not on the screen: rows are 1 to {}", row, kRows);
  if (column < 1 || column > kFieldColumns)
    return fmt::format("column {} is not one a field starts at: 1 to {}", column, kFieldColumns);
  if (on_ && fields_.count(field) && fields_.at(field).shown)
    return fmt::format("field {} is on the screen: switch it off (SCR,OFF) to define it again", field);
  Field f{row, column, Format::Chars, 0, attributes, {}, false};
  if (init) f.content = *init;
  if (init && init->is_text) {
    if (format && *format != Format::Chars)
      return fmt::format("a text does not fit format {} ({}): its format is 7 (CH)", static_cast<int>(*format),
                         kFormatNames[static_cast<int>(*format)]);
    f.width = static_cast<int>(utf8_length(init->text));
  } else if (init) {
    if (format == Format::Chars) return "a number does not fit format 7 (CH): give its own format, 1 to 6";
    f.format = format.value_or(init->value == std::trunc(init->value) ? Format::Integer : Format::LongReal);
    f.width = format_width(f.format);
  } else {
    if (!format || *format == Format::Chars) return "a field without an initial value needs a numeric format, 1 to 6";
    f.format = *format;
    f.width = format_width(f.format);
  }
  if (f.width < 1) return "an empty text gives the field no width";
  if (column + f.width - 1 > kColumns)
    return fmt::format("the field ends at column {}, past the screen's {}", column + f.width - 1, kColumns);
  fields_[field] = f;
  return "";
}

std::string UserScreen::rendered(uint32_t field) const {
  const Field& f = fields_.at(field);
  if (!numeric(f.format)) {
    std::string s = f.content.text;
    for (size_t n = utf8_length(s); n < static_cast<size_t>(f.width); ++n) s += ' ';
    return s;
  }
  return show_value(f.format, f.content.value, f.width);
}

// The grid holds characters only: inverse video and colours are the trace's to record.
void UserScreen::paint(uint32_t field) {
  Field& f = fields_.at(field);
  f.shown = true;
  shown_.push_back(field);
  std::vector<std::string> chars = characters(rendered(field));
  for (size_t i = 0; i < chars.size() && f.column - 1 + static_cast<int>(i) < kColumns; ++i)
    cells_[static_cast<size_t>(f.row - 1)][static_cast<size_t>(f.column - 1) + i] = chars[i];
}

std::string UserScreen::show(uint32_t field, bool inverse) {
  if (!on_) return "the user screen is off: (SCR,ON) first";
  auto it = fields_.find(field);
  if (it == fields_.end()) return fmt::format("field {} is not defined (DEF)", field);
  if (inverse) it->second.attributes.inverse = true;
  paint(field);
  return "";
}

std::string UserScreen::show_all() {
  if (!on_) return "the user screen is off: (SCR,ON) first";
  for (auto& [n, f] : fields_)
    if (!f.shown) paint(n);
  return "";
}

std::string UserScreen::show_with(uint32_t field, const Content& content) {
  if (!on_) return "the user screen is off: (SCR,ON) first";
  auto it = fields_.find(field);
  if (it == fields_.end()) return fmt::format("field {} is not defined (DEF)", field);
  Field& f = it->second;
  if (content.is_text != !numeric(f.format))
    return fmt::format("field {} is of format {} ({}): {}", field, static_cast<int>(f.format),
                       kFormatNames[static_cast<int>(f.format)],
                       content.is_text ? "a number goes there, not a text" : "a text goes there, not a number");
  if (content.is_text && utf8_length(content.text) > static_cast<size_t>(f.width))
    return fmt::format("field {} holds {} characters, not {}", field, f.width, utf8_length(content.text));
  f.content = content;
  paint(field);
  return "";
}

std::optional<std::string> UserScreen::text(uint32_t field) const {
  auto it = fields_.find(field);
  if (it == fields_.end() || numeric(it->second.format)) return std::nullopt;
  return it->second.content.text;
}

std::vector<std::string> UserScreen::lines() const {
  std::vector<std::string> out;
  for (const auto& row : cells_) {
    std::string line;
    for (const std::string& c : row) line += c;
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out.push_back(line);
  }
  return out;
}

}  // namespace ncc::screen
