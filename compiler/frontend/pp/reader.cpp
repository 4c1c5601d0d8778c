#include "reader.h"

#include <charconv>
#include <set>

#include "frontend/frontend.h"
#include "frontend/limits.h"
#include "support/text.h"

namespace ncc::pp {

namespace {

constexpr size_t kLineLimit = 80;     // §2.2.1 f
constexpr uint32_t kParameters = 96;  // R0..R95
constexpr size_t kSubprograms = 99;   // §2.3.3

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view trim_left(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  return s;
}

// A value as written: [sign] digits [. digits], or [sign] R<n>.
struct Written {
  bool has_sign = false, negative = false, param = false, point = false;
  std::string before, after;  // digits around the point; the parameter number
};

// The word slot of an address: its letter's, or pp's link '&'.
int slot_of(char letter) { return letter == '&' ? kLinkSlot : letter_slot(letter); }

Written parse_written(std::string_view v) {
  Written w;
  if (!v.empty() && (v[0] == '+' || v[0] == '-')) {
    w.has_sign = true;
    w.negative = v[0] == '-';
    v.remove_prefix(1);
  }
  if (!v.empty() && v[0] == 'R') {
    w.param = true;
    w.before = std::string(v.substr(1));
    return w;
  }
  size_t point = v.find('.');
  w.point = point != std::string_view::npos;
  w.before = std::string(v.substr(0, point));
  if (w.point) w.after = std::string(v.substr(point + 1));
  return w;
}

size_t significant_integer_digits(const std::string& digits) {
  size_t first = digits.find_first_not_of('0');
  return first == std::string::npos ? 0 : digits.size() - first;
}

size_t significant_fraction_digits(const std::string& digits) {
  size_t last = digits.find_last_not_of('0');
  return last == std::string::npos ? 0 : last + 1;
}

}  // namespace

std::string Reader::macro_name(uint32_t number) { return fmt::format("L{:04}", number); }

Reader::Reader(const Settings& settings, ir::Program& program, const SourceFile& source, uint32_t file,
               Diagnostics& diags, Spaces& spaces, std::optional<uint32_t> macro, bool fast_path, BlockSink* sink)
    : s_(settings), program_(program), source_(source), file_(file), diags_(diags), spaces_(spaces), macro_(macro),
      fast_path_(fast_path), sink_(sink), first_unit_(program.units.size()), in_main_(!macro), streaming_(!macro) {
  lexer_.removeErrorListeners();
  parser_.removeErrorListeners();
  parser_.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(antlr4::atn::PredictionMode::SLL);
}

void Reader::run() {
  read_tape();
  build_units();
}

// ---- The tape ---------------------------------------------------------------------

void Reader::read_tape() {
  std::string_view text = source_.text();
  // §2.3.1: characters before the '%' are not read.
  size_t pct = text.find('%');
  if (pct == std::string_view::npos) {
    diags_.report(DiagId::NoProgramStart, SourceRange::point(file_, 1, 1));
    return;
  }
  uint32_t start_line = 1;
  while (start_line < source_.line_count() && source_.line_offset(start_line + 1) <= pct) ++start_line;
  read_start(start_line, pct);
  main_.kind = ir::UnitKind::Program;
  main_.name = number_;
  main_.title = title_;
  main_.range = start_range_;

  std::optional<Piece> open;  // the block being cut out
  bool star = false;
  auto close = [&](size_t end) {
    if (!open) return;
    open->end = end;
    read_block(*open);
    open.reset();
  };
  for (uint32_t line_no = start_line; line_no <= source_.line_count() && !star; ++line_no) {
    std::string_view line = source_.line(line_no);
    const size_t base = source_.line_offset(line_no);
    // §2.2.1 f: at most 80 characters a line (UTF-8 characters, not bytes).
    size_t chars = 0, col81 = 0;
    for (size_t i = 0; i < line.size(); ++i)
      if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80 && ++chars == kLineLimit + 1) col81 = i;
    if (chars > kLineLimit)
      diags_.report(DiagId::LineTooLong,
                    {file_, line_no, static_cast<uint32_t>(col81 + 1), line_no, static_cast<uint32_t>(line.size() + 1)},
                    chars, kLineLimit);
    if (line_no == start_line) continue;  // the program-start line
    bool comment = false;
    size_t junk = std::string_view::npos;  // text before the first block, on this line
    size_t from = 0;                       // where a comment's text begins
    // A comment line before the first block continues the program start's (§2.2.1 c):
    // the title.
    auto title = [&](size_t end) {
      if (open) return;
      std::string_view more = trim(line.substr(from, end - from));
      if (!more.empty()) main_.title += (main_.title.empty() ? "" : " ") + std::string(more);
    };
    for (size_t i = 0; i < line.size(); ++i) {
      char c = line[i];
      if (comment) {
        comment = c != '"';
        if (!comment) title(i);
        continue;
      }
      if (c == '"') {
        comment = true;
        from = i + 1;
      } else if (c == '*') {
        // §2.3.2: the physical end; nothing after it is read.
        close(base + i);
        star = true;
        break;
      } else if (c == 'N') {
        close(base + i);
        open = Piece{line_no, static_cast<uint32_t>(i + 1), base + i, 0};
      } else if (!open && !is_space(c) && junk == std::string_view::npos) {
        junk = i;
      }
    }
    if (comment) title(line.size());
    if (junk != std::string_view::npos) {
      size_t end = junk;
      while (end < line.size() && !is_space(line[end]) && line[end] != '"' && line[end] != 'N') ++end;
      diags_.report(DiagId::TextOutsideBlock,
                    {file_, line_no, static_cast<uint32_t>(junk + 1), line_no, static_cast<uint32_t>(end + 1)},
                    fmt::format("'{}'", line.substr(junk, end - junk)));
    }
  }
  close(text.size());
  if (!star && s_.require_star) {
    uint32_t last = source_.line_count();
    diags_.report(DiagId::NoStar,
                  SourceRange::point(file_, last, static_cast<uint32_t>(source_.line(last).size() + 1)));
  }
}

