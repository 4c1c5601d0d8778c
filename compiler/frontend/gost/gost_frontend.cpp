// GOST 20999-83 front end: the tape reader of §1 (leader, '%', programs ended by
// M02, the medium by M30) feeding the ANTLR block grammar one line at a time, and a
// visitor that turns each block into IR, decoding numbers by the §9 format.
#include "gost_frontend.h"

#include <antlr4-runtime.h>

#include "GostLexer.h"
#include "GostParser.h"
#include "GostParserBaseVisitor.h"
#include "frontend/limits.h"
#include "frontend/plain_words.h"
#include "settings.h"

namespace ncc::gost {

namespace {

using ncc_gost::GostLexer;
using ncc_gost::GostParser;

bool is_ignored(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\0' || c == '\x7F'; }

// Maps ANTLR syntax errors to diagnostics at the right column.
class ErrorListener final : public antlr4::BaseErrorListener {
 public:
  void reset(std::string_view original, uint32_t file, uint32_t line, uint32_t base) {
    original_ = original;
    file_ = file;
    line_ = line;
    base_ = base;
  }
  void bind(Diagnostics* diags, bool* errors) {
    diags_ = diags;
    errors_ = errors;
  }

  void syntaxError(antlr4::Recognizer*, antlr4::Token* token, size_t, size_t position, const std::string&,
                   std::exception_ptr) override {
    *errors_ = true;
    size_t at = token ? token->getStartIndex() : position;
    if (token && token->getType() == antlr4::Token::EOF) at = original_.size();
    uint32_t col = base_ + static_cast<uint32_t>(at) + 1;
    if (token && token->getType() == GostLexer::INVALID && at < original_.size()) {
      size_t length = 1;
      std::string what = describe_char(original_, at, length);
      diags_->report(DiagId::CharInvalid, {file_, line_, col, line_, col + static_cast<uint32_t>(length)}, what);
      return;
    }
    std::string what = !token || token->getType() == antlr4::Token::EOF ? std::string("end of the line")
                                                                        : fmt::format("'{}'", token->getText());
    uint32_t len = token && token->getType() != antlr4::Token::EOF
                       ? static_cast<uint32_t>(token->getStopIndex() - token->getStartIndex() + 1)
                       : 1;
    diags_->report(DiagId::SyntaxError, {file_, line_, col, line_, col + len}, what);
  }

 private:
  std::string_view original_;
  uint32_t file_ = 0, line_ = 0, base_ = 0;
  Diagnostics* diags_ = nullptr;
  bool* errors_ = nullptr;
};

// Reads one file. The ANTLR objects are made once and reset for every line.
class Reader final : public ncc_gost::GostParserBaseVisitor {
 public:
  Reader(const Settings& settings, ir::Program& program, const SourceFile& source, uint32_t file, Diagnostics& diags,
         const ReadOptions& options)
      : s_(settings), program_(program), source_(source), file_(file), diags_(diags), fast_path_(options.fast_path),
        sink_(options.sink) {
    lexer_.removeErrorListeners();
    parser_.removeErrorListeners();
    parser_.addErrorListener(&listener_);
    parser_.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(antlr4::atn::PredictionMode::SLL);
    listener_.bind(&diags_, &line_has_errors_);
  }

  void run();

 private:
  enum class State { Leader, Program, Trailer };

  // Tape level (§1).
  void start_program(std::string_view line, uint32_t line_no, uint32_t col);
  void end_program(SourceRange at, bool terminated);
  void read_block(std::string_view line, uint32_t line_no);

  // Block level.
  void parse(std::string_view text, uint32_t line_no, uint32_t base);
  antlrcpp::Any visitSkip(GostParser::SkipContext* ctx) override;
  antlrcpp::Any visitBlockNumber(GostParser::BlockNumberContext* ctx) override;
  antlrcpp::Any visitWord(GostParser::WordContext* ctx) override;
  // A word or block number as written, from the parse tree or the fast path.
  void block_number(bool main, const WrittenNumber& n, SourceRange r, const std::string& text);
  void address_word(char letter, const WrittenNumber& n, SourceRange r, std::string text);
  bool scan_plain(std::string_view line);
  antlrcpp::Any visitComment(GostParser::CommentContext* ctx) override;
  antlrcpp::Any visitElement(GostParser::ElementContext* ctx) override;
  void finish_block();

  SourceRange range(antlr4::Token* first, antlr4::Token* last) const;
  SourceRange range(antlr4::ParserRuleContext* ctx) const { return range(ctx->getStart(), ctx->getStop()); }
  WrittenNumber written_number(GostParser::SignContext* sign, GostParser::NumberContext* number, char letter);
  void check_comment_text(antlr4::Token* token);
  int32_t code_index(char letter, int number);
  template <typename... Args>
  void report_mode(DiagIdFor<Args...> id, SourceRange r, Severity strict_severity, const Args&... args);

  const Settings& s_;
  ir::Program& program_;
  const SourceFile& source_;
  uint32_t file_;
  Diagnostics& diags_;
  bool fast_path_;
  PlainBlock plain_;  // the fast path's words, kept from line to line
  BlockSink* sink_;   // takes each finished block (the reader keeps nothing of them)

  antlr4::ANTLRInputStream input_;
  GostLexer lexer_{&input_};
  antlr4::CommonTokenStream tokens_{&lexer_};
  GostParser parser_{&tokens_};
  ErrorListener listener_;
  std::string sanitized_;
  std::string_view line_text_;
  uint32_t line_no_ = 0;
  uint32_t base_ = 0;
  bool line_has_errors_ = false;

  State state_ = State::Leader;
  ir::Unit unit_;
  bool first_block_ = true;
  bool any_program_ = false;
  ir::Block block_;
  bool seen_element_ = false;                 // something other than a leading '/' was read
  bool optional_rest_ = false;                // a '/' inside the block made the rest optional
  size_t optional_comments_from_ = SIZE_MAX;  // comments from this index on are optional too
};

SourceRange Reader::range(antlr4::Token* first, antlr4::Token* last) const {
  uint32_t begin = base_ + static_cast<uint32_t>(first->getStartIndex()) + 1;
  uint32_t end = base_ + static_cast<uint32_t>(last->getStopIndex()) + 2;
  if (last->getType() == antlr4::Token::EOF || end < begin) end = begin + 1;
  return {file_, line_no_, begin, line_no_, end};
}

template <typename... Args>
void Reader::report_mode(DiagIdFor<Args...> id, SourceRange r, Severity strict_severity, const Args&... args) {
  Diagnostic d{id.id(), diag_info(id.id()).severity, r, diag_message(id, args...), {}};
  if (s_.decode.mode == Mode::Strict) d.severity = strict_severity;
  diags_.add(std::move(d));
}

void Reader::parse(std::string_view text, uint32_t line_no, uint32_t base) {
  // Outside 7-bit ASCII nothing is a valid character; U+0001 stands in so that the
  // lexer reports it and every column stays a byte offset.
  sanitized_.assign(text);
  for (char& c : sanitized_)
    if (static_cast<unsigned char>(c) >= 0x80) c = '\x01';
  line_text_ = text;
  line_no_ = line_no;
  base_ = base;
  line_has_errors_ = false;
  input_.load(sanitized_);
  lexer_.setInputStream(&input_);
  tokens_.setTokenSource(&lexer_);
  parser_.setTokenStream(&tokens_);
  listener_.reset(text, file_, line_no, base);
}

void Reader::run() {
  for (uint32_t line_no = 1; line_no <= source_.line_count() && !diags_.limit_reached(); ++line_no) {
    std::string_view line = source_.line(line_no);
    size_t first = 0;
    while (first < line.size() && is_ignored(line[first])) ++first;
    if (first == line.size()) continue;  // nothing the NC perceives: not a block
    auto at = [&](size_t col) { return SourceRange::point(file_, line_no, static_cast<uint32_t>(col + 1)); };
    if (state_ == State::Trailer) {
      // §1.9: after the end of information nothing is perceived.
      diags_.report(DiagId::TrailerIgnored, at(first));
      return;
    }
    if (!s_.format.program_start) {
      if (line[first] == '%') {
        diags_.report(DiagId::FeatureNotInFormat, at(first), "the program-start character '%'", "%");
        continue;
      }
      // Without '%' the medium holds programs one after the other.
      if (state_ == State::Leader) start_program({}, line_no, 0);
      read_block(line, line_no);
    } else if (state_ == State::Leader) {
      // §1.8: anything before the '%' is leader and is not read.
      if (size_t pct = line.find('%'); pct != std::string_view::npos)
        start_program(line.substr(pct), line_no, static_cast<uint32_t>(pct));
    } else if (line[first] == '%') {
      // §1.9: the next program starts before this one ended.
      end_program(at(first), false);
      start_program(line.substr(first), line_no, static_cast<uint32_t>(first));
    } else {
      read_block(line, line_no);
    }
  }
  if (state_ == State::Program) {
    uint32_t last = source_.line_count();
    end_program(SourceRange::point(file_, last, static_cast<uint32_t>(source_.line(last).size() + 1)), false);
  }
  if (!any_program_ && s_.format.program_start) diags_.report(DiagId::NoProgramStart, SourceRange::point(file_, 1, 1));
}

void Reader::start_program(std::string_view line, uint32_t line_no, uint32_t col) {
  unit_ = ir::Unit{};
  unit_.range = SourceRange::point(file_, line_no, col + 1);
  unit_.name = "%";
  first_block_ = true;
  state_ = State::Program;
  bool first_program = !any_program_;
  any_program_ = true;
  if (line.empty()) return;  // a format without '%': the program starts at its first block
  if (!block_fits(line.size(), {file_, line_no, col + 1, line_no, col + 1 + static_cast<uint32_t>(line.size())},
                  diags_))
    return;
  parse(line, line_no, col);
  GostParser::ProgramStartContext* ctx = parser_.programStart();
  unit_.range = range(ctx);
  auto percents = ctx->PERCENT();
  // §1.8: the first of two '%' marks the physical start of the medium.
  if (percents.size() == 2 && !first_program)
    diags_.report(DiagId::TapeStartMarker, range(percents[0]->getSymbol(), percents[0]->getSymbol()));
  std::string number;
  for (auto* d : ctx->DIGITS()) number += d->getText();
  if (!number.empty()) {
    unit_.name += number;
    if (number.size() > 8) {
      auto digits = ctx->DIGITS();
      diags_.report(DiagId::ProgramNumberLength, range(digits.front()->getSymbol(), digits.back()->getSymbol()),
                    number.size(), 8);
    }
  }
  if (auto* c = ctx->comment()) {
    check_comment_text(c->getStart());
    std::string text = c->getText();
    if (c->COMMENT()) unit_.title = std::string(line_text_.substr(c->getStart()->getStartIndex() + 1, text.size() - 2));
  }
}

void Reader::end_program(SourceRange at, bool terminated) {
  if (!terminated)
    diags_.report(DiagId::ProgramNotTerminated, at,
                  at.line > source_.line_count() || at.col > source_.line(at.line).size()
                      ? std::string("the end of the file")
                      : std::string("the next program start '%'"));
  if (unit_.blocks.empty() && !unit_.streamed) diags_.report(DiagId::EmptyProgram, unit_.range, unit_.name);
  program_.units.push_back(std::move(unit_));
  unit_ = ir::Unit{};
  state_ = State::Leader;
}

void Reader::read_block(std::string_view line, uint32_t line_no) {
  line_text_ = line;
  line_no_ = line_no;
  base_ = 0;
  block_ = ir::Block{};
  seen_element_ = false;
  optional_rest_ = false;
  optional_comments_from_ = SIZE_MAX;
  uint32_t errors = diags_.error_count();
  block_.range = {file_, line_no, 1, line_no, static_cast<uint32_t>(line.size() + 1)};
  if (!block_fits(line.size(), block_.range, diags_)) {
    block_.has_errors = block_.unread = true;
    first_block_ = false;
    unit_.blocks.push_back(std::move(block_));
    return;
  }
  // Most blocks are address words only: the hand-written scanner reads them, ANTLR the
  // rest (both give the same IR: tests/fastpath).
  if (fast_path_ && scan_plain(line)) {
    block_.has_errors = diags_.error_count() != errors;
  } else {
    block_ = ir::Block{};
    block_.range = {file_, line_no, 1, line_no, static_cast<uint32_t>(line.size() + 1)};
    parse(line, line_no, 0);
    GostParser::BlockContext* ctx = parser_.block();
    for (auto* element : ctx->element()) visit(element);
    block_.has_errors = diags_.error_count() != errors;
  }
  finish_block();
  if (sink_ && state_ == State::Program) sink_->take(program_, unit_);
}

void Reader::finish_block() {
  // §1.4: the first block of a program carries its number.
  if (first_block_ && !block_.number)
    report_mode(DiagId::FirstBlockNoNumber, SourceRange::point(file_, line_no_, 1), Severity::Error);
  first_block_ = false;

  // The machine action reads the codes and parameter words; comments show first.
  for (size_t i = 0; i < block_.comments.size(); ++i) {
    ir::Stmt c{ir::StmtKind::Comment, block_.range};
    c.label = block_.comments[i];
    c.optional = i >= optional_comments_from_;
    block_.stmts.push_back(std::move(c));
  }
  bool action = false;
  for (const ir::Word& w : block_.words)
    action = action || w.kind == ir::WordKind::Code || w.kind == ir::WordKind::Parameter;
  if (action) block_.stmts.push_back({ir::StmtKind::Machine, block_.range});

  // §2.6: a main block holds everything needed to resume machining.
  if (block_.main_block) {
    std::vector<std::string> missing;
    auto has_group = [&](std::string_view group) {
      for (const ir::Word& w : block_.words)
        if (w.kind == ir::WordKind::Code && w.address == "G" && w.code >= 0) {
          auto it = s_.tables.g_codes.find(ir::code_number(program_, w.value));
          if (it != s_.tables.g_codes.end() && it->second.group == group) return true;
        }
      return false;
    };
    auto has_word = [&](std::string_view address) {
      for (const ir::Word& w : block_.words)
        if (w.address == address) return true;
      return false;
    };
    auto has_spindle = [&] {
      for (const ir::Word& w : block_.words)
        if (w.kind == ir::WordKind::Code && w.code >= 0)
          for (const FnCall& call : program_.semantics.codes[w.code].calls)
            if (fn_group(call.fn) == FnGroup::Spindle) return true;
      return false;
    };
    if (!has_group("a")) missing.push_back("the motion (group a)");
    if (!has_group("i")) missing.push_back("G90/G91");
    if (s_.control_type != "positioning" && !has_group("c")) missing.push_back("the plane (G17-G19)");
    auto feed_motion = [&] {
      for (const ir::Word& w : block_.words)
        if (w.kind == ir::WordKind::Code && w.code >= 0)
          for (const FnCall& call : program_.semantics.codes[w.code].calls)
            if (fn_group(call.fn) == FnGroup::Motion && call.fn != Fn::MotionRapid) return true;
      return false;
    };
    if (feed_motion() && !has_word("F")) missing.push_back("F");
    if (!has_word("S") || !has_spindle()) missing.push_back("S with M03/M04/M05");
    if (!has_word("T")) missing.push_back("T");
    if (!missing.empty()) {
      std::string list;
      for (size_t i = 0; i < missing.size(); ++i) list += (i ? ", " : "") + missing[i];
      diags_.report(DiagId::MainBlockIncomplete, block_.range, list);
    }
  }

  // §1.9: M02 ends the program, M30 the information. In a part the block-skip switch
  // may drop, it ends nothing for sure: the reader goes on.
  bool ends = false, ends_information = false;
  for (const ir::Word& w : block_.words) {
    if (w.kind != ir::WordKind::Code || w.code < 0) continue;
    for (const FnCall& call : program_.semantics.codes[w.code].calls) {
      if (call.fn != Fn::ProgramEnd && call.fn != Fn::ProgramEndInformation) continue;
      if (block_.skippable || w.optional) {
        diags_.report(DiagId::SkippableEnd, w.range, w.address + w.text);
        continue;
      }
      ends = true;
      ends_information = ends_information || call.fn == Fn::ProgramEndInformation;
    }
  }
  bool empty = block_.words.empty() && block_.comments.empty() && !block_.skippable && !block_.has_errors;
  if (!empty) unit_.blocks.push_back(std::move(block_));
  if (ends) {
    unit_.ends_information = ends_information;
    end_program({}, true);
    if (ends_information) state_ = State::Trailer;
  }
}

antlrcpp::Any Reader::visitElement(GostParser::ElementContext* ctx) {
  if (ctx->RPAREN()) {
    // Table 2: ')' switches processing on; without '(' it changes nothing.
    diags_.report(DiagId::StrayRightParen, range(ctx));
    return nullptr;
  }
  visitChildren(ctx);
  return nullptr;
}

antlrcpp::Any Reader::visitSkip(GostParser::SkipContext* ctx) {
  if (!s_.format.block_skip) {
    diags_.report(DiagId::FeatureNotInFormat, range(ctx), "block skip '/'", "/");
  } else if (ctx->DIGITS()) {
    diags_.report(DiagId::SkipLevel, range(ctx), ctx->DIGITS()->getText());
  }
  // Table 2 and §2.7: before the block number (or as the first thing in a block
  // without one) '/' acts on the whole block; inside it, on the rest of the block.
  if (!seen_element_) {
    block_.skippable = true;
  } else if (!optional_rest_) {
    optional_rest_ = true;
    optional_comments_from_ = block_.comments.size();
  }
  return nullptr;
}

WrittenNumber Reader::written_number(GostParser::SignContext* sign, GostParser::NumberContext* number, char letter) {
  WrittenNumber n;
  std::vector<antlr4::Token*> tokens;
  if (sign) {
    n.has_sign = true;
    n.negative = sign->MINUS() != nullptr;
    tokens.push_back(sign->getStart());
  }
  for (auto* child : number->children) {
    auto* terminal = dynamic_cast<antlr4::tree::TerminalNode*>(child);
    if (!terminal) continue;
    antlr4::Token* t = terminal->getSymbol();
    tokens.push_back(t);
    if (t->getType() == GostLexer::POINT)
      n.has_point = true;
    else
      (n.has_point ? n.after : n.before) += t->getText();
  }
  // Ignored characters between the digits are dropped (Table 2 note 2) but worth
  // a warning: `X10 30` is read as X1030.
  for (size_t i = 1; i < tokens.size(); ++i)
    if (tokens[i]->getStartIndex() != tokens[i - 1]->getStopIndex() + 1) {
      std::string as_read(1, letter);
      if (n.has_sign) as_read += n.negative ? '-' : '+';
      as_read += n.before + (n.has_point ? "." + n.after : "");
      diags_.report(DiagId::SpaceInNumber, range(tokens.front(), tokens.back()), std::string(1, letter), as_read);
      break;
    }
  return n;
}

antlrcpp::Any Reader::visitBlockNumber(GostParser::BlockNumberContext* ctx) {
  bool main = ctx->COLON() != nullptr;
  SourceRange r = range(ctx);
  if (seen_element_ || block_.number) {
    diags_.report(DiagId::BlockNumberPosition, r, ctx->getText());
    return nullptr;
  }
  seen_element_ = true;
  if (main && !s_.format.main_block) {
    diags_.report(DiagId::FeatureNotInFormat, r, "the main block ':'", ":");
    return nullptr;
  }
  block_number(main, written_number(ctx->sign(), ctx->number(), main ? ':' : 'N'), r, ctx->getText().substr(1));
  return nullptr;
}

void Reader::block_number(bool main, const WrittenNumber& n, SourceRange r, const std::string& text) {
  std::string address = main ? ":" : "N";
  const char letter = main ? ':' : 'N';
  if (main && n.before.empty() && n.after.empty()) {
    diags_.report(DiagId::MainBlockNoDigits, r);
    return;
  }
  const WordFormat* format = s_.format.word('N');
  if (!format) {
    diags_.report(DiagId::AddressUndefined, r, "N");
    return;
  }
  auto value = decode(letter, *format, n, s_.decode, r, diags_);
  if (!value) return;
  block_.number = whole_in<uint32_t>(*value, 0, UINT32_MAX);  // at most 9 digits: the format
  block_.main_block = main;
  ir::Word w;
  w.kind = ir::WordKind::BlockNumber;
  w.slot = static_cast<uint8_t>(letter_slot('N'));
  w.address = address;
  w.text = text;
  w.value = program_.number(*value, r);
  w.range = r;
  block_.words.push_back(std::move(w));
}

int32_t Reader::code_index(char letter, int number) {
  const auto& table = letter == 'G' ? s_.tables.g_codes : s_.tables.m_codes;
  auto it = table.find(number);
  return it == table.end() ? -1 : program_code(program_, it->second.desc);
}

antlrcpp::Any Reader::visitWord(GostParser::WordContext* ctx) {
  seen_element_ = true;
  char letter = ctx->LETTER()->getText()[0];
  address_word(letter, written_number(ctx->sign(), ctx->number(), letter), range(ctx), ctx->getText().substr(1));
  return nullptr;
}

void Reader::address_word(char letter, const WrittenNumber& n, SourceRange r, std::string text) {
  ir::Word w;
  w.slot = static_cast<uint8_t>(letter_slot(letter));
  w.address = std::string(1, letter);
  w.text = std::move(text);
  w.range = r;
  w.optional = optional_rest_;
  // Table 1 note 2: the format of the NC says which addresses exist.
  const WordFormat* format = s_.format.word(letter);
  if (!format) {
    diags_.report(DiagId::AddressUndefined, r, std::string(1, letter));
    w.kind = ir::WordKind::Ignored;
    block_.words.push_back(std::move(w));
    return;
  }
  auto value = decode(letter, *format, n, s_.decode, r, diags_);
  if (!value) {
    w.kind = ir::WordKind::Ignored;
    block_.words.push_back(std::move(w));
    return;
  }
  w.value = program_.number(*value, r);
  if (letter == 'G' || letter == 'M') {
    w.kind = ir::WordKind::Code;
    w.code = code_index(letter, ir::code_number(program_, w.value));
  }
  if (letter == 'T' && s_.tool_digits > 0) {
    // §3.3.5: T may carry the tool number and then the offset number.
    int scale = 1;
    for (int i = 0; i < s_.offset_digits; ++i) scale *= 10;
    const int all = whole_in(*value, 0, INT32_MAX).value_or(0);  // at most 9 digits: the format
    int tool = all / scale, offset = all % scale;
    if (tool == 0 && all != 0)
      diags_.report(DiagId::ToolSplitZero, r, "T" + w.text, tool, offset, s_.tool_digits + s_.offset_digits);
    program_.exprs[w.value].number = tool;
    ir::Word d = w;
    d.slot = static_cast<uint8_t>(letter_slot('D'));
    d.value = program_.number(offset, r);
    d.address = "D";
    d.text = std::to_string(offset);
    d.derived = true;
    block_.words.push_back(std::move(w));
    block_.words.push_back(std::move(d));
    return;
  }
  block_.words.push_back(std::move(w));
  return;
}

// `[N<number>] {<letter>[sign]<number>}`, blanks between the words only: the common
// block. A blank inside a word, '/', ':', a comment, a damaged number or anything
// else is for the parser. Nothing is changed before the whole line is known plain.
bool Reader::scan_plain(std::string_view t) {
  static constexpr PlainRules kRules{"ABCDEFGHIJKLMNOPQRSTUVWXYZ"};
  PlainBlock& block = plain_;
  if (!scan_plain_words(t, kRules, block)) return false;
  for (const PlainWord& p : block.words) {
    const SourceRange r{file_, line_no_, p.from + 1, line_no_, p.to + 1};
    const std::string text(t.substr(p.from + 1, p.to - p.from - 1));
    const WrittenNumber number{p.sign != 0, p.sign == '-', std::string(p.before), p.point, std::string(p.after)};
    seen_element_ = true;
    if (p.letter == 'N')
      block_number(false, number, r, text);
    else
      address_word(p.letter, number, r, text);
  }
  return true;
}

void Reader::check_comment_text(antlr4::Token* token) {
  // §1.5: '%' and ':' must not be used inside the parentheses.
  size_t begin = token->getStartIndex();
  size_t end = token->getStopIndex();
  for (size_t i = begin + 1; i <= end && i < line_text_.size(); ++i) {
    char c = line_text_[i];
    if (c != '%' && c != ':') continue;
    uint32_t col = base_ + static_cast<uint32_t>(i) + 1;
    const SourceRange at{file_, line_no_, col, line_no_, col + 1};
    if (c == '%')
      diags_.report(DiagId::CommentPercent, at);
    else
      diags_.report(DiagId::CommentColon, at);
  }
}

antlrcpp::Any Reader::visitComment(GostParser::CommentContext* ctx) {
  antlr4::Token* t = ctx->getStart();
  check_comment_text(t);
  size_t begin = t->getStartIndex();
  size_t length = t->getStopIndex() - begin + 1;
  if (ctx->OPEN_COMMENT()) {
    diags_.report(DiagId::CommentUnterminated, range(t, t));
    block_.comments.emplace_back(line_text_.substr(begin + 1, length - 1));
  } else {
    block_.comments.emplace_back(line_text_.substr(begin + 1, length - 2));
  }
  return nullptr;
}

class GostFrontend final : public DialectFrontend<Settings> {
 public:
  explicit GostFrontend(Settings settings) : DialectFrontend(std::move(settings)) {
    rules_.pedantic = s_.decode.mode == Mode::Pedantic;
  }

  ir::Program read(SourceManager& sources, uint32_t file, Diagnostics& diags, const ReadOptions& options) override {
    ir::Program program = start_program("gost", file);
    Reader reader(s_, program, sources.file(file), file, diags, options);
    if (admit_text(sources.file(file), file, diags)) reader.run();
    // §8: the functions set at power-on and after M02/M30 for the control type.
    set_power_on(program, s_.tables, s_.tables.power_on.at(s_.control_type));
    return program;
  }
};

}  // namespace

std::unique_ptr<Frontend> make_gost_frontend(const stdlib::Profile& profile, Diagnostics& diags) {
  return make_dialect_frontend<GostFrontend>(load_settings(profile, diags));
}

}  // namespace ncc::gost
