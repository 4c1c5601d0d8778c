#include "structured.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>

#include "runtime/machine_config.h"
#include "stdlib/profile.h"
#include "support/numbers.h"

namespace ncc::translate {
namespace {

// The mapping of parameters (docs/translate.md, "Structured translation"): a
// dialect's numbered parameters (NC-110 E, pp R) become Macro B's common variables
// from #500 on, which keep their values for the whole run as E and R do; ISO's own
// variables stay where they are. Repeat loops count in #199 downwards.
constexpr uint32_t kMappedBase = 500;
constexpr uint32_t kMappedEnd = 1000;
constexpr uint32_t kFirstCounter = 199, kLastCounter = 100;
constexpr int kFreshNumbers = 9000;  // block numbers and program numbers the translation adds

// ISO's expression levels, loosest first (iso decision 6).
enum Level : int { kOr = 1, kAnd, kCompare, kSum, kTerm, kSign, kPrimary };

// How the machine runs the path, not where it goes: a target without the code is
// warned of, as flattening does.
bool path_manner(Fn fn) {
  switch (fn) {
    case Fn::DynamicsCornerSlowdown: case Fn::DynamicsContinuous: case Fn::DynamicsPointToPoint:
    case Fn::DynamicsSmooth: case Fn::PathAccelerate: case Fn::PathDecelerate: case Fn::OverrideEnable:
    case Fn::OverrideDisable: return true;
    default: return false;
  }
}

// A number as a double reads it back, in fixed notation (ISO reads no exponent).
std::string exact(double v, bool point) {
  if (v == 0) v = 0;  // never "-0"
  std::string s;
  for (int decimals = 0; decimals <= 24; ++decimals) {
    s = fmt::format("{:.{}f}", v, decimals);
    if (std::strtod(s.c_str(), nullptr) == v) break;
  }
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.' && !point) s.pop_back();
  } else if (point) {
    s += '.';
  }
  return s;
}

// What the target cannot say (refused), or says otherwise than the source without
// changing the path (dropped: a warning).
struct Problem {
  SourceRange at;
  std::string what;
  bool dropped = false;
};

class Structured {
 public:
  Structured(const ir::Program& program, Writer& writer, const MachineConfig& target_machine)
      : p_(program), w_(writer), target_(target_machine), src_(program.semantics.conventions), dst_(writer.conventions()),
        same_(program.dialect == writer.dialect()) {
    for (size_t i = 0; i < p_.spaces.size() && mapped_space_ < 0; ++i)
      if (!p_.spaces[i].memory && p_.spaces[i].size > 0) mapped_space_ = static_cast<int>(i);
  }

  // The whole program: the body first, so that the start can set what it uses.
  void write(const Header& header) {
    name_programs();
    for (size_t u = 0; u < p_.units.size(); ++u) unit(p_.units[u], u == 0);
    const std::string body = w_.take();
    w_.begin(header);
    if (!same_) start();
    w_.append(body);
    w_.end();
  }

  std::vector<Problem> problems;

 private:
  // --- programs and block numbers ---------------------------------------------

  // The O number of each unit the program calls: ISO keeps its own; a pp L number
  // is kept when it is free; anything else gets a number from 9001 up.
  void name_programs() {
    std::set<int> taken{1};  // the main program is O0001 (the writer's)
    std::vector<const ir::Unit*> unnamed;
    for (size_t u = 1; u < p_.units.size(); ++u) {
      const std::string& name = p_.units[u].name;
      std::optional<int> n;
      if (name.size() > 1 && (name[0] == 'O' || name[0] == 'L') && name.size() <= 5 &&
          name.find_first_not_of("0123456789", 1) == std::string::npos)
        n = std::stoi(name.substr(1));
      if (n && *n > 0 && taken.insert(*n).second) programs_[name] = *n;
      else unnamed.push_back(&p_.units[u]);
    }
    int next = kFreshNumbers;
    for (const ir::Unit* u : unnamed) {
      while (taken.count(++next)) {}
      taken.insert(next);
      programs_[u->name] = next;
      if (same_) fail(u->range, fmt::format("program {}: O0001 is the translation's main program", u->name));
    }
  }

  // The block numbers of a unit: a jump target keeps its own number when no other
  // block has it, else gets one from 9001 up; other blocks keep theirs.
  void number_blocks(const ir::Unit& unit) {
    labels_.clear();
    numbers_.clear();
    std::set<std::string> targets;
    for (const ir::Block& b : unit.blocks)
      for (const ir::Stmt& s : b.stmts)
        if (s.kind == ir::StmtKind::Jump && !s.label.empty()) targets.insert(s.label);
    for (const ir::Unit& u : p_.units)  // M97: a block of this unit
      for (const ir::Block& b : u.blocks)
        for (const ir::Stmt& s : b.stmts)
          if (s.kind == ir::StmtKind::Call && s.label.starts_with(unit.name + "/"))
            targets.insert(s.label.substr(unit.name.size() + 1));
    std::map<uint32_t, int> count;
    for (const ir::Block& b : unit.blocks)
      if (b.number) ++count[*b.number];
    for (const ir::Block& b : unit.blocks) {
      if (b.label.empty() || !targets.count(b.label) || labels_.count(b.label)) continue;
      if (b.number && count[*b.number] == 1 && b.label == fmt::format("N{}", *b.number)) labels_[b.label] = static_cast<int>(*b.number);
      else labels_[b.label] = fresh_number(count);
    }
    std::set<std::string> placed;  // a label used twice names its first block (lowering)
    for (const ir::Block& b : unit.blocks)
      if (!b.label.empty() && labels_.count(b.label) && placed.insert(b.label).second) numbers_[&b] = labels_.at(b.label);
    for (const ir::Block& b : unit.blocks)
      if (b.number && !numbers_.count(&b)) numbers_[&b] = static_cast<int>(*b.number);
    for (const auto& [number, n] : count) taken_numbers_.insert(static_cast<int>(number));
    for (const auto& [label, n] : labels_) taken_numbers_.insert(n);
  }