void Reader::read_start(uint32_t line_no, size_t pct) {
  const size_t base = source_.line_offset(line_no);
  std::string_view line = source_.line(line_no);
  start_range_ = SourceRange::point(file_, line_no, static_cast<uint32_t>(pct - base + 1));
  number_ = "%";
  if (!block_fits(base + line.size() - pct, start_range_, diags_)) return;
  load(Piece{line_no, static_cast<uint32_t>(pct - base + 1), pct, base + line.size()});
  PpParser::ProgramStartContext* ctx = parser_.programStart();
  start_range_ = range(ctx->getStart(), ctx->getStart());
  // §2.3.1: a whole number 1..999999.
  if (auto* n = ctx->NUMBER()) {
    std::string digits = n->getText();
    SourceRange r = range(n->getSymbol(), n->getSymbol());
    uint32_t v = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (ec != std::errc() || end != digits.data() + digits.size() || v < 1 || v > 999999)
      diags_.report(DiagId::ValueForm, r, "The program number", "a whole number from 1 to 999999",
                    fmt::format("'{}'", digits));
    else
      number_ += std::to_string(v);
  } else {
    diags_.report(DiagId::ValueForm, start_range_, "'%'", "the program number", "a whole number from 1 to 999999");
  }
  for (auto* c : ctx->comment()) {
    if (title_.empty()) title_ = comment_text(c->getStart());
  }
  // Anything else, once: what stands there, as written.
  if (auto elements = ctx->element(); !elements.empty()) {
    antlr4::Token* t = elements.front()->getStart();
    std::string_view rest = line.substr(pct - base + t->getStartIndex());
    while (!rest.empty() && is_space(rest.back())) rest.remove_suffix(1);
    SourceRange r = range(t, elements.back()->getStop());
    diags_.report(
        DiagId::ProgramStructure, r,
        fmt::format("'{}' stands on the program-start line, which holds the program number and a comment only", rest));
  }
}

void Reader::load(const Piece& piece) {
  // Outside 7-bit ASCII only a comment takes a character: U+0001 stands in for each
  // byte, so that the lexer reports it and every column stays a byte offset.
  piece_ = piece;
  sanitized_.assign(source_.text().substr(piece.begin, piece.end - piece.begin));
  for (char& c : sanitized_)
    if (static_cast<unsigned char>(c) >= 0x80) c = '\x01';
  input_.load(sanitized_);
  lexer_.setInputStream(&input_);
  tokens_.setTokenSource(&lexer_);
  parser_.setTokenStream(&tokens_);
}

SourceRange Reader::range(antlr4::Token* first, antlr4::Token* last) const {
  auto at = [&](antlr4::Token* t, size_t offset) {
    uint32_t line = piece_.line + static_cast<uint32_t>(t->getLine()) - 1;
    uint32_t col = (t->getLine() == 1 ? piece_.col : 1) + static_cast<uint32_t>(t->getCharPositionInLine() + offset);
    return std::pair{line, col};
  };
  auto [line, col] = at(first, 0);
  if (last->getType() == antlr4::Token::EOF) return SourceRange::point(file_, line, col);
  auto [end_line, end_col] = at(last, last->getStopIndex() - last->getStartIndex() + 1);
  return {file_, line, col, end_line, end_col};
}

std::string Reader::comment_text(antlr4::Token* t) const {
  std::string_view text =
      source_.text().substr(piece_.begin + t->getStartIndex(), t->getStopIndex() - t->getStartIndex() + 1);
  text.remove_prefix(1);
  if (t->getType() == PpLexer::COMMENT) text.remove_suffix(1);
  return std::string(text);
}

// ---- One block --------------------------------------------------------------------

