// ISO's corners (,C a chamfer and ,R a fillet after a move, §8.3) into a target
// without them: the move is cut short at the corner's first end, and the chamfer's
// line or the fillet's arc is written after it, to where the next block's move then
// goes on. The geometry is the runtime's (runtime/corner.cpp), so the path is the
// one the source's run makes. The next block must be a move in the plane under G90
// whose words are constants: a line written as it stands goes on from the corner's
// second end; an arc gets its centre words from there.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "runtime/corner.h"
#include "structured_impl.h"

namespace ncc::translate {
namespace {

bool is_corner_word(const ir::Word& w) {
  return w.kind == ir::WordKind::Parameter && w.address.size() == 2 && w.address[1] == '\'' &&
         (w.address[0] == 'C' || w.address[0] == 'R');
}

// Only machine words and comments: no jump, call or store between the two moves.
bool plain(const ir::Block& b) {
  return std::all_of(b.stmts.begin(), b.stmts.end(), [](const ir::Stmt& s) {
    return s.kind == ir::StmtKind::Machine || s.kind == ir::StmtKind::Comment;
  });
}

// An element's sweep, an arc's.
double sweep(const corner::Element& e) {
  return arc_sweep(std::atan2(e.a.y() - e.c.y(), e.a.x() - e.c.x()), std::atan2(e.b.y() - e.c.y(), e.b.x() - e.c.x()),
                   e.ccw);
}

}  // namespace

bool Structured::lowers_corner(const ir::Word& w) const { return src_.corners && !dst_.corners && is_corner_word(w); }

bool Structured::looks_ahead(const ir::Program& program, const ir::Block& b) const {
  auto has = [&](Fn fn) {
    return std::any_of(b.words.begin(), b.words.end(), [&](const ir::Word& w) {
      return w.kind == ir::WordKind::Code && w.code >= 0 &&
             program.semantics.codes[static_cast<size_t>(w.code)].calls == std::vector<FnCall>{{fn}};
    });
  };
  // ISO's M06 into NC-110: a G43 H in the block after it goes into its T word.
  const Conventions& src = program.semantics.conventions;
  if (src.tool_change_iso && dst_.corrector_in_tool_word && has(Fn::ToolChange)) return true;
  // A spindle stop the target says with the coolant's only (NC-110's and GOST's M05),
  // where the next block ends the coolant (coolant_ends_next()).
  if (has(Fn::SpindleStop) && !target_code({{Fn::SpindleStop}}, Scope::Modal)) return true;
  return program.semantics.conventions.corners && !dst_.corners &&
         std::any_of(b.words.begin(), b.words.end(), is_corner_word);
}

// The block's own words get the corner's first end on the plane's axes; the words
// of the corner's move are returned. `chained`: where the previous block's corner
// left the tool, the start of this block's move in the target.
std::vector<std::string> Structured::corner_moves(const ir::Word& c, const Position& start,
                                                  const std::optional<std::array<double, 2>>& chained,
                                                  std::vector<std::string>& words) {
  const bool fillet = c.address[0] == 'R';
  auto refuse = [&](const std::string& why) {
    fail(c.range, fmt::format(",{} (a {} after the move): {} has none, and it cannot be written as moves here: {}",
                              c.address[0], fillet ? "fillet" : "chamfer", w_.dialect(), why));
    return std::vector<std::string>{};
  };
  const auto size = constant_of(c.value);
  if (!size) return refuse("its size is a parameter");
  if (!plane_ || !incremental_ || !unit_) return refuse("the plane, G90/G91 or the unit is not known");
  const bool arc = motion_ == Fn::MotionArcCw || motion_ == Fn::MotionArcCcw;
  if (!arc && motion_ != Fn::MotionLinear) return refuse("it follows no feed move");
  const size_t u = plane_u(), v = plane_v();
  const size_t n = static_cast<size_t>(normal_axis() - 'X');
  if (!start[u] || !start[v] || !position_[u] || !position_[v])
    return refuse("the move's start or end is not known (after a label, a call or a computed move)");
  if (start[n] != position_[n]) return refuse(fmt::format("the move goes along {} too, or may", normal_axis()));

  // The next block: a line in the plane under G90, with constant words.
  if (!next_ || !next_->label.empty() || !plain(*block_) || !plain(*next_))
    return refuse("the next block is not known (a label, a jump, a store or the unit's end)");
  Fn next_motion = *motion_;
  bool absolute = !*incremental_, other = false;
  corner::Vec end(*position_[u], *position_[v]), offset(0, 0);
  std::optional<double> radius;
  for (const ir::Word& w : next_->words) {
    if (w.kind == ir::WordKind::Code) {
      if (w.code < 0) return refuse("the next block's codes are chosen at run time");
      for (const FnCall& f : p_->semantics.codes[static_cast<size_t>(w.code)].calls) {
        if (fn_group(f.fn) == FnGroup::Motion)
          next_motion = f.fn;
        else if (f.fn == Fn::DistanceAbsolute)
          absolute = true;
        else if (f.fn == Fn::DistanceIncremental)
          absolute = false;
        else
          other = true;
      }
    } else if (w.kind == ir::WordKind::Parameter) {
      const char letter = w.address.size() == 1 ? w.address[0] : 0;
      const auto value = constant_of(w.value);
      if (letter == 'X' + static_cast<char>(u) && value)
        end.x() = *value;
      else if (letter == 'X' + static_cast<char>(v) && value)
        end.y() = *value;
      else if (letter == 'I' + static_cast<char>(u) && value)
        offset.x() = *value;
      else if (letter == 'I' + static_cast<char>(v) && value)
        offset.y() = *value;
      else if (letter && letter == src_.radius_word && value)
        radius = *value;
      else if (letter != 'F' && !is_corner_word(w))
        other = true;
    }
  }
  const bool next_arc = next_motion == Fn::MotionArcCw || next_motion == Fn::MotionArcCcw;
  if (!next_arc && next_motion != Fn::MotionLinear) return refuse("the next block makes no feed move");
  if (!absolute) return refuse("the next block is incremental, G91 (not written yet)");
  if (other) return refuse("the next block has other words than G01-G03, G90, F and constants of the plane");

  const corner::Vec from = chained ? corner::Vec((*chained)[0], (*chained)[1]) : corner::Vec(*start[u], *start[v]);
  const corner::Vec at(*position_[u], *position_[v]);
  corner::Element in{from, at};
  if (arc) {
    const auto centre = arc_centre(start);
    if (!centre) return refuse("the arc's centre is not known");
    in.arc = true;
    in.c = corner::Vec((*centre)[0], (*centre)[1]);
    in.ccw = motion_ == Fn::MotionArcCcw;
    in.sweep = sweep(in);
  }
  corner::Element next{at, end};
  if (next_arc) {
    next.arc = true;
    next.ccw = next_motion == Fn::MotionArcCcw;
    next.c = at + offset;
    if (radius) {  // the centre the runtime takes (machine_motion.cpp)
      const corner::Vec chord = end - at;
      const double length = chord.norm();
      if (length < 1e-9) return refuse("the next arc by its radius ends where it starts");
      const double h = std::sqrt(std::max(0.0, *radius * *radius - length * length / 4));
      const corner::Vec left(-chord.y() / length, chord.x() / length);
      next.c = (at + end) / 2 + ((!next.ccw) == (*radius < 0) ? 1.0 : -1.0) * h * left;
    }
    next.sweep = sweep(next);
  }
  std::string why;
  const auto cut = corner::cut(in, next, fillet, *size, why);
  if (!cut) return refuse(why);

  // A point's words on the plane's axes, in the mode in force, from `base`.
  auto point = [&](const corner::Vec& p, const corner::Vec& base, std::vector<std::string>& out) {
    for (int k = 0; k < 2; ++k) {
      const char letter = static_cast<char>('X' + (k == 0 ? u : v));
      const double value = *incremental_ ? p[k] - base[k] : p[k];
      const auto text = length(c.range, letter, value);
      if (!text) return;
      // In the place of the block's word of that axis, else after the axes before it.
      const auto same = std::find_if(out.begin(), out.end(), [&](const std::string& o) { return o[0] == letter; });
      if (same != out.end()) {
        *same = letter + *text;
        continue;
      }
      const auto after = std::find_if(out.begin(), out.end(), [&](const std::string& o) {
        return o[0] != 'G' && (std::string_view("XYZ").find(o[0]) == std::string_view::npos || o[0] > letter);
      });
      out.insert(after, letter + *text);
    }
  };
  point(cut->t1, from, words);
  std::vector<std::string> joint;
  const Fn motion = !cut->fillet ? Fn::MotionLinear : cut->ccw ? Fn::MotionArcCcw : Fn::MotionArcCw;
  if (motion != motion_) {
    const auto code = target_code({{motion}}, Scope::Modal);
    if (!code) return refuse(fmt::format("it has no code for {}", fn_name(motion)));
    joint.push_back(code->text());
  }
  point(cut->t2, cut->t1, joint);
  // An arc's centre words in the target's conventions, from its start `base`.
  auto centre = [&](const corner::Vec& p, const corner::Vec& base, bool incremental) {
    std::vector<std::string> out;
    const bool from_start = dst_.arc_centre == ArcCentre::Incremental || incremental;
    for (int k = 0; k < 2; ++k) {
      const char letter = centre_letter(dst_, k);
      if (const auto text = length(c.range, letter, from_start ? p[k] - base[k] : p[k])) out.push_back(letter + *text);
    }
    return out;
  };
  if (cut->fillet) {
    const auto centre_words = centre(cut->centre, cut->t1, *incremental_);
    joint.insert(joint.end(), centre_words.begin(), centre_words.end());
    // The next block's motion needs its code again.
    if (const auto code = target_code({{next_motion}}, Scope::Modal)) restore_motion_ = code->text();
  }
  if (next_arc) centre_override_ = centre(next.c, cut->t2, false);
  chained_start_ = std::array<double, 2>{cut->t2.x(), cut->t2.y()};
  return joint;
}

}  // namespace ncc::translate
