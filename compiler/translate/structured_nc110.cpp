// Structured translation into NC-110 (docs/translate.md): the main program, then
// after its M30 each subprogram as a range of blocks between two labels that
// (EPP,first,last) runs; jumps as labels and the branches BNC, BEQ, BGT, ...; a
// repeat loop as (RPT,n)...(ERP) or, where the count is not a constant of 0..99, a
// count in a parameter of its own. A block holds one instruction and a word one
// constant or one E parameter (§2.5, Table 2.9): a computed value is stored in a
// scratch E parameter of the class the word takes, in a block before.
#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "contract/system_vars.h"
#include "stdlib/tables.h"
#include "structured_impl.h"

namespace ncc::translate {
namespace {

// The E parameter classes of Table 2.8: BY E0-E9, IN E10-E19, LI E20-E24, RE E25-E29,
// LR from E30.
enum Class : int { BY, IN, LI, RE, LR };
constexpr uint32_t kFirst[] = {0, 10, 20, 25, 30};
constexpr uint32_t kEnd[] = {10, 20, 25, 30, 0};
constexpr const char* kClassName[] = {"BY", "IN", "LI", "RE", "LR"};
// At the top of the E parameters: scratch values of a block (LR), then the counts of
// repeat loops that do not fit RPT.
constexpr uint32_t kScratch = 16, kCounters = 8;
constexpr int kMaxRpt = 3;  // RPT levels (§2.13.2.1)

Class class_of(uint32_t e) {
  for (int c = RE; c >= BY; --c)
    if (e >= kFirst[c] && e < kEnd[c]) return static_cast<Class>(c);
  return LR;
}

std::string quoted(const std::string& label) { return "\"" + label + "\""; }

// NC-110's name of each system variable a program reads or writes (its table, the
// first name of each), and whether it takes a number after it (TIM0, RMN11).
const std::map<SysVar, std::pair<std::string, bool>>& system_names() {
  static const auto names = [] {
    std::map<SysVar, std::pair<std::string, bool>> out;
    Diagnostics quiet;
    if (auto table = stdlib::load_table("nc110", "system_variables.tsv", 5, quiet))
      for (const stdlib::TableRow& row : table->rows)
        if (auto var = sys_by_name(row.cells[1])) out.try_emplace(*var, row.cells[0], row.cells[2] != "-");
    return out;
  }();
  return names;
}

// 1 to 6 capital letters and digits (nc110 decision 3).
bool valid_label(const std::string& s) {
  return !s.empty() && s.size() <= 6 &&
         std::all_of(s.begin(), s.end(), [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); });
}

class Nc110Structured final : public Structured {
 public:
  Nc110Structured(std::string dialect, Writer& writer, const MachineConfig& target, uint32_t e_count)
      : Structured(std::move(dialect), writer, target), e_count_(e_count) {}

 private:
  // --- layout -----------------------------------------------------------------------

  // Even NC-110's own blocks are written anew: a code of the tables, a three-letter
  // code (UAO) or a call on a block of its own.
  bool verbatim() const override { return false; }
  bool title_line() const override { return false; }

  void body() override {
    scan();
    // A program of another dialect brings its subprograms: ranges after the main
    // program's end. NC-110's own CLS programs are files of the library.
    for (size_t u = 0; u < p_->units.size(); ++u)
      if (u == 0 || !same_) unit(p_->units[u], u == 0);
  }

  // The labels and E parameters the program has, before any is made up.
  void scan() {
    for (const ir::Unit& u : p_->units)
      for (const ir::Block& b : u.blocks)
        if (valid_label(b.label)) taken_.insert(b.label);
    if (same_)
      for (const ir::Expr& e : p_->exprs)
        if (e.op == ir::ExprOp::Var && p_->is_constant(e.a))
          source_e_.insert(static_cast<uint32_t>(p_->exprs[e.a].number));
    if (same_) return;
    for (size_t u = 1; u < p_->units.size(); ++u) {
      const std::string& name = p_->units[u].name;
      std::string label;
      for (char c : name.substr(name.rfind('/') + 1))
        if (std::isalnum(static_cast<unsigned char>(c)))
          label += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      ranges_[name] = {own(label), fresh()};
    }
  }