  int fresh_number(const std::map<uint32_t, int>& count) {
    while (count.count(static_cast<uint32_t>(++next_number_)) || taken_numbers_.count(next_number_)) {}
    taken_numbers_.insert(next_number_);
    return next_number_;
  }
  int fresh_number() { return fresh_number({}); }

  // --- units and blocks -----------------------------------------------------------

  void unit(const ir::Unit& u, bool main) {
    if (u.kind == ir::UnitKind::Process) return fail(u.range, "a process program (EXE)");
    if (!main && u.kind == ir::UnitKind::Program)  // GOST 20999 §1.8
      return fail(u.range, fmt::format("a second program on the medium, run after the first ends: {} runs one", w_.dialect()));
    next_number_ = kFreshNumbers;
    taken_numbers_.clear();
    number_blocks(u);
    if (!main) {
      forget();
      w_.append("\n");
      line(fmt::format("O{:04}", programs_.at(u.name)));
      if (!u.title.empty()) w_.comment(u.title);
    }
    if (main)
      for (uint16_t i : p_.semantics.power_on) state(p_.semantics.codes[i].calls);
    bool returned = false;
    for (const ir::Block& b : u.blocks) returned = block(b);
    if (pending_head_) w_.line(fmt::format("N{}", *pending_head_));  // a loop with an empty body
    pending_head_.reset();
    if (main && p_.units.size() > 1 && !ends_program(u)) line("M30");
    if (!main && !returned) line("M99");
  }

  // Whether a unit's last block ends the program or leaves it (what stands after it
  // is the subprograms' place in ISO).
  bool ends_program(const ir::Unit& u) const {
    if (u.blocks.empty()) return false;
    for (const ir::Stmt& s : u.blocks.back().stmts)
      if (s.kind == ir::StmtKind::Return || (s.kind == ir::StmtKind::Jump && s.cond == ir::kNoExpr)) return true;
    for (const ir::Word& w : u.blocks.back().words)
      if (w.kind == ir::WordKind::Code && w.code >= 0)
        for (const FnCall& c : p_.semantics.codes[static_cast<size_t>(w.code)].calls)
          if (c.fn == Fn::ProgramEnd || c.fn == Fn::ProgramEndInformation) return true;
    return false;
  }

  // One source block: its lines, the first with the block number. True when its
  // last statement returns.
  bool block(const ir::Block& b) {
    block_ = &b;
    words_written_ = false;
    if (!b.label.empty() && labels_.count(b.label)) forget();
    pending_number_ = numbers_.count(&b) ? std::optional<int>(numbers_.at(&b)) : std::nullopt;
    if (pending_head_) {  // a loop's body starts here
      if (pending_number_) w_.line(fmt::format("N{}", *pending_head_));
      else pending_number_ = pending_head_;
      pending_head_.reset();
    }
    skip_ = b.skippable;
    if (std::any_of(b.words.begin(), b.words.end(), [](const ir::Word& w) { return w.optional; }))
      fail(b.range, "a '/' in the middle of a block");
    // Operator text (GOST's comments) or the block's comments, on its first line.
    bool has_comment_stmt = false;
    for (const ir::Stmt& s : b.stmts) has_comment_stmt |= s.kind == ir::StmtKind::Comment;
    if (!has_comment_stmt)
      for (const std::string& c : b.comments) comment(c);
    bool returned = false;
    for (const ir::Stmt& s : b.stmts) {
      returned = s.kind == ir::StmtKind::Return;
      if (s.cond != ir::kNoExpr && s.kind != ir::StmtKind::Jump) {
        // Only when the condition holds: IF THEN.
        then_ = fmt::format("IF [{}] THEN ", expr(s.cond, kOr));
        statement(s);
        if (!then_.empty()) fail(s.range, "a statement under a condition");
        then_.clear();
      } else {
        statement(s);
      }
    }
    if (pending_number_ || !comments_.empty()) line("");  // a block with nothing else
    return returned;
  }

