// The user screen of NC-110 (video frame 8, §5.6): fields a program defines (DEF)
// and shows (OUT) while the screen is on (SCR). A field holds a text or a value of a
// format (table 5.3: its width), shown by the format's mask (table 5.5). The screen
// is a grid of character cells, so a run can print what the operator would see.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ncc::screen {

// DEF's format operand 1..7 (table 5.3's order; the example's 6 for LR and 5 for RE
// agree).
enum class Format : uint8_t { Bool = 1, Byte, Integer, Long, Real, LongReal, Chars };

struct Attributes {
  bool inverse = false;  // R
  int colour = -1;       // A0..A255: 16 × background + text (table 5.4); -1: the screen's
  bool operator==(const Attributes&) const = default;
};

// What a field starts with: a text, or a value of a format.
struct Content {
  bool is_text = false;
  std::string text;
  double value = 0;
};

class UserScreen {
 public:
  static constexpr int kRows = 20;  // DEF's rows 1..20 (the manual's 19 × 78 frame is one short)
  static constexpr int kColumns = 78;
  static constexpr int kFieldColumns = 64;  // DEF's columns 1..64

  bool on() const { return on_; }
  // SCR ON: a clear screen with no field; SCR OFF: the screen goes (its fields stay
  // defined, so they may be defined anew).
  void switch_on();
  void switch_off() { on_ = false; }

  // Each returns "" when done, else why not (the program's error).
  // DEF: field n at row, column, its width from `init` or `format` (table 5.3).
  [[nodiscard]] std::string define(uint32_t field, int row, int column, const std::optional<Content>& init,
                                   std::optional<Format> format, Attributes attributes);
  [[nodiscard]] std::string show(uint32_t field, bool inverse);                 // OUT n, OUT -n
  [[nodiscard]] std::string show_all();                                         // OUT: the fields not shown yet
  [[nodiscard]] std::string show_with(uint32_t field, const Content& content);  // OUT n, value
  // The text of field n, as its prompt (INP with a field number).
  std::optional<std::string> text(uint32_t field) const;

  // The screen, a line a row, blanks at the ends of lines left out.
  std::vector<std::string> lines() const;
  // How field n looks now: its characters, the width of its format; its attributes.
  std::string rendered(uint32_t field) const;
  Attributes attributes(uint32_t field) const { return fields_.at(field).attributes; }
  int row(uint32_t field) const { return fields_.at(field).row; }
  int column(uint32_t field) const { return fields_.at(field).column; }
  // The fields shown since the last call, in order.
  std::vector<uint32_t> take_shown() { return std::exchange(shown_, {}); }

 private:
  struct Field {
    int row = 1, column = 1;
    Format format = Format::Chars;
    int width = 0;  // characters
    Attributes attributes;
    Content content;
    bool shown = false;
  };
  void paint(uint32_t field);  // shows it

  bool on_ = false;
  std::map<uint32_t, Field> fields_;
  std::vector<std::vector<std::string>> cells_;  // rows × columns of UTF-8 characters
  std::vector<uint32_t> shown_;
};

// Table 5.3: a format's width; table 5.5: a value as its mask shows it, `width`
// characters (stars when it does not fit).
int format_width(Format f);
std::string show_value(Format f, double value, int width);
size_t utf8_length(const std::string& s);

}  // namespace ncc::screen
