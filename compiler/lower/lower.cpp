#include "lower.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <unordered_map>

#include "support/numbers.h"
#include "support/text.h"
#include "vm/opcodes.h"

namespace ncc {

namespace {

using vm::Op;

constexpr double kMaxRepeatCount = 2147483647;

// What lowering a unit keeps from block to block.
struct UnitState {
  std::map<std::string, uint32_t> labels;
  std::vector<std::pair<uint32_t, std::string>> jumps;  // (operand, label)
  std::vector<uint32_t> repeats;                        // Repeat operands whose loop has not ended
  std::vector<uint32_t> loop_start;                     // where each open loop's body starts
  size_t starting_loops = 0;                            // loops whose body starts at the next block
  bool entry_added = false;
  // The repeat loops open at each label (a jump out of loops closes them), and the
  // labels that end a range (a RangeEnd follows their block).
  std::map<std::string, size_t> label_depth;
  std::set<std::string> range_ends;
  std::vector<std::pair<uint32_t, std::string>> ranges;  // (CallRange operands, start label)
  size_t depth = 0;
};

class Lowering {
 public:
  explicit Lowering(const SourceManager& sources) : sources_(sources) {}

  // A block of the first unit lowered while the program is still being read: one
  // without a flow statement, so that nothing after it changes its code (a call to
  // its label adds an entry point in finish()).
  void stream(const ir::Program& program, const ir::Unit& unit, const ir::Block& b) {
    if (!p_)  // the files so far, in their order (finish() adds the others)
      for (uint32_t file : program.files) file_index(file);
    p_ = &program;
    const uint32_t at = pc();
    lower_block(unit, b, first_unit_);
    if (!b.label.empty()) streamed_label_pcs_.push_back(at);  // of Unit::streamed_labels, in order
  }

  // The streamed blocks' labels the rest of their unit names, where the fix-ups look
  // for them. No loop is open in a stream.
  void name_streamed_labels(const ir::Unit& unit) {
    for (size_t i : unit.named_streamed_labels()) {
      const std::string label = unit.streamed_labels[i].label();
      first_unit_.labels.emplace(label, streamed_label_pcs_[i]);
      first_unit_.label_depth.emplace(label, 0);
    }
  }

  void expect(size_t source_bytes) {
    const size_t bytes = std::min(source_bytes * 2, size_t{1} << 30);  // beyond, they grow as they must
    m_.code.reserve(bytes);
    m_.source_map.reserve(bytes);
    m_.lines.reserve(bytes / 16);
  }

  // The rest of the program, once it is read and checked.
  vm::Module finish(const ir::Program& program) {
    p_ = &program;
    m_.dialect = program.dialect;
    m_.semantics = program.semantics;
    m_.spaces = program.spaces;
    for (uint32_t file : program.files) file_index(file);
    for (const ir::Unit& unit : program.units)
      for (const ir::Block& b : unit.blocks)
        for (const ir::Stmt& s : b.stmts)
          if (s.kind == ir::StmtKind::Call) called_.insert(s.label);
    // A streamed block a call names (Macro B M97) is an entry point too; put where
    // lower_block would have put it (entries stand in code order).
    if (!program.units.empty()) {
      const ir::Unit& first = program.units.front();
      for (size_t i = 0; i < first.streamed_labels.size() && !called_.empty(); ++i)
        if (std::string name = first.name + "/" + first.streamed_labels[i].label(); called_.count(name))
          m_.entries.push_back({name, vm::EntryKind::Subprogram, streamed_label_pcs_[i]});
    }
    if (!program.units.empty()) name_streamed_labels(program.units.front());
    for (size_t u = 0; u < program.units.size(); ++u) {
      UnitState fresh;
      lower_unit(program.units[u], u == 0 ? first_unit_ : fresh);
    }
    std::stable_sort(m_.entries.begin(), m_.entries.end(),
                     [](const vm::Entry& a, const vm::Entry& b) { return a.pc < b.pc; });
    resolve_calls();
    return std::move(m_);
  }

 private:
  uint32_t file_index(uint32_t file) {
    auto [it, fresh] = files_.emplace(file, static_cast<uint32_t>(m_.source_map.files.size()));
    if (fresh) m_.source_map.files.push_back(sources_.file(file).path());
    return it->second;
  }

