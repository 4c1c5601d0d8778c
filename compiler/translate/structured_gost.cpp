// Structured translation into GOST 20999-83: the program's blocks with their codes,
// canned cycles, arcs and comments, every value a constant in the words of the
// target's format descriptor. GOST 20999 has no parameters, jumps, loops or
// subprograms: a loop of a constant count and a call are written out block by
// block; a program with parameters or jumps is refused, and --flatten writes the
// blocks it runs (docs/translate.md).
#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "structured_impl.h"

namespace ncc::translate {
namespace {

constexpr const char* kFlatten = "; --flatten writes the blocks the program runs";

class GostStructured final : public Structured {
 public:
  GostStructured(std::string dialect, Writer& writer, const MachineConfig& target)
      : Structured(std::move(dialect), writer, target), last_number_(same_ ? 0 : 1) {}

 private:
  // The main program with its repeat loops and calls written out (a loop of a
  // constant count runs the same blocks each time: the program needs no loop); a
  // second program on the medium follows it into GOST, and is refused elsewhere (unit()).
  void body() override {
    ir::Unit main = p_->units.front();
    main.blocks.clear();
    const size_t before = problems.size();
    if (unroll(p_->units.front().blocks, 0, p_->units.front().blocks.size(), main.blocks, 0)) {
      unit(main, true);
    } else {  // the blocks before what cannot be written out, for their own problems, in the text's order
      std::vector<Problem> unrolling(problems.begin() + static_cast<std::ptrdiff_t>(before), problems.end());
      problems.resize(before);
      unit(main, true);
      problems.insert(problems.end(), unrolling.begin(), unrolling.end());
    }
    for (size_t u = 1; u < p_->units.size(); ++u)
      if (p_->units[u].kind == ir::UnitKind::Program) unit(p_->units[u], false);
  }

  // Blocks [from, to) with each repeat loop's body `count` times and each call's
  // program in its place; false (and refused) where a count is not a constant or
  // the blocks would be too many.
  bool unroll(const std::vector<ir::Block>& blocks, size_t from, size_t to, std::vector<ir::Block>& out, int depth) {
    constexpr size_t kMost = 200000;
    for (size_t i = from; i < to; ++i) {
      ir::Block b = blocks[i];
      auto flow = std::find_if(b.stmts.begin(), b.stmts.end(), [](const ir::Stmt& s) {
        return s.kind == ir::StmtKind::RepeatBegin || s.kind == ir::StmtKind::Call;
      });
      if (flow == b.stmts.end()) {
        // The end of a repeat written out, and a return at a program's end: nothing left.
        std::erase_if(b.stmts, [&](const ir::Stmt& s) {
          return s.kind == ir::StmtKind::RepeatEnd || (s.kind == ir::StmtKind::Return && depth > 0 && i + 1 == to);
        });
        out.push_back(std::move(b));
        if (out.size() > kMost)
          return fail(blocks[i].range, fmt::format("a program of more than {} blocks written out{}", kMost, kFlatten)),
                 false;
        continue;
      }
      const ir::Stmt s = *flow;
      if (std::next(flow) != b.stmts.end())
        return fail(s.range, std::string("a call or a repeat before other statements of its block") + kFlatten), false;
      b.stmts.erase(flow);
      int count = 1;
      if (s.value != ir::kNoExpr) {
        const ir::Expr& n = p_->exprs[s.value];
        count = n.op == ir::ExprOp::Number && n.number >= 0 && n.number == std::trunc(n.number)
                    ? static_cast<int>(n.number)
                    : -1;
      }
      if (count < 0) return fail(s.range, std::string("a count computed when the program runs") + kFlatten), false;
      out.push_back(std::move(b));  // its words run first
      if (s.kind == ir::StmtKind::Call) {
        auto unit =
            std::find_if(p_->units.begin(), p_->units.end(), [&](const ir::Unit& u) { return u.name == s.label; });
        if (unit == p_->units.end() || !s.args.empty() || depth > 8)
          return fail(s.range,
                      std::string("a call of ") + s.label + ", with arguments or nested deeper than 8" + kFlatten),
                 false;
        for (int k = 0; k < count; ++k)
          if (!unroll(unit->blocks, 0, unit->blocks.size(), out, depth + 1)) return false;
        continue;
      }
      // The repeat's end: the block whose first statement closes it.
      size_t end = i + 1;
      for (int open = 0; end < to; ++end) {
        const auto& stmts = blocks[end].stmts;
        if (!stmts.empty() && stmts.front().kind == ir::StmtKind::RepeatEnd && open == 0) break;
        for (const ir::Stmt& x : stmts)
          open += x.kind == ir::StmtKind::RepeatBegin ? 1 : x.kind == ir::StmtKind::RepeatEnd ? -1 : 0;
      }
      if (end == to) return fail(s.range, std::string("a repeat without its end") + kFlatten), false;
      for (int k = 0; k < count; ++k)
        if (!unroll(blocks, i + 1, end, out, depth)) return false;
      i = end - 1;  // the end's block goes on as any other, without its end
    }
    return true;
  }
  // GOST into GOST: the medium's programs one after the other, each with its number.
  bool next_program(const ir::Unit& u) override {
    if (!same_ || !w_.next_program(std::string_view(u.name).substr(1), u.title)) return false;
    last_number_ = 0;  // its numbers rise from its start
    return true;
  }
  // GOST into GOST: the words and comments after a '/' in the middle of a block stay
  // after it (Table 2), and the block's end of program counts where it is before it.
  bool skip_within(const ir::Block& b) override {
    if (!same_ || std::any_of(b.stmts.begin(), b.stmts.end(), [](const ir::Stmt& s) {
          return s.kind != ir::StmtKind::Comment && s.kind != ir::StmtKind::Machine;
        }))
      return false;
    std::array<std::string, 2> part;  // before the '/', after it
    auto add = [&](bool optional, const std::string& text) {
      std::string& to = part[optional];
      if (!text.empty()) to += (to.empty() ? "" : " ") + text;
    };
    for (const ir::Word& w : b.words) {
      add(w.optional, verbatim_word(w));
      if (!w.optional && w.kind == ir::WordKind::Code && w.code >= 0)
        state(p_->semantics.codes[static_cast<size_t>(w.code)].calls);
    }
    for (const ir::Stmt& s : b.stmts)
      if (s.kind == ir::StmtKind::Comment) add(s.optional, w_.inline_comment(s.label));
    line(part[0] + (part[0].empty() ? "/" : " /") + (part[1].empty() ? "" : " " + part[1]));
    return true;
  }
  void open_unit(const ir::Unit& u, bool) override { unit_ = &u; }
  void close_unit(const ir::Unit&, bool, bool) override {}
  void before_block(size_t i) override { pending_number_ = number_of(unit_->blocks[i]); }

