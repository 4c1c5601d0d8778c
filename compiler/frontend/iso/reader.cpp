#include "reader.h"

#include <algorithm>
#include <bitset>
#include <charconv>
#include <cmath>
#include <set>

#include "foreign.h"
#include "frontend/block_errors.h"
#include "frontend/frontend.h"
#include "frontend/limits.h"
#include "support/numbers.h"
#include "support/text.h"

namespace ncc::iso {

namespace {

constexpr uint32_t kMaxCount = 999;  // L of M97, M98, G65 (§8.16, §8.33)
constexpr int kMaxLoopDepth = 3;     // DO1..DO3 (§8.34.3)
// The words the fast path reads (scan_plain): every address but O.
constexpr PlainRules kPlainRules{"ABCDEFGHIJKLMNPQRSTUVWXYZ", true, true, true};

// #0..#33 are local to a macro call (§8.16), #100..#199 and #500..#999 common
// (decision 3); #0 is always vacant.
bool variable_exists(uint32_t n) { return n <= 33 || (n >= 100 && n <= 199) || (n >= 500 && n <= 999); }

// A code's value as written agrees with its key (code_key): a number written with a
// point has one digit after it and is a decimal code (G54.1, not G1. or G01.0).
bool decimal_form(std::string_view text, int key) {
  const size_t point = text.find('.');
  if (point == std::string_view::npos || text.find('[') != std::string_view::npos) return true;
  return key >= kDecimalCode && point + 2 == text.size();
}

// G65 argument specification I (§8.16): the letter's local variable; 0 = not an argument.
uint32_t argument_of(char letter) {
  switch (letter) {
    case 'A': return 1;
    case 'B': return 2;
    case 'C': return 3;
    case 'I': return 4;
    case 'J': return 5;
    case 'K': return 6;
    case 'D': return 7;
    case 'E': return 8;
    case 'F': return 9;
    case 'H': return 11;
    case 'M': return 13;
    case 'Q': return 17;
    case 'R': return 18;
    case 'S': return 19;
    case 'T': return 20;
    case 'U': return 21;
    case 'V': return 22;
    case 'W': return 23;
    case 'X': return 24;
    case 'Y': return 25;
    case 'Z': return 26;
    default: return 0;
  }
}

}  // namespace

// A stretch of text between block ends: a block, or a brace of a multi-line IF.
struct Reader::Piece {
  enum Kind { Text, Open, Close } kind = Text;
  uint32_t line = 0, col = 0;                       // 1-based, of its first character
  size_t begin = 0, end = 0;                        // byte offsets in the file
  std::vector<std::pair<size_t, size_t>> comments;  // byte ranges of '(' ... ')'
  bool semicolon = false;                           // ends at ';' (an empty one is an empty block)
};

// An open WHILE/DO loop (§8.34.3).
struct Reader::Loop {
  int index = 0;
  SourceRange range;
  size_t do_block = 0;
  std::optional<size_t> exit;  // the WHILE's jump out (the block's stmt)
  ir::ExprId cond = ir::kNoExpr;
  std::optional<size_t> body;  // its first block
};

// An open multi-line IF (§8.34.2): the jump to the next branch, the jumps to its end.
struct Reader::Branch {
  SourceRange range;
  std::optional<std::pair<size_t, size_t>> next;  // (block, stmt) of the condition's false jump
  std::vector<std::pair<size_t, size_t>> exits;   // the jumps of the bodies to the end
  bool in_body = false, closed = false, has_else = false;
  std::optional<size_t> close_block;  // the '}' block of the last body
  SourceRange head;                   // of its last IF, ELIF or ELSE
};

std::string Reader::program_name(uint32_t number) { return fmt::format("O{:04}", number); }

Reader::Reader(const Settings& settings, ir::Program& program, const SourceFile& source, uint32_t file,
               Diagnostics& diags, uint16_t space, std::optional<std::string> called, bool fast_path, BlockSink* sink)
    : s_(settings), program_(program), source_(source), file_(file), diags_(diags), space_(space),
      called_(std::move(called)), fast_path_(fast_path), sink_(sink),
      errors_(std::make_unique<BlockErrors>(
          BlockTokens{IsoLexer::INVALID,
                      IsoLexer::LETTER,
                      {IsoLexer::PLUS, IsoLexer::MINUS, IsoLexer::NUMBER, IsoLexer::HASH, IsoLexer::LBRACKET}},
          diags)) {
  lexer_.removeErrorListeners();
  parser_.removeErrorListeners();
  parser_.addErrorListener(errors_.get());
  parser_.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(antlr4::atn::PredictionMode::SLL);
}

Reader::~Reader() = default;

void Reader::run() {
  // Decision 56: another control's language is told once, and the file is not read.
  if (auto f = foreign_language(source_)) {
    diags_.report(DiagId::ForeignLanguage, SourceRange::point(file_, f->line, 1), f->language, f->evidence);
    return;
  }
  if (called_) start_unit(ir::UnitKind::Subprogram, *called_, SourceRange::point(file_, 1, 1));
  cut();
  if (nested_at_)
    diags_.report(DiagId::CommentNested, *nested_at_,
                  nested_lines_ ? fmt::format(" (and on {} more line{})", nested_lines_, nested_lines_ > 1 ? "s" : "")
                                : std::string());
  if (semicolon_at_)
    diags_.report(DiagId::SemicolonComment, *semicolon_at_,
                  semicolon_lines_
                      ? fmt::format(" (and {} more line{})", semicolon_lines_, semicolon_lines_ > 1 ? "s" : "")
                      : std::string());
  if (in_unit_) end_unit();
}

// Blocks of comments alone (a title line before the O number) are no program yet.
bool Reader::holds_program(const ir::Block& b) { return !b.words.empty() || !b.stmts.empty(); }

void Reader::take(const Piece& p) {
  if (diags_.limit_reached()) return;
  switch (p.kind) {
    case Piece::Text: read(p); break;
    case Piece::Open: open_brace(p); break;
    case Piece::Close: close_brace(p); break;
  }
  // The blocks read so far go to the sink when nothing refers back to them: no loop
  // or IF open, no chamfer waiting for its move, the main program's end not yet read;
  // and not while they are comments alone, which an O number may still name.
  if (sink_ && in_unit_ && unit_.kind == ir::UnitKind::Program && loops_.empty() && branches_.empty() &&
      !expect_brace_ && !corner_ && !end_block_ &&
      (unit_.streamed || std::any_of(unit_.blocks.begin(), unit_.blocks.end(), holds_program)))
    sink_->take(program_, unit_);
}

// ---- Cutting the text -------------------------------------------------------------

// Cuts the text into blocks at ';' and line ends, and braces, and reads each as it
// is cut: nothing of the whole text is held.
void Reader::cut() {
  bool started = false;  // a '%' line was seen (the tape start)
  Piece piece;
  for (uint32_t line_no = 1; line_no <= source_.line_count(); ++line_no) {
    std::string_view line = source_.line(line_no);
    const size_t base = source_.line_offset(line_no);
    std::string_view trimmed = trim(line);
    // '%' alone on a line marks the start and the end of the tape.
    if (trimmed == "%") {
      if (started) {
        for (uint32_t rest = line_no + 1; rest <= source_.line_count(); ++rest)
          if (!trim(source_.line(rest)).empty()) {
            diags_.report(DiagId::TrailerIgnored, SourceRange::point(file_, rest, 1));
            break;
          }
        return;
      }
      started = true;
      continue;
    }
    auto start = [&](uint32_t col, size_t at) {
      piece.kind = Piece::Text;
      piece.line = line_no;
      piece.col = col;
      piece.begin = piece.end = at;
      piece.comments.clear();
    };
    start(1, base);
    auto close = [&](size_t at) {
      piece.end = at;
      piece.semicolon = at < base + line.size() && line[at - base] == ';';
      take(piece);
      start(static_cast<uint32_t>(at - base + 2), at + 1);
    };
    bool rest_is_comment = false;
    for (size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (c == '(') {
        // A comment runs to its ')' on the same line. Comments do not nest: one that
        // does is reported once a file (decision 55) and read to its matching ')'.
        size_t end = std::string_view::npos;
        bool nested = false;
        for (size_t j = i, depth = 0; j < line.size() && end == std::string_view::npos; ++j) {
          if (line[j] == '(' && depth++ > 0) nested = true;
          if (line[j] == ')' && --depth == 0) end = j;
        }
        if (end == std::string_view::npos) end = line.find(')', i + 1);
        if (nested && end != std::string_view::npos) {
          const auto col = static_cast<uint32_t>(i + 1);
          if (!nested_at_)
            nested_at_ = SourceRange{file_, line_no, col, line_no, static_cast<uint32_t>(end + 2)};
          else if (nested_line_ != line_no)
            ++nested_lines_;
          nested_line_ = line_no;
        }
        if (end == std::string_view::npos) {
          diags_.report(DiagId::CommentUnterminated, {file_, line_no, static_cast<uint32_t>(i + 1), line_no,
                                                      static_cast<uint32_t>(line.size() + 1)});
          end = line.size() - 1;
        }
        piece.comments.push_back({base + i, base + end + 1});
        i = end;
      } else if (c == ';') {
        close(base + i);
        if (semicolon_comment(line, i, line_no)) {
          rest_is_comment = true;
          break;
        }
      } else if (c == '%') {
        // Decision 55: '%' after a block (`N890 %`) ends it; it belongs on a line of its own.
        diags_.report(DiagId::PercentInBlock, SourceRange::point(file_, line_no, static_cast<uint32_t>(i + 1)));
        close(base + i);
      } else if (c == '{' || c == '}') {
        close(base + i);
        take(
            {c == '{' ? Piece::Open : Piece::Close, line_no, static_cast<uint32_t>(i + 1), base + i, base + i + 1, {}});
      }
    }
    if (!rest_is_comment) close(base + line.size());
  }
}

// Decision 54: `; text` as Mach3 and LinuxCNC comment. With iso.semicolon_comments the
// ';' at `at` starts a comment to the end of the line; otherwise it does when the text
// after it (to the next ';' or brace) is no block, which is reported once a file.
bool Reader::semicolon_comment(std::string_view line, size_t at, uint32_t line_no) {
  if (s_.semicolon_comments) return true;
  size_t end = at + 1;
  for (bool comment = false; end < line.size(); ++end) {
    const char c = line[end];
    if (!comment && (c == ';' || c == '{' || c == '}')) break;
    comment = c == '(' || (comment && c != ')');
  }
  if (is_block(line.substr(at + 1, end - at - 1))) return false;
  const auto col = static_cast<uint32_t>(at + 1);
  if (!semicolon_at_)
    semicolon_at_ = SourceRange{file_, line_no, col, line_no, col + 1};
  else
    ++semicolon_lines_;
  return true;
}

bool Reader::is_block(std::string_view text) {
  std::string& t = sanitized_;
  t.assign(text);
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '(') {
      const size_t shut = t.find(')', i);
      if (shut == std::string::npos) return false;
      std::fill(t.begin() + static_cast<std::ptrdiff_t>(i), t.begin() + static_cast<std::ptrdiff_t>(shut) + 1, ' ');
    } else if (t[i] >= 'a' && t[i] <= 'z') {
      t[i] = static_cast<char>(t[i] - 'a' + 'A');
    } else if (static_cast<unsigned char>(t[i]) >= 0x80) {
      return false;
    }
  }
  if (trim(t).empty() || scan_plain_words(t, kPlainRules, plain_words_)) return true;
  input_.load(t);
  lexer_.setInputStream(&input_);
  tokens_.setTokenSource(&lexer_);
  tokens_.fill();
  parser_.setTokenStream(&tokens_);
  errors_->start_quiet();
  parser_.block();
  return !errors_->any();
}

