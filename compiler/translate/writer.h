// How a program is written in a target dialect: its start and end, block numbers,
// comments, number formats and line length. A translation says what each block
// holds (words by their meaning); the target's Writer says how the block reads.
// One Writer per target dialect (writer_<dialect>.cpp).
#pragma once

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "frontend/frontend.h"
#include "stdlib/profile.h"

namespace ncc::translate {

// What a word's value is: it decides how the value is written.
enum class Value : uint8_t {
  Code,     // a G or M number: G00, M30
  Length,   // a position, an arc centre, a pitch: mm or inch
  Angle,    // a rotary axis: degrees
  Feed,     // F
  Speed,    // S
  Count,    // a whole number: T, D, H, a repeat count
  Seconds,  // a dwell, in the target's dwell unit already
};

// What a translation says of a construct it cannot write as it is.
enum class Finding : uint8_t {
  Refused,      // the target cannot say it: nothing is written
  Dropped,      // a path mode or the like: the path is the same, the way the machine runs it is not
  Rounded,      // a length, to the target's step
  RoundedRate,  // a feed, a speed or a dwell, to the target's decimals (kRateRounding)
};

// How far a feed, a speed or a dwell may move, of itself, rounded to the decimals the
// target writes (a machine keeps its feed no closer): more is another feed, and refused.
inline constexpr double kRateRounding = 1e-2;

// The subject of a rounding warning (NC4098, NC4099): "this length is", "this value
// and 3 more are".
inline std::string rounded_these(std::string_view what, size_t more) {
  return more ? "this " + std::string(what) + " and " + std::to_string(more) + " more are"
              : "this " + std::string(what) + " is";
}

struct OutWord {
  char letter = 0;
  double value = 0;
  Value kind = Value::Length;
  int offset = -1;  // GOST's T of tool and offset digits (§3.3.5): its offset (-1: the one in force)
};

// The program being written: what its leading comment says.
struct Header {
  std::string source;   // the source file, as named on the command line
  std::string dialect;  // the source's dialect
  std::string title;    // the source program's title, if it has one
  bool flattened = false;
  std::string number;  // the source program's number, if it has one ("%0012": "0012")
};

// The leading comment of a translation: "translated from F, dialect D: TITLE"
// (`separator` before the title).
std::string header_text(const Header& h, std::string_view separator = ": ");
// A program's own title, without the header_text() a translation put before it: a
// round trip names only the file it comes from.
std::string own_title(std::string_view title);

class Writer {
 public:
  virtual ~Writer() = default;
  // The dialect written ("linuxcnc" writes RS274NGC as LinuxCNC 2.9 reads it).
  virtual std::string_view dialect() const = 0;
  // The program start: the target's program number and a comment naming the source.
  virtual void begin(const Header& header) = 0;
  // One block: the words in the target's usual order, then the comment (if any).
  virtual void block(const std::vector<OutWord>& words, std::string_view comment = {}) = 0;
  // A block of operator text only.
  void comment(std::string_view text) { block({}, text); }
  // A line the caller wrote in the target's syntax (a structured translation's
  // statements), and text of several lines.
  virtual void line(std::string_view text) {
    out_ += text;
    out_ += '\n';
  }
  void append(std::string_view text) { out_ += text; }
  // A comment after a block's words, as the target reads it: "(text)".
  virtual std::string inline_comment(std::string_view text) const;
  // The target takes no comment after a block's words (NC-110): a comment is a line
  // of its own.
  virtual bool comments_apart() const { return false; }
  // The longest line the target reads (0: any); a block's comments that would make it
  // longer go on lines of their own before it, broken to fit.
  virtual size_t longest_line() const { return 0; }
  // A word's value as the target writes it (its address' format).
  virtual std::string number(const OutWord& w) const;
  // A block number of its own for a structured translation's line (pp: jumps go to
  // block numbers), or 0 where the target numbers no blocks.
  virtual long fresh_number() { return 0; }
  virtual void reserve_number(long) {}  // a number a line will give itself
  // The source's block number n for a line, where no line has it yet (pp: each number
  // once in the file): reserved, true.
  [[nodiscard]] virtual bool claim_number(long) { return true; }
  // The program end (after the block that ends it, if any).
  virtual void end() = 0;
  // The M code a target that must end its program with one writes where the source's
  // run made no end: end of information (M30), as the end of an ISO tape rewinds it,
  // else end of program. ISO has only the first, so a round trip through it keeps it.
  std::optional<int> end_code() const;
  // The G code of a parabola given by its end in X and Y and its control point's
  // offset from the start, I and J (LinuxCNC's quadratic spline G5.1); none where the
  // target has none.
  virtual std::optional<double> parabola_code() const { return std::nullopt; }
  // A program after the first on the medium, which the target runs after it (GOST
  // 20999 §1.9): its start, with its own number and title. False: the target has none.
  [[nodiscard]] virtual bool next_program(std::string_view /*number*/, std::string_view /*title*/) { return false; }
  // The smallest length step the target's numbers write (mm): a position it writes
  // is exact to half of it.
  virtual double resolution() const = 0;
  // Why `w` cannot be written in the target (a value beyond the range of its
  // address, docs/dialects: addresses.tsv), or nothing.
  [[nodiscard]] virtual std::optional<std::string> unwritable(const OutWord& w) const;
  // The decimals the target writes a feed, a speed, a dwell or a count of `letter` with.
  virtual int rate_decimals(char letter) const;
  // Such a value as the target writes it, where that is not its value: rounded to the
  // target's decimals (a CAM program's F369.752387 into NC-110's F of 2). unwritable()
  // takes a feed, a speed or a dwell that moves by at most kRateRounding of itself.
  std::optional<double> rounded_rate(const OutWord& w) const;
  // The target's code tables and conventions, with its machine profile.
  const stdlib::DialectTables& tables() const { return own_tables_ ? *own_tables_ : *target_->rules().tables; }
  // A target ncc does not read yet (LinuxCNC) has code tables and conventions of its own.
  void set_own(stdlib::DialectTables tables, Conventions conventions) {
    own_tables_ = std::move(tables);
    own_conventions_ = std::move(conventions);
  }
  const Conventions& conventions() const { return own_conventions_ ? *own_conventions_ : target_->conventions(); }