  void statement(const ir::Stmt& s) {
    switch (s.kind) {
      case ir::StmtKind::Comment: return comment(s.label);
      case ir::StmtKind::Machine: return machine(s);
      case ir::StmtKind::Assign: return assign(s);
      case ir::StmtKind::Jump: return jump(s);
      case ir::StmtKind::RepeatBegin: return repeat_begin(s);
      case ir::StmtKind::RepeatEnd: return repeat_end(s);
      case ir::StmtKind::Call: return call(s);
      case ir::StmtKind::Return:
        if (same_) return machine(s);  // the same dialect's M99 is a word of the block
        return line("M99");
      case ir::StmtKind::CallRange: return fail(s.range, "a call of a range of blocks (EPP)");
      case ir::StmtKind::Display: return display(s);
      case ir::StmtKind::Asset: return fail(s.range, "an ASSET file statement");
      case ir::StmtKind::Input: return fail(s.range, "operator input (INP)");
      case ir::StmtKind::ScreenSwitch: case ir::StmtKind::ScreenDefine: case ir::StmtKind::ScreenShow:
      case ir::StmtKind::ScreenShowWith: return fail(s.range, "the user screen");
      case ir::StmtKind::ProcessStart: case ir::StmtKind::ProcessRelease: case ir::StmtKind::ProcessWait:
      case ir::StmtKind::ProcessWaitUntil: case ir::StmtKind::ProcessSignal: return fail(s.range, "processes");
    }
  }

  // A line of the target, after the block number still to be written.
  void line(std::string text) {
    std::string head = skip_ ? "/" : "";
    if (pending_number_) head += fmt::format("N{}", *pending_number_) + (text.empty() ? "" : " ");
    pending_number_.reset();
    skip_ = false;
    text = head + std::exchange(then_, {}) + text;
    for (const std::string& c : comments_) {
      if (!text.empty()) text += ' ';
      text += '(';
      for (char ch : c) text += ch == '(' ? '[' : ch == ')' ? ']' : ch;  // a comment does not nest
      text += ')';
    }
    comments_.clear();
    w_.line(text);
  }

  void comment(std::string_view text) { comments_.emplace_back(text); }

  // --- the machine action -----------------------------------------------------------

  // The block's words: its codes and parameters, and in the same dialect its call
  // words too (M98 P L, G65 A..Z), once for all the statements they make.
  void machine(const ir::Stmt&) {
    if (std::exchange(words_written_, true)) return;
    if (!same_) return translated_machine();
    std::vector<std::string> words;
    for (const ir::Word& w : block_->words) {
      switch (w.kind) {
        case ir::WordKind::Code: words.push_back(w.code < 0 ? as_written(w) : p_.semantics.codes[static_cast<size_t>(w.code)].name); break;
        case ir::WordKind::Parameter: case ir::WordKind::Argument: words.push_back(as_written(w)); break;
        case ir::WordKind::Control: words.push_back(w.address + value(w.value, 'N')); break;  // M98 P1000, not P1000.
        default: break;
      }
    }
    write_words(words);
  }

  void write_words(const std::vector<std::string>& words) {
    if (words.empty()) return;
    std::string text;
    for (const std::string& word : words) text += (text.empty() ? "" : " ") + word;
    line(text);
  }

  // A block of another dialect. An M code acts before or after the block's motion
  // (GOST 20999 Table 7): where the target's acts at the other time, it gets a block
  // of its own before or after the motion, with the S and T words it needs; so do M
  // codes the target does not take in one block (ISO M03 and M06).
  void translated_machine() {
    std::vector<Mapped> codes;
    std::vector<std::string> params;
    bool moves = false;
    if (src_.corrector_in_tool_word)  // before M06 of the same block
      for (const ir::Word& w : block_->words)
        if (w.kind == ir::WordKind::Parameter && w.address[0] == 'T') corrector(w);
    for (const ir::Word& w : block_->words)
      if (w.kind == ir::WordKind::Code) code(w, codes);
    for (const Mapped& c : codes) state(c.code.entry->desc.calls);
    for (const ir::Word& w : block_->words)
      if (w.kind == ir::WordKind::Parameter) {
        moves |= w.address.size() == 1 && src_.axes.find(w.address[0]) != std::string::npos;
        if (w.address != "T'") parameter(w, params);
      }
    std::vector<std::string> before, main, after, later;
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
      const bool apart = c.code.letter == 'M' && ((moves && c.wants != c.has) || conflict(c));
      any_before |= apart && c.wants == Timing::Before;
      any_after |= apart && c.wants == Timing::After;
    }
    // G codes, then the other words, then M codes (ISO's usual order); M codes of one
    // time together, in the source's order.
    std::vector<std::string> m;
    for (const Mapped& c : codes) {
      if (!c.later.empty()) later.push_back(c.later);
      else if (c.code.letter == 'M' && any_before && c.wants == Timing::Before) before.push_back(c.code.text());
      else if (c.code.letter == 'M' && any_after && c.wants == Timing::After) after.push_back(c.code.text());
      else (c.code.letter == 'M' ? m : main).push_back(c.code.text());
    }
    main.insert(main.end(), params.begin(), params.end());
    main.insert(main.end(), m.begin(), m.end());
    write_words(before);
    write_words(main);
    write_words(after);
    write_words(later);
  }

  struct Code {
    char letter;
    int number;
    const stdlib::CodeEntry* entry;
    std::string text() const { return fmt::format("{}{:02}", letter, number); }
  };
  // A target code for a source code: when it acts, and when the source's acts.
  struct Mapped {
    Code code;
    Timing wants, has;
    std::vector<std::string> sets;  // the M conflict sets (stdlib tables)
    std::string later;  // written after the block's other codes instead (G43 H after M06)
  };