void Reader::read_block(const Piece& piece) {
  block_ = ir::Block{};
  char_reported_ = false;
  assignments_.clear();
  slash_ = false;
  const size_t errors = diags_.error_count();
  std::string_view first_line = source_.line(piece.line);
  size_t end = first_line.size();
  while (end > piece.col - 1 && is_space(first_line[end - 1])) --end;
  block_.range = {file_, piece.line, piece.col, piece.line, static_cast<uint32_t>(end + 1)};
  // Most blocks are address words only: the hand-written scanner reads them, ANTLR the
  // rest (both give the same IR: tests/fastpath). A block beyond the limit is not read.
  if (!block_fits(piece.end - piece.begin, block_.range, diags_)) {
    block_.has_errors = block_.unread = true;
  } else if (!fast_path_ || !scan_plain(piece)) {
    load(piece);
    PpParser::BlockContext* ctx = parser_.block();
    antlr4::Token* n = ctx->number;
    block_number(trim_left(std::string_view(n->getText()).substr(1)), range(n, n),
                 n->getType() == PpLexer::BARE_ADDRESS);
    auto elements = ctx->element();
    for (size_t i = 0; i < elements.size(); ++i) element(elements[i], i, elements);
  }
  block_.has_errors = diags_.error_count() != errors;
  finish_block();
}

// `N<number> {<address> <value>}` on one line, blanks between the words and after an
// address: the common block. R words, '&', '/', comments, axes 4. 5. 6., a value
// cut by a blank or anything damaged are for the parser.
bool Reader::scan_plain(const Piece& piece) {
  static constexpr PlainRules kRules{"ABCDEFGHIJKLMNOPQSTUVWXYZ", true};
  std::string_view text = source_.text().substr(piece.begin, piece.end - piece.begin);
  // The piece runs to the next block: what follows its first line must be blank.
  const size_t eol = std::min(text.find('\n'), text.size());
  if (text.substr(eol).find_first_not_of(" \t\r\n") != std::string_view::npos) return false;
  text = text.substr(0, eol);
  if (!scan_plain_words(text, kRules, plain_) || plain_.words.empty() || plain_.words.front().letter != 'N')
    return false;
  auto at = [&](uint32_t from, uint32_t to) {
    return SourceRange{file_, piece.line, piece.col + from, piece.line, piece.col + to};
  };
  const PlainWord& n = plain_.words.front();
  block_.words.reserve(plain_.words.size());  // the block keeps them: no spare room
  block_number(text.substr(n.value_from, n.to - n.value_from), at(n.from, n.to), false);
  for (size_t i = 1; i < plain_.words.size(); ++i) {
    const PlainWord& w = plain_.words[i];
    word(text.substr(w.from, w.to - w.from), at(w.from, w.to));
  }
  return true;
}

// §2.2.1 d: the block number, 1..99999999, a written number; `bare`: N without a value.
void Reader::block_number(std::string_view digits, SourceRange nr, bool bare) {
  Written w = parse_written(digits);
  uint32_t number = 0;
  auto [stop, ec] = std::from_chars(w.before.data(), w.before.data() + w.before.size(), number);
  if (bare) {
    diags_.report(DiagId::NoDigits, nr, "N");
  } else if (w.param) {
    diags_.report(DiagId::ValueForm, nr, "N", "a written number", "a block number cannot be a parameter (§2.2.1 g)");
  } else if (w.has_sign || w.point || ec != std::errc() || stop != w.before.data() + w.before.size() || number < 1 ||
             number > 99999999) {
    diags_.report(DiagId::ValueForm, nr, "N", "a whole number from 1 to 99999999", fmt::format("'N{}'", digits));
  } else {
    block_.number = number;
    block_.label = fmt::format("N{}", number);
    ir::Word word;
    word.kind = ir::WordKind::BlockNumber;
    word.slot = static_cast<uint8_t>(letter_slot('N'));
    word.address = "N";
    word.text = std::string(digits);
    word.value = program_.number(number, nr);
    word.range = nr;
    block_.words.push_back(std::move(word));
  }
}