  // The text written so far, taken (a caller writes it out as it goes).
  std::string take() { return std::exchange(out_, {}); }
  size_t pending() const { return out_.size(); }

 protected:
  explicit Writer(std::unique_ptr<Frontend> target) : target_(std::move(target)) {}
  // A number with at most `decimals` decimals, trailing zeros dropped; "-0" never.
  static std::string decimal(double v, int decimals, bool point = true);
  std::string out_;

 private:
  std::unique_ptr<Frontend> target_;
  std::optional<stdlib::DialectTables> own_tables_;
  std::optional<Conventions> own_conventions_;
};

// What a writer has written, spilled to a file as it grows: a long program
// translates in bounded memory.
class Spill {
 public:
  Spill(Writer& writer, std::FILE* out) : w_(writer), out_(out) {}
  void grown() {
    if (w_.pending() > (1 << 16)) flush();
  }
  void flush() {
    const std::string text = w_.take();
    if (std::fwrite(text.data(), 1, text.size(), out_) != text.size()) failed = true;
  }
  bool failed = false;

 private:
  Writer& w_;
  std::FILE* out_;
};

// A number as a double reads it back, in fixed notation (no dialect reads an
// exponent), without trailing zeros; with a point when `point`.
std::string exact(double v, bool point);

// The dialects a program can be translated to.
bool is_target(std::string_view dialect);
// The writer of `dialect` (is_target) with the target's profile; nothing when the
// profile's settings for it are invalid (reported).
[[nodiscard]] std::unique_ptr<Writer> make_writer(std::string_view dialect, const stdlib::Profile& profile,
                                                  Diagnostics& diags);

// The writers (writer_<dialect>.cpp).
std::unique_ptr<Writer> make_iso_writer(std::unique_ptr<Frontend> target, bool linuxcnc);
[[nodiscard]] std::unique_ptr<Writer> make_gost_writer(std::unique_ptr<Frontend> target,
                                                       const stdlib::Profile& profile);
std::unique_ptr<Writer> make_pp_writer(std::unique_ptr<Frontend> target);
std::unique_ptr<Writer> make_nc110_writer(std::unique_ptr<Frontend> target);

}  // namespace ncc::translate
