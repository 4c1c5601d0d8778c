#include "structured.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>

#include <fmt/format.h>

#include "runtime/cycle_steps.h"
#include "stdlib/profile.h"
#include "structured_impl.h"
#include "support/numbers.h"
#include "support/text.h"

namespace ncc::translate {

constexpr std::string_view kAngularAxes = "ABC";  // rotary axes: degrees, in every unit
namespace {

// The mapping of parameters (docs/translate.md, "Structured translation"): a
// dialect's numbered parameters (NC-110 E, pp R) become the target's variables from
// #500 on, which keep their values for the whole run as E and R do (Macro B's
// common variables, LinuxCNC's globals); ISO's own variables stay where they are.
constexpr uint32_t kMappedBase = 500;
constexpr uint32_t kMappedEnd = 1000;
constexpr uint32_t kExtraBase = 100, kExtraEnd = 150;

// How the machine runs the path, not where it goes: a target without the code is
// warned of, as flattening does.
bool path_manner(Fn fn) {
  switch (fn) {
    case Fn::DynamicsCornerSlowdown:
    case Fn::DynamicsContinuous:
    case Fn::DynamicsPointToPoint:
    case Fn::DynamicsSmooth:
    case Fn::PathAccelerate:
    case Fn::PathDecelerate:
    case Fn::OverrideEnable:
    case Fn::OverrideDisable: return true;
    default: return false;
  }
}

}  // namespace

namespace {

// A code table's key as the code is written: G01, G54.1 (code_key).
std::string code_digits(int key) {
  return key >= kDecimalCode ? fmt::format("{:02}.{}", (key - kDecimalCode) / 10, (key - kDecimalCode) % 10)
                             : fmt::format("{:02}", key);
}

}  // namespace

std::string Structured::Code::text() const { return letter + code_digits(number); }

// A target code for a source code: when it acts, and when the source's acts.
struct Structured::Mapped {
  Code code;
  Timing wants, has;
  std::vector<std::string> sets;  // the M conflict sets (stdlib tables)
  std::string later;              // written after the block's other codes instead (G43 H after M06)
};

Structured::Structured(std::string dialect, Writer& writer, const MachineConfig& target_machine)
    : w_(writer), target_(target_machine), dst_(writer.conventions()), same_(dialect == writer.dialect()),
      target_inch_(exact_code({{Fn::UnitsInch}}, Scope::Modal).has_value()),
      target_polar_(exact_code({{Fn::PolarOn}}, Scope::Modal).has_value()) {}

void Structured::attach(const ir::Program& program) {
  p_ = &program;
  src_ = program.semantics.conventions;
  const std::array<bool, 3> was{lowers_inch_, lowers_polar_, lowers_frame_};
  // A program that changes to inches or to polar coordinates, into a target without
  // them: its lengths are written in mm, its points in X Y Z, and after a label or a
  // call the mode is not known.
  if (!target_inch_ || !target_polar_)
    for (const ir::Unit& u : program.units)
      for (const ir::Block& b : u.blocks)
        for (const ir::Word& w : b.words)
          if (w.kind == ir::WordKind::Code && w.code >= 0) {
            const auto& calls = program.semantics.codes[static_cast<size_t>(w.code)].calls;
            auto has = [&](Fn fn) { return std::find(calls.begin(), calls.end(), FnCall{fn}) != calls.end(); };
            lowers_inch_ |= !target_inch_ && has(Fn::UnitsInch);
            lowers_polar_ |= !target_polar_ && has(Fn::PolarOn);
          }
  // A rotation, scale or mirror the target has not (or whose mirror toggles otherwise):
  // every frame written into the points (a block with a frame code is not streamed).
  for (const ir::Unit& u : program.units)
    for (const ir::Block& b : u.blocks) lowers_frame_ |= frame_codes(program, b) == 2;
  // The blocks streamed before were written not knowing it: the program is read and
  // translated again whole.
  if (streamed_ && was != std::array<bool, 3>{lowers_inch_, lowers_polar_, lowers_frame_}) needs_whole_ = true;
}

// 0: the block has no frame code; 1: only codes the target has as the source's;
// 2: one it has not.
int Structured::frame_codes(const ir::Program& program, const ir::Block& b) const {
  int found = 0;
  for (const ir::Word& w : b.words)
    if (w.kind == ir::WordKind::Code && w.code >= 0) {
      const CodeDesc& d = program.semantics.codes[static_cast<size_t>(w.code)];
      for (const FnCall& c : d.calls)
        if (is_frame(c.fn))
          found = std::max(found, same_ || own_frame(c.fn) ||
                                          (exact_code({c}, d.scope) &&
                                           (c.fn != Fn::Mirror ||
                                            program.semantics.conventions.mirror_toggles == dst_.mirror_toggles))
                                      ? 1
                                      : 2);
    }
  return found;
}

// The power-on codes' functions: the program's, or those given before it was read.
std::vector<FnCall> Structured::power_on() const {
  if (power_on_) return *power_on_;
  std::vector<FnCall> calls;
  for (uint16_t i : p_->semantics.power_on)
    calls.insert(calls.end(), p_->semantics.codes[i].calls.begin(), p_->semantics.codes[i].calls.end());
  return calls;
}

// Where a space's variables go: the dialect's parameters from #500 (ISO's own
// where they are); a space of its statements' own (pp G73's repeat count) from #100.
// Decided when a program first names the space: a front end may add one late.
std::optional<uint32_t> Structured::space_base(uint16_t index) {
  if (auto it = space_base_.find(index); it != space_base_.end()) return it->second;
  int first = -1;
  for (size_t i = 0; i < p_->spaces.size() && first < 0; ++i)
    if (!p_->spaces[i].memory && p_->spaces[i].size > 0) first = static_cast<int>(i);
  const VarSpace& space = p_->spaces[index];
  if (static_cast<int>(index) == first) {
    mapped_space_ = first;
    return space_base_[index] = p_->dialect == "iso" ? 0 : kMappedBase;
  }
  if (space.memory || extra_ + space.size > kExtraEnd) return std::nullopt;
  space_base_[index] = extra_;
  extra_ += space.size;
  return space_base_[index];
}

std::optional<int> Structured::number_of(const ir::Block& b) {
  if (!b.number || w_.unwritable({'N', static_cast<double>(*b.number), Value::Count})) return std::nullopt;
  return static_cast<int>(*b.number);
}

void Structured::stream(const ir::Program& program, const ir::Block& b, const ir::Block* next) {
  attach(program);
  if (!streamed_) {
    streamed_ = true;
    begin_main();
  }
  block_begun();
  pending_number_ = number_of(b);
  pending_sync_ = sync_of(b);
  next_ = next;
  block(b);
  next_ = nullptr;
}

// The functions of the main program's leading blocks, up to the first that moves,
// computes, jumps or calls, or may be skipped: the start need not set their groups.
void Structured::lead(const ir::Block& b) {
  in_lead_ = false;
  if (!lead_open_) return;
  const bool plain = !b.skippable && std::all_of(b.stmts.begin(), b.stmts.end(), [](const ir::Stmt& s) {
    return s.cond == ir::kNoExpr && (s.kind == ir::StmtKind::Machine || s.kind == ir::StmtKind::Comment);
  });
  const bool moves = std::any_of(b.words.begin(), b.words.end(), [&](const ir::Word& w) {
    return (w.kind == ir::WordKind::Code && w.code < 0) ||
           (w.kind == ir::WordKind::Parameter && w.address.size() == 1 &&
            src_.axes.find(w.address[0]) != std::string::npos);
  });
  lead_before_ = lead_.size();
  if (!plain) {
    lead_open_ = false;
    return;
  }
  in_lead_ = true;
  for (const ir::Word& w : b.words) lead_feed_ |= w.kind == ir::WordKind::Parameter && w.address == "F";
  for (const ir::Word& w : b.words)
    if (w.kind == ir::WordKind::Code && w.code >= 0) {
      const CodeDesc& desc = p_->semantics.codes[static_cast<size_t>(w.code)];
      if (!moves || desc.timing != Timing::After)  // a code acting after the first move is too late
        lead_.insert(lead_.end(), desc.calls.begin(), desc.calls.end());
    }
  lead_open_ = !moves;
}

// Whether the target machine is in c's state when the program starts: its power-on
// has c, or c is where every machine starts (the spindle stopped, the coolants off,
// the overrides on, no spindle range forced: the range follows S; its clamps as the
// machine has them, which a target without a clamp state at power-on does not claim
// otherwise).
bool Structured::at_power_on(const FnCall& c) const {
  if (!target_power_on_) return false;
  switch (c.fn) {
    case Fn::SpindleStop:
    case Fn::CoolantOff:
    case Fn::CoolantOff34:
    case Fn::OverrideEnable:
    case Fn::SpindleRangeCancel:
    case Fn::SpindleRangeAuto: return true;
    case Fn::ClampOff:
    case Fn::ClampRotaryOff:
      return std::none_of(target_power_on_->begin(), target_power_on_->end(),
                          [&](const FnCall& o) { return fn_group(o.fn) == fn_group(c.fn); });
    default: break;
  }
  if (std::find(target_power_on_->begin(), target_power_on_->end(), c) != target_power_on_->end()) return true;
  // A work offset of zero where the target starts in another of zero, or in none.
  if (c.fn != Fn::WorkOffset) return false;
  auto zero = [&](int n) {
    const auto it = target_.work_offsets.find(n);
    return it == target_.work_offsets.end() ||
           std::all_of(it->second.values.begin(), it->second.values.end(), [](double v) { return v == 0; });
  };
  int start = 0;
  for (const FnCall& o : *target_power_on_)
    if (o.fn == Fn::WorkOffset) start = o.arg;
  return zero(c.arg) && zero(start);
}

// Whether the start writes c: the target does not start so, and the program's
// leading blocks do not set it before it matters.
bool Structured::start_needs(const FnCall& c) const {
  return !at_power_on(c) && std::none_of(lead_.begin(), lead_.end(), [&](const FnCall& o) { return sets_as(o, c); });
}

// Whether o sets what c sets: the same function, or one of its group.
bool Structured::sets_as(const FnCall& o, const FnCall& c) {
  return o == c || (fn_group(c.fn) != FnGroup::None && fn_group(o.fn) == fn_group(c.fn));
}

// ... and the program's leading blocks before this one have not changed it.
bool Structured::still_at_power_on(const FnCall& c) const {
  if (!in_lead_ || !in_main_) return false;
  return at_power_on(c) && std::none_of(lead_.begin(), lead_.begin() + static_cast<long>(lead_before_),
                                        [&](const FnCall& o) { return sets_as(o, c); });
}

// The main program's state at power-on, as far as the text says.
void Structured::begin_main() {
  in_main_ = false;  // nothing is forgotten before the program starts
  forget();
  in_main_ = true;
  frame_ = Frame{};  // no rotation, scale or mirror at power-on
  moved_ = false;    // the tool is where the machine starts
  coolant_on_ = length_on_ = comp_on_ = false;
  length_entry_ = 0;
  spindle_turns_ = spindle_direction_ = 0;
  rpm_ = true;                        // a cutting speed needs its code (G96)
  tool_selected_ = tool_loaded_ = 0;  // no tool in the spindle
  corrector_ = 0;
  timer_ = 0;  // NC-110's TMR at power-on
  state(power_on());
  source_origin_ = 0;  // NC-110 powers on in origin 0, unshifted
  for (const FnCall& c : power_on())
    if (c.fn == Fn::WorkOffset) source_origin_ = c.arg;
  shift_ = {};
  shift_known_ = true;
  // Before its first move the tool is where the machine starts: in the program's
  // coordinates (mm at power-on), that less the power-on origin's offset.
  const auto origin = target_.work_offsets.find(*source_origin_);
  if (inch_ == false && (origin != target_.work_offsets.end() ? !origin->second.inch : *source_origin_ == 0))
    for (size_t i = 0; i < 3; ++i)
      position_[i] =
          target_.initial_position[i] - (origin != target_.work_offsets.end() ? origin->second.values[i] : 0);
  // Where a motion code alone moves (LinuxCNC's G0 to where the tool is), the
  // power-on motion goes into the main program's first move instead of the start.
  if (motion_code_moves() && !same_)
    for (const FnCall& c : power_on())
      if (fn_group(c.fn) == FnGroup::Motion && c.fn != Fn::CycleCancel)
        if (auto code = target_code({c}, Scope::Modal)) deferred_motion_ = code->text();
}

void Structured::translate(const ir::Program& program, const Header& header) {
  attach(program);
  body();
  text_ = w_.take();
  Header h = header;
  for (const std::string& c : title_comments_) h.title += (h.title.empty() ? "" : " ") + c;
  h.title = own_title(h.title);
  w_.begin(h);
  const size_t begun = w_.pending();
  if (!same_) start();  // last: it sets what the program uses
  start_empty_ = w_.pending() == begun;
  head_ = w_.take();
}

bool Structured::emit(std::FILE* streamed, std::FILE* out) {
  bool ok = std::fwrite(head_.data(), 1, head_.size(), out) == head_.size();
  // The first block the program writes, where the start wrote none: what the target
  // puts before it (GOST's N1).
  bool first = start_empty_;
  auto put = [&](const char* data, size_t n) {
    if (first && n > 0) {
      first = false;
      const std::string before = first_block_prefix(data[0]);
      ok = ok && std::fwrite(before.data(), 1, before.size(), out) == before.size();
    }
    ok = ok && std::fwrite(data, 1, n, out) == n;
  };
  // The streamed blocks stand where the main program's others begin.
  const size_t at = std::min(main_at_, text_.size());
  put(text_.data(), at);
  if (streamed) {
    std::rewind(streamed);
    char buffer[1 << 16];
    for (size_t n; ok && (n = std::fread(buffer, 1, sizeof buffer, streamed)) > 0;) put(buffer, n);
  }
  put(text_.data() + at, text_.size() - at);
  w_.end();
  const std::string tail = w_.take();
  return ok && std::fwrite(tail.data(), 1, tail.size(), out) == tail.size();
}

// --- units and blocks -----------------------------------------------------------------

void Structured::unit(const ir::Unit& u, bool main) {
  if (u.kind == ir::UnitKind::Process) return fail(u.range, "a process program (EXE)");
  if (!main && u.kind == ir::UnitKind::Program && !next_program(u))  // GOST 20999 §1.8
    return fail(u.range,
                fmt::format("a second program on the medium, run after the first ends: {} runs one", w_.dialect()));
  if (main) main_at_ = w_.pending();
  in_main_ = main;
  if (!main)
    forget();
  else if (!streamed_)
    begin_main();  // else its leading blocks are written already
  open_unit(u, main);
  bool returned = false;
  for (size_t i = 0; i < u.blocks.size(); ++i) {
    block_begun();
    before_block(i);
    next_ = i + 1 < u.blocks.size() ? &u.blocks[i + 1] : nullptr;
    returned = block(u.blocks[i]);
    after_block(i);
  }
  next_ = nullptr;
  close_unit(u, main, returned);
}

std::optional<uint32_t> Structured::common_number(const ir::Expr& e) const {
  if (p_->dialect != "iso" || e.op != ir::ExprOp::Var || e.space != 0 || !p_->is_constant(e.a)) return std::nullopt;
  const double n = p_->exprs[e.a].number;
  if (n < kMappedBase || n >= kMappedEnd) return std::nullopt;
  return static_cast<uint32_t>(n) - kMappedBase;
}

std::optional<uint32_t> Structured::parameter_number(const ir::Expr& e, uint32_t first, uint32_t end,
                                                     std::set<uint32_t>& taken, uint32_t& next) const {
  std::optional<uint32_t> n = common_number(e);
  if (!n || *n < first || *n >= end || taken.count(*n)) {
    while (taken.count(next)) ++next;
    if (next >= end) return std::nullopt;
    n = next;
  }
  taken.insert(*n);
  return n;
}

bool Structured::block_has(Fn fn) const {
  return block_has_call([&](const FnCall& c) { return c.fn == fn; });
}

bool Structured::block_has_call(const std::function<bool(const FnCall&)>& is, const ir::Block* b) const {
  if (!b) b = block_;
  return std::any_of(b->words.begin(), b->words.end(), [&](const ir::Word& w) {
    if (w.kind != ir::WordKind::Code || w.code < 0) return false;
    const auto& calls = p_->semantics.codes[static_cast<size_t>(w.code)].calls;
    return std::any_of(calls.begin(), calls.end(), is);
  });
}

void Structured::note_access(const ir::Block& b, const ir::Stmt* stmt) {
  first_store_ = false;
  if (!in_main_ || !straight_) return;
  bool computed = false;
  std::set<std::pair<uint16_t, uint32_t>> named;
  std::function<void(ir::ExprId)> add = [&](ir::ExprId id) {
    if (id == ir::kNoExpr) return;
    const ir::Expr& e = p_->exprs[id];
    if (e.op == ir::ExprOp::Var) {
      if (p_->is_constant(e.a))
        named.emplace(e.space, static_cast<uint32_t>(p_->exprs[e.a].number));
      else
        computed = true;
    }
    if (e.op != ir::ExprOp::Number && e.op != ir::ExprOp::String) {
      add(e.a);
      add(e.b);
    }
  };
  if (!stmt) {  // the block's words, read before its statements are
    for (const ir::Word& w : b.words) add(w.value);
    accessed_.insert(named.begin(), named.end());
    straight_ = !computed;
    return;
  }
  const ir::Stmt& s = *stmt;
  add(s.value);
  add(s.cond);
  for (const ir::CallArg& a : s.args) add(a.value);
  const ir::Expr* target = s.target == ir::kNoExpr ? nullptr : &p_->exprs[s.target];
  if (s.kind == ir::StmtKind::Assign && s.cond == ir::kNoExpr && !b.skippable && target->op == ir::ExprOp::Var &&
      p_->is_constant(target->a) && !computed) {
    const std::pair<uint16_t, uint32_t> key{target->space, static_cast<uint32_t>(p_->exprs[target->a].number)};
    first_store_ = !accessed_.count(key) && !named.count(key);
  }
  if (target) add(s.target);
  accessed_.insert(named.begin(), named.end());
  straight_ = !computed && !b.skippable && s.cond == ir::kNoExpr &&
              (s.kind == ir::StmtKind::Assign || s.kind == ir::StmtKind::Machine || s.kind == ir::StmtKind::Comment);
}

// Whether a unit's last block ends the program or leaves it.
bool Structured::ends_program(const ir::Unit& u) const {
  if (u.blocks.empty()) return false;
  for (const ir::Stmt& s : u.blocks.back().stmts)
    if (s.kind == ir::StmtKind::Return || (s.kind == ir::StmtKind::Jump && s.cond == ir::kNoExpr)) return true;
  for (const ir::Word& w : u.blocks.back().words)
    if (w.kind == ir::WordKind::Code && w.code >= 0)
      for (const FnCall& c : p_->semantics.codes[static_cast<size_t>(w.code)].calls)
        if (c.fn == Fn::ProgramEnd || c.fn == Fn::ProgramEndInformation) return true;
  return false;
}

// One source block: its lines, the first with the block number (set by the target
// before it) and the block's comments.
bool Structured::block(const ir::Block& b) {
  if (program_ended_ && in_main_ && !reads_after_end()) return false;
  // Comment blocks before the main program's first block: its title, on the line
  // that starts the target's program (an NC-110 comment block takes a block cycle).
  if (in_main_ && !main_begun_ && b.words.empty() && b.stmts.empty() && !b.number && !b.comments.empty() &&
      title_line()) {
    for (const std::string& c : b.comments)
      if (auto text = trim(c); !text.empty()) title_comments_.emplace_back(text);
    return false;
  }
  // (A block that writes no line yet begins the program where it does more than its
  // words: a loop's head, a label.)
  main_begun_ |= in_main_ && (!b.label.empty() || std::any_of(b.stmts.begin(), b.stmts.end(), [](const ir::Stmt& s) {
                   return s.kind != ir::StmtKind::Machine && s.kind != ir::StmtKind::Comment;
                 }));
  block_ = &b;
  words_written_ = false;
  if (!pending_number_) pending_number_ = carried_number_;  // a block before it wrote nothing
  carried_number_.reset();
  skip_ = b.skippable;
  if (in_main_) lead(b);
  if (std::any_of(b.words.begin(), b.words.end(), [](const ir::Word& w) { return w.optional; })) {
    if (skip_within(b)) return false;
    fail(b.range, "a '/' in the middle of a block");
  }
  // Operator text (GOST's comments) or the block's comments, on its first line.
  bool has_comment_stmt = false;
  for (const ir::Stmt& s : b.stmts) has_comment_stmt |= s.kind == ir::StmtKind::Comment;
  if (!has_comment_stmt)
    for (const std::string& c : b.comments) comment(c);
  bool returned = false;
  const size_t lines = lines_;
  note_access(b, nullptr);
  for (const ir::Stmt& s : b.stmts) {
    note_access(b, &s);
    returned = s.kind == ir::StmtKind::Return;
    if (s.cond != ir::kNoExpr && s.kind != ir::StmtKind::Jump)
      conditional(s);
    else
      statement(s);
  }
  if (!extra_words_.empty()) write_words(std::exchange(extra_words_, {}));  // with no machine words to join
  if (std::exchange(carry_, false)) return returned;
  if (returns_after() && !in_main_ && !next_ && !returned && lines == lines_ && comments_.empty() && label_.empty())
    end_number_ = std::exchange(pending_number_, std::nullopt);
  flush();  // a block with nothing else
  return returned;
}

void Structured::statement(const ir::Stmt& s) {
  switch (s.kind) {
    case ir::StmtKind::Comment: return comment(s.label);
    case ir::StmtKind::Machine: return machine();
    case ir::StmtKind::Assign: return assign(s);
    case ir::StmtKind::Jump: return jump(s);
    case ir::StmtKind::RepeatBegin: return repeat_begin(s);
    case ir::StmtKind::RepeatEnd: return repeat_end(s);
    case ir::StmtKind::Call: return verbatim() ? machine() : call(s);  // M98 P L: the words of the block
    case ir::StmtKind::Return: return verbatim() ? machine() : ret(s);
    case ir::StmtKind::CallRange: return call_range(s);
    case ir::StmtKind::Display: return display(s);
    case ir::StmtKind::Service: {
      static constexpr const char* kWhat[] = {"an ASSET file statement", "operator input (INP)", "the user screen",
                                              "processes"};  // by Device
      static_assert(std::size(kWhat) == kDeviceCount);
      return fail(s.range, kWhat[static_cast<size_t>(service_info(s.service).device)]);
    }
  }
}

void Structured::line(std::string text) {
  main_begun_ |= in_main_;
  std::string head = std::exchange(label_, {});
  if (pending_number_)
    head += (head.empty() ? "" : " ") + fmt::format("{}{}", main_number_ ? ':' : 'N', *pending_number_);
  pending_number_.reset();  // a skipped block's lines all start with '/'
  if (pending_sync_) head += (head.empty() ? "" : " ") + std::string(1, std::exchange(pending_sync_, 0));
  text = std::exchange(then_, {}) + text;
  if (!head.empty() && !text.empty()) head += ' ';
  text = (skip_ ? "/" : "") + head + text;
  std::vector<std::string> written;
  size_t inline_length = text.size();
  for (const std::string& c : comments_) inline_length += written.emplace_back(w_.inline_comment(c)).size() + 1;
  const bool apart = w_.comments_apart() || (w_.longest_line() && inline_length > w_.longest_line());
  for (size_t i = 0; i < comments_.size(); ++i) {
    if (apart) {  // lines of their own, before the block's
      w_.comment(comments_[i]);
      continue;
    }
    if (written[i].empty()) continue;  // no text: nothing to keep
    if (!text.empty()) text += ' ';
    text += written[i];
  }
  comments_.clear();
  if (text.empty()) return;
  w_.line(text);
  ++lines_;
}

void Structured::forget() {
  if (in_main_ && !offset_selected_) moved_before_offset_ = true;  // a jump may go round the selection
  moved_ = true;
  coolant_on_ = cycle_on_ = length_on_ = comp_on_ = std::nullopt;
  length_entry_.reset();
  spindle_turns_.reset();
  spindle_direction_.reset();
  tool_selected_.reset();
  tool_loaded_.reset();
  position_ = {};
  incremental_.reset();
  corrector_.reset();
  plane_.reset();
  rpm_.reset();
  motion_.reset();
  inch_.reset();
  per_minute_.reset();
  timer_.reset();
  if (unit_ != 1.0 || lowers_inch_) unit_.reset();
  if (polar_ != false || lowers_polar_) polar_.reset();
  if (lowers_frame_) frame_.reset();
  helix_mode_.reset();
  return_initial_.reset();
  level_cycle_.reset();
  source_origin_.reset();
  work_offset_.reset();
  shift_known_ = false;
  if (!shifted_axes_.empty()) shifted_axes_ = dst_.axes;  // a local shift may be on any axis the target moves
}

// --- the machine action -----------------------------------------------------------------

// The block's words: its codes and parameters, and in the same dialect its call
// words too (M98 P L, G65 A..Z), once for all the statements they make.
void Structured::machine() {
  if (std::exchange(words_written_, true)) return;
  if (!verbatim()) return translated_machine();
  std::vector<std::string> words;
  for (const ir::Word& w : block_->words)
    if (std::string text = verbatim_word(w); !text.empty()) words.push_back(std::move(text));
  write_words(words);
}

// A word of the same dialect as it is written (nothing for a word the block's
// statements say).
std::string Structured::verbatim_word(const ir::Word& w) {
  switch (w.kind) {
    case ir::WordKind::Code: return w.code < 0 ? as_written(w) : p_->semantics.codes[static_cast<size_t>(w.code)].name;
    case ir::WordKind::Parameter:
    case ir::WordKind::Argument: return as_written(w);
    case ir::WordKind::Control: return w.address + value(w.value, 'N');  // M98 P1000, not P1000.
    default: return {};
  }
}

void Structured::write_words(const std::vector<std::string>& words) {
  if (words.empty()) return;
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : " ") + word;
  line(text);
}

