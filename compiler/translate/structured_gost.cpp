// Structured translation into GOST 20999-83: the program's blocks with their codes,
// canned cycles, arcs and comments, every value a constant in the words of the
// target's format descriptor. GOST 20999 has no parameters, jumps, loops or
// subprograms: a program that uses them is refused, and --flatten writes the blocks
// it runs (docs/translate.md).
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
  // The main program; a second program on the medium is refused (unit()), a
  // subprogram with its calls.
  void body() override {
    for (size_t u = 0; u < p_->units.size(); ++u)
      if (u == 0 || p_->units[u].kind == ir::UnitKind::Program) unit(p_->units[u], u == 0);
  }
  void open_unit(const ir::Unit& u, bool) override { unit_ = &u; }
  void close_unit(const ir::Unit&, bool, bool) override {}
  void before_block(size_t i) override { pending_number_ = number_of(unit_->blocks[i]); }

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
  void repeat_begin(const ir::Stmt& s) override { fail(s.range, std::string("a repeat loop: GOST 20999 has none") + kFlatten); }
  void repeat_end(const ir::Stmt&) override {}
  void call(const ir::Stmt& s) override { fail(s.range, std::string("a subprogram call: GOST 20999 has none") + kFlatten); }
  void ret(const ir::Stmt& s) override { fail(s.range, std::string("a return from a subprogram: GOST 20999 has none") + kFlatten); }
  void conditional(const ir::Stmt& s) override { fail(s.range, std::string("a condition: GOST 20999 has none") + kFlatten); }
  std::string assignment(const std::string&, ir::ExprId, std::string) override { return {}; }
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
    if (e.op == ir::ExprOp::Number) v = e.number;
    else if (e.op == ir::ExprOp::Neg && p_->exprs[e.a].op == ir::ExprOp::Number) v = -p_->exprs[e.a].number;
    if (!v) {
      fail(e.range, std::string("a value computed when the program runs: GOST 20999 has no parameters") + kFlatten);
      return "0";
    }
    // §3.3.5: a format whose T word holds tool and offset digits (T1 is written T100)
    // says the offset in it: D is not written yet.
    if (letter == 'D' && std::stoll(w_.number({'T', 1, Value::Count})) != 1) {
      fail(e.range, "an offset of a T word of tool and offset digits (§3.3.5): not written yet");
      return "0";
    }
    const OutWord word{letter, *v, kind_of(letter)};
    if (auto why = w_.unwritable(word)) fail(e.range, *why);
    return w_.number(word);
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