  // A label of the output: the source's where it is NC-110's and free, else K1 up.
  // ISO's N9001 up are the labels a translation from NC-110 gave its K1 up: K1 again.
  std::string own(const std::string& label) {
    if (p_->dialect == "iso" && label.size() == 5 && label.starts_with("N9") && label != "N9000" &&
        label.find_first_not_of("0123456789", 1) == std::string::npos) {
      const std::string k = fmt::format("K{}", std::stoi(label.substr(1)) - 9000);
      if (!taken_.count(k) && made_.insert(k).second) return k;
    }
    if (valid_label(label) && !made_.count(label) && !(label.size() > 1 && label[0] == 'K' && std::isdigit(label[1]))) {
      made_.insert(label);
      return label;
    }
    return fresh();
  }
  std::string fresh() {
    std::string label;
    do label = fmt::format("K{}", ++next_label_);
    while (taken_.count(label) || made_.count(label));
    made_.insert(label);
    return label;
  }

  void open_unit(const ir::Unit& u, bool main) override {
    unit_ = &u;
    labels_.clear();
    label_at_.clear();
    std::set<std::string> targets;
    for (const ir::Block& b : u.blocks)
      for (const ir::Stmt& s : b.stmts) {
        if (s.kind == ir::StmtKind::Jump && !s.label.empty()) targets.insert(s.label);
        if (s.kind == ir::StmtKind::CallRange) targets.insert({s.label, s.end_label});
      }
    for (size_t i = 0; i < u.blocks.size(); ++i) {
      const std::string& label = u.blocks[i].label;
      if (label.empty() || !targets.count(label) || labels_.count(label)) continue;
      labels_[label] = same_ && valid_label(label) ? label : own(label);
      label_at_[i] = labels_[label];
    }
    if (main) return;
    w_.comment(u.title.empty() ? u.name : u.name + ": " + u.title);
    w_.line(quoted(ranges_.at(u.name).first));
  }

  void close_unit(const ir::Unit& u, bool main, bool) override {
    if (!main) return w_.line(quoted(ranges_.at(u.name).second));
    // What stands after the main program's end is the subprograms' place.
    if (!same_ && p_->units.size() > 1 && !ends_program(u)) line("M30");
  }

  void block_begun() override {
    scratch_used_ = 0;
    for (int c = BY; c <= RE; ++c) class_used_[c] = 0;
  }

  char sync_of(const ir::Block& b) const override { return b.sync; }  // the block waits for the motion, or does not

  void before_block(size_t i) override {
    const ir::Block& b = unit_->blocks[i];
    if (label_at_.count(i)) {
      label_ = quoted(label_at_.at(i));
      forget();
    }
    pending_number_ = number_of(b);
    pending_sync_ = sync_of(b);
    // An ISO jump target's number is its label: the label says it.
    if (p_->dialect == "iso" && label_at_.count(i) && b.number && b.label == fmt::format("N{}", *b.number))
      pending_number_.reset();
    if ((b.skippable) && std::any_of(b.stmts.begin(), b.stmts.end(), [](const ir::Stmt& s) {
          return s.kind == ir::StmtKind::Jump || s.kind == ir::StmtKind::RepeatBegin ||
                 s.kind == ir::StmtKind::RepeatEnd || s.kind == ir::StmtKind::Call || s.cond != ir::kNoExpr;
        }))
      fail(b.range,
           "a jump, a repeat, a call or a condition in a block '/' skips: the translation writes it in several blocks");
  }

  // --- flow -------------------------------------------------------------------------

  void jump(const ir::Stmt& s) override {
    if (s.label.empty()) return fail(s.range, "a jump to a computed block number: NC-110 jumps to labels");
    auto it = labels_.find(s.label);
    if (it == labels_.end()) {  // a block streamed and written already: read the program whole
      needs_whole_ = true;
      return;
    }
    if (s.cond == ir::kNoExpr) return line(fmt::format("(BNC,{})", it->second));
    branch(s.cond, it->second, false);
  }

