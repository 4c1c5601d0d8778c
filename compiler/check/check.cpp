#include "check.h"

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <set>

namespace ncc {

// What check_block remembers while it reads one block, kept from block to block so
// that checking a block allocates nothing (CAM programs have millions).
struct BlockScratch {
  std::array<const ir::Word*, 256> first{};                          // a letter's first word
  std::array<int, 256> count{};                                      // a letter's words so far
  std::string letters;                                               // the letters to clear
  std::vector<std::pair<std::string_view, const ir::Word*>> groups;  // G group -> first code
  std::vector<std::pair<std::string_view, const ir::Word*>> sets;    // M conflict set -> first code
  std::vector<std::pair<int, const ir::Word*>> codes;                // M code number -> its word
  std::vector<const ir::Word*> g_codes;                              // for a compatibility matrix

  void clear() {
    for (char c : letters) {
      first[static_cast<uint8_t>(c)] = nullptr;
      count[static_cast<uint8_t>(c)] = 0;
    }
    letters.clear();
    groups.clear();
    sets.clear();
    codes.clear();
    g_codes.clear();
  }
  // The count of a letter, which the caller raises: a letter is noted at its first.
  int& count_of(char letter) {
    int& c = count[static_cast<uint8_t>(letter)];
    if (c == 0) letters += letter;
    return c;
  }
  // `key`'s word is `w` from now on.
  template <typename Key>
  static void replace(std::vector<std::pair<Key, const ir::Word*>>& seen, Key key, const ir::Word* w) {
    for (auto& [k, word] : seen)
      if (k == key) word = w;
  }
  // The word of `key` seen first, after making `w` it if there was none.
  template <typename Key>
  static const ir::Word* first_of(std::vector<std::pair<Key, const ir::Word*>>& seen, Key key, const ir::Word* w) {
    for (const auto& [k, word] : seen)
      if (k == key) return word;
    seen.push_back({key, w});
    return w;
  }
};

namespace {

int code_number(const ir::Program& p, const ir::Word& w) { return ir::code_number(p, w.value); }

// A code written without digits (NC-110 "G" is G00, decision 4) is named by its number.
std::string word_text(const ir::Program& p, const ir::Word& w) {
  if (w.text.empty() && w.kind == ir::WordKind::Code && w.value != ir::kNoExpr)
    return fmt::format("{}{:02}", w.address, code_number(p, w));
  return w.address + w.text;
}

// Both labels of a block range, where they are written.
SourceRange range_operands(const ir::Stmt& s) {
  SourceRange r = s.range;
  if (s.end_range.line == r.line && s.end_range.end_col > r.end_col) r.end_col = s.end_range.end_col;
  return r;
}

const stdlib::CodeEntry* code_entry(const ir::Program& p, const CheckRules& rules, const ir::Word& w) {
  const auto& table = w.address == "G" ? rules.tables->g_codes : rules.tables->m_codes;
  auto it = table.find(code_number(p, w));
  return it == table.end() ? nullptr : &it->second;
}

template <typename... Args>
void report_with_note(const ir::Program& p, Diagnostics& diags, DiagIdFor<Args...> id, const ir::Word& second,
                      const ir::Word& first, const Args&... args) {
  if (Diagnostic* d = diags.report(id, second.range, args...))
    d->notes.push_back({first.range, fmt::format("{} is here", word_text(p, first))});
}

void check_block(const ir::Program& p, const CheckRules& rules, ir::Block& block, BlockScratch& seen,
                 Diagnostics& diags) {
  std::vector<size_t> superseded;  // codes a later one of their group replaces (group_last_wins)
  seen.clear();
  const ir::Word* feed = nullptr;
  const ir::Word* previous = nullptr;  // for the word order
  const bool matrix = !rules.tables->incompatible.empty();
  // At most n words of an address that may stand several times (NC-110: 4 M words).
  auto count_several = [&](const ir::Word& w) {
    auto addr = rules.tables->addresses.find(w.address.size() == 1 ? w.address[0] : 0);
    if (addr == rules.tables->addresses.end() || addr->second.repeat != stdlib::Repeat::Several ||
        !addr->second.max_count)
      return;
    if (++seen.count_of(addr->first) == addr->second.max_count + 1)
      diags.report(DiagId::TooManyWords, w.range, addr->second.max_count + 1, w.address, addr->second.max_count);
  };
  for (const ir::Word& w : block.words) {
    if (w.kind == ir::WordKind::Ignored || w.kind == ir::WordKind::Argument || w.value == ir::kNoExpr) continue;
    if (w.kind == ir::WordKind::Code && w.code == ir::kDynamicCode) {
      count_several(w);  // what it is comes at run time; that it is a word, now
      continue;
    }
    // An operand of a code (a three-letter code's, a GTL definition's) follows its
    // code's rules, not its letter's.
    if (w.slot >= operand_slot(0) && w.slot <= operand_slot(kOperandSlots - 1)) continue;
    char letter = w.address.size() == 1 ? w.address[0] : 0;
    auto addr = rules.tables->addresses.find(letter);
    // The second word of a letter that may stand twice (NC-110 R1 R2) counts as it.
    if (w.address.size() == 2 && w.address[1] == '\'') {
      addr = rules.tables->addresses.find(w.address[0]);
      if (addr != rules.tables->addresses.end() && addr->second.repeat != stdlib::Repeat::Twice)
        addr = rules.tables->addresses.end();
    }
    if (addr == rules.tables->addresses.end()) continue;
    const char key = addr->first;
    if (rules.pedantic && previous) {
      auto prev = rules.tables->addresses.find(previous->address[0]);
      if (prev != rules.tables->addresses.end() && prev->second.order > addr->second.order)
        diags.report(DiagId::WordOrder, w.range, word_text(p, w), word_text(p, *previous));
    }
    previous = &w;
    switch (addr->second.repeat) {
      case stdlib::Repeat::Once:
      case stdlib::Repeat::Twice: {
        int& count = seen.count_of(key);
        const ir::Word*& first = seen.first[static_cast<uint8_t>(key)];
        if (!first) first = &w;
        int allowed = addr->second.repeat == stdlib::Repeat::Twice ? 2 : 1;
        if (++count == allowed + 1)
          report_with_note(p, diags, DiagId::WordRepeated, w, *first, std::string(1, key),
                           allowed == 1 ? "once" : "twice");
        break;
      }
      case stdlib::Repeat::Feed:
        if (feed) report_with_note(p, diags, DiagId::SeveralFeeds, w, *feed);
        if (!feed) feed = &w;
        break;
      case stdlib::Repeat::Group:
      case stdlib::Repeat::Several: {
        if (w.kind != ir::WordKind::Code) break;
        const stdlib::CodeEntry* entry = code_entry(p, rules, w);
        if (!entry) {
          if (w.address == "G")
            diags.report(DiagId::GCodeUndefined, w.range, word_text(p, w));
          else
            diags.report(DiagId::MCodeUndefined, w.range, word_text(p, w));
          break;
        }
        if (addr->second.repeat == stdlib::Repeat::Group && matrix) {
          // A compatibility matrix says which codes may share a block (NC-110 Table 2.4).
          for (const ir::Word* other : seen.g_codes)
            if (stdlib::has_pair(rules.tables->incompatible, code_number(p, *other), code_number(p, w))) {
              report_with_note(p, diags, DiagId::CodesIncompatible, w, *other, word_text(p, *other), word_text(p, w));
              break;
            }
          seen.g_codes.push_back(&w);
        } else if (addr->second.repeat == stdlib::Repeat::Group) {
          // Block-only codes without a group letter count as their own group (§2.5).
          std::string_view group = entry->group == "-" ? entry->desc.name : entry->group;
          if (const ir::Word* other = BlockScratch::first_of(seen.groups, group, &w); other != &w) {
            if (rules.group_last_wins && group != "00") {
              report_with_note(p, diags, DiagId::GroupLastWins, w, *other, word_text(p, *other), word_text(p, w),
                               std::string(group));
              superseded.push_back(static_cast<size_t>(other - block.words.data()));
              BlockScratch::replace(seen.groups, group, &w);
            } else {
              report_with_note(p, diags, DiagId::GroupConflict, w, *other, word_text(p, *other), word_text(p, w),
                               std::string(group));
            }
          }
        } else {
          count_several(w);
          // The same code twice is a word too many; two codes of one set contradict.
          if (const ir::Word* same = BlockScratch::first_of(seen.codes, code_number(p, w), &w); same != &w) {
            report_with_note(p, diags, DiagId::WordRepeated, w, *same, word_text(p, w), "once");
            break;
          }
          for (const std::string& set : entry->conflict_sets) {
            if (const ir::Word* other = BlockScratch::first_of(seen.sets, std::string_view(set), &w); other != &w) {
              report_with_note(p, diags, DiagId::MCodeConflict, w, *other, word_text(p, *other), word_text(p, w), set);
              break;
            }
          }
        }
        break;
      }
    }
  }
  for (size_t i : superseded) block.words[i].kind = ir::WordKind::Ignored;
}

const ir::Word& number_word(const ir::Block& b) {
  for (const ir::Word& w : b.words)
    if (w.kind == ir::WordKind::BlockNumber) return w;
  return b.words.front();
}

}  // namespace

void BlockNumbers::add(const ir::Block& b, Diagnostics& diags) {
  if (!b.number) return;
  const SourceRange at = number_word(b).range;
  auto [it, fresh] = first_.emplace(*b.number, at);
  if (!fresh) {
    if (Diagnostic* d = diags.report(DiagId::BlockNumberOrder, at, *b.number, "is used again"))
      d->notes.push_back({it->second, "first used here"});
  } else if (last_ && *b.number < *last_) {
    diags.report(DiagId::BlockNumberOrder, at, *b.number,
                 fmt::format("is lower than the previous block number {}", *last_));
  }
  last_ = *b.number;
}

namespace {

// Jumps stay within their unit; calls name a unit or main block of the medium (the
// names lowering gives entry points). A call the front end could not resolve it has
// reported already.
void check_targets(ir::Program& program, ir::Unit& unit, const CheckRules& rules, const StreamChecks* streamed,
                   Diagnostics& diags) {
  std::set<std::string> labels, entries;
  if (streamed) entries = streamed->entries();
  // Macro B M97 calls a block of its own unit: "unit/label".
  const std::string own = unit.name + "/";
  for (size_t i : unit.named_streamed_labels()) labels.insert(unit.streamed_labels[i].label());
  std::map<std::string, const ir::Block*> defined;
  for (const ir::Block& b : unit.blocks) {
    if (!b.label.empty()) {
      labels.insert(b.label);
      auto [it, fresh] = defined.emplace(b.label, &b);
      if (!fresh && rules.unique_labels)
        if (Diagnostic* d = diags.report(DiagId::LabelDuplicate, b.range, b.label))
          d->notes.push_back({it->second->range, "first defined here"});
    }
  }
  for (const ir::Unit& u : program.units) {
    entries.insert(u.name);
    for (const ir::Block& b : u.blocks)
      if (b.main_block && b.number) entries.insert(fmt::format(":{}", *b.number));
  }
  auto callable = [&](const std::string& name) {
    return name.starts_with(own) ? labels.count(name.substr(own.size())) > 0 : entries.count(name) > 0;
  };
  // A block refused whole may hold the label a jump names: its own error says enough.
  const bool unread = std::ranges::any_of(unit.blocks, [](const ir::Block& b) { return b.unread; });
  auto undefined = [&](const std::string& label) { return !unread && !labels.count(label); };
  for (ir::Block& b : unit.blocks) {
    uint32_t errors = diags.error_count();
    for (ir::Stmt& s : b.stmts) {
      if (s.kind == ir::StmtKind::Jump && !s.label.empty() && undefined(s.label) && rules.absent_jump_runs &&
          s.label.starts_with("N")) {
        diags.report(DiagId::JumpTargetAbsent, s.range, s.label);
        s.value = program.number(std::stod(s.label.substr(1)), s.range);  // NC4081 if it is taken
        s.label.clear();
        continue;
      }
      if (s.kind == ir::StmtKind::Jump && !s.label.empty() && undefined(s.label))
        diags.report(DiagId::LabelUndefined, s.range, "jump to", s.label);
      if (s.kind == ir::StmtKind::CallRange) {
        if (undefined(s.label)) diags.report(DiagId::LabelUndefined, s.range, "block range from", s.label);
        if (undefined(s.end_label)) diags.report(DiagId::LabelUndefined, s.end_range, "block range to", s.end_label);
      }
      if (s.kind == ir::StmtKind::Call && !callable(s.label) && !b.has_errors)
        diags.report(DiagId::CallUndefined, s.range, s.label);
    }
    if (diags.error_count() != errors) b.has_errors = true;
  }
}

// Repeat loops: balanced, not too deep, never entered by a jump; block ranges
// whole, in order, and not inside another range (NC-110 §2.13.2).
void check_structure(ir::Unit& unit, const CheckRules& rules, Diagnostics& diags) {
  const size_t n = unit.blocks.size();
  std::vector<std::vector<size_t>> before(n), after(n);  // the loops open at each block
  std::vector<size_t> open;
  std::vector<const ir::Stmt*> open_stmt;
  size_t next_loop = 0;
  for (size_t i = 0; i < n; ++i) {
    const ir::Block& b = unit.blocks[i];
    before[i] = open;
    for (const ir::Stmt& s : b.stmts) {
      bool begin = s.kind == ir::StmtKind::RepeatBegin, end = s.kind == ir::StmtKind::RepeatEnd;
      if ((begin || end) && b.skippable)
        diags.report(DiagId::RepeatUnbalanced, b.range,
                     "a repeat loop cannot begin or end in a block that may be skipped ('/')");
      if (begin) {
        open.push_back(next_loop++);
        open_stmt.push_back(&s);
        if (rules.max_repeat_depth && open.size() == rules.max_repeat_depth + 1)
          diags.report(DiagId::RepeatDepth, s.range, open.size(), rules.max_repeat_depth);
      } else if (end) {
        if (open.empty()) {
          diags.report(DiagId::RepeatUnbalanced, s.range, "this end of a repeat loop has no beginning before it");
        } else {
          open.pop_back();
          open_stmt.pop_back();
        }
      }
    }
    after[i] = open;
  }
  for (const ir::Stmt* s : open_stmt)
    diags.report(DiagId::RepeatUnbalanced, s->range, "this repeat loop has no end in its program unit");

  std::map<std::string, size_t> at;
  for (size_t i = 0; i < n; ++i)
    if (!unit.blocks[i].label.empty()) at.emplace(unit.blocks[i].label, i);
  auto inside = [](const std::vector<size_t>& inner, const std::vector<size_t>& outer) {
    return inner.size() <= outer.size() && std::equal(inner.begin(), inner.end(), outer.begin());
  };
  std::vector<std::pair<size_t, size_t>> ranges;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t errors = diags.error_count();
    for (const ir::Stmt& s : unit.blocks[i].stmts) {
      if (s.kind == ir::StmtKind::Jump)
        if (auto it = at.find(s.label); it != at.end() && !inside(before[it->second], before[i]))
          diags.report(DiagId::JumpIntoRepeat, s.range, s.label, "the jump");
      if (s.kind != ir::StmtKind::CallRange) continue;
      auto from = at.find(s.label), to = at.find(s.end_label);
      if (from == at.end() || to == at.end()) continue;
      std::string name = fmt::format("{} to {}", s.label, s.end_label);
      if (to->second < from->second) {
        diags.report(DiagId::RangeInvalid, range_operands(s), name, "its last block comes before its first");
      } else if (before[from->second] != after[to->second]) {
        diags.report(DiagId::RangeInvalid, range_operands(s), name, "it cuts a repeat loop: a range holds whole loops");
      } else if (!inside(before[from->second], before[i])) {
        diags.report(DiagId::JumpIntoRepeat, s.range, s.label, "the range call");
      } else {
        ranges.push_back({from->second, to->second});
      }
    }
    // Such a jump or range is not lowered: it would enter a loop from outside.
    if (diags.error_count() != errors) unit.blocks[i].has_errors = true;
  }
  for (size_t i = 0; i < n; ++i)
    for (const ir::Stmt& s : unit.blocks[i].stmts)
      if (s.kind == ir::StmtKind::CallRange)
        for (auto [first, last] : ranges)
          if (i >= first && i <= last) {
            diags.report(DiagId::RangeInvalid, range_operands(s), fmt::format("{} to {}", s.label, s.end_label),
                         fmt::format("it stands inside the range {} to {}, and ranges do not nest",
                                     unit.blocks[first].label, unit.blocks[last].label));
            break;
          }
}

// Calls: at most the dialect's depth open at once, and none that would never end. The
// walk follows the calls depth first, in a loop, and walks each unit once at each
// depth it is reached at (once in all without a depth limit): it is linear in the
// program however often its units call each other (every path was walked before: 8
// calls a level, 18 levels deep, never ended).
void check_calls(const ir::Program& program, const CheckRules& rules, Diagnostics& diags) {
  if (program.units.empty()) return;
  const uint32_t limit = program.semantics.conventions.max_call_depth;
  std::map<std::string, const ir::Unit*> units;
  for (const ir::Unit& u : program.units) units.emplace(u.name, &u);
  std::set<const ir::Stmt*> reported;
  std::set<std::pair<const ir::Unit*, size_t>> walked;  // (unit, depth)
  struct Open {
    const ir::Unit* unit;
    size_t block = 0, stmt = 0;  // the next statement to look at
  };
  std::vector<Open> path{{&program.units.front()}};
  while (!path.empty()) {
    Open& open = path.back();
    if (open.block == open.unit->blocks.size()) {
      path.pop_back();
      continue;
    }
    const ir::Block& b = open.unit->blocks[open.block];
    if (open.stmt == b.stmts.size()) {
      ++open.block, open.stmt = 0;
      continue;
    }
    const ir::Stmt& s = b.stmts[open.stmt++];
    if (s.kind != ir::StmtKind::Call) continue;
    auto it = units.find(s.label);
    if (it == units.end() || reported.count(&s)) continue;
    auto at = std::find_if(path.begin(), path.end(), [&](const Open& o) { return o.unit == it->second; });
    if (at != path.end()) {
      reported.insert(&s);
      if (rules.recursion) continue;  // a condition may end it; the call depth limit holds at run time
      std::string through;            // the programs between: none when it calls itself directly
      for (++at; at != path.end(); ++at) through += (through.empty() ? " through " : " -> ") + at->unit->name;
      diags.report(DiagId::CallRecursive, s.range, s.label, through);
    } else if (limit && path.size() > limit) {
      reported.insert(&s);
      std::string chain;
      for (const Open& o : path) chain += o.unit->name + " -> ";
      diags.report(DiagId::CallTooDeep, s.range, s.label, path.size(), limit, chain + s.label);
    } else if (walked.insert({it->second, limit ? path.size() + 1 : 0}).second) {
      path.push_back({it->second});
    }
  }
}

}  // namespace