  // NC-110's T tool.corrector: the corrector takes effect at M06 (nc110 decision
  // 11). ISO's M06 ends the length offset: G43 H<corrector> after it, G49 for none.
  void corrector(const ir::Word& w) {
    if (w.address == "T") {
      corrector_ = 0;  // T6 is corrector 0 unless T' follows
      return;
    }
    if (!p_.is_constant(w.value)) {
      corrector_.reset();
      return fail(w.range, "a corrector given by a parameter");
    }
    corrector_ = static_cast<int>(p_.exprs[w.value].number);
  }
  std::string length_offset(SourceRange at) {
    if (!corrector_) {
      fail(at, "M06 with a corrector that is not known here");
      return {};
    }
    auto code = target_code({{*corrector_ ? Fn::LengthPlus : Fn::LengthOff}}, Scope::Modal);
    if (!code) {
      fail(at, fmt::format("the corrector: {} has no tool length offset", w_.dialect()));
      return {};
    }
    return *corrector_ ? fmt::format("{} H{}", code->text(), *corrector_) : code->text();
  }

  void forget() {
    spindle_on_ = coolant_on_ = std::nullopt;
    corrector_.reset();
    plane_.reset();
  }

  // What the blocks so far leave the spindle, the coolant and the plane in, where
  // the text alone says: not after a label a jump goes to, nor after a call.
  void state(const std::vector<FnCall>& calls) {
    for (const FnCall& f : calls) {
      switch (f.fn) {
        case Fn::PlaneXY: plane_ = 'K'; break;  // the plane by its normal's centre word
        case Fn::PlaneZX: plane_ = 'J'; break;
        case Fn::PlaneYZ: plane_ = 'I'; break;
        case Fn::SpindleCw: case Fn::SpindleCcw: spindle_on_ = true; break;
        case Fn::SpindleStop: case Fn::SpindleOrient: spindle_on_ = false; break;
        case Fn::CoolantMist: case Fn::CoolantFlood: case Fn::Coolant3: case Fn::Coolant4: coolant_on_ = true; break;
        case Fn::CoolantOff: coolant_on_ = false; break;
        case Fn::ProgramEnd: case Fn::ProgramEndInformation: spindle_on_ = coolant_on_ = false; break;
        case Fn::ToolChange:
          // ISO's M06 stops the spindle and the coolant: a change while they run is
          // not the same change (flattening refuses it too).
          if (dst_.tool_change_iso && !src_.tool_change_iso && (spindle_on_ != false || coolant_on_ != false))
            fail(block_->range, fmt::format("a tool change with the spindle or the coolant {}: {}'s M06 stops them",
                                            spindle_on_ == true || coolant_on_ == true ? "on" : "perhaps on", w_.dialect()));
          break;
        default: break;
      }
    }
  }

  void code(const ir::Word& w, std::vector<Mapped>& out) {
    if (w.code < 0) return fail(w.range, fmt::format("a code chosen at run time ({})", w.address.str()));
    const CodeDesc& desc = p_.semantics.codes[static_cast<size_t>(w.code)];
    if (desc.calls.empty()) return;  // a call, a return: the statements write them
    for (const FnCall& c : desc.calls)
      if (c.fn == Fn::Cycle)
        return fail(w.range, fmt::format("canned cycle {}: cycles are translated between dialects by --flatten only",
                                         desc.name));
    auto add = [&](const Code& c) {
      out.push_back({c, desc.timing, c.entry->desc.timing, c.entry->conflict_sets, {}});
      if (src_.corrector_in_tool_word && std::find(c.entry->desc.calls.begin(), c.entry->desc.calls.end(), FnCall{Fn::LengthPlus}) != c.entry->desc.calls.end())
        out.back().later = length_offset(w.range);
    };
    // One code of the same functions, else one code for each.
    if (auto one = target_code(desc.calls, desc.scope)) return add(*one);
    std::vector<Code> each;
    for (const FnCall& c : desc.calls) {
      auto code = target_code({c}, desc.scope);
      if (code) each.push_back(*code);
      else if (path_manner(c.fn)) drop(w.range, fmt::format("{} ({})", desc.name, fn_name(c.fn)));
      else return fail(w.range, fmt::format("{} ({}): {} has no code for it", desc.name, fn_name(c.fn), w_.dialect()));
    }
    for (const Code& c : each) add(c);
  }

  // A word of the same dialect, as the IR holds it.
  // ISO's second C or R (a chamfer or fillet after the move) is written ",C"; an
  // axis after G92 in a block that moves is the G92 value by its place.
  std::string as_written(const ir::Word& w) {
    std::string address = w.address.str();
    if (address.size() == 2 && address[1] == '\'')
      address = address[0] == 'C' || address[0] == 'R' ? std::string{',', address[0]} : address.substr(0, 1);
    return address + value(w.value, w.address[0]);
  }

