// The NC-110 reader: lines, the leading fields and ISO blocks (§2.4-§2.8).
#include "reader.h"
#include "frontend/limits.h"
#include "support/text.h"
#include "support/utf8.h"

#include <charconv>

namespace ncc::nc110 {

namespace {

constexpr size_t kMaxBlockLength = 128;                    // characters (§2.4.4)
constexpr std::string_view kLowerCase = "abcdlmoprstuvw";  // Table 2.1
constexpr std::string_view kDefinitionLetters = "oadm";    // of GTL definitions only (§2.11.3)

bool blank(char c) { return c == ' ' || c == '\t'; }

// The Latin letter a Cyrillic one looks like, or 0.
char latin_twin(uint32_t cp) {
  static constexpr std::pair<uint32_t, char> kTwins[] = {
      {0x410, 'A'}, {0x412, 'B'}, {0x415, 'E'}, {0x41A, 'K'}, {0x41C, 'M'}, {0x41D, 'H'},
      {0x41E, 'O'}, {0x420, 'P'}, {0x421, 'C'}, {0x422, 'T'}, {0x425, 'X'}, {0x430, 'a'},
      {0x435, 'e'}, {0x43E, 'o'}, {0x440, 'p'}, {0x441, 'c'}, {0x443, 'y'}, {0x445, 'x'}};
  for (auto [c, l] : kTwins)
    if (c == cp) return l;
  return 0;
}

// Where the leading fields end (§2.4.4): '/', "label", N number, '#' or '&', in any
// order here; the parser checks their order.
size_t skip_leading(std::string_view line, size_t i) {
  while (i < line.size()) {
    char c = line[i];
    if (blank(c) || c == '/' || c == '#' || c == '&') {
      ++i;
    } else if (c == '"') {
      size_t close = line.find('"', i + 1);
      i = close == std::string_view::npos ? line.size() : close + 1;
    } else if (c == 'N') {
      size_t j = i + 1;
      while (j < line.size() && blank(line[j])) ++j;
      if (j == line.size() || line[j] < '0' || line[j] > '9') break;
      while (j < line.size() && line[j] >= '0' && line[j] <= '9') ++j;
      i = j;
    } else {
      break;
    }
  }
  return i;
}

// The length of a GTL element's name where a GTL definition starts (`c1 =`), or 0.
size_t gtl_definition(std::string_view line, size_t at) {
  if (at >= line.size() || kGtlElements.find(line[at]) == std::string_view::npos) return 0;
  size_t i = at + 1;
  while (i < line.size() && line[i] >= '0' && line[i] <= '9') ++i;
  size_t end = i;
  while (i < line.size() && blank(line[i])) ++i;
  return end > at + 1 && i < line.size() && line[i] == '=' ? end - at : 0;
}

bool has_equals(std::string_view s) {
  bool quoted = false;
  for (char c : s) {
    if (c == '"') quoted = !quoted;
    if (c == '=' && !quoted) return true;
  }
  return false;
}

}  // namespace

// Syntax errors at their byte column, with the messages the NC-110 calls for.
class Reader::Listener final : public antlr4::BaseErrorListener {
 public:
  explicit Listener(Reader& r) : r_(r) {}

