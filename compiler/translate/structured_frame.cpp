// Rotation, scaling and mirroring (ISO G68/G51, NC-110 URT/SCF/MIR, pp G36) into a
// target that lacks one of them: the frame is kept here, and every point it moves is
// written where the source's run takes it (runtime/machine_frame.cpp: scale and
// mirror about the scaling centre, then the rotation about its centre in the plane of
// the move). All frames of the program are lowered together, so that no transform of
// the target's acts on points this translation has transformed already.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "contract/word_slots.h"
#include "structured_impl.h"

namespace ncc::translate {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
constexpr double kNotKnown = std::numeric_limits<double>::quiet_NaN();

// The functions whose words are their operands, not a move.
bool defines_frame(Fn fn) { return is_frame(fn) && fn != Fn::ScalingOff && fn != Fn::RotationOff; }

}  // namespace

bool is_frame(Fn fn) {
  switch (fn) {
    case Fn::Mirror:
    case Fn::Rotation:
    case Fn::Scale:
    case Fn::ScaleAxes:
    case Fn::ScalingOn:
    case Fn::ScalingOff:
    case Fn::RotationOn:
    case Fn::RotationOff: return true;
    default: return false;
  }
}

bool Structured::Frame::moves(size_t axis, size_t u, size_t v) const {
  return scale[axis] != 1 || mirror[axis] || (rotation != 0 && (axis == u || axis == v));
}

std::array<double, 3> Structured::Frame::apply(std::array<double, 3> p, size_t u, size_t v) const {
  for (size_t i = 0; i < 3; ++i)
    if (scale[i] != 1 || mirror[i])
      p[i] = scale_centre[i] + (p[i] - scale_centre[i]) * (mirror[i] ? -scale[i] : scale[i]);
  if (rotation != 0) {
    const double c = std::cos(rotation * kDegree), s = std::sin(rotation * kDegree);
    const double x = p[u] - rotation_centre[0], y = p[v] - rotation_centre[1];
    p[u] = rotation_centre[0] + x * c - y * s;
    p[v] = rotation_centre[1] + x * s + y * c;
  }
  return p;
}

std::array<double, 3> Structured::Frame::invert(std::array<double, 3> q, size_t u, size_t v) const {
  if (rotation != 0) {
    const double c = std::cos(rotation * kDegree), s = std::sin(rotation * kDegree);
    const double x = q[u] - rotation_centre[0], y = q[v] - rotation_centre[1];
    q[u] = rotation_centre[0] + x * c + y * s;
    q[v] = rotation_centre[1] - x * s + y * c;
  }
  for (size_t i = 0; i < 3; ++i)
    if (scale[i] != 1 || mirror[i])
      q[i] = scale_centre[i] + (q[i] - scale_centre[i]) / (mirror[i] ? -scale[i] : scale[i]);
  return q;
}

bool Structured::lowers_frame(const CodeDesc& desc) const {
  return lowers_frame_ &&
         std::any_of(desc.calls.begin(), desc.calls.end(), [](const FnCall& c) { return is_frame(c.fn); });
}

