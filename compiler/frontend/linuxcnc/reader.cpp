#include "reader.h"

#include <cmath>

#include "frontend/limits.h"
#include "support/numbers.h"
#include "support/text.h"

namespace ncc::linuxcnc {

namespace {

constexpr size_t kMaxArguments = kLocalParameters;  // o-call [a] [b] ... sets #1-#30

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return out;
}

// "(MSG, text)" -> " text" (LinuxCNC keeps what follows the comma, blanks and all).
std::optional<std::string> after_keyword(std::string_view comment, std::string_view keyword) {
  std::string_view t = comment;
  while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
  if (t.size() < keyword.size() || upper(t.substr(0, keyword.size())) != keyword) return std::nullopt;
  return std::string(t.substr(keyword.size()));
}

}  // namespace

// An open o-word construct: a sub, an if, a loop.
struct Reader::Open {
  enum Kind { If, While, Do, Repeat } kind = If;
  std::string name;  // the o-word: "o101"
  SourceRange range;
  size_t head = 0;                                   // its first block (a loop goes back there)
  std::optional<std::pair<size_t, size_t>> next;     // if: the false condition's jump (block, stmt)
  std::vector<std::pair<size_t, size_t>> exits;      // if: the bodies' jumps to endif; loops: break
  std::vector<std::pair<size_t, size_t>> continues;  // do, repeat: continue
  bool has_else = false;
};

Reader::Reader(const Settings& settings, ir::Program& program, Parameters& params, const SourceFile& source,
               uint32_t file, Diagnostics& diags, bool called)
    : s_(settings), program_(program), params_(params), source_(source), file_(file), diags_(diags), called_(called),
      errors_(std::make_unique<BlockErrors>(BlockTokens{LinuxcncLexer::INVALID, 0, {}}, diags)) {
  lexer_.removeErrorListeners();
  parser_.removeErrorListeners();
  parser_.addErrorListener(errors_.get());
  parser_.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(antlr4::atn::PredictionMode::SLL);
  main_.kind = ir::UnitKind::Program;
  main_.name = "%";
  main_.range = SourceRange::point(file_, 1, 1);
}

Reader::~Reader() = default;

void Reader::run() {
  for (uint32_t n = 1; n <= source_.line_count() && !closed_ && !diags_.limit_reached(); ++n) line(n);
  if (in_sub_ && fanuc_sub_) end_sub();
  if (in_sub_) {
    diags_.report(DiagId::ProgramStructure, sub_.range, fmt::format("{} sub has no endsub", sub_.name));
    end_sub();
  }
  for (const Open& o : open_)
    diags_.report(DiagId::ProgramStructure, o.range,
                  fmt::format("{} is not closed: {}", o.name,
                              o.kind == Open::If      ? "endif is missing"
                              : o.kind == Open::While ? "endwhile is missing"
                              : o.kind == Open::Do    ? "the while of its do is missing"
                                                      : "endrepeat is missing"));
  open_.clear();
  if (called_) return;
  // rs274 reads until M2, M30 or the closing '%' (decision 3).
  if (!ended_ && !closed_ && !diags_.limit_reached())
    diags_.report(DiagId::ProgramStructure, SourceRange::point(file_, std::max<uint32_t>(source_.line_count(), 1), 1),
                  "the file ends without M2, M30 or a closing '%'");
  // The main program comes first: a run starts with the first unit.
  program_.units.insert(program_.units.begin(), std::move(main_));
}

// ---- A line --------------------------------------------------------------------------