  void syntaxError(antlr4::Recognizer*, antlr4::Token* token, size_t, size_t position, const std::string&,
                   std::exception_ptr) override {
    // The first error of a block is the one to fix; the parser's recovery after it
    // would only report what follows from it.
    if (r_.block_.has_errors) return;
    r_.block_.has_errors = true;
    if (!token || token->getType() == antlr4::Token::EOF) {
      size_t at = token ? token->getStartIndex() : position;
      uint32_t col = r_.byte_col(at);
      r_.diags_.report(DiagId::SyntaxError, {r_.file_, r_.line_no_, col, r_.line_no_, col + 1}, "end of the line");
      return;
    }
    SourceRange range = r_.range(token, token);
    std::string text = r_.text(token, token);
    switch (token->getType()) {
      case Nc110Lexer::OPEN_STRING: r_.diags_.report(DiagId::StringUnterminated, range); return;
      case Nc110Lexer::CYRILLIC: r_.report_cyrillic(range, text); return;
      case Nc110Lexer::INVALID:
        if (text == "(" && r_.second_instruction(range.col - 1)) return;
        if (text == ";") {
          r_.diags_.report(DiagId::CommentInline, range);
        } else {
          unsigned char c = text.empty() ? 0 : static_cast<unsigned char>(text[0]);
          const uint32_t cp = c >= 0x80 ? decode_utf8(text, 0).code_point : c;
          // Typographic quotes come with texts copied from word processors.
          bool quote = cp == 0x201C || cp == 0x201D || cp == 0x201E || cp == 0xAB || cp == 0xBB;
          // ... and dashes with numbers ("X–10").
          bool dash = (cp >= 0x2010 && cp <= 0x2015) || cp == 0x2212;
          size_t length = 0;
          const std::string keyboard = text == "," ? r_.keyboard_form(range.col - 1) : std::string();
          r_.diags_.report(
              DiagId::CharInvalid, range,
              !keyboard.empty() ? fmt::format("',' (\"{0},\" is how the keyboard takes a code; a program writes it in "
                                              "parentheses: ({0},...))",
                                              keyboard)
              : c >= 0x20 && c < 0x7F ? fmt::format("'{}'", text)
              : quote ? fmt::format("'{}' (U+{:04X}, a typographic quote: a text is written in '\"')", text, cp)
              : dash  ? fmt::format("'{}' (U+{:04X}, a typographic dash: a minus is written '-')", text, cp)
                      : describe_char(text, 0, length));
        }
        return;
      case Nc110Lexer::TRAILING:
        if (text[0] == ';')
          r_.diags_.report(DiagId::CommentInline, {range.file, range.line, range.col, range.line, range.col + 1});
        else
          r_.diags_.report(DiagId::OneInstruction, range, fmt::format("words after a three-letter code, '{}'", text));
        return;
      default: {
        if (r_.second_instruction(range.col - 1)) return;
        // "C- X80": a sign without its digits before the token (an OCR's C0).
        std::string_view before = r_.line_.substr(0, range.col - 1);
        while (!before.empty() && before.back() == ' ') before.remove_suffix(1);
        const bool sign_alone = before.size() >= 2 && (before.back() == '-' || before.back() == '+') &&
                                std::isalpha(static_cast<unsigned char>(before[before.size() - 2]));
        r_.diags_.report(
            DiagId::SyntaxError, range,
            sign_alone ? fmt::format("'{}' ('{}' has a sign and no value)", text, before.substr(before.size() - 2))
                       : fmt::format("'{}'", text));
      }
    }
  }