  // A word's value: a number with its point (ISO reads some whole numbers as
  // thousandths), a variable, or an expression in brackets.
  std::string value(ir::ExprId id, char letter) {
    const ir::Expr& e = p_.exprs[id];
    std::string text;
    // Counts and numbers are whole; any other whole number is written with its point
    // (ISO reads P2 in G04 as 2 ms).
    if (e.op == ir::ExprOp::Number) text = exact(e.number, std::string_view("STHDLNOM").find(letter) == std::string_view::npos);
    // X-#5: a vacant #5 leaves the word out, as X#5 does; X[-#5] would be X0.
    else if (e.op == ir::ExprOp::Neg && p_.exprs[e.a].op == ir::ExprOp::Var) text = "-" + expr(e.a, kSign);
    else if (e.op == ir::ExprOp::Var || e.op == ir::ExprOp::ZeroIfVacant) text = expr(id, kSign);
    else text = "[" + expr(id, kOr) + "]";
    return text;
  }

  void code(const ir::Word& w, std::vector<std::string>& words) {
    if (w.code < 0 && same_) return words.push_back(as_written(w));  // G#1
    if (w.code < 0) return fail(w.range, fmt::format("a code chosen at run time ({})", w.address.str()));
    const CodeDesc& desc = p_.semantics.codes[static_cast<size_t>(w.code)];
    if (same_) {
      words.push_back(desc.name);
      return;
    }
    if (desc.calls.empty()) return;  // a call, a return: the statements write them
    for (const FnCall& c : desc.calls)
      if (c.fn == Fn::Cycle)
        return fail(w.range, fmt::format("canned cycle {}: cycles are translated between dialects by --flatten only",
                                         desc.name));
    // One code of the same functions, else one code for each.
    if (auto one = target_code(desc.calls, desc.scope)) {
      words.push_back(one->text());
      return;
    }
    std::vector<std::string> each;
    for (const FnCall& c : desc.calls) {
      auto code = target_code({c}, desc.scope);
      if (!code) return fail(w.range, fmt::format("{} ({}): {} has no code for it", desc.name, fn_name(c.fn), w_.dialect()));
      each.push_back(code->text());
    }
    words.insert(words.end(), each.begin(), each.end());
  }

  // The target's code that calls exactly `calls` (in any order), in scope; of two,
  // not the one its table calls another's alias.
  std::optional<Code> target_code(const std::vector<FnCall>& calls, Scope scope) const {
    // The ISO seed's M02 is its M30: an end is an end (docs/translate.md).
    if (calls.size() == 1 && calls[0].fn == Fn::ProgramEnd && !exact_code(calls, scope))
      return exact_code({{Fn::ProgramEndInformation}}, scope);
    return exact_code(calls, scope);
  }
  std::optional<Code> exact_code(const std::vector<FnCall>& calls, Scope scope) const {
    std::optional<Code> best;
    bool best_alias = true;
    for (const auto* table : {&w_.tables().g_codes, &w_.tables().m_codes})
      for (const auto& [number, entry] : *table) {
        const std::vector<FnCall>& has = entry.desc.calls;
        // A code of a block and a modal one differ only in a state they set.
        const bool stateful = std::any_of(calls.begin(), calls.end(), [](const FnCall& c) { return fn_group(c.fn) != FnGroup::None; });
        if (has.size() != calls.size() || (stateful && entry.desc.scope != scope)) continue;
        if (!std::all_of(calls.begin(), calls.end(), [&](const FnCall& c) { return std::find(has.begin(), has.end(), c) != has.end(); }))
          continue;
        const bool alias = entry.meaning.find("(as ") != std::string::npos;
        if (!best || (best_alias && !alias)) {
          best = Code{entry.letter, number, &entry};
          best_alias = alias;
        }
      }
    return best;
  }

  void parameter(const ir::Word& w, std::vector<std::string>& words) {
    if (same_) return words.push_back(as_written(w));
    const std::string address = w.address.str();
    const char letter = address.size() == 1 ? address[0] : 0;
    if (letter < 'A' || letter > 'Z') return fail(w.range, fmt::format("the word {}", address));
    auto write = [&](char to) { words.push_back(to + value(w.value, to)); };
    if (src_.axes.find(letter) != std::string::npos) {
      if (dst_.axes.find(letter) == std::string::npos)
        return fail(w.range, fmt::format("axis {}: the target machine has axes {}", letter, dst_.axes));
      return write(letter);
    }
    switch (letter) {
      case 'F': case 'S': case 'T': return write(letter);
      case 'I': case 'J': case 'K':
        if (src_.centre_words == CentreWords::PerAxis && (src_.helix_lead != dst_.helix_lead || dst_.helix_by_end)) {
          if (!plane_) return fail(w.range, fmt::format("{} where the plane is not known: a centre or a helix lead", letter));
          if (*plane_ == letter)
            return fail(w.range, fmt::format("a helix lead {}: {}", letter,
                                             dst_.helix_by_end ? fmt::format("{} gives a helix by its end point alone", w_.dialect())
                                                               : std::string("the dialects give the lead in other units")));
        }
        if (src_.arc_centre != dst_.arc_centre)
          return fail(w.range, fmt::format("the arc centre {}: {} gives it from the origin, {} from the start point",
                                           letter, src_.arc_centre == ArcCentre::Absolute ? p_.dialect : w_.dialect(),
                                           src_.arc_centre == ArcCentre::Absolute ? w_.dialect() : p_.dialect));
        if (src_.centre_words != dst_.centre_words)
          return fail(w.range, fmt::format("the arc centre {}: the dialects give the centre by different words", letter));
        return write(letter);
      default: break;
    }
    if (letter == src_.radius_word && letter == dst_.radius_word) return write(letter);
    if (letter == src_.dwell_word && dst_.dwell_word) {
      const double factor = src_.dwell_seconds_per_unit / dst_.dwell_seconds_per_unit;
      const ir::Expr& e = p_.exprs[w.value];
      words.push_back(dst_.dwell_word + (e.op == ir::ExprOp::Number ? exact(e.number * factor, true)
                                         : factor == 1              ? value(w.value, 'P')
                                                                    : fmt::format("[{}*{}]", expr(w.value, kTerm), exact(factor, false))));
      return;
    }
    fail(w.range, fmt::format("the word {} of {}: {} has no word of its meaning", address, p_.dialect, w_.dialect()));
  }