void Reader::load(const Piece& piece) {
  // Upper case outside comments (decision 2); comments become spaces; the typographic
  // dash the seed prints (U+2013) is a minus (decision 4); other bytes outside 7-bit
  // ASCII are U+0001, which the lexer reports. Every column stays a byte offset.
  sanitized_.assign(source_.text().substr(piece.begin, piece.end - piece.begin));
  for (auto [from, to] : piece.comments)
    for (size_t i = from; i < to; ++i) sanitized_[i - piece.begin] = ' ';
  for (size_t i = 0; i < sanitized_.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(sanitized_[i]);
    if (c >= 'a' && c <= 'z') {
      sanitized_[i] = static_cast<char>(c - 'a' + 'A');
    } else if (c == 0xE2 && sanitized_.compare(i, 3, "\xE2\x80\x93") == 0) {
      sanitized_.replace(i, 3, "-  ");
      uint32_t col = piece.col + static_cast<uint32_t>(i);
      diags_.report(DiagId::TypographicDash, {file_, piece.line, col, piece.line, col + 1});
      i += 2;
    } else if (c >= 0x80) {
      sanitized_[i] = '\x01';
    }
  }
  line_ = piece.line;
  base_ = piece.col - 1;
  errors_->start(file_, line_, source_.line(line_), sanitized_.size(),
                 [this](size_t i) { return base_ + static_cast<uint32_t>(i) + 1; });
}

IsoParser::BlockContext* Reader::parse() {
  // The tokens first: a block beyond the limits of nesting and length is not parsed.
  static const ExpressionTokens kTokens{
      {IsoLexer::LBRACKET},
      {IsoLexer::RBRACKET},
      {IsoLexer::PLUS, IsoLexer::MINUS},
      {IsoLexer::STAR, IsoLexer::SLASH, IsoLexer::MOD, IsoLexer::AND, IsoLexer::OR, IsoLexer::XOR, IsoLexer::EQ,
       IsoLexer::NE, IsoLexer::GT, IsoLexer::GE, IsoLexer::LT, IsoLexer::LE},
      {IsoLexer::NUMBER, IsoLexer::RBRACKET}};
  if (!lex_block(
          sanitized_, input_, lexer_, tokens_, kTokens,
          [this](antlr4::Token* a, antlr4::Token* b) { return range(a, b); }, diags_))
    return nullptr;
  parser_.setTokenStream(&tokens_);
  return parser_.block();
}

SourceRange Reader::range(antlr4::Token* first, antlr4::Token* last) const {
  uint32_t begin = base_ + static_cast<uint32_t>(first->getStartIndex()) + 1;
  uint32_t end = base_ + static_cast<uint32_t>(last->getStopIndex()) + 2;
  if (last->getType() == antlr4::Token::EOF || end < begin) end = begin + 1;
  return {file_, line_, begin, line_, end};
}

// ---- Units and blocks ------------------------------------------------------------------

void Reader::start_unit(ir::UnitKind kind, std::string name, SourceRange r) {
  if (in_unit_) end_unit();
  unit_ = ir::Unit{};
  unit_.kind = kind;
  unit_.name = std::move(name);
  unit_.range = r;
  in_unit_ = true;
}

