#include "check.h"

#include <map>
#include <set>

namespace ncc {

namespace {

std::string word_text(const ir::Word& w) { return w.address + w.text; }

const stdlib::CodeEntry* code_entry(const ir::Program& p, const CheckRules& rules, const ir::Word& w) {
  const auto& table = w.address == "G" ? rules.tables->g_codes : rules.tables->m_codes;
  auto it = table.find(static_cast<int>(p.exprs[w.value].number));
  return it == table.end() ? nullptr : &it->second;
}

void report_with_note(Diagnostics& diags, DiagId id, const ir::Word& second, const ir::Word& first,
                      const std::string& a, const std::string& b = {}, const std::string& c = {}) {
  if (Diagnostic* d = diags.report(id, second.range, a, b, c))
    d->notes.push_back({first.range, fmt::format("{} is here", word_text(first))});
}

void check_block(const ir::Program& p, const CheckRules& rules, const ir::Block& block, Diagnostics& diags) {
  std::map<std::string, const ir::Word*> once;    // address -> first word
  std::map<std::string, const ir::Word*> groups;  // G group -> first code
  std::map<std::string, const ir::Word*> sets;    // M conflict set -> first code
  const ir::Word* feed = nullptr;
  const ir::Word* previous = nullptr;  // for the word order
  for (const ir::Word& w : block.words) {
    if (w.kind == ir::WordKind::Ignored || w.value == ir::kNoExpr) continue;
    char letter = w.address.size() == 1 ? w.address[0] : 0;
    auto addr = rules.tables->addresses.find(letter);
    if (addr == rules.tables->addresses.end()) continue;
    if (rules.pedantic && previous) {
      auto prev = rules.tables->addresses.find(previous->address[0]);
      if (prev != rules.tables->addresses.end() && prev->second.order > addr->second.order)
        diags.report(DiagId::WordOrder, w.range, word_text(w), word_text(*previous));
    }
    previous = &w;
    switch (addr->second.repeat) {
      case stdlib::Repeat::Once: {
        auto [it, fresh] = once.emplace(w.address, &w);
        if (!fresh) report_with_note(diags, DiagId::WordRepeated, w, *it->second, w.address);
        break;
      }
      case stdlib::Repeat::Feed:
        if (feed) report_with_note(diags, DiagId::SeveralFeeds, w, *feed, "");
        if (!feed) feed = &w;
        break;
      case stdlib::Repeat::Group:
      case stdlib::Repeat::Several: {
        if (w.kind != ir::WordKind::Code) break;
        const stdlib::CodeEntry* entry = code_entry(p, rules, w);
        if (!entry) {
          diags.report(w.address == "G" ? DiagId::GCodeUndefined : DiagId::MCodeUndefined, w.range, word_text(w));
          break;
        }
        if (addr->second.repeat == stdlib::Repeat::Group) {
          // Block-only codes without a group letter count as their own group (§2.5).
          std::string group = entry->group == "-" ? entry->desc.name : entry->group;
          auto [it, fresh] = groups.emplace(group, &w);
          if (!fresh) report_with_note(diags, DiagId::GroupConflict, w, *it->second, word_text(*it->second), word_text(w), group);
        } else {
          std::vector<std::string> my_sets = entry->conflict_sets;
          if (my_sets.empty()) my_sets.push_back(entry->desc.name);  // the same code twice
          for (const std::string& set : my_sets) {
            auto [it, fresh] = sets.emplace(set, &w);
            if (!fresh) {
              report_with_note(diags, DiagId::MCodeConflict, w, *it->second, word_text(*it->second), word_text(w), set);
              break;
            }
          }
        }
        break;
      }
    }
  }
}

const ir::Word& number_word(const ir::Block& b) {
  for (const ir::Word& w : b.words)
    if (w.kind == ir::WordKind::BlockNumber) return w;
  return b.words.front();
}

void check_block_numbers(const ir::Unit& unit, Diagnostics& diags) {
  std::map<uint32_t, const ir::Block*> seen;
  const ir::Block* last = nullptr;
  for (const ir::Block& b : unit.blocks) {
    if (!b.number) continue;
    auto [it, fresh] = seen.emplace(*b.number, &b);
    const ir::Word& word = number_word(b);
    if (!fresh) {
      if (Diagnostic* d = diags.report(DiagId::BlockNumberOrder, word.range, *b.number, "is used again"))
        d->notes.push_back({number_word(*it->second).range, "first used here"});
    } else if (last && *b.number < *last->number) {
      diags.report(DiagId::BlockNumberOrder, word.range, *b.number,
                   fmt::format("is lower than the previous block number {}", *last->number));
    }
    last = &b;
  }
}

// Jumps stay within their unit; calls name a unit or main block of the medium (the
// names lowering gives entry points).
void check_targets(const ir::Program& program, const ir::Unit& unit, Diagnostics& diags) {
  std::set<std::string> labels, entries;
  for (const ir::Block& b : unit.blocks) {
    if (!b.label.empty()) labels.insert(b.label);
    if (b.number) labels.insert(fmt::format("N{}", *b.number));
  }
  for (const ir::Unit& u : program.units) {
    entries.insert(u.name);
    for (const ir::Block& b : u.blocks)
      if (b.main_block && b.number) entries.insert(fmt::format(":{}", *b.number));
  }
  for (const ir::Block& b : unit.blocks)
    for (const ir::Stmt& s : b.stmts) {
      if (s.kind == ir::StmtKind::Jump && !labels.count(s.label)) diags.report(DiagId::LabelUndefined, s.range, s.label);
      if (s.kind == ir::StmtKind::Call && !entries.count(s.label)) diags.report(DiagId::CallUndefined, s.range, s.label);
    }
}

}  // namespace

void check(const ir::Program& program, const CheckRules& rules, Diagnostics& diags) {
  for (const ir::Unit& unit : program.units) {
    for (const ir::Block& block : unit.blocks) {
      check_block(program, rules, block, diags);
      if (diags.limit_reached()) return;
    }
    check_block_numbers(unit, diags);
    check_targets(program, unit, diags);
  }
}

}  // namespace ncc