// A block of another dialect. An M code acts before or after the block's motion
// (GOST 20999 Table 7): where the target's acts at the other time, it gets a block
// of its own before or after the motion, with the S and T words it needs; so do M
// codes the target does not take in one block (ISO M03 and M06).
void Structured::translated_machine() {
  // NC-110 GTL (§2.11): geometric elements and the profiles made of them, one refusal
  // for all of them; the flattened translation writes the path a run makes.
  const bool opens = block_has(Fn::GtlOpen);
  if (opens || in_gtl_ || block_has(Fn::GtlDefine) || block_has(Fn::GtlClose)) {
    in_gtl_ = (in_gtl_ || opens) && !block_has(Fn::GtlClose);
    return fail(block_->range, fmt::format("GTL geometry (§2.11): {} has no geometric elements or profiles; "
                                           "--flatten writes the path a run makes",
                                           w_.dialect()));
  }
  std::vector<Mapped> codes;
  const auto motion_code = [](const Mapped& c) {
    const auto& calls = c.code.entry->desc.calls;
    return std::any_of(calls.begin(), calls.end(), [](const FnCall& f) { return fn_group(f.fn) == FnGroup::Motion; });
  };
  std::vector<std::string> params;
  bool moves = false;
  bool drills = false;                              // the block has a position in the plane (a converted cycle's hole)
  std::array<const ir::Word*, 6> parabola_words{};  // X Y Z I J K of a parabola the target writes otherwise
  operand_words_ = false;
  // Where the previous block's corner left the tool, and the motion code its fillet
  // leaves to be written again.
  const auto chained = std::exchange(chained_start_, std::nullopt);
  std::string restore_motion = std::exchange(restore_motion_, {});
  const auto centre_override = std::exchange(centre_override_, std::nullopt);  // its arc's, from that point
  if (src_.corrector_in_tool_word)                                             // before M06 of the same block
    for (const ir::Word& w : block_->words)
      if (w.kind == ir::WordKind::Parameter && w.address[0] == 'T') corrector(w);
  for (const ir::Word& w : block_->words)
    if (w.kind == ir::WordKind::Parameter && w.address == "T") {
      const auto t = constant_of(w.value);
      tool_selected_ = t ? std::optional<int>(static_cast<int>(*t)) : std::nullopt;
    }
  const std::vector<std::optional<Mapped>> merged = merge_codes();
  for (size_t i = 0; i < block_->words.size(); ++i)
    if (block_->words[i].kind == ir::WordKind::Code && merged[i]) {
      if (merged[i]->code.entry) codes.push_back(*merged[i]);
    } else if (block_->words[i].kind == ir::WordKind::Code) {
      code(block_->words[i], codes);
    }
  // A converted cycle ends at G80 or (ISO) a motion code, before the block's words.
  std::vector<std::string> cycle_before;  // a converted cycle's lines before the block's (NC-110's cycle block, G80)
  if (level_cycle_) {
    // ... but not the cycle the block's own cycle code begins (code() has read it).
    const bool cancel = block_has(Fn::CycleCancel);
    const bool as_moves = level_cycle_->moves;
    if (cancel || (src_.fanuc_cycles && !block_has(Fn::Cycle) && block_has_motion()))
      end_level_cycle(!cancel, cycle_before);
    // The holes written as moves left the target in G00 or G01: from this block's moves on.
    if (as_moves && !level_cycle_ && restore_motion.empty()) restore_motion = std::exchange(restore_motion_, {});
  }
  // A code two words map to (GOST's M05 M09: pp's M05 M09, and M09 again), once.
  for (size_t i = 0; i < codes.size(); ++i)
    for (size_t j = codes.size() - 1; j > i; --j)
      if (codes[j].code.letter == codes[i].code.letter && codes[j].code.number == codes[i].code.number &&
          codes[j].later.empty())
        codes.erase(codes.begin() + static_cast<long>(j));
  for (const Mapped& c : codes) state(c.code.entry->desc.calls);
  for (const ir::Word* w : std::exchange(frames_, {}))
    frame_code(*w, p_->semantics.codes[static_cast<size_t>(w->code)]);
  // A block in machine coordinates (G53) leaves the program's coordinates unknown.
  const bool machine_frame = std::any_of(block_->words.begin(), block_->words.end(), [&](const ir::Word& w) {
    if (w.kind != ir::WordKind::Code || w.code < 0) return false;
    const CodeDesc& d = p_->semantics.codes[static_cast<size_t>(w.code)];
    return std::any_of(d.calls.begin(), d.calls.end(), [&](const FnCall& c) {
      return c.fn == Fn::OriginMachine || (c.fn == Fn::WorkOffset && c.arg == 0 && d.scope == Scope::Block);
    });
  });
  if (machine_frame) position_ = {};
  const auto start = position_;  // where the block's arc starts
  // ISO's, GOST's and pp's centre along X Y Z, from the start: NC-110's two words of
  // the plane (both needed), from the origin under G90.
  const bool plane_words =
      !reads_source_words() && src_.centre_words == CentreWords::PerAxis && dst_.centre_words == CentreWords::Plane;
  std::array<const ir::Word*, 3> centre_words{};
  size_t centre_at = 0;                    // ... written at this place of params
  const ir::Word* radius = nullptr;        // an arc's R, where the target gives arcs by their centre
  const ir::Word* lead = nullptr;          // a helix's lead word
  const ir::Word* corner = nullptr;        // ISO's ,C or ,R, where the target has no corners
  std::array<const ir::Word*, 2> polar{};  // the plane's radius and angle, where the target has no G16
  size_t polar_at = 0;                     // ... written at this place of params
  const bool arc = motion_ == Fn::MotionArcCw || motion_ == Fn::MotionArcCcw;
  // A move under a frame the target has not: its points transformed (framed_move()).
  const bool framed_block =
      !operand_words_ && !machine_frame &&
      framed(std::any_of(block_->words.begin(), block_->words.end(), [](const ir::Word& w) {
        return w.kind == ir::WordKind::Parameter && w.address.size() == 1 && w.address[0] >= 'X' && w.address[0] <= 'Z';
      }));
  size_t framed_at = SIZE_MAX;
  std::string arc_code;    // ... an arc's motion code, turned where one axis of its plane is mirrored
  std::string helix_code;  // the target's helix mode, where a helix needs it
  for (const ir::Word& w : block_->words)
    if (w.kind == ir::WordKind::Parameter) {
      if (operand_words_) continue;  // the code says them (UAO by its work offset), or they are refused with it
      if (level_word(w)) continue;   // a converted cycle's level, depth or dwell
      if (skip_offset_word_ && w.address == "H") continue;  // G43's, folded into the M06 before
      const char l = w.address.size() == 1 ? w.address[0] : 0;
      drills |= plane_ && l && (l == 'X' + static_cast<char>(plane_u()) || l == 'X' + static_cast<char>(plane_v()));
      if (const size_t k = std::string_view("XYZIJK").find(l); l && k != std::string_view::npos && lowers_parabola()) {
        parabola_words[k] = &w;
        continue;
      }
      if (framed_block && l >= 'X' && l <= 'Z' && framed_axis(static_cast<size_t>(l - 'X'), arc)) {
        framed_at = std::min(framed_at, params.size());
        moves = true;
        track(w);
        continue;
      }
      if (framed_block && arc && ((l >= 'I' && l <= 'K') || (l && l == src_.radius_word)))
        continue;  // the centre, transformed
      if (lowers_frame_ && frame_ && frame_->scales_others && l &&
          std::string_view("UVW").find(l) != std::string_view::npos)
        fail(w.range,
             fmt::format("an axis {} under a scale or mirror: {} has none, and only X Y Z are written transformed", l,
                         w_.dialect()));
      if (lowers_corner(w)) {
        if (framed_block)
          fail(w.range, fmt::format("a corner under a rotation, scale or mirror: {} has none of them", w_.dialect()));
        corner = &w;
        continue;
      }
      if (const int k = polar_word(w); k >= 0 && !machine_frame) {  // 0 the radius, 1 the angle, 2 not known
        if (k == 2) {
          fail(w.range, fmt::format("an axis word where the plane or G15/G16 is not known: {} has no polar coordinates",
                                    w_.dialect()));
          continue;
        }
        if (!polar[0] && !polar[1]) polar_at = params.size();
        polar[static_cast<size_t>(k)] = &w;
        moves = true;
        continue;
      }
      if (centre_override && arc && w.address.size() == 1 &&
          ((w.address[0] >= 'I' && w.address[0] <= 'K') || w.address[0] == src_.radius_word))
        continue;
      if (arc && !reads_source_words() && plane_ && !src_.helix_by_end && w.address.size() == 1 &&
          w.address[0] == (src_.centre_words == CentreWords::Plane ? 'K' : *plane_)) {
        lead = &w;  // a helix's lead, in the source's unit (helix())
        continue;
      }
      if (plane_words && w.address.size() == 1 && w.address[0] >= 'I' && w.address[0] <= 'K') {
        if (std::none_of(centre_words.begin(), centre_words.end(), [](const ir::Word* c) { return c; }))
          centre_at = params.size();
        centre_words[static_cast<size_t>(w.address[0] - 'I')] = &w;
        continue;
      }
      if (arc && !reads_source_words() && w.address.size() == 1 && w.address[0] == src_.radius_word &&
          dst_.radius_word != src_.radius_word && !cycle_word(w.address[0])) {
        radius = &w;
        continue;
      }
      moves |= w.address.size() == 1 && src_.axes.find(w.address[0]) != std::string::npos;
      if (src_.corrector_in_tool_word && !dst_.corrector_in_tool_word && w.address == "T'") continue;
      if (!reads_source_words() && w.address.size() == 1 && w.address[0] >= 'I' && w.address[0] <= 'K' &&
          !cycle_word(w.address[0]) && (src_.arc_centre != dst_.arc_centre || src_.centre_words != dst_.centre_words))
        centre(w, start, params);
      else
        parameter(w, params);
      track(w);
    }
  if (polar[0] || polar[1]) polar_point(polar, start, params, polar_at);
  if (std::any_of(parabola_words.begin(), parabola_words.end(), [](const ir::Word* w) { return w; })) {
    moves = true;
    parabola(parabola_words, start, params);
  }
  if (const auto h = std::exchange(folded_corrector_, std::nullopt)) {  // NC-110's M06 of T tool.corrector
    std::erase_if(params, [](const std::string& p) { return p[0] == 'T'; });
    params.push_back(fmt::format("T{}.{}", *tool_selected_, *h));
    folded_g43_ = true;
    length_entry_ = *h;
  }
  skip_offset_word_ = false;
  bool hole = false;  // the block's own line goes over a hole written as moves (hole_moves())
  if (level_cycle_) {
    if (level_cycle_lines(drills, start, cycle_before, params))
      restore_motion.clear();  // the cycle is the block's motion
    hole = level_cycle_ && level_cycle_->moves && !hole_lines_.empty();
    if (hole)
      std::erase_if(codes, motion_code);  // ... whose motion it is: a motion code of the block is its state only
    if (const auto rapid = std::exchange(hole_rapid_, std::nullopt))
      codes.push_back({*rapid, Timing::None, rapid->entry->desc.timing, rapid->entry->conflict_sets, {}});
  } else {
    unknown_level_cycle(moves);
  }
  if (framed_block) {
    std::vector<std::string> transformed;
    framed_move(start, arc, transformed, arc_code);
    params.insert(params.begin() + static_cast<long>(std::min(framed_at, params.size())), transformed.begin(),
                  transformed.end());
  } else if (lowers_frame_ && arc && moves && std::exchange(flipped_, false)) {
    if (auto code = target_code({{*motion_}}, Scope::Modal))
      arc_code = code->text();  // the target's is the other way round
  }
  if (machine_frame) position_ = {};
  if (moves && in_main_ && !offset_selected_) moved_before_offset_ = true;
  moved_ |= moves;
  if (centre_override) {
    params.insert(params.end(), centre_override->begin(), centre_override->end());
  } else if (framed_block) {
    centre_ = {};
  } else {
    std::vector<std::string> centre;  // the centre and the lead, where the source has its first centre word
    const bool by_plane = std::any_of(centre_words.begin(), centre_words.end(), [](const ir::Word* w) { return w; });
    if (by_plane) plane_centre(centre_words, start, centre);
    if (radius) radius_centre(*radius, start, params);
    if (!by_plane) centre_at = params.size();
    if (arc) helix(start, lead, centre, helix_code);
    params.insert(params.begin() + static_cast<long>(std::min(centre_at, params.size())), centre.begin(), centre.end());
    absolute_centre(start, params);
    arc_on_circle(start);
  }
  if (!arc_code.empty()) {  // instead of the block's own
    std::erase_if(codes, [](const Mapped& c) {
      const auto& calls = c.code.entry->desc.calls;
      return std::find(calls.begin(), calls.end(), FnCall{Fn::MotionArcCw}) != calls.end() ||
             std::find(calls.begin(), calls.end(), FnCall{Fn::MotionArcCcw}) != calls.end();
    });
  }
  std::vector<std::string> joint;  // the corner's move, after the block's
  if (corner) joint = corner_moves(*corner, start, chained, params);
  auto conflict = [&](const Mapped& a) {
    return std::any_of(codes.begin(), codes.end(), [&](const Mapped& b) {
      if (&a == &b) return false;
      for (const std::string& set : a.sets)
        if (std::find(b.sets.begin(), b.sets.end(), set) != b.sets.end()) return true;
      return false;
    });
  };
  bool any_before = false, any_after = false;
  for (const Mapped& c : codes) {
    const bool apart = c.code.letter == 'M' && ((moves && c.wants != c.has) || conflict(c) || hole);
    any_before |= apart && c.wants == Timing::Before;
    any_after |= apart && c.wants == Timing::After;
  }
  // G codes, then the other words, then M codes (the usual order); M codes of one
  // time together, in the source's order.
  std::vector<std::string> before, main, m, after, later;
  std::vector<Code> g;
  for (const Mapped& c : codes) {
    if (!c.later.empty())
      later.push_back(c.later);
    else if (c.code.letter == 'M' && any_before && c.wants == Timing::Before)
      before.push_back(c.code.text());
    else if (c.code.letter == 'M' && any_after && c.wants == Timing::After)
      after.push_back(c.code.text());
    else if (c.code.letter == 'M')
      m.push_back(c.code.text());
    else
      g.push_back(c.code);
  }
  for (const std::string& line : cycle_before) write_words({line});
  for (const std::string& line : std::exchange(lines_before_, {})) write_words({line});
  // G codes the target takes in no one block: the last block's with the motion,
  // the others' before it.
  const auto blocks = together(g);
  for (size_t i = 0; i < blocks.size(); ++i) {
    std::vector<std::string> texts;
    for (const Code& c : blocks[i]) texts.push_back(c.text());
    if (i + 1 < blocks.size())
      write_words(texts);
    else
      main = texts;
  }
  if (!before.empty()) {  // the speed and the tool the codes before the motion act on
    for (auto it = params.begin(); it != params.end();) {
      if ((*it)[0] == 'S' || (*it)[0] == 'T') {
        before.insert(before.begin(), *it);
        it = params.erase(it);
      } else {
        ++it;
      }
    }
  }
  const bool has_motion = std::any_of(codes.begin(), codes.end(), motion_code);
  if (!restore_motion.empty() && !has_motion) {  // at the next move
    if (moves)
      main.insert(main.begin(), restore_motion);
    else
      restore_motion_ = restore_motion;
  }
  if (!arc_code.empty()) main.push_back(arc_code);  // after the block's other G codes
  if (!helix_code.empty()) main.insert(main.begin(), helix_code);
  if (moves && in_main_ && !deferred_motion_.empty()) {
    if (!has_motion) main.insert(main.begin(), deferred_motion_);
    deferred_motion_.clear();
  }
  main.insert(main.end(), params.begin(), params.end());
  main.insert(main.end(), extra_words_.begin(), extra_words_.end());
  extra_words_.clear();
  main.insert(main.end(), m.begin(), m.end());
  // M codes apart that conflict with each other (two coolants) in blocks of their own.
  auto apart_blocks = [&](const std::vector<std::string>& words) {
    std::vector<std::string> line;
    for (const std::string& word : words) {
      const bool is_m = word[0] == 'M';
      if (is_m && std::any_of(line.begin(), line.end(), [](const std::string& x) { return x[0] == 'M'; }) &&
          std::any_of(codes.begin(), codes.end(),
                      [&](const Mapped& c) { return c.code.text() == word && conflict(c); })) {
        write_words(line);
        line.clear();
      }
      line.push_back(word);
    }
    write_words(line);
  };
  apart_blocks(before);
  write_words(main);
  for (const std::string& line : std::exchange(hole_lines_, {})) write_words({line});
  write_words(joint);
  apart_blocks(after);
  later.insert(later.end(), later_lines_.begin(), later_lines_.end());
  later_lines_.clear();
  for (const std::string& line : later) write_words({line});                           // each a block of its own
  if (level_cycle_ && std::exchange(level_cycle_->carry, false) && pending_number_) {  // to the cycle's first hole
    carried_number_ = std::exchange(pending_number_, std::nullopt);
    carry_ = true;
  }
}

