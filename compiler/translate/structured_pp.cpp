// Structured translation into the partprogram dialect (docs/translate.md): R
// parameters, their formulas G26-G29, subprograms after the main program's end
// (G79 L ... G70) called by G71 L Q, and repeat loops as G73's counted jump back.
// pp has no condition: a jump on one is refused. Its R parameters hold thousandths,
// so only what keeps a value in thousandths is written: sums, differences and
// products by whole numbers of constants with at most three decimals.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "structured_impl.h"

namespace ncc::translate {
namespace {

constexpr uint32_t kParameters = 96;  // R0..R95 (P-9.1)
constexpr uint32_t kScratch = 16;     // R95 down: a block's computed values
constexpr double kLimit = 69999.999;  // P-9.1

class PpStructured final : public Structured {
 public:
  using Structured::Structured;

 private:
  // --- layout -----------------------------------------------------------------------

  bool verbatim() const override { return false; }
  bool reads_after_end() const override { return false; }

  void body() override {
    numbers_ = unit_numbers({});
    for (const ir::Unit& u : p_->units)
      for (const ir::Block& b : u.blocks)
        if (same_ && b.number) w_.reserve_number(static_cast<long>(*b.number));
    for (size_t u = 0; u < p_->units.size(); ++u)
      if (u == 0 || !(same_ && p_->units[u].kind == ir::UnitKind::Macro)) unit(p_->units[u], u == 0);
  }

  void open_unit(const ir::Unit& u, bool main) override {
    unit_ = &u;
    if (main) return;
    if (!u.title.empty()) w_.comment(u.title);
    // P-8.2: the entry block holds G79 and L alone: the unit's first block when it
    // has nothing else (pp's own), else a block before it.
    const std::string entry = fmt::format("G79 L{}", numbers_.at(u.name));
    if (!u.blocks.empty() && only_entry(u.blocks.front()))
      extra_words_ = {entry};
    else
      line(entry);
  }

  bool only_entry(const ir::Block& b) const {
    for (const ir::Word& w : b.words)
      if (w.kind == ir::WordKind::Parameter || (w.kind == ir::WordKind::Code && w.code >= 0 &&
                                                !p_->semantics.codes[static_cast<size_t>(w.code)].calls.empty()))
        return false;
    return std::all_of(b.stmts.begin(), b.stmts.end(), [](const ir::Stmt& s) {
      return s.kind == ir::StmtKind::Machine || s.kind == ir::StmtKind::Comment;
    });
  }

  void close_unit(const ir::Unit& u, bool main, bool) override {
    if (main) {
      // What stands after the main part's end is the subprograms' place (P-8.3).
      if (p_->units.size() > 1 && !ends_program(u)) line("M30");
      return;
    }
    if (!extra_words_.empty()) write_words(std::exchange(extra_words_, {}));
  }

  void block_begun() override {
    scratch_used_ = 0;
    r_words_ = 0;
  }

  void before_block(size_t i) override {
    const ir::Block& b = unit_->blocks[i];
    if (same_ && b.number)
      pending_number_ = static_cast<int>(*b.number);  // a jump's target
    else if (head_)
      pending_number_ = static_cast<int>(*std::exchange(head_, std::nullopt));
    else
      pending_number_ = number_of(b);
    if (!p_->units.empty() && unit_ != &p_->units.front()) {
      // P-8.2: the end block; a return alone after the last block (ISO's M99 line)
      // is its G70, as the translation back writes it.
      const auto& blocks = unit_->blocks;
      const ir::Block& last = blocks.back();
      const bool bare =
          blocks.size() > 1 && !last.number && last.comments.empty() && last.stmts.size() == 1 &&
          last.stmts.front().kind == ir::StmtKind::Return &&
          std::all_of(last.words.begin(), last.words.end(), [&](const ir::Word& w) {  // M99: the return's own
            return w.kind == ir::WordKind::Control || (w.kind == ir::WordKind::Code && w.code >= 0 &&
                                                       p_->semantics.codes[static_cast<size_t>(w.code)].calls.empty());
          });
      if (i + (bare ? 2 : 1) == blocks.size()) extra_words_.push_back("G70");
      for (const ir::Word& w : b.words)
        if (w.kind == ir::WordKind::Code && w.code >= 0)
          for (const FnCall& c : p_->semantics.codes[static_cast<size_t>(w.code)].calls)
            if (c.fn == Fn::ProgramEnd || c.fn == Fn::ProgramEndInformation)
              return fail(w.range, "the program's end in a subprogram: pp's ends the subprogram at G70, warned of");
    }
  }

  // --- flow -------------------------------------------------------------------------