  uint32_t pc() const { return static_cast<uint32_t>(m_.code.size()); }
  void op(Op o) { m_.code.push_back(static_cast<uint8_t>(o)); }
  // A SERVICE instruction; its service's operands follow (contract/services.def).
  void service(Service s) {
    m_.devices |= vm::device_bit(service_info(s).device);
    op(Op::Service);
    u8(static_cast<uint32_t>(s));
  }
  void u8(uint32_t v) { m_.code.push_back(static_cast<uint8_t>(v)); }
  void u16(uint32_t v) {
    u8(v & 0xFF);
    u8((v >> 8) & 0xFF);
  }
  void u32(uint32_t v) {
    for (int i = 0; i < 4; ++i) u8((v >> (8 * i)) & 0xFF);
  }
  void patch(uint32_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) m_.code[at + i] = static_cast<uint8_t>((v >> (8 * i)) & 0xFF);
  }
  // Emits a jump-like instruction and returns where its target goes.
  uint32_t jump(Op o, uint32_t target = 0) {
    op(o);
    uint32_t at = pc();
    u32(target);
    return at;
  }

  uint32_t number(double v) {
    auto [it, fresh] = numbers_.emplace(std::bit_cast<uint64_t>(v), static_cast<uint32_t>(m_.numbers.size()));
    if (fresh) m_.numbers.push_back(v);
    return it->second;
  }
  // A constant as its decimal digits (operands `pm`) when it has at most 9 places and
  // they fit 32 bits: the common case, with no constant table entry. -0 is not one.
  std::optional<std::pair<uint32_t, int32_t>> decimal(double v) {
    if (!std::isfinite(v) || (v == 0 && std::signbit(v))) return std::nullopt;
    for (uint32_t places = 0; places <= vm::kMaxDecimalPlaces; ++places) {
      const auto digits = whole_in<int32_t>(std::nearbyint(v * vm::kPowersOfTen[places]), -INT32_MAX, INT32_MAX);
      if (!digits) break;
      if (vm::decimal(places, *digits) == v) return std::pair{places, *digits};
    }
    return std::nullopt;
  }
  // CONST/WORD with a table entry, or CONSTDEC/WORDDEC with the digits.
  void constant(Op table_op, Op decimal_op, std::optional<uint32_t> slot, double v) {
    auto d = decimal(v);
    op(d ? decimal_op : table_op);
    if (slot) u8(*slot);
    if (!d) return u32(number(v));
    u8(d->first);
    u32(static_cast<uint32_t>(d->second));
  }
  uint32_t string(const std::string& s) {
    auto [it, fresh] = strings_.emplace(s, static_cast<uint32_t>(m_.strings.size()));
    if (fresh) m_.strings.push_back(s);
    return it->second;
  }

  uint32_t source_block(const ir::Block& b) {
    SourceBlock s;
    s.file = file_index(b.range.file);
    s.line = b.range.line;
    s.col = b.range.col;
    s.end_line = b.range.end_line;
    s.end_col = b.range.end_col;
    s.has_number = b.number.has_value();
    s.main_block = b.main_block;
    s.has_errors = b.has_errors;
    s.number = b.number.value_or(0);
    // A code chosen at run time (GE1) is found by its slot, as a parameter word is.
    words_.clear();
    for (const ir::Word& w : b.words)
      if (w.kind == ir::WordKind::Parameter || w.kind == ir::WordKind::Code || w.kind == ir::WordKind::Control)
        words_.push_back({w.slot, static_cast<int16_t>(w.kind == ir::WordKind::Code && w.code >= 0 ? w.code : -1),
                          w.range.line, w.range.col, w.range.end_col});
    m_.source_map.add(s, words_);
    return m_.source_map.size() - 1;
  }

  // The index of a variable when it is written and names one of its space; none when
  // it is computed, or names none (LOADX, STOREX: the VM reports it where it runs).
  std::optional<uint32_t> written_index(const ir::Expr& var) const {
    if (!p_->is_constant(var.a)) return std::nullopt;
    const uint32_t size = p_->spaces[var.space].size;
    return size ? whole_in<uint32_t>(p_->exprs[var.a].number, 0, size - 1) : std::nullopt;
  }