  // §1.4: the first block carries its number; N1 is the start's (last_number_).
  std::string first_block_prefix(char first) override {
    if (first == 'N' || first == ':' || same_ || w_.unwritable({'N', 1, Value::Count})) return {};
    w_.reserve_number(1);  // the end's M02 comes after it
    return "N" + w_.number({'N', 1, Value::Count}) + " ";
  }

  bool verbatim() const override { return false; }
  bool reads_after_end() const override { return false; }

  // The source's numbers where they rise (§1.4), after the start's N1.
  std::optional<int> number_of(const ir::Block& b) override {
    auto n = Structured::number_of(b);
    if (!n || *n <= last_number_) return std::nullopt;
    last_number_ = *n;
    main_number_ = b.main_block;  // ':' (§2.6)
    return n;
  }

  void jump(const ir::Stmt& s) override { fail(s.range, std::string("a jump: GOST 20999 has none") + kFlatten); }
  // Repeats and calls are written out (unroll()); what is left could not be.
  void repeat_begin(const ir::Stmt&) override {}
  void repeat_end(const ir::Stmt&) override {}
  void call(const ir::Stmt&) override {}
  void ret(const ir::Stmt& s) override {
    fail(s.range, std::string("a return from a subprogram: GOST 20999 has none") + kFlatten);
  }
  void conditional(const ir::Stmt& s) override {
    fail(s.range, std::string("a condition: GOST 20999 has none") + kFlatten);
  }
  std::string assignment(const ir::Stmt&, const std::string&, std::string) override { return {}; }
  void zero_all(uint32_t, uint32_t) override {}
  void start_parameters() override {}

  std::string var(const ir::Expr& e) override {
    fail(e.range, std::string("a parameter: GOST 20999 has none") + kFlatten);
    return {};
  }

  // A word's value: a constant in the format's digits (§9.2).
  std::string value(ir::ExprId id, char letter) override {
    const ir::Expr& e = p_->exprs[id];
    std::optional<double> v;
    if (e.op == ir::ExprOp::Number)
      v = e.number;
    else if (e.op == ir::ExprOp::Neg && p_->exprs[e.a].op == ir::ExprOp::Number)
      v = -p_->exprs[e.a].number;
    if (!v) {
      fail(e.range, std::string("a value computed when the program runs: GOST 20999 has no parameters") + kFlatten);
      return "0";
    }
    // §3.3.5: a format whose T word holds tool and offset digits (T1 is written T100)
    // says the offset with the tool only (GOST's own D: the T word's, value('T')).
    if (letter == 'D' && std::stoll(w_.number({'T', 1, Value::Count})) != 1) {
      fail(e.range,
           "an offset (D) where the T word holds tool and offset digits (§3.3.5): the target says it with its tool "
           "only");
      return "0";
    }
    OutWord word{letter, *v, kind_of(letter)};
    if (letter == 'T')  // GOST's own T of tool and offset digits: the offset the reader took from it
      for (const ir::Word& d : block_->words)
        if (d.derived && d.address == "D") word.offset = static_cast<int>(p_->exprs[d.value].number);
    if (auto why = w_.unwritable(word)) fail(e.range, *why);
    return number(word, e.range);
  }

  Value kind_of(char letter) const {
    if (letter == 'F') return Value::Feed;
    if (letter == 'S') return Value::Speed;
    if (letter == 'T' || letter == 'D' || letter == 'H' || letter == 'L') return Value::Count;
    if (letter == dst_.dwell_word) return Value::Seconds;
    return Value::Length;
  }

  const ir::Unit* unit_ = nullptr;
  int last_number_;  // N1 is the start's, in another dialect's translation
};

}  // namespace

std::unique_ptr<Structured> make_gost_structured(std::string dialect, Writer& writer, const MachineConfig& target) {
  return std::make_unique<GostStructured>(std::move(dialect), writer, target);
}

}  // namespace ncc::translate