void Reader::end_unit() {
  if (unit_.kind == ir::UnitKind::Program) end_main();
  for (const Loop& l : loops_) {
    diags_.report(DiagId::RepeatUnbalanced, l.range, fmt::format("DO{} has no END{} in its program", l.index, l.index));
    unit_.blocks[l.do_block].has_errors = true;  // its jump out has nowhere to go
  }
  loops_.clear();
  if (expect_brace_) {
    diags_.report(DiagId::ProgramStructure, branches_.back().head, "a multi-line IF needs its '{'");
    drop_branch();
  }
  // A multi-line IF still open at the end: its last '}' ends it, if it has one.
  while (!branches_.empty()) {
    if (branches_.back().closed) {
      finish_branch();
      continue;
    }
    diags_.report(DiagId::ProgramStructure, branches_.back().range, "this IF has no closing '}' in its program");
    drop_branch();
  }
  // §8.33 (E-29): M97 subprograms stand after M02/M30, at a block that exists. (A
  // block compiled while it was read stands before them.)
  std::set<std::string> called, streamed;
  for (const LocalCall& call : local_calls_) called.insert(call.label);
  if (!called.empty())
    for (const ir::Unit::StreamedLabel& l : unit_.streamed_labels)
      if (called.count(l.label())) streamed.insert(l.label());
  for (const LocalCall& call : local_calls_) {
    const bool was_streamed = streamed.count(call.label) > 0;
    size_t i = 0;
    while (!was_streamed && i < unit_.blocks.size() && unit_.blocks[i].label != call.label) ++i;
    if (!was_streamed && i == unit_.blocks.size()) {
      diags_.report(DiagId::LabelUndefined, call.range, "M97 to", call.label);
      unit_.blocks[call.block].has_errors = true;
    } else if (was_streamed || (unit_.kind == ir::UnitKind::Program && (!end_block_ || i <= *end_block_))) {
      diags_.report(DiagId::ProgramStructure, call.range,
                    fmt::format("M97 calls {}, which stands before M02/M30: an internal subprogram is written after "
                                "the end of the main program",
                                call.label));
      unit_.blocks[call.block].has_errors = true;
    }
  }
  const std::vector<LocalCall> local_calls = std::move(local_calls_);
  local_calls_.clear();
  if (unit_.kind != ir::UnitKind::Program) {
    // E-23, E-28: a subprogram or macro ends with M99 (its last block that does anything).
    const ir::Block* last = nullptr;
    for (const ir::Block& b : unit_.blocks)
      if (!b.stmts.empty()) last = &b;
    const bool returns = last && std::any_of(last->stmts.begin(), last->stmts.end(), [](const ir::Stmt& s) {
                           return s.kind == ir::StmtKind::Return && s.cond == ir::kNoExpr;
                         });
    if (!returns)
      diags_.report(DiagId::ProgramStructure, last ? last->range : unit_.range,
                    fmt::format("{} does not end with M99", unit_.name));
  }
  // §8.34.2 (A-46): a block number used twice that a GOTO or M97 names: it goes to the
  // first. (CAM output numbers its blocks round and round: only a target matters.)
  std::set<std::string> targets;
  for (const ir::Block& b : unit_.blocks)
    for (const ir::Stmt& s : b.stmts)
      if (s.kind == ir::StmtKind::Jump && !s.label.empty()) targets.insert(s.label);
  for (const LocalCall& call : local_calls) targets.insert(call.label);
  std::map<uint32_t, SourceRange> numbers;
  auto repeated = [&](const std::optional<uint32_t>& number, SourceRange range) {
    if (number && targets.count(fmt::format("N{}", *number)))
      if (auto [it, fresh] = numbers.emplace(*number, range); !fresh)
        if (Diagnostic* d = diags_.report(DiagId::BlockNumberRepeated, range, *number, unit_.name))
          d->notes.push_back({it->second, "a GOTO or M97 goes here"});
  };
  for (const ir::Unit::StreamedLabel& l : unit_.streamed_labels) repeated(l.number, l.range);
  for (const ir::Block& b : unit_.blocks) repeated(b.number, b.range);
  program_.units.push_back(std::move(unit_));
  unit_ = ir::Unit{};
  in_unit_ = false;
}

ir::Block& Reader::new_block(SourceRange r) {
  if (!in_unit_) start_unit(ir::UnitKind::Program, "%", r);
  unit_.blocks.emplace_back();
  ir::Block& b = unit_.blocks.back();
  b.range = r;
  for (Loop& l : loops_)
    if (!l.body) l.body = unit_.blocks.size() - 1;
  return b;
}

std::string Reader::label_of(size_t block) {
  ir::Block& b = unit_.blocks[block];
  if (b.label.empty()) b.label = fmt::format("@{}", ++next_label_);
  return b.label;
}

// ---- Braces of the multi-line IF ------------------------------------------------------

void Reader::open_brace(const Piece& at) {
  SourceRange r = SourceRange::point(file_, at.line, at.col);
  if (!expect_brace_ || branches_.empty()) {
    diags_.report(DiagId::ProgramStructure, r, "'{' opens the body of IF, ELIF or ELSE and stands after its condition");
    return;
  }
  expect_brace_ = false;
  branches_.back().in_body = true;
}

// An ELIF or ELSE that continues no IF (reported): its body is read as a body of
// nothing, so that its braces raise no more errors.
void Reader::orphan_head(SourceRange r) {
  new_block(r).has_errors = true;
  branches_.push_back({r, std::nullopt, {}, false, false, true, std::nullopt, r});
  expect_brace_ = true;
}

// A multi-line IF that cannot be completed (reported): its jumps have nowhere to go,
// so the blocks that hold them have errors.
void Reader::drop_branch() {
  const Branch& b = branches_.back();
  for (auto [block, stmt] : b.exits) unit_.blocks[block].has_errors = true;
  if (b.next) unit_.blocks[b.next->first].has_errors = true;
  branches_.pop_back();
  expect_brace_ = false;
}

// A closed multi-line IF that no ELIF or ELSE continues: its jumps land on its last '}'.
void Reader::finish_branch() {
  Branch& b = branches_.back();
  std::string end = label_of(*b.close_block);
  if (b.next) unit_.blocks[b.next->first].stmts[b.next->second].label = end;
  for (auto [block, stmt] : b.exits) unit_.blocks[block].stmts[stmt].label = end;
  branches_.pop_back();
}

void Reader::close_brace(const Piece& at) {
  SourceRange r = SourceRange::point(file_, at.line, at.col);
  // An IF that was the last thing of the body this brace closes ends with it.
  while (!branches_.empty() && branches_.back().closed) finish_branch();
  if (branches_.empty() || !branches_.back().in_body) {
    diags_.report(DiagId::ProgramStructure, r, "'}' without the '{' of an IF, ELIF or ELSE body");
    return;
  }
  new_block(r);
  Branch& b = branches_.back();
  b.in_body = false;
  b.closed = true;
  b.close_block = unit_.blocks.size() - 1;
}

// ---- Blocks -----------------------------------------------------------------------------