  void expr(ir::ExprId id) {
    const ir::Expr& e = p_->exprs[id];
    switch (e.op) {
      case ir::ExprOp::Number: constant(Op::Const, Op::ConstDec, std::nullopt, e.number); return;
      case ir::ExprOp::Var:
        if (auto index = written_index(e)) {
          op(Op::Load);
          u8(e.space);
          u32(*index);
        } else {
          expr(e.a);
          op(Op::LoadX);
          u8(e.space);
        }
        return;
      case ir::ExprOp::Neg:
      case ir::ExprOp::Not:
        expr(e.a);
        op(e.op == ir::ExprOp::Neg ? Op::Neg : Op::Not);
        return;
      case ir::ExprOp::Call:
        expr(e.a);
        if (e.b != ir::kNoExpr) expr(e.b);
        op(builtin_info(e.builtin).arity == 2 ? Op::Call2 : Op::Call1);
        u8(static_cast<uint32_t>(e.builtin));
        return;
      case ir::ExprOp::Mem:
        expr(e.a);
        op(Op::LoadMem);
        u8(e.space);
        u8(static_cast<uint32_t>(e.format));
        return;
      case ir::ExprOp::Sys:
        op(Op::GetSys);
        u16(e.sys);
        return;
      case ir::ExprOp::TextEq: {
        const ir::Expr& a = p_->exprs[e.a];
        const ir::Expr& b = p_->exprs[e.b];
        expr(a.a);
        if (b.op == ir::ExprOp::String) {
          op(Op::EqText);
          u8(a.space);
          u32(string(p_->texts[b.text]));
        } else {
          expr(b.a);
          op(Op::EqMem);
          u8(a.space);
          u8(b.space);
          u8(a.count);
        }
        return;
      }
      case ir::ExprOp::ZeroIfVacant:
        expr(e.a);
        op(Op::ZeroIfVacant);
        return;
      case ir::ExprOp::Check:
        expr(e.a);
        op(Op::Check);
        u8(e.slot);
        u8(e.rule);
        return;
      case ir::ExprOp::Text:
      case ir::ExprOp::String: return;  // not numbers: only parts of the above
      default: break;
    }
    expr(e.a);
    expr(e.b);
    static const std::map<ir::ExprOp, Op> binary = {
        {ir::ExprOp::Add, Op::Add}, {ir::ExprOp::Sub, Op::Sub}, {ir::ExprOp::Mul, Op::Mul}, {ir::ExprOp::Div, Op::Div},
        {ir::ExprOp::Mod, Op::Mod}, {ir::ExprOp::Pow, Op::Pow}, {ir::ExprOp::Eq, Op::Eq},   {ir::ExprOp::Ne, Op::Ne},
        {ir::ExprOp::Lt, Op::Lt},   {ir::ExprOp::Le, Op::Le},   {ir::ExprOp::Gt, Op::Gt},   {ir::ExprOp::Ge, Op::Ge},
        {ir::ExprOp::And, Op::And}, {ir::ExprOp::Or, Op::Or},   {ir::ExprOp::Xor, Op::Xor}};
    op(binary.at(e.op));
  }

  void machine(const ir::Block& b) {
    // A '/' inside the block: the words after it are dropped when block skip is on.
    uint32_t skip = 0;
    for (const ir::Word& w : b.words) {
      if (w.optional && !skip) skip = jump(Op::JumpSkip);
      if (w.kind == ir::WordKind::Code && w.code >= 0) {
        op(Op::Code);
        u16(static_cast<uint32_t>(w.code));
      } else if (w.kind == ir::WordKind::Code && w.code == ir::kDynamicCode) {
        expr(w.value);
        op(Op::CodeOf);
        u8(w.slot);
      } else if (w.kind == ir::WordKind::Parameter) {
        if (p_->is_constant(w.value)) {
          constant(Op::Word, Op::WordDec, w.slot, p_->exprs[w.value].number);
        } else {
          expr(w.value);
          op(Op::WordPop);
          u8(w.slot);
        }
      }
    }
    if (skip) patch(skip, pc());
    op(Op::Exec);
  }

