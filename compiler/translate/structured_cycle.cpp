// Canned cycles between dialects whose levels differ (docs/translate.md, decision 21).
// NC-110's cycle block stores the cycle and moves nothing; the blocks after it with a
// position drill; it has two levels, R1 (approach) and R2 (return, R1 unless given).
// ISO's, GOST 20999's and pp's cycle block drills at its own position, from one level
// R; ISO returns to R (G99) or to the level the cycle began at (G98), GOST and pp to
// that level always. A cycle whose moves are the same in both (in at feed, nothing at
// the bottom, out at rapid or at feed, a dwell or not) is written as the target's own,
// its levels converted, where the text says them; any other is refused.
#include <cmath>

#include <fmt/format.h>

#include "structured_impl.h"

namespace ncc::translate {

bool Structured::converts_cycle_levels() const { return !same_ && src_.cycle_two_levels != dst_.cycle_two_levels; }

// A source cycle code: the target's of the same pattern, the rest of the block read
// by level_word() and written by level_cycle_lines().
void Structured::level_cycle_code(const ir::Word& w, const CodeDesc& desc, const CyclePattern& pattern) {
  level_cycle_.reset();
  cycle_on_ = true;
  if (pattern.in != CyclePattern::In::Feed || pattern.bottom != CyclePattern::Bottom::None ||
      pattern.out == CyclePattern::Out::Manual)
    return fail(w.range, fmt::format("canned cycle {}: {} drills, turns or pecks it otherwise; --flatten writes its moves",
                                     desc.name, w_.dialect()));
  for (const auto& [number, entry] : w_.tables().g_codes) {
    if (entry.desc.calls.size() != 1 || entry.desc.calls[0].fn != Fn::Cycle) continue;
    const CyclePattern& has = w_.tables().cycles[entry.desc.calls[0].arg];
    if (has.in == pattern.in && has.dwell == pattern.dwell && has.bottom == pattern.bottom && has.out == pattern.out) {
      level_cycle_ = LevelCycle{&pattern, Code{'G', number, &entry}, w.range, {}, {}, {}};
      level_cycles_ = true;
      return;
    }
  }
  fail(w.range, fmt::format("canned cycle {}: {} has no cycle of its pattern", desc.name, w_.dialect()));
}

// A word of a block under a converted cycle that the cycle says (its levels, depth,
// dwell), kept for level_cycle_lines(); true when taken. Any other word but the
// position's goes as usual.
bool Structured::level_word(const ir::Word& w) {
  if (!level_cycle_ || w.kind != ir::WordKind::Parameter || w.address.empty()) return false;
  const std::string address = w.address.str();
  const char letter = address[0];
  const bool second = address.size() == 2 && address[1] == '\'';
  LevelCycle::Levels& given = level_cycle_->given;
  std::optional<double>* slot = nullptr;
  if (letter == src_.cycle_level_word) slot = second ? &given.r2 : &given.r1;
  else if (plane_ && letter == normal_axis() && address.size() == 1) slot = &given.depth;
  else if (src_.dwell_word && letter == src_.dwell_word) slot = &given.dwell;
  else if (letter == src_.peck_word || src_.cycle_repeat_words.find(letter) != std::string::npos)
    return fail(w.range, fmt::format("{}{}: a word of a canned cycle that {} has not", letter, w.text, w_.dialect())), true;
  if (!slot) return false;
  *slot = constant_of(w.value);
  if (!*slot) fail(w.range, "a canned cycle's level, depth or dwell given by a parameter");
  else if (slot == &given.dwell) **slot *= src_.dwell_seconds_per_unit;  // seconds
  return true;
}

// The lines of a block under a converted cycle: `before` its own line, `words` in it.
// `drills`: the block has a position in the plane. True where the words have the
// target's cycle code (the block's motion code).
bool Structured::level_cycle_lines(bool drills, std::vector<std::string>& before, std::vector<std::string>& words) {
  if (!level_cycle_) return false;
  LevelCycle& c = *level_cycle_;
  const bool defined_here = std::exchange(c.defined_here, false);
  const LevelCycle::Levels given = std::exchange(c.given, {});
  const LevelCycle::Levels was = c.now;
  const std::optional<double> z = position_[2];
  auto refuse = [&](const std::string& why) {
    fail(defined_here ? c.at : block_->range, "canned cycle " + c.code.text() + ": " + why);
    level_cycle_.reset();
    return false;
  };
  if (incremental_ != false && (defined_here || drills))
    return refuse("under G91, or where G90 is not known: the one-level dialects read its R and depth as increments then, "
                  "NC-110 as levels");
  if (defined_here && plane_ != 'K') return refuse("in another plane than XY, or where the plane is not known");
  // The levels in force after this block's words.
  LevelCycle::Levels& now = c.now;
  if (given.depth) now.depth = given.depth;
  if (given.dwell) now.dwell = given.dwell;
  if (src_.cycle_two_levels) {  // NC-110: one R sets both levels, two each; none at first: where the tool is
    if (given.r1) now.r2 = given.r2 ? given.r2 : given.r1, now.r1 = given.r1;
    else if (given.r2) now.r2 = given.r2;
    if (defined_here && !now.r1) now.r1 = now.r2 = z;
  } else {  // the return level: ISO's G98 or G99; GOST's and pp's is where the cycle began
    if (given.r1) now.r1 = given.r1;
    if (defined_here) c.initial = z;
    const std::optional<bool> initial = src_.fanuc_cycles ? return_initial_ : true;
    if (initial == std::nullopt) return refuse("where G98 or G99 is not known");
    if (*initial && !c.initial) return refuse("returning to the level it begins at, which the text does not say here");
    now.r2 = *initial ? c.initial : now.r1;
  }
  if (!now.r1 || !now.depth) return refuse("without its level R or its depth, or where the tool's level is not known");
  if (c.pattern->dwell && !now.dwell && !src_.cycle_two_levels) return refuse("a dwell without its time");
  if (*now.depth >= *now.r1 || *now.r2 < *now.r1) return refuse("its depth is not below R, or its return level is below R");
  // NC-110 (as ISO) feeds out to R1, then goes at rapid to R2; GOST and pp feed all the way.
  auto all_the_way = [](const Conventions& k) { return !k.fanuc_cycles && !k.cycle_two_levels; };
  if (c.pattern->out == CyclePattern::Out::Feed && *now.r2 != *now.r1 && (all_the_way(src_) || all_the_way(dst_)))
    return refuse("its way out: one feeds to R and then goes at rapid, the other feeds all the way");
  const bool changed = now.r1 != was.r1 || now.r2 != was.r2 || now.depth != was.depth || now.dwell != was.dwell;
  // The one-level dialects go up to R first from a start below it; NC-110 goes over
  // the hole at the level the tool is at.
  if (drills && !c.written && (!z || *z < *now.r1))
    return refuse("its first hole starts below R, or where the tool's level is not known: the dialects go there otherwise");
  auto level_words = [&](std::vector<std::string>& out, bool both) {
    for (const auto& [letter, v] : {std::pair{dst_.cycle_level_word, *now.r1}, std::pair{'Z', *now.depth}}) {
      const auto text = length(c.at, letter, v);
      if (!text) return false;
      out.push_back(letter + *text);
      if (both && letter == dst_.cycle_level_word && *now.r2 != *now.r1) {
        const auto back = length(c.at, letter, *now.r2);
        if (!back) return false;
        out.push_back(letter + *back);
      }
    }
    return true;
  };
  if (dst_.cycle_two_levels) {  // into NC-110: the cycle's block (or its levels again), then the position drills
    if (!defined_here && !drills && changed)
      return refuse(fmt::format("a level or depth in a block without a position: {} drills where the tool is, {} sets "
                                "them only", p_->dialect, w_.dialect()));
    if (defined_here && !drills)
      return refuse(fmt::format("a cycle block without a position: {}'s cycle drills at the blocks after its own", w_.dialect()));
    if (now.dwell && (!timer_ || *timer_ != *now.dwell)) {
      if (per_minute_ != true) return refuse("a dwell where the feed may be per revolution: TMR then counts revolutions");
      before.push_back("TMR=" + exact(*now.dwell, false));
      timer_ = now.dwell;
    }
    if (defined_here || changed) {
      std::vector<std::string> define;
      if (defined_here) define.push_back(c.code.text());
      if (!level_words(define, true)) return level_cycle_.reset(), false;  // length() said why
      std::string line;
      for (const std::string& word : define) line += (line.empty() ? "" : " ") + word;
      before.push_back(line);
    }
    c.written |= drills;
  } else {  // from NC-110: a hole drills with the target's cycle block, or its levels again
    c.restate |= c.written && changed;
    c.carry = defined_here;  // NC-110's cycle block writes nothing: the target's is written at its first hole
    if (!drills) return false;
    if (c.pattern->dwell) {  // TMR's time (seconds under G94) when the hole is drilled
      if (!timer_ || per_minute_ != true) return refuse("a dwell whose time is not known here (TMR, and G94)");
      c.restate |= c.written && now.dwell != timer_;
      now.dwell = timer_;
    }
    if (!c.written) c.initial = z;
    std::vector<std::string> cycle;
    if (dst_.fanuc_cycles) {
      if (*now.r2 != *now.r1 && now.r2 != c.initial)
        return refuse("returning to R2, which is neither R nor the level the cycle began at");
      const auto back = target_code({{*now.r2 == *now.r1 ? Fn::CycleReturnLevel : Fn::CycleReturnInitial}}, Scope::Modal);
      if (!back) return refuse(fmt::format("{} has no code for its return level", w_.dialect()));
      if (!c.written || c.restate) cycle.push_back(back->text());
    } else if (now.r2 != c.initial) {
      return refuse(fmt::format("returning to R2, which is not the level the cycle began at ({}'s cycles return there)",
                                w_.dialect()));
    }
    const bool motion = !c.written;
    if (motion) cycle.push_back(c.code.text());
    if (!c.written || c.restate) {
      if (!level_words(cycle, false)) return level_cycle_.reset(), false;
      if (now.dwell) {
        const OutWord time{dst_.dwell_word, *now.dwell / dst_.dwell_seconds_per_unit, Value::Seconds};
        if (!dst_.dwell_word) return refuse(fmt::format("a dwell: {} gives its cycles none", w_.dialect()));
        if (auto why = w_.unwritable(time)) return refuse(*why);
        cycle.push_back(dst_.dwell_word + w_.number(time));
      }
    }
    words.insert(words.begin(), cycle.begin(), cycle.end());
    c.written = true;
    c.restate = false;
    position_[2] = now.r2;  // the tool ends each hole at the return level
    return motion;
  }
  if (drills) position_[2] = now.r2;
  return false;
}

// A hole where a converted cycle may be on but is not known from the text (after a
// label or a call): G91 reads the cycle's levels otherwise in the two.
void Structured::unknown_level_cycle(bool moves) {
  if (level_cycles_ && !level_cycle_ && moves && cycle_on_ == std::nullopt && incremental_ != false)
    fail(block_->range, "a move under G91 where a canned cycle may be on: the one-level dialects read its R and depth as "
                        "increments then, NC-110 as levels");
}

// The end of a converted cycle: G80, or (ISO) a motion code, which ends it there and
// which NC-110 needs G80 before. After it the target moves in the source's modal
// motion again, which ISO's G80 has ended: the code is written again.
void Structured::end_level_cycle(bool by_motion, std::vector<std::string>& before) {
  if (!level_cycle_) return;
  if (by_motion && dst_.cycle_two_levels)
    if (const auto cancel = target_code({{Fn::CycleCancel}}, Scope::Modal)) before.push_back(cancel->text());
  if (!by_motion && dst_.fanuc_cycles && motion_)
    if (const auto code = target_code({{*motion_}}, Scope::Modal)) restore_motion_ = code->text();
  level_cycle_.reset();
}

}  // namespace ncc::translate