void Reader::element(PpParser::ElementContext* ctx, size_t index, const std::vector<PpParser::ElementContext*>& all) {
  antlr4::Token* t = ctx->getStart();
  switch (t->getType()) {
    case PpLexer::WORD:
    case PpLexer::LINK: word(t->getText(), range(t, t)); return;
    case PpLexer::PARAMETER: parameter(t); return;
    case PpLexer::BLOCK_SKIP: {
      // §2.2.1 i: anywhere after the block number, '/' marks the whole block.
      SourceRange r = range(t, t);
      if (slash_) diags_.report(DiagId::WordRepeated, r, "/", "once");
      slash_ = true;
      block_.skippable = true;
      if (t->getText().size() > 1) diags_.report(DiagId::SkipDigits, r, t->getText());
      return;
    }
    case PpLexer::COMMENT:
    case PpLexer::OPEN_COMMENT: block_.comments.push_back(comment_text(t)); return;
    default: break;
  }
  // A damaged word: what is next to it says what was meant. After a character
  // outside the alphabet, what looks damaged is most likely more of the same text.
  if (char_reported_) return;
  auto adjacent = [&](size_t a, size_t b) {  // only spaces between elements a and b
    if (b >= all.size()) return false;
    antlr4::Token* x = all[a]->getStop();
    antlr4::Token* y = all[b]->getStart();
    std::string_view between =
        std::string_view(sanitized_).substr(x->getStopIndex() + 1, y->getStartIndex() - x->getStopIndex() - 1);
    return between.find_first_not_of(" \t") == std::string_view::npos;
  };
  auto type = [&](size_t i) { return i < all.size() ? all[i]->getStart()->getType() : 0; };
  SourceRange r = range(t, t);
  switch (t->getType()) {
    case PpLexer::BARE_ADDRESS:
      if ((type(index + 1) == PpLexer::SIGN || type(index + 1) == PpLexer::NUMBER) && adjacent(index, index + 1)) {
        size_t last = index + 1;
        if (type(last) == PpLexer::SIGN && type(last + 1) == PpLexer::NUMBER && adjacent(last, last + 1)) ++last;
        SourceRange whole = range(t, all[last]->getStop());
        diags_.report(
            DiagId::SpaceInValue, whole, t->getText(),
            sanitized_.substr(t->getStartIndex(), all[last]->getStop()->getStopIndex() - t->getStartIndex() + 1));
      } else {
        diags_.report(DiagId::NoDigits, r, t->getText());
      }
      return;
    case PpLexer::SIGN:
    case PpLexer::NUMBER: {
      // Reported with the address before it (`X-  36.12`), or as the rest of a value
      // that a space cut (`X36.  12`).
      if (index > 0 && adjacent(index - 1, index)) {
        antlr4::Token* before = all[index - 1]->getStart();
        if (before->getType() == PpLexer::BARE_ADDRESS || before->getType() == PpLexer::SIGN ||
            before->getType() == PpLexer::INVALID)
          return;
        if (before->getType() == PpLexer::WORD) {
          diags_.report(DiagId::SpaceInValue, range(before, t), std::string(1, before->getText()[0]),
                        sanitized_.substr(before->getStartIndex(), t->getStopIndex() - before->getStartIndex() + 1));
          return;
        }
      }
      diags_.report(DiagId::ValueWithoutAddress, r, fmt::format("'{}'", t->getText()));
      return;
    }
    case PpLexer::PERCENT:
      diags_.report(DiagId::ProgramStructure, r, "'%' begins the program and stands once, before its first block");
      return;
    default: {
      // One character a block: a line of foreign text (a comment in another dialect's
      // parentheses) is one mistake, not one a letter. Each byte of a character
      // outside 7-bit ASCII is a token: its first reports it.
      const size_t at = piece_.begin + t->getStartIndex();
      if (char_reported_ || (static_cast<unsigned char>(source_.text()[at]) & 0xC0) == 0x80) return;
      char_reported_ = true;
      size_t length = 1;
      std::string what = describe_char(source_.text(), at, length);
      diags_.report(DiagId::CharInvalid, {r.file, r.line, r.col, r.line, r.col + static_cast<uint32_t>(length)}, what);
      return;
    }
  }
}

ir::ExprId Reader::r_value(uint32_t index, bool negative, SourceRange r) {
  ir::Expr var{ir::ExprOp::Var, Builtin::Sin, spaces_.r, 0, program_.number(index, r), ir::kNoExpr, r};
  ir::ExprId id = program_.add(var);
  return negative ? program_.add({ir::ExprOp::Neg, Builtin::Sin, 0, 0, id, ir::kNoExpr, r}) : id;
}

std::optional<ir::ExprId> Reader::value(std::string_view text, char letter, const stdlib::AddressEntry& entry,
                                        SourceRange r, const std::string& shown) {
  Written w = parse_written(text);
  const bool dimensionless = entry.word_class == stdlib::WordClass::NonDimension;
  if (w.param) {
    // §2.2.1 g: R<n> in place of the value, in every address but N (decision 10).
    uint32_t index = 0;
    auto [end, ec] = std::from_chars(w.before.data(), w.before.data() + w.before.size(), index);
    if (ec != std::errc() || end != w.before.data() + w.before.size() || index >= kParameters) {
      diags_.report(DiagId::ValueForm, r, shown, "a parameter R0 to R95", fmt::format("there is no R{}", w.before));
      return std::nullopt;
    }
    if (w.negative && dimensionless) {
      diags_.report(DiagId::SignNotAllowed, r, shown, "it is a number without dimension");
      return std::nullopt;
    }
    ir::ExprId v = r_value(index, w.negative, r);
    if (letter == 'G' || letter == 'M' || !entry.ranged) return v;
    // What a written number would be checked for, checked when the value is known.
    if (dimensionless || entry.word_class == stdlib::WordClass::Feed) {
      auto& rules = program_.semantics.value_rules;
      std::string address(1, letter);
      size_t rule = 0;
      while (rule < rules.size() && rules[rule].address != address) ++rule;
      if (rule == rules.size()) rules.push_back({address, entry.min, entry.max, dimensionless});
      ir::Expr check{ir::ExprOp::Check, Builtin::Sin, 0, 0, v, ir::kNoExpr, r};
      check.slot = static_cast<uint8_t>(slot_of(letter));
      check.rule = static_cast<uint8_t>(rule);
      v = program_.add(check);
    }
    return v;
  }
  if (w.before.empty() && w.after.empty()) {
    diags_.report(DiagId::NoDigits, r, shown);
    return std::nullopt;
  }
  if (dimensionless) {
    // §2.1.3: digits only.
    if (w.has_sign)
      return (diags_.report(DiagId::SignNotAllowed, r, shown, "it is a number without dimension"), std::nullopt);
    if (w.point)
      return (diags_.report(DiagId::PointNotAllowed, r, shown, "it is a number without dimension"), std::nullopt);
  } else {
    // The maximum block format (§2.2): ±5.3.
    if (size_t n = significant_integer_digits(w.before); n > 5)
      return (diags_.report(DiagId::IntegerDigits, r, shown, n, "±5.3", 5), std::nullopt);
    if (size_t n = significant_fraction_digits(w.after); n > 3)
      return (diags_.report(DiagId::FractionDigits, r, shown, n, "±5.3", 3), std::nullopt);
    if (w.negative && entry.word_class == stdlib::WordClass::Feed)
      return (diags_.report(DiagId::SignNotAllowed, r, shown, "a feed is not negative"), std::nullopt);
  }
  // A number without dimension has any number of digits: it may be out of range.
  auto magnitude = read_number(w.before + (w.point ? "." + w.after : ""), r, diags_);
  if (!magnitude) return std::nullopt;
  const double v = w.negative ? -*magnitude : *magnitude;
  if (entry.ranged && (v < entry.min || v > entry.max)) {
    diags_.report(DiagId::ValueRange, r, shown, std::string(1, letter), shortest(entry.min), shortest(entry.max));
    return std::nullopt;
  }
  if (letter == '&' && w.before.find_first_not_of("012") != std::string::npos) {
    diags_.report(DiagId::ValueForm, r, shown, "a digit 0, 1 or 2 for each of X Y Z 4.",
                  "0 is no length compensation, 1 adds the tool length and 2 subtracts it");
    return std::nullopt;
  }
  return program_.number(v, r);
}