  // A Service statement: the service the front end named, its values onto the stack
  // first (contract/services.def gives how many and in which order). Lowering expands
  // what makes one statement several instructions (docs/ir.md, Services): the bindings
  // before asset.define, the store after an input.*, a screen.show per field.
  void service_stmt(const ir::Stmt& s) {
    const ServiceInfo& info = service_info(s.service);
    switch (info.device) {
      case Device::Asset:  // docs/asset.md: the operands in order, then the service
        if (s.service == Service::AssetDefine) bind(s);
        for (size_t i = 0; i < info.pop && i < s.items.size(); ++i) expr(s.items[i].value);
        service(s.service);
        if (info.format == "s") u32(string(s.label));  // the file
        return;
      case Device::Input: return input(s);
      case Device::Screen: return user_screen(s);
      case Device::Process: return process(s);
      case Device::Count: return;
    }
  }

  // DER: each variable items[1..] added to the structure being defined.
  void bind(const ir::Stmt& s) {
    for (size_t i = 1; i < s.items.size(); ++i) {
      const ir::Expr& v = p_->exprs[s.items[i].value];
      if (v.op == ir::ExprOp::Var) {  // an E parameter: the front end writes its index
        service(Service::AssetBind);
        u8(v.space);
        u32(written_index(v).value_or(0));
        continue;
      }
      expr(v.a);
      service(v.op == ir::ExprOp::Text ? Service::AssetBindText : Service::AssetBindMem);
      u8(v.space);
      u8(v.op == ir::ExprOp::Text ? v.count : static_cast<uint32_t>(v.format));
    }
  }

  // An instruction `o` (or a service) with operands v n that takes a text in memory:
  // its byte index first.
  void memory_text(const ir::Expr& text, Op o) {
    expr(text.a);
    op(o);
    u8(text.space);
    u8(text.count);
  }
  void memory_text(const ir::Expr& text, Service s) {
    expr(text.a);
    service(s);
    u8(text.space);
    u8(text.count);
  }

  // Service `s`, whose last operand is `item`: a text in quotes (its string operand), a
  // text in memory (its byte index, then v n) or a value (the front end named `s` by it).
  void service_with(Service s, const ir::DisplayItem& item) {
    const ir::Expr& e = p_->exprs[item.value];
    if (e.op == ir::ExprOp::String) {
      service(s);
      u32(string(p_->texts[e.text]));
    } else if (e.op == ir::ExprOp::Text) {
      memory_text(e, s);
    } else {
      expr(item.value);
      service(s);
    }
  }

  // INP: the variable's value is offered, the answer stored back (a memory's index
  // goes first, under the value, for StoreMem); a text goes straight to memory.
  void input(const ir::Stmt& s) {
    const ir::Expr& target = p_->exprs[s.target];
    const bool field = s.service == Service::InputField || s.service == Service::InputFieldText;  // else `label`
    const bool text = target.op == ir::ExprOp::Text;
    if (target.op == ir::ExprOp::Mem) expr(target.a);
    if (field) expr(s.items[0].value);
    expr(text ? target.a : s.target);
    service(s.service);
    if (text) {
      u8(target.space);
      u8(target.count);
    }
    if (!field) u32(string(s.label));
    if (target.op == ir::ExprOp::Mem) {
      op(Op::StoreMem);
      u8(target.space);
      u8(static_cast<uint32_t>(target.format));
    } else if (!text) {
      op(Op::Store);
      u8(target.space);
      u32(written_index(target).value_or(0));  // E<n>: the front end writes it
    }
    if (s.items.size() == 2) {  // the field that shows the answer
      expr(s.items[1].value);
      if (text) {
        memory_text(target, Service::ScreenShowMem);
      } else {
        expr(s.target);
        service(Service::ScreenShowValue);
      }
    }
  }