void Reader::line(uint32_t n) {
  std::string_view text = source_.line(n);
  std::string_view trimmed = trim(text);
  // '%' alone: the first line starts the program, the next one ends it.
  // '%' alone: on the first line that is not blank it starts the program, and the
  // next one ends it; anywhere else rs274 refuses it (decision 3).
  if (!trimmed.empty() && trimmed.front() == '%' && trim(trimmed.substr(1)).empty()) {
    if (percent_ || ended_) {
      closed_ = true;
    } else if (!read_any_) {
      percent_ = true;
    } else {
      const auto col = static_cast<uint32_t>(text.find('%') + 1);
      diags_.report(DiagId::CharInvalid, {file_, n, col, n, col + 1}, "'%'");
      closed_ = true;
    }
    return;
  }
  read_any_ = read_any_ || !trimmed.empty();
  std::vector<std::pair<size_t, size_t>> comments;  // byte ranges in the line, ( ) included
  std::vector<std::string> texts;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == ';') {
      comments.push_back({i, text.size()});
      break;
    }
    if (text[i] != '(') continue;
    size_t end = text.find(')', i + 1);
    if (end == std::string_view::npos) {
      diags_.report(DiagId::CommentUnterminated,
                    {file_, n, static_cast<uint32_t>(i + 1), n, static_cast<uint32_t>(text.size() + 1)});
      end = text.size() - 1;
    }
    comments.push_back({i, end + 1});
    texts.emplace_back(text.substr(i + 1, end - i - 1));
    i = end;
  }
  load(n, text, comments);
  const SourceRange whole{file_, n, 1, n, static_cast<uint32_t>(text.size() + 1)};
  // After the main program's end rs274 reads no more of it: only the subroutines
  // that stand there (the O programs of M98) are read.
  if (ended_ && !in_sub_ && sanitized_.find('O') == std::string::npos) return;
  if (sanitized_.empty()) {
    if (texts.empty()) return;
    ir::Block& b = new_block(whole);
    b.comments = texts;
    messages(texts, b);
    return;
  }
  if (!block_fits(text.size(), whole, diags_)) {
    ir::Block& refused = new_block(whole);
    refused.has_errors = refused.unread = true;
    return;
  }
  LinuxcncParser::BlockContext* ctx = parse();
  if (!ctx || errors_->any()) {
    if (ended_ && !in_sub_) return;
    ir::Block& b = new_block(whole);
    b.has_errors = true;
    b.comments = texts;
    return;
  }
  if (ended_ && !in_sub_ && !ctx->oword()) return;
  ir::Block b;
  b.range = whole;
  b.comments = texts;
  messages(texts, b);
  read_block(ctx, b);
}

// The line as the lexer reads it: no comments, upper case, no blanks (LinuxCNC drops
// them everywhere: `G 0 1` is G01); columns_ keeps each character's column.
void Reader::load(uint32_t n, std::string_view text, const std::vector<std::pair<size_t, size_t>>& comments) {
  sanitized_.clear();
  columns_.clear();
  size_t next = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    if (next < comments.size() && i == comments[next].first) {
      i = comments[next++].second - 1;
      continue;
    }
    const char c = text[i];
    if (c == ' ' || c == '\t' || c == '\r') continue;
    sanitized_ += c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
    columns_.push_back(static_cast<uint32_t>(i + 1));
  }
  columns_.push_back(static_cast<uint32_t>(text.size() + 1));
  line_ = n;
  errors_->start(file_, line_, text, sanitized_.size(),
                 [this](size_t i) { return columns_[std::min(i, columns_.size() - 1)]; });
}

LinuxcncParser::BlockContext* Reader::parse() {
  static const ExpressionTokens kTokens{
      {LinuxcncLexer::LBRACKET},
      {LinuxcncLexer::RBRACKET},
      {LinuxcncLexer::PLUS, LinuxcncLexer::MINUS},
      {LinuxcncLexer::STAR, LinuxcncLexer::SLASH, LinuxcncLexer::MOD, LinuxcncLexer::POWER, LinuxcncLexer::AND,
       LinuxcncLexer::OR, LinuxcncLexer::XOR, LinuxcncLexer::EQ, LinuxcncLexer::NE, LinuxcncLexer::GT,
       LinuxcncLexer::GE, LinuxcncLexer::LT, LinuxcncLexer::LE},
      {LinuxcncLexer::NUMBER, LinuxcncLexer::RBRACKET, LinuxcncLexer::NAMED}};
  if (!lex_block(
          sanitized_, input_, lexer_, tokens_, kTokens,
          [this](antlr4::Token* a, antlr4::Token* b) { return range(a, b); }, diags_))
    return nullptr;
  parser_.setTokenStream(&tokens_);
  return parser_.block();
}

SourceRange Reader::range(antlr4::Token* first, antlr4::Token* last) const {
  auto col = [&](size_t i) { return columns_[std::min(i, columns_.size() - 1)]; };
  const uint32_t begin = col(first->getStartIndex());
  uint32_t end = last->getType() == antlr4::Token::EOF ? begin + 1 : col(last->getStopIndex()) + 1;
  if (end <= begin) end = begin + 1;
  return {file_, line_, begin, line_, end};
}

// (MSG,text) shows text to the operator; (DEBUG,text) too, with the parameters it
// names replaced by their values. (PRINT,...) writes to rs274's standard error: no
// canonical call, nothing here.
void Reader::messages(const std::vector<std::string>& comments, ir::Block& b) {
  for (const std::string& c : comments) {
    ir::Stmt s{ir::StmtKind::Display, b.range};
    if (auto msg = after_keyword(c, "MSG,")) {
      program_.texts.push_back(*msg);
      ir::ExprId e = program_.add({ir::ExprOp::String, Builtin::Sin, 0, 0, ir::kNoExpr, ir::kNoExpr, b.range});
      program_.exprs[e].text = static_cast<uint32_t>(program_.texts.size() - 1);
      s.items.push_back({e, VarType::LongReal});
      b.stmts.push_back(std::move(s));
    }
  }
}

