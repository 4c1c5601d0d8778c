// Structured translation into RS274NGC as LinuxCNC 2.9 reads it: subprograms as
// named o-word subs before the main program, and every jump and repeat loop as one
// of LinuxCNC's o-word blocks (if, while, do, repeat) — it has no GOTO. A jump
// becomes a block when the jumps of a program nest: a forward jump skips an `if`
// block, a backward one closes a `do ... while`, Macro B's WHILE pattern is a
// `while`; jumps that cross each other are refused (docs/translate.md).
#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "structured_impl.h"

namespace ncc::translate {
namespace {

class NgcStructured final : public Structured {
 public:
  using Structured::Structured;

 private:
  // An o-word block over a stretch of the unit: it opens and closes at positions 2i
  // (before block i) and 2i+1 (after it).
  struct Region {
    enum Kind { If, While, Do, Repeat } kind;
    size_t open, close;
    std::string cond;  // the condition or the count, written
    int number = 0;
    size_t rank = 0;  // in the order the regions open
  };

  void body() override {
    name_subs();
    for (size_t u = 1; u < p_->units.size(); ++u) unit(p_->units[u], false);
    if (!p_->units.empty()) unit(p_->units.front(), true);
  }

  // Each called unit is a named sub: o<o1000>, o<l100>, o<flowa>.
  void name_subs() {
    std::set<std::string> taken;
    for (size_t u = 1; u < p_->units.size(); ++u) {
      std::string name;
      const std::string& source = p_->units[u].name;
      for (char c : source.substr(source.rfind('/') + 1))
        if (std::isalnum(static_cast<unsigned char>(c)))
          name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (name.empty()) name = "sub";
      std::string unique = name;
      for (int n = 2; !taken.insert(unique).second; ++n) unique = fmt::format("{}_{}", name, n);
      subs_[source] = unique;
    }
  }

  void open_unit(const ir::Unit& u, bool main) override {
    unit_ = &u;
    analyse(u);
    if (main) return;
    w_.append("\n");
    if (!u.title.empty()) w_.comment(u.title);
    w_.line(fmt::format("o<{}> sub", subs_.at(u.name)));
  }

  void close_unit(const ir::Unit& u, bool main, bool) override {
    at(2 * u.blocks.size());
    if (!main) return w_.line(fmt::format("o<{}> endsub", subs_.at(u.name)));
    if (!ends_program(u)) w_.line("M2");  // LinuxCNC reads a program to its M2
  }

  void before_block(size_t i) override {
    at(2 * i);
    const ir::Block& b = unit_->blocks[i];
    if (b.number) pending_number_ = static_cast<int>(*b.number);
  }
  void after_block(size_t i) override { at(2 * i + 1); }

  // The o-word blocks that close, then those that open, at a position.
  void at(size_t position) {
    std::vector<const Region*> closing, opening;
    for (const Region& r : regions_) {
      if (r.close == position) closing.push_back(&r);
      if (r.open == position) opening.push_back(&r);
    }
    std::sort(closing.begin(), closing.end(), [](const Region* a, const Region* b) { return a->rank > b->rank; });
    std::sort(opening.begin(), opening.end(), [](const Region* a, const Region* b) { return a->rank < b->rank; });
    for (const Region* r : closing) {
      static constexpr const char* kClose[] = {"endif", "endwhile", "", "endrepeat"};
      w_.line(r->kind == Region::Do ? fmt::format("o{} while [{}]", r->number, r->cond)
                                    : fmt::format("o{} {}", r->number, kClose[r->kind]));
    }
    for (const Region* r : opening) {
      static constexpr const char* kOpen[] = {"if", "while", "do", "repeat"};
      w_.line(r->kind == Region::Do ? fmt::format("o{} do", r->number)
                                    : fmt::format("o{} {} [{}]", r->number, kOpen[r->kind], r->cond));
    }
    if (!closing.empty() || !opening.empty()) forget();
  }