// A frame code: the frame it leaves, and the program coordinates of the tool's
// position in it (the tool does not move).
void Structured::frame_code(const ir::Word& w, const CodeDesc& desc) {
  const std::optional<Frame> before = frame_;
  auto refuse = [&](std::string why) {
    frame_ = Frame{};  // (the translation is refused: its moves are not refused again)
    position_ = {};
    fail(w.range, fmt::format("{} {}: {} has no such frame, and it cannot be written in X Y Z here", desc.name, why,
                              w_.dialect()));
  };
  // The block's word of a letter, or operand n: absent, or its constant.
  std::optional<const ir::Word*> bad;
  auto find = [&](auto match) -> std::optional<double> {
    for (const ir::Word& o : block_->words)
      if (o.kind == ir::WordKind::Parameter && match(o)) {
        if (auto v = constant_of(o.value)) return v;
        bad = &o;
      }
    return std::nullopt;
  };
  auto letter = [&](char l) {
    return find([&](const ir::Word& o) { return o.address.size() == 1 && o.address[0] == l; });
  };
  auto listed = [&]() {  // the axes a code names (NC-110's MIR, SCF; pp's G36)
    std::vector<size_t> axes;
    for (const ir::Word& o : block_->words)
      if (o.kind == ir::WordKind::Parameter && o.slot < operand_slot(0) && o.address.size() == 1 &&
          src_.axes.find(o.address[0]) != std::string::npos)
        axes.push_back(static_cast<size_t>(std::string_view("XYZ").find(o.address[0])));  // npos: another axis
    return axes;
  };
  Position here = position_;
  std::array<double, 3> at{};
  for (size_t i = 0; i < 3; ++i) at[i] = here[i].value_or(kNotKnown);
  for (const FnCall& call : desc.calls) {
    if (!is_frame(call.fn)) continue;
    operand_words_ |= defines_frame(call.fn);
    if (!frame_) return refuse("where the frame in force is not known (after a label, a call or a computed value)");
    Frame& f = *frame_;
    switch (call.fn) {
      case Fn::RotationOff: f.rotation = 0, f.rotation_centre = {}; break;
      case Fn::ScalingOff: f.scale = {1, 1, 1}, f.mirror = {}, f.scale_centre = {}, f.scales_others = false; break;
      case Fn::Rotation:  // NC-110: about the origin
        if (auto a = find([](const ir::Word& o) { return o.slot == operand_slot(0); }))
          f.rotation = *a, f.rotation_centre = {};
        break;
      case Fn::Scale: {  // NC-110 (SCF,n[,axes]): n on those, every linear axis when none
        const auto n = find([](const ir::Word& o) { return o.slot == operand_slot(0); });
        const auto axes = listed();
        f.scale = {1, 1, 1};
        f.scales_others = n && *n != 1 &&
                          (axes.empty() ? src_.axes.find_first_of("UVW") != std::string::npos
                                        : std::count(axes.begin(), axes.end(), std::string_view::npos) > 0);
        for (size_t i = 0; i < 3; ++i)
          if (axes.empty() || std::find(axes.begin(), axes.end(), i) != axes.end()) f.scale[i] = n.value_or(1);
        break;
      }
      case Fn::Mirror: {
        const auto axes = listed();
        if (axes.empty()) f.mirror = {};
        for (size_t i : axes)
          if (i == std::string_view::npos)
            f.scales_others = true;
          else
            f.mirror[i] = src_.mirror_toggles ? !f.mirror[i] : true;
        break;
      }
      case Fn::ScaleAxes: {  // pp G36: the named axes' factors, 1 on the others
        const auto axes = listed();
        f.scale = {1, 1, 1};
        for (size_t i = 0; i < 3; ++i)
          if (auto v = letter(static_cast<char>('X' + i))) f.scale[i] = *v;
        f.scales_others = std::count(axes.begin(), axes.end(), std::string_view::npos) > 0;
        break;
      }
      case Fn::ScalingOn: {  // ISO G51: about the words' point (G91: from the position), else the position
        if (!incremental_) return refuse("where G90 or G91 is not known");
        std::array<double, 3> centre = at, factor{1, 1, 1};
        for (size_t i = 0; i < 3; ++i)
          if (auto v = letter(static_cast<char>('X' + i))) centre[i] = *incremental_ ? at[i] + *v : *v;
        const auto all = letter('P');
        for (size_t i = 0; i < 3; ++i) {
          factor[i] = all.value_or(1);
          if (auto v = letter(static_cast<char>('I' + i))) factor[i] = *v;
        }
        for (size_t i = 0; i < 3; ++i) {
          f.scale[i] = std::fabs(factor[i]), f.mirror[i] = factor[i] < 0;
          f.scale_centre[i] = factor[i] == 1 ? 0 : centre[i];  // (an axis not scaled needs no centre)
        }
        break;
      }
      case Fn::RotationOn: {  // ISO G68: about the words' point in the plane, else the position
        if (!plane_ || !incremental_) return refuse("where the plane or G90/G91 is not known");
        const size_t u = plane_u(), v = plane_v();
        std::array<double, 3> centre = at;
        for (size_t i : {u, v})
          if (auto c = letter(static_cast<char>('X' + i))) centre[i] = *incremental_ ? at[i] + *c : *c;
        const auto r = letter('R');
        if (!r) return refuse(bad ? "with its angle R given by a parameter" : "without R");
        for (size_t i = 0; i < 3; ++i)  // a programmed point: scaled as the path is
          if (f.scale[i] != 1 || f.mirror[i])
            centre[i] = f.scale_centre[i] + (centre[i] - f.scale_centre[i]) * (f.mirror[i] ? -f.scale[i] : f.scale[i]);
        f.rotation = *incremental_ ? last_rotation_ + *r : *r;
        last_rotation_ = f.rotation;
        f.rotation_centre = {centre[u], centre[v]};
        break;
      }
      default: break;
    }
    if (bad) return refuse(fmt::format("given by a parameter ({})", (*bad)->address.str()));
    if (std::isnan(f.rotation_centre[0] + f.rotation_centre[1]) ||
        std::any_of(f.scale_centre.begin(), f.scale_centre.end(), [](double c) { return std::isnan(c); }))
      return refuse("about the tool's position, which is not known here");
  }
  // The tool stays where it is: its program coordinates in the new frame.
  if (!plane_) {
    if (before->rotation != 0 || frame_->rotation != 0) position_ = {};
    return;
  }
  const size_t u = plane_u(), v = plane_v();
  const auto p = frame_->invert(before->apply(at, u, v), u, v);
  for (size_t i = 0; i < 3; ++i) position_[i] = std::isnan(p[i]) ? std::nullopt : std::optional<double>(p[i]);
}