ir::Block& Reader::new_block(SourceRange r) {
  ir::Unit& u = unit();
  u.blocks.emplace_back();
  u.blocks.back().range = r;
  return u.blocks.back();
}

std::string Reader::label_of(size_t block) {
  ir::Block& b = unit().blocks[block];
  if (b.label.empty()) b.label = fmt::format("@{}", ++next_label_);
  return b.label;
}

void Reader::land(const std::vector<std::pair<size_t, size_t>>& jumps, const std::string& label) {
  for (auto [block, stmt] : jumps) unit().blocks[block].stmts[stmt].label = label;
}

void Reader::read_block(LinuxcncParser::BlockContext* ctx, ir::Block& b) {
  b.skippable = ctx->SLASH() != nullptr;
  if (auto* seq = ctx->SEQUENCE()) {
    const std::string digits = seq->getText().substr(1);
    ir::Word w;
    w.kind = ir::WordKind::BlockNumber;
    w.slot = static_cast<uint8_t>(letter_slot('N'));
    w.address = "N";
    w.text = digits;
    w.range = range(seq->getSymbol(), seq->getSymbol());
    const double n = parse_number<double>(digits).value_or(0);
    w.value = program_.number(n, w.range);
    if (auto whole = whole_in<uint32_t>(n, 0, 99999999)) b.number = *whole;
    b.words.push_back(std::move(w));
  }
  if (auto* o = ctx->oword()) return oword(o, b);
  unit().blocks.push_back(std::move(b));
  items(ctx, unit().blocks.back());
}

// ---- Words and parameters ---------------------------------------------------------------

void Reader::items(LinuxcncParser::BlockContext* ctx, ir::Block& b) {
  std::vector<std::pair<ir::ExprId, ir::ExprId>> sets;  // target, value
  std::optional<size_t> call;                           // the M98 word
  bool returns_here = false;
  std::string ignored_words;  // of the codes read as nothing: G64's P Q
  for (auto* item : ctx->item()) {
    if (auto* a = item->assignment()) {
      ir::ExprId target = variable(a->variable(), true);
      ir::ExprId v = value(a->value());
      if (target != ir::kNoExpr) sets.push_back({target, v});
      continue;
    }
    auto* wc = item->word();
    const char letter = wc->LETTER()->getText()[0];
    ir::Word w;
    w.slot = static_cast<uint8_t>(letter_slot(letter));
    w.address = std::string(1, letter);
    w.text = wc->value()->getText();
    w.range = range(wc);
    w.value = value(wc->value());
    w.kind = ir::WordKind::Parameter;
    if (letter == 'G' || letter == 'M') {
      w.kind = ir::WordKind::Code;
      if (!program_.is_constant(w.value)) {
        w.code = ir::kDynamicCode;
      } else {
        const double v = program_.exprs[w.value].number;
        const std::string name = fmt::format("{}{}", letter, shortest(v));
        const std::optional<int> n = whole_in(v, 0, 999);
        const auto& table = letter == 'G' ? s_.tables.g_codes : s_.tables.m_codes;
        auto it = n ? table.find(*n) : table.end();
        if (auto refused = s_.refused.find(name); refused != s_.refused.end()) {
          diags_.report(DiagId::Unsupported, w.range, name, refused->second);
          w.kind = ir::WordKind::Ignored;
          b.has_errors = true;
        } else if (auto ignored = s_.ignored.find(name); ignored != s_.ignored.end()) {
          w.kind = ir::WordKind::Ignored;  // G64, G91.1 (decision 4)
          ignored_words += ignored->second;
        } else if (it == table.end()) {
          w.code = -1;  // the checks report it
        } else if (it->second.desc.calls.empty()) {
          w.kind = ir::WordKind::Control;  // M98 M99
          if (*n == 98) call = b.words.size();
          if (*n == 99) returns_here = true;
        } else {
          w.code = program_code(program_, it->second.desc);
          if (letter == 'M' && (*n == 2 || *n == 30) && !in_sub_ && open_.empty() && !b.skippable) ended_ = true;
        }
      }
    }
    b.words.push_back(std::move(w));
  }
  for (ir::Word& w : b.words)
    if (w.kind == ir::WordKind::Parameter && ignored_words.find(w.address[0]) != std::string::npos)
      w.kind = ir::WordKind::Ignored;
  // G80 beside another motion code: the other one acts (decision 12).
  auto motion = [&](const ir::Word& w) -> int {
    if (w.kind != ir::WordKind::Code || w.address != "G" || !program_.is_constant(w.value)) return -1;
    const int n = ir::code_number(program_, w.value);
    auto it = s_.tables.g_codes.find(n);
    return it != s_.tables.g_codes.end() && it->second.group == "01" ? n : -1;
  };
  if (std::count_if(b.words.begin(), b.words.end(), [&](const ir::Word& w) { return motion(w) >= 0; }) > 1)
    for (ir::Word& w : b.words)
      if (motion(w) == 80) w.kind = ir::WordKind::Ignored;
  if (call) {
    call_words(b, *call);
  } else {
    bool action = false;
    for (const ir::Word& w : b.words)
      action = action || w.kind == ir::WordKind::Code || w.kind == ir::WordKind::Parameter;
    if (action) b.stmts.push_back({ir::StmtKind::Machine, b.range});
  }
  // Parameters set on a line take their values once the whole line is read: with
  // several, each value goes through a temporary first (decision 2).
  std::vector<ir::ExprId> values;
  for (auto& [target, v] : sets) {
    if (sets.size() == 1) break;
    const uint32_t temp = kMaxParameter + 1 + static_cast<uint32_t>(values.size());
    params_.temporaries = std::max<uint32_t>(params_.temporaries, static_cast<uint32_t>(values.size()) + 1);
    ir::ExprId t = program_.add(
        {ir::ExprOp::Var, Builtin::Sin, params_.numbered, 0, program_.number(temp, b.range), ir::kNoExpr, b.range});
    ir::Stmt s{ir::StmtKind::Assign, b.range};
    s.target = t;
    s.value = v;
    b.stmts.push_back(std::move(s));
    values.push_back(t);
  }
  for (size_t i = 0; i < sets.size(); ++i) {
    ir::Stmt s{ir::StmtKind::Assign, b.range};
    s.target = sets[i].first;
    s.value = values.empty() ? sets[i].second : values[i];
    b.stmts.push_back(std::move(s));
  }
  if (returns_here) {
    if (!in_sub_) {
      diags_.report(DiagId::ProgramStructure, b.range, "M99 stands outside an O subprogram");
      b.has_errors = true;
    } else {
      b.stmts.push_back({ir::StmtKind::Return, b.range});
    }
  }
}