  // The o-word blocks of a unit's jumps and repeat loops, checked to nest.
  void analyse(const ir::Unit& u) {
    regions_.clear();
    std::map<std::string, size_t> labels;
    for (size_t i = 0; i < u.blocks.size(); ++i)
      if (!u.blocks[i].label.empty()) labels.emplace(u.blocks[i].label, i);
    std::set<const ir::Stmt*> consumed;
    std::vector<const ir::Stmt*> of_region;  // the statement each region comes from
    auto last = [](const ir::Block& b, const ir::Stmt& s) { return &b.stmts.back() == &s; };
    for (size_t i = 0; i < u.blocks.size(); ++i) {
      const ir::Block& b = u.blocks[i];
      for (const ir::Stmt& s : b.stmts) {
        if (consumed.count(&s)) continue;
        if (b.skippable && (s.kind == ir::StmtKind::Jump || s.kind == ir::StmtKind::RepeatBegin))
          return fail(s.range, "a jump or a repeat in a block '/' skips: LinuxCNC skips no o-word");
        if (s.kind == ir::StmtKind::Jump) {
          if (s.label.empty()) return fail(s.range, "a jump to a computed block number: LinuxCNC has no GOTO");
          if (!last(b, s)) return fail(s.range, "a jump before other statements of its block");
          if (!labels.count(s.label)) {  // a block streamed and written already
            needs_whole_ = true;
            return;
          }
          const size_t t = labels.at(s.label);
          if (t > i) {
            // Macro B's WHILE: a jump over the body to a block that jumps back.
            const ir::Block& end = u.blocks[t];
            const ir::Stmt* back =
                end.stmts.size() == 1 && end.stmts[0].kind == ir::StmtKind::Jump ? &end.stmts[0] : nullptr;
            if (back && !back->label.empty() && labels.count(back->label) && labels.at(back->label) == i + 1 &&
                s.cond != ir::kNoExpr && p_->exprs[s.cond].op == ir::ExprOp::Not && p_->exprs[s.cond].a == back->cond) {
              regions_.push_back({Region::While, 2 * i + 1, 2 * t, expr(back->cond, kOr)});
              consumed.insert(back);
            } else {
              regions_.push_back({Region::If, 2 * i + 1, 2 * t, s.cond == ir::kNoExpr ? "0" : negation(s.cond, kOr)});
            }
          } else {
            regions_.push_back({Region::Do, 2 * t, 2 * i + 1, s.cond == ir::kNoExpr ? "1" : expr(s.cond, kOr)});
          }
          of_region.push_back(&s);
        } else if (s.kind == ir::StmtKind::RepeatBegin) {
          if (!last(b, s)) return fail(s.range, "a repeat before other statements of its block");
          size_t depth = 0, e = i + 1;
          for (; e < u.blocks.size(); ++e) {
            const auto& stmts = u.blocks[e].stmts;
            const auto end = std::find_if(stmts.begin(), stmts.end(), [&](const ir::Stmt& x) {
              if (x.kind == ir::StmtKind::RepeatBegin) ++depth;
              return x.kind == ir::StmtKind::RepeatEnd && depth-- == 0;
            });
            if (end != stmts.end()) {
              if (end != stmts.begin())
                return fail(end->range, "the end of a repeat after other statements of its block");
              break;
            }
          }
          if (e == u.blocks.size()) return fail(s.range, "a repeat without its end");
          regions_.push_back({Region::Repeat, 2 * i + 1, 2 * e, expr(s.value, kOr)});
          of_region.push_back(&s);
        }
      }
    }
    breaks(u, of_region, consumed);
    // Opening order: by position, the outer (longer) first; each region inside the
    // one before it or after its end.
    std::vector<size_t> order(regions_.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return regions_[a].open != regions_[b].open ? regions_[a].open < regions_[b].open
                                                  : regions_[a].close > regions_[b].close;
    });
    std::vector<size_t> open;
    for (size_t rank = 0; rank < order.size(); ++rank) {
      Region& r = regions_[order[rank]];
      r.rank = rank;
      r.number = ++next_number_;
      while (!open.empty() && regions_[open.back()].close <= r.open) open.pop_back();
      if (!open.empty() && r.close > regions_[open.back()].close) {
        regions_.clear();
        breaks_.clear();
        return fail(of_region[order[rank]]->range,
                    "a jump into or out of a loop or another jump's blocks: LinuxCNC has no GOTO, only o-word blocks "
                    "that nest");
      }
      open.push_back(order[rank]);
    }
  }