  // --- parameters and expressions -----------------------------------------------------

  void assign(const ir::Stmt& s) {
    const ir::Expr& target = p_.exprs[s.target];
    std::string value = expr(s.value, kOr);
    if (!same_ && target.op == ir::ExprOp::Var && p_.is_constant(target.a)) {
      // A store rounds as the parameter's class does (NC-110 decision 8; pp R: 0.001).
      const VarType type = p_.spaces[target.space].type_of(static_cast<uint32_t>(p_.exprs[target.a].number));
      const bool whole = type == VarType::Byte || type == VarType::Integer || type == VarType::Long;
      if (type == VarType::Real) fail(s.range, "a store into a single-precision parameter");
      if (whole || type == VarType::Thousandths) {
        if (p_.is_constant(s.value)) {
          double v = p_.exprs[s.value].number;
          if (convert_value(type, 0, v)) value = exact(v, false);
          else fail(s.range, "a value outside its parameter's class");
        } else {
          value = whole ? "ROUND[" + value + "]" : "ROUND[" + expr(s.value, kTerm) + "*1000]/1000";
        }
      }
    }
    line(var(target) + "=" + value);
  }

  std::string var(const ir::Expr& e) {
    if (e.op != ir::ExprOp::Var) {
      fail(e.range, "a store into a memory or a system variable");
      return "#0";
    }
    const VarSpace& space = p_.spaces[e.space];
    if (!same_ && static_cast<int>(e.space) != mapped_space_) {
      fail(e.range, fmt::format("the parameters {}: {} maps one space of parameters", space.name, w_.dialect()));
      return "#0";
    }
    const uint32_t base = same_ ? 0 : kMappedBase;
    if (p_.is_constant(e.a)) {
      const uint32_t index = base + static_cast<uint32_t>(p_.exprs[e.a].number);
      if (index >= kMappedEnd) fail(e.range, fmt::format("{}{}: mapped to #{}, beyond #999", space.name, index - base, index));
      used_.insert(index);
      return fmt::format("#{}", index);
    }
    indirect_ = true;
    return fmt::format("#[{}{}]", base ? fmt::format("{}+", base) : "", expr(e.a, kTerm));
  }