// Two codes of the block whose functions together are one code of the target, which
// has no code for one of them alone: that code (pp's M05 M09: GOST's M05, which also
// ends the coolants), at the first word's place; the second's place holds no code.
std::vector<std::optional<Structured::Mapped>> Structured::merge_codes() {
  std::vector<std::optional<Mapped>> merged(block_->words.size());
  if (reads_source_words()) return merged;
  auto desc_of = [&](size_t i) -> const CodeDesc* {
    const ir::Word& w = block_->words[i];
    if (w.kind != ir::WordKind::Code || w.code < 0 || merged[i]) return nullptr;
    const CodeDesc& d = p_->semantics.codes[static_cast<size_t>(w.code)];
    const bool plain = !d.calls.empty() && std::none_of(d.calls.begin(), d.calls.end(), [](const FnCall& c) {
      return c.fn == Fn::Cycle || c.fn == Fn::OriginSelect;
    });
    return plain ? &d : nullptr;
  };
  std::vector<char> alone(merged.size());  // the word's functions are a code of the target
  for (size_t i = 0; i < merged.size(); ++i)
    if (const CodeDesc* d = desc_of(i)) alone[i] = exact_code(d->calls, d->scope).has_value();
  for (size_t i = 0; i < merged.size(); ++i)
    for (size_t j = i + 1; j < merged.size(); ++j) {
      const CodeDesc* a = desc_of(i);
      const CodeDesc* b = desc_of(j);
      if (!a || !b || a->scope != b->scope || a->timing != b->timing || (alone[i] && alone[j])) continue;
      std::vector<FnCall> both = a->calls;
      both.insert(both.end(), b->calls.begin(), b->calls.end());
      if (auto one = exact_code(both, a->scope)) {
        merged[i] = Mapped{*one, a->timing, one->entry->desc.timing, one->entry->conflict_sets, {}};
        merged[j] = Mapped{{0, 0, nullptr}, {}, {}, {}, {}};
      }
    }
  return merged;
}

// ISO's G28 through a point no way off (G91 Z0: where the tool is) to the reference
// point, on the axes it names: the target's code that takes them there (pp's G30).
// With a length offset on, ISO's goes there without it and the target's not.
void Structured::reference(const ir::Word& w, const CodeDesc& desc, std::vector<Mapped>& out) {
  const auto to = target_code({{Fn::MotionReference}}, Scope::Block);
  std::optional<bool> incremental = incremental_;
  bool axes = false, zero = true;
  for (const ir::Word& o : block_->words) {
    if (o.kind == ir::WordKind::Code && o.code >= 0)
      for (const FnCall& c : p_->semantics.codes[static_cast<size_t>(o.code)].calls)
        if (c.fn == Fn::DistanceIncremental || c.fn == Fn::DistanceAbsolute)
          incremental = c.fn == Fn::DistanceIncremental;
    if (o.kind == ir::WordKind::Parameter && o.address.size() == 1 &&
        src_.axes.find(o.address[0]) != std::string::npos) {
      axes = true;
      const auto v = constant_of(o.value);
      zero &= v && *v == 0;
    }
  }
  // Without words every axis goes there directly (docs/dialects/iso.md, decision 17):
  // a rapid in machine coordinates, or pp's G30 naming X Y Z, says it for a machine of
  // X Y Z.
  const bool every = !axes && src_.axes == "XYZ";
  if (!every && (!axes || incremental != true || !zero))
    return fail(w.range,
                fmt::format("{} through a point off the tool's position (only G91 with zero words, or none on a "
                            "machine of X Y Z, as {} goes there directly)",
                            desc.name,
                            to ? fmt::format("{}'s {}", w_.dialect(), to->text())
                               : fmt::format("a rapid in {}'s machine coordinates", w_.dialect())));
  if (!to) {  // NC-110 and GOST: a rapid in machine coordinates (iso_tool_change())
    std::string
        named;  // the axes to move: before the program's first move, one that starts at the reference point does not
    auto add = [&](char axis) {
      const size_t i = static_cast<size_t>(axis - 'X');
      if (moved_ || target_.initial_position[i] != target_.reference_position[i]) named += axis;
    };
    if (every)
      for (char axis : std::string_view("XYZ")) add(axis);
    for (const ir::Word& o : block_->words)
      if (o.kind == ir::WordKind::Parameter && o.address.size() == 1 &&
          std::string_view("XYZ").find(o.address[0]) != std::string_view::npos)
        add(o.address[0]);
    std::vector<std::string> lines;
    if (named.empty()) return void(operand_words_ = true);
    if (std::string why = machine_reference(named, incremental, lines, true); !why.empty())
      return fail(w.range,
                  fmt::format("{} (reference.return): {} has no code for it, and a rapid in its machine coordinates "
                              "cannot say it here: {}",
                              desc.name, w_.dialect(), why));
    operand_words_ = true;  // the axes named are the move's, not a point to go through
    later_lines_.insert(later_lines_.end(), lines.begin(), lines.end());
    for (const char axis : named) position_[static_cast<size_t>(axis - 'X')].reset();
    return;
  }
  // With a length offset on, ISO's goes there without it and the target's not: the
  // offset ends before and is applied again after (pp's link).
  std::vector<std::string> off, on;
  if (length_on_ != false)
    if (std::string why = length_around(off, on, true); !why.empty())
      return fail(w.range,
                  fmt::format("{} with a length offset (perhaps) on: {} goes there without it, {}'s {} with it; {}",
                              desc.name, p_->dialect, w_.dialect(), to->text(), why));
  lines_before_.insert(lines_before_.end(), off.begin(), off.end());
  later_lines_.insert(later_lines_.end(), on.begin(), on.end());
  if (every)
    for (char axis : std::string_view("XYZ"))
      extra_words_.push_back(std::string(1, axis) + number({axis, 0, Value::Length}, w.range));
  out.push_back({*to, desc.timing, to->entry->desc.timing, {}, {}});
}

// NC-110's dwells into a dialect with a dwell code and word: (DLY,t), t seconds, and
// G04, which dwells at the end of its block for the time in TMR (seconds under G94):
// the target's G04 with its time, after the block's motion.
void Structured::timed_dwell(const ir::Word& w, const CodeDesc& desc, std::vector<Mapped>& out) {
  const auto code = target_code({{Fn::Dwell}}, Scope::Block);
  if (!code || !dst_.dwell_word)
    return fail(w.range, fmt::format("{} ({}): {} has no dwell with a time", desc.name, fn_name(desc.calls[0].fn),
                                     w_.dialect()));
  bool known = timer_.has_value();
  double seconds = timer_.value_or(0);
  if (desc.calls[0].fn == Fn::DwellSeconds) {
    known = false;
    for (const ir::Word& o : block_->words)
      if (o.kind == ir::WordKind::Parameter && o.slot == operand_slot(0))
        if (const auto v = constant_of(o.value)) known = true, seconds = *v;
    operand_words_ = true;  // its operand is the dwell's time
  } else if (per_minute_ != true) {
    return fail(w.range,
                fmt::format("{} where the feed may be per revolution: TMR then counts revolutions", desc.name));
  }
  if (!known)
    return fail(w.range,
                fmt::format("{} whose time is not known here (TMR set by a label's way, or computed)", desc.name));
  const OutWord time{dst_.dwell_word, seconds / dst_.dwell_seconds_per_unit, Value::Seconds};
  if (auto why = w_.unwritable(time)) return fail(w.range, *why);
  out.push_back(
      {*code, desc.timing, code->entry->desc.timing, {}, code->text() + " " + dst_.dwell_word + number(time, w.range)});
}

// NC-110's (UAO,n): origin n on every axis it declares. It is the target's work
// offset n (G54 for 1) where origin n declares every axis of the target machine and
// no axis is listed: otherwise an axis would keep its origin in NC-110, not in ISO.
void Structured::origin(const ir::Word& w, const CodeDesc& desc, std::vector<Mapped>& out) {
  std::optional<double> n;
  bool listed = false;
  for (const ir::Word& o : block_->words) {
    if (o.kind != ir::WordKind::Parameter) continue;
    if (o.slot == operand_slot(0))
      n = constant_of(o.value);
    else if (o.slot < 52)
      listed = true;
  }
  auto code = n && *n >= 1 && *n <= 0xFFFF ? target_code({{Fn::WorkOffset, static_cast<uint16_t>(*n)}}, Scope::Modal)
                                           : std::nullopt;
  // NC-110's origin 0 (none) into a target without "none": the offset it powers on in,
  // where the target machine sets it to zero (as the start takes it, start_offset()).
  if (n && *n == 0) {
    const int k = start_work_offset();
    const auto it = target_.work_offsets.find(k);
    if (k > 0 && (it == target_.work_offsets.end() ||
                  std::all_of(it->second.values.begin(), it->second.values.end(), [](double v) { return v == 0; })))
      code = target_code({{Fn::WorkOffset, static_cast<uint16_t>(k)}}, Scope::Modal);
  }
  operand_words_ = true;  // its operands are said by the work offset, or refused with it
  if (!n) return fail(w.range, fmt::format("{} of an origin given by a parameter", desc.name));
  if (listed)
    return fail(w.range,
                fmt::format("{} on the axes it lists: {}'s work offset sets every axis", desc.name, w_.dialect()));
  if (!code) return fail(w.range, fmt::format("{},{}: {} has no work offset {}", desc.name, *n, w_.dialect(), *n));
  if (*n != 0)
    if (auto why = partial_offset(static_cast<int>(*n), desc.name)) return fail(w.range, *why);
  out.push_back({*code, desc.timing, code->entry->desc.timing, {}, {}});
  // UAO ends the temporary and incremental shifts; the target's work offset brings
  // back the local shift it had: ended in a block after it.
  source_origin_ = static_cast<int>(*n);
  shift_ = {};
  shift_known_ = true;
  if (!shifted_axes_.empty()) {
    std::string zero = local_shift_code()->text();
    for (char axis : shifted_axes_)
      if (const auto text = length(w.range, axis, 0.0)) zero += fmt::format(" {}{}", axis, *text);
    later_lines_.push_back(zero);
  }
}

// NC-110's temporary origin (UOT: origin n shifted on the axes it lists) and
// incremental origin (UIO: the origin in force shifted, cumulatively) into a target
// whose work offset has a local shift of its own (ISO's G52, which replaces the shift
// of the axes it names). The shift of each axis is known from the text since the last
// UAO; the origin UOT names must be the one in force (the target shifts that one).
void Structured::origin_shift(const ir::Word& w, const CodeDesc& desc) {
  operand_words_ = true;  // the shift's words are written below, or refused with it
  const auto local = local_shift_code();
  if (!local)
    return fail(w.range,
                fmt::format("{} ({}): {} has no code for it", desc.name, fn_name(desc.calls[0].fn), w_.dialect()));
  if (lowers_frame_)
    return fail(w.range,
                fmt::format("{} in a program with a rotation, scale or mirror written into its points: {}'s {} "
                            "shifts the points written",
                            desc.name, w_.dialect(), local->text()));
  // pp's G37 sets every axis's shift: the others' it does not name end.
  const auto& calls = local->entry->desc.calls;
  const bool names_every = std::find(calls.begin(), calls.end(), FnCall{Fn::ShiftAxes}) != calls.end();
  const bool temporary = desc.calls[0].fn == Fn::OriginTemporary;
  std::optional<double> n;
  std::vector<std::pair<int, std::optional<double>>> axes;
  for (const ir::Word& o : block_->words) {
    if (o.kind != ir::WordKind::Parameter) continue;
    if (temporary && o.slot == operand_slot(0))
      n = constant_of(o.value);
    else if (o.address.size() == 1 && std::string_view(kAxisLetters).find(o.address[0]) != std::string_view::npos)
      axes.emplace_back(static_cast<int>(std::string_view(kAxisLetters).find(o.address[0])), constant_of(o.value));
  }
  if (temporary && (!n || !source_origin_ || *n != *source_origin_))
    return fail(w.range,
                fmt::format("{} of another origin than the one in force, or where that is not known (after a "
                            "label, a loop's start or a call): {}'s local shift moves the work offset in force",
                            desc.name, w_.dialect()));
  if (!temporary && !shift_known_)
    return fail(
        w.range,
        fmt::format("{} where the shift it adds to is not known (after a label, a loop's start or a call)", desc.name));
  std::string text = local->text();
  for (const auto& [axis, v] : axes) {
    const char letter = kAxisLetters[static_cast<size_t>(axis)];
    if (!v) return fail(w.range, fmt::format("{} by a parameter: the shift is not known from the text", desc.name));
    if (dst_.axes.find(letter) == std::string::npos)
      return fail(w.range, fmt::format("{} of axis {}: {} has axes {}", desc.name, letter, w_.dialect(), dst_.axes));
    shift_[static_cast<size_t>(axis)] = temporary ? *v : shift_[static_cast<size_t>(axis)] + *v;
    if (shifted_axes_.find(letter) == std::string::npos) shifted_axes_ += letter;
  }
  for (size_t i = 0; i < kAxisLetters.size(); ++i) {
    const char letter = kAxisLetters[i];
    const bool named =
        std::any_of(axes.begin(), axes.end(), [&](const auto& a) { return static_cast<size_t>(a.first) == i; });
    if (!named && !(names_every && shifted_axes_.find(letter) != std::string::npos)) continue;
    const auto written = length(w.range, letter, shift_[i]);
    if (!written) return;
    text += fmt::format(" {}{}", letter, *written);
  }
  forget_position();             // the program's coordinates of the tool move with its origin
  later_lines_.push_back(text);  // a block of its own (ISO)
}

std::optional<std::string> Structured::partial_offset(int n, std::string_view name) const {
  // The axes both dialects move: an axis the source cannot move keeps its origin unseen.
  std::string axes;
  for (char axis : dst_.axes)
    if (src_.axes.find(axis) != std::string::npos &&
        std::string_view(kAxisLetters).find(axis) != std::string_view::npos)
      axes += axis;
  const auto record = target_.work_offsets.find(n);
  bool every = record != target_.work_offsets.end();
  for (char axis : axes)
    if (every) every = (record->second.axes >> std::string_view(kAxisLetters).find(axis)) & 1u;
  if (every) return std::nullopt;
  std::string declared;
  if (record != target_.work_offsets.end())
    for (size_t i = 0; i < kAxisLetters.size(); ++i)
      if ((record->second.axes >> i) & 1u) declared += kAxisLetters[i];
  return fmt::format(
      "{},{}: origin {} declares {}, and {}'s work offset sets every axis ({}): the others would not "
      "keep their origins",
      name, n, n, declared.empty() ? "no axis" : declared, w_.dialect(), axes);
}