  // NC-110 SCR, DEF, OUT (§5.6): the operands in order, then the service.
  void user_screen(const ir::Stmt& s) {
    switch (s.service) {
      case Service::ScreenDefineText:
      case Service::ScreenDefineMem:
      case Service::ScreenDefineValue: {
        for (size_t i = 0; i < 3; ++i) expr(s.items[i].value);  // field, row, column
        if (s.items.size() > 4)
          expr(s.items[4].value);
        else
          constant(Op::Const, Op::ConstDec, std::nullopt, 0);  // no format
        // The attribute: -1 none, 256 inverse (R), else the colour (An, 0..255: the front end).
        const double attribute = s.label.empty() ? -1
                                 : s.label == "R"
                                     ? 256
                                     : parse_number<double>(std::string_view(s.label).substr(1)).value_or(-1);
        constant(Op::Const, Op::ConstDec, std::nullopt, attribute);
        service_with(s.service, s.items[3]);
        break;
      }
      case Service::ScreenShow:  // OUT n, m...: each field in turn
        for (const ir::DisplayItem& field : s.items) {
          expr(field.value);
          service(Service::ScreenShow);
        }
        break;
      case Service::ScreenShowText:
      case Service::ScreenShowMem:
      case Service::ScreenShowValue:  // OUT n, value
        expr(s.items[0].value);
        service_with(s.service, s.items[1]);
        break;
      default: service(s.service);  // SCR ON, SCR OFF, OUT alone
    }
  }

  // NC-110 EXE, REL, WAI, SND (chapter 4): the process operand, then the service.
  void process(const ir::Stmt& s) {
    switch (s.service) {
      case Service::ProcessStart:
        expr(s.value);
        calls_.push_back({pc() + 2, s.label, true});  // the entry after the service's number
        service(Service::ProcessStart);
        u16(0);
        break;
      case Service::ProcessWaitUntil: {  // a memory compared with a value (the front end)
        const ir::Expr& compare = p_->exprs[s.value];
        const ir::Expr& memory = p_->exprs[compare.a];
        expr(memory.a);
        expr(compare.b);
        service(Service::ProcessWaitUntil);
        u8(memory.space);
        u8(static_cast<uint32_t>(memory.format));
        u8(compare.op == ir::ExprOp::Eq ? 1 : compare.op == ir::ExprOp::Lt ? 2 : compare.op == ir::ExprOp::Gt ? 3 : 4);
        u32(string(s.label));
        break;
      }
      default:  // REL; WAI n and SND n: the process first
        if (s.value != ir::kNoExpr) expr(s.value);
        service(s.service);
    }
  }

  void assign(const ir::Stmt& s) {
    const ir::Expr& target = p_->exprs[s.target];
    switch (target.op) {
      case ir::ExprOp::Var:
        if (auto index = written_index(target)) {
          expr(s.value);
          op(Op::Store);
          u8(target.space);
          u32(*index);
        } else {
          expr(target.a);
          expr(s.value);
          op(Op::StoreX);
          u8(target.space);
        }
        return;
      case ir::ExprOp::Mem:
        expr(target.a);
        expr(s.value);
        op(Op::StoreMem);
        u8(target.space);
        u8(static_cast<uint32_t>(target.format));
        return;
      case ir::ExprOp::Sys:
        expr(s.value);
        op(Op::SetSys);
        u16(target.sys);
        return;
      case ir::ExprOp::Text: {
        const ir::Expr& value = p_->exprs[s.value];
        expr(target.a);
        if (value.op == ir::ExprOp::String) {
          op(Op::StoreText);
          u8(target.space);
          u32(string(p_->texts[value.text]));
        } else {
          expr(value.a);
          op(Op::CopyText);
          u8(target.space);
          u8(value.space);
          u8(target.count);
        }
        return;
      }
      default: return;  // the front end makes no other targets
    }
  }

  void display(const ir::Stmt& s) {
    for (const ir::DisplayItem& item : s.items) {
      const ir::Expr& e = p_->exprs[item.value];
      if (e.op == ir::ExprOp::String) {
        op(Op::Show);
        u32(string(p_->texts[e.text]));
      } else if (e.op == ir::ExprOp::Text) {
        memory_text(e, Op::ShowText);
      } else {
        expr(item.value);
        op(Op::ShowValue);
        u8(static_cast<uint32_t>(item.type));
      }
    }
    op(Op::Message);
  }

