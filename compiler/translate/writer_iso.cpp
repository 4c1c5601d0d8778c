// ISO/Fanuc programs, and RS274NGC as LinuxCNC 2.9 reads it: the same words, but
// LinuxCNC reads `O` as an o-word and acts on comments that start with MSG.
#include <cmath>

#include <fmt/format.h>

#include "frontend/iso/settings.h"
#include "writer.h"

namespace ncc::translate {
namespace {

class IsoWriter final : public Writer {
 public:
  IsoWriter(std::unique_ptr<Frontend> target, bool linuxcnc) : Writer(std::move(target)), linuxcnc_(linuxcnc) {}

  std::string_view dialect() const override { return linuxcnc_ ? "linuxcnc" : "iso"; }
  // Fanuc's finest increment (IS-C) is 0.0001 mm; LinuxCNC reads any number, and a
  // CAM program's fifth decimal matters on a 0.3 mm arc.
  double resolution() const override { return linuxcnc_ ? 1e-6 : 1e-4; }

  int rate_decimals(char letter) const override { return letter == 'F' ? 6 : letter == 'S' ? 4 : linuxcnc_ ? 6 : 4; }

  // Fanuc's and LinuxCNC's N holds 0 to 99999: a block number beyond is left out.
  [[nodiscard]] std::optional<std::string> unwritable(const OutWord& w) const override {
    if (w.letter == 'N' && (w.value < 0 || w.value > iso::kMaxBlockNumber))
      return fmt::format("N{}: {} writes N from 0 to {}", decimal(w.value, 0, false), dialect(), iso::kMaxBlockNumber);
    return Writer::unwritable(w);
  }

  void begin(const Header& h) override {
    const std::string text = header_text(h);
    if (linuxcnc_) return comment(text);
    out_ += "%\nO0001 " + inline_comment(text) + "\n";  // the O block's comment is the program's title
  }

  void block(const std::vector<OutWord>& words, std::string_view comment) override {
    std::string line;
    for (const OutWord& w : words) {
      if (!line.empty()) line += ' ';
      line += w.letter;
      line += number(w);
    }
    // LinuxCNC reads lines of kLinuxcncLine characters at most: a longer comment goes
    // on in comment lines of its own, broken at blanks. (A comment takes its
    // parentheses and maybe a mark, and a blank after the words before it.)
    auto words_part = [&](size_t most) { return line.empty() ? 0 : std::min(line.size(), most) + 1; };
    while (linuxcnc_) {
      const size_t marks = inline_comment(comment).size() - comment.size();
      if (words_part(line.size()) + comment.size() + marks <= kLinuxcncLine) break;
      const size_t room = kLinuxcncLine - marks - words_part(kLinuxcncLine - 64);  // 60 characters at least
      size_t cut = comment.rfind(' ', room);
      if (cut == std::string_view::npos || cut == 0) cut = room;
      out_ += (line.empty() ? "" : line + " ") + inline_comment(comment.substr(0, cut)) + "\n";
      line.clear();
      comment.remove_prefix(std::min(comment.size(), cut + (cut < comment.size() && comment[cut] == ' ')));
      if (comment.empty()) return;  // it ended at a blank: no "()" after it
    }
    if (!comment.empty() || words.empty()) {  // an empty message is "()", not an empty line
      if (!line.empty()) line += ' ';
      line += inline_comment(comment);
    }
    out_ += line;
    out_ += '\n';
  }

  size_t longest_line() const override { return linuxcnc_ ? kLinuxcncLine : 0; }

  std::string inline_comment(std::string_view text) const override {
    std::string out = "(";
    // A comment that starts with MSG, DEBUG or PRINT is an instruction to LinuxCNC.
    if (linuxcnc_ && starts_command(text)) out += "- ";
    for (char c : text) out += c == '(' ? '[' : c == ')' ? ']' : c == ';' ? ',' : c;
    return out + ")";
  }

  void end() override {
    if (!linuxcnc_) out_ += "%\n";
  }

  std::optional<double> parabola_code() const override { return linuxcnc_ ? std::optional(5.1) : std::nullopt; }

 private:
  // Fanuc reads a length without a decimal point in thousandths: every length has one.
  std::string number(const OutWord& w) const override {
    switch (w.kind) {
      case Value::Code:  // G5.1: a code with a decimal
        return w.value == std::floor(w.value) ? fmt::format("{:02}", static_cast<int>(w.value)) : exact(w.value, false);
      case Value::Count: return fmt::format("{}", static_cast<long long>(w.value));
      case Value::Speed: return decimal(w.value, rate_decimals(w.letter), false);
      case Value::Feed:
        return decimal(w.value, rate_decimals(w.letter), true);  // a computed feed as it is (inverse time, G95)
      default: return decimal(w.value, linuxcnc_ ? 6 : 4, true);
    }
  }

  static bool starts_command(std::string_view text) {
    std::string head;
    for (char c : text.substr(0, 5)) head += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return head.starts_with("MSG") || head.starts_with("DEBUG") || head.starts_with("PRINT") ||
           head.starts_with("LOG") || head.starts_with("PROBE");
  }

  // rs274 2.9 says "Command too long" from 253 characters (its buffer of 255 holds the
  // newline and the terminator too).
  static constexpr size_t kLinuxcncLine = 252;
  bool linuxcnc_;
};

}  // namespace

std::unique_ptr<Writer> make_iso_writer(std::unique_ptr<Frontend> target, bool linuxcnc) {
  return std::make_unique<IsoWriter>(std::move(target), linuxcnc);
}

}  // namespace ncc::translate