// An arc's centre where the dialects give it otherwise: NC-110's I and J are the
// plane's abscissa and ordinate, measured from the origin; ISO's and LinuxCNC's I J
// K go along X Y Z from the arc's start. The start must be known from the text: a
// constant position since the last label, call or computed value.
void Structured::centre(const ir::Word& w, const Position& start, std::vector<std::string>& words) {
  const char letter = w.address[0];
  int axis = letter - 'I';
  if (src_.centre_words == CentreWords::Plane) {
    if (!plane_) return fail(w.range, fmt::format("the arc centre {} where the plane is not known", letter));
    if (letter == 'K')
      return fail(w.range, fmt::format("a helix pitch K: {} gives a helix by its end point alone", w_.dialect()));
    const int plane = plane_index();
    axis = letter == 'I' ? kPlanes[plane].u : kPlanes[plane].v;
  }
  auto v = constant_of(w.value);
  if (src_.arc_centre == ArcCentre::Absolute && dst_.arc_centre == ArcCentre::Incremental) {
    if (!incremental_) return fail(w.range, fmt::format("the arc centre {} where G90 or G91 is not known", letter));
    if (!*incremental_) {  // under G91 the centre is from the start already
      if (!v) return fail(w.range, fmt::format("the arc centre {} given by a parameter, from the origin", letter));
      if (!start[static_cast<size_t>(axis)])
        return fail(w.range, fmt::format("the arc centre {} from the origin, where the arc's start is not known (after "
                                         "a label, a call or a computed move)",
                                         letter));
      centre_[static_cast<size_t>(axis)] = *v;
      *v -= *start[static_cast<size_t>(axis)];
    }
  }
  if (src_.arc_centre == ArcCentre::Incremental && dst_.arc_centre == ArcCentre::Absolute &&
      src_.centre_words == dst_.centre_words) {
    if (!incremental_) return fail(w.range, fmt::format("the arc centre {} where G90 or G91 is not known", letter));
    if (!*incremental_) {  // from the origin in the target
      if (!v) return fail(w.range, fmt::format("the arc centre {} given by a parameter, from the origin", letter));
      if (!start[static_cast<size_t>(axis)])
        return fail(w.range, fmt::format("the arc centre {} from the origin, where the arc's start is not known (after "
                                         "a label, a call or a computed move)",
                                         letter));
      *v += *start[static_cast<size_t>(axis)];
    }
  }
  // The target's word: I J K of X Y Z, or (pp) I J of the plane's two axes.
  if (dst_.centre_words == CentreWords::Plane && !plane_)
    return fail(w.range, fmt::format("the arc centre {} where the plane is not known", letter));
  const char to = dst_.centre_words == CentreWords::Plane
                      ? centre_letter(dst_, static_cast<size_t>(axis) == plane_u() ? 0 : 1)
                      : static_cast<char>('I' + axis);
  if (!v && unit_ == 1.0) return words.push_back(to + value(w.value, to));
  if (const auto text = length(w.range, to, v)) words.push_back(to + *text);
}

// An arc's centre word the source leaves out (0 from the start) where the target
// reads the centre from the origin (GOST's arc_center = "absolute" under G90): the
// start's coordinate.
void Structured::absolute_centre(const Position& start, std::vector<std::string>& words) {
  if (reads_source_words() || src_.arc_centre != ArcCentre::Incremental || dst_.arc_centre != ArcCentre::Absolute ||
      src_.centre_words != CentreWords::PerAxis || dst_.centre_words != CentreWords::PerAxis || incremental_ != false ||
      !plane_)
    return;
  std::array<bool, 3> given{};
  const ir::Word* any = nullptr;
  for (const ir::Word& w : block_->words)
    if (w.kind == ir::WordKind::Parameter && w.address.size() == 1 && w.address[0] >= 'I' && w.address[0] <= 'K') {
      given[static_cast<size_t>(w.address[0] - 'I')] = true;
      any = &w;
    }
  if (!any) return;  // a block without a centre word: no arc, or an R arc
  const int plane = plane_index();
  for (const int axis : {kPlanes[plane].u, kPlanes[plane].v}) {
    if (given[static_cast<size_t>(axis)]) continue;
    const char to = static_cast<char>('I' + axis);
    if (!start[static_cast<size_t>(axis)])
      return fail(any->range,
                  fmt::format("the arc centre {} from the origin, where the arc's start is not known (after "
                              "a label, a call or a computed move)",
                              to));
    if (const auto text = length(any->range, to, *start[static_cast<size_t>(axis)])) words.push_back(to + *text);
  }
}

void Structured::plane_centre(const std::array<const ir::Word*, 3>& words, const Position& start,
                              std::vector<std::string>& out) {
  const ir::Word& first = **std::find_if(words.begin(), words.end(), [](const ir::Word* w) { return w; });
  if (src_.arc_centre != ArcCentre::Incremental)
    return fail(first.range, "an arc centre from the origin, given by X Y Z");
  if (!plane_) return fail(first.range, "an arc centre where the plane is not known");
  if (!incremental_ && dst_.arc_centre == ArcCentre::Absolute)
    return fail(first.range, "an arc centre where G90 or G91 is not known");
  const int plane = plane_index();
  if (const ir::Word* lead = words[static_cast<size_t>(kPlanes[plane].w)])
    return fail(lead->range,
                fmt::format("a helix lead {}: the dialects give the lead in other units", lead->address.str()));
  for (int k = 0; k < 2; ++k) {
    const size_t axis = static_cast<size_t>(k == 0 ? kPlanes[plane].u : kPlanes[plane].v);
    const char to = k == 0 ? 'I' : 'J';
    const ir::Word* w = words[axis];
    if (dst_.arc_centre == ArcCentre::Incremental || *incremental_) {  // from the start in both (pp's I J)
      if (unit_ == 1.0)
        out.push_back(to + (w ? value(w->value, to) : std::string("0")));
      else if (const auto text = length(w ? w->range : first.range, to, w ? constant_of(w->value) : 0.0))
        out.push_back(to + *text);
      continue;
    }
    const std::optional<double> v = w ? constant_of(w->value) : std::optional<double>(0);
    if (!v)
      return fail(w->range,
                  fmt::format("the arc centre {} given by a parameter, from the start point", w->address.str()));
    if (!start[axis])
      return fail(first.range,
                  "an arc centre from the start point, where the arc's start is not known (after a label, a "
                  "call or a computed move)");
    centre_[axis] = *start[axis] + *v;
    if (const auto text = length(first.range, to, *centre_[axis])) out.push_back(to + *text);
  }
}

// An arc by its radius (ISO's and NC-110's R: up to 180 degrees, beyond where
// negative) into a target that gives the centre: the centre the source's runtime
// takes (machine_motion.cpp), written to the target's step. The start and the end
// must be known from the text.
std::optional<std::array<double, 2>> Structured::centre_by_radius(const ir::Word& r, const Position& start) {
  const auto radius = constant_of(r.value);
  if (!radius) {
    fail(r.range, fmt::format("an arc by its radius {} given by a parameter: {} gives the centre", r.address.str(),
                              w_.dialect()));
    return std::nullopt;
  }
  const size_t u = plane_u(), v = plane_v();
  if (!start[u] || !start[v] || !position_[u] || !position_[v]) {
    fail(r.range,
         "an arc by its radius, where its start or end is not known (after a label, a call or a computed move)");
    return std::nullopt;
  }
  const double du = *position_[u] - *start[u], dv = *position_[v] - *start[v];
  const double chord = std::hypot(du, dv);
  if (chord < 1e-9) {
    fail(r.range, "an arc by its radius that ends where it starts");
    return std::nullopt;
  }
  // The centre lies on the chord's normal, to its left for G03 R+ and G02 R-.
  const double h = std::sqrt(std::max(0.0, *radius * *radius - chord * chord / 4));
  const double side = (motion_ == Fn::MotionArcCw) == (*radius < 0) ? h / chord : -h / chord;
  return std::array<double, 2>{*start[u] + du / 2 - side * dv, *start[v] + dv / 2 + side * du};
}

void Structured::radius_centre(const ir::Word& r, const Position& start, std::vector<std::string>& words) {
  if (!plane_ || !incremental_) return fail(r.range, "an arc by its radius where the plane or G90/G91 is not known");
  const auto centre = centre_by_radius(r, start);
  if (!centre) return;
  const size_t u = plane_u(), v = plane_v();
  if (!unit_) return fail(r.range, unit_unknown());
  const double unit = *unit_;  // in the target's unit
  for (int k = 0; k < 2; ++k) {
    const size_t axis = k == 0 ? u : v;
    const double exact = (*centre)[static_cast<size_t>(k)] * unit, at = on_step(exact);
    if (off_step(exact)) problems.push_back({r.range, "rounded", Finding::Rounded});
    centre_[axis] = at / unit;  // arc_on_circle() checks the end against it
    const char to = centre_letter(dst_, k);
    const bool from_start = dst_.arc_centre == ArcCentre::Incremental || *incremental_;
    words.push_back(to + w_.number({to, from_start ? at - *start[axis] * unit : at, Value::Length}));
  }
}

// An arc that moves along its plane's normal too: a helix. ISO gives it by its end
// point alone (one turn at most), GOST 20999 by a lead per radian or per revolution
// as well, NC-110 by a pitch (a lead per revolution, positive), each a lead that
// selects the number of turns (machine_motion.cpp). The target's lead is the travel
// over the sweep the source's run takes (the turns its lead selects, or its end
// point's); a helix of more than one turn is refused where the target has no lead.
// The start, the end and the centre must be known from the text.
void Structured::helix(const Position& start, const ir::Word* lead, std::vector<std::string>& words,
                       std::string& mode) {
  if (reads_source_words() || !plane_) return;
  const size_t u = plane_u(), v = plane_v();
  const size_t n = static_cast<size_t>(normal_axis() - 'X');
  const ir::Word* travel = nullptr;
  for (const ir::Word& w : block_->words)
    if (w.kind == ir::WordKind::Parameter && w.address.size() == 1 && w.address[0] == normal_axis()) travel = &w;
  const SourceRange at = lead ? lead->range : travel ? travel->range : block_->range;
  // A lead in an arc that does not move along the normal does nothing (the source's
  // check warns of it, NC4025): not written.
  if (!travel || (start[n] && position_[n] && *start[n] == *position_[n])) return;
  // A target that moves along the normal in its helix mode only (pp's G09): the mode
  // is written in the block, where the text does not say it is on already.
  if (helix_mode_ != true)
    for (const auto& [number, entry] : w_.tables().g_codes)
      if (std::find(entry.desc.calls.begin(), entry.desc.calls.end(), FnCall{Fn::HelixOn}) != entry.desc.calls.end()) {
        mode = Code{entry.letter, number, &entry}.text();
        helix_mode_ = true;
      }
  const bool writes_lead = !dst_.helix_by_end;
  if (!lead && !writes_lead) return;
  const auto centre = arc_centre(start);
  const std::optional<double> source_lead = lead ? constant_of(lead->value) : std::nullopt;
  if (!centre || !start[u] || !start[v] || !start[n] || !position_[u] || !position_[v] || !position_[n] ||
      (lead && !source_lead))
    return fail(
        at, "a helix whose start, end, centre or lead is not known here (after a label, a call or a computed value)");
  double sweep =
      arc_sweep(std::atan2(*start[v] - (*centre)[1], *start[u] - (*centre)[0]),
                std::atan2(*position_[v] - (*centre)[1], *position_[u] - (*centre)[0]), motion_ == Fn::MotionArcCcw);
  const double dw = *position_[n] - *start[n];
  if (source_lead) {  // the turns it selects, as the runtime takes them
    const double per_radian = *source_lead / (src_.helix_lead == HelixLead::PerRevolution ? kTwoPi : 1.0);
    if (per_radian != 0) {
      const double candidate = sweep + kTwoPi * std::round((std::fabs(dw / per_radian) - sweep) / kTwoPi);
      if (candidate > 0) sweep = candidate;
    }
  }
  if (!writes_lead) {  // the source's lead dropped, where it selects the turns the end point does
    if (sweep > kTwoPi + 1e-9)
      fail(at, fmt::format("a helix of more than one turn: {} gives a helix by its end point alone", w_.dialect()));
    return;
  }
  if (!unit_) return fail(at, unit_unknown());
  double to = dw * *unit_ / sweep * (dst_.helix_lead == HelixLead::PerRevolution ? kTwoPi : 1.0);
  if (dst_.centre_words == CentreWords::Plane) to = std::fabs(to);  // NC-110's pitch: the travel's sign is Z's
  const char letter = dst_.centre_words == CentreWords::Plane ? 'K' : static_cast<char>('I' + n);
  words.push_back(letter + w_.number({letter, to, Value::Length}));
}

// Which polar word `w` is where the target has no polar coordinates: 0 the radius
// (the plane's first axis), 1 the angle, 2 an axis word where the plane or the mode
// is not known; -1 none.
int Structured::polar_word(const ir::Word& w) const {
  if (target_polar_ || polar_ == false || w.address.size() != 1) return -1;
  const char letter = w.address[0];
  if (!plane_ || !polar_) return std::string_view("XYZ").find(letter) != std::string_view::npos ? 2 : -1;
  const Plane& plane = kPlanes[plane_index()];
  return letter == 'X' + plane.u ? 0 : letter == 'X' + plane.v ? 1 : -1;
}

// ISO's polar coordinates (G16, §8.6) into a target without them: the plane's first
// word is a radius, its second an angle in degrees from the first axis, about the work
// zero under G90 (a word not written keeps the position's), about the position under
// G91 (a word not written is 0), as the runtime reads them (machine_frame.cpp). The
// point is written in the plane's two axes.
void Structured::polar_point(const std::array<const ir::Word*, 2>& words, const Position& start,
                             std::vector<std::string>& out, size_t at) {
  const ir::Word& first = words[0] ? *words[0] : *words[1];
  const size_t u = plane_u(), v = plane_v();
  position_[u].reset();
  position_[v].reset();
  if (!incremental_ ||
      std::any_of(words.begin(), words.end(), [&](const ir::Word* w) { return w && !constant_of(w->value); }))
    return fail(first.range,
                fmt::format("a point in polar coordinates given by a parameter, or where G90/G91 is not known: {} "
                            "has none, and it cannot be written in X Y Z here",
                            w_.dialect()));
  if (!start[u] || !start[v])
    return fail(first.range,
                fmt::format("a point in polar coordinates, where the tool's position is not known: {} has none, "
                            "and it cannot be written in X Y Z here",
                            w_.dialect()));
  constexpr double kDegree = std::numbers::pi / 180;
  const bool absolute = !*incremental_;
  double radius = absolute ? std::hypot(*start[u], *start[v]) : 0;
  double angle = absolute ? std::atan2(*start[v], *start[u]) / kDegree : 0;
  if (words[0]) radius = *constant_of(words[0]->value);
  if (words[1]) angle = *constant_of(words[1]->value);
  const double pu = (absolute ? 0 : *start[u]) + radius * std::cos(angle * kDegree);
  const double pv = (absolute ? 0 : *start[v]) + radius * std::sin(angle * kDegree);
  std::vector<std::string> words_xy;
  for (const auto& [axis, p] : {std::pair{u, pu}, std::pair{v, pv}}) {
    const char letter = static_cast<char>('X' + axis);
    if (const auto text = length(first.range, letter, absolute ? p : p - *start[axis]))
      words_xy.push_back(letter + *text);
  }
  if (u > v) std::swap(words_xy.front(), words_xy.back());  // X Y Z order
  out.insert(out.begin() + static_cast<long>(std::min(at, out.size())), words_xy.begin(), words_xy.end());
  position_[u] = pu;
  position_[v] = pv;
}

double arc_sweep(double from, double to, bool ccw) {
  const double s = std::fmod(std::fmod(ccw ? to - from : from - to, kTwoPi) + kTwoPi, kTwoPi);
  return s < 1e-12 ? kTwoPi : s;  // the end over the start: a whole turn
}

// The block's arc's centre in the plane (source coordinates): as this translation
// computed it, from the source's R, or from its centre words; nothing where the text
// does not say it.
std::optional<std::array<double, 2>> Structured::arc_centre(const Position& start) {
  const size_t u = plane_u(), v = plane_v();
  if (centre_[u] && centre_[v]) return std::array<double, 2>{*centre_[u], *centre_[v]};
  for (const ir::Word& w : block_->words)
    if (w.kind == ir::WordKind::Parameter && w.address.size() == 1 && w.address[0] == src_.radius_word)
      return centre_by_radius(w, start);
  std::array<double, 2> centre{};
  for (int k = 0; k < 2; ++k) {
    const size_t axis = k == 0 ? u : v;
    const char letter = centre_letter(src_, k);
    std::optional<double> word = 0.0;
    for (const ir::Word& w : block_->words)
      if (w.kind == ir::WordKind::Parameter && w.address.size() == 1 && w.address[0] == letter)
        word = constant_of(w.value);
    const bool from_start = src_.arc_centre == ArcCentre::Incremental || incremental_ == true;
    if (!word || !start[axis] || !incremental_) return std::nullopt;
    centre[static_cast<size_t>(k)] = from_start ? *start[axis] + *word : *word;
  }
  return centre;
}

// An arc whose centre this translation computed: its end must lie on its circle as
// closely as the target asks (the source's machine may take more).
void Structured::arc_on_circle(const Position& start) {
  const auto centre = std::exchange(centre_, {});
  if (!plane_) return;
  const size_t u = plane_u(), v = plane_v();
  if (!start[u] || !start[v] || !position_[u] || !position_[v]) return;
  const double unit = unit_.value_or(1.0);
  auto at = [&](const std::optional<double>& pu, const std::optional<double>& pv) {  // as the target reads it
    return std::array<double, 2>{on_step(*pu * unit), on_step(*pv * unit)};
  };
  const auto a = at(start[u], start[v]);
  if (centre[u] && centre[v]) return on_circle(a, at(position_[u], position_[v]), at(centre[u], centre[v]));
  // The source's centre words from the start, each written to the target's step, where
  // the target reads them so too (pp's I J from inches).
  const bool arc = motion_ == Fn::MotionArcCw || motion_ == Fn::MotionArcCcw;
  if (!arc || reads_source_words() || src_.arc_centre != ArcCentre::Incremental ||
      dst_.arc_centre != ArcCentre::Incremental || incremental_ != false)
    return;
  std::array<double, 2> c{};
  bool given = false;
  for (int k = 0; k < 2; ++k) {
    std::optional<double> word = 0.0;
    for (const ir::Word& w : block_->words)
      if (w.kind == ir::WordKind::Parameter && w.address.size() == 1 && w.address[0] == centre_letter(src_, k))
        word = constant_of(w.value), given = true;
    if (!word) return;
    c[static_cast<size_t>(k)] = a[static_cast<size_t>(k)] + on_step(*word * unit);
  }
  if (given) on_circle(a, at(position_[u], position_[v]), c);
}

// Where the text leaves the tool on X, Y and Z, in the program's coordinates.
void Structured::track(const ir::Word& w) {
  if (w.address.size() != 1 || w.address[0] < 'X' || w.address[0] > 'Z') return;
  auto& axis = position_[static_cast<size_t>(w.address[0] - 'X')];
  const auto v = constant_of(w.value);
  // A cycle's depth is no position: the tool comes back to a level the text may not say.
  const bool depth = cycle_on_ != false && (!plane_ || w.address[0] == normal_axis());
  if (!v || !incremental_ || depth)
    axis.reset();
  else if (!*incremental_)
    axis = *v;
  else if (axis)
    *axis += *v;
}

// A word's or an operand's value where it is a number, signed or not (a read's
// vacancy check aside).
std::optional<double> Structured::constant_of(ir::ExprId id) const {
  const ir::Expr& e = p_->exprs[bare(id)];
  if (e.op == ir::ExprOp::Number) return e.number;
  if (e.op == ir::ExprOp::Neg)
    if (auto a = constant_of(e.a)) return -*a;
  return std::nullopt;
}

// A constant as the target writes it. A length with more decimals than the target
// writes is rounded to its step, with a warning (once): CAM output's fourth decimal
// into GOST or pp; so is a feed, a speed or a dwell (F369.752387 into NC-110).
std::string Structured::number(const OutWord& w, SourceRange at) {
  if ((w.kind == Value::Length || w.kind == Value::Angle) && off_step(w.value))
    problems.push_back({at, "rounded", Finding::Rounded});
  if (w.kind != Value::Count && w_.rounded_rate(w) && !w_.unwritable(w))
    problems.push_back({at, std::string(1, w.letter), Finding::RoundedRate});
  return w_.number(w);
}

double Structured::on_step(double v) const {
  const double step = w_.resolution();
  return step > 0 ? std::round(v / step) * step : v;
}