void Reader::read(const Piece& piece) {
  SourceRange whole{file_, piece.line, piece.col, piece.line,
                    piece.col + static_cast<uint32_t>(piece.end - piece.begin)};
  if (!block_fits(piece.end - piece.begin, whole, diags_)) {
    corner_.reset();
    ir::Block& refused = new_block(whole);
    refused.has_errors = refused.unread = true;
    return;
  }
  load(piece);
  if (trim(sanitized_).empty() && piece.comments.empty()) {
    // §8.3 (E-05): an empty block (a lone ';') cannot follow a chamfer or fillet.
    if (corner_ && piece.semicolon) {
      const uint32_t col = piece.col + static_cast<uint32_t>(piece.end - piece.begin);
      diags_.report(DiagId::ProgramStructure, SourceRange::point(file_, piece.line, col),
                    "an empty block cannot follow a block with a chamfer or fillet (E-05)");
      corner_.reset();
    }
    return;
  }
  std::vector<std::string> comments;
  for (auto [from, to] : piece.comments) comments.emplace_back(source_.text().substr(from + 1, to - from - 2));
  // §8.3 (E-05): what follows a chamfer or fillet is a move, not an empty or comment block.
  const bool after_corner = corner_.has_value();
  if (after_corner && trim(sanitized_).empty()) {
    diags_.report(DiagId::ProgramStructure, whole,
                  "a comment block cannot follow a block with a chamfer or fillet (E-05)");
    new_block(whole).has_errors = true;
    corner_.reset();
  }
  corner_.reset();
  if (trim(sanitized_).empty()) {
    // A comment alone: kept for the listing, runs nothing (an ELSE may follow it).
    new_block(whole).comments = std::move(comments);
    return;
  }

  // Most blocks are address words only: the hand-written scanner reads them, ANTLR the
  // rest (both give the same IR: tests/fastpath).
  FastBlock& plain = fast_;
  const bool fast = fast_path_ && scan_plain(plain);
  // E-32: brackets that do not pair up.
  const auto open = fast ? 0 : std::count(sanitized_.begin(), sanitized_.end(), '[');
  const auto shut = fast ? 0 : std::count(sanitized_.begin(), sanitized_.end(), ']');
  IsoParser::BlockContext* ctx = nullptr;
  if (open != shut) {
    diags_.report(DiagId::BracketsUnbalanced, whole, open, shut);
  } else if (!fast) {
    ctx = parse();
  }
  const bool bad = !fast && (!ctx || errors_->any());
  IsoParser::BodyContext* body = bad || fast ? nullptr : ctx->body();
  auto* head = body ? body->braceHead() : nullptr;

  // After a '}': ELIF or ELSE continues the IF; anything else ends it.
  bool continues = false;
  if (!branches_.empty() && branches_.back().closed) {
    Branch& b = branches_.back();
    if (head && !head->IF() && !b.has_else) {
      // The body before jumps to the end; the false condition lands here.
      ir::Block& close = unit_.blocks[*b.close_block];
      close.stmts.push_back({ir::StmtKind::Jump, close.range});
      b.exits.push_back({*b.close_block, close.stmts.size() - 1});
      b.closed = false;
      continues = true;
    } else {
      finish_branch();
      if (head && !head->IF()) {
        diags_.report(DiagId::ProgramStructure, range(head),
                      fmt::format("{} follows the ELSE of its IF", head->ELSE() ? "ELSE" : "ELIF"));
        orphan_head(whole);
        return;
      }
    }
  }
  if (head && !head->IF() && !continues) {
    diags_.report(DiagId::ProgramStructure, range(head),
                  fmt::format("{} has no IF before it: it continues a multi-line IF right after its '}}'",
                              head->ELSE() ? "ELSE" : "ELIF"));
    orphan_head(whole);
    return;
  }
  if (expect_brace_) {
    diags_.report(DiagId::ProgramStructure, whole, "a multi-line IF needs its '{' before the next block");
    drop_branch();
  }

  ir::Block& block = new_block(whole);
  const size_t index = unit_.blocks.size() - 1;
  block.comments = std::move(comments);
  if (bad) {
    block.has_errors = true;
    return;
  }
  block_ = ir::Block{};
  block_.range = whole;
  if (fast) {
    block_.skippable = plain.skip;
    block_.has_errors = plain.has_errors;
    if (plain.sequence) number_block(plain.sequence->first, plain.sequence->second, index);
    words(plain.words, nullptr, ir::kNoExpr);
    return finish_read(index);
  }
  block_.skippable = ctx->SLASH() != nullptr;
  if (auto* seq = ctx->SEQUENCE())
    number_block(std::string(trim(seq->getText().substr(1))), range(seq->getSymbol(), seq->getSymbol()), index);

  if (auto* prog = ctx->PROGRAM()) {
    // §8.16, §8.33: OXXXX alone in its block starts a subprogram or macro.
    const char address = prog->getText()[0];  // O, or ISO code's ':' (decision 53)
    std::string digits(trim(prog->getText().substr(1)));
    SourceRange r = range(prog->getSymbol(), prog->getSymbol());
    uint32_t n = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
    // The program's title is the comment of its O block ("O1003 (BRACKET)").
    std::string title;
    for (const std::string& c : unit_.blocks.back().comments) title += (title.empty() ? "" : " ") + c;
    unit_.blocks.pop_back();
    if (ec != std::errc() || n > s_.max_program) {
      program_range(r, address + digits, std::string(1, address));
      return;
    }
    const std::string name = program_name(n);
    const bool blocks_before = std::any_of(unit_.blocks.begin(), unit_.blocks.end(), holds_program);
    if (called_) {
      if (name != *called_ || blocks_before)
        diags_.report(DiagId::ProgramStructure, r,
                      fmt::format("{} stands in the file of {}: a program file holds its own program", name, *called_));
      return;
    }
    if (unit_.kind == ir::UnitKind::Program && !blocks_before && !unit_.streamed && in_unit_ && unit_.name == "%") {
      unit_.name = name;  // the main program's own number
      unit_.range = r;
      unit_.title = std::move(title);
      return;
    }
    if (!in_unit_) {
      start_unit(ir::UnitKind::Program, name, r);
      unit_.title = std::move(title);
      return;
    }
    if (unit_.kind == ir::UnitKind::Program && !main_done_ && !main_is_macro())
      diags_.report(DiagId::ProgramStructure, r,
                    fmt::format("{} starts before the main program ends: subprograms and macros follow M02/M30", name));
    for (const ir::Unit& u : program_.units)
      if (u.name == name) diags_.report(DiagId::ProgramStructure, r, fmt::format("{} is defined twice", name));
    if (unit_.name == name) diags_.report(DiagId::ProgramStructure, r, fmt::format("{} is defined twice", name));
    start_unit(ir::UnitKind::Subprogram, name, r);
    unit_.title = std::move(title);
    return;
  }

  ir::ExprId cond = ir::kNoExpr;
  if (body) {
    if (auto* a = body->assignment()) {
      block_.stmts.push_back(assignment(a));
    } else if (auto* g = body->gotoStmt()) {
      block_.stmts.push_back(go_to(g));
    } else if (auto* i = body->ifStmt()) {
      cond = condition(i->expr(), "IF");
      if (auto* g2 = i->gotoStmt()) {
        ir::Stmt j = go_to(g2);
        j.cond = cond;
        block_.stmts.push_back(std::move(j));
      } else if (auto* a2 = i->assignment()) {
        ir::Stmt s = assignment(a2);
        s.cond = cond;
        block_.stmts.push_back(std::move(s));
      } else {
        words(i->words(), cond);
      }
    } else if (head) {
      if (head->IF())
        branches_.push_back({range(head), std::nullopt, {}, false, false, false, std::nullopt, range(head)});
      Branch& b = branches_.back();
      b.head = range(head);
      if (b.next) unit_.blocks[b.next->first].stmts[b.next->second].label = label_of(index);
      b.next.reset();
      if (head->expr()) {
        ir::Stmt j{ir::StmtKind::Jump, range(head)};
        j.cond = program_.add({ir::ExprOp::Not, Builtin::Sin, 0, 0, condition(head->expr(), head->IF() ? "IF" : "ELIF"),
                               ir::kNoExpr, range(head)});
        block_.stmts.push_back(std::move(j));
        b.next = std::pair{index, block_.stmts.size() - 1};
      } else {
        b.has_else = true;
      }
      expect_brace_ = true;
    } else if (auto* w = body->whileStmt()) {
      const int n = parse_number<int>(w->NUMBER()->getText()).value_or(0);
      SourceRange r = range(w);
      if (w->NUMBER()->getText().find('.') != std::string::npos || n < 1 || n > kMaxLoopDepth)
        diags_.report(DiagId::RepeatUnbalanced, r,
                      fmt::format("the loop index is 1, 2 or 3, not {}", w->NUMBER()->getText()));
      Loop loop{n, r, index, std::nullopt, ir::kNoExpr, std::nullopt};
      for (const Loop& l : loops_)
        if (l.index == n)
          diags_.report(DiagId::RepeatUnbalanced, r,
                        fmt::format("DO{} stands inside the loop DO{} of the same index", n, n));
      if (loops_.size() == kMaxLoopDepth) diags_.report(DiagId::RepeatDepth, r, loops_.size() + 1, kMaxLoopDepth);
      if (w->WHILE()) {
        loop.cond = condition(w->expr(), "WHILE");
        ir::Stmt j{ir::StmtKind::Jump, r};
        j.cond = program_.add({ir::ExprOp::Not, Builtin::Sin, 0, 0, loop.cond, ir::kNoExpr, r});
        block_.stmts.push_back(std::move(j));
        loop.exit = block_.stmts.size() - 1;
      }
      loops_.push_back(loop);
    } else if (auto* e = body->endStmt()) {
      const int n = parse_number<int>(e->NUMBER()->getText()).value_or(0);
      SourceRange r = range(e);
      if (loops_.empty() || loops_.back().index != n) {
        diags_.report(DiagId::RepeatUnbalanced, r,
                      loops_.empty()
                          ? fmt::format("END{} has no DO{} before it", n, n)
                          : fmt::format("END{} stands where END{} closes the innermost loop", n, loops_.back().index));
        block_.has_errors = true;
      } else {
        Loop loop = loops_.back();
        loops_.pop_back();
        if (unit_.blocks[loop.do_block].has_errors) block_.has_errors = true;  // a broken WHILE does not loop
        const size_t body_start = loop.body.value_or(index);
        ir::Stmt back{ir::StmtKind::Jump, r};
        back.cond = loop.cond;
        back.label = label_of(body_start);
        block_.stmts.push_back(std::move(back));
        if (loop.exit) unit_.blocks[loop.do_block].stmts[*loop.exit].label = label_of(index);
      }
    } else if (auto* ws = body->words()) {
      words(ws, ir::kNoExpr);
    }
  }
  finish_read(index);
}

void Reader::finish_read(size_t index) {
  // The block read into block_ is the one new_block() made (a label may have been
  // given to it meanwhile).
  ir::Block& target = unit_.blocks[index];
  block_.label = target.label;
  block_.comments = std::move(target.comments);
  block_.has_errors = block_.has_errors || target.has_errors;
  target = std::move(block_);
  block_ = ir::Block{};
  if (unit_.kind == ir::UnitKind::Program && !main_done_ && !target.stmts.empty())
    main_returns_last_ = std::any_of(target.stmts.begin(), target.stmts.end(), [](const ir::Stmt& st) {
      return st.kind == ir::StmtKind::Return && st.cond == ir::kNoExpr;
    });
}