  // A jump to `label` when `cond` holds (when it does not: `negate`). A branch compares
  // two operands; AND and OR become several branches.
  void branch(ir::ExprId cond, const std::string& label, bool negate) {
    const ir::Expr& c = p_->exprs[cond];
    static const std::map<ir::ExprOp, std::pair<const char*, const char*>> kBranch = {
        {ir::ExprOp::Eq, {"BEQ", "BNE"}}, {ir::ExprOp::Ne, {"BNE", "BEQ"}}, {ir::ExprOp::Lt, {"BLT", "BGE"}},
        {ir::ExprOp::Le, {"BLE", "BGT"}}, {ir::ExprOp::Gt, {"BGT", "BLE"}}, {ir::ExprOp::Ge, {"BGE", "BLT"}}};
    switch (c.op) {
      case ir::ExprOp::Not: return branch(c.a, label, !negate);
      case ir::ExprOp::ZeroIfVacant:
      case ir::ExprOp::Check: return branch(c.a, label, negate);
      case ir::ExprOp::And:
      case ir::ExprOp::Or:
        if ((c.op == ir::ExprOp::And) != negate) {  // both must hold: past the second test if the first fails
          const std::string skip = fresh();
          branch(c.a, skip, !negate);
          branch(c.b, label, negate);
          label_line(skip);
        } else {  // either will do
          branch(c.a, label, negate);
          branch(c.b, label, negate);
        }
        return;
      default: break;
    }
    if (auto it = kBranch.find(c.op); it != kBranch.end()) {
      const std::string a = operand_of(c.a), b = operand_of(c.b);
      return line(fmt::format("({},{},{},{})", negate ? it->second.second : it->second.first, a, b, label));
    }
    line(fmt::format("({},{},0,{})", negate ? "BEQ" : "BNE", operand_of(cond), label));  // true when not 0
  }

  // A branch's operand: a constant or one E parameter (§2.13.2.4).
  std::string operand_of(ir::ExprId id) {
    const ir::Expr& e = p_->exprs[bare(id)];
    if (auto v = constant_of(id)) return exact(*v, false);
    if (e.op == ir::ExprOp::Var && p_->is_constant(e.a)) return var(e);
    return scratch(LR, expr(id, kOr));
  }

  // A label on a block of its own (a block may have one label).
  void label_line(const std::string& label) {
    flush();
    w_.line(quoted(label));
  }

  void repeat_begin(const ir::Stmt& s) override {
    open_loop(s.value, s.range);
    forget();
  }
  void repeat_end(const ir::Stmt&) override {
    close_loop();
    forget();
  }

  // RPT for a constant count of 0..99 within three levels; else a count in a
  // parameter of its own, tested at the end (and first, when it may be 0).
  void open_loop(ir::ExprId count, SourceRange at) {
    Loop loop;
    const auto n = constant_of(count);
    if (n && *n >= 0 && *n <= 99 && *n == std::trunc(*n) && rpt_depth_ < kMaxRpt) {
      line(fmt::format("(RPT,{})", static_cast<int>(*n)));
      ++rpt_depth_;
      loop.rpt = true;
    } else {
      if (counters_ == kCounters) return fail(at, fmt::format("more than {} repeat loops open at once", kCounters));
      loop.counter = e_count_ - kScratch - 1 - counters_++;
      line(fmt::format("E{}={}", loop.counter, expr(count, kOr)));
      if (!n || *n < 1) {
        loop.exit = fresh();
        line(fmt::format("(BLE,E{},0,{})", loop.counter, loop.exit));
      }
      loop.head = fresh();
      label_line(loop.head);
    }
    loops_.push_back(loop);
  }

  void close_loop() {
    if (loops_.empty()) return;
    const Loop loop = loops_.back();
    loops_.pop_back();
    if (loop.rpt) {
      --rpt_depth_;
      return line("(ERP)");
    }
    --counters_;
    line(fmt::format("E{0}=E{0}-1", loop.counter));
    line(fmt::format("(BGT,E{},0,{})", loop.counter, loop.head));
    if (!loop.exit.empty()) label_line(loop.exit);
  }