void Reader::word(std::string_view written, SourceRange r) {
  const std::string text(written);
  const bool numbered = text[0] >= '4' && text[0] <= '6';
  // §2.2.1 a, b: axes 4. 5. 6. by number, or by the letters the machine gives them.
  char letter = numbered ? s_.axis_letters[static_cast<size_t>(text[0] - '4')] : text[0];
  std::string_view rest = trim_left(std::string_view(text).substr(numbered ? 2 : 1));
  ir::Word w;
  w.address = std::string(1, letter);
  w.text = std::string(rest);
  w.range = r;
  w.slot = static_cast<uint8_t>(slot_of(letter));
  w.kind = ir::WordKind::Ignored;
  auto entry = s_.tables.addresses.find(letter);
  if (entry == s_.tables.addresses.end() || letter == 'N' || letter == 'R') {
    diags_.report(DiagId::AddressUnknown, r, std::string(1, letter));
  } else if (!numbered && std::string_view("ABCUVW").find(letter) != std::string_view::npos &&
             s_.axis_letters.find(letter) == std::string::npos) {
    diags_.report(DiagId::AxisAbsent, r, std::string(1, letter), s_.conventions.axes + " (machine profile)");
  } else if (auto v = value(rest, letter, entry->second, r, text)) {
    w.value = *v;
    if (letter == 'G' || letter == 'M') {
      w.kind = ir::WordKind::Code;
      if (!program_.is_constant(*v)) {
        w.code = ir::kDynamicCode;
      } else {
        const auto& table = letter == 'G' ? s_.tables.g_codes : s_.tables.m_codes;
        auto it = table.find(ir::code_number(program_, *v));
        w.code = it == table.end() ? -1 : program_code(program_, it->second.desc);
      }
    } else {
      w.kind = ir::WordKind::Parameter;
    }
  }
  block_.words.push_back(std::move(w));
}

void Reader::parameter(antlr4::Token* t) {
  // R<n> <value> (decision 9): the value after a space, or right after the number when
  // it begins with a sign or R.
  std::string text = t->getText();
  SourceRange r = range(t, t);
  size_t digits = 1;
  while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) ++digits;
  std::string name = text.substr(0, digits);
  std::string_view rest(text);
  rest.remove_prefix(digits);
  const bool spaced = !rest.empty() && is_space(rest.front());
  rest = trim_left(rest);
  uint32_t index = 0;
  auto [end, ec] = std::from_chars(name.data() + 1, name.data() + name.size(), index);
  if (ec != std::errc() || index >= kParameters) {
    diags_.report(DiagId::ValueForm, r, name, "a parameter R0 to R95", fmt::format("there is no {}", name));
    return;
  }
  if (rest.empty()) {
    diags_.report(DiagId::ValueMissing, r, name);
    return;
  }
  if (!spaced && rest.front() == '.') {
    diags_.report(DiagId::ValueForm, r, name, "its value after a space", fmt::format("write {} {}", name, rest));
    return;
  }
  auto entry = s_.tables.addresses.find('R');
  if (auto v = value(rest, 'R', entry->second, r, text)) assignments_.push_back({index, *v, r});
}

// ---- The block's statements -------------------------------------------------------

