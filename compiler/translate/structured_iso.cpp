// Structured translation into ISO with Macro B: the main program, then after its
// M30 the subprograms as O programs; jumps as IF/GOTO to block numbers; a repeat
// loop as a count in a common variable of its own (docs/translate.md).
#include <algorithm>

#include <fmt/format.h>

#include "structured_impl.h"

namespace ncc::translate {
namespace {

constexpr int kFresh = 9000;  // block numbers the translation adds: 9001 up
// A repeat loop counts down #199 (the first of the program), #198, ... #100.
constexpr uint32_t kFirstCounter = 199, kLastCounter = 100;

class IsoStructured final : public Structured {
 public:
  using Structured::Structured;

 private:
  void body() override {
    name_programs();
    for (size_t u = 0; u < p_->units.size(); ++u) unit(p_->units[u], u == 0);
  }

  // The O number of each unit the program calls (unit_numbers); the main program is
  // O0001 (the writer's).
  void name_programs() {
    std::vector<const ir::Unit*> unnamed;
    programs_ = unit_numbers({1}, &unnamed);
    if (same_)
      for (const ir::Unit* u : unnamed)
        fail(u->range, fmt::format("program {}: O0001 is the translation's main program", u->name));
  }

  void open_unit(const ir::Unit& u, bool main) override {
    number_blocks(u);
    if (main) return;
    w_.append("\n");
    line(fmt::format("O{:04}", programs_.at(u.name)));
    if (!u.title.empty()) w_.comment(u.title);
  }

  void close_unit(const ir::Unit& u, bool main, bool returned) override {
    if (head_) line(fmt::format("N{}", *std::exchange(head_, std::nullopt)));  // a loop with an empty body
    // What stands after the main program's end is the subprograms' place.
    if (main && p_->units.size() > 1 && !ends_program(u)) line("M30");
    if (!main && !returned)
      line(end_number_ ? fmt::format("N{} M99", *std::exchange(end_number_, std::nullopt)) : "M99");
  }
  bool returns_after() const override { return true; }

  // The block numbers of a unit: a jump target keeps its own number when no other
  // block has it, else gets one from 9001 up; other blocks keep theirs.
  void number_blocks(const ir::Unit& unit) {
    labels_.clear();
    numbers_.clear();
    taken_.clear();
    next_ = kFresh;
    std::set<std::string> targets;
    for (const ir::Block& b : unit.blocks)
      for (const ir::Stmt& s : b.stmts)
        if (s.kind == ir::StmtKind::Jump && !s.label.empty()) targets.insert(s.label);
    for (const ir::Unit& u : p_->units)  // M97: a block of this unit
      for (const ir::Block& b : u.blocks)
        for (const ir::Stmt& s : b.stmts)
          if (s.kind == ir::StmtKind::Call && s.label.starts_with(unit.name + "/"))
            targets.insert(s.label.substr(unit.name.size() + 1));
    std::map<uint32_t, int> count;
    for (const ir::Block& b : unit.blocks)
      if (b.number) ++count[*b.number];
    for (const auto& [number, n] : count) taken_.insert(static_cast<int>(number));
    // Blocks streamed and written already kept their numbers: a jump to one of
    // them goes to the first block of the number, as it does in ISO.
    for (const ir::Unit::StreamedLabel& l : unit.streamed_labels) {
      taken_.insert(static_cast<int>(l.number));
      if (targets.count(l.label())) labels_.emplace(l.label(), static_cast<int>(l.number));
    }
    for (const ir::Block& b : unit.blocks) {
      if (b.label.empty() || !targets.count(b.label) || labels_.count(b.label)) continue;
      const bool own = number_of(b) && count[*b.number] == 1 && b.label == fmt::format("N{}", *b.number);
      labels_[b.label] = own ? static_cast<int>(*b.number) : fresh(b.label);
    }
    std::set<std::string> placed;  // a label used twice names its first block (lowering)
    for (size_t i = 0; i < unit.blocks.size(); ++i) {
      const ir::Block& b = unit.blocks[i];
      if (!b.label.empty() && labels_.count(b.label) && placed.insert(b.label).second)
        numbers_[i] = labels_.at(b.label);
      else if (auto n = number_of(b))
        numbers_[i] = *n;  // one ISO's N holds
    }
    blocks_ = &unit.blocks;
  }

  // A number of the translation's own. NC-110's labels N1 up and K1 up (those a
  // translation into NC-110 gives, structured_nc110.cpp) get 1 up and 9001 up where free.
  int fresh(std::string_view label = {}) {
    if (p_->dialect == "nc110" && label.size() > 1 && label.size() <= 5 && (label[0] == 'K' || label[0] == 'N') &&
        label.find_first_not_of("0123456789", 1) == std::string_view::npos) {
      const int n = std::stoi(std::string(label.substr(1))) + (label[0] == 'K' ? kFresh : 0);
      if (n > (label[0] == 'K' ? kFresh : 0) && n <= 9999 && taken_.insert(n).second) return n;
    }
    while (taken_.count(++next_)) {}
    taken_.insert(next_);
    return next_;
  }