  void call(const ir::Stmt& s) override {
    forget();
    // G65 gives the called program locals of its own: the target's parameters are global.
    if (p_->dialect == "iso" && !s.shares_locals && uses_locals(s.label))
      return fail(s.range,
                  "G65 of a program that uses #1-#33: ISO gives it locals of its own, NC-110's parameters are global");
    if (!s.args.empty())
      return fail(s.range, "a call with arguments: NC-110's subprograms take none (E parameters are global)");
    std::string text;
    if (same_) {  // the unit "MP0/FLOWA" is CLS's FLOWA/MP0
      const size_t slash = s.label.find('/');
      text = fmt::format("(CLS,{})", slash == std::string::npos
                                         ? s.label
                                         : s.label.substr(slash + 1) + "/" + s.label.substr(0, slash));
    } else {
      if (!ranges_.count(s.label))
        return fail(s.range,
                    s.label.find('/') != std::string::npos ? "a call of a block of a program" : "a call of " + s.label);
      if (!in_main_)
        return fail(s.range,
                    "a call from a subprogram: the translation's subprograms are EPP ranges, which do not nest");
      text = fmt::format("(EPP,{},{})", ranges_.at(s.label).first, ranges_.at(s.label).second);
    }
    if (s.value == ir::kNoExpr || (p_->is_constant(s.value) && p_->exprs[s.value].number == 1)) return line(text);
    open_loop(s.value, s.range);
    line(text);
    close_loop();
  }

  // NC-110's own EPP, in NC-110: its labels are kept.
  void call_range(const ir::Stmt& s) override {
    if (!same_) return Structured::call_range(s);
    forget();
    if (!labels_.count(s.label) || !labels_.count(s.end_label)) {  // a block streamed already
      needs_whole_ = true;
      return;
    }
    line(fmt::format("(EPP,{},{})", labels_.at(s.label), labels_.at(s.end_label)));
  }

  // NC-110 shows texts and values (DIS). A value not right after a text shows as
  // NAME=value (apart from an item before it): a text that says that before such a
  // value is the reader's, and left to it.
  void display(const ir::Stmt& s) override {
    std::string text = "(DIS";
    bool after_text = false;  // the item written last is a text
    for (size_t i = 0; i < s.items.size(); ++i) {
      const ir::Expr& e = p_->exprs[s.items[i].value];
      if (e.op != ir::ExprOp::String) {
        text += "," + expr(s.items[i].value, kOr);
        after_text = false;
        continue;
      }
      const std::string& shown = p_->texts[e.text];
      // ("NAME=" first; " NAME=" apart from an item before it.)
      const bool names_next = !after_text && i + 1 < s.items.size() &&
                              p_->exprs[s.items[i + 1].value].op != ir::ExprOp::String &&
                              shown == (i == 0 ? "" : " ") + expr(s.items[i + 1].value, kOr) + "=";
      if (names_next) continue;
      text += "," + quoted(shown);
      after_text = true;
    }
    line(text + ")");
  }

  void ret(const ir::Stmt& s) override {
    if (in_main_) return fail(s.range, "M99 in the main program");
    if (block_ == &unit_->blocks.back()) return;  // the range ends here
    line(fmt::format("(BNC,{})", ranges_.at(unit_->name).second));
  }

  // NC-110 has no IF: a branch round the statement.
  void conditional(const ir::Stmt& s) override {
    const std::string skip = fresh();
    branch(s.cond, skip, true);
    statement(s);
    label_line(skip);
    forget();
  }

  // --- codes ------------------------------------------------------------------------

  // A work offset (ISO's G54..., NC-110's own UAO): (UAO,n) in a block of its own,
  // before the block's motion. NC-110's other three-letter codes of a function
  // (MIR, URT, SCF, UOT, UIO, ...) into NC-110: as written.
  bool own_frame(Fn fn) const override { return fn == Fn::Mirror || fn == Fn::Rotation || fn == Fn::Scale; }