StreamChecks::StreamChecks(const CheckRules& rules) : rules_(rules), scratch_(std::make_unique<BlockScratch>()) {}
StreamChecks::~StreamChecks() = default;

void StreamChecks::block(const ir::Program& program, ir::Block& b) {
  const uint32_t errors = block_diags_.error_count();
  check_block(program, rules_, b, *scratch_, block_diags_);
  if (block_diags_.error_count() != errors) b.has_errors = true;
  if (rules_.block_number_order) numbers_.add(b, number_diags_);
  if (b.main_block && b.number) entries_.insert(fmt::format(":{}", *b.number));
}

void check(ir::Program& program, const CheckRules& rules, Diagnostics& diags, StreamChecks* streamed) {
  // A block with an error is marked: the dry run would only repeat it.
  BlockScratch own;
  BlockScratch& scratch = streamed ? *streamed->scratch_ : own;
  for (size_t u = 0; u < program.units.size(); ++u) {
    ir::Unit& unit = program.units[u];
    StreamChecks* stream = u == 0 ? streamed : nullptr;  // the checks of its dropped blocks
    if (stream) {
      for (const Diagnostic& d : stream->block_diags_.all()) diags.add(d);
      if (diags.limit_reached()) return;
    }
    for (ir::Block& block : unit.blocks) {
      uint32_t errors = diags.error_count();
      check_block(program, rules, block, scratch, diags);
      if (diags.error_count() != errors) block.has_errors = true;
      if (diags.limit_reached()) return;
    }
    // The first unit's numbers go on from those of its streamed blocks.
    if (rules.block_number_order) {
      BlockNumbers fresh;
      BlockNumbers& numbers = stream ? stream->numbers_ : fresh;
      if (stream)
        for (const Diagnostic& d : stream->number_diags_.all()) diags.add(d);
      for (const ir::Block& block : unit.blocks) numbers.add(block, diags);
    }
    check_targets(program, unit, rules, streamed, diags);
    check_structure(unit, rules, diags);
  }
  check_calls(program, rules, diags);
}

}  // namespace ncc