  std::string expr(ir::ExprId id, int min) {
    const ir::Expr& e = p_.exprs[id];
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
      case ir::ExprOp::ZeroIfVacant: case ir::ExprOp::Check: return expr(e.a, min);
      case ir::ExprOp::Neg: return wrap(kSign, "-" + expr(e.a, kSign));
      case ir::ExprOp::Not: return negation(e.a, min);
      case ir::ExprOp::Add: return binary(kSum, "+");
      case ir::ExprOp::Sub: return binary(kSum, "-");
      case ir::ExprOp::Mul: return binary(kTerm, "*");
      case ir::ExprOp::Div: return binary(kTerm, "/");
      case ir::ExprOp::Mod: return binary(kTerm, "MOD");
      case ir::ExprOp::Eq: return binary(kCompare, "EQ");
      case ir::ExprOp::Ne: return binary(kCompare, "NE");
      case ir::ExprOp::Lt: return binary(kCompare, "LT");
      case ir::ExprOp::Le: return binary(kCompare, "LE");
      case ir::ExprOp::Gt: return binary(kCompare, "GT");
      case ir::ExprOp::Ge: return binary(kCompare, "GE");
      case ir::ExprOp::And: return binary(kAnd, "AND");
      case ir::ExprOp::Or: return binary(kOr, "OR");
      case ir::ExprOp::Xor: return binary(kOr, "XOR");
      case ir::ExprOp::Call: return call_expr(e);
      case ir::ExprOp::Pow: fail(e.range, "a power (ISO has no power operator)"); return "0";
      default: fail(e.range, "a memory, a system variable or a text in an expression"); return "0";
    }
  }

  // not a: the opposite comparison when a is one (operands never vacant there: the
  // order comparisons read vacant as 0, and EQ and NE are each other's opposite).
  std::string negation(ir::ExprId id, int min) {
    const ir::Expr& a = p_.exprs[id];
    static const std::map<ir::ExprOp, std::string_view> kOpposite = {
        {ir::ExprOp::Eq, "NE"}, {ir::ExprOp::Ne, "EQ"}, {ir::ExprOp::Lt, "GE"},
        {ir::ExprOp::Le, "GT"}, {ir::ExprOp::Gt, "LE"}, {ir::ExprOp::Ge, "LT"}};
    std::string text;
    if (auto it = kOpposite.find(a.op); it != kOpposite.end())
      text = fmt::format("{} {} {}", expr(a.a, kSum), it->second, expr(a.b, kSum));
    else if (a.op == ir::ExprOp::Not)
      text = fmt::format("[{}] NE 0", expr(a.a, kOr));
    else
      text = expr(id, kSum) + " EQ 0";
    return kCompare < min ? "[" + text + "]" : text;
  }

  std::string call_expr(const ir::Expr& e) {
    auto one = [&](std::string_view name) { return fmt::format("{}[{}]", name, expr(e.a, kOr)); };
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

  // --- flow ----------------------------------------------------------------------

  void jump(const ir::Stmt& s) {
    std::string to;
    if (!s.label.empty()) {
      to = fmt::format("{}", labels_.at(s.label));
    } else if (same_) {
      to = value(s.value, 'N');  // GOTO #1: the block numbers are the source's
    } else {
      return fail(s.range, "a jump to a computed block number");
    }
    if (s.cond == ir::kNoExpr) return line("GOTO " + to);
    line(fmt::format("IF [{}] GOTO {}", expr(s.cond, kOr), to));
  }

  // A repeat loop counts down a common variable of its own: #199 for the first loop
  // of the program, #198 for the next. A jump out of the body leaves the count
  // behind, as leaving a loop closes it; a jump back to the repeat starts it again.
  void repeat_begin(const ir::Stmt& s) {
    if (loops_count_ > kFirstCounter - kLastCounter)
      return fail(s.range, "more than 100 repeat loops");
    const uint32_t counter = kFirstCounter - loops_count_++;
    Loop loop{counter, fresh_number(), 0};
    line(fmt::format("#{}={}", counter, expr(s.value, kOr)));
    if (!p_.is_constant(s.value) || p_.exprs[s.value].number < 1) {
      loop.exit = fresh_number();
      line(fmt::format("IF [#{} LE 0] GOTO {}", counter, loop.exit));
    }
    pending_head_ = loop.head;
    loops_.push_back(loop);
  }

  void repeat_end(const ir::Stmt&) {
    if (loops_.empty()) return;
    const Loop loop = loops_.back();
    loops_.pop_back();
    line(fmt::format("#{0}=#{0}-1", loop.counter));
    line(fmt::format("IF [#{} GT 0] GOTO {}", loop.counter, loop.head));
    if (loop.exit) line(fmt::format("N{}", loop.exit));
  }

  // ISO shows the operator no values: the display becomes a comment that says what
  // it showed, with a warning.
  void display(const ir::Stmt& s) {
    std::string text = "DIS";
    for (const ir::DisplayItem& item : s.items) {
      const ir::Expr& e = p_.exprs[item.value];
      text += ' ';
      text += e.op == ir::ExprOp::String ? "\"" + p_.texts[e.text] + "\"" : expr(item.value, kOr);
    }
    comment(text);
    drop(s.range, "a display to the operator (DIS), written as a comment");
  }

  void call(const ir::Stmt& s) {
    if (same_) return machine(s);
    forget();
    if (!programs_.count(s.label))
      return fail(s.range, s.label.find('/') != std::string::npos ? "a call of a block of a program" : "a call of " + s.label);
    if (!s.args.empty()) return fail(s.range, "a call with arguments");
    std::string text = fmt::format("M98 P{}", programs_.at(s.label));
    if (s.value != ir::kNoExpr && !(p_.is_constant(s.value) && p_.exprs[s.value].number == 1))
      text += " L" + value(s.value, 'L');
    line(text);
  }

  // --- the start ----------------------------------------------------------------------

  // The source's power-on state, in the target's codes (those it has), then its
  // parameters at 0: Macro B variables start vacant, E and R parameters at 0.
  void start() {
    std::vector<Code> g, m;
    for (uint16_t i : p_.semantics.power_on)
      for (const FnCall& c : p_.semantics.codes[i].calls)
        if (auto code = target_code({c}, Scope::Modal)) {
          auto& list = code->letter == 'G' ? g : m;
          if (std::none_of(list.begin(), list.end(), [&](const Code& o) { return o.number == code->number; }))
            list.push_back(*code);
        }
    // G codes that must not share a block (two of one group) in blocks of their own.
    std::vector<std::vector<Code>> blocks;
    for (const Code& c : g) {
      auto it = std::find_if(blocks.begin(), blocks.end(), [&](const std::vector<Code>& b) {
        return std::none_of(b.begin(), b.end(),
                            [&](const Code& o) { return stdlib::has_pair(w_.tables().incompatible, o.number, c.number); });
      });
      if (it == blocks.end()) blocks.push_back({c});
      else it->push_back(c);
    }
    for (const auto& b : blocks) {
      std::string text;
      for (const Code& c : b) text += (text.empty() ? "" : " ") + c.text();
      w_.line(text);
    }
    for (const Code& c : m) w_.line(c.text());
    start_offset();
    if (mapped_space_ >= 0 && !p_.spaces[static_cast<size_t>(mapped_space_)].vacant) {
      if (indirect_) {
        const uint32_t size = std::min(p_.spaces[static_cast<size_t>(mapped_space_)].size, kMappedEnd - kMappedBase);
        w_.line(fmt::format("#1=0"));
        w_.line(fmt::format("WHILE [#1 LT {}] DO1", size));
        w_.line(fmt::format("#[{}+#1]=0", kMappedBase));
        w_.line("#1=#1+1");
        w_.line("END1");
      } else {
        for (uint32_t v : used_) w_.line(fmt::format("#{}=0", v));
      }
    }
  }

  // A source that starts without a work offset (GOST, pp G53) on a target that
  // starts in one and has no code to leave it: the same only where the target
  // machine's offset is zero.
  void start_offset() {
    auto offset_of = [](const std::vector<FnCall>& calls) -> std::optional<int> {
      for (const FnCall& c : calls)
        if (c.fn == Fn::WorkOffset) return c.arg;
      return std::nullopt;
    };
    int source = 0, target = 0;
    for (uint16_t i : p_.semantics.power_on) source = offset_of(p_.semantics.codes[i].calls).value_or(source);
    if (auto it = w_.tables().power_on.find("default"); it != w_.tables().power_on.end())
      for (const std::string& token : it->second)
        if (auto code = w_.tables().g_codes.find(token.size() > 1 && token[0] == 'G' ? std::atoi(token.c_str() + 1) : -1);
            code != w_.tables().g_codes.end())
          target = offset_of(code->second.desc.calls).value_or(target);
    if (source == target || target_code({{Fn::WorkOffset, static_cast<uint16_t>(source)}}, Scope::Modal)) return;
    const auto it = target_.work_offsets.find(target);
    if (it == target_.work_offsets.end() ||
        std::all_of(it->second.values.begin(), it->second.values.end(), [](double v) { return v == 0; }))
      return;
    fail(p_.units.front().range,
         fmt::format("the start without a work offset: {} starts in work offset {}, which the target machine sets, and "
                     "has no code for none (give --target-machine a profile whose offset {} is zero)",
                     w_.dialect(), target, target));
  }

  void fail(SourceRange at, std::string what) { problems.push_back({at, std::move(what)}); }
  void drop(SourceRange at, std::string what) { problems.push_back({at, std::move(what), true}); }

  const ir::Program& p_;
  Writer& w_;
  const MachineConfig& target_;
  const Conventions& src_;
  const Conventions& dst_;
  const bool same_;
  int mapped_space_ = -1;
  std::map<std::string, int> programs_;  // unit name -> O number
  std::map<std::string, int> labels_;    // of the unit being written: label -> N
  std::map<const ir::Block*, int> numbers_;
  std::set<int> taken_numbers_;
  int next_number_ = kFreshNumbers;
  const ir::Block* block_ = nullptr;
  std::optional<int> pending_number_;
  bool skip_ = false;
  bool words_written_ = false;
  std::optional<bool> spindle_on_ = false, coolant_on_ = false;  // nothing: not known
  std::optional<char> plane_;
  std::optional<int> corrector_ = 0;  // NC-110: the corrector the next M06 applies  // the centre word along the plane's normal: a helix lead
  std::string then_;  // "IF [c] THEN " before the next line
  std::vector<std::string> comments_;  // for the block's first line
  std::set<uint32_t> used_;  // target variables the program reads or writes
  bool indirect_ = false;    // ... and one computed
  struct Loop {
    uint32_t counter;
    int head;
    int exit;
  };
  std::vector<Loop> loops_;
  uint32_t loops_count_ = 0;
  std::optional<int> pending_head_;
};

}  // namespace