  // A jump out of the innermost loop to the first block after it is a `break` (an
  // `if` around it when the jump has a condition): its region goes.
  void breaks(const ir::Unit& u, std::vector<const ir::Stmt*>& of_region, const std::set<const ir::Stmt*>& consumed) {
    breaks_.clear();
    for (size_t k = 0; k < regions_.size();) {
      const Region& r = regions_[k];
      const Region* loop = nullptr;
      for (const Region& l : regions_)
        if (l.kind != Region::If && l.open < r.open && r.open < l.close && l.close < r.close &&
            (!loop || l.open > loop->open))
          loop = &l;
      // Between the loop's end and the jump's target, only what ends the loop: the
      // jump back of a while, the end of a repeat.
      bool after = loop && r.kind == Region::If;
      for (size_t b = loop ? (loop->close + 1) / 2 : 0; after && b < r.close / 2; ++b)
        for (const ir::Stmt& x : u.blocks[b].stmts) after &= consumed.count(&x) || x.kind == ir::StmtKind::RepeatEnd;
      if (!after) {
        ++k;
        continue;
      }
      breaks_[of_region[k]] = static_cast<size_t>(loop - regions_.data());
      regions_.erase(regions_.begin() + static_cast<std::ptrdiff_t>(k));
      of_region.erase(of_region.begin() + static_cast<std::ptrdiff_t>(k));
      // The loop index moved if it stood after the erased region.
      for (auto& [stmt, index] : breaks_)
        if (index > k) --index;
    }
  }

  void jump(const ir::Stmt& s) override {
    auto it = breaks_.find(&s);
    if (it == breaks_.end()) return;  // the regions' o-words
    const int loop = regions_[it->second].number;
    if (s.cond == ir::kNoExpr) return oword(fmt::format("o{} break", loop));
    const int n = ++next_number_;
    oword(fmt::format("o{} if [{}]", n, expr(s.cond, kOr)));
    oword(fmt::format("o{} break", loop));
    oword(fmt::format("o{} endif", n));
  }
  void repeat_begin(const ir::Stmt&) override {}
  void repeat_end(const ir::Stmt&) override {}

  void call(const ir::Stmt& s) override {
    forget();
    if (!subs_.count(s.label))
      return fail(s.range,
                  s.label.find('/') != std::string::npos ? "a call of a block of a program" : "a call of " + s.label);
    if (s.shares_locals && uses_locals(s.label))
      return fail(s.range,
                  "M98 of a subprogram that uses #1-#33: it shares them with its caller, a LinuxCNC sub has its own");
    // G65's arguments by their place: #1 is the first.
    std::string text = fmt::format("o<{}> call", subs_.at(s.label));
    uint32_t last = 0;
    for (const ir::CallArg& a : s.args) last = std::max(last, a.index);
    if (last > 30) return fail(s.range, fmt::format("the argument #{}: a LinuxCNC sub takes #1-#30", last));
    for (uint32_t i = 1; i <= last; ++i) {
      auto a = std::find_if(s.args.begin(), s.args.end(), [&](const ir::CallArg& x) { return x.index == i; });
      text += a == s.args.end() ? " [0]" : " [" + expr(a->value, kOr) + "]";
    }
    if (s.value == ir::kNoExpr || (p_->is_constant(s.value) && p_->exprs[s.value].number == 1)) return oword(text);
    const int n = ++next_number_;
    oword(fmt::format("o{} repeat [{}]", n, expr(s.value, kOr)));
    oword(text);
    oword(fmt::format("o{} endrepeat", n));
  }

  void ret(const ir::Stmt&) override {
    if (in_main_) return line("M2");              // M99 with no call open ends the run
    if (block_ == &unit_->blocks.back()) return;  // endsub returns
    oword(fmt::format("o<{}> return", subs_.at(unit_->name)));
  }

  void conditional(const ir::Stmt& s) override {
    const int n = ++next_number_;
    oword(fmt::format("o{} if [{}]", n, expr(s.cond, kOr)));
    statement(s);
    oword(fmt::format("o{} endif", n));
    forget();
  }

  // An o-word line: the block's number and comments go on a line before it.
  void oword(const std::string& text) {
    if (block_ && block_->skippable)
      fail(block_->range, "a call or a condition in a block '/' skips: LinuxCNC skips no o-word");
    flush();
    w_.line(text);
  }

  std::string assignment(const ir::Stmt&, const std::string& var, std::string text) override {
    const bool simple = text.find_first_of("+-*/[ ") == std::string::npos ||
                        (text[0] == '-' && text.find_first_of("+*/[ ", 1) == std::string::npos);
    return var + "=" + (simple ? text : "[" + text + "]");
  }

  void zero_all(uint32_t first, uint32_t count) override {
    const int n = ++next_number_;
    w_.line("#1=0");
    w_.line(fmt::format("o{} while [#1 LT {}]", n, count));
    w_.line(fmt::format("#[{}+#1]=0", first));
    w_.line("#1=[#1+1]");
    w_.line(fmt::format("o{} endwhile", n));
  }