Reader::Flow Reader::flow_of(const ir::Block& b) const {
  Flow f;
  for (const ir::Word& w : b.words) {
    if (w.kind == ir::WordKind::Code && w.code >= 0) {
      const CodeDesc& code = program_.semantics.codes[static_cast<size_t>(w.code)];
      if (auto it = s_.control.find(code.name); it != s_.control.end())
        f.control_word[static_cast<size_t>(it->second.action)] = &w;
      for (const FnCall& call : code.calls)
        if (call.fn == Fn::ProgramEnd || call.fn == Fn::ProgramEndInformation) f.ends_main = &w;
    }
    if (w.address == "L" && w.kind != ir::WordKind::Ignored) {
      f.l_word = &w;
      if (program_.is_constant(w.value))
        f.l = whole_in<uint32_t>(program_.exprs[w.value].number, 0, UINT32_MAX);  // 1..9999: the table
    }
    if (w.address == "Q" && w.kind != ir::WordKind::Ignored) f.q_word = &w;
  }
  return f;
}

void Reader::finish_block() {
  // §2.2, the maximum block format: "11G", "10M" (one per group is the rule that binds).
  for (auto [letter, most] : {std::pair{'G', 11}, std::pair{'M', 10}}) {
    int n = 0;
    for (const ir::Word& w : block_.words)
      if (w.kind == ir::WordKind::Code && w.address[0] == letter && ++n == most + 1)
        diags_.report(DiagId::TooManyCodes, w.range, most + 1, std::string(1, letter), most);
  }
  for (const ir::Word& w : block_.words) {
    if (w.kind != ir::WordKind::Code || w.code < 0) continue;
    auto it = s_.control.find(program_.semantics.codes[static_cast<size_t>(w.code)].name);
    if (it != s_.control.end() && it->second.action == Control::Unsupported) {
      diags_.report(DiagId::Unsupported, w.range, w.address + w.text, it->second.note);
      block_.has_errors = true;
    }
  }
  Flow f = flow_of(block_);
  // G14-G16: the plane's axes as the operands of plane.select.
  if (const ir::Word* w = f.control_word[static_cast<size_t>(Control::Plane)]) {
    const std::string axes = s_.control.at(program_.semantics.codes[static_cast<size_t>(w->code)].name).plane;
    const SourceRange r = w->range;
    for (int i = 0; i < 2; ++i) {
      char axis = axes[static_cast<size_t>(i)] == '4' ? s_.axis_letters[0] : axes[static_cast<size_t>(i)];
      ir::Word op;
      op.slot = static_cast<uint8_t>(operand_slot(i));
      op.address = "#";
      op.text = std::string(1, axis);
      op.value = program_.number(axis_index(axis), r);
      op.range = r;
      block_.words.push_back(std::move(op));
    }
    f = flow_of(block_);
  }
  auto has = [&](Control c) { return f.control_word[static_cast<size_t>(c)] != nullptr; };
  const bool calls = has(Control::CallSubprogram) || has(Control::CallMacro) || has(Control::Jump);
  const bool uses_l = calls || has(Control::Entry);
  // L names a unit or a block: a written number, known before the run (decision 11).
  if (f.l_word && !uses_l) {
    diags_.report(DiagId::ProgramStructure, f.l_word->range,
                  fmt::format("L{} has no G71, G72, G73 or G79 in its block to read it", f.l_word->text));
    block_.has_errors = true;
  } else if (f.l_word && !f.l) {
    diags_.report(DiagId::ValueForm, f.l_word->range, "L" + f.l_word->text, "a written number",
                  "ncc resolves calls and jumps before the run");
    block_.has_errors = true;
  } else if (uses_l && !f.l_word && !block_.has_errors) {
    const ir::Word* code = f.control_word[static_cast<size_t>(has(Control::Entry)       ? Control::Entry
                                                              : has(Control::Jump)      ? Control::Jump
                                                              : has(Control::CallMacro) ? Control::CallMacro
                                                                                        : Control::CallSubprogram)];
    diags_.report(DiagId::ValueMissing, code->range,
                  fmt::format("{}{} (L in the same block)", code->address, code->text));
    block_.has_errors = true;
  }
  // §2.2.1 j: with G04, Q is the dwell and a call or jump runs once.
  const bool q_counts = calls && !has(Control::Dwell);
  for (ir::Word& w : block_.words)
    if ((w.address == "L" && uses_l) || (w.address == "Q" && q_counts))
      if (w.kind == ir::WordKind::Parameter) w.kind = ir::WordKind::Control;

  // R words first, left to right (decision 9), then the machine, then the flow.
  const ir::Word* formula = f.control_word[static_cast<size_t>(Control::Formula)];
  char op = formula ? s_.control.at(program_.semantics.codes[formula->code].name).op : 0;
  for (const Assignment& a : assignments_) {
    ir::Stmt s(ir::StmtKind::Assign, a.range);
    s.target = r_value(a.index, false, a.range);
    s.value = a.value;
    if (op) {
      static const std::map<char, ir::ExprOp> kOps = {
          {'+', ir::ExprOp::Add}, {'-', ir::ExprOp::Sub}, {'*', ir::ExprOp::Mul}, {'/', ir::ExprOp::Div}};
      s.value = program_.add({kOps.at(op), Builtin::Sin, 0, 0, r_value(a.index, false, a.range), a.value, a.range});
    }
    block_.stmts.push_back(s);
  }
  bool machine = false;
  for (const ir::Word& w : block_.words)
    machine = machine || w.kind == ir::WordKind::Code || w.kind == ir::WordKind::Parameter;
  if (machine) block_.stmts.push_back({ir::StmtKind::Machine, block_.range});
  place_block();
}