  // Each block starts with a Step (counted by --max-steps): jumps back land on block
  // starts, so every loop passes one (the verifier insists).
  // Only programs run in the order of the medium; subprograms and macros run when called.
  static vm::EntryKind entry_kind(const ir::Unit& unit) {
    return unit.kind == ir::UnitKind::Program   ? vm::EntryKind::Program
           : unit.kind == ir::UnitKind::Process ? vm::EntryKind::Process
                                                : vm::EntryKind::Subprogram;
  }

  void lower_unit(const ir::Unit& unit, UnitState& st) {
    for (const ir::Block& b : unit.blocks) {
      if (!b.label.empty()) st.label_depth.emplace(b.label, st.depth);
      for (const ir::Stmt& s : b.stmts) {
        if (s.kind == ir::StmtKind::RepeatBegin) ++st.depth;
        if (s.kind == ir::StmtKind::RepeatEnd && st.depth > 0) --st.depth;
        if (s.kind == ir::StmtKind::CallRange) st.range_ends.insert(s.end_label);
      }
    }
    st.depth = 0;
    for (const ir::Block& b : unit.blocks) {
      if (!b.label.empty()) st.labels.emplace(b.label, pc());  // a label used twice (Macro B N): the first
      lower_block(unit, b, st);
    }
    if (!st.entry_added) {
      // An empty program still gets its entry point, so it can be run (and end).
      SourceBlock s;
      s.file = file_index(unit.range.file);
      s.line = unit.range.line;
      s.col = unit.range.col;
      m_.source_map.add(s, {});
      m_.lines.push_back({pc(), m_.source_map.size() - 1});
      m_.entries.push_back({unit.name, entry_kind(unit), pc(), unit.processes});
      op(Op::Step);
    }
    uint32_t end = pc();
    for (uint32_t at : st.repeats) patch(at, end);  // repeats without their end (the checks report them)
    // A subprogram returns at its end (NC-110 §2.13.2.2); a program ends there.
    op(unit.kind == ir::UnitKind::Program || unit.kind == ir::UnitKind::Process ? Op::End : Op::Return);
    // The checks report labels that do not exist; should one slip through, the jump
    // ends the unit rather than going anywhere else.
    for (const auto& [at, label] : st.jumps) {
      auto it = st.labels.find(label);
      patch(at, it != st.labels.end() ? it->second : end);
    }
    // A range whose labels do not exist (the checks report it) runs nothing.
    uint32_t nothing = pc();
    if (!st.ranges.empty()) {
      op(Op::RangeEnd);
      op(Op::End);
    }
    for (const auto& [at, label] : st.ranges) {
      auto it = st.labels.find(label);
      patch(at, it != st.labels.end() ? it->second : nothing);
    }
    for (const auto& [at, label] : range_ends_at_) {
      auto it = labels_end_.find(label);
      patch(at, it != labels_end_.end() ? it->second : nothing);
    }
    range_ends_at_.clear();
    labels_end_.clear();
  }