void Structured::on_circle(const std::array<double, 2>& a, const std::array<double, 2>& b,
                           const std::array<double, 2>& c) {
  const double r0 = std::hypot(a[0] - c[0], a[1] - c[1]), r1 = std::hypot(b[0] - c[0], b[1] - c[1]);
  const double mm =
      std::fabs(r1 - r0) * (inch_ != false && unit_.value_or(1.0) == 1.0 ? 25.4 : 1.0);  // the tolerance is in mm
  if (mm > dst_.arc_tolerance)
    fail(block_->range,
         fmt::format("an arc whose end, written to {}'s step of {}, lies farther off its circle than the "
                     "{} mm {} takes",
                     w_.dialect(), exact(w_.resolution(), false), exact(dst_.arc_tolerance, false), w_.dialect()));
}

// Without the checks the source's reads make (a vacant value, a range).
ir::ExprId Structured::bare(ir::ExprId id) const {
  while (p_->exprs[id].op == ir::ExprOp::ZeroIfVacant || p_->exprs[id].op == ir::ExprOp::Check) id = p_->exprs[id].a;
  return id;
}

// NC-110's T tool.corrector: the corrector takes effect at M06 (nc110 decision 11).
// The target's M06 ends the length offset: G43 H<corrector> after it, G49 for none.
void Structured::corrector(const ir::Word& w) {
  if (w.address == "T") {
    corrector_ = 0;  // T6 is corrector 0 unless T' follows
    return;
  }
  if (!p_->is_constant(w.value)) {
    corrector_.reset();
    return fail(w.range, "a corrector given by a parameter");
  }
  corrector_ = static_cast<int>(p_->exprs[w.value].number);
}

std::string Structured::length_offset(SourceRange at) {
  if (!corrector_) {
    fail(at, "M06 with a corrector that is not known here");
    return {};
  }
  const int n = *corrector_;
  const char axis = corrector_axis(source_offsets_, n, src_);
  // pp has no G43: its link adds the D entry's length on the axes it names.
  if (!dst_.link_axes.empty()) {
    const size_t at_digit = dst_.link_axes.find(axis);
    if (n && at_digit == std::string::npos) {
      fail(at,
           fmt::format("corrector {}'s length is on {}, which {}'s length link does not name", n, axis, w_.dialect()));
      return {};
    }
    const bool was_on = length_on_ != false;
    length_on_ = n != 0;
    if (!n) return was_on ? "&0" : std::string();
    return fmt::format("D{} &1{}", n, std::string(dst_.link_axes.size() - at_digit - 1, '0'));
  }
  auto code = target_code({{n ? Fn::LengthPlus : Fn::LengthOff}}, Scope::Modal);
  if (!code) code = code_doing_more({{n ? Fn::LengthPlus : Fn::LengthOff}}, Scope::Modal);  // GOST's G43 also ends G41
  if (!code) {
    fail(at, fmt::format("the corrector: {} has no tool length offset", w_.dialect()));
    return {};
  }
  if (n && corrector_axis(target_.offsets, n, dst_) != axis) {
    fail(at, fmt::format("corrector {}'s length is on {}, the target machine's offset {} on {}", n, axis, n,
                         corrector_axis(target_.offsets, n, dst_)));
    return {};
  }
  const char letter = reads_offset_number(dst_, 'H') ? 'H' : 'D';
  length_on_ = n != 0;
  return n ? fmt::format("{} {}{}", code->text(), letter, n) : code->text();
}

// The axis corrector (or offset) n's length applies to: its entry's, else the
// dialect's tool axis.
char Structured::corrector_axis(const std::map<int, OffsetEntry>& offsets, int n, const Conventions& c) {
  const auto it = offsets.find(n);
  return it != offsets.end() && it->second.axis ? it->second.axis : tool_axis(c);
}

// ISO's M06 as the target's blocks (pp: M05, M09, G30 Z0, then its M06): what ISO's
// does first when it changes the tool (§8.31), said where the text knows that it
// does (another tool than the one in the spindle, the spindle, the coolant and the
// plane known) and the block does not move. A target without a reference-point code
// goes there at rapid in machine coordinates (NC-110's G79, GOST's G53), to the target
// machine's reference point in the program's unit, and takes the motion code in
// force again; machine coordinates take no length offset or cutter compensation.
// Nothing when written, else why not.
std::string Structured::iso_tool_change() {
  const auto reference = target_code({{Fn::MotionReference}}, Scope::Block);
  const char axis = plane_ ? normal_axis() : 'Z';

  std::vector<std::string> retract;  // where the target has no reference-point code
  if (!reference)
    if (std::string why = machine_reference(std::string(1, axis), incremental_, retract, false); !why.empty())
      return why;
  // A block of M06 alone (and T, and an end of the program, which comes last): another
  // code would act before or after the change as the target orders them, not as ISO does.
  const bool moves = std::any_of(block_->words.begin(), block_->words.end(), [&](const ir::Word& w) {
    if (w.kind == ir::WordKind::Parameter)
      return w.address.size() == 1 && src_.axes.find(w.address[0]) != std::string::npos;
    if (w.kind != ir::WordKind::Code) return false;
    if (w.code < 0) return true;
    const std::vector<FnCall>& calls = p_->semantics.codes[static_cast<size_t>(w.code)].calls;
    return calls != std::vector<FnCall>{{Fn::ToolChange}} && calls != std::vector<FnCall>{{Fn::ProgramEnd}} &&
           calls != std::vector<FnCall>{{Fn::ProgramEndInformation}};
  });
  if (moves) return "its block has other codes or moves";
  const std::optional<bool> spindle_on = this->spindle_on();
  if (!plane_ || !spindle_on || !coolant_on_) return "the plane, the spindle or the coolant is not known here";
  if (!tool_selected_ || !tool_loaded_ || *tool_selected_ == *tool_loaded_)
    return "the tool selected and the one in the spindle are not known to differ";
  std::vector<std::string> before;
  // ISO's M06 ends the length offset: pp's link with it (its M06 keeps the link).
  if (length_on_ != false) {
    const std::string off = link_word(Fn::LengthOff);
    if (off.empty()) return "a length offset is (perhaps) on, which its M06 keeps";
    before.push_back(off);
  }
  const auto both =
      *spindle_on && *coolant_on_ ? target_code({{Fn::SpindleStop}, {Fn::CoolantOff}}, Scope::Modal) : std::nullopt;
  if (both) before.push_back(both->text());  // one code for both (GOST's M05)
  if (*spindle_on && !both) {
    auto stop = target_code({{Fn::SpindleStop}}, Scope::Modal);
    if (!stop) stop = code_doing_more({{Fn::SpindleStop}}, Scope::Modal);
    if (!stop) return "it has no code that stops the spindle alone";
    before.push_back(stop->text());
  }
  if (*coolant_on_ && !both) {
    auto off = target_code({{Fn::CoolantOff}}, Scope::Modal);
    if (!off) return "it has no code that ends the coolant";
    before.push_back(off->text());
  }
  for (const std::string& code : before) write_words({code});
  const size_t i = static_cast<size_t>(axis - 'X');
  // Before the program's first move the tool is where the machine starts: no move
  // where that is the reference point.
  if (!moved_ && target_.initial_position[i] == target_.reference_position[i]) {
  } else if (reference) {
    write_words({reference->text(), std::string(1, axis) + "0"});
  } else {
    for (const std::string& line : retract) write_words({line});
  }
  coolant_on_ = false;
  spindle_turns_ = 0;
  if (!before.empty() && before.front()[0] == '&') length_on_ = false;
  position_[i].reset();
  return {};
}

// The move at rapid to the target machine's reference point along `axes`, in machine
// coordinates, where the target has no reference-point code (NC-110's G79, GOST's
// G53), and the codes in force again after it: its lines, or why it cannot be written.
std::string Structured::machine_reference(std::string_view axes, std::optional<bool> incremental,
                                          std::vector<std::string>& lines, bool keep_length) {
  auto machine_zero = target_code({{Fn::OriginMachine}, {Fn::DistanceAbsolute}}, Scope::Block);
  const bool absolute = machine_zero.has_value();  // NC-110's G79 is absolute in its block
  if (!machine_zero) machine_zero = target_code({{Fn::WorkOffset, 0}}, Scope::Block);
  const auto rapid = target_code({{Fn::MotionRapid}}, Scope::Modal);
  const auto g90 = target_code({{Fn::DistanceAbsolute}}, Scope::Modal),
             g91 = target_code({{Fn::DistanceIncremental}}, Scope::Modal);
  std::optional<Code> restore;
  if (motion_ && *motion_ != Fn::MotionRapid) restore = target_code({{*motion_}}, Scope::Modal);
  if (!machine_zero || !rapid) return "it has no code for the reference point nor for machine coordinates";
  if (!motion_ || (*motion_ != Fn::MotionRapid && !restore)) return "the motion code in force is not known here";
  if (comp_on_ != false) return "cutter compensation is (perhaps) on, which its machine coordinates do not take";
  std::vector<std::string> off, on;
  if (length_on_ != false)
    if (std::string why = length_around(off, on, keep_length); !why.empty()) return why;
  if (!inch_) return "the unit is not known here";
  if (!absolute && (!incremental || (*incremental && (!g90 || !g91)))) return "G90 or G91 is not known here";
  lines.insert(lines.end(), off.begin(), off.end());
  std::string line = machine_zero->text() + (!absolute && *incremental ? " " + g90->text() : "") + " " + rapid->text();
  for (char axis : axes) {
    const double at = target_.reference_position[static_cast<size_t>(axis - 'X')] / (*inch_ ? 25.4 : 1.0);
    line += " " + (axis + number({axis, at, Value::Length}, block_->range));
  }
  lines.push_back(line);
  std::string again = (!absolute && *incremental ? g91->text() : "") + (restore ? " " + restore->text() : "");
  if (again.starts_with(' ')) again.erase(0, 1);
  if (!again.empty()) lines.push_back(again);
  lines.insert(lines.end(), on.begin(), on.end());
  return {};
}

// A length offset code of the source's block: on or off, and the entry in force where
// the block says it (ISO's H, GOST's D; G44's is another direction).
void Structured::length(Fn fn) {
  length_on_ = fn != Fn::LengthOff;
  std::optional<double> h;
  if (block_)  // not at power-on
    for (const ir::Word& o : block_->words)
      if (o.kind == ir::WordKind::Parameter && (o.address == "H" || o.address == "D")) h = constant_of(o.value);
  length_entry_.reset();
  if (fn == Fn::LengthOff)
    length_entry_ = 0;
  else if (fn == Fn::LengthPlus && h && *h >= 1 && *h == std::floor(*h))
    length_entry_ = static_cast<int>(*h);
}

// The length offset in force ended before a move in machine coordinates, which take
// none, and applied again after it where `keep` (ISO's G28 keeps it, its M06 does
// not): NC-110's M06 of the tool in the spindle with corrector 0, then with the
// source's entry; pp's length link; elsewhere the target's codes, the entry as D.
// Nothing when written, else why not.
std::string Structured::length_around(std::vector<std::string>& off, std::vector<std::string>& on, bool keep) {
  const std::string why = "a length offset is (perhaps) on, which its machine coordinates do not take, and ";
  if (length_on_ != true || !length_entry_) return why + "which entry is not known here";
  if (!dst_.link_axes.empty()) {  // pp: its length link, with the entry as D
    const std::string end = link_word(Fn::LengthOff), plus = link_word(Fn::LengthPlus);
    if (end.empty() || plus.empty()) return why + "its length link does not name the source's offset axes";
    off.push_back(end);
    if (keep) on.push_back(fmt::format("D{} {}", *length_entry_, plus));
    return {};
  }
  if (dst_.corrector_in_tool_word) {
    const auto m06 = target_code({{Fn::ToolChange}, {Fn::LengthPlus}}, Scope::Modal);
    if (!m06 || !tool_loaded_ || *tool_loaded_ < 1 || !tool_selected_)
      return why + "no tool is known to be in the spindle";
    off.push_back(fmt::format("T{} {}", *tool_loaded_, m06->text()));
    if (keep) on.push_back(fmt::format("T{}.{} {}", *tool_loaded_, *length_entry_, m06->text()));
    // The next tool selected since (ISO's T2 after T1 M06), selected again for its M06.
    if (*tool_selected_ != *tool_loaded_) (keep ? on : off).push_back(fmt::format("T{}", *tool_selected_));
    return {};
  }
  auto end = target_code({{Fn::LengthOff}}, Scope::Modal), plus = target_code({{Fn::LengthPlus}}, Scope::Modal);
  if (!end) end = code_doing_more({{Fn::LengthOff}}, Scope::Modal);  // GOST's G40 also ends G41: none is on
  if (!plus) plus = code_doing_more({{Fn::LengthPlus}}, Scope::Modal);
  if (!end || !plus) return why + "it has no codes for a length offset";
  off.push_back(end->text());
  if (keep) on.push_back(fmt::format("{} D{}", plus->text(), *length_entry_));  // ISO's H is the target's D, as a word
  return {};
}

// What the blocks so far leave the spindle, the coolant and the plane in, where the
// text alone says: not after a label a jump goes to, nor after a call.
// The positions the text says, in the source's new unit (`factor` from the old one;
// 0: the old one is not known, nor are they then).
void Structured::rescale(double factor) {
  if (factor == 1.0) return;
  for (auto& p : position_)
    if (p) p = factor ? std::optional(*p * factor) : std::nullopt;
  if (level_cycle_ && level_cycle_->initial)
    level_cycle_->initial = factor ? std::optional(*level_cycle_->initial * factor) : std::nullopt;
}

void Structured::state(const std::vector<FnCall>& calls) {
  // ISO's M06 ends the length offset: NC-110's M06 it becomes applies corrector 0.
  const bool iso_change =
      src_.tool_change_iso && std::find(calls.begin(), calls.end(), FnCall{Fn::ToolChange}) != calls.end();
  for (const FnCall& f : calls) {
    if (fn_group(f.fn) == FnGroup::Motion) {
      motion_ = f.fn;
      // ISO: a code of the motion group ends the canned cycle (the runtime's rule),
      // and its R is a radius again.
      if (src_.fanuc_cycles) cycle_on_ = false;
    }
    switch (f.fn) {
      case Fn::UnitsMm:
        rescale(inch_ == true ? 25.4 : inch_ ? 1.0 : 0.0);
        inch_ = false, unit_ = 1.0;
        break;
      case Fn::PolarOn:
      case Fn::PolarOff: polar_ = f.fn == Fn::PolarOn; break;
      case Fn::HelixOn:
      case Fn::HelixOff: helix_mode_ = f.fn == Fn::HelixOn; break;
      case Fn::CycleReturnInitial:
      case Fn::CycleReturnLevel: return_initial_ = f.fn == Fn::CycleReturnInitial; break;
      case Fn::FeedPerMinute:
      case Fn::FeedPerRevolution:
      case Fn::FeedInverseTime: per_minute_ = f.fn == Fn::FeedPerMinute; break;
      case Fn::UnitsInch:
        rescale(inch_ == false ? 1 / 25.4 : inch_ ? 1.0 : 0.0);
        inch_ = true, unit_ = target_inch_ ? 1.0 : 25.4;
        break;
      case Fn::Cycle: cycle_on_ = true; break;
      case Fn::WorkOffset:
        offset_selected_ = true;
        work_offset_ = f.arg;
        break;
      case Fn::CycleCancel: cycle_on_ = false; break;
      case Fn::DistanceAbsolute: incremental_ = false; break;
      case Fn::DistanceIncremental: incremental_ = true; break;
      case Fn::PlaneXY: plane_ = 'K'; break;  // the plane by its normal's centre word
      case Fn::PlaneZX: plane_ = 'J'; break;
      case Fn::PlaneYZ: plane_ = 'I'; break;
      case Fn::SpindleCw:
      case Fn::SpindleCcw: spindle_turns_ = spindle_direction_ = cycle::spindle_turns(f.fn); break;
      case Fn::SpindleStop:
      case Fn::SpindleOrient: spindle_turns_ = cycle::spindle_turns(f.fn); break;
      case Fn::CoolantMist:
      case Fn::CoolantFlood:
      case Fn::Coolant3:
      case Fn::Coolant4: coolant_on_ = true; break;
      case Fn::CoolantOff: coolant_on_ = false; break;
      case Fn::LengthPlus:
      case Fn::LengthMinus:
      case Fn::LengthOff: length(iso_change ? Fn::LengthOff : f.fn); break;
      case Fn::CompLeft:
      case Fn::CompRight: comp_on_ = true; break;
      case Fn::SpindleRpm: rpm_ = true; break;
      case Fn::SpindleConstantSurface: rpm_ = false; break;
      case Fn::CompOff: comp_on_ = false; break;
      case Fn::ProgramEnd:
      case Fn::ProgramEndInformation:
        coolant_on_ = cycle_on_ = false;
        spindle_turns_ = 0;
        program_ended_ |= in_main_ && !skip_;  // after a '/' it ends the program only with block skip off
        break;
      case Fn::ToolChange:
        // ... and first takes the tool axis to the reference point: a move the
        // target's M06 does not make.
        if (src_.m06_stops_spindle && !dst_.m06_stops_spindle && !dst_.tool_change_iso &&
            (spindle_on() != false || coolant_on_ != false))
          fail(block_->range,
               fmt::format("a tool change with the spindle or the coolant {}: {}'s M06 stops them, {}'s does not",
                           spindle_on() == true || coolant_on_ == true ? "on" : "perhaps on", p_->dialect,
                           w_.dialect()));
        if (src_.tool_change_iso && !dst_.tool_change_iso) {
          if (src_.tool_change_retract) {
            if (const std::string why = iso_tool_change(); !why.empty())
              fail(block_->range,
                   fmt::format("a tool change: {}'s M06 first takes the tool axis to the reference point, "
                               "{}'s does not, and it cannot be written before it here: {} (a machine "
                               "that changes tools in place says iso.tool_change_retract = false)",
                               p_->dialect, w_.dialect(), why));
          } else if (spindle_on() != false || coolant_on_ != false) {
            fail(block_->range,
                 fmt::format("a tool change with the spindle or the coolant {}: {}'s M06 stops them, {}'s "
                             "does not",
                             spindle_on() == true || coolant_on_ == true ? "on" : "perhaps on", p_->dialect,
                             w_.dialect()));
          }
        }
        // The target's M06 first takes the tool axis to the reference point, the
        // source's changes the tool where it stands: the same only where the tool is
        // there already, before the first move on a machine that starts there.
        if (dst_.tool_change_retract && !src_.tool_change_retract) {
          const size_t i = std::string_view(kAxisLetters).find(tool_axis(dst_));
          if (moved_ || target_.initial_position[i] != target_.reference_position[i])
            fail(block_->range,
                 fmt::format("a tool change where the tool stands: {}'s M06 first takes the tool axis to the "
                             "reference point, {}'s does not (a machine that changes tools in place says "
                             "iso.tool_change_retract = false)",
                             w_.dialect(), p_->dialect));
        }
        tool_loaded_ = tool_selected_;
        // ... which stops the spindle (a translation where the target's does not, with
        // the spindle perhaps on, is refused).
        if (src_.m06_stops_spindle || src_.tool_change_iso) spindle_turns_ = 0;
        // ISO's M06 stops the spindle and the coolant: a change while they run is
        // not the same change (flattening refuses it too).
        if (dst_.tool_change_iso && !src_.tool_change_iso && (spindle_on() != false || coolant_on_ != false))
          fail(block_->range,
               fmt::format("a tool change with the spindle or the coolant {}: {}'s M06 stops them",
                           spindle_on() == true || coolant_on_ == true ? "on" : "perhaps on", w_.dialect()));
        break;
      default: break;
    }
  }
}