// Decision 71: a file whose first program is an O program ending in M99 (no M02/M30)
// is a library of macros, as Fanuc keeps O9xxx: its programs are called, not run.
bool Reader::main_is_macro() const {
  return !called_ && unit_.kind == ir::UnitKind::Program && unit_.name != "%" && !main_done_ && main_returns_last_;
}

// The main program ends (another O or the end of the file): a macro's M99 returns, a
// main program's ends the run (NC3044).
void Reader::end_main() {
  if (main_is_macro())
    program_.library = true;
  else
    for (const SourceRange& r : main_returns_) diags_.report(DiagId::ReturnInMain, r);
  main_returns_.clear();
}

void Reader::number_block(const std::string& digits, SourceRange r, size_t index) {
  uint32_t n = 0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (ec != std::errc() || n > kMaxBlockNumber) {
    diags_.report(DiagId::ValueRange, r, "N" + digits, "N", 0, kMaxBlockNumber);
    return;
  }
  block_.number = n;
  unit_.blocks[index].label = fmt::format("N{}", n);  // §8.34.2 (decision 5): N01 is N1
  ir::Word w;
  w.kind = ir::WordKind::BlockNumber;
  w.slot = static_cast<uint8_t>(letter_slot('N'));
  w.address = "N";
  w.text = digits;
  w.value = program_.number(n, r);
  w.range = r;
  block_.words.push_back(std::move(w));
}

// ---- The fast path --------------------------------------------------------------------------

// `[/] [N<digits>] {<letter> [sign] <number>}` with blanks anywhere between the parts,
// as the grammar reads them; anything else (a variable, a bracket, a keyword, O, a
// comma) is for the parser. Columns are those the parser would give.
bool Reader::scan_plain(FastBlock& out) {
  PlainBlock& block = plain_words_;
  out.words.clear();
  out.sequence.reset();
  out.has_errors = false;
  if (!scan_plain_words(sanitized_, kPlainRules, block)) return false;
  auto at = [&](size_t from, size_t to) {
    return SourceRange{file_, line_, base_ + static_cast<uint32_t>(from) + 1, line_,
                       base_ + static_cast<uint32_t>(to) + 1};
  };
  out.skip = block.skip;
  for (const PlainWord& p : block.words) {
    if (p.letter == 'N') {
      if (p.sign || p.point) return false;  // a sequence number is digits
      out.sequence = {std::string(p.before), at(p.from, p.to)};
      continue;
    }
    auto v = read_number(p.number, at(static_cast<size_t>(p.number.data() - sanitized_.data()), p.to), diags_);
    out.has_errors = out.has_errors || !v;
    RawWord w;
    w.letter = p.letter;
    w.value = program_.number(p.sign == '-' ? -v.value_or(0) : v.value_or(0), at(p.value_from, p.to));
    w.text = (p.sign ? std::string(1, p.sign) : std::string()) + std::string(p.number);
    w.range = at(p.from, p.to);
    w.literal = !p.point;
    out.words.push_back(std::move(w));
  }
  return true;
}

// A word of the parse tree; `address`: its value is an address's (ROUND keeps decimals).
Reader::RawWord Reader::raw_word(antlr4::tree::TerminalNode* letter, IsoParser::ValueContext* v, SourceRange r,
                                 bool address) {
  RawWord w;
  w.letter = letter->getText()[0];
  in_word_ = address;
  w.value = value(v, w.literal);
  in_word_ = false;
  w.text = v->getText();
  w.range = r;
  return w;
}

void Reader::words(IsoParser::WordsContext* ctx, ir::ExprId cond) {
  std::vector<RawWord> list;
  for (auto* wc : ctx->word()) list.push_back(raw_word(wc->LETTER(), wc->value(), range(wc), true));
  std::optional<RawWord> corner;
  if (ctx->COMMA())
    corner = raw_word(ctx->LETTER(), ctx->value(), range(ctx->COMMA()->getSymbol(), ctx->value()->getStop()), false);
  words(list, corner ? &*corner : nullptr, cond);
}

// ---- Statements ---------------------------------------------------------------------------

ir::Stmt Reader::assignment(IsoParser::AssignmentContext* ctx) {
  ir::Stmt s{ir::StmtKind::Assign, range(ctx)};
  s.target = variable(ctx->variable(), true);
  s.value = expr(ctx->expr());  // `#2 = #1` copies a vacant #1 (decision 3)
  return s;
}

ir::Stmt Reader::go_to(IsoParser::GotoStmtContext* ctx) {
  ir::Stmt s{ir::StmtKind::Jump, range(ctx)};
  bool literal = false;
  ir::ExprId target = value(ctx->value(), literal);
  if (program_.is_constant(target)) {
    // §8.34.2 (E-33): the target is a block number.
    const double n = program_.exprs[target].number;
    const std::optional<uint32_t> number = whole_in<uint32_t>(n, 0, kMaxBlockNumber);
    if (!number) {
      diags_.report(DiagId::ValueForm, range(ctx->value()), "GOTO", "a block number 0 to 99999", shortest(n));
      block_.has_errors = true;
      return s;  // no target: a block with errors does not jump
    }
    s.label = fmt::format("N{}", *number);
  } else {
    s.value = operand(target);  // found among the unit's numbered blocks at run time
  }
  return s;
}

ir::ExprId Reader::condition(IsoParser::ExprContext* ctx, const char* what) {
  ir::ExprId e = expr(ctx);
  // §8.34.2, §8.34.3 (E-34): a condition compares.
  std::vector<ir::ExprId> todo{e};
  bool compares = false;
  while (!todo.empty() && !compares) {
    const ir::Expr& x = program_.exprs[todo.back()];
    todo.pop_back();
    compares = x.op >= ir::ExprOp::Eq && x.op <= ir::ExprOp::Ge;
    if (x.op == ir::ExprOp::And || x.op == ir::ExprOp::Or || x.op == ir::ExprOp::Xor || x.op == ir::ExprOp::Not) {
      todo.push_back(x.a);
      if (x.b != ir::kNoExpr) todo.push_back(x.b);
    }
  }
  if (!compares) {
    diags_.report(DiagId::ConditionNoComparison, range(ctx), what);
    block_.has_errors = true;
  }
  return e;
}

std::optional<uint32_t> Reader::whole(const ir::Word& w, uint32_t min, uint32_t max, const char* what) {
  if (!program_.is_constant(w.value)) {
    diags_.report(DiagId::ValueForm, w.range, w.address, fmt::format("{} written as a number", what),
                  w.address + w.text);
    block_.has_errors = true;
    return std::nullopt;
  }
  const std::optional<uint32_t> v = whole_in(program_.exprs[w.value].number, min, max);
  if (!v) {
    diags_.report(DiagId::ValueForm, w.range, w.address, fmt::format("{}, a whole number {} to {}", what, min, max),
                  w.address + w.text);
    block_.has_errors = true;
  }
  return v;
}