  // pp's own G73 L Q, which the front end writes as its counter's statements; any
  // other jump tests a condition or goes on for ever.
  void jump(const ir::Stmt& s) override {
    const ir::Expr* c = s.cond == ir::kNoExpr ? nullptr : &p_->exprs[s.cond];
    const bool counted = same_ && c && c->op == ir::ExprOp::Gt && p_->exprs[c->a].op == ir::ExprOp::Var &&
                         p_->spaces[p_->exprs[c->a].space].name == "G73";
    if (!counted) return fail(s.range, "a jump: pp's G73 jumps a number of times, it tests no condition");
    if (s.label.size() < 2 || s.label[0] != 'N') return fail(s.range, "a jump to a block without a number");
    line(fmt::format("G73 L{} Q{}", s.label.substr(1), count_));
  }

  // The counter's arming (its count, Q) and its step: in the G73 word.
  std::string assignment(const ir::Stmt& s, const std::string& var, std::string) override {
    const ir::Expr& target = p_->exprs[s.target];
    const ir::ExprId value = s.value;
    if (same_ && target.op == ir::ExprOp::Var && p_->spaces[target.space].name == "G73") {
      // counter = [counter EQ 0]*[Q+1] + counter: Q is the Add's first operand.
      const ir::Expr& e = p_->exprs[value];
      if (e.op == ir::ExprOp::Add && p_->exprs[e.a].op == ir::ExprOp::Mul) {
        const ir::Expr& q1 = p_->exprs[p_->exprs[e.a].b];
        count_ = q1.op == ir::ExprOp::Add ? word_value(q1.a, 'Q') : "1";
      }
      return {};
    }
    // A store into a whole parameter (NC-110's BY, IN, LI) rounds: pp's does not.
    if (!same_ && target.op == ir::ExprOp::Var && p_->is_constant(target.a)) {
      const VarType type = p_->spaces[target.space].type_of(static_cast<uint32_t>(p_->exprs[target.a].number));
      if ((type == VarType::Byte || type == VarType::Integer || type == VarType::Long) && !is_whole(value))
        fail(target.range, "a store that rounds to a whole number: pp has no rounding");
    }
    store(var, value, true);
    return {};
  }

  // The source's numbers (pp's own: jumps go to them); another dialect's where pp
  // writes them and no line has the number yet (§2.2.1 d), else the writer's: a
  // translation back keeps them.
  std::optional<int> number_of(const ir::Block& b) override {
    auto n = Structured::number_of(b);
    if (same_ || !n) return n;
    return *n >= 1 && w_.claim_number(*n) ? n : std::nullopt;
  }

  void repeat_begin(const ir::Stmt& s) override {
    const ir::Expr& n = p_->exprs[s.value];
    if (n.op != ir::ExprOp::Number || n.number < 1 || n.number > 10000 || n.number != std::trunc(n.number))
      return fail(s.range,
                  "a repeat loop whose count is not a constant of 1..10000: pp's G73 counts Q of 1..9999 jumps");
    if (block_ && block_->skippable) return fail(s.range, "a repeat in a block '/' skips");
    flush();  // an outer loop's first block, numbered, when this one is its first
    Loop loop{static_cast<int>(n.number), 0};
    if (loop.count > 1) {
      loop.head = w_.fresh_number();
      head_ = loop.head;
    }
    loops_.push_back(loop);
    forget();
  }

  void repeat_end(const ir::Stmt&) override {
    if (loops_.empty()) return;
    const Loop loop = loops_.back();
    loops_.pop_back();
    if (head_) {  // an empty body
      fail(block_->range, "a repeat loop with no block in it");
      head_.reset();
    }
    if (loop.count > 1) line(fmt::format("G73 L{} Q{}", loop.head, loop.count - 1));
    forget();
  }

  void call(const ir::Stmt& s) override {
    forget();
    if (!numbers_.count(s.label))
      return fail(s.range,
                  s.label.find('/') != std::string::npos ? "a call of a block of a program" : "a call of " + s.label);
    // G65 gives the called program locals of its own: the target's parameters are global.
    if (p_->dialect == "iso" && !s.shares_locals && uses_locals(s.label))
      return fail(s.range,
                  "G65 of a program that uses #1-#33: ISO gives it locals of its own, pp's parameters are global");
    if (!s.args.empty())
      return fail(s.range, "a call with arguments: pp's subprograms take none (R parameters are global)");
    const bool macro = same_ && std::any_of(p_->units.begin(), p_->units.end(), [&](const ir::Unit& u) {
                         return u.name == s.label && u.kind == ir::UnitKind::Macro;
                       });
    std::string text = fmt::format("{} L{}", macro ? "G72" : "G71", numbers_.at(s.label));
    if (s.value != ir::kNoExpr && !(p_->is_constant(s.value) && p_->exprs[s.value].number == 1))
      text += " Q" + word_value(s.value, 'Q');
    line(text);
  }