// ---- Program units ----------------------------------------------------------------

void Reader::place_block() {
  // §2.3: block numbers are unique in the file.
  if (block_.number) {
    const Numbered here{*block_.number, read_, block_.words.front().range};
    if (const Numbered* first = numbered(here.number)) {
      if (Diagnostic* d = diags_.report(DiagId::BlockNumberTwice, here.range, here.number))
        d->notes.push_back({first->range, "first used here"});
    } else if (rising_.empty() || here.number > rising_.back().number) {
      rising_.push_back(here);
    } else {
      others_.emplace(here.number, here);
    }
  }
  ++read_;
  last_range_ = block_.range;
  if (!in_main_) {
    blocks_.push_back(std::move(block_));
    return;
  }
  Flow f = flow_of(block_);
  if (f.control_word[static_cast<size_t>(Control::End)])
    structure(block_, "G70 ends a subprogram or a macro, not the main part (§2.3.3)");
  if (f.control_word[static_cast<size_t>(Control::Entry)])
    structure(block_, "G79 starts a subprogram, after the main part (§2.3.3)");
  // §2.3.2: the main part ends at the block with M02 or M30.
  in_main_ = !f.ends_main;
  // A call or a jump is resolved once the whole file is read: from it on, the main
  // part is held.
  if (flow(block_, f, 0, main_)) streaming_ = false;
  main_.blocks.push_back(std::move(block_));
  if (streaming_ && sink_) sink_->take(program_, main_);
  streaming_ = streaming_ && in_main_;
}

const Reader::Numbered* Reader::numbered(uint32_t number) const {
  auto it = std::lower_bound(rising_.begin(), rising_.end(), number,
                             [](const Numbered& n, uint32_t v) { return n.number < v; });
  if (it != rising_.end() && it->number == number) return &*it;
  auto other = others_.find(number);
  return other != others_.end() ? &other->second : nullptr;
}

bool Reader::flow(ir::Block& b, const Flow& f, size_t unit, const ir::Unit& in) {
  if (b.has_errors || !f.l) return false;
  auto word = [&](Control c) { return f.control_word[static_cast<size_t>(c)]; };
  const size_t block = in.blocks.size();  // where `b` goes
  if (word(Control::Jump) && !word(Control::CallSubprogram) && !word(Control::CallMacro)) {
    jumps_.push_back({unit, block});
    return true;
  }
  ir::Stmt call(ir::StmtKind::Call, f.l_word->range);
  call.value = f.q_word && f.q_word->kind == ir::WordKind::Control ? f.q_word->value : program_.number(1, b.range);
  if (const ir::Word* w = word(Control::CallSubprogram)) {
    if (macro_) {
      diags_.report(DiagId::ProgramStructure, w->range,
                    "a macro cannot call a subprogram: subprograms belong to their part program (§2.3.3)");
      return true;
    }
    call.label = fmt::format("L{}", *f.l);
  } else if (word(Control::CallMacro)) {
    call.label = macro_name(*f.l);
    macro_calls_.push_back({*f.l, f.l_word->range, first_unit_ + unit, block});
  } else {
    return false;
  }
  b.stmts.push_back(call);
  return true;
}

void Reader::structure(const ir::Block& b, const std::string& what) {
  diags_.report(DiagId::ProgramStructure, b.range, what);
}