void Reader::words(const std::vector<RawWord>& list, const RawWord* corner, ir::ExprId cond) {
  // The codes written as numbers: only those below 1000 are asked about.
  std::bitset<1000> g, m;
  const size_t first = block_.words.size();                      // after the block number
  block_.words.reserve(first + list.size() + (corner ? 1 : 0));  // the block keeps them: no spare room
  // §8.16: in a G65 block M is argument #13, not an M code.
  bool macro_call = false;
  for (const RawWord& r : list) macro_call = macro_call || (r.letter == 'G' && r.literal && r.text == "65");
  std::vector<bool>& literal_integer = literal_integer_;  // of each word from `first` on
  literal_integer.clear();
  // G10, G54.1, G154: P is an offset's number; a machine's G30 (decision 65): the
  // reference point's. Not thousandths.
  bool p_is_number = false;
  for (const RawWord& raw : list) {
    const char letter = raw.letter;
    const bool literal = raw.literal;
    const ir::ExprId e = raw.value;
    ir::Word w;
    w.slot = static_cast<uint8_t>(letter_slot(letter));
    w.address = std::string(1, letter);
    w.text = raw.text;
    w.range = raw.range;
    w.value = e;
    if (letter == 'N' || letter == 'O') {
      diags_.report(DiagId::BlockNumberPosition, w.range, w.address + w.text);
      w.kind = ir::WordKind::Ignored;
      block_.has_errors = true;
    } else if (letter == 'G' || (letter == 'M' && !macro_call)) {
      w.kind = ir::WordKind::Code;
      if (!program_.is_constant(e)) {
        w.code = ir::kDynamicCode;  // G#4 (§8.34.1): the code comes at run time
      } else if (const std::optional<int> n = code_key(program_.exprs[e].number); !n) {
        diags_.report(DiagId::ValueForm, w.range, w.address, "a code number", w.address + w.text);
        w.kind = ir::WordKind::Ignored;
        block_.has_errors = true;
      } else if (!decimal_form(raw.text, *n)) {
        // Decision 52: a point written names a decimal code (G54.1); G1. and G01.0 name none.
        if (letter == 'G')
          diags_.report(DiagId::GCodeUndefined, w.range, w.address + w.text);
        else
          diags_.report(DiagId::MCodeUndefined, w.range, w.address + w.text);
        w.kind = ir::WordKind::Ignored;
        block_.has_errors = true;
      } else {
        if (*n < kDecimalCode) (letter == 'G' ? g : m).set(static_cast<size_t>(*n));
        const auto& table = letter == 'G' ? s_.tables.g_codes : s_.tables.m_codes;
        auto it = table.find(*n);
        if (it == table.end())
          w.code = -1;  // the checks report it
        else if (it->second.desc.calls.empty())
          w.kind = ir::WordKind::Control;  // G65 M97 M98 M99
        else
          w.code = program_code(program_, it->second.desc);
        if (it != table.end())
          for (const FnCall& call : it->second.desc.calls)
            p_is_number |=
                call.fn == Fn::DataSet || call.fn == Fn::WorkOffsetExtended || call.fn == Fn::ReferenceReturnNth;
      }
    } else if (!macro_call && kAxisLetters.substr(3, 3).find(letter) != std::string_view::npos &&
               s_.conventions.axes.find(letter) == std::string::npos) {
      // A rotary axis the machine lacks: the program is for another machine (said once).
      // U (G04's dwell word) and V W stay words that have no effect.
      if (absent_axes_.find(letter) == std::string::npos) {
        absent_axes_ += letter;
        diags_.report(DiagId::AxisAbsent, w.range, w.address,
                      fmt::format("{} (--machine {}; --machine haas has XYZA, a profile's iso.axes others)",
                                  s_.conventions.axes, s_.machine));
      }
      w.kind = ir::WordKind::Ignored;
      block_.has_errors = true;
    } else {
      w.kind = ir::WordKind::Parameter;
    }
    literal_integer.push_back(literal);
    block_.words.push_back(std::move(w));
  }
  if (corner) {
    // §8.3: ,C chamfer and ,R fillet: the second C or R word, which the runtime reads.
    const char letter = corner->letter;
    const bool literal = corner->literal;
    ir::Word w;
    w.kind = ir::WordKind::Parameter;
    w.address = std::string(1, letter) + "'";
    w.text = corner->text;
    w.range = corner->range;
    w.value = corner->value;
    if (letter == 'C' || letter == 'R') {
      w.slot = static_cast<uint8_t>(second_slot(letter));
      corner_ = w.range;
    } else {
      diags_.report(DiagId::ValueForm, w.range, "','", "C (a chamfer) or R (a fillet) after it",
                    fmt::format(",{}{}", w.address[0], w.text));
      w.kind = ir::WordKind::Ignored;
      block_.has_errors = true;
    }
    literal_integer.push_back(literal);
    block_.words.push_back(std::move(w));
  }
  // §8.12, §8.13, §8.17 (E-16, E-19, E-24): G51, G52 and G68 stand in blocks of their
  // own; the modal G90/G91 and G17-G19 may join them (decision 27).
  for (int own : {51, 52, 68}) {
    if (!g.test(own)) continue;
    for (const ir::Word& w : block_.words) {
      const bool code = w.kind == ir::WordKind::Code || w.kind == ir::WordKind::Control;
      const int n =
          code && program_.is_constant(w.value) ? whole_in(program_.exprs[w.value].number, 0, 999).value_or(-1) : -1;
      const bool allowed = w.kind == ir::WordKind::BlockNumber ||
                           (w.kind == ir::WordKind::Parameter && w.address != "F" && w.address != "S" &&
                            w.address != "T" && w.address != "D" && w.address != "H") ||
                           (code && w.address == "G" && (n == own || n == 90 || n == 91 || (n >= 17 && n <= 19)));
      if (!allowed) {
        diags_.report(DiagId::ProgramStructure, w.range,
                      fmt::format("{}{} cannot share the block of G{}: G{} and its words stand in a block of their own",
                                  w.address, w.text, own, own));
        block_.has_errors = true;
      }
    }
  }
  if (g.test(92)) g92_words(first);
  if (g.test(65) || m.test(97) || m.test(98)) {
    call_words(cond);
    return;
  }
  // The decimal-point rule (§8.4, §8.12, §8.17, §8.24): an integer is thousandths
  // (milliseconds of a dwell, a factor / 1000, an angle / 1000 degrees).
  auto thousandths = [&](size_t i) {
    ir::Word& w = block_.words[i];
    if (literal_integer[i - first]) w.value = program_.number(program_.exprs[w.value].number / 1000, w.range);
  };
  const bool dwell_block = g.test(4);
  bool has_p = false;
  for (size_t i = first; i < block_.words.size(); ++i) {
    const char a = block_.words[i].address[0];
    if (block_.words[i].kind != ir::WordKind::Parameter) continue;
    if (a == 'P') {
      has_p = true;
      if (!p_is_number) thousandths(i);
    }
    if ((g.test(51) && (a == 'I' || a == 'J' || a == 'K')) || (g.test(68) && a == 'R')) thousandths(i);
  }
  // §8.4 (decision 8): G04 X or U is the dwell when no P gives it.
  if (dwell_block && !has_p)
    for (size_t i = first; i < block_.words.size(); ++i)
      if (ir::Word& w = block_.words[i]; w.kind == ir::WordKind::Parameter && (w.address == "X" || w.address == "U")) {
        thousandths(i);
        w.slot = static_cast<uint8_t>(letter_slot('P'));
        break;
      }
  bool action = false;
  for (const ir::Word& w : block_.words)
    action = action || w.kind == ir::WordKind::Code || w.kind == ir::WordKind::Parameter;
  if (action) {
    ir::Stmt s{ir::StmtKind::Machine, block_.range};
    s.cond = cond;
    block_.stmts.push_back(std::move(s));
  }
  if (m.test(99)) {
    if (unit_.kind == ir::UnitKind::Program && !main_done_) main_returns_.push_back(block_.range);
    ir::Stmt s{ir::StmtKind::Return, block_.range};
    s.cond = cond;
    block_.stmts.push_back(std::move(s));
  }
  if ((m.test(2) || m.test(30)) && unit_.kind == ir::UnitKind::Program && !main_done_ && !block_.skippable &&
      cond == ir::kNoExpr) {
    main_done_ = true;
    end_block_ = unit_.blocks.size() - 1;
  }
}

// §8.19 (E-25): in a block with a motion G92 stands after the motion's words; the
// axis words after it are its values (the axes' second words, read after the move).
void Reader::g92_words(size_t first) {
  size_t at = first;
  while (at < block_.words.size() &&
         !(block_.words[at].kind == ir::WordKind::Code && block_.words[at].address == "G" &&
           program_.is_constant(block_.words[at].value) && program_.exprs[block_.words[at].value].number == 92))
    ++at;
  auto axis = [](const ir::Word& w) {
    return w.kind == ir::WordKind::Parameter && std::string_view("XYZ").find(w.address[0]) != std::string_view::npos;
  };
  bool motion_before = false;
  for (size_t i = first; i < at; ++i) motion_before = motion_before || axis(block_.words[i]);
  for (size_t i = at + 1; i < block_.words.size(); ++i) {
    const ir::Word& w = block_.words[i];
    if (w.kind == ir::WordKind::Code && w.address == "G" && program_.is_constant(w.value) &&
        program_.exprs[w.value].number <= 3) {
      diags_.report(
          DiagId::ProgramStructure, w.range,
          fmt::format("G{} follows G92: in a block with a motion, G92 and its values stand after the motion's words",
                      w.text));
      block_.has_errors = true;
      return;
    }
  }
  if (!motion_before) return;
  for (size_t i = at + 1; i < block_.words.size(); ++i)
    if (ir::Word& w = block_.words[i]; axis(w)) {
      w.slot = static_cast<uint8_t>(second_slot(w.address[0]));
      w.address += "'";
    }
}