  void lower_block(const ir::Unit& unit, const ir::Block& b, UnitState& st) {
    uint32_t source = source_block(b);
    m_.lines.push_back({pc(), source});
    for (; st.starting_loops > 0; --st.starting_loops) st.loop_start.push_back(pc());
    if (!st.entry_added) {
      m_.entries.push_back({unit.name, entry_kind(unit), pc(), unit.processes});
      st.entry_added = true;
    }
    if (b.main_block && b.number) m_.entries.push_back({fmt::format(":{}", *b.number), vm::EntryKind::MainBlock, pc()});
    // A block a call names (Macro B M97) is an entry point of its own.
    if (!b.label.empty() && called_.count(unit.name + "/" + b.label))
      m_.entries.push_back({unit.name + "/" + b.label, vm::EntryKind::Subprogram, pc()});
    op(Op::Step);
    uint32_t skip = b.skippable ? jump(Op::JumpSkip) : 0;
    if (b.waits_motion) op(Op::Sync);
    for (const ir::Stmt& s : b.stmts) {
      // A block the compiler rejected does not jump or call: where to is in doubt (a
      // dry run goes on past it, its other errors already reported).
      if (b.has_errors &&
          (s.kind == ir::StmtKind::Jump || s.kind == ir::StmtKind::Call || s.kind == ir::StmtKind::CallRange ||
           (s.kind == ir::StmtKind::Service && s.service == Service::ProcessStart)))
        continue;
      // A statement with a condition (Macro B `IF [...] THEN`) runs only when it holds.
      uint32_t unless = 0;
      if (s.cond != ir::kNoExpr && s.kind != ir::StmtKind::Jump) {
        expr(s.cond);
        unless = jump(Op::JumpIfNot);
      }
      switch (s.kind) {
        case ir::StmtKind::Comment: {
          uint32_t skip_comment = s.optional ? jump(Op::JumpSkip) : 0;
          op(Op::Comment);
          u32(string(s.label));
          if (skip_comment) patch(skip_comment, pc());
          break;
        }
        case ir::StmtKind::Machine: machine(b); break;
        case ir::StmtKind::Assign: assign(s); break;
        case ir::StmtKind::Display: display(s); break;
        case ir::StmtKind::Service: service_stmt(s); break;
        case ir::StmtKind::Jump: {
          if (s.label.empty()) {
            computed_jump(unit, s, st.jumps);
            break;
          }
          // A jump out of repeat loops closes them (the checks reject jumps into
          // one): it lands at its target's loop depth. So does a jump where a range
          // may run the code, which may leave the range.
          auto it = st.label_depth.find(s.label);
          const size_t landing = it != st.label_depth.end() ? it->second : st.depth;
          if (landing >= st.depth && st.range_ends.empty()) {
            if (s.cond != ir::kNoExpr) expr(s.cond);
            st.jumps.push_back({jump(s.cond != ir::kNoExpr ? Op::JumpIf : Op::Jump), s.label});
            break;
          }
          uint32_t not_taken = 0;
          if (s.cond != ir::kNoExpr) {
            expr(s.cond);
            not_taken = jump(Op::JumpIfNot);
          }
          op(Op::Unloop);
          u8(static_cast<uint32_t>(landing));
          st.jumps.push_back({jump(Op::Jump), s.label});
          if (not_taken) patch(not_taken, pc());
          break;
        }
        case ir::StmtKind::RepeatBegin:
          // The loop body starts at the next block (RepeatBegin ends its block).
          expr(s.value);
          st.repeats.push_back(jump(Op::Repeat));
          u32(number(s.limit ? s.limit : kMaxRepeatCount));
          ++st.starting_loops;
          ++st.depth;
          break;
        case ir::StmtKind::RepeatEnd:
          if (st.loop_start.empty()) break;  // without its repeat: the checks report it
          jump(Op::EndRepeat, st.loop_start.back());
          st.loop_start.pop_back();
          patch(st.repeats.back(), pc());
          st.repeats.pop_back();
          --st.depth;
          break;
        case ir::StmtKind::CallRange:
          st.ranges.push_back({pc() + 1, s.label});
          range_ends_at_.push_back({pc() + 5, s.end_label});
          op(Op::CallRange);
          u32(0);
          u32(0);
          u8(static_cast<uint32_t>(st.label_depth.count(s.label) ? st.label_depth.at(s.label) : 0));
          break;
        case ir::StmtKind::Call:
          for (const ir::CallArg& a : s.args) {
            expr(a.value);
            op(Op::Arg);
            u8(a.space);
            u32(a.index);
          }
          if (s.value != ir::kNoExpr) {
            expr(s.value);
          } else {
            constant(Op::Const, Op::ConstDec, std::nullopt, 1);
          }
          calls_.push_back({pc() + 1, s.label, false});
          op(s.shares_locals ? Op::CallShared : Op::CallEntry);
          u16(0);
          break;
        case ir::StmtKind::Return: op(Op::Return); break;
      }
      if (unless) patch(unless, pc());
    }
    if (skip) patch(skip, pc());
    if (!b.label.empty() && st.range_ends.count(b.label)) {
      labels_end_[b.label] = pc();
      op(Op::RangeEnd);
    }
  }