  void ret(const ir::Stmt& s) override {
    if (in_main_) return fail(s.range, "M99 in the main program");
    if (block_ != &unit_->blocks.back())
      fail(s.range, "a return before the subprogram's end: pp's ends at its G70 block");
  }

  void conditional(const ir::Stmt& s) override { fail(s.range, "a statement under a condition: pp has no condition"); }
  void zero_all(uint32_t, uint32_t) override {}

  // R parameters start at 0, or as the machine's profile sets them (P-9.5).
  void start_parameters() override {
    if (mapped_.empty()) return;
    std::string text;
    for (const auto& [name, r] : mapped_)
      if (const std::string var = fmt::format("R{}", r); !starts_stored(var))
        text += fmt::format("{}{} 0", text.empty() ? "" : " ", var);
    if (!text.empty()) w_.line(text);
    std::string legend = "R parameters:";
    for (const auto& [r, name] : legend_) legend += fmt::format(" R{} {},", r, name);
    legend.pop_back();
    w_.comment(legend);
  }

  // --- values -----------------------------------------------------------------------

  // Each variable of the source in an R parameter from R0 up, in the order the
  // program first names them; pp's own keep their numbers.
  std::string var(const ir::Expr& e) override {
    if (e.op != ir::ExprOp::Var) {
      fail(e.range, "a store into a memory or a system variable");
      return "R0";
    }
    if (!p_->is_constant(e.a)) {
      fail(e.range, "a computed parameter number: pp names each R parameter");
      return "R0";
    }
    const uint32_t index = static_cast<uint32_t>(p_->exprs[e.a].number);
    if (same_) return fmt::format("R{}", index);
    if (p_->dialect == "iso" && index == 0) fail(e.range, "the vacant #0: pp's parameters are never vacant");
    const std::string name = fmt::format("{}{}", p_->spaces[e.space].name, index);
    auto it = mapped_.find(name);
    if (it == mapped_.end()) {
      // ISO's #500+n is R n, as R n goes to #500+n: a round trip keeps the number.
      const auto n = parameter_number(e, 0, kParameters - kScratch, r_taken_, next_r_);
      if (!n) {
        fail(e.range, fmt::format("more variables than the R parameters R0-R{} hold", kParameters - kScratch - 1));
        return "R0";
      }
      it = mapped_.emplace(name, *n).first;
      legend_.emplace_back(it->second, name);
    }
    return fmt::format("R{}", it->second);
  }

  // The text expressions of the common part are not pp's: store() writes them.
  std::string expr(ir::ExprId, int) override { return {}; }

  std::string value(ir::ExprId id, char letter) override { return word_value(id, letter); }

  // A word's value (P-9.3): a constant, R<m> or -R<m>, else a scratch parameter.
  std::string word_value(ir::ExprId id, char letter) {
    const ir::Expr& e = p_->exprs[bare(id)];
    if (auto v = constant_of(id)) {
      const OutWord word{letter, *v, kind_of(letter)};
      if (auto why = w_.unwritable(word)) fail(e.range, *why);
      return number(word, e.range);
    }
    if (auto r = plain(id)) return *r;
    const std::string r = scratch(e.range);
    store(r, id);
    return r;
  }

  static Value kind_of(char letter) {
    switch (letter) {
      case 'F': return Value::Feed;
      case 'S': return Value::Speed;
      case 'T':
      case 'D':
      case 'L':
      case 'Q': return Value::Count;
      case 'G':
      case 'M': return Value::Code;
      default: return Value::Length;
    }
  }

  // R<m> or -R<m>: what a word or an R word takes as its value.
  std::optional<std::string> plain(ir::ExprId id) {
    const ir::Expr& e = p_->exprs[bare(id)];
    if (e.op == ir::ExprOp::Var) return var(e);
    if (e.op == ir::ExprOp::Neg && p_->exprs[bare(e.a)].op == ir::ExprOp::Var) return "-" + var(p_->exprs[bare(e.a)]);
    return std::nullopt;
  }

  std::string scratch(SourceRange at) {
    if (scratch_used_ == kScratch) {
      fail(at, fmt::format("more than {} computed values in a block", kScratch));
      return "R95";
    }
    return fmt::format("R{}", kParameters - 1 - scratch_used_++);
  }