// M97, M98, G65 (§8.16, §8.33): the block's other words run first (M97/M98), or are
// the macro's arguments (G65).
void Reader::call_words(ir::ExprId cond) {
  const ir::Word* code = nullptr;
  const ir::Word* p = nullptr;
  const ir::Word* l = nullptr;
  bool macro = false;
  for (ir::Word& w : block_.words) {
    if (w.kind == ir::WordKind::Control && !code) {
      code = &w;
      macro = w.address == "G";
    }
  }
  ir::Stmt call{ir::StmtKind::Call, block_.range};
  call.cond = cond;
  call.shares_locals = !macro;            // §8.16: only a macro call opens new locals
  std::map<uint32_t, std::string> given;  // G65: argument variable -> the word that gives it
  int set = -1;
  char last = 'K';
  bool machine_words = false;
  for (ir::Word& w : block_.words) {
    if (&w == code || w.kind == ir::WordKind::BlockNumber) continue;
    const char a = w.address[0];
    if (a == 'P' && !p) {
      p = &w;
      w.kind = ir::WordKind::Control;
    } else if (a == 'L' && !l) {
      l = &w;
      w.kind = ir::WordKind::Control;
    } else if (macro) {
      // Specification I, and II for repeated I J K: a set begins with a letter that
      // does not follow the one before in I J K (decision 14).
      uint32_t var = argument_of(a);
      if (a == 'I' || a == 'J' || a == 'K') {
        if (a <= last) ++set;
        last = a;
        var = static_cast<uint32_t>(3 * set + 4 + (a - 'I'));
      }
      if (var == 0 || var > 33) {
        diags_.report(DiagId::MacroArgument, w.range,
                      var ? fmt::format("{}{} would be argument #{}: at most 10 sets of I J K", a, w.text, var)
                          : fmt::format("{}{} is not a G65 argument: the arguments are the letters A-Z but G L N O P",
                                        a, w.text));
        block_.has_errors = true;
        continue;
      }
      if (auto [it, fresh] = given.emplace(var, w.address + w.text); !fresh) {
        diags_.report(DiagId::MacroArgument, w.range,
                      fmt::format("#{} is given twice, by {} and by {}", var, it->second, w.address + w.text));
        block_.has_errors = true;
        continue;
      }
      w.kind = ir::WordKind::Argument;
      call.args.push_back({space_, var, w.value});
    } else if (w.kind == ir::WordKind::Code || w.kind == ir::WordKind::Parameter) {
      machine_words = true;
    } else if (w.kind == ir::WordKind::Control) {
      diags_.report(DiagId::MacroArgument, w.range,
                    fmt::format("{} and {} cannot share a block", code->address + code->text, w.address + w.text));
      block_.has_errors = true;
    }
  }
  const std::string what = code->address + code->text;
  if (!p) {
    diags_.report(DiagId::ValueMissing, code->range, what + " P");
    block_.has_errors = true;
    return;
  }
  // §8.33: with four-digit programs, M98 P31002 is O1002 three times; with longer
  // ones P is the program number alone (decision 53), as Haas and Fanuc read it.
  const bool packed = what == "M98" && s_.program_digits == 4;
  std::optional<uint32_t> number;
  if (what == "M97")
    number = whole(*p, 0, kMaxBlockNumber, "a block number");
  else if (program_.is_constant(p->value) && !packed && program_.exprs[p->value].number > s_.max_program &&
           whole_in(program_.exprs[p->value].number, 0u, UINT32_MAX))
    program_range(p->range, p->address + p->text, what + " P");
  else
    number = whole(*p, 0, packed ? 9999999 : s_.max_program, "a program number");
  uint32_t count = 0;
  if (number && packed && *number > 9999) {
    count = *number / 10000;  // §8.33: P31002 = O1002 three times
    number = *number % 10000;
  }
  if (l) {
    if (count) {
      diags_.report(DiagId::MacroArgument, l->range,
                    fmt::format("{}{} already holds the count {}", p->address, p->text, count));
      block_.has_errors = true;
    } else if (program_.is_constant(l->value)) {
      (void)whole(*l, 1, kMaxCount, "the number of calls");  // reported, and the block marked, if not whole
    }
    // From a variable, checked when the call runs (§8.16, §8.33: at most 999).
    call.value = program_.is_constant(l->value) ? l->value : checked(operand(l->value), *l, "L", 1, kMaxCount);
  } else if (count) {
    call.value = program_.number(count, p->range);
  }
  if (!number) return;
  if (macro && machine_words) block_.has_errors = true;
  if (machine_words) block_.stmts.push_back({ir::StmtKind::Machine, block_.range});
  if (what == "M97") {
    const std::string label = fmt::format("N{}", *number);
    call.label = unit_.name + "/" + label;
    local_calls_.push_back({label, p->range, unit_.blocks.size() - 1});
  } else {
    call.label = program_name(*number);
    calls_.push_back({call.label, p->range, program_.units.size(), unit_.blocks.size() - 1});
  }
  block_.stmts.push_back(std::move(call));
}

// A program number beyond iso.program_number_digits (decision 53).
void Reader::program_range(SourceRange r, const std::string& written, const std::string& what) {
  Diagnostic* d = diags_.report(DiagId::ValueRange, r, written, what, 0, s_.max_program);
  if (d && !digits_told_++)  // once a file: the cause is the same
    d->notes.push_back({r, fmt::format("program numbers have iso.program_number_digits = {} digits; a machine with "
                                       "longer ones sets it (--machine haas: 5, --machine fanuc: 8)",
                                       s_.program_digits)});
  block_.has_errors = true;
}

// ---- Expressions ------------------------------------------------------------------------

// A value a run-time word gives, which must be a whole number lo..hi (ProgramSemantics::value_rules).
ir::ExprId Reader::checked(ir::ExprId e, const ir::Word& w, const std::string& address, double lo, double hi) {
  auto& rules = program_.semantics.value_rules;
  ValueRule rule{address, lo, hi, true};
  auto it = std::find_if(rules.begin(), rules.end(), [&](const ValueRule& r) {
    return r.address == rule.address && r.lo == lo && r.hi == hi && r.whole;
  });
  const auto index = static_cast<uint8_t>(it - rules.begin());
  if (it == rules.end()) rules.push_back(rule);
  ir::ExprId c = program_.add({ir::ExprOp::Check, Builtin::Sin, 0, 0, e, ir::kNoExpr, w.range});
  program_.exprs[c].slot = w.slot;
  program_.exprs[c].rule = index;
  return c;
}

// The value of a number as written; nothing when it is out of range (reported: the
// block has errors).
std::optional<double> Reader::number(antlr4::tree::TerminalNode* n) {
  auto v = read_number(n->getText(), range(n->getSymbol(), n->getSymbol()), diags_);
  block_.has_errors = block_.has_errors || !v;
  return v;
}

// Macro B arithmetic reads a vacant variable as 0; a comparison EQ/NE, an assignment
// and an address keep it vacant (decision 3).
ir::ExprId Reader::operand(ir::ExprId e) {
  if (program_.exprs[e].op != ir::ExprOp::Var) return e;
  return program_.add({ir::ExprOp::ZeroIfVacant, Builtin::Sin, 0, 0, e, ir::kNoExpr, program_.exprs[e].range});
}

// A chain `a op b op c` of one precedence level, left to right; `op_of` gives the IR
// operator of each operator token. Its operands are arithmetic: vacant reads as 0.
template <typename Ctx, typename Part, typename Read, typename OpOf>
ir::ExprId Reader::chain(Ctx* ctx, const std::vector<Part*>& parts, Read operand_of, OpOf op_of) {
  ir::ExprId e = (this->*operand_of)(parts[0]);
  size_t k = 1;
  for (auto* child : ctx->children)
    if (auto* t = dynamic_cast<antlr4::tree::TerminalNode*>(child))
      e = program_.add({op_of(t->getSymbol()->getType()), Builtin::Sin, 0, 0, operand(e),
                        operand((this->*operand_of)(parts[k++])), range(ctx)});
  return e;
}

ir::ExprId Reader::expr(IsoParser::ExprContext* ctx) {
  return chain(ctx, ctx->andExpr(), &Reader::and_expr,
               [](size_t t) { return t == IsoLexer::XOR ? ir::ExprOp::Xor : ir::ExprOp::Or; });
}

ir::ExprId Reader::and_expr(IsoParser::AndExprContext* ctx) {
  return chain(ctx, ctx->compare(), &Reader::compare, [](size_t) { return ir::ExprOp::And; });
}