  bool own_code(const ir::Word& w, const CodeDesc& desc) override {
    if (!same_ && desc.calls == std::vector<FnCall>{{Fn::Dwell}}) return dwell_block(w), true;
    if (same_ && w.address.size() == 3 && desc.calls.size() == 1) {
      offset_selected_ |= desc.calls[0].fn == Fn::OriginSelect;
      return as_written(w);
    }
    if (desc.calls.size() != 1 || desc.scope != Scope::Modal) return false;  // G53's one block: no UAO for it
    const Fn fn = desc.calls[0].fn;
    if (fn != Fn::WorkOffset && fn != Fn::OriginSelect) return false;
    int n = fn == Fn::WorkOffset ? desc.calls[0].arg : -1;
    bool listed = false;
    if (fn == Fn::OriginSelect) {
      operand_words_ = true;
      for (const ir::Word& o : block_->words) {
        if (o.kind != ir::WordKind::Parameter) continue;
        if (o.slot != operand_slot(0))
          listed |= o.slot < 52;
        else if (auto v = constant_of(o.value); v && *v >= 0 && *v <= 99)
          n = static_cast<int>(*v);
      }
    }
    if (n < 0) return fail(w.range, fmt::format("{} of an origin given by a parameter", desc.name)), true;
    if (listed) return fail(w.range, fmt::format("{} on the axes it lists", desc.name)), true;
    if (n != 0 && !same_)
      if (auto why = partial_offset(n, desc.name)) return fail(w.range, *why), true;
    line(fmt::format("(UAO,{})", n));
    offset_selected_ = true;
    return true;
  }

  // Another dialect's dwell (G04 and its time): NC-110 dwells at the end of a G04
  // block for the time in the system variable TMR, in seconds under G94 (at most
  // 60), in revolutions under G95 (§2.10.1). So: TMR=t, then G04.
  void dwell_block(const ir::Word& code) {
    operand_words_ = true;  // its time is written here
    const ir::Word* time = nullptr;
    for (const ir::Word& o : block_->words) {
      if (o.kind != ir::WordKind::Parameter) continue;
      if (o.address.size() != 1 || o.address[0] != src_.dwell_word)
        return fail(o.range, fmt::format("a dwell with the word {}: NC-110 dwells in a block of its own, by TMR",
                                         o.address.str()));
      time = &o;
    }
    const auto value = time ? constant_of(time->value) : std::nullopt;
    if (!value) return fail(code.range, "a dwell whose time is not a constant: NC-110 dwells by TMR, set before");
    std::vector<std::string> lines;
    if (dwell_lines(*value * src_.dwell_seconds_per_unit, lines))
      for (std::string& l : lines) line(std::move(l));
  }

  // A three-letter code and its operands, which are the block's other words (one
  // instruction a block): a value operand by its text, an axis with its value or
  // alone. It may move the origin or the frame: the position is not known after it.
  bool as_written(const ir::Word& code) {
    std::string text = "(" + code.address.str();
    for (const ir::Word& o : block_->words) {
      if (o.kind != ir::WordKind::Parameter) continue;
      const std::string address = o.address.str();
      if (address.find('\'') != std::string::npos) {  // the pair's second value (DLO): after the first, a blank between
        text += " " + address.substr(0, 1) + o.text;
        continue;
      }
      text += "," + (address[0] == '#' ? o.text.substr(o.text.starts_with("=") ? 1 : 0) : address + o.text);
    }
    line(text + ")");
    operand_words_ = true;  // its operands are written
    forget_position();
    return true;
  }

  // --- the start --------------------------------------------------------------------

  // NC-110 starts in origin 0 with every E parameter 0 (nc110 decision 8): the
  // source's work offset, and which E parameter holds what.
  void start_offset() override {
    int n = 0;
    for (const FnCall& c : power_on())
      if (c.fn == Fn::WorkOffset) n = c.arg;
    if (n == 0) {
      const auto it = target_.work_offsets.find(0);
      if (moved_before_offset_ && it != target_.work_offsets.end() &&
          std::any_of(it->second.values.begin(), it->second.values.end(), [](double v) { return v != 0; }))
        fail(p_->units.front().range, "the start without a work offset: the target machine's origin 0 is not zero");
      return;
    }
    if (!start_needs({Fn::WorkOffset, static_cast<uint16_t>(n)})) return;
    if (auto why = partial_offset(n, "the start's work offset")) {
      if (moved_before_offset_) fail(p_->units.front().range, *why);
      return;
    }
    w_.line(fmt::format("(UAO,{})", n));
  }