void Structured::code(const ir::Word& w, std::vector<Mapped>& out) {
  if (w.code < 0) return fail(w.range, fmt::format("a code chosen at run time ({})", w.address.str()));
  const CodeDesc& desc = p_->semantics.codes[static_cast<size_t>(w.code)];
  if (desc.calls.empty()) return;  // a call, a return: the statements write them
  if (own_code(w, desc)) return;
  if (lowers_frame(desc)) return frames_.push_back(&w);  // after the block's G90/G91 and plane (translated_machine())
  if (src_.mirror_toggles != dst_.mirror_toggles &&
      std::find(desc.calls.begin(), desc.calls.end(), FnCall{Fn::Mirror}) != desc.calls.end())
    return fail(
        w.range,
        fmt::format("{}: a mirror code on a mirrored axis turns it back in one dialect, not in the other", desc.name));
  if (desc.calls == std::vector<FnCall>{{Fn::MotionParabola}} && w_.parabola_code() &&
      !target_code(desc.calls, desc.scope))
    return state(desc.calls);  // its points written as the target's parabola (parabola())
  if (desc.calls.size() == 1 && desc.calls[0].fn == Fn::OriginSelect) return origin(w, desc, out);
  if (desc.calls.size() == 1 &&
      (desc.calls[0].fn == Fn::OriginTemporary || desc.calls[0].fn == Fn::OriginIncremental) &&
      !target_code(desc.calls, desc.scope))
    return origin_shift(w, desc);
  if (desc.calls == std::vector<FnCall>{{Fn::ReferenceReturn}} && !target_code(desc.calls, desc.scope))
    return reference(w, desc, out);
  // ISO's G53 (its block in machine coordinates, absolute) into NC-110: G79.
  if (desc.calls == std::vector<FnCall>{{Fn::WorkOffset, 0}} && desc.scope == Scope::Block &&
      !target_code(desc.calls, desc.scope))
    if (auto g79 = target_code({{Fn::OriginMachine}, {Fn::DistanceAbsolute}}, Scope::Block)) {
      if (incremental_ != false || comp_on_ != false)
        return fail(
            w.range,
            fmt::format("{} under G91, or with cutter compensation, or where the text does not say they are off: "
                        "{}'s {} is absolute and takes no compensation",
                        desc.name, w_.dialect(), g79->text()));
      return out.push_back({*g79, desc.timing, g79->entry->desc.timing, {}, {}});
    }
  // ... into pp: its G53 (the machine's zero, modal) before the block, the work offset
  // in force again after it.
  if (desc.calls == std::vector<FnCall>{{Fn::WorkOffset, 0}} && desc.scope == Scope::Block &&
      !target_code(desc.calls, desc.scope))
    if (auto zero = target_code({{Fn::WorkOffset, 0}}, Scope::Modal)) {
      const auto back = work_offset_
                            ? target_code({{Fn::WorkOffset, static_cast<uint16_t>(*work_offset_)}}, Scope::Modal)
                            : std::nullopt;
      if (incremental_ != false || comp_on_ != false || !back)
        return fail(w.range,
                    fmt::format("{} under G91, or with cutter compensation, or where the work offset in force is "
                                "not known: {}'s {} is absolute, takes no compensation and stays until the work "
                                "offset is selected again",
                                desc.name, w_.dialect(), zero->text()));
      lines_before_.push_back(zero->text());
      later_lines_.push_back(back->text());
      return;
    }
  if ((desc.calls == std::vector<FnCall>{{Fn::PathDwellEnd}} ||
       desc.calls == std::vector<FnCall>{{Fn::DwellSeconds}}) &&
      !target_code(desc.calls, desc.scope))
    return timed_dwell(w, desc, out);
  // ISO's and NC-110's G41/G42 move the tool's centre off the path by their own rules
  // (cutter_path.h); the others' runs keep to the programmed path.
  if (src_.cutter != dst_.cutter && std::any_of(desc.calls.begin(), desc.calls.end(), [](const FnCall& c) {
        return c.fn == Fn::CompLeft || c.fn == Fn::CompRight;
      })) {
    if (src_.comp_path() && dst_.comp_path())
      return fail(w.range,
                  fmt::format("{}: cutter compensation turns outside corners and ends by other rules in {} than in {}",
                              desc.name, p_->dialect, w_.dialect()));
    return fail(w.range, fmt::format("{}: cutter compensation moves the tool's centre off the path in {}, not in {}",
                                     desc.name, src_.comp_path() ? p_->dialect : w_.dialect(),
                                     src_.comp_path() ? w_.dialect() : p_->dialect));
  }
  for (const FnCall& c : desc.calls)
    if (c.fn == Fn::Cycle) {
      // A target that reads the source's words has its cycles too (LinuxCNC's are
      // ISO's, words and all): the cycle of the same name.
      // Another dialect's cycle of one level, whose block drills (ISO's, GOST 20999's,
      // pp's): the target's of the same pattern, the level, peck and dwell words
      // renamed (parameter()): ISO's R Q P are pp's K I and Q in 10 ms.
      // Where the target has no cycle of the pattern, or reads its words otherwise,
      // each hole is written as its moves (moves_cycle_code()); so is any cycle
      // after one written so, whose levels ISO keeps to G80.
      const CyclePattern& pattern = p_->semantics.cycles[c.arg];
      if (level_cycle_ && level_cycle_->moves) return moves_cycle_code(w, pattern);
      if (converts_cycle_levels()) return level_cycle_code(w, pattern);
      const bool alike = !src_.cycle_two_levels && !src_.cycle_defines_only && !dst_.cycle_two_levels &&
                         !dst_.cycle_defines_only && dst_.cycle_level_word && (!src_.peck_word || dst_.peck_word) &&
                         (!src_.dwell_word || dst_.dwell_word);
      if (!reads_source_words() && !alike) return moves_cycle_code(w, pattern);
      // ISO feeds out to R, then rapids to the initial level; GOST feeds out all the way.
      if (!reads_source_words() && pattern.out == CyclePattern::Out::Feed && src_.fanuc_cycles != dst_.fanuc_cycles)
        return moves_cycle_code(w, pattern);
      // ISO's G99 returns to R; GOST's and pp's cycles return to where they began.
      if (!reads_source_words() && src_.fanuc_cycles && !dst_.fanuc_cycles &&
          !(block_has(Fn::CycleReturnInitial) || (return_initial_ == true && !block_has(Fn::CycleReturnLevel))))
        return moves_cycle_code(w, pattern);
      for (const auto& [number, entry] : w_.tables().g_codes) {
        if (entry.desc.calls.size() != 1 || entry.desc.calls[0].fn != Fn::Cycle) continue;
        const CyclePattern& has = w_.tables().cycles[entry.desc.calls[0].arg];
        const bool same = reads_source_words() ? has.name == pattern.name
                                               : has.in == pattern.in && has.dwell == pattern.dwell &&
                                                     has.bottom == pattern.bottom && has.out == pattern.out;
        if (same) {
          // GOST's cycles return to the level the tool came from: the target's G98.
          if (!reads_source_words() && !src_.fanuc_cycles)
            if (auto back = target_code({{Fn::CycleReturnInitial}}, Scope::Modal))
              out.push_back({*back, desc.timing, back->entry->desc.timing, {}, {}});
          out.push_back({{'G', number, &entry}, desc.timing, entry.desc.timing, {}, {}});
          return;
        }
      }
      return moves_cycle_code(w, pattern);
    }
  auto add = [&](const Code& c) {
    out.push_back({c, desc.timing, c.entry->desc.timing, c.entry->conflict_sets, {}});
    const auto& calls = c.entry->desc.calls;
    if (src_.corrector_in_tool_word && !dst_.corrector_in_tool_word &&
        std::find(calls.begin(), calls.end(), FnCall{Fn::LengthPlus}) != calls.end())
      out.back().later = length_offset(w.range);
  };
  if (desc.calls == std::vector<FnCall>{{Fn::Aux}}) {
    if (auto own = aux_code(desc.name)) return add(*own);
    return fail(w.range, fmt::format("{} (aux), a function of the machine's logic: {} has no {} of that kind",
                                     desc.name, w_.dialect(), desc.name));
  }
  // One code of the same functions, else one code for each.
  if (auto one = target_code(desc.calls, desc.scope)) return add(*one);
  // A code that does more, where what it does more changes nothing here (GOST's G40
  // also ends a length offset that is not on; its M05 stops a coolant that is off).
  if (auto more = code_doing_more(desc.calls, desc.scope)) return add(*more);
  // ISO's M06 ends the length offset: NC-110's M06 with the T word's corrector 0, or
  // with the corrector of a G43 H in the block after it, where nothing moves between.
  if (desc.calls == std::vector<FnCall>{{Fn::ToolChange}} && src_.tool_change_iso && dst_.corrector_in_tool_word)
    if (auto m06 = target_code({{Fn::ToolChange}, {Fn::LengthPlus}}, Scope::Modal)) {
      if (tool_selected_) folded_corrector_ = offset_after_change();
      return add(*m06);
    }
  // ... that G43 H, applied by that M06 already.
  if (desc.calls == std::vector<FnCall>{{Fn::LengthPlus}} && dst_.corrector_in_tool_word &&
      !src_.corrector_in_tool_word) {
    skip_offset_word_ = true;
    if (std::exchange(folded_g43_, false)) return void(length_on_ = true);
    if (corrector_change(true)) return;
    return fail(w.range,
                fmt::format("{}: {} applies a length offset at its tool change only (T tool.corrector M06), and "
                            "no tool is known to be in the spindle here, or its H is not a constant",
                            desc.name, w_.dialect()));
  }
  if (desc.calls == std::vector<FnCall>{{Fn::LengthOff}} && length_on_ != false && dst_.corrector_in_tool_word &&
      !src_.corrector_in_tool_word && !target_code(desc.calls, desc.scope) && corrector_change(false))
    return;
  std::vector<Code> each;
  std::string later;
  // Where it all changes nothing (GOST's G40 of a safety block: no compensation nor
  // length offset on), its first function is written still, as the source says it.
  const bool all_idle = std::all_of(desc.calls.begin(), desc.calls.end(), [&](const FnCall& c) { return idle(c); });
  for (const FnCall& c : desc.calls) {
    // What a code does more changes nothing here (GOST's M05 ends a coolant that is off).
    if (desc.calls.size() > 1 && idle(c) && !(all_idle && &c == &desc.calls.front()) &&
        std::none_of(block_->words.begin(), block_->words.end(), [&](const ir::Word& o) {
          if (&o == &w || o.kind != ir::WordKind::Code || o.code < 0) return false;
          const auto& calls = p_->semantics.codes[static_cast<size_t>(o.code)].calls;
          return std::any_of(calls.begin(), calls.end(),
                             [&](const FnCall& f) { return fn_group(f.fn) == fn_group(c.fn); });
        }))
      continue;
    auto code = target_code({c}, desc.scope);
    if (code)
      each.push_back(*code);
    else if (c.fn == Fn::LengthOff && length_on_ == false)
      continue;  // ends no offset (ISO's G49 of a safety block)
    else if ((c.fn == Fn::CycleReturnInitial || c.fn == Fn::CycleReturnLevel) && dst_.cycle_two_levels)
      state({c});  // the return level, written as the cycle's R2 (level_cycle_lines())
    else if (c.fn == Fn::CycleReturnInitial && !dst_.fanuc_cycles)
      state({c});  // GOST's cycles return so always
    // ... and ISO's G99 changes nothing where no cycle is on, or the holes are written
    // as moves, or the block has a cycle code, which code() writes so then.
    else if (c.fn == Fn::CycleReturnLevel &&
             (cycle_on_ == false || (level_cycle_ && level_cycle_->moves) || block_has(Fn::Cycle)))
      state({c});
    else if ((c.fn == Fn::UnitsMm || c.fn == Fn::UnitsInch) && !target_inch_)
      state({c});  // pp: mm always, inches written as mm (unit_)
    else if ((c.fn == Fn::PolarOn || c.fn == Fn::PolarOff) && !target_polar_)
      state({c});  // the points written in X Y Z (polar())
    else if (c.fn == Fn::SpindleRpm && !target_code({{Fn::SpindleConstantSurface}}, Scope::Modal))
      continue;  // ISO: rpm always
    else if (still_at_power_on(c))
      continue;  // GOST's M11 of a start, into NC-110 (unclamped at power-on)
    // pp has no G43: its length link adds the offset's length on the axes it names.
    else if (const std::string link = link_word(c.fn); !link.empty()) {
      extra_words_.push_back(link);
      length(c.fn);
    }
    // NC-110's M06 applies the T word's corrector: corrector 0 is no length offset.
    else if (c.fn == Fn::LengthPlus && src_.corrector_in_tool_word && corrector_ == 0 && length_on_ == false)
      continue;
    // ... in a block after the target's M06 (pp's D and link, GOST's G43).
    else if (c.fn == Fn::LengthPlus && src_.corrector_in_tool_word && !each.empty() &&
             each.back().entry->desc.calls == std::vector<FnCall>{{Fn::ToolChange}})
      later = length_offset(w.range);
    else if (path_manner(c.fn))
      drop(w.range, fmt::format("{} ({})", desc.name, fn_name(c.fn)));
    else {
      operand_words_ |= takes_operands(c.fn);  // refused with it
      return fail(w.range, fmt::format("{} ({}): {} has no code for it{}", desc.name, fn_name(c.fn), w_.dialect(),
                                       doing_more(c, desc.scope)));
    }
  }
  for (const Code& c : each) add(c);
  if (!later.empty()) {  // a block of its own after the M06's
    out.push_back(out.back());
    out.back().later = later;
  }
}

// A function that changes nothing in the state the text says.
bool Structured::idle(const FnCall& f) const {
  switch (f.fn) {
    case Fn::LengthOff: return length_on_ == false;
    case Fn::CoolantOff: return coolant_on_ == false;
    case Fn::CompOff: return comp_on_ == false;
    case Fn::SpindleRpm: return rpm_ == true;  // pp's G94 also says rpm
    default: return false;
  }
}

// Whether the next block ends the coolant, or the program, before anything moves or
// dwells (no axis word, no motion, no '/'), this block going on to it (no jump, no call): a
// CAM program's M05 before its M09 or M30, which may stop the coolant too.
bool Structured::coolant_ends_next() const {
  if (!next_ || next_->skippable || std::any_of(block_->stmts.begin(), block_->stmts.end(), [](const ir::Stmt& s) {
        return s.kind != ir::StmtKind::Machine && s.kind != ir::StmtKind::Comment;
      }))
    return false;
  for (const ir::Word& w : next_->words)
    if (w.kind == ir::WordKind::Parameter && w.address.size() == 1 && src_.axes.find(w.address[0]) != std::string::npos)
      return false;
  if (block_has_call(
          [](const FnCall& c) {
            return fn_group(c.fn) == FnGroup::Motion || c.fn == Fn::Dwell || c.fn == Fn::DwellSeconds;
          },
          next_))
    return false;
  return block_has_call(
      [](const FnCall& c) {
        return c.fn == Fn::CoolantOff || c.fn == Fn::ProgramEnd || c.fn == Fn::ProgramEndInformation;
      },
      next_);
}

// Where the target has `f` in a code that does more, which changes something here:
// ", only with coolant.off, which would change the state in force here".
std::string Structured::doing_more(const FnCall& f, Scope scope) const {
  for (const auto* table : {&w_.tables().g_codes, &w_.tables().m_codes})
    for (const auto& [number, entry] : *table) {
      const std::vector<FnCall>& has = entry.desc.calls;
      if (entry.desc.scope != scope || has.size() < 2 || std::find(has.begin(), has.end(), f) == has.end()) continue;
      std::string more;
      for (const FnCall& c : has)
        if (c != f) more += (more.empty() ? "" : "+") + std::string(fn_name(c.fn));
      return fmt::format(" alone: its {}{} also does {}, which would change the state in force here", entry.letter,
                         code_digits(number), more);
    }
  return {};
}

std::optional<Structured::Code> Structured::code_doing_more(const std::vector<FnCall>& calls, Scope scope) const {
  std::optional<Code> best;
  size_t fewest = SIZE_MAX;
  for (const auto* table : {&w_.tables().g_codes, &w_.tables().m_codes})
    for (const auto& [number, entry] : *table) {
      const std::vector<FnCall>& has = entry.desc.calls;
      if (entry.desc.scope != scope || has.size() <= calls.size() || has.size() - calls.size() >= fewest) continue;
      const bool all = std::all_of(calls.begin(), calls.end(),
                                   [&](const FnCall& c) { return std::find(has.begin(), has.end(), c) != has.end(); });
      const bool rest_idle = std::all_of(has.begin(), has.end(), [&](const FnCall& c) {
        // ... or ends the coolant just before the next block does (coolant_ends_next())
        return std::find(calls.begin(), calls.end(), c) != calls.end() || idle(c) ||
               (c.fn == Fn::CoolantOff && coolant_ends_next());
      });
      if (all && rest_idle) {
        best = Code{entry.letter, number, &entry};
        fewest = has.size() - calls.size();
      }
    }
  return best;
}

// GOST 20999's parabola (G06) into a target that writes one by its end and control
// point (LinuxCNC's G5.1, in XY: I J the control point from the start).
bool Structured::lowers_parabola() const {
  return !same_ && motion_ == Fn::MotionParabola && w_.parabola_code() &&
         !target_code({{Fn::MotionParabola}}, Scope::Modal);
}

// The parabola's control point as the runtime takes it (machine_motion.cpp, §4.4): the
// tangents' intersection I J K (coordinates under G90, or from the start, as the
// source machine says), or from two blocks without them twice the intermediate point
// less half the start and the end. The words must be constants, the start known.
void Structured::parabola(const std::array<const ir::Word*, 6>& words, const Position& start,
                          std::vector<std::string>& out) {
  const ir::Word& first = **std::find_if(words.begin(), words.end(), [](const ir::Word* w) { return w; });
  position_ = {};
  if (!incremental_ || !start[0] || !start[1] || !start[2] || plane_ != 'K')
    return fail(first.range,
                fmt::format("a parabola where the tool's position, G90/G91 or the plane is not known, or out of "
                            "the XY plane: {}'s G5.1 is in XY (G17)",
                            w_.dialect()));
  const bool tangent = words[3] || words[4] || words[5];
  // The second of two blocks goes on from the intermediate point (G91, words not written).
  const Position base = !tangent && parabola_middle_ ? *parabola_middle_ : start;
  std::array<double, 3> end{}, control{};
  for (size_t a = 0; a < 3; ++a) {
    const auto p = words[a] ? constant_of(words[a]->value) : std::optional<double>(0.0);
    const auto t = words[3 + a] ? constant_of(words[3 + a]->value) : std::optional<double>(0.0);
    if (!p || !t) return fail(first.range, "a parabola given by a parameter");
    end[a] = *incremental_ || !words[a] ? *base[a] + *p : *p;
    const bool coordinates = src_.parabola_tangent == ParabolaTangent::Coordinates && !*incremental_;
    control[a] = coordinates && words[3 + a] ? *t : *start[a] + *t;
  }
  if (!tangent && !parabola_middle_) {  // the first of two blocks: nothing moves yet
    parabola_middle_ = Position{end[0], end[1], end[2]};
    position_ = start;
    return;
  }
  if (!tangent) {
    for (size_t a = 0; a < 3; ++a) control[a] = 2 * *(*parabola_middle_)[a] - (*start[a] + end[a]) / 2;
    parabola_middle_.reset();
  }
  if (std::fabs(end[2] - *start[2]) > 1e-9 || std::fabs(control[2] - *start[2]) > 1e-9)
    return fail(first.range, fmt::format("a parabola out of the XY plane: {}'s G5.1 moves X and Y only", w_.dialect()));
  if (std::fabs(control[0] - *start[0]) < 1e-9 && std::fabs(control[1] - *start[1]) < 1e-9)
    return fail(first.range,
                fmt::format("a parabola whose control point is its start: {}'s G5.1 takes none", w_.dialect()));
  std::vector<std::string> written{"G" + w_.number({'G', *w_.parabola_code(), Value::Code})};
  for (const auto& [letter, v] : {std::pair{'X', end[0]}, std::pair{'Y', end[1]},
                                  std::pair{'I', control[0] - *start[0]}, std::pair{'J', control[1] - *start[1]}}) {
    const auto text = length(first.range, letter, letter >= 'X' && *incremental_ ? v - *start[letter - 'X'] : v);
    if (!text) return;
    written.push_back(letter + *text);
  }
  out.insert(out.begin(), written.begin(), written.end());
  position_ = Position{end[0], end[1], end[2]};
}

