// Canned cycles between dialects whose levels differ (docs/translate.md, decision 21).
// NC-110's cycle block stores the cycle and moves nothing; the blocks after it with a
// position drill; it has two levels, R1 (approach) and R2 (return, R1 unless given).
// ISO's, GOST 20999's and pp's cycle block drills at its own position, from one level
// R; ISO returns to R (G99) or to the level the cycle began at (G98), GOST and pp to
// that level always. A cycle whose moves are the same in both (in at feed, nothing at
// the bottom, out at rapid or at feed, a dwell or not) is written as the target's own,
// its levels converted, where the text says them. A cycle the target drills
// otherwise is written hole by hole as its moves, the runtime's own
// (runtime/cycle_steps.h; decision 25).
#include <cmath>

#include <fmt/format.h>

#include "runtime/cycle_steps.h"
#include "structured_impl.h"

namespace ncc::translate {

bool Structured::converts_cycle_levels() const { return !same_ && src_.cycle_two_levels != dst_.cycle_two_levels; }

// A source cycle code: the target's of the same pattern, the rest of the block read
// by level_word() and written by level_cycle_lines().
void Structured::level_cycle_code(const ir::Word& w, const CyclePattern& pattern) {
  cycle_on_ = true;
  // GOST's and pp's way out at feed goes all the way, NC-110's to R1 and then at rapid.
  const bool all_the_way = !src_.cycle_two_levels && !src_.fanuc_cycles && pattern.out == CyclePattern::Out::Feed;
  if (pattern.in != CyclePattern::In::Feed || pattern.bottom != CyclePattern::Bottom::None ||
      pattern.out == CyclePattern::Out::Manual || all_the_way)
    return moves_cycle_code(w, pattern);
  for (const auto& [number, entry] : w_.tables().g_codes) {
    if (entry.desc.calls.size() != 1 || entry.desc.calls[0].fn != Fn::Cycle) continue;
    const CyclePattern& has = w_.tables().cycles[entry.desc.calls[0].arg];
    if (has.in == pattern.in && has.dwell == pattern.dwell && has.bottom == pattern.bottom && has.out == pattern.out) {
      level_cycle_ = LevelCycle{&pattern, Code{'G', number, &entry}, w.range, {}, {}, {}};
      level_cycles_ = true;
      return;
    }
  }
  moves_cycle_code(w, pattern);
}

void Structured::moves_cycle_code(const ir::Word& w, const CyclePattern& pattern) {
  std::optional<LevelCycle> was = std::exchange(level_cycle_, LevelCycle{&pattern, Code{}, w.range, {}, {}, {}});
  level_cycle_->moves = true;
  level_cycles_ = true;
  cycle_on_ = true;
  // The one-level dialects' registers (and ISO's initial level) hold from the cycle
  // before, up to G80 (ISO's: or a motion code).
  if (was && !src_.cycle_two_levels && !(src_.fanuc_cycles && block_has_motion()))
    level_cycle_->now = was->now, level_cycle_->initial = was->initial;
  // ... which, where the target drills it with its own cycle, ends first.
  if (was && !was->moves)
    if (const auto cancel = target_code({{Fn::CycleCancel}}, Scope::Modal)) lines_before_.push_back(cancel->text());
}

// A dwell of `seconds` as the target's lines: its dwell code with the time, or
// NC-110's G04, which dwells for TMR's time (seconds under G94, at most 60), TMR set
// where it holds another. False, said why, where it has none.
bool Structured::dwell_lines(double seconds, std::vector<std::string>& lines) {
  auto refuse = [&](const std::string& why) { return fail(block_->range, why), false; };
  if (const auto code = target_code({{Fn::Dwell}}, Scope::Block); code && dst_.dwell_word) {
    const OutWord time{dst_.dwell_word, seconds / dst_.dwell_seconds_per_unit, Value::Seconds};
    if (auto why = w_.unwritable(time)) return refuse(*why);
    lines.push_back(code->text() + " " + dst_.dwell_word + number(time, block_->range));
    return true;
  }
  const auto g04 = target_code({{Fn::PathDwellEnd}}, Scope::Block);
  if (!g04) return refuse(fmt::format("a dwell: {} has no dwell with a time", w_.dialect()));
  if (per_minute_ != true)
    return refuse(
        fmt::format("a dwell where the feed may be per revolution: {}'s TMR counts revolutions then", w_.dialect()));
  if (seconds < 0 || seconds > 60)
    return refuse(fmt::format("a dwell of {} s: {}'s TMR holds 0 to 60 s", exact(seconds, false), w_.dialect()));
  if (!timer_ || *timer_ != seconds) lines.push_back("TMR=" + exact(seconds, false));
  timer_ = seconds;
  lines.push_back(g04->text());
  return true;
}

// A block under a cycle written as moves: where it drills (an axis or R word, the
// runtime's rule), its own line goes over the hole at rapid and the hole's moves
// follow in lines of their own (hole_lines_); the levels are constants the text
// says, and so is the level the tool starts at. True where it drills.
bool Structured::hole_moves(const Position& start, std::vector<std::string>& before, std::vector<std::string>& words) {
  LevelCycle& c = *level_cycle_;
  const bool defined_here = std::exchange(c.defined_here, false);
  const LevelCycle::Levels given = std::exchange(c.given, {});
  for (auto [now, was] : {std::pair{&c.now.depth, given.depth},
                          {&c.now.peck, given.peck},
                          {&c.now.dwell, given.dwell},
                          {&c.now.factor, given.factor},
                          {&c.now.minimum, given.minimum}})
    if (was) *now = was;
  const bool two_levels = src_.cycle_two_levels;
  // The drilling axis: the plane's normal (NC-110's is Z here, its cycle block's axis).
  const size_t d = plane_ && !two_levels ? static_cast<size_t>(normal_axis() - 'X') : 2;
  const std::optional<double> z = position_[d];
  if (!two_levels && given.r1) c.now.r1 = given.r1;
  if (two_levels) {  // one R sets both levels, two each; none at the cycle's block: where the tool is
    if (given.r1)
      c.now.r2 = given.r2 ? given.r2 : given.r1, c.now.r1 = given.r1;
    else if (given.r2)
      c.now.r2 = given.r2;
    if (defined_here && !c.now.r1) c.now.r1 = c.now.r2 = z;
  }
  // A hole: an axis word or R (the one-level dialects), an axis word off the drilling
  // axis (NC-110, whose cycle block drills none).
  const bool drills =
      !(two_levels && defined_here) && std::any_of(block_->words.begin(), block_->words.end(), [&](const ir::Word& w) {
        if (w.kind != ir::WordKind::Parameter || w.address.size() != 1) return false;
        const char l = w.address[0];
        return two_levels ? l != 'Z' && src_.axes.find(l) != std::string::npos
                          : src_.axes.find(l) != std::string::npos || l == src_.cycle_level_word;
      });
  c.carry = two_levels && defined_here;  // its block writes nothing: its number goes to the next line
  if (!drills) return false;
  const SourceRange at = defined_here ? c.at : block_->range;
  auto refuse = [&](const std::string& why) { return refuse_moves(at, why); };
  if (!incremental_) return refuse("where G90 or G91 is not known");
  // Under G91 the one-level dialects' R is from the initial level (GOST's, pp's: where
  // the hole begins), the depth from R; the lines then move by increments too.
  const bool relative = *incremental_;
  if (relative && two_levels) return refuse("under G91, where NC-110's levels are increments from the axis' position");
  if (!plane_ || (two_levels && plane_ != 'K'))
    return refuse("where the plane is not known, or NC-110's in another plane than XY");
  if (lowers_frame_ || polar_ != false)
    return refuse("under a rotation, scale, mirror or polar coordinates the target has not");
  if (!unit_) return refuse(unit_unknown());
  if (!z) return refuse("the level the tool starts at is not known");
  if (!c.now.r1 || !c.now.depth) return refuse("without its level R or its depth");
  using In = CyclePattern::In;
  const CyclePattern& pattern = *c.pattern;
  const bool pecks = pattern.in == In::Peck || pattern.in == In::ChipBreak;
  if (pecks && !c.now.peck) return refuse("without its peck depth");
  if (pattern.dwell && !c.now.dwell && !src_.fanuc_cycles && !two_levels) return refuse("without its dwell");
  if (pattern.out == CyclePattern::Out::Manual) return refuse("the operator takes the tool out of the hole by hand");
  if (!spindle_direction_) return refuse("the spindle's direction is not known");
  const double mm = inch_ == true ? 25.4 : 1;  // the source's unit
  std::vector<cycle::Step> steps;
  if (two_levels) {
    cycle::Pecks p{*c.now.r1, *c.now.depth, c.now.peck.value_or(0), 1 / mm, c.now.factor, c.now.minimum};
    if (p.bottom >= p.r1 || *c.now.r2 < p.r1) return refuse("its bottom is not below R1, or R2 lies below R1");
    std::optional<double> n;
    if (pattern.in == In::Peck) {
      double stuck = 0;
      if (p.step <= 0 || p.factor.value_or(1) <= 0 || p.minimum.value_or(0) < 0)
        return refuse("a peck, factor or minimum not above 0");
      n = p.count(stuck);
      if (!n || *n > 1000) return refuse("its pecks never reach the bottom, or are more than 1000");
    }
    // G84: K is a tap synchronised with the spindle; without it the tap feeds at F and
    // comes out at RMS % of it, RMS's 100 at power-on (a program that stores RMS is
    // refused into the others).
    if (pattern.bottom == CyclePattern::Bottom::Reverse && c.now.factor)
      return refuse("a tap synchronised with the spindle (K)");
    cycle::Nc110Hole h{*z, *c.now.r2, p, 0, *spindle_direction_};
    if (pattern.dwell || (n && *n > 1 && !p.unloading())) {  // TMR's seconds, under G94
      if (!timer_ || per_minute_ != true) return refuse("a dwell whose time is not known here (TMR, and G94)");
      h.dwell = *timer_;
    }
    steps = cycle::nc110_hole(pattern, h);
  } else {
    cycle::Hole h;
    h.current = *z;
    if (src_.fanuc_cycles) {
      if (!c.initial) c.initial = z;
      if (!return_initial_) return refuse("where G98 or G99 is not known");
      h.return_level = !*return_initial_;
    } else {
      c.initial = z;
    }
    h.initial = *c.initial;
    h.level = relative ? h.initial + *c.now.r1 : *c.now.r1;
    h.bottom = relative ? h.level + *c.now.depth : *c.now.depth;
    const bool shifts = pattern.bottom == CyclePattern::Bottom::OrientShift;
    if ((pecks || ((pattern.in == In::TapCw || pattern.in == In::TapCcw) && src_.fanuc_cycles)) && c.now.peck) {
      if (*c.now.peck <= 0) return refuse("its peck depth is not above 0");
      if (std::fabs(h.bottom - h.level) / *c.now.peck > 1000) return refuse("more than 1000 pecks");
      h.peck = c.now.peck;
    }
    if (shifts && !c.now.peck) return refuse("without its shift Q");
    if (pattern.dwell) h.dwell = c.now.dwell.value_or(0);
    if (pattern.in == In::Back && h.bottom < h.level) return refuse("G87's bottom lies below R");
    Conventions conv = src_;
    conv.peck_clearance /= mm;
    conv.chip_break_retract /= mm;
    h.shift = shifts ? *c.now.peck * src_.boring_shift : 0;
    h.direction = *spindle_direction_ ? *spindle_direction_ : src_.fanuc_cycles ? 1 : 0;
    steps = src_.fanuc_cycles ? cycle::iso_hole(pattern, h, conv) : cycle::hole(pattern, h);
  }
  return hole_lines(steps, at, start, relative, before, words);
}

bool Structured::refuse_moves(SourceRange at, const std::string& why) {
  fail(at, fmt::format("canned cycle {}: {} has no cycle that drills it so, and its moves cannot be written here: {}",
                       level_cycle_->pattern->name, w_.dialect(), why));
  level_cycle_.reset();
  return false;
}

// A hole's steps as lines: the way up to R first in the block's `before`; the block's
// own line (`words`) over the hole; the rest after it (hole_lines_), by increments
// where `relative`.
bool Structured::hole_lines(const std::vector<cycle::Step>& steps, SourceRange at, const Position& start, bool relative,
                            std::vector<std::string>& before, std::vector<std::string>& words) {
  auto refuse = [&](const std::string& why) { return refuse_moves(at, why); };
  std::vector<std::string> lines;
  std::optional<Fn> written;  // the target's motion code of the line before
  const size_t d = static_cast<size_t>(normal_axis() - 'X'), u = plane_u();  // the drilling axis, the shift's
  const char depth = static_cast<char>('X' + d), across = static_cast<char>('X' + u);
  double shift_written = 0, level_written = *position_[d];  // where the lines before leave the tool
  for (const cycle::Step& s : steps) {
    std::vector<std::string> line;
    switch (s.kind) {
      case cycle::Step::Kind::Over: {
        // Over the hole already (X Y as they were): no move, as in the source.
        auto axis = [&](const std::string& word) { return dst_.axes.find(word[0]) != std::string::npos; };
        if (std::all_of(words.begin(), words.end(), [&](const std::string& word) {
              const size_t i = word[0] >= 'X' && word[0] <= 'Z' ? static_cast<size_t>(word[0] - 'X') : 3;
              return !axis(word) || (i < 3 && i != d && start[i] && position_[i] && *start[i] == *position_[i]);
            }))
          std::erase_if(words, axis);
        const bool position = std::any_of(words.begin(), words.end(), axis);
        for (std::string& l : lines) before.push_back(std::move(l));
        lines.clear();
        if (position) {  // the block's own line with the target's rapid (translated_machine() adds it)
          hole_rapid_ = target_code({{Fn::MotionRapid}}, Scope::Modal);
          if (!hole_rapid_) return refuse("no rapid motion code");
          written = Fn::MotionRapid;
        }
        continue;
      }
      case cycle::Step::Kind::Rapid:
      case cycle::Step::Kind::Feed:
      case cycle::Step::Kind::Tap:
      case cycle::Step::Kind::TapOut: {
        const Fn fn = s.kind == cycle::Step::Kind::Rapid ? Fn::MotionRapid : Fn::MotionLinear;
        if (written != fn) {
          const auto code = target_code({{fn}}, Scope::Modal);
          if (!code) return refuse("no rapid or linear motion code");
          line.push_back(code->text());
          written = fn;
        }
        if (s.shift != shift_written) {
          if (!position_[u] && !relative)
            return refuse("the hole's position is not known, which the shift off the wall moves from");
          const auto x = length(block_->range, across, relative ? s.shift - shift_written : *position_[u] + s.shift);
          if (!x) return level_cycle_.reset(), false;
          line.push_back(across + *x);
          shift_written = s.shift;
        }
        const auto text = length(block_->range, depth, relative ? s.level - level_written : s.level);
        if (!text) return level_cycle_.reset(), false;
        line.push_back(depth + *text);
        level_written = s.level;
        break;
      }
      case cycle::Step::Kind::Dwell:
        if (!dwell_lines(s.seconds, lines)) return level_cycle_.reset(), false;
        continue;
      case cycle::Step::Kind::Spindle: {
        if (!spindle_turns_) return refuse("whether the spindle turns is not known");
        if (!s.always && *spindle_turns_ == cycle::spindle_turns(s.spindle)) continue;
        auto code = target_code({{s.spindle}}, Scope::Modal);
        if (!code) code = code_doing_more({{s.spindle}}, Scope::Modal);  // NC-110's M05 ends a coolant that is off
        if (!code) return refuse(fmt::format("no code for {} alone", fn_name(s.spindle)));
        line.push_back(code->text());
        state({{s.spindle}});  // as the machine's run of the step sets it
        break;
      }
      case cycle::Step::Kind::Manual: return refuse("the operator takes the tool out of the hole by hand");
    }
    std::string text;
    for (const std::string& word : line) text += (text.empty() ? "" : " ") + word;
    lines.push_back(text);
  }
  hole_lines_ = std::move(lines);
  position_[d] = steps.back().level;
  return true;
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
  if (letter == src_.cycle_level_word)
    slot = second ? &given.r2 : &given.r1;
  else if (letter == src_.peck_word && level_cycle_->moves)
    slot = &given.peck;
  else if (letter == src_.peck_factor_word && level_cycle_->moves)
    slot = &given.factor;
  else if (letter == src_.peck_minimum_word && level_cycle_->moves)
    slot = &given.minimum;
  else if (plane_ && letter == normal_axis() && address.size() == 1)
    slot = &given.depth;
  else if (src_.dwell_word && letter == src_.dwell_word)
    slot = &given.dwell;
  else if (letter == src_.peck_word || src_.cycle_repeat_words.find(letter) != std::string::npos)
    return fail(w.range, fmt::format("{}{}: a word of a canned cycle that {} has not", letter, w.text, w_.dialect())),
           true;
  if (!slot) return false;
  *slot = constant_of(w.value);
  if (!*slot)
    fail(w.range, "a canned cycle's level, depth, peck or dwell given by a parameter");
  else if (slot == &given.dwell)
    **slot *= src_.dwell_seconds_per_unit;  // seconds
  return true;
}

// The lines of a block under a converted cycle: `before` its own line, `words` in it.
// `drills`: the block has a position in the plane. True where the words have the
// target's cycle code (the block's motion code).
bool Structured::level_cycle_lines(bool drills, const Position& start, std::vector<std::string>& before,
                                   std::vector<std::string>& words) {
  if (!level_cycle_) return false;
  if (level_cycle_->moves) return hole_moves(start, before, words);
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
  // A hole the target's cycle cannot drill so: its moves, from here on (decision 25),
  // the target's cycle ended first.
  auto as_moves = [&] {
    if (c.written)
      if (const auto cancel = target_code({{Fn::CycleCancel}}, Scope::Modal)) before.push_back(cancel->text());
    c.moves = true;
    c.defined_here = defined_here;
    c.given = given;
    return hole_moves(start, before, words);
  };
  if (incremental_ == true && (defined_here || drills) && !src_.cycle_two_levels) return as_moves();
  if (incremental_ != false && (defined_here || drills))
    return refuse(
        "under G91, or where G90 is not known: the one-level dialects read its R and depth as increments then, "
        "NC-110 as levels");
  if (defined_here && plane_ && plane_ != 'K' && !src_.cycle_two_levels)
    return as_moves();  // NC-110's drills along Z here
  // NC-110's cycle block goes before the block's own, in the unit before its G70 or G71.
  if (defined_here && dst_.cycle_two_levels && (block_has(Fn::UnitsInch) || block_has(Fn::UnitsMm))) return as_moves();
  if (defined_here && plane_ != 'K') return refuse("in another plane than XY, or where the plane is not known");
  // The levels in force after this block's words.
  LevelCycle::Levels& now = c.now;
  if (given.depth) now.depth = given.depth;
  if (given.dwell) now.dwell = given.dwell;
  if (src_.cycle_two_levels) {  // NC-110: one R sets both levels, two each; none at first: where the tool is
    if (given.r1)
      now.r2 = given.r2 ? given.r2 : given.r1, now.r1 = given.r1;
    else if (given.r2)
      now.r2 = given.r2;
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
  if (*now.depth >= *now.r1 || *now.r2 < *now.r1)
    return refuse("its depth is not below R, or its return level is below R");
  // NC-110 (as ISO) feeds out to R1, then goes at rapid to R2; GOST and pp feed all the way.
  auto all_the_way = [](const Conventions& k) { return !k.fanuc_cycles && !k.cycle_two_levels; };
  if (c.pattern->out == CyclePattern::Out::Feed && *now.r2 != *now.r1 && (all_the_way(src_) || all_the_way(dst_)))
    return as_moves();  // one feeds to R and then goes at rapid, the other feeds all the way
  const bool changed = now.r1 != was.r1 || now.r2 != was.r2 || now.depth != was.depth || now.dwell != was.dwell;
  // The one-level dialects go up to R first from a start below it; NC-110 goes over
  // the hole at the level the tool is at.
  if (drills && !c.written && (!z || *z < *now.r1)) return as_moves();  // the dialects go there otherwise
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
    // A level or depth in a block without a position: the source drills where the tool
    // is, NC-110 sets them only; a cycle block without one: NC-110's drills at the
    // blocks after it.
    if ((!defined_here && !drills && changed) || (defined_here && !drills)) return as_moves();
    if (now.dwell && (!timer_ || *timer_ != *now.dwell)) {
      if (per_minute_ != true)
        return refuse("a dwell where the feed may be per revolution: TMR then counts revolutions");
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
    // NC-110's cycle block, and a block of its levels alone, write nothing: the
    // target's are written at the next hole, which takes the block's number.
    c.carry = !drills;
    if (!drills) return false;
    if (c.pattern->dwell) {  // TMR's time (seconds under G94) when the hole is drilled
      if (!timer_ || per_minute_ != true) return refuse("a dwell whose time is not known here (TMR, and G94)");
      c.restate |= c.written && now.dwell != timer_;
      now.dwell = timer_;
    }
    if (!c.written) c.initial = z;
    std::vector<std::string> cycle;
    if (dst_.fanuc_cycles) {
      if (*now.r2 != *now.r1 && now.r2 != c.initial) return as_moves();  // R2 is neither R nor the level it began at
      const auto back =
          target_code({{*now.r2 == *now.r1 ? Fn::CycleReturnLevel : Fn::CycleReturnInitial}}, Scope::Modal);
      if (!back) return refuse(fmt::format("{} has no code for its return level", w_.dialect()));
      if (!c.written || c.restate) cycle.push_back(back->text());
    } else if (now.r2 != c.initial) {
      return as_moves();  // R2 is not the level it began at, where the target's cycles return
    }
    const bool motion = !c.written;
    if (motion) cycle.push_back(c.code.text());
    if (!c.written || c.restate) {
      if (!level_words(cycle, false)) return level_cycle_.reset(), false;
      if (now.dwell) {
        const OutWord time{dst_.dwell_word, *now.dwell / dst_.dwell_seconds_per_unit, Value::Seconds};
        if (!dst_.dwell_word) return refuse(fmt::format("a dwell: {} gives its cycles none", w_.dialect()));
        if (auto why = w_.unwritable(time)) return refuse(*why);
        cycle.push_back(dst_.dwell_word + number(time, block_->range));
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
    fail(block_->range,
         "a move under G91 where a canned cycle may be on: the one-level dialects read its R and depth as "
         "increments then, NC-110 as levels");
}

// The end of a converted cycle: G80, or (ISO) a motion code, which ends it there and
// which NC-110 needs G80 before. After it the target moves in the source's modal
// motion again, which ISO's G80 has ended: the code is written again.
void Structured::end_level_cycle(bool by_motion, std::vector<std::string>& before) {
  if (!level_cycle_) return;
  if (level_cycle_->moves) {  // the moves leave the target in G00 or G01: the source's motion again
    if (!by_motion && motion_)
      if (const auto code = target_code({{*motion_}}, Scope::Modal)) restore_motion_ = code->text();
    if (!by_motion && !motion_)
      fail(block_->range, "the end of a canned cycle written as moves, where the motion code in force is not known");
    return level_cycle_.reset();
  }
  if (by_motion && dst_.cycle_two_levels)
    if (const auto cancel = target_code({{Fn::CycleCancel}}, Scope::Modal)) before.push_back(cancel->text());
  if (!by_motion && dst_.fanuc_cycles && motion_)
    if (const auto code = target_code({{*motion_}}, Scope::Modal)) restore_motion_ = code->text();
  level_cycle_.reset();
}

}  // namespace ncc::translate