 private:
  Reader& r_;
};

std::string Reader::keyboard_form(size_t comma) const {
  // "DPT, 10, 12, 1000" (§2.15.1.1): a code typed at the keyboard, without parentheses.
  std::string_view before = line_.substr(0, comma);
  while (!before.empty() && before.back() == ' ') before.remove_suffix(1);
  if (before.size() < 3) return {};
  std::string_view code = before.substr(before.size() - 3);
  std::string_view rest = before.substr(0, before.size() - 3);
  while (!rest.empty() && rest.back() == ' ') rest.remove_suffix(1);
  const bool numbered =
      rest.empty() || (rest[0] == 'N' && rest.find_first_not_of("0123456789", 1) == std::string_view::npos);
  return numbered && s_.codes.count(std::string(code)) ? std::string(code) : std::string();
}

bool Reader::second_instruction(size_t at) {
  // §2.5: a block holds one instruction. A syntax error where a second one starts
  // says so: an assignment after other words or after an assignment, a code after
  // words of an ISO block.
  std::string_view rest = line_.substr(at);
  size_t start = std::string_view::npos;
  std::string what;
  if (kind_ == Kind::Assign) {
    size_t eq = line_.find('=', at);
    if (eq == std::string_view::npos || !has_equals(line_.substr(0, eq + 1))) return false;
    // The assignment's target: the word before its '=' (the first assignment's
    // expression may have taken it: `E51 = 5/E35 = FEL(37,1)`).
    const size_t floor = line_.find('=') < eq ? line_.find('=') + 1 : at;
    size_t end = eq;
    while (end > floor && blank(line_[end - 1])) --end;
    start = end;
    while (start > floor && !blank(line_[start - 1]) && line_[start - 1] != '/' && line_[start - 1] != '+' &&
           line_[start - 1] != '-' && line_[start - 1] != '*')
      --start;
    what = has_equals(line_.substr(0, at)) ? "a second assignment" : "an assignment after other words";
  } else if (kind_ == Kind::Iso && !rest.empty() && rest[0] == '(') {
    // An address before the '(' takes an expression, which NC-110 words do not.
    size_t before = line_.find_last_not_of(" \t", at == 0 ? 0 : at - 1);
    if (at > 0 && before != std::string_view::npos && std::isalpha(static_cast<unsigned char>(line_[before]))) {
      size_t close = line_.find(')', at);
      size_t end = close == std::string_view::npos ? line_.size() : close + 1;
      diags_.report(DiagId::ExpressionInWord,
                    {file_, line_no_, static_cast<uint32_t>(before + 1), line_no_, static_cast<uint32_t>(end + 1)},
                    std::string(1, line_[before]));
      return true;
    }
    start = at;
    what = "a three-letter code after other words";
  } else {
    return false;
  }
  size_t end = line_.find_last_not_of(" \t\r") + 1;
  if (kind_ == Kind::Iso && line_.find(')', start) != std::string_view::npos) end = line_.find(')', start) + 1;
  diags_.report(DiagId::OneInstruction,
                {file_, line_no_, static_cast<uint32_t>(start + 1), line_no_, static_cast<uint32_t>(end + 1)},
                fmt::format("{}, '{}'", what, line_.substr(start, end - start)));
  return true;
}

void Reader::report_cyrillic(const SourceRange& range, const std::string& letter) {
  const uint32_t cp = decode_utf8(letter, 0).code_point;
  // A twin only where the Latin letter is one of Table 2.1 (no lower-case y).
  char twin = latin_twin(cp);
  if (twin >= 'a' && twin <= 'z' && kLowerCase.find(twin) == std::string_view::npos) twin = 0;
  if (twin)
    diags_.report(DiagId::Homoglyph, range, fmt::format("'{}' (U+{:04X})", letter, cp), twin);
  else
    diags_.report(DiagId::CharInvalid, range, fmt::format("'{}' (U+{:04X})", letter, cp));
  block_.has_errors = true;
}

Reader::Reader(const Settings& settings, ir::Program& program, const SourceFile& source, uint32_t file,
               Diagnostics& diags, bool fast_path, BlockSink* sink)
    : s_(settings), program_(program), source_(source), file_(file), diags_(diags), fast_path_(fast_path), sink_(sink) {
  listener_ = std::make_unique<Listener>(*this);
  lexer_.removeErrorListeners();
  parser_.removeErrorListeners();
  parser_.addErrorListener(listener_.get());
  parser_.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(antlr4::atn::PredictionMode::SLL);
}

Reader::~Reader() = default;

uint32_t Reader::byte_col(size_t code_point) const {
  size_t i = std::min(code_point, byte_of_.size() - 1);
  return byte_of_[i] + 1;
}

SourceRange Reader::range(antlr4::Token* first, antlr4::Token* last) const {
  uint32_t begin = byte_col(first->getStartIndex());
  uint32_t end = last->getType() == antlr4::Token::EOF ? begin + 1 : byte_col(last->getStopIndex() + 1);
  if (end <= begin) end = begin + 1;
  return {file_, line_no_, begin, line_no_, end};
}

std::string Reader::text(antlr4::Token* first, antlr4::Token* last) const {
  size_t begin = byte_col(first->getStartIndex()) - 1;
  size_t end = byte_col(last->getStopIndex() + 1) - 1;
  return end > begin ? std::string(line_.substr(begin, end - begin)) : std::string();
}

void Reader::run(ir::Unit& unit) {
  unit_ = &unit;
  uint32_t first = 0, last = 0;  // the first and last lines with something on them
  for (uint32_t n = 1; n <= source_.line_count(); ++n) {
    std::string_view l = source_.line(n);
    if (l.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    if (!first) first = n;
    last = n;
  }
  for (uint32_t n = first; n && n <= last && !diags_.limit_reached(); ++n) {
    std::string_view l = source_.line(n);
    while (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    size_t begin = l.find_first_not_of(" \t");
    if (begin == std::string_view::npos) continue;  // a blank line is not a block
    // '%', the ISO tape mark, alone on the first or the last line (§2.4.1, decision 28).
    if (l.substr(begin) == "%" && (n == first || n == last)) continue;
    read_line(l, n);
    if (sink_) sink_->take(program_, *unit_);
  }
  for (const Unsynced& u : unsynced_)
    diags_.report(DiagId::SyncNeeded, u.at, u.code, u.why,
                  u.more ? fmt::format(" (and in {} more block{})", u.more, u.more == 1 ? "" : "s") : "");
}

void Reader::read_line(std::string_view line, uint32_t line_no) {
  line_ = line;
  line_no_ = line_no;
  block_ = ir::Block{};
  block_.range = {file_, line_no, 1, line_no, static_cast<uint32_t>(line.size() + 1)};
  // A line far beyond the 128 characters of a block is not read at all.
  if (!block_fits(line.size(), block_.range, diags_)) {
    block_.has_errors = block_.unread = true;
    return keep_block();
  }
  // Most blocks are address words only: the hand-written scanner reads them, ANTLR the
  // rest (both give the same IR: tests/fastpath).
  if (fast_path_ && line.size() <= kMaxBlockLength && scan_plain(line)) return keep_block();

  // Code points for ANTLR, each with its byte column. The text is UTF-8 (admit_text);
  // were a byte not, U+0001 (INVALID) would stand for it: ANTLR's input throws on one.
  // So does a byte-order mark first on the line, which ANTLR's input would drop,
  // shifting every column after it.
  decoded_.clear();
  byte_of_.clear();
  for (size_t i = 0; i < line.size();) {
    const Utf8Char c = decode_utf8(line, i);
    const size_t length = c.length;
    byte_of_.push_back(static_cast<uint32_t>(i));
    if (length && !(i == 0 && c.code_point == 0xFEFF))
      decoded_.append(line.substr(i, length));
    else
      decoded_ += '\x01';
    i += std::max<size_t>(length, 1);
  }
  byte_of_.push_back(static_cast<uint32_t>(line.size()));
  uint32_t errors = diags_.error_count();
  if (byte_of_.size() - 1 > kMaxBlockLength) {
    uint32_t col = byte_of_[kMaxBlockLength] + 1;
    diags_.report(DiagId::BlockTooLong, {file_, line_no, col, line_no, static_cast<uint32_t>(line.size() + 1)},
                  byte_of_.size() - 1, kMaxBlockLength);
  }

  size_t first = line.find_first_not_of(" \t");
  if (line[first] == ';') {
    // A comment block (§2.5): not shown, not executed; kept for the reader of the IR.
    block_.comments.emplace_back(line.substr(first + 1));
    unit_->blocks.push_back(std::move(block_));
    return;
  }
  size_t body = skip_leading(line, first);
  const Kind kind = body < line.size() && line[body] == '(' ? Kind::Code
                    : gtl_definition(line, body)            ? Kind::Gtl
                    : has_equals(line.substr(body))         ? Kind::Assign
                                                            : Kind::Iso;
  kind_ = kind;

  input_.load(decoded_);
  lexer_.setInputStream(&input_);
  size_t mode = kind == Kind::Iso      ? size_t{Nc110Lexer::DEFAULT_MODE}
                : kind == Kind::Assign ? size_t{Nc110Lexer::ASSIGN}
                : kind == Kind::Gtl    ? size_t{Nc110Lexer::GTL}
                                       : size_t{Nc110Lexer::TLC};
  lexer_.setMode(mode);
  tokens_.setTokenSource(&lexer_);
  // The tokens first: a block beyond the limits of nesting and length is not parsed.
  static const ExpressionTokens kTokens{{Nc110Lexer::LPAREN},
                                        {Nc110Lexer::RPAREN},
                                        {Nc110Lexer::PLUS, Nc110Lexer::MINUS},
                                        {Nc110Lexer::STAR, Nc110Lexer::SLASH},
                                        {Nc110Lexer::NUMBER, Nc110Lexer::EREF, Nc110Lexer::VARREF, Nc110Lexer::NAME,
                                         Nc110Lexer::RPAREN, Nc110Lexer::DIGITS}};
  tokens_.fill();
  if (!expression_fits(
          tokens_, kTokens, [this](antlr4::Token* a, antlr4::Token* b) { return range(a, b); }, diags_)) {
    block_.has_errors = block_.unread = true;
    return keep_block();
  }
  parser_.setTokenStream(&tokens_);
  // A block the grammar rejects keeps its label and number; its body is not read on
  // (the syntax error says what is wrong with it).
  switch (kind) {
    case Kind::Iso: {
      auto* ctx = parser_.isoBlock();
      if (block_.has_errors)
        leading(ctx->leading(), true);
      else
        iso_block(ctx);
      break;
    }
    case Kind::Gtl: {
      auto* ctx = parser_.gtlBlock();
      if (block_.has_errors)
        leading(ctx->leading(), true);
      else
        gtl_block(ctx);
      break;
    }
    case Kind::Assign: {
      auto* ctx = parser_.assignBlock();
      if (block_.has_errors)
        leading(ctx->leading(), true);
      else
        assign_block(ctx);
      break;
    }
    case Kind::Code: {
      auto* ctx = parser_.tlcBlock();
      if (block_.has_errors)
        leading(ctx->leading(), true);
      else
        code_block(ctx);
      break;
    }
  }
  block_.has_errors = block_.has_errors || diags_.error_count() != errors;
  keep_block();
}

void Reader::keep_block() {
  bool empty = block_.words.empty() && block_.stmts.empty() && block_.label.empty() && !block_.number &&
               !block_.skippable && !block_.has_errors;
  if (!empty) unit_->blocks.push_back(std::move(block_));
}

// ---- The leading fields ------------------------------------------------------------

void Reader::leading(Nc110Parser::LeadingContext* ctx, bool has_body) {
  // 1 '/', 2 the label, 3 the block number, 4 '#' or '&' (§2.4.4, §2.16).
  int stage = 0;
  for (auto* field : ctx->field()) {
    antlr4::Token* t = field->getStart();
    SourceRange r = range(t, t);
    auto out_of_order = [&](const char* message) {
      diags_.report(DiagId::LeadingFieldOrder, r, message);
      block_.has_errors = true;
    };
    switch (t->getType()) {
      case Nc110Lexer::SLASH:
        if (stage > 0 || r.col != line_.find_first_not_of(" \t") + 1) {
          out_of_order("the block skip '/' must be the first character of the block");
          break;
        }
        stage = 1;
        block_.skippable = true;
        break;
      case Nc110Lexer::STRING: {
        if (stage >= 2) {
          out_of_order(stage == 2 ? "a block has one label"
                                  : "the label must come before the block number and '#'/'&'");
          break;
        }
        stage = 2;
        std::string label = text(t, t);
        label = label.substr(1, label.size() - 2);
        // 1..6 capitals, digits or Cyrillic capitals (§2.4.4, decision 3).
        size_t count = 0;
        std::string bad;
        for (size_t i = 0; i < label.size();) {
          const auto [cp, decoded] = decode_utf8(label, i);
          const size_t length = std::max<size_t>(decoded, 1);
          bool ok = (cp >= 'A' && cp <= 'Z') || (cp >= '0' && cp <= '9') || (cp >= 0x410 && cp <= 0x42F) || cp == 0x401;
          if (!ok && bad.empty()) bad = label.substr(i, length);
          ++count;
          i += length;
        }
        if (count == 0 || count > 6 || !bad.empty()) {
          std::string why = count == 0  ? "is empty"
                            : count > 6 ? fmt::format("has {} characters; a label has at most 6", count)
                                        : fmt::format("holds '{}': a label is made of capital letters and digits", bad);
          diags_.report(DiagId::LabelInvalid, r, fmt::format("\"{}\"", label), why);
          block_.has_errors = true;
          break;
        }
        block_.label = label;
        break;
      }
      case Nc110Lexer::OPEN_STRING:
        diags_.report(DiagId::StringUnterminated, r);
        block_.has_errors = true;
        stage = std::max(stage, 2);
        break;
      case Nc110Lexer::BLOCK_NUMBER: {
        if (stage >= 3) {
          out_of_order(stage == 3 ? "a block has one block number" : "the block number must come before '#' and '&'");
          break;
        }
        stage = 3;
        std::string digits;
        for (char c : text(t, t))
          if (c >= '0' && c <= '9') digits += c;
        block_number(digits, r);
        break;
      }
      default:  // '#', '&'
        if (stage == 4) {
          out_of_order("'#' and '&' exclude each other, and stand once");
          break;
        }
        stage = 4;
        block_.sync = t->getType() == Nc110Lexer::HASH ? '#' : '&';
        block_.waits_motion = block_.sync == '#';
        if (!has_body) {
          diags_.report(DiagId::LeadingFieldOrder, r,
                        fmt::format("'{}' must be followed by the instruction it synchronises", block_.sync));
          block_.has_errors = true;
        }
        break;
    }
  }
}

// ---- ISO blocks --------------------------------------------------------------------

int32_t Reader::code_index(char letter, int number) {
  const auto& table = letter == 'G' ? s_.tables.g_codes : s_.tables.m_codes;
  auto it = table.find(number);
  return it == table.end() ? -1 : program_code(program_, it->second.desc);
}

void Reader::add_word(char letter, int slot, ir::ExprId value, std::string text, SourceRange r, ir::WordKind kind,
                      int32_t code) {
  ir::Word w;
  w.kind = kind;
  w.slot = static_cast<uint8_t>(slot);
  // An operand of a three-letter code is shown by its slot: #1, X' (contract/word_slots.h).
  w.address = letter == '#' || slot == second_slot(letter) ? slot_name(slot) : std::string(1, letter);
  w.text = std::move(text);
  w.value = value;
  w.code = code;
  w.range = r;
  block_.words.push_back(std::move(w));
}

std::optional<double> Reader::constant(char letter, std::string_view written, bool negative, SourceRange r,
                                       const std::string& shown) {
  auto parsed = read_number(written, r, diags_);
  if (!parsed) return std::nullopt;
  const double v = negative ? -*parsed : *parsed;
  auto entry = s_.tables.addresses.find(letter);
  if (entry == s_.tables.addresses.end() || !entry->second.ranged) return v;
  const stdlib::AddressEntry& a = entry->second;
  // The format's digits (§1.2.6): significant decimals, then the range (§2.7).
  size_t point = written.find('.');
  std::string_view fraction = point == std::string_view::npos ? std::string_view() : written.substr(point + 1);
  while (!fraction.empty() && fraction.back() == '0') fraction.remove_suffix(1);
  if (static_cast<int>(fraction.size()) > a.decimals) {
    if (a.decimals == 0)
      diags_.report(DiagId::WholeNumber, r, shown);
    else {
      // The format as §1.2.6 writes it: X5.4 (the integer digits of the range's bound).
      const auto whole = static_cast<long long>(std::max(std::fabs(a.min), std::fabs(a.max)));
      diags_.report(DiagId::FractionDigits, r, shown, fraction.size(),
                    fmt::format("{}{}.{}", letter, std::to_string(whole).size(), a.decimals), a.decimals);
    }
    return std::nullopt;
  }
  if (v < a.min || v > a.max) {
    diags_.report(DiagId::ValueRange, r, shown, std::string(1, letter), shortest(a.min), shortest(a.max));
    return std::nullopt;
  }
  return v;
}

void Reader::block_number(std::string_view digits, SourceRange r) {
  if (digits.size() > 4) {
    diags_.report(DiagId::TooManyDigits, r, fmt::format("N{}", digits), digits.size(), "N4", 4);
    block_.has_errors = true;
    return;
  }
  block_.number = parse_number<uint32_t>(digits).value_or(0);  // at most 4 digits
  ir::Word w;
  w.kind = ir::WordKind::BlockNumber;
  w.slot = static_cast<uint8_t>(letter_slot('N'));
  w.address = "N";
  w.text = digits;
  w.value = program_.number(*block_.number, r);
  w.range = r;
  block_.words.push_back(std::move(w));
}

void Reader::iso_block(Nc110Parser::IsoBlockContext* ctx) {
  leading(ctx->leading(), !ctx->isoWord().empty());
  last_operand_.clear();
  for (auto* w : ctx->isoWord()) {
    if (auto* a = dynamic_cast<Nc110Parser::AddressWordContext*>(w))
      address_word(a);
    else if (auto* t = dynamic_cast<Nc110Parser::ToolWordContext*>(w))
      tool_word(t);
    else if (auto* e = dynamic_cast<Nc110Parser::ResultWordContext*>(w))
      result_word(e);
  }
  finish_iso_block();
}

// `[/] [N<digits>] {<letter> [sign] <number>}`, blanks anywhere between the parts: the
// common ISO block. Labels, '#'/'&', E parameters, T, lower case, a letter without
// its value, anything else is for the parser; nothing is read before the whole line
// is known plain.
bool Reader::scan_plain(std::string_view line) {
  static constexpr PlainRules kRules{"ABCDFGHIJKLMNOPQRSUVWXYZ", true, true, true};
  if (!scan_plain_words(line, kRules, plain_)) return false;
  if (!plain_.words.empty() && plain_.words.front().letter == 'N' &&
      (plain_.words.front().sign || plain_.words.front().point))
    return false;  // a block number is digits
  const uint32_t errors = diags_.error_count();
  block_.skippable = plain_.skip;
  last_operand_.clear();
  block_.words.reserve(plain_.words.size());  // the block keeps them: no spare room
  for (const PlainWord& p : plain_.words) {
    const SourceRange r{file_, line_no_, p.from + 1, line_no_, p.to + 1};
    if (p.letter == 'N') {
      block_number(p.before, r);
      continue;
    }
    WordValue v{p.sign, p.number, {}, std::string(line.substr(p.value_from, p.to - p.value_from))};
    address_word(p.letter, &v, r);
  }
  finish_iso_block();
  block_.has_errors = block_.has_errors || diags_.error_count() != errors;
  return true;
}

void Reader::finish_iso_block() {
  check_iso_block();
  bool action = false;
  for (const ir::Word& w : block_.words)
    action = action || w.kind == ir::WordKind::Code || w.kind == ir::WordKind::Parameter;
  if (action) block_.stmts.push_back({ir::StmtKind::Machine, block_.range});
}

void Reader::address_word(Nc110Parser::AddressWordContext* ctx) {
  auto* v = ctx->wordValue();
  if (!v) return address_word(ctx->LETTER()->getText()[0], nullptr, range(ctx));
  WordValue value;
  value.sign = !v->sign() ? 0 : v->sign()->MINUS() ? '-' : '+';
  const std::string number = v->NUMBER() ? v->NUMBER()->getText() : std::string();
  const std::string eref = v->EREF() ? v->EREF()->getText() : std::string();
  value.number = number;
  value.eref = eref;
  value.written = text(v->getStart(), v->getStop());
  address_word(ctx->LETTER()->getText()[0], &value, range(ctx));
}

void Reader::address_word(char letter, const WordValue* v, SourceRange r) {
  const std::string written = v ? v->written : std::string();
  const std::string shown = letter + written;
  auto fail = [&]<typename... Args>(DiagIdFor<Args...> id, const Args&... args) {
    diags_.report(id, r, args...);
    block_.has_errors = true;
  };
  if (letter >= 'a' && letter <= 'z') {
    if (kLowerCase.find(letter) == std::string_view::npos)
      return fail(DiagId::AddressUnknown, fmt::format("lower-case '{}'", letter));
    if (kDefinitionLetters.find(letter) != std::string_view::npos)
      return fail(DiagId::GtlWord, shown, letter == 'o' ? ": an origin is defined as o1 = X.. Y.. a.." : "");
  }
  if (letter == 's' && !(v && v->eref.empty() && !v->sign && v->number == "2"))
    return fail(DiagId::GtlSyntax, "s2 takes the second solution; the first is taken without s (§2.8.6)");
  if (letter == 'N')
    return fail(DiagId::LeadingFieldOrder, "the block number N comes first in the block, with its digits");
  if (letter == 'E') return fail(DiagId::ParameterNumber, s_.e_count - 1);
  auto entry = s_.tables.addresses.find(letter);
  if (entry == s_.tables.addresses.end() || entry->second.word_class == stdlib::WordClass::Undefined)
    return fail(DiagId::AddressUnknown, fmt::format("'{}'", letter));
  const stdlib::AddressEntry& a = entry->second;

  // §2.8: the G words after the block number, before any operand.
  if (letter == 'G' && !last_operand_.empty()) fail(DiagId::GAfterOperand, shown, last_operand_);
  if (letter != 'G') last_operand_ = shown;
  const bool negative = v && v->sign == '-';
  if (v && !v->eref.empty()) {
    if (v->sign) return fail(DiagId::SignedParameter, shown);
    auto index = parameter(std::string(v->eref), r);
    if (!index) return;
    std::vector<std::string> allowed = a.params;
    if (!check_class(*index, allowed, r, std::string(1, letter))) return;
    ir::ExprId value = parameter_expr(*index, r);
    if (letter == 'G' || letter == 'M') {
      // A code given at run time (§2.4.5: "G programmed implicitly by an E parameter").
      add_word(letter, letter_slot(letter), value, written, r, ir::WordKind::Code, ir::kDynamicCode);
      return;
    }
    int slot = letter_slot(letter);
    if (letter == 'R')
      for (const ir::Word& w : block_.words)
        if (w.address == "R") slot = second_slot('R');
    add_word(letter, slot, value, written, r);
    return;
  }
  // A constant, or nothing: zero for G, the axes, I J K and R (§2.4.3, decision 4).
  bool zero_allowed =
      letter == 'G' || a.word_class == stdlib::WordClass::Dimension || letter == 'I' || letter == 'J' || letter == 'K';
  if (!v && !zero_allowed) return fail(DiagId::ValueMissing, shown);
  std::string number_text = v ? std::string(v->number) : "0";
  if (letter == 'G' || letter == 'M') {
    if (v && v->sign) return fail(DiagId::SignNotAllowed, shown, "a code has no sign");
    std::string_view digits = number_text;
    if (digits.find('.') != std::string_view::npos) return fail(DiagId::WholeNumber, shown);
    if (digits.size() > 2) return fail(DiagId::TooManyDigits, shown, digits.size(), std::string(1, letter) + "2", 2);
    const int number = parse_number<int>(digits).value_or(0);  // at most 2 digits
    int32_t code = code_index(letter, number);
    if (code < 0 && letter == 'G') return fail(DiagId::GCodeUndefined, fmt::format("G{:02}", number));
    if (code < 0) return fail(DiagId::MCodeUndefined, fmt::format("M{:02}", number));
    add_word(letter, letter_slot(letter), program_.number(number, r), v ? written : "", r, ir::WordKind::Code, code);
    return;
  }
  auto value = constant(letter, number_text, negative, r, shown);
  if (!value) {
    block_.has_errors = true;
    return;
  }
  int slot = letter_slot(letter);
  if (letter == 'R')
    for (const ir::Word& w : block_.words)
      if (w.address == "R") slot = second_slot('R');
  add_word(letter, slot, program_.number(*value, r), written, r);
}

void Reader::tool_word(Nc110Parser::ToolWordContext* ctx) {
  // T tool.corrector: two integers, each a constant or an IN parameter (§2.7.7,
  // Table 2.9 `TE14.E15`); T6 is corrector 0, T.5 tool 0 (decision 11).
  SourceRange r = range(ctx);
  std::string written;
  for (char c : ctx->TOOL()->getText().substr(1))
    if (!blank(c)) written += c;
  const std::string shown = "T" + written;
  if (written.empty() || written == ".") {
    diags_.report(DiagId::ValueMissing, r, "T");
    block_.has_errors = true;
    return;
  }
  size_t point = written.find('.');
  std::string parts[2] = {written.substr(0, point), point == std::string::npos ? "" : written.substr(point + 1)};
  ir::ExprId values[2];
  for (int i = 0; i < 2; ++i) {
    const std::string& part = parts[i];
    if (!part.empty() && part[0] == 'E') {
      auto index = parameter(part, r);
      if (!index || !check_class(*index, {"IN"}, r, "T")) return;
      values[i] = parameter_expr(*index, r);
    } else if (part.size() > 4) {
      diags_.report(DiagId::TooManyDigits, r, shown, part.size(), "T4.4", 4);
      block_.has_errors = true;
      return;
    } else {
      values[i] = program_.number(part.empty() ? 0 : parse_number<int>(part).value_or(0), r);  // at most 4 digits
    }
  }
  last_operand_ = shown;
  add_word('T', letter_slot('T'), values[0], parts[0].empty() ? "0" : parts[0], r);
  add_word('T', second_slot('T'), values[1], parts[1].empty() ? "0" : parts[1], r);
}

void Reader::result_word(Nc110Parser::ResultWordContext* ctx) {
  // `G72 Z200 X50 E32`: the first E parameter the results go to (§1.2.33).
  SourceRange r = range(ctx);
  auto index = parameter(ctx->EREF()->getText(), r);
  if (!index) {
    block_.has_errors = true;
    return;
  }
  std::string written = ctx->EREF()->getText();
  written.erase(std::remove_if(written.begin(), written.end(), blank), written.end());
  last_operand_ = written;
  add_word('E', letter_slot('E'), program_.number(*index, r), written.substr(1), r);
}

void Reader::check_iso_block() {
  // What the measuring cycles need, and what only they may have (§2.8.12).
  const ir::Word* measure = nullptr;
  const ir::Word* result = nullptr;
  const ir::Word* radius = nullptr;
  int axes = 0;
  for (const ir::Word& w : block_.words) {
    if (w.kind == ir::WordKind::Code && w.code >= 0) {
      for (const FnCall& call : program_.semantics.codes[w.code].calls)
        if (call.fn == Fn::MeasurePoint || call.fn == Fn::MeasureHole || call.fn == Fn::MeasureDeviation) measure = &w;
    }
    if (w.kind != ir::WordKind::Parameter) continue;
    if (w.address == "E") result = &w;
    if (w.address == "r") radius = &w;
    if (w.address.size() == 1 && s_.conventions.axes.find(w.address[0]) != std::string::npos)
      ++axes;
    else if (w.address.size() == 1 && kAxisLetters.find(w.address[0]) != std::string_view::npos &&
             s_.conventions.axes.find(w.address[0]) == std::string::npos)
      diags_.report(DiagId::AxisAbsent, w.range, w.address, s_.conventions.axes + " (machine profile)");
  }
  auto fail = [&](SourceRange r, const std::string& message) {
    diags_.report(DiagId::ResultWord, r, message);
    block_.has_errors = true;
  };
  const bool hole = measure && measure->address == "G" && program_.semantics.codes[measure->code].name == "G73";
  if (result && !measure)
    fail(result->range, "an E parameter alone names where G72, G73 or G74 store what they measure");
  if (measure && !result)
    fail(measure->range, fmt::format("{} needs the E parameter its results go to, e.g. E40",
                                     program_.semantics.codes[measure->code].name));
  // r beside a measuring code other than G73 is a fillet in a block that measures.
  if (radius && measure && !hole)
    fail(radius->range, fmt::format("r is the nominal radius of the hole G73 measures; {} takes none",
                                    program_.semantics.codes[measure->code].name));
  if (hole && !radius) {
    bool upper = false;
    for (const ir::Word& w : block_.words) upper = upper || w.address == "R";
    fail(measure->range, upper ? "G73 needs the nominal radius of the hole in the lower-case r; R is a cycle's level"
                               : "G73 needs the nominal radius of the hole in r");
  }
  if (measure && result) {
    const std::string name = program_.semantics.codes[measure->code].name;
    if (!hole && (axes < 1 || axes > 3))
      fail(measure->range, fmt::format("{} measures 1 to 3 axes; this block has {}", name, axes));
    uint32_t count = hole ? 3 : static_cast<uint32_t>(std::max(axes, 1));
    const uint32_t first = whole_in<uint32_t>(program_.exprs[result->value].number, 0, s_.e_count - 1)
                               .value_or(0);  // result_word() checked it
    uint32_t last = first + count - 1;
    if (last >= s_.e_count) {
      diags_.report(DiagId::ParameterRange, result->range, fmt::format("E{}", last), s_.e_count - 1);
      block_.has_errors = true;
    }
    for (uint32_t e = first; e <= last && e < s_.e_count; ++e)
      if (!check_class(e, {"LR"}, result->range, fmt::format("the result of {}", name))) break;
    if (measured_.size() <= last) measured_.resize(last + 1);
    for (uint32_t e = first; e <= last; ++e) measured_[e] = true;
    // Where each axis' value goes: E<first> for the axis written first (§1.2.33:
    // `G 72 Z200 X50 E32` stores Z in E32, X in E33), at the axis' second slot.
    if (!hole) {
      uint32_t next = first;
      std::vector<ir::Word> destinations;
      for (const ir::Word& w : block_.words)
        if (w.kind == ir::WordKind::Parameter && w.address.size() == 1 &&
            s_.conventions.axes.find(w.address[0]) != std::string::npos && w.slot == letter_slot(w.address[0])) {
          ir::Word d = w;
          d.slot = static_cast<uint8_t>(second_slot(w.address[0]));
          d.address = slot_name(d.slot);
          d.text = fmt::format("E{}", next);
          d.value = program_.number(next++, w.range);
          d.derived = true;
          destinations.push_back(d);
        }
      for (ir::Word& d : destinations) block_.words.push_back(std::move(d));
    }
  }
  if (axes > 8) {  // §2.8.1.1: at most 8 axes; reported at the ninth
    int seen = 0;
    for (const ir::Word& w : block_.words)
      if (w.kind == ir::WordKind::Parameter && w.address.size() == 1 &&
          s_.conventions.axes.find(w.address[0]) != std::string::npos && ++seen == 9)
        diags_.report(DiagId::TooManyWords, w.range, axes, "axis", 8);
    block_.has_errors = true;
  }
}

}  // namespace ncc::nc110