  // r := the value of `id`, as R words and G26-G29 formulas (P-9.3, P-9.4): r = a op b
  // is r := a, then r op= b, where a and b are constants or parameters, else scratch
  // parameters computed first. A constant with more than three decimals, a product
  // of two variables or a quotient would be rounded to R's 0.001: refused.
  void store(const std::string& r, ir::ExprId id, bool in_block = false) {
    const ir::Expr& e = p_->exprs[bare(id)];
    // An R word takes a constant or ±R<m> (P-9.3): it goes into the block's words,
    // which pp evaluates first (P-9.5).
    if (auto v = constant_of(id)) {
      if (std::fabs(*v) > kLimit || std::fabs(*v * 1000 - std::round(*v * 1000)) > 1e-6)
        return fail(e.range, fmt::format("{}: pp's R holds thousandths within ±69999.999", exact(*v, false)));
      return r_word(fmt::format("{} {}", r, exact(*v, false)), in_block);
    }
    if (auto p = plain(id)) {
      if (*p != r) r_word(fmt::format("{} {}", r, *p), in_block);
      return;
    }
    flush_r_words();  // a formula reads the values set before it
    auto operand = [&](ir::ExprId x) -> std::string {
      if (auto v = constant_of(x)) return exact(*v, false);
      if (auto p = plain(x)) return *p;
      const std::string t = scratch(e.range);
      store(t, x);
      return t;
    };
    auto formula = [&](const char* code, ir::ExprId a, ir::ExprId b) {
      // Into r itself when r is the first operand (R1 = R1 + R2: G26 R1 R2).
      const std::string first = plain(a).value_or("");
      const std::string second = operand(b);
      if (first != r) store(r, a);
      flush_r_words();
      line(fmt::format("{} {} {}", code, r, second));
    };
    auto whole = [&](ir::ExprId x) {
      auto v = constant_of(x);
      return v && *v == std::trunc(*v);
    };
    switch (e.op) {
      case ir::ExprOp::Add: return formula("G26", e.a, e.b);
      case ir::ExprOp::Sub: return formula("G27", e.a, e.b);
      case ir::ExprOp::Neg:
        store(r, e.a);
        flush_r_words();
        return line(fmt::format("G28 {} -1", r));
      case ir::ExprOp::Mul:
        if (whole(e.b)) return formula("G28", e.a, e.b);
        if (whole(e.a)) return formula("G28", e.b, e.a);
        if (same_) return formula("G28", e.a, e.b);  // pp's own: rounded as the source rounds
        return fail(e.range, "a product of two values: pp's R would round it to 0.001");
      case ir::ExprOp::Div:
        if (same_) return formula("G29", e.a, e.b);
        return fail(e.range, "a quotient: pp's R would round it to 0.001");
      case ir::ExprOp::Call: return fail(e.range, "a function: pp has none");
      default: return fail(e.range, "a comparison, a logical operation, a memory or a system variable: pp has none");
    }
  }

  // An R word of the block (a variable set to a constant or ±R<m>), or a block of its
  // own when a formula or a word's scratch value follows it.
  void r_word(std::string word, bool in_block) {
    if (!in_block) {
      flush_r_words();
      return line(word);
    }
    if (r_words_ > extra_words_.size()) r_words_ = 0;  // taken by the block's words
    extra_words_.insert(extra_words_.begin() + static_cast<std::ptrdiff_t>(r_words_++), std::move(word));
  }
  void flush_r_words() {
    if (r_words_ > extra_words_.size()) r_words_ = 0;
    if (r_words_ == 0) return;
    std::vector<std::string> words(extra_words_.begin(), extra_words_.begin() + static_cast<std::ptrdiff_t>(r_words_));
    extra_words_.erase(extra_words_.begin(), extra_words_.begin() + static_cast<std::ptrdiff_t>(r_words_));
    r_words_ = 0;
    write_words(words);
  }

  const ir::Unit* unit_ = nullptr;
  size_t r_words_ = 0;                  // the R words at the front of extra_words_
  std::map<std::string, int> numbers_;  // unit -> its L number
  std::map<std::string, uint32_t> mapped_;
  std::vector<std::pair<uint32_t, std::string>> legend_;
  uint32_t next_r_ = 0, scratch_used_ = 0;
  std::set<uint32_t> r_taken_;  // the R parameters mapped_ gives
  std::string count_ = "1";     // the Q of pp's own G73 being written
  struct Loop {
    int count;
    long head;
  };
  std::vector<Loop> loops_;
  std::optional<long> head_;  // the number of a loop's first block, still to be written
};

}  // namespace

std::unique_ptr<Structured> make_pp_structured(std::string dialect, Writer& writer, const MachineConfig& target) {
  return std::make_unique<PpStructured>(std::move(dialect), writer, target);
}

}  // namespace ncc::translate