  // NC-110 powers on in G27, where M, S or T after a feed move is an error (nc110
  // decision 44): a source without path modes NC-110 has runs point to point, each
  // block alone.
  void start_modes(std::vector<FnCall>& modes) const override {
    if (std::none_of(modes.begin(), modes.end(), [&](const FnCall& c) {
          return fn_group(c.fn) == FnGroup::Dynamics && target_code({c}, Scope::Modal);
        }))
      modes.push_back({Fn::DynamicsPointToPoint});
  }

  void start_parameters() override {
    if (legend_.empty()) return;
    std::string text = "E parameters:";
    for (const auto& [e, name] : legend_) text += fmt::format(" E{} {},", e, name);
    text.pop_back();
    w_.comment(text);
  }

  // --- values -----------------------------------------------------------------------

  // Each variable of the source in an LR parameter from E30 up, in the order the
  // program first names them; NC-110's own keep their numbers.
  std::string var(const ir::Expr& e) override {
    if (same_ && (e.op == ir::ExprOp::Mem || e.op == ir::ExprOp::Text || e.op == ir::ExprOp::Sys))
      return own_reference(e);
    const auto n = e_of(e);
    return n ? fmt::format("E{}", *n) : "E0";
  }

  // NC-110's own memories (SA3.IN, SYVAR16.3CH) and system variables (TMR, TIM0),
  // into NC-110: as NC-110 names them.
  std::string own_reference(const ir::Expr& e) {
    if (e.op == ir::ExprOp::Sys) {
      const SysRef ref = SysRef::unpack(e.sys);
      const auto it = system_names().find(ref.var);
      if (it == system_names().end()) return fail(e.range, "a system variable NC-110 has no name for"), "E0";
      return it->second.second ? fmt::format("{}{}", it->second.first, ref.index) : it->second.first;
    }
    const auto index = constant_of(e.a);
    if (!index) return fail(e.range, "a memory at a computed index"), "E0";
    static constexpr const char* kFormats[] = {"BL", "BY", "IN", "LI", "RE", "LR"};
    const std::string format =
        e.op == ir::ExprOp::Text ? fmt::format("{}CH", e.count) : kFormats[static_cast<int>(e.format)];
    return fmt::format("{}{}.{}", p_->spaces[e.space].name, static_cast<uint32_t>(*index), format);
  }

  std::optional<uint32_t> e_of(const ir::Expr& e) {
    if (e.op != ir::ExprOp::Var) {
      fail(e.range, "a store into a memory or a system variable");
      return std::nullopt;
    }
    if (!p_->is_constant(e.a)) {
      fail(e.range, "a computed parameter number: NC-110 names each E parameter");
      return std::nullopt;
    }
    const uint32_t index = static_cast<uint32_t>(p_->exprs[e.a].number);
    if (same_) return index;
    if (p_->dialect == "iso" && index == 0) fail(e.range, "the vacant #0: NC-110's parameters are never vacant");
    const std::string name = fmt::format("{}{}", p_->spaces[e.space].name, index);
    auto it = mapped_.find(name);
    if (it == mapped_.end()) {
      const uint32_t end = e_count_ - kScratch - kCounters;
      // ISO's #500+n is E n (LR), as E n goes to #500+n: a round trip keeps the number.
      const auto n = parameter_number(e, kFirst[LR], end, e_taken_, next_e_);
      if (!n) {
        fail(e.range, fmt::format("more variables than the E parameters E30-E{} hold", end - 1));
        return std::nullopt;
      }
      it = mapped_.emplace(name, *n).first;
      legend_.emplace_back(it->second, name);
    }
    return it->second;
  }

  // A word's value: a constant in its address' format, an E parameter of a class
  // the address takes, else a scratch parameter of such a class.