// ISO's G43 H (on) or G49 elsewhere than after an M06, into NC-110, whose correction
// only M06 activates (§2.7.7): the M06 of the tool in the spindle with the corrector H
// (0: none) in a block before the G43's, and the next tool selected again. False where
// the tools, the H or the block's own tool change make that another change.
bool Structured::corrector_change(bool on) {
  if (!tool_loaded_ || *tool_loaded_ < 1 || !tool_selected_) return false;  // T0 is no tool: NC-110's T is 1 on
  if (block_has(Fn::ToolChange)) return false;
  std::optional<double> h = 0.0;
  for (const ir::Word& x : block_->words)
    if (x.kind == ir::WordKind::Parameter && x.address == "H") h = on ? constant_of(x.value) : std::nullopt;
  if (!h || *h < 0 || *h != std::floor(*h) || *h > 9999 || (on && *h == 0)) return false;
  auto m06 = target_code({{Fn::ToolChange}, {Fn::LengthPlus}}, Scope::Modal);
  if (!m06) return false;
  const int corrector = static_cast<int>(*h);
  lines_before_.push_back(
      fmt::format("T{}{} {}", *tool_loaded_, corrector ? fmt::format(".{}", corrector) : "", m06->text()));
  // The next tool selected since (ISO's T2 after T1 M06), selected again for its M06.
  if (*tool_selected_ != *tool_loaded_) lines_before_.push_back(fmt::format("T{}", *tool_selected_));
  corrector_ = corrector;
  length_on_ = on;
  length_entry_ = corrector;
  return true;
}

// The length offset number of ISO's G43 H in the block after an M06, where that block
// moves nothing and no jump comes to it: NC-110's M06 applies it.
std::optional<int> Structured::offset_after_change() const {
  if (!next_ || !next_->label.empty()) return std::nullopt;
  bool g43 = false;
  std::optional<double> h;
  for (const ir::Word& w : next_->words) {
    if (w.kind == ir::WordKind::Code && w.code >= 0)
      g43 |= p_->semantics.codes[static_cast<size_t>(w.code)].calls == std::vector<FnCall>{{Fn::LengthPlus}};
    else if (w.kind == ir::WordKind::Parameter && w.address == "H")
      h = constant_of(w.value);
    else if (w.kind == ir::WordKind::Parameter && w.address.size() == 1 &&
             src_.axes.find(w.address[0]) != std::string::npos)
      return std::nullopt;
  }
  for (const ir::Stmt& s : next_->stmts)
    if (s.kind != ir::StmtKind::Machine && s.kind != ir::StmtKind::Comment) return std::nullopt;
  if (!g43 || !h || *h < 1 || *h != std::floor(*h) || *h > 9999) return std::nullopt;
  return static_cast<int>(*h);
}

// The number of each unit the program calls: ISO's O number and pp's L number are
// kept when free, anything else gets one from 9001 up; `unnamed` gets the units
// without one of their own.
std::map<std::string, int> Structured::unit_numbers(std::set<int> taken, std::vector<const ir::Unit*>* unnamed) const {
  std::map<std::string, int> numbers;
  std::vector<const ir::Unit*> rest;
  for (size_t u = 1; u < p_->units.size(); ++u) {
    const std::string& name = p_->units[u].name;
    std::optional<int> n;
    if (name.size() > 1 && name.size() <= 5 && (name[0] == 'O' || name[0] == 'L') &&
        name.find_first_not_of("0123456789", 1) == std::string::npos)
      n = std::stoi(name.substr(1));
    if (n && *n > 0 && taken.insert(*n).second)
      numbers[name] = *n;
    else
      rest.push_back(&p_->units[u]);
  }
  int next = 9000;
  for (const ir::Unit* u : rest) {
    while (taken.count(++next)) {}
    taken.insert(next);
    numbers[u->name] = next;
  }
  if (unnamed) *unnamed = std::move(rest);
  return numbers;
}

// Whether a unit, or one it calls sharing its locals, names Macro B's locals #1-#33.
bool Structured::uses_locals(const std::string& unit) const {
  std::set<std::string> seen;
  std::function<bool(const std::string&)> in_unit = [&](const std::string& name) {
    if (!seen.insert(name).second) return false;
    std::function<bool(ir::ExprId)> local = [&](ir::ExprId id) {
      if (id == ir::kNoExpr) return false;
      const ir::Expr& e = p_->exprs[id];
      if (e.op == ir::ExprOp::Var && e.space == 0 && (!p_->is_constant(e.a) || p_->exprs[e.a].number <= 33))
        return true;
      if (e.op == ir::ExprOp::Number || e.op == ir::ExprOp::String) return false;
      return local(e.a) || local(e.b);
    };
    for (const ir::Unit& u : p_->units)
      if (u.name == name)
        for (const ir::Block& b : u.blocks) {
          for (const ir::Word& w : b.words)
            if (local(w.value)) return true;
          for (const ir::Stmt& s : b.stmts)
            if (local(s.target) || local(s.value) || local(s.cond) ||
                (s.kind == ir::StmtKind::Call && s.shares_locals && in_unit(s.label)))
              return true;
        }
    return false;
  };
  return in_unit(unit);
}

// A word of a dialect the target reads as it is written. ISO's second C or R (a
// chamfer or fillet after the move) is written ",C"; an axis after G92 in a block
// that moves is the G92 value by its place.
std::string Structured::as_written(const ir::Word& w) {
  std::string address = w.address.str();
  if (address.size() == 2 && address[1] == '\'') {
    if ((address[0] == 'C' || address[0] == 'R') && !w_.tables().addresses.count(',') && !same_)
      fail(w.range, fmt::format(",{}: {} has no corners after a move", address[0], w_.dialect()));
    const bool corner = (address[0] == 'C' || address[0] == 'R') && dst_.corners;
    address = corner ? std::string{',', address[0]} : address.substr(0, 1);  // NC-110's R R: two levels
  }
  return address + value(w.value, w.address[0]);
}

// A word's value: a number (counts and numbers whole, any other whole number with
// its point: ISO reads P2 in G04 as 2 ms), a variable, or an expression in brackets.
std::string Structured::value(ir::ExprId id, char letter) {
  const ir::Expr& e = p_->exprs[id];
  if (e.op == ir::ExprOp::Number)
    return exact(e.number, std::string_view("STHDLNOM").find(letter) == std::string_view::npos);
  // X-#5: a vacant #5 leaves the word out, as X#5 does; X[-#5] would be X0.
  if (e.op == ir::ExprOp::Neg && p_->exprs[e.a].op == ir::ExprOp::Var) return "-" + expr(e.a, kSign);
  if (e.op == ir::ExprOp::Var || e.op == ir::ExprOp::ZeroIfVacant) return expr(id, kSign);
  return "[" + expr(id, kOr) + "]";
}

std::optional<Structured::Code> Structured::target_code(const std::vector<FnCall>& calls, Scope scope) const {
  // The ISO seed's M02 is its M30: an end is an end (docs/translate.md).
  if (calls.size() == 1 && calls[0].fn == Fn::ProgramEnd && !exact_code(calls, scope))
    return exact_code({{Fn::ProgramEndInformation}}, scope);
  return exact_code(calls, scope);
}

// An auxiliary function is the machine logic's own: the target's code of its name, if
// that is one too (functions alone cannot tell two of them apart).
std::optional<Structured::Code> Structured::aux_code(std::string_view name) const {
  for (const auto* table : {&w_.tables().g_codes, &w_.tables().m_codes})
    for (const auto& [number, entry] : *table)
      if (entry.desc.name == name && entry.desc.calls == std::vector<FnCall>{{Fn::Aux}})
        return Code{entry.letter, number, &entry};
  return std::nullopt;
}

// The target's code that calls exactly `calls` (in any order); of two, not the one
// its table calls another's alias.
std::optional<Structured::Code> Structured::exact_code(const std::vector<FnCall>& calls, Scope scope) const {
  // A code of a block and a modal one differ only in a state they set.
  const bool stateful =
      std::any_of(calls.begin(), calls.end(), [](const FnCall& c) { return fn_group(c.fn) != FnGroup::None; });
  std::optional<Code> best;
  bool best_alias = true;
  for (const auto* table : {&w_.tables().g_codes, &w_.tables().m_codes})
    for (const auto& [number, entry] : *table) {
      const std::vector<FnCall>& has = entry.desc.calls;
      if (has.size() != calls.size() || (stateful && entry.desc.scope != scope)) continue;
      if (!std::all_of(calls.begin(), calls.end(),
                       [&](const FnCall& c) { return std::find(has.begin(), has.end(), c) != has.end(); }))
        continue;
      const bool alias = entry.meaning.find("(as ") != std::string::npos;
      if (!best || (best_alias && !alias)) {
        best = Code{entry.letter, number, &entry};
        best_alias = alias;
      }
    }
  return best;
}

void Structured::parameter(const ir::Word& w, std::vector<std::string>& words) {
  // NC-110's T tool.corrector: the corrector after the tool's word.
  if (w.address == "T'" && dst_.corrector_in_tool_word && !words.empty() && words.back()[0] == 'T') {
    if (!(p_->is_constant(w.value) && p_->exprs[w.value].number == 0)) words.back() += "." + value(w.value, 'T');
    return;  // T6 is corrector 0
  }
  // A code's operand (pp G14's plane axes, from the block's axis words): the code says it.
  if (w.address.str()[0] == '#' || (w.derived && same_)) return;  // the same reader derives it again
  if (reads_source_words()) return words.push_back(as_written(w));
  const std::string address = w.address.str();
  const char letter = address.size() == 1 ? address[0] : 0;
  if (letter < 'A' || letter > 'Z') return fail(w.range, fmt::format("the word {}", address));
  auto write = [&](char to) { words.push_back(to + value(w.value, to)); };
  auto write_length = [&](char to) {  // in the target's unit (inches into mm)
    if (unit_ == 1.0) return write(to);
    if (const auto mm = length(w.range, to, constant_of(w.value))) words.push_back(to + *mm);
  };
  if (src_.axes.find(letter) != std::string::npos) {
    if (dst_.axes.find(letter) == std::string::npos)
      return fail(w.range, fmt::format("axis {}: the target machine has axes {}", letter, dst_.axes));
    return kAngularAxes.find(letter) == std::string_view::npos ? write_length(letter) : write(letter);
  }
  if (const char to = cycle_word(letter)) {
    if (letter == src_.dwell_word) return dwell(w, words);
    if (to == '-')
      return fail(w.range,
                  fmt::format("a repeat count {} of a canned cycle: {} makes one hole a block", letter, w_.dialect()));
    return write_length(to);  // a level or a peck
  }
  if ((letter == 'D' || letter == 'H') && reads_offset_number(src_, letter)) {
    // ISO's D and H, GOST's D: the one register of the offset in force (the runtime's),
    // the target's D; once where a block has both.
    if (!reads_offset_number(dst_, 'D') || !w_.tables().addresses.count('D') ||
        src_.tool_offset_axes != dst_.tool_offset_axes)
      return fail(w.range,
                  fmt::format("the word {} of {}: {} has no word of its meaning", address, p_->dialect, w_.dialect()));
    const std::string word = "D" + value(w.value, 'D');
    if (std::find(words.begin(), words.end(), word) != words.end()) return;
    if (std::any_of(words.begin(), words.end(), [](const std::string& o) { return o[0] == 'D'; }))
      return fail(w.range, "a D and an H of different offsets in one block: the target has one offset word");
    return words.push_back(word);
  }
  switch (letter) {
    case 'F': return write_length(letter);  // inch/min (or per revolution) into mm
    case 'S':
      if (unit_ != 1.0 && rpm_ != true)
        return fail(w.range, fmt::format("a cutting speed in feet a minute: {} has no inch mode", w_.dialect()));
      return write(letter);
    case 'T': return write(letter);
    case 'I':
    case 'J':
    case 'K':
      if (src_.helix_by_end && plane_ && *plane_ == letter) return;  // ISO's K in G17 does nothing (NC4025)
      if (src_.centre_words == CentreWords::PerAxis && (src_.helix_lead != dst_.helix_lead || dst_.helix_by_end)) {
        if (!plane_)
          return fail(w.range, fmt::format("{} where the plane is not known: a centre or a helix lead", letter));
        if (*plane_ == letter)
          return fail(w.range, fmt::format("a helix lead {}: {}", letter,
                                           dst_.helix_by_end
                                               ? fmt::format("{} gives a helix by its end point alone", w_.dialect())
                                               : std::string("the dialects give the lead in other units")));
      }
      if (src_.arc_centre != dst_.arc_centre)
        return fail(w.range, fmt::format("the arc centre {}: {} gives it from the origin, {} from the start point",
                                         letter, src_.arc_centre == ArcCentre::Absolute ? p_->dialect : w_.dialect(),
                                         src_.arc_centre == ArcCentre::Absolute ? w_.dialect() : p_->dialect));
      if (src_.centre_words != dst_.centre_words)
        return fail(w.range, fmt::format("the arc centre {}: the dialects give the centre by different words", letter));
      return write_length(letter);
    default: break;
  }
  if (letter == src_.radius_word && letter == dst_.radius_word) return write_length(letter);
  if (letter == src_.dwell_word && dst_.dwell_word) return dwell(w, words);
  fail(w.range, fmt::format("the word {} of {}: {} has no word of its meaning", address, p_->dialect, w_.dialect()));
}

// A length word's constant in the target's unit, where the source's inches become
// the target's mm (a target without an inch mode: pp); refused where it is not a
// constant or the unit is not known.
std::optional<std::string> Structured::length(SourceRange at, char to, std::optional<double> v) {
  if (!unit_)
    fail(at, unit_unknown());
  else if (!v)
    fail(at, fmt::format("a length in inches given by a parameter: {} has no inch mode", w_.dialect()));
  if (!unit_ || !v) return std::nullopt;
  return number({to, *v * *unit_, to == 'F' ? Value::Feed : Value::Length}, at);
}

// The target's length link (pp's &, decision 12) that does what `fn` does to the
// source's length offset: plus (1) or minus (2) on the source's offset axes, or off;
// nothing where the target has none or lacks one of the axes.
std::string Structured::link_word(Fn fn) const {
  // (NC-110's corrector names its own axis: not known from the text.)
  if (dst_.link_axes.empty() || src_.corrector_in_tool_word ||
      (fn != Fn::LengthPlus && fn != Fn::LengthMinus && fn != Fn::LengthOff))
    return {};
  std::string digits;
  for (char axis : dst_.link_axes)
    digits += src_.tool_offset_axes.find(axis) == std::string::npos || fn == Fn::LengthOff ? '0'
              : fn == Fn::LengthPlus                                                       ? '1'
                                                                                           : '2';
  if (std::any_of(src_.tool_offset_axes.begin(), src_.tool_offset_axes.end(),
                  [&](char a) { return dst_.link_axes.find(a) == std::string::npos; }))
    return {};
  const size_t first = digits.find_first_not_of('0');
  return "&" + (first == std::string::npos ? std::string("0") : digits.substr(first));
}

// Whether a dialect reads `letter` as the number of the tool offset in force (not
// NC-110, whose D is an axis and whose corrector is in T; not pp's H, an auxiliary
// function).
bool Structured::reads_offset_number(const Conventions& c, char letter) {
  return !c.corrector_in_tool_word && c.aux_words.find(letter) == std::string::npos && c.comp_length_word != letter &&
         c.axes.find(letter) == std::string::npos;
}

// The target's letter of a canned cycle's level, peck or dwell word, in a block where a
// cycle is on (ISO's R is a radius elsewhere, pp's K a centre); '-' for ISO's
// repeat count, which the target has not; 0 for another word.
char Structured::cycle_word(char letter) const {
  if (cycle_on_ != true || !letter) return 0;
  if (letter == src_.cycle_level_word) return dst_.cycle_level_word;
  if (letter == src_.peck_word) return dst_.peck_word;
  if (letter == src_.dwell_word) return dst_.dwell_word;
  if (src_.cycle_repeat_words.find(letter) != std::string::npos && dst_.cycle_repeat_words.empty()) return '-';
  return 0;
}

// A dwell's time in the target's unit (pp's 10 ms).
void Structured::dwell(const ir::Word& w, std::vector<std::string>& words) {
  const double factor = src_.dwell_seconds_per_unit / dst_.dwell_seconds_per_unit;
  const ir::Expr& e = p_->exprs[w.value];
  if (e.op == ir::ExprOp::Number)
    if (auto why = w_.unwritable({dst_.dwell_word, e.number * factor, Value::Seconds})) return fail(w.range, *why);
  words.push_back(dst_.dwell_word +
                  (e.op == ir::ExprOp::Number ? number({dst_.dwell_word, e.number * factor, Value::Seconds}, w.range)
                   : factor == 1              ? value(w.value, dst_.dwell_word)
                                              : fmt::format("[{}*{}]", expr(w.value, kTerm), exact(factor, false))));
}

// --- parameters and expressions -----------------------------------------------------------

void Structured::assign(const ir::Stmt& s) {
  const ir::Expr& target = p_->exprs[s.target];
  // NC-110's dwell time TMR, into a dialect without it: what its next G04 dwells
  // (timed_dwell()); nothing written.
  if (!same_ && target.op == ir::ExprOp::Sys && SysRef::unpack(target.sys).var == SysVar::DwellTime) {
    timer_ = constant_of(s.value);
    if (!timer_)
      fail(s.range, fmt::format("a dwell time TMR that is not a constant: {} gives a dwell its time in its block",
                                w_.dialect()));
    carried_number_ = std::exchange(pending_number_, std::nullopt);  // with the comments, to the next line
    carry_ = true;
    return;
  }
  std::string value = expr(s.value, kOr);
  if (!same_ && target.op == ir::ExprOp::Var && p_->is_constant(target.a)) {
    // A store rounds as the parameter's class does (NC-110 decision 8; pp R: 0.001).
    const VarType type = p_->spaces[target.space].type_of(static_cast<uint32_t>(p_->exprs[target.a].number));
    const bool whole = type == VarType::Byte || type == VarType::Integer || type == VarType::Long;
    if (type == VarType::Real) fail(s.range, "a store into a single-precision parameter");
    if (whole || type == VarType::Thousandths) {
      if (whole ? is_whole(s.value) : is_thousandths(s.value)) {
        // nothing to round (a sum of thousandths is one to within 1e-15)
      } else if (p_->is_constant(s.value)) {
        double v = p_->exprs[s.value].number;
        if (convert_value(type, 0, v))
          value = exact(v, false);
        else
          fail(s.range, "a value outside its parameter's class");
      } else {
        // Half away from zero, as the class stores (ISO's ROUND; LinuxCNC's own
        // rounds halves up: builtin()).
        ir::Expr round{ir::ExprOp::Call, Builtin::Round, 0, 0, s.value, ir::kNoExpr, s.range};
        value = whole ? builtin(round) : fmt::format("{}/1000", builtin_of_scaled(s.value, s.range));
      }
    }
  }
  // A target may write the store itself, in the block's words or lines of its own (pp).
  std::string name = var(target);
  if (first_store_) starts_stored_.insert(name);
  if (std::string text = assignment(s, name, value); !text.empty()) line(std::move(text));
}