ir::ExprId Reader::compare(IsoParser::CompareContext* ctx) {
  auto parts = ctx->sum();
  ir::ExprId a = sum(parts[0]);
  if (parts.size() == 1) return a;
  ir::ExprId b = sum(parts[1]);
  ir::ExprOp op = ctx->EQ()   ? ir::ExprOp::Eq
                  : ctx->NE() ? ir::ExprOp::Ne
                  : ctx->GT() ? ir::ExprOp::Gt
                  : ctx->GE() ? ir::ExprOp::Ge
                  : ctx->LT() ? ir::ExprOp::Lt
                              : ir::ExprOp::Le;
  // EQ and NE tell vacant from 0 (`#1 EQ #0`); the order comparisons read it as 0.
  if (op != ir::ExprOp::Eq && op != ir::ExprOp::Ne) {
    a = operand(a);
    b = operand(b);
  }
  return program_.add({op, Builtin::Sin, 0, 0, a, b, range(ctx)});
}

ir::ExprId Reader::sum(IsoParser::SumContext* ctx) {
  return chain(ctx, ctx->term(), &Reader::term,
               [](size_t t) { return t == IsoLexer::PLUS ? ir::ExprOp::Add : ir::ExprOp::Sub; });
}

ir::ExprId Reader::term(IsoParser::TermContext* ctx) {
  return chain(ctx, ctx->factor(), &Reader::factor, [](size_t t) {
    return t == IsoLexer::STAR ? ir::ExprOp::Mul : t == IsoLexer::SLASH ? ir::ExprOp::Div : ir::ExprOp::Mod;
  });
}

ir::ExprId Reader::factor(IsoParser::FactorContext* ctx) {
  if (auto* inner = ctx->factor()) {
    ir::ExprId e = factor(inner);
    if (ctx->PLUS()) return e;
    return program_.add({ir::ExprOp::Neg, Builtin::Sin, 0, 0, operand(e), ir::kNoExpr, range(ctx)});
  }
  return primary(ctx->primary());
}

ir::ExprId Reader::primary(IsoParser::PrimaryContext* ctx) {
  if (auto* n = dynamic_cast<IsoParser::NumberPrimaryContext*>(ctx))
    return program_.number(number(n->NUMBER()).value_or(0), range(ctx));
  if (auto* v = dynamic_cast<IsoParser::VariablePrimaryContext*>(ctx)) return variable(v->variable(), false);
  if (auto* g = dynamic_cast<IsoParser::GroupPrimaryContext*>(ctx)) return expr(g->expr());
  auto* c = dynamic_cast<IsoParser::CallPrimaryContext*>(ctx);
  const std::string name = c->FUNCTION()->getText();
  auto args = c->expr();
  ir::ExprId a = operand(expr(args[0]));
  static const std::map<std::string, Builtin> kFunctions = {{"SIN", Builtin::Sin},
                                                            {"COS", Builtin::Cos},
                                                            {"TAN", Builtin::Tan},
                                                            {"ASIN", Builtin::Asin},
                                                            {"ACOS", Builtin::Acos},
                                                            {"ATAN", Builtin::Atan},
                                                            {"SQRT", Builtin::Sqrt},
                                                            {"ABS", Builtin::Abs},
                                                            {"ROUND", Builtin::Round},
                                                            {"EXP", Builtin::Exp},
                                                            {"LN", Builtin::Ln},
                                                            {"FIX", Builtin::Trunc},
                                                            {"FUP", Builtin::Away},
                                                            // Fanuc's two-letter abbreviations (decision 70).
                                                            {"SI", Builtin::Sin},
                                                            {"CO", Builtin::Cos},
                                                            {"TA", Builtin::Tan},
                                                            {"AS", Builtin::Asin},
                                                            {"AC", Builtin::Acos},
                                                            {"AT", Builtin::Atan},
                                                            {"SQ", Builtin::Sqrt},
                                                            {"AB", Builtin::Abs},
                                                            {"RO", Builtin::Round},
                                                            {"EX", Builtin::Exp},
                                                            {"FI", Builtin::Trunc},
                                                            {"FU", Builtin::Away}};
  Builtin b = kFunctions.at(name);
  ir::ExprId second = ir::kNoExpr;
  if (args.size() == 2) {
    if (b != Builtin::Atan) {
      // `SIN[a]/[b]` is SIN[a] divided by b.
      ir::ExprId call = program_.add({ir::ExprOp::Call, b, 0, 0, a, ir::kNoExpr, range(ctx)});
      return program_.add({ir::ExprOp::Div, Builtin::Sin, 0, 0, call, operand(expr(args[1])), range(ctx)});
    }
    b = Builtin::Atan2;  // ATAN[a]/[b] (decision 7)
    second = operand(expr(args[1]));
  }
  if (b == Builtin::Round && in_word_) {
    // §8.34.1: after an address ROUND keeps 3 decimals (mm) or 4 (inch).
    ir::ExprId inch = program_.add({ir::ExprOp::Sys, Builtin::Sin, 0, 0, ir::kNoExpr, ir::kNoExpr, range(ctx)});
    program_.exprs[inch].sys = SysRef{SysVar::InchMode, 0}.packed();
    ir::ExprId places =
        program_.add({ir::ExprOp::Add, Builtin::Sin, 0, 0, program_.number(3, range(ctx)), inch, range(ctx)});
    return program_.add({ir::ExprOp::Call, Builtin::RoundTo, 0, 0, a, places, range(ctx)});
  }
  return program_.add({ir::ExprOp::Call, b, 0, 0, a, second, range(ctx)});
}

ir::ExprId Reader::variable(IsoParser::VariableContext* ctx, bool target) {
  SourceRange r = range(ctx);
  ir::ExprId index;
  std::string text;  // as written after '#': "12", "[12]"
  if (auto* n = ctx->NUMBER()) {
    text = n->getText();
    const std::optional<double> v = number(n);
    if (!v) return program_.add({ir::ExprOp::Var, Builtin::Sin, space_, 0, program_.number(0, r), ir::kNoExpr, r});
    index = program_.number(*v, r);
  } else {
    text = ctx->getText().substr(1);
    index = operand(expr(ctx->expr()));  // #[...]: checked when it runs, unless it is a number
  }
  if (!program_.is_constant(index))
    return program_.add({ir::ExprOp::Var, Builtin::Sin, space_, 0, index, ir::kNoExpr, r});
  // A variable number that is written (decision 3): #12 or #[12].
  const std::optional<uint32_t> n = whole_in<uint32_t>(program_.exprs[index].number, 0, UINT32_MAX);
  if (n && *n >= 1000) {
    // A system variable (decision 48).
    auto it = s_.system.find(*n);
    if (it == s_.system.end()) {
      diags_.report(DiagId::VariableNumber, r, text);
      block_.has_errors = true;
    } else if (target && !sys_writable(it->second)) {
      diags_.report(DiagId::SystemNotWritable, r, "#" + text, "is read-only");
      block_.has_errors = true;
    } else {
      ir::ExprId e = program_.add({ir::ExprOp::Sys, Builtin::Sin, 0, 0, ir::kNoExpr, ir::kNoExpr, r});
      program_.exprs[e].sys = it->second.packed();
      return e;
    }
    program_.exprs[index].number = 0;  // the block has an error: the dry run reads #0
  } else if (!n || !variable_exists(*n)) {
    diags_.report(DiagId::VariableNumber, r, text);
    block_.has_errors = true;
    program_.exprs[index].number = 0;
  } else if (target && *n == 0) {
    diags_.report(DiagId::VacantVariable, r, "#0");
    block_.has_errors = true;
  }
  return program_.add({ir::ExprOp::Var, Builtin::Sin, space_, 0, index, ir::kNoExpr, r});
}

ir::ExprId Reader::value(IsoParser::ValueContext* ctx, bool& literal_integer) {
  ir::ExprId e;
  literal_integer = false;
  if (auto* n = ctx->NUMBER()) {
    std::string text = n->getText();
    double v = number(n).value_or(0);
    literal_integer = text.find('.') == std::string::npos;
    if (ctx->MINUS()) v = -v;
    return program_.number(v, range(ctx));
  }
  e = ctx->variable() ? variable(ctx->variable(), false) : expr(ctx->expr());
  // X-#1 with #1 vacant stays vacant: the word is left out.
  if (ctx->MINUS()) e = program_.add({ir::ExprOp::Neg, Builtin::Sin, 0, 0, e, ir::kNoExpr, range(ctx)});
  return e;
}

}  // namespace ncc::iso