// Whether the block's move is written transformed: a frame is lowered and in force
// (or not known) on an axis of the move.
bool Structured::framed(bool moves) const {
  if (!lowers_frame_ || !moves) return false;
  if (!frame_ || !plane_) return true;
  for (size_t i = 0; i < 3; ++i)
    if (frame_->moves(i, plane_u(), plane_v())) return true;
  return false;
}

// Whether the frame decides an axis's coordinate in a framed block: an axis it moves,
// and an arc's plane, whose centre it maps (every axis where the frame is not known).
bool Structured::framed_axis(size_t axis, bool arc) const {
  if (!frame_ || !plane_) return true;
  return frame_->moves(axis, plane_u(), plane_v()) || (arc && (axis == plane_u() || axis == plane_v()));
}

// The move as the frame maps it, in the target's program coordinates: every axis the
// frame moves that the block writes or whose coordinate changes, and an arc's centre
// (the arc turned the other way where one axis of its plane is mirrored: the motion
// code in `arc_code`).
void Structured::framed_move(const Position& start, bool arc, std::vector<std::string>& words, std::string& arc_code) {
  const SourceRange at = block_->range;
  const std::string name = std::string(w_.dialect());
  if (!frame_)
    return fail(at, fmt::format("a move where the rotation, scale or mirror in force is not known (after a label, a "
                                "call or a computed value): {} has none",
                                name));
  if (!plane_ || !incremental_ || !unit_)
    return fail(at, fmt::format("a move under a rotation, scale or mirror where the plane, "
                                "G90/G91 or the unit is not known: {} has none",
                                name));
  if (cycle_on_ != false || comp_on_ != false)
    return fail(
        at, fmt::format("a canned cycle or cutter compensation under a rotation, scale or mirror: {} has none", name));
  const size_t u = plane_u(), v = plane_v();
  std::array<double, 3> p0{}, p1{};
  for (size_t i = 0; i < 3; ++i) {
    if (!framed_axis(i, arc)) continue;
    if (!start[i] || !position_[i])
      return fail(
          at, fmt::format("a move under a rotation, scale or mirror, where the tool's position is not known (after a "
                          "label, a call or a computed move): {} has none",
                          name));
    p0[i] = *start[i], p1[i] = *position_[i];
  }
  const auto q0 = frame_->apply(p0, u, v), q1 = frame_->apply(p1, u, v);
  const double unit = *unit_;
  bool rounded = false;
  auto target = [&](double x) {  // a coordinate as the target reads it
    rounded |= off_step(x * unit);
    return on_step(x * unit);
  };
  for (size_t i = 0; i < 3; ++i) {
    if (!framed_axis(i, arc)) continue;
    const char letter = static_cast<char>('X' + i);
    const bool written = std::any_of(block_->words.begin(), block_->words.end(), [&](const ir::Word& w) {
      return w.kind == ir::WordKind::Parameter && w.address.size() == 1 && w.address[0] == letter;
    });
    const double from = target(q0[i]), to = target(q1[i]);
    if (written || from != to)
      words.push_back(letter + w_.number({letter, *incremental_ ? to - from : to, Value::Length}));
  }
  if (arc) {
    if (frame_->scale[u] != frame_->scale[v])
      return fail(at, fmt::format("an arc under scale factors that differ on {} and {}: the path is no circle",
                                  char('X' + u), char('X' + v)));
    const size_t n = static_cast<size_t>(normal_axis() - 'X');
    if (frame_->moves(n, u, v) ? target(q0[n]) != target(q1[n]) : start[n] != position_[n])
      return fail(at, fmt::format("a helix under a rotation, scale or mirror: {} has none", name));
    const auto centre = arc_centre(start);
    if (!centre)
      return fail(
          at,
          fmt::format("an arc under a rotation, scale or mirror whose centre is not known here: {} has none", name));
    std::array<double, 3> c = p0;
    c[u] = (*centre)[0], c[v] = (*centre)[1];
    const auto qc = frame_->apply(c, u, v);
    for (int k = 0; k < 2; ++k) {
      const size_t axis = k == 0 ? u : v;
      const char to = centre_letter(dst_, k);
      const bool from_start = dst_.arc_centre == ArcCentre::Incremental || *incremental_;
      words.push_back(
          to + w_.number({to, from_start ? target(qc[axis]) - target(q0[axis]) : target(qc[axis]), Value::Length}));
    }
    on_circle({target(q0[u]), target(q0[v])}, {target(q1[u]), target(q1[v])}, {target(qc[u]), target(qc[v])});
  }
  if (rounded) problems.push_back({at, "rounded", Finding::Rounded});
  if (arc) {
    const bool flip = frame_->mirror[u] != frame_->mirror[v];
    const Fn way = (motion_ == Fn::MotionArcCw) != flip ? Fn::MotionArcCw : Fn::MotionArcCcw;
    if (auto code = target_code({{way}}, Scope::Modal)) arc_code = code->text();
    flipped_ = flip;
  }
}

}  // namespace ncc::translate