  std::string value(ir::ExprId id, char letter) override {
    const ir::Expr& e = p_->exprs[bare(id)];
    if (letter == 'E' && !same_) {  // G72-G74: where the results go (NC-110 keeps its own E numbers)
      fail(e.range,
           fmt::format("the word E of {}: NC-110's E says where a measurement stores its results", p_->dialect));
      return "0";
    }
    const auto address = w_.tables().addresses.find(letter);
    if (auto v = constant_of(id)) {
      OutWord word{letter, *v, kind_of(letter)};
      if (auto why = w_.unwritable(word)) fail(e.range, *why);
      return number(word, e.range);
    }
    std::vector<Class> takes;
    if (address != w_.tables().addresses.end())
      for (const std::string& p : address->second.params)
        for (int c = BY; c <= LR; ++c)
          if (p == kClassName[c]) takes.push_back(static_cast<Class>(c));
    if (takes.empty()) {
      fail(e.range, fmt::format("{} given by a parameter: NC-110's {} takes a constant only", letter, letter));
      return "0";
    }
    if (e.op == ir::ExprOp::Var && p_->is_constant(e.a)) {
      const auto n = e_of(e);
      if (!n || std::find(takes.begin(), takes.end(), class_of(*n)) != takes.end())
        return fmt::format("E{}", n.value_or(0));
      return scratch(takes.back(), fmt::format("E{}", *n));
    }
    return scratch(takes.back(), expr(id, kOr));
  }

  static Value kind_of(char letter) {
    switch (letter) {
      case 'F': return Value::Feed;
      case 'S': return Value::Speed;
      case 'T':
      case 'H': return Value::Count;
      case 'G':
      case 'M': return Value::Code;
      default: return Value::Length;
    }
  }

  // `text` stored in a scratch parameter of class c, in a block of its own.
  std::string scratch(Class c, const std::string& text) {
    uint32_t e = 0;
    do {
      if (c == LR) {
        if (scratch_used_ == kScratch) {
          fail(block_->range, fmt::format("more than {} computed values in a block", kScratch));
          return "E0";
        }
        e = e_count_ - 1 - scratch_used_++;
      } else {
        if (kFirst[c] + class_used_[c] == kEnd[c]) {
          fail(block_->range,
               fmt::format("more computed {} values in a block than E{}-E{}", kClassName[c], kFirst[c], kEnd[c] - 1));
          return "E0";
        }
        e = kFirst[c] + class_used_[c]++;
      }
    } while (source_e_.count(e));  // NC-110's own program uses it
    line(stored(fmt::format("E{}", e), text));
    return fmt::format("E{}", e);
  }

  std::string assignment(const ir::Stmt&, const std::string& var, std::string text) override {
    return stored(var, text);
  }
  std::string stored(const std::string& var, const std::string& text) {
    std::string line = var + "=" + text;
    if (line.size() > 120) fail(block_->range, "an expression longer than an NC-110 line of 128 characters");
    return line;
  }

  void zero_all(uint32_t, uint32_t) override {}  // never: var() refuses computed parameter numbers