void Reader::build_units() {
  std::vector<Span> spans;
  if (!macro_) {
    if (in_main_ && !number_.empty())  // (no '%': that is the error)
      diags_.report(DiagId::ProgramStructure, read_ ? last_range_ : start_range_,
                    read_ ? std::string("the main part does not end with M02 or M30 (§2.3.2)")
                          : std::string("the program has no blocks: its main part ends with M02 or M30 (§2.3.2)"));
    spans.push_back({0, read_ - blocks_.size()});
    program_.units.push_back(std::move(main_));
  }
  // Subprograms after the main part (§2.3.3), or the one macro of a macro file.
  const size_t base = read_ - blocks_.size();  // blocks_[0] is the file's block `base`
  std::set<uint32_t> defined;
  size_t i = 0;
  while (i < blocks_.size()) {
    Flow f = flow_of(blocks_[i]);
    if (!f.control_word[static_cast<size_t>(Control::Entry)]) {
      structure(blocks_[i],
                macro_ ? "a macro file holds one macro: G79 L<number> ... G70 (§2.3.5)"
                       : "after the main part (M02, M30) come only subprograms: G79 L<number> ... G70 (§2.3.2)");
      ++i;
      continue;
    }
    size_t last = i;
    while (last + 1 < blocks_.size() && !flow_of(blocks_[last]).control_word[static_cast<size_t>(Control::End)]) ++last;
    ir::Unit unit;
    unit.kind = macro_ ? ir::UnitKind::Macro : ir::UnitKind::Subprogram;
    unit.range = blocks_[i].range;
    uint32_t n = f.l.value_or(0);
    unit.name = macro_ ? macro_name(*macro_) : fmt::format("L{}", n);
    if (!flow_of(blocks_[last]).control_word[static_cast<size_t>(Control::End)])
      structure(blocks_[i], fmt::format("{} L{} does not end: a block with G70 ends it (§2.3.3)",
                                        macro_ ? "macro" : "subprogram", n));
    if (macro_ && n != *macro_)
      structure(blocks_[i],
                fmt::format("the macro in file {} must be L{}, not L{} (§2.3.5)", macro_name(*macro_), *macro_, n));
    if (macro_ && !spans.empty()) structure(blocks_[i], "a macro file holds one macro: G79 L<number> ... G70 (§2.3.5)");
    if (f.l && !defined.insert(n).second && !macro_)
      structure(blocks_[i], fmt::format("subprogram L{} is defined twice", n));
    if (defined.size() == kSubprograms + 1 && !macro_)
      structure(blocks_[i], fmt::format("a part program holds at most {} subprograms (§2.3.3)", kSubprograms));
    // §2.3.3: the entry block holds G79 and L only.
    for (const ir::Word& w : blocks_[i].words)
      if (w.kind != ir::WordKind::BlockNumber && w.address != "L" &&
          !(w.address == "G" && &w == f.control_word[static_cast<size_t>(Control::Entry)]))
        diags_.report(DiagId::ProgramStructure, w.range,
                      fmt::format("{}{} stands in the entry block of L{}, which holds G79 and L only (§2.3.3)",
                                  w.address, w.text, n));
    for (size_t k = i; k <= last; ++k) {
      ir::Block& b = blocks_[k];
      Flow bf = flow_of(b);
      if (bf.ends_main)
        diags_.report(DiagId::EndInSubprogram, bf.ends_main->range, bf.ends_main->address + bf.ends_main->text,
                      macro_ ? "a macro" : "subprogram " + unit.name);
      if (bf.control_word[static_cast<size_t>(Control::Entry)] && k != i)
        structure(b, "G79 inside a subprogram: G70 ends the one before it (§2.3.3)");
      flow(b, bf, spans.size(), unit);
      unit.blocks.push_back(std::move(b));
    }
    spans.push_back({base + i, base + last + 1});
    program_.units.push_back(std::move(unit));
    i = last + 1;
  }
  if (macro_ && spans.empty() && !blocks_.empty()) structure(blocks_.front(), "the macro file holds no G79 block");
  blocks_.clear();
  resolve_jumps(spans);
}

void Reader::resolve_jumps(const std::vector<Span>& spans) {
  for (const Jump& j : jumps_) {
    ir::Unit& unit = program_.units[first_unit_ + j.unit];
    ir::Block& b = unit.blocks[j.block];
    Flow f = flow_of(b);
    // §2.3.6: a jump stays in its unit; the section runs Q+1 times (decision 14).
    const Numbered* target = numbered(*f.l);
    auto in = [&](const Span& s) { return target->at >= s.begin && target->at < s.end; };
    if (!target || !in(spans[j.unit])) {
      if (!target) {
        diags_.report(DiagId::LabelUndefined, f.l_word->range, "G73", fmt::format("L{}", *f.l));
      } else {
        std::string where = "the main part";
        for (size_t s = 0; s < spans.size(); ++s)
          if (in(spans[s]) && program_.units[first_unit_ + s].kind != ir::UnitKind::Program)
            where = "subprogram " + program_.units[first_unit_ + s].name;
        std::string unit_name = macro_ ? "this macro" : j.unit == 0 ? "the main part" : "subprogram " + unit.name;
        diags_.report(DiagId::JumpScope, f.l_word->range, *f.l, where, unit_name);
      }
      b.has_errors = true;
      continue;
    }
    ir::ExprId count =
        f.q_word && f.q_word->kind == ir::WordKind::Control ? f.q_word->value : program_.number(1, b.range);
    ir::ExprId index = program_.number(spaces_.next_counter++, b.range);
    auto counter = [&] {
      return program_.add({ir::ExprOp::Var, Builtin::Sin, spaces_.counters, 0, index, ir::kNoExpr, b.range});
    };
    auto bin = [&](ir::ExprOp o, ir::ExprId a, ir::ExprId c) {
      return program_.add({o, Builtin::Sin, 0, 0, a, c, b.range});
    };
    // Unarmed (0): arm with Q + 1; then count down, and jump while it lasts.
    ir::Stmt arm(ir::StmtKind::Assign, b.range);
    arm.target = counter();
    arm.value = bin(ir::ExprOp::Add,
                    bin(ir::ExprOp::Mul, bin(ir::ExprOp::Eq, counter(), program_.number(0, b.range)),
                        bin(ir::ExprOp::Add, count, program_.number(1, b.range))),
                    counter());
    ir::Stmt down(ir::StmtKind::Assign, b.range);
    down.target = counter();
    down.value = bin(ir::ExprOp::Sub, counter(), program_.number(1, b.range));
    ir::Stmt jump(ir::StmtKind::Jump, f.l_word->range);
    jump.label = fmt::format("N{}", *f.l);
    jump.cond = bin(ir::ExprOp::Gt, counter(), program_.number(0, b.range));
    b.stmts.push_back(arm);
    b.stmts.push_back(down);
    b.stmts.push_back(jump);
  }
}

}  // namespace ncc::pp