  // A jump to the block whose number an expression gives (Macro B `GOTO #1`): each
  // numbered block of the unit in turn, and an error if none has the number.
  void computed_jump(const ir::Unit& unit, const ir::Stmt& s, std::vector<std::pair<uint32_t, std::string>>& jumps) {
    uint32_t not_taken = 0;
    if (s.cond != ir::kNoExpr) {
      expr(s.cond);
      not_taken = jump(Op::JumpIfNot);
    }
    std::set<uint32_t> seen;
    auto target = [&](const std::optional<uint32_t>& number, const std::string& label) {
      if (!number || label.empty() || !seen.insert(*number).second) return;
      expr(s.value);
      constant(Op::Const, Op::ConstDec, std::nullopt, *number);
      op(Op::Eq);
      jumps.push_back({jump(Op::JumpIf), label});
    };
    for (const ir::Unit::StreamedLabel& l : unit.streamed_labels) target(l.number, l.label());
    for (const ir::Block& b : unit.blocks) target(b.number, b.label);
    expr(s.value);
    op(Op::NoBlock);
    if (not_taken) patch(not_taken, pc());
  }

  // Calls name entry points of any unit, so they are resolved last. A call the checks
  // reported as unresolved goes to an entry that returns at once.
  void resolve_calls() {
    size_t missing[2] = {SIZE_MAX, SIZE_MAX};  // a subprogram's, a process's
    for (const auto& [at, name, process] : calls_) {
      size_t i = 0;
      while (i < m_.entries.size() &&
             (m_.entries[i].name != name || (m_.entries[i].kind == vm::EntryKind::Process) != process))
        ++i;
      if (i == m_.entries.size()) {
        if (missing[process] == SIZE_MAX) {
          missing[process] = m_.entries.size();
          m_.entries.push_back({"?", process ? vm::EntryKind::Process : vm::EntryKind::Subprogram, pc()});
          op(Op::Step);
          op(process ? Op::End : Op::Return);
        }
        i = missing[process];
      }
      m_.code[at] = static_cast<uint8_t>(i & 0xFF);
      m_.code[at + 1] = static_cast<uint8_t>((i >> 8) & 0xFF);
    }
  }

  const ir::Program* p_ = nullptr;
  const SourceManager& sources_;
  vm::Module m_;
  std::map<uint32_t, uint32_t> files_;
  std::unordered_map<uint64_t, uint32_t> numbers_;  // lookups only: the constants keep their first-use order
  std::map<std::string, uint32_t> strings_;
  struct CallTarget {
    uint32_t at;       // the operand
    std::string name;  // of the entry
    bool process;      // a Process entry (EXE), else a subprogram's
  };
  std::vector<CallTarget> calls_;
  std::set<std::string> called_;                                 // every entry name a call names
  std::vector<std::pair<uint32_t, std::string>> range_ends_at_;  // (CallRange end operand, end label)
  std::map<std::string, uint32_t> labels_end_;                   // label -> its RangeEnd
  UnitState first_unit_;                      // of the first unit, whose leading blocks may come streamed
  std::vector<WordPosition> words_;           // of the block being lowered
  std::vector<uint32_t> streamed_label_pcs_;  // where each of Unit::streamed_labels starts
};

}  // namespace

struct StreamLowering::Impl : Lowering {
  using Lowering::Lowering;
};

StreamLowering::StreamLowering(const SourceManager& sources) : impl_(std::make_unique<Impl>(sources)) {}
StreamLowering::~StreamLowering() = default;

void StreamLowering::expect(size_t source_bytes) { impl_->expect(source_bytes); }

void StreamLowering::block(const ir::Program& program, const ir::Unit& unit, const ir::Block& b) {
  impl_->stream(program, unit, b);
}

vm::Module StreamLowering::finish(const ir::Program& program, const stdlib::Profile& profile) {
  vm::Module m = impl_->finish(program);
  m.profile_name = profile.text().empty() ? "" : profile.name();
  m.profile_text = profile.text();
  return m;
}

vm::Module lower(const ir::Program& program, const SourceManager& sources, const stdlib::Profile& profile) {
  return StreamLowering(sources).finish(program, profile);
}

}  // namespace ncc