bool writes_structured(std::string_view target) { return target == "iso"; }

bool structured(Session& s, const ir::Program& program, const Request& request, std::FILE* out) {
  const uint32_t errors = s.diags.error_count();
  auto writer = make_writer(request.to, *request.target_profile, s.diags);
  if (!writer) return false;
  const MachineConfig target = stdlib::load_machine_config(*request.target_profile, s.diags);
  if (s.diags.error_count() != errors) return false;
  Structured translation(program, *writer, target);
  Header header = request.header;
  if (!program.units.empty()) header.title = program.units.front().title;
  translation.write(header);
  // Each construct once, at its first place, with the count of the others.
  std::map<std::string, std::pair<const Problem*, size_t>> seen;
  std::vector<std::string> order;
  for (const Problem& p : translation.problems) {
    auto [it, fresh] = seen.try_emplace(p.what, &p, 0);
    if (fresh) order.push_back(p.what);
    else ++it->second.second;
  }
  bool refused = false;
  for (const std::string& what : order) {
    const auto& [p, more] = seen.at(what);
    const std::string text = what + (more ? fmt::format(" (and in {} more places)", more) : "");
    s.diags.report(p->dropped ? DiagId::TranslateDropped : DiagId::TranslateRefused, p->at, writer->dialect(), text);
    refused |= !p->dropped;
  }
  if (refused) return false;
  const std::string text = writer->take();
  return std::fwrite(text.data(), 1, text.size(), out) == text.size() && s.diags.error_count() == errors;
}

}  // namespace ncc::translate