  void before_block(size_t i) override {
    const ir::Block& b = (*blocks_)[i];
    if (!b.label.empty() && labels_.count(b.label)) forget();
    pending_number_ = numbers_.count(i) ? std::optional<int>(numbers_.at(i)) : std::nullopt;
    if (head_) {  // a loop's body starts here
      if (pending_number_)
        w_.line(fmt::format("N{}", *head_));
      else
        pending_number_ = head_;
      head_.reset();
    }
  }

  void jump(const ir::Stmt& s) override {
    std::string to;
    if (!s.label.empty())
      to = fmt::format("{}", labels_.at(s.label));
    else if (same_)
      to = value(s.value, 'N');  // GOTO #1: the block numbers are the source's
    else
      return fail(s.range, "a jump to a computed block number");
    if (s.cond == ir::kNoExpr) return line("GOTO " + to);
    line(fmt::format("IF [{}] GOTO {}", expr(s.cond, kOr), to));
  }

  // A jump out of the body leaves the count behind, as leaving a loop closes it; a
  // jump back to the repeat starts it again.
  void repeat_begin(const ir::Stmt& s) override {
    if (counters_ > kFirstCounter - kLastCounter) return fail(s.range, "more than 100 repeat loops");
    Loop loop{kFirstCounter - counters_++, fresh(), 0};
    line(fmt::format("#{}={}", loop.counter, expr(s.value, kOr)));
    if (!p_->is_constant(s.value) || p_->exprs[s.value].number < 1) {
      loop.exit = fresh();
      line(fmt::format("IF [#{} LE 0] GOTO {}", loop.counter, loop.exit));
    }
    head_ = loop.head;
    loops_.push_back(loop);
    forget();
  }

  void repeat_end(const ir::Stmt&) override {
    if (loops_.empty()) return;
    const Loop loop = loops_.back();
    loops_.pop_back();
    line(fmt::format("#{0}=#{0}-1", loop.counter));
    line(fmt::format("IF [#{} GT 0] GOTO {}", loop.counter, loop.head));
    if (loop.exit) line(fmt::format("N{}", loop.exit));
    forget();
  }

  void call(const ir::Stmt& s) override {
    forget();
    if (!programs_.count(s.label))
      return fail(s.range,
                  s.label.find('/') != std::string::npos ? "a call of a block of a program" : "a call of " + s.label);
    if (!s.args.empty()) return fail(s.range, "a call with arguments");
    std::string text = fmt::format("M98 P{}", programs_.at(s.label));
    if (s.value != ir::kNoExpr && !(p_->is_constant(s.value) && p_->exprs[s.value].number == 1))
      text += " L" + value(s.value, 'L');
    line(text);
  }

  void ret(const ir::Stmt&) override { line("M99"); }

  // IF [c] THEN before the statement's one line; one that takes several (an M code
  // apart from its motion) is refused.
  void conditional(const ir::Stmt& s) override {
    then_ = fmt::format("IF [{}] THEN ", expr(s.cond, kOr));
    const size_t before = w_.pending();
    statement(s);
    const std::string written = w_.take();
    if (!then_.empty() || std::count(written.begin() + static_cast<std::ptrdiff_t>(before), written.end(), '\n') > 1)
      fail(s.range, "a statement under a condition that ISO writes in more than one block");
    w_.append(written);
    then_.clear();
  }

  std::string assignment(const ir::Stmt&, const std::string& var, std::string text) override {
    return var + "=" + text;
  }

  void zero_all(uint32_t first, uint32_t count) override {
    w_.line("#1=0");
    w_.line(fmt::format("WHILE [#1 LT {}] DO1", count));
    w_.line(fmt::format("#[{}+#1]=0", first));
    w_.line("#1=#1+1");
    w_.line("END1");
  }

  std::map<std::string, int> programs_;  // unit name -> O number
  std::map<std::string, int> labels_;    // of the unit being written: label -> N
  std::map<size_t, int> numbers_;        // block index -> N
  const std::vector<ir::Block>* blocks_ = nullptr;
  std::set<int> taken_;
  int next_ = kFresh;
  struct Loop {
    uint32_t counter;
    int head;
    int exit;
  };
  std::vector<Loop> loops_;
  uint32_t counters_ = 0;
  std::optional<int> head_;  // the block number of a loop's first block, still to be written
};

}  // namespace

std::unique_ptr<Structured> make_iso_structured(std::string dialect, Writer& writer, const MachineConfig& target) {
  return std::make_unique<IsoStructured>(std::move(dialect), writer, target);
}

}  // namespace ncc::translate