// M98 P<program> [L<count>]: calls the Fanuc-style O program, sharing the parameters.
void Reader::call_words(ir::Block& b, size_t code_index) {
  const ir::Word& code = b.words[code_index];
  const ir::Word* p = nullptr;
  const ir::Word* l = nullptr;
  bool machine = false;
  for (ir::Word& w : b.words) {
    if (&w == &code || w.kind == ir::WordKind::BlockNumber) continue;
    if (w.address == "P" && !p) {
      p = &w;
      w.kind = ir::WordKind::Control;
    } else if (w.address == "L" && !l) {
      l = &w;
      w.kind = ir::WordKind::Control;
    } else if (w.kind == ir::WordKind::Code || w.kind == ir::WordKind::Parameter) {
      machine = true;
    }
  }
  if (!p || !program_.is_constant(p->value) || !whole_in<uint32_t>(program_.exprs[p->value].number, 0, 99999)) {
    diags_.report(DiagId::ValueForm, p ? p->range : code.range, "M98", "P, the O program's number", p ? p->text : "");
    b.has_errors = true;
    return;
  }
  if (machine) b.stmts.push_back({ir::StmtKind::Machine, b.range});
  ir::Stmt s{ir::StmtKind::Call, b.range};
  s.shares_locals = true;
  s.label = fmt::format("o{}", shortest(program_.exprs[p->value].number));
  if (l) s.value = l->value;
  calls_.push_back({s.label, p->range, unit().name, unit().blocks.size() - 1});
  b.stmts.push_back(std::move(s));
}

ir::ExprId Reader::global(uint32_t index, SourceRange r) {
  return program_.add({ir::ExprOp::Var, Builtin::Sin, params_.globals, 0, program_.number(index, r), ir::kNoExpr, r});
}