  // LinuxCNC reads ISO's words as ISO does (its codes differ: M07 is mist).
  bool reads_source_words() const override { return p_->dialect == "iso"; }

  // rs274 makes a G0 or G1 without axis words a move to where the tool is.
  bool motion_code_moves() const override { return true; }

  // LinuxCNC's AND binds as loosely as OR; they go left to right.
  int and_level() const override { return kOr; }

  // LinuxCNC's FIX rounds down, FUP up and ROUND halves up: the IR's towards zero,
  // away from zero and halves away from zero are written out of them.
  std::string builtin(const ir::Expr& e) override {
    double v = 0;
    std::string_view why;
    const bool emulated = e.builtin == Builtin::Trunc || e.builtin == Builtin::Away || e.builtin == Builtin::Round;
    if (auto a = constant(e.a); emulated && a && e.a != scaled_ && eval_builtin(e.builtin, &*a, v, why))
      return exact(v, false);  // FIX[-2.5]: -2, as ISO has it
    const std::string x = "[" + operand(e.a) + "]";
    switch (e.builtin) {
      case Builtin::Trunc: return fmt::format("[[{0} GE 0]*FIX{0}+[{0} LT 0]*FUP{0}]", x);
      case Builtin::Away: return fmt::format("[[{0} GE 0]*FUP{0}+[{0} LT 0]*FIX{0}]", x);
      case Builtin::Round: return fmt::format("[[{0} GE 0]*FIX[{0}+0.5]+[{0} LT 0]*FUP[{0}-0.5]]", x);
      case Builtin::Floor: return "FIX" + x;
      case Builtin::Ceil: return "FUP" + x;
      case Builtin::RoundTo: fail(e.range, "ROUND of an address value (to the increment of its units)"); return "0";
      default: return Structured::builtin(e);
    }
  }

  // The value of an expression of numbers alone (7/2, -2.5).
  std::optional<double> constant(ir::ExprId id) const {
    const ir::Expr& e = p_->exprs[id];
    if (e.op == ir::ExprOp::Number) return e.number;
    if (e.op == ir::ExprOp::Neg || e.op == ir::ExprOp::ZeroIfVacant || e.op == ir::ExprOp::Check) {
      auto a = constant(e.a);
      return a && e.op == ir::ExprOp::Neg ? std::optional<double>(-*a) : a;
    }
    if (e.a == ir::kNoExpr || e.b == ir::kNoExpr) return std::nullopt;
    const std::optional<double> a = constant(e.a), b = constant(e.b);
    if (!a || !b) return std::nullopt;
    const double x = *a, y = *b;
    switch (e.op) {
      case ir::ExprOp::Add: return x + y;
      case ir::ExprOp::Sub: return x - y;
      case ir::ExprOp::Mul: return x * y;
      case ir::ExprOp::Div: return y != 0 ? std::optional<double>(x / y) : std::nullopt;
      default: return std::nullopt;
    }
  }

  // The IR's remainder has the dividend's sign (C's fmod); LinuxCNC adds |b| to a
  // negative one.
  std::string modulo(const ir::Expr& e, int) override {
    const std::string a = "[" + expr(e.a, kOr) + "]", b = "[" + expr(e.b, kOr) + "]";
    return fmt::format("[[{0} MOD {1}]-ABS{1}*[[{0} LT 0] AND [[{0} MOD {1}] NE 0]]]", a, b);
  }

  // Macro B's vacant value has no LinuxCNC counterpart; #31-#33 are locals of a
  // Macro B call and globals in LinuxCNC.
  void check_variable(const ir::Expr& e, uint32_t index) override {
    if (p_->dialect != "iso") return;
    if (index == 0)
      fail(e.range, "the vacant #0: LinuxCNC's parameters are never vacant");
    else if (index >= 31 && index <= 33)
      fail(e.range, fmt::format("#{}: a local of ISO, a global of LinuxCNC", index));
  }

  std::map<std::string, std::string> subs_;   // unit name -> sub name
  std::vector<Region> regions_;               // of the unit being written
  std::map<const ir::Stmt*, size_t> breaks_;  // a jump that leaves a loop: the loop's region
  const ir::Unit* unit_ = nullptr;
  int next_number_ = 99;  // o-words of the file: o100 up
};

}  // namespace

std::unique_ptr<Structured> make_ngc_structured(std::string dialect, Writer& writer, const MachineConfig& target) {
  return std::make_unique<NgcStructured>(std::move(dialect), writer, target);
}

}  // namespace ncc::translate