// Whether a value is a whole number whatever the variables hold: whole constants,
// parameters of a whole class, comparisons, and sums and products of them.
bool Structured::is_whole(ir::ExprId id) const {
  const ir::Expr& e = p_->exprs[id];
  switch (e.op) {
    case ir::ExprOp::Number: return e.number == std::trunc(e.number);
    case ir::ExprOp::Var: {
      if (!p_->is_constant(e.a)) return false;
      const VarType t = p_->spaces[e.space].type_of(static_cast<uint32_t>(p_->exprs[e.a].number));
      return t == VarType::Byte || t == VarType::Integer || t == VarType::Long;
    }
    case ir::ExprOp::ZeroIfVacant:
    case ir::ExprOp::Check:
    case ir::ExprOp::Neg: return is_whole(e.a);
    case ir::ExprOp::Add:
    case ir::ExprOp::Sub:
    case ir::ExprOp::Mul: return is_whole(e.a) && is_whole(e.b);
    case ir::ExprOp::Not:
    case ir::ExprOp::Eq:
    case ir::ExprOp::Ne:
    case ir::ExprOp::Lt:
    case ir::ExprOp::Le:
    case ir::ExprOp::Gt:
    case ir::ExprOp::Ge:
    case ir::ExprOp::And:
    case ir::ExprOp::Or:
    case ir::ExprOp::Xor: return true;
    default: return false;
  }
}

// Whether a value is a sum of thousandths: constants with at most three decimals,
// parameters that hold thousandths (pp R), and sums of them.
bool Structured::is_thousandths(ir::ExprId id) const {
  const ir::Expr& e = p_->exprs[id];
  switch (e.op) {
    case ir::ExprOp::Number: return std::fabs(e.number * 1000 - std::round(e.number * 1000)) < 1e-6;
    case ir::ExprOp::Var:
      return p_->is_constant(e.a) &&
             p_->spaces[e.space].type_of(static_cast<uint32_t>(p_->exprs[e.a].number)) == VarType::Thousandths;
    case ir::ExprOp::ZeroIfVacant:
    case ir::ExprOp::Check:
    case ir::ExprOp::Neg: return is_thousandths(e.a);
    case ir::ExprOp::Add:
    case ir::ExprOp::Sub: return is_thousandths(e.a) && is_thousandths(e.b);
    default: return is_whole(id);
  }
}

std::string Structured::builtin_of_scaled(ir::ExprId value, SourceRange at) {
  // ROUND[v*1000]: the product as an operand of the rounding.
  scaled_ = value;
  ir::Expr round{ir::ExprOp::Call, Builtin::Round, 0, 0, value, ir::kNoExpr, at};
  std::string text = builtin(round);
  scaled_ = ir::kNoExpr;
  return text;
}

std::string Structured::var(const ir::Expr& e) {
  if (e.op != ir::ExprOp::Var) {
    fail(e.range, "a store into a memory or a system variable");
    return "#0";
  }
  const VarSpace& space = p_->spaces[e.space];
  const std::optional<uint32_t> at = space_base(e.space);
  if (!at) {
    fail(e.range, fmt::format("the parameters {}: {} has no place for them", space.name, w_.dialect()));
    return "#0";
  }
  const uint32_t base = *at;
  if (p_->is_constant(e.a)) {
    const uint32_t index = base + static_cast<uint32_t>(p_->exprs[e.a].number);
    if (index >= kMappedEnd || (base >= kExtraBase && base < kExtraEnd && index >= kExtraEnd))
      fail(e.range, fmt::format("{}{}: mapped to #{}, beyond the variables kept", space.name, index - base, index));
    check_variable(e, index);
    used_.insert(index);
    return fmt::format("#{}", index);
  }
  indirect_ = true;
  check_variable(e, UINT32_MAX);
  return fmt::format("#[{}{}]", base ? fmt::format("{}+", base) : "", expr(e.a, kTerm));
}

std::string Structured::expr(ir::ExprId id, int min) {
  const ir::Expr& e = p_->exprs[id];
  auto wrap = [&](int level, std::string s) { return level < min ? "[" + s + "]" : s; };
  auto binary = [&](int level, std::string_view op) {
    const int right = level == kCompare ? kSum : level + 1;
    const int left = level == kCompare ? kSum : level;
    const char* blank = std::isalpha(static_cast<unsigned char>(op[0])) ? " " : "";  // #1 GT 2, #1+2
    return wrap(level, fmt::format("{}{}{}{}{}", expr(e.a, left), blank, op, blank, expr(e.b, right)));
  };
  switch (e.op) {
    case ir::ExprOp::Number: return e.number < 0 ? wrap(kSign, exact(e.number, false)) : exact(e.number, false);
    case ir::ExprOp::Var: return var(e);
    case ir::ExprOp::ZeroIfVacant:
    case ir::ExprOp::Check: return expr(e.a, min);
    case ir::ExprOp::Neg:
      if (auto v = constant_of(id)) {  // NC-110's NEG(NEG(-2)) is -2, not ---2
        const double c = *v == 0 ? 0.0 : *v;
        return c < 0 ? wrap(kSign, exact(c, false)) : exact(c, false);
      }
      return wrap(kSign, "-" + expr(e.a, kSign));
    case ir::ExprOp::Not: return negation(e.a, min);
    case ir::ExprOp::Add: return binary(kSum, "+");
    case ir::ExprOp::Sub: return binary(kSum, "-");
    case ir::ExprOp::Mul: return binary(kTerm, "*");
    case ir::ExprOp::Div: return binary(kTerm, "/");
    case ir::ExprOp::Mod: return modulo(e, min);
    case ir::ExprOp::Eq: return binary(kCompare, "EQ");
    case ir::ExprOp::Ne: return binary(kCompare, "NE");
    case ir::ExprOp::Lt: return binary(kCompare, "LT");
    case ir::ExprOp::Le: return binary(kCompare, "LE");
    case ir::ExprOp::Gt: return binary(kCompare, "GT");
    case ir::ExprOp::Ge: return binary(kCompare, "GE");
    case ir::ExprOp::And: return binary(and_level(), "AND");
    case ir::ExprOp::Or: return binary(kOr, "OR");
    case ir::ExprOp::Xor: return binary(kOr, "XOR");
    case ir::ExprOp::Call: return builtin(e);
    case ir::ExprOp::Pow: fail(e.range, fmt::format("a power: {} has no power operator", w_.dialect())); return "0";
    default: fail(e.range, "a memory, a system variable or a text in an expression"); return "0";
  }
}

std::string Structured::modulo(const ir::Expr& e, int min) {
  const std::string text = fmt::format("{} MOD {}", expr(e.a, kTerm), expr(e.b, kSign));
  return kTerm < min ? "[" + text + "]" : text;
}

// not a: the opposite comparison when a is one (operands never vacant there: the
// order comparisons read vacant as 0, and EQ and NE are each other's opposite).
std::string Structured::negation(ir::ExprId id, int min) {
  const ir::Expr& a = p_->exprs[id];
  static const std::map<ir::ExprOp, std::string_view> kOpposite = {{ir::ExprOp::Eq, "NE"}, {ir::ExprOp::Ne, "EQ"},
                                                                   {ir::ExprOp::Lt, "GE"}, {ir::ExprOp::Le, "GT"},
                                                                   {ir::ExprOp::Gt, "LE"}, {ir::ExprOp::Ge, "LT"}};
  std::string text;
  if (auto it = kOpposite.find(a.op); it != kOpposite.end())
    text = fmt::format("{} {} {}", expr(a.a, kSum), it->second, expr(a.b, kSum));
  else if (a.op == ir::ExprOp::Not)
    text = fmt::format("[{}] NE 0", expr(a.a, kOr));
  else
    text = expr(id, kSum) + " EQ 0";
  return kCompare < min ? "[" + text + "]" : text;
}

// ISO's functions (iso decision 7), which keep the IR's meaning.
std::string Structured::builtin(const ir::Expr& e) {
  auto one = [&](std::string_view name) { return fmt::format("{}[{}]", name, operand(e.a)); };
  switch (e.builtin) {
    case Builtin::Sin: return one("SIN");
    case Builtin::Cos: return one("COS");
    case Builtin::Tan: return one("TAN");
    case Builtin::Asin: return one("ASIN");
    case Builtin::Acos: return one("ACOS");
    case Builtin::Atan: return one("ATAN");
    case Builtin::Atan2: return fmt::format("ATAN[{}]/[{}]", expr(e.a, kOr), expr(e.b, kOr));
    case Builtin::Sqrt: return one("SQRT");
    case Builtin::Abs: return one("ABS");
    case Builtin::Trunc: return one("FIX");
    case Builtin::Round: return one("ROUND");
    case Builtin::RoundTo: return one("ROUND");  // ISO's own ROUND of an address value
    case Builtin::Away: return one("FUP");
    case Builtin::Exp: return one("EXP");
    case Builtin::Ln: return one("LN");
    default:
      fail(e.range, fmt::format("the function {}: {} has none like it", builtin_info(e.builtin).name, w_.dialect()));
      return "0";
  }
}

// A function's operand: the value, or the value times 1000 (a store into pp's R).
std::string Structured::operand(ir::ExprId a) {
  if (a == scaled_) return expr(a, kTerm) + "*1000";
  return expr(a, kOr);
}

// The target shows the operator no values: the display becomes a comment that says
// what it showed, with a warning.
void Structured::display(const ir::Stmt& s) {
  std::string text = "DIS";
  for (const ir::DisplayItem& item : s.items) {
    const ir::Expr& e = p_->exprs[item.value];
    text += ' ';
    text += e.op == ir::ExprOp::String ? "\"" + p_->texts[e.text] + "\"" : expr(item.value, kOr);
  }
  comment(text);
  drop(s.range, "a display to the operator (DIS), written as a comment");
}

// --- the start ------------------------------------------------------------------------------

// The source's power-on state, in the target's codes (those it has), then its
// parameters at 0: the target's may start vacant (Macro B) or as a file left them.
void Structured::start() {
  std::vector<Code> g, m;
  std::vector<FnCall> modes = power_on();
  start_modes(modes);
  // A mode the target machine starts in, or one the program's leading blocks set
  // before it matters, is not written: a second translation adds nothing.
  for (const FnCall& c : modes)
    if (auto code = target_code({c}, Scope::Modal);
        code && start_needs(c) &&
        !(motion_code_moves() && fn_group(c.fn) == FnGroup::Motion && c.fn != Fn::CycleCancel)) {
      auto& list = code->letter == 'G' ? g : m;
      if (std::none_of(list.begin(), list.end(), [&](const Code& o) { return o.number == code->number; }))
        list.push_back(*code);
    }
  for (const auto& b : together(g)) {
    std::string text;
    for (const Code& c : b) text += (text.empty() ? "" : " ") + c.text();
    w_.line(text);
  }
  for (const Code& c : m) w_.line(c.text());
  // A machine that starts with a feed (iso.initial_feed) where the target's starts
  // with another.
  if (src_.initial_feed > 0 && dst_.initial_feed != src_.initial_feed && !lead_feed_)
    w_.line("F" + w_.number({'F', src_.initial_feed, Value::Feed}));
  start_offset();
  start_parameters();
}

void Structured::start_parameters() {
  if (p_->dialect == "iso") return;  // ISO's variables start vacant in both
  if (indirect_ && mapped_space_ >= 0)
    zero_all(kMappedBase, std::min(p_->spaces[static_cast<size_t>(mapped_space_)].size, kMappedEnd - kMappedBase));
  for (uint32_t v : used_)
    if ((!indirect_ || v < kMappedBase) && !starts_stored_.count(fmt::format("#{}", v)))
      w_.line(fmt::format("#{}=0", v));
}

// G codes in as few blocks as the target takes them: two of one group, or a pair
// its tables forbid (NC-110 Table 2.4), in blocks of their own.
std::vector<std::vector<Structured::Code>> Structured::together(const std::vector<Code>& g) const {
  auto apart = [&](const Code& a, const Code& b) {
    return stdlib::has_pair(w_.tables().incompatible, a.number, b.number) ||
           (a.entry->group != "-" && a.entry->group == b.entry->group);
  };
  std::vector<std::vector<Code>> blocks;
  for (const Code& c : g) {
    auto it = std::find_if(blocks.begin(), blocks.end(), [&](const std::vector<Code>& b) {
      return std::none_of(b.begin(), b.end(), [&](const Code& o) { return apart(o, c); });
    });
    if (it == blocks.end())
      blocks.push_back({c});
    else
      it->push_back(c);
  }
  return blocks;
}

// A source that starts without a work offset (GOST, pp G53) on a target that starts
// in one and has no code to leave it: the same only where the target machine's
// offset is zero.
// The work offset the target powers on in (its tables' power-on codes); 0: none.
int Structured::start_work_offset() const {
  int n = 0;
  if (auto it = w_.tables().power_on.find("default"); it != w_.tables().power_on.end())
    for (const std::string& token : it->second)
      if (auto code = w_.tables().g_codes.find(token.size() > 1 && token[0] == 'G' ? std::atoi(token.c_str() + 1) : -1);
          code != w_.tables().g_codes.end())
        for (const FnCall& c : code->second.desc.calls)
          if (c.fn == Fn::WorkOffset) n = c.arg;
  return n;
}

void Structured::start_offset() {
  auto offset_of = [](const std::vector<FnCall>& calls) -> std::optional<int> {
    for (const FnCall& c : calls)
      if (c.fn == Fn::WorkOffset) return c.arg;
    return std::nullopt;
  };
  const int source = offset_of(power_on()).value_or(0), target = start_work_offset();
  if (source == target || target_code({{Fn::WorkOffset, static_cast<uint16_t>(source)}}, Scope::Modal)) return;
  if (!moved_before_offset_) return;  // the program selects its offset before it moves
  const auto it = target_.work_offsets.find(target);
  if (it == target_.work_offsets.end() ||
      std::all_of(it->second.values.begin(), it->second.values.end(), [](double v) { return v == 0; }))
    return;
  fail(p_->units.front().range,
       fmt::format("the start without a work offset: {} starts in work offset {}, which the target machine sets, and "
                   "has no code for none (give --target-machine a profile whose offset {} is zero)",
                   w_.dialect(), target, target));
}

// --- the entry -----------------------------------------------------------------------------

namespace {

// The streamed blocks' text, written to a scratch file as it grows.
class Streamer final : public StreamObserver {
 public:
  Streamer(Structured& t, Writer& w, std::FILE* file) : spill(w, file), t_(t) {}
  void streamed(const ir::Program& program, const ir::Block& block, const ir::Block* next) override {
    t_.stream(program, block, next);
    spill.grown();
  }
  bool streams(const ir::Program& program, const ir::Block& block) const override {
    return !t_.frame_codes(program, block);
  }
  bool looks_ahead(const ir::Program& program, const ir::Block& block) const override {
    return t_.looks_ahead(program, block);
  }

  Spill spill;

 private:
  Structured& t_;
};

}  // namespace

bool structured(Session& s, uint32_t file, const std::string& dialect, const Request& request, std::FILE* out) {
  const uint32_t errors = s.diags.error_count();
  auto writer = make_writer(request.to, *request.target_profile, s.diags);
  if (!writer) return false;
  const MachineConfig target = stdlib::load_machine_config(*request.target_profile, s.diags);
  if (s.diags.error_count() != errors) return false;
  uint32_t e_count = 1000;  // NC-110's E parameters (nc110.e_count, checked by the target's reader)
  if (auto n = request.target_profile->number("nc110.e_count", s.diags); n && *n >= 64 && *n <= 65536)
    e_count = static_cast<uint32_t>(*n);
  auto make = [&]() -> std::unique_ptr<Structured> {
    if (request.to == "linuxcnc") return make_ngc_structured(dialect, *writer, target);
    if (request.to == "nc110") return make_nc110_structured(dialect, *writer, target, e_count);
    if (request.to == "gost") return make_gost_structured(dialect, *writer, target);
    if (request.to == "pp") return make_pp_structured(dialect, *writer, target);
    return make_iso_structured(dialect, *writer, target);
  };
  auto configured = [&] {
    auto t = make();
    t->set_power_on(power_on_functions(s, dialect));
    if (request.to != "linuxcnc") t->set_target_power_on(power_on_functions(s, request.to, *request.target_profile));
    if (s.profile) t->set_source_offsets(stdlib::load_machine_config(*s.profile, s.diags).offsets);
    return t;
  };
  auto translation = configured();
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> streamed(std::tmpfile(), &std::fclose);
  if (!streamed) {
    s.diags.report(DiagId::FileUnwritable, {}, std::string("a temporary file"), std::strerror(errno));
    return false;
  }
  Streamer streamer(*translation, *writer, streamed.get());
  ir::Program rest;
  {
    auto module = compile_source(s, file, dialect, streamer, rest);
    if (!module || s.diags.error_count() != errors) return false;
    if (!s.diags.limit_reached()) dry_run(s, *module, request.run);
    if (s.diags.error_count() != errors) return false;
  }
  streamer.spill.flush();
  Header header = request.header;
  if (!rest.units.empty()) {
    header.title = rest.units.front().title;
    const std::string& name = rest.units.front().name;  // GOST's and pp's "%12"
    if (name.size() > 1 && name.size() <= 9 && name[0] == '%' &&
        name.find_first_not_of("0123456789", 1) == std::string::npos)
      header.number = name.substr(1);
  }
  translation->translate(rest, header);
  // LinuxCNC: a loop back into the streamed blocks; a frame lowered after them.
  if (translation->needs_whole()) {
    auto whole = read_whole(s, file, dialect);
    if (!whole) return false;
    writer = make_writer(request.to, *request.target_profile, s.diags);  // afresh: it numbers blocks
    if (!writer) return false;
    translation = configured();
    translation->translate(*whole, header);
    streamed.reset();
  }
  // Each construct once, at its first place, with the count of the others.
  std::map<std::string, std::pair<const Problem*, size_t>> seen;
  std::vector<std::string> order;
  for (const Problem& p : translation->problems) {
    auto [it, fresh] = seen.try_emplace(p.what, &p, 0);
    if (fresh)
      order.push_back(p.what);
    else
      ++it->second.second;
  }
  bool refused = false;
  for (const std::string& what : order) {
    const auto& [p, more] = seen.at(what);
    const std::string text = what + (more ? fmt::format(" (and in {} more places)", more) : "");
    if (p->kind == Finding::Rounded)
      s.diags.report(DiagId::TranslateRounded, p->at, writer->dialect(),
                     static_cast<int>(std::lround(-std::log10(writer->resolution()))), rounded_these("length", more));
    else if (p->kind == Finding::RoundedRate)
      s.diags.report(DiagId::TranslateRoundedRate, p->at, writer->dialect(), what, writer->rate_decimals(what[0]),
                     rounded_these("value", more));
    else if (p->kind == Finding::Dropped)
      s.diags.report(DiagId::TranslateDropped, p->at, writer->dialect(), text);
    else
      s.diags.report(DiagId::TranslateRefused, p->at, writer->dialect(), text);
    refused |= p->kind == Finding::Refused;
  }
  if (refused || streamer.spill.failed) return false;
  return translation->emit(streamed.get(), out) && s.diags.error_count() == errors;
}

}  // namespace ncc::translate