ir::ExprId Reader::variable(LinuxcncParser::VariableContext* ctx, bool target) {
  const SourceRange r = range(ctx);
  if (auto* named = ctx->NAMED()) {
    const std::string text = named->getText();
    const std::string name = lower(text.substr(2, text.size() - 3));  // names know no case
    if (name.empty()) {
      diags_.report(DiagId::ValueForm, r, "#<>", "a name", text);
      return target ? ir::kNoExpr : program_.number(0, r);
    }
    const bool is_global = name[0] == '_';
    if (auto it = s_.refused.find("#<" + name + ">"); is_global && it != s_.refused.end()) {
      diags_.report(DiagId::Unsupported, r, it->first, it->second);  // LinuxCNC's own: the machine's state
      return target ? ir::kNoExpr : program_.number(0, r);
    }
    auto& names = is_global ? params_.global_names : params_.local_names;
    auto [it, fresh] = names.emplace(name, static_cast<uint32_t>(names.size() + 1));
    (void)fresh;
    return program_.add({ir::ExprOp::Var, Builtin::Sin, is_global ? params_.globals : params_.locals, 0,
                         program_.number(it->second, r), ir::kNoExpr, r});
  }
  ir::ExprId index;
  if (auto* n = ctx->NUMBER())
    index = number(n);
  else if (auto* v = ctx->variable())
    index = variable(v, false);
  else
    index = expr(ctx->expr());
  if (program_.is_constant(index)) {
    const double v = program_.exprs[index].number;
    const std::optional<uint32_t> n = whole_in<uint32_t>(std::round(v), 1, kMaxParameter);
    if (!n) {
      diags_.report(DiagId::LinuxcncParameter, r, shortest(v));
      return target ? ir::kNoExpr : program_.number(0, r);
    }
    program_.exprs[index].number = *n;
  }
  return program_.add({ir::ExprOp::Var, Builtin::Sin, params_.numbered, 0, index, ir::kNoExpr, r});
}

ir::ExprId Reader::number(antlr4::tree::TerminalNode* n) {
  const SourceRange r = range(n->getSymbol(), n->getSymbol());
  return program_.number(read_number(n->getText(), r, diags_).value_or(0), r);
}

ir::ExprId Reader::value(LinuxcncParser::ValueContext* ctx) {
  ir::ExprId e;
  if (auto* n = ctx->NUMBER())
    e = number(n);
  else if (auto* v = ctx->variable())
    e = variable(v, false);
  else if (auto* c = ctx->call())
    e = call(c);
  else
    e = expr(ctx->expr());
  if (ctx->MINUS()) {
    if (program_.is_constant(e)) return program_.number(-program_.exprs[e].number, range(ctx));
    return program_.add({ir::ExprOp::Neg, Builtin::Sin, 0, 0, e, ir::kNoExpr, range(ctx)});
  }
  return e;
}

// ---- Expressions --------------------------------------------------------------------

// `a op b op c` of one precedence level, left to right.
ir::ExprId Reader::binary(antlr4::ParserRuleContext* ctx, const std::vector<ir::ExprId>& operands) {
  ir::ExprId e = operands[0];
  size_t k = 1;
  for (auto* child : ctx->children) {
    auto* t = dynamic_cast<antlr4::tree::TerminalNode*>(child);
    if (!t) continue;
    ir::ExprOp op;
    switch (t->getSymbol()->getType()) {
      case LinuxcncLexer::AND: op = ir::ExprOp::And; break;
      case LinuxcncLexer::OR: op = ir::ExprOp::Or; break;
      case LinuxcncLexer::XOR: op = ir::ExprOp::Xor; break;
      case LinuxcncLexer::EQ: op = ir::ExprOp::Eq; break;
      case LinuxcncLexer::NE: op = ir::ExprOp::Ne; break;
      case LinuxcncLexer::GT: op = ir::ExprOp::Gt; break;
      case LinuxcncLexer::GE: op = ir::ExprOp::Ge; break;
      case LinuxcncLexer::LT: op = ir::ExprOp::Lt; break;
      case LinuxcncLexer::LE: op = ir::ExprOp::Le; break;
      case LinuxcncLexer::PLUS: op = ir::ExprOp::Add; break;
      case LinuxcncLexer::MINUS: op = ir::ExprOp::Sub; break;
      case LinuxcncLexer::STAR: op = ir::ExprOp::Mul; break;
      case LinuxcncLexer::SLASH: op = ir::ExprOp::Div; break;
      case LinuxcncLexer::MOD: op = ir::ExprOp::Mod; break;
      default: op = ir::ExprOp::Pow; break;
    }
    e = program_.add({op, Builtin::Sin, 0, 0, e, operands[k++], range(ctx)});
  }
  return e;
}

// One precedence level: its operands, read by `read`, joined left to right.
template <typename Ctx, typename Part>
ir::ExprId Reader::level(Ctx* ctx, const std::vector<Part*>& parts, ir::ExprId (Reader::*read)(Part*)) {
  std::vector<ir::ExprId> operands;
  for (Part* p : parts) operands.push_back((this->*read)(p));
  return binary(ctx, operands);
}