  // NC-110's expressions (§2.12, nc110 decisions 9 and 10): ( ), + - * /, one sign
  // before an operand, MOD(A,B), functions of degrees; no comparison outside a branch.
  std::string expr(ir::ExprId id, int min) override {
    const ir::Expr& e = p_->exprs[id];
    auto wrap = [&](int level, std::string s) { return level < min ? "(" + s + ")" : s; };
    auto binary = [&](int level, std::string_view op) {
      return wrap(level, expr(e.a, level) + std::string(op) + expr(e.b, level + 1));
    };
    switch (e.op) {
      case ir::ExprOp::Number: return e.number < 0 ? wrap(kSign, exact(e.number, false)) : exact(e.number, false);
      case ir::ExprOp::Var: return var(e);
      case ir::ExprOp::Mem:
      case ir::ExprOp::Text:
      case ir::ExprOp::Sys:
        if (same_) return own_reference(e);
        fail(e.range, "a memory, a system variable or a text in an expression");
        return "0";
      case ir::ExprOp::String:
        if (same_) return quoted(p_->texts[e.text]);
        fail(e.range, "a memory, a system variable or a text in an expression");
        return "0";
      case ir::ExprOp::ZeroIfVacant:
      case ir::ExprOp::Check: return expr(e.a, min);
      case ir::ExprOp::Neg:  // -(-2) reads back as 2: a constant is folded
        if (auto v = constant_of(id)) return *v < 0 ? wrap(kSign, exact(*v, false)) : exact(*v, false);
        return wrap(kSign, "-" + expr(e.a, kPrimary));
      case ir::ExprOp::Add: return binary(kSum, "+");
      case ir::ExprOp::Sub: return binary(kSum, "-");
      case ir::ExprOp::Mul: return binary(kTerm, "*");
      case ir::ExprOp::Div: return binary(kTerm, "/");
      case ir::ExprOp::Mod:
        return fmt::format("MOD({},{})", expr(e.a, kOr), expr(e.b, kOr));  // the dividend's sign, as the IR
      case ir::ExprOp::Call: return builtin(e);
      case ir::ExprOp::Pow: fail(e.range, "a power: NC-110 has no power operator"); return "0";
      case ir::ExprOp::Eq:
      case ir::ExprOp::Ne:
      case ir::ExprOp::Lt:
      case ir::ExprOp::Le:
      case ir::ExprOp::Gt:
      case ir::ExprOp::Ge:
      case ir::ExprOp::And:
      case ir::ExprOp::Or:
      case ir::ExprOp::Not: {
        // A truth as a value (pp G73's counter is armed by one): 1 or 0 by a branch.
        const std::string truth = scratch(LR, "0"), skip = fresh();
        branch(id, skip, true);
        line(truth + "=1");
        label_line(skip);
        return truth;
      }
      default: fail(e.range, "a memory, a system variable or a text in an expression"); return "0";
    }
  }

  // The IR's functions by NC-110's names; ROUND (halves away from zero) as a store
  // into an LI parameter, which rounds so (nc110 decision 8).
  std::string builtin(const ir::Expr& e) override {
    auto one = [&](std::string_view name) { return fmt::format("{}({})", name, expr(e.a, kOr)); };
    switch (e.builtin) {
      case Builtin::Sin: return one("SIN");
      case Builtin::Cos: return one("COS");
      case Builtin::Tan: return one("TAN");
      case Builtin::Asin: return one("ARS");
      case Builtin::Acos: return one("ARC");
      case Builtin::Atan: return one("ART");
      case Builtin::Sqrt: return one("SQR");
      case Builtin::Abs: return one("ABS");
      case Builtin::Trunc: return one("INT");
      case Builtin::Round: return scratch(LI, operand(e.a));
      default:
        fail(e.range, fmt::format("the function {}: NC-110 has none like it", builtin_info(e.builtin).name));
        return "0";
    }
  }

  const uint32_t e_count_;
  const ir::Unit* unit_ = nullptr;
  std::set<std::string> taken_, made_;  // the source's labels; the output's
  int next_label_ = 0;
  std::map<std::string, std::pair<std::string, std::string>> ranges_;  // unit -> its first and last label
  std::map<std::string, std::string> labels_;  // of the unit being written: source label -> output label
  std::map<size_t, std::string> label_at_;     // block index -> its label
  std::map<std::string, uint32_t> mapped_;     // source variable -> E
  std::vector<std::pair<uint32_t, std::string>> legend_;
  uint32_t next_e_ = kFirst[LR];
  std::set<uint32_t> e_taken_;   // the E parameters mapped_ gives
  std::set<uint32_t> source_e_;  // NC-110's own E parameters
  uint32_t scratch_used_ = 0, class_used_[LR] = {};
  struct Loop {
    bool rpt = false;
    uint32_t counter = 0;
    std::string head, exit;
  };
  std::vector<Loop> loops_;
  int rpt_depth_ = 0;
  uint32_t counters_ = 0;
};

}  // namespace

std::unique_ptr<Structured> make_nc110_structured(std::string dialect, Writer& writer, const MachineConfig& target,
                                                  uint32_t e_count) {
  return std::make_unique<Nc110Structured>(std::move(dialect), writer, target, e_count);
}

}  // namespace ncc::translate