ir::ExprId Reader::expr(LinuxcncParser::ExprContext* ctx) { return level(ctx, ctx->compare(), &Reader::compare); }
ir::ExprId Reader::compare(LinuxcncParser::CompareContext* ctx) { return level(ctx, ctx->sum(), &Reader::sum); }
ir::ExprId Reader::sum(LinuxcncParser::SumContext* ctx) { return level(ctx, ctx->term(), &Reader::term); }
ir::ExprId Reader::term(LinuxcncParser::TermContext* ctx) { return level(ctx, ctx->power(), &Reader::power); }
ir::ExprId Reader::power(LinuxcncParser::PowerContext* ctx) { return level(ctx, ctx->factor(), &Reader::factor); }

ir::ExprId Reader::factor(LinuxcncParser::FactorContext* ctx) {
  if (auto* inner = ctx->factor()) {
    ir::ExprId e = factor(inner);
    if (ctx->PLUS()) return e;
    return program_.add({ir::ExprOp::Neg, Builtin::Sin, 0, 0, e, ir::kNoExpr, range(ctx)});
  }
  if (auto* n = ctx->NUMBER()) return number(n);
  if (auto* v = ctx->variable()) return variable(v, false);
  if (auto* c = ctx->call()) return call(c);
  return expr(ctx->expr());
}

ir::ExprId Reader::call(LinuxcncParser::CallContext* ctx) {
  const SourceRange r = range(ctx);
  if (ctx->EXISTS()) {
    // A named parameter exists once it is set; a numbered one always does.
    ir::ExprId v = variable(ctx->variable(), false);
    if (program_.exprs[v].op != ir::ExprOp::Var || program_.exprs[v].space == params_.numbered)
      return program_.number(1, r);
    ir::ExprId never = program_.add({ir::ExprOp::Var, Builtin::Sin, program_.exprs[v].space, 0, program_.number(0, r),
                                     ir::kNoExpr, r});  // index 0: never set
    return program_.add({ir::ExprOp::Ne, Builtin::Sin, 0, 0, v, never, r});
  }
  auto args = ctx->expr();
  if (ctx->ATAN()) return program_.add({ir::ExprOp::Call, Builtin::Atan2, 0, 0, expr(args[0]), expr(args[1]), r});
  static const std::map<std::string, Builtin> kFunctions = {
      {"SIN", Builtin::Sin},   {"COS", Builtin::Cos},   {"TAN", Builtin::Tan},   {"ASIN", Builtin::Asin},
      {"ACOS", Builtin::Acos}, {"SQRT", Builtin::Sqrt}, {"ABS", Builtin::Abs},   {"ROUND", Builtin::Round},
      {"EXP", Builtin::Exp},   {"LN", Builtin::Ln},     {"FIX", Builtin::Floor}, {"FUP", Builtin::Ceil}};
  return program_.add(
      {ir::ExprOp::Call, kFunctions.at(ctx->FUNCTION()->getText()), 0, 0, expr(args[0]), ir::kNoExpr, r});
}

// ---- o-words -------------------------------------------------------------------------------

void Reader::start_sub(const std::string& name, SourceRange r, bool fanuc) {
  if (in_sub_ && fanuc_sub_ && fanuc) end_sub();
  if (in_sub_) {
    diags_.report(DiagId::ProgramStructure, r,
                  fmt::format("{} sub stands inside {}: a subroutine is defined outside any other", name, sub_.name));
    return;
  }
  for (const ir::Unit& u : program_.units)
    if (u.name == name) diags_.report(DiagId::ProgramStructure, r, fmt::format("{} is defined twice", name));
  sub_ = ir::Unit{};
  sub_.kind = ir::UnitKind::Subprogram;
  sub_.name = name;
  sub_.range = r;
  in_sub_ = true;
  fanuc_sub_ = fanuc;
}

void Reader::end_sub() {
  program_.units.push_back(std::move(sub_));
  defined_.push_back(program_.units.back().name);
  sub_ = ir::Unit{};
  in_sub_ = fanuc_sub_ = false;
}

// return [v], endsub [v]: #<_value> is v (0 without), #<_value_returned> says whether
// one was given.
void Reader::returns(ir::Block& b, ir::ExprId value) {
  ir::Stmt v{ir::StmtKind::Assign, b.range};
  v.target = global(Parameters::kValue, b.range);
  v.value = value == ir::kNoExpr ? program_.number(0, b.range) : value;
  b.stmts.push_back(std::move(v));
  ir::Stmt given{ir::StmtKind::Assign, b.range};
  given.target = global(Parameters::kValueReturned, b.range);
  given.value = program_.number(value == ir::kNoExpr ? 0 : 1, b.range);
  b.stmts.push_back(std::move(given));
  b.stmts.push_back({ir::StmtKind::Return, b.range});
}

Reader::Open* Reader::innermost(const std::string& name, SourceRange r, const char* what) {
  if (open_.empty() || open_.back().name != name) {
    diags_.report(DiagId::ProgramStructure, r,
                  open_.empty() ? fmt::format("{} {} closes nothing that is open", name, what)
                                : fmt::format("{} {} stands where {} is open", name, what, open_.back().name));
    return nullptr;
  }
  return &open_.back();
}

void Reader::oword(LinuxcncParser::OwordContext* ctx, ir::Block& block) {
  // In lower case, as LinuxCNC writes names; o0100 is o100.
  std::string name = lower(ctx->OWORD()->getText());
  if (name.size() > 1 && name[1] != '<') {
    size_t first = name.find_first_not_of('0', 1);
    name = "o" + (first == std::string::npos ? std::string("0") : name.substr(first));
  }
  const SourceRange r = range(ctx);
  std::vector<ir::ExprId> args;
  for (auto* e : ctx->expr()) args.push_back(expr(e));
  auto* kw = ctx->keyword();
  const size_t keyword = kw ? kw->getStart()->getType() : 0;
  auto takes = [&](size_t at_most, const char* what) {
    if (args.size() <= at_most) return true;
    diags_.report(DiagId::ProgramStructure, r, fmt::format("{} {} takes {}", name, lower(kw->getText()), what));
    block.has_errors = true;
    return false;
  };
  auto needs = [&](const char* what) {
    if (args.size() == 1) return true;
    diags_.report(DiagId::ProgramStructure, r, fmt::format("{} {} takes {}", name, lower(kw->getText()), what));
    block.has_errors = true;
    return false;
  };
  auto push = [&]() -> size_t {
    unit().blocks.push_back(std::move(block));
    return unit().blocks.size() - 1;
  };
  auto jump = [&](size_t at, ir::ExprId cond) {
    ir::Stmt j{ir::StmtKind::Jump, r};
    j.cond = cond;
    unit().blocks[at].stmts.push_back(std::move(j));
    return std::pair{at, unit().blocks[at].stmts.size() - 1};
  };
  auto negate = [&](ir::ExprId e) { return program_.add({ir::ExprOp::Not, Builtin::Sin, 0, 0, e, ir::kNoExpr, r}); };
  auto empty_block = [&]() {
    new_block(r);
    return unit().blocks.size() - 1;
  };
  auto loop = [&](const char* what) -> Open* {
    for (auto it = open_.rbegin(); it != open_.rend(); ++it)
      if (it->name == name && it->kind != Open::If) return &*it;
    diags_.report(DiagId::ProgramStructure, r, fmt::format("{} {} is in no loop {}", name, what, name));
    return nullptr;
  };
  switch (keyword) {
    case 0:  // O1000 alone: a Fanuc-style program, called by M98, ending with M99
      start_sub(name, r, true);
      return;
    case LinuxcncLexer::SUB:
      takes(0, "no value");
      if (!open_.empty() && !in_sub_)
        diags_.report(DiagId::ProgramStructure, r, fmt::format("{} sub stands inside {}", name, open_.back().name));
      start_sub(name, r, false);
      return;
    case LinuxcncLexer::ENDSUB:
    case LinuxcncLexer::RETURN: {
      const bool end = keyword == LinuxcncLexer::ENDSUB;
      if (!in_sub_ || (end && sub_.name != name)) {
        diags_.report(DiagId::ProgramStructure, r,
                      in_sub_ ? fmt::format("{} {} stands in {} sub", name, lower(kw->getText()), sub_.name)
                              : fmt::format("{} {} stands outside its sub", name, lower(kw->getText())));
        return;
      }
      takes(1, "at most one value");
      returns(block, args.empty() ? ir::kNoExpr : args[0]);
      push();
      if (end) {
        while (!open_.empty()) {
          diags_.report(DiagId::ProgramStructure, open_.back().range,
                        fmt::format("{} is not closed before {} endsub", open_.back().name, name));
          open_.pop_back();
        }
        end_sub();
      }
      return;
    }
    case LinuxcncLexer::CALL: {
      takes(kMaxArguments, "at most 30 arguments");
      ir::Stmt s{ir::StmtKind::Call, r};
      s.label = name;
      for (size_t i = 0; i < args.size() && i < kMaxArguments; ++i)
        s.args.push_back({params_.numbered, static_cast<uint32_t>(i + 1), args[i]});
      block.stmts.push_back(std::move(s));
      const size_t at = push();
      calls_.push_back({name, range(ctx->OWORD()->getSymbol(), ctx->OWORD()->getSymbol()), unit().name, at});
      return;
    }
    case LinuxcncLexer::IF: {
      if (!needs("a condition [...]")) return;
      const size_t at = push();
      open_.push_back({Open::If, name, r, at, jump(at, negate(args[0])), {}, {}, false});
      return;
    }
    case LinuxcncLexer::ELSEIF:
    case LinuxcncLexer::ELSE: {
      const bool is_else = keyword == LinuxcncLexer::ELSE;
      Open* o = innermost(name, r, lower(kw->getText()).c_str());
      if (!o || o->kind != Open::If || o->has_else) {
        if (o)
          diags_.report(DiagId::ProgramStructure, r,
                        fmt::format("{} {} {}", name, lower(kw->getText()),
                                    o->kind != Open::If ? "continues no if" : "follows the else of its if"));
        block.has_errors = true;
        push();
        return;
      }
      if (is_else ? !takes(0, "no value") : !needs("a condition [...]")) return;
      // The body before goes to endif; the false condition lands here.
      const size_t exit = empty_block();
      o->exits.push_back(jump(exit, ir::kNoExpr));
      const size_t at = push();
      if (o->next) land({*o->next}, label_of(at));
      o->next.reset();
      if (is_else)
        o->has_else = true;
      else
        o->next = jump(at, negate(args[0]));
      return;
    }
    case LinuxcncLexer::ENDIF: {
      Open* o = innermost(name, r, "endif");
      const size_t at = push();
      if (!o || o->kind != Open::If) {
        unit().blocks[at].has_errors = true;
        return;
      }
      const std::string label = label_of(at);
      if (o->next) land({*o->next}, label);
      land(o->exits, label);
      open_.pop_back();
      return;
    }
    case LinuxcncLexer::DO: {
      takes(0, "no value");
      const size_t at = push();
      label_of(at);
      open_.push_back({Open::Do, name, r, at, std::nullopt, {}, {}, false});
      return;
    }
    case LinuxcncLexer::WHILE: {
      if (!needs("a condition [...]")) return;
      if (!open_.empty() && open_.back().name == name && open_.back().kind == Open::Do) {
        // The end of do ... while: back to the do while the condition holds.
        Open o = std::move(open_.back());
        open_.pop_back();
        const size_t at = push();
        unit().blocks[at].stmts.push_back({ir::StmtKind::Jump, r});
        unit().blocks[at].stmts.back().cond = args[0];
        unit().blocks[at].stmts.back().label = label_of(o.head);
        land(o.continues, label_of(at));
        land(o.exits, label_of(empty_block()));
        return;
      }
      const size_t at = push();
      label_of(at);
      open_.push_back({Open::While, name, r, at, jump(at, negate(args[0])), {}, {}, false});
      return;
    }
    case LinuxcncLexer::ENDWHILE: {
      Open* o = innermost(name, r, "endwhile");
      const size_t at = push();
      if (!o || o->kind != Open::While) {
        unit().blocks[at].has_errors = true;
        return;
      }
      unit().blocks[at].stmts.push_back({ir::StmtKind::Jump, r});
      unit().blocks[at].stmts.back().label = label_of(o->head);
      const std::string exit = label_of(empty_block());
      land({*o->next}, exit);
      land(o->exits, exit);
      open_.pop_back();
      return;
    }
    case LinuxcncLexer::REPEAT: {
      if (!needs("a count [...]")) return;
      ir::Stmt s{ir::StmtKind::RepeatBegin, r};
      s.value = args[0];
      block.stmts.push_back(std::move(s));
      const size_t at = push();
      open_.push_back({Open::Repeat, name, r, at, std::nullopt, {}, {}, false});
      return;
    }
    case LinuxcncLexer::ENDREPEAT: {
      Open* o = innermost(name, r, "endrepeat");
      if (!o || o->kind != Open::Repeat) {
        block.has_errors = true;
        push();
        return;
      }
      block.stmts.push_back({ir::StmtKind::RepeatEnd, r});
      const size_t at = push();
      land(o->continues, label_of(at));
      land(o->exits, label_of(empty_block()));
      open_.pop_back();
      return;
    }
    case LinuxcncLexer::BREAK:
    case LinuxcncLexer::CONTINUE: {
      const bool is_break = keyword == LinuxcncLexer::BREAK;
      Open* o = loop(is_break ? "break" : "continue");
      const size_t at = push();
      if (!o) {
        unit().blocks[at].has_errors = true;
        return;
      }
      auto j = jump(at, ir::kNoExpr);
      if (is_break)
        o->exits.push_back(j);
      else if (o->kind == Open::While)
        land({j}, label_of(o->head));
      else
        o->continues.push_back(j);
      return;
    }
    default: return;
  }
}

}  // namespace ncc::linuxcnc
