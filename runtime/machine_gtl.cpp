// GTL (NC-110 §2.11) in the block cycle: definitions into the store, and the blocks of
// a profile into gtl::Profile, whose pieces become moves one element late, each
// shown as a move of the block it belongs to. The geometry is runtime/gtl*.cpp.
#include <cmath>
#include <deque>

#include "gtl_profile.h"
#include "machine.h"
#include "support/text.h"

namespace ncc {

// A block of the open profile, kept until its pieces have moved: where its axes
// outside the plane go (program coordinates, mm) and its feed.
struct Machine::GtlState {
  gtl::Store store;
  gtl::Profile profile;
  struct Block {
    uint32_t source = 0;
    AxisValues others{};
    uint32_t axes = 0;  // bit i: axis i is written
    std::optional<double> feed;
  };
  std::deque<Block> blocks;
  size_t first_tag = 0;    // the tag of blocks.front()
  uint32_t opened_at = 0;  // the G21 block
  bool refused = false;    // a block of the profile failed: G20 ends it quietly
};

// (The state's type is complete only here: the deleter keeps Eigen out of machine.h.)
void Machine::GtlDelete::operator()(GtlState* s) const { std::default_delete<GtlState>()(s); }
void Machine::gtl_init() { gtl_.reset(std::make_unique<GtlState>().release()); }

bool Machine::gtl_open() const { return gtl_->profile.active(); }

namespace {

gtl::Kind kind_of(char letter) {
  return letter == 'o'   ? gtl::Kind::Origin
         : letter == 'p' ? gtl::Kind::Point
         : letter == 'l' ? gtl::Kind::Line
                         : gtl::Kind::Circle;
}

}  // namespace

double Machine::gtl_tolerance() const { return to_program(config_.gtl_tolerance); }

void Machine::gtl_define(uint16_t arg) {
  const gtl::Shape shape = gtl::Shape::unpack(arg);
  // (A bytecode file may hold a shape the compiler does not make.)
  if (std::string why = gtl::form_error(shape, false); !why.empty() || shape.value_count() > kOperandSlots)
    return report(DiagId::GtlGeometry, 0, std::string(1, gtl::letter(shape.target)),
                  why.empty() ? "too many operands" : why);
  std::vector<double> values;
  for (size_t i = 0; i < shape.value_count(); ++i) values.push_back(slot_value(operand_slot(static_cast<int>(i))));
  const char letter = gtl::letter(shape.target);
  const auto index = whole_in(values[0], 0, gtl::kMaxIndex);
  if (!index) {
    report_slot(DiagId::ValueRange, operand_slot(0), fmt::format("{}{}", letter, shortest(values[0])),
                std::string(1, letter), "0", std::to_string(gtl::kMaxIndex));
    return;
  }
  gtl::Result r = gtl::define(shape, values, gtl_->store, gtl::Tolerance{gtl_tolerance()}, kAxisLetters, modal_.plane.u,
                              modal_.plane.v);
  if (!r.element) {
    gtl_->store.fail(shape.target, *index);
    if (!r.why.empty()) report(DiagId::GtlGeometry, 0, fmt::format("{}{}", letter, *index), r.why);
    return;
  }
  gtl_->store.set(*index, *r.element);
}

bool Machine::gtl_field(int kind, double index, double field, double& out) const {
  const auto n = whole_in(index, 0, gtl::kMaxIndex);
  const gtl::Element* e = n ? gtl_->store.find(static_cast<gtl::Kind>(kind), *n) : nullptr;
  if (!e) return false;
  switch (e->kind) {
    case gtl::Kind::Point: out = field == 1 ? e->at.x() : e->at.y(); break;
    case gtl::Kind::Circle: out = field == 1 ? e->at.x() : field == 2 ? e->at.y() : e->r; break;
    default:
      // FEL: the sine and cosine of the line's angle, and its distance from the zero,
      // positive when the zero lies to its right: the points X with left(dir).X = FEL3.
      out = field == 1 ? e->dir.y() : field == 2 ? e->dir.x() : gtl::left(e->dir).dot(e->at);
      break;
  }
  return true;
}

void Machine::gtl_block() {
  GtlState& g = *gtl_;
  const bool opens = block_has(Fn::GtlOpen), closes = block_has(Fn::GtlClose);
  const int u = modal_.plane.u, v = modal_.plane.v;
  // A block that fails ends the profile's moves (its other errors would follow from
  // this one): the blocks up to G20 are read, not run.
  auto refuse = [&](char word, const std::string& why) {
    g.profile.abandon();
    g.refused = true;
    report(DiagId::GtlProfile, word, why);
  };
  for (char f : {'u', 'v', 'w'})
    if (has(f))
      return refuse(
          f, fmt::format("{}{} corrects a point by the tool's radius; a GTL profile offsets its elements itself (§2.9)",
                         f, shortest(word(f))));
  char element = 0;
  for (char l : {'p', 'l', 'c'})
    if (has(l)) {
      if (element)
        return refuse(l, fmt::format("a block of a profile names one element; this one names {}{} and {}{}", element,
                                     shortest(word(element)), l, shortest(word(l))));
      element = l;
    }
  const bool fillet = has('r'), chamfer = has('b');
  if ((fillet || chamfer) && (element || opens || closes))
    return refuse(fillet ? 'r' : 'b',
                  "a fillet r or a chamfer b stands in a block of its own, between two elements (§2.11.9)");
  if (fillet && chamfer) return refuse('b', "one connection joins two elements: r or b, not both");
  GtlState::Block block{block_.request->source, {}, 0, feed_};
  const AxisValues to = program_target();
  for (char letter : conv_.axes) {
    if (!has(letter)) continue;
    const int i = axis_index(letter);
    if (i == u || i == v)
      return refuse(letter, fmt::format("{} is an axis of the profile's plane {}: its elements give the path there; "
                                        "a block of a profile moves only the other axes (§2.8.6)",
                                        letter, plane_name(modal_.plane)));
    block.others[i] = to[i];
    block.axes |= 1u << i;
  }
  if (!opens && (!g.profile.active() || g.profile.failed())) {
    for (char l : {'p', 'l', 'c', 's', 'r', 'b'})
      if (has(l)) word(l);
    if (closes) {
      if (!g.profile.active() && !g.refused)
        report(DiagId::GtlProfile, 0, "G20 closes a GTL profile; none is open: G21 opens one (§2.11.8)");
      g.profile = gtl::Profile{};
      g.refused = false;
      flush_compensation();
      if (kernel_.path()) kernel_.path()->resume();
    }
    return;
  }
  if (opens && g.profile.active()) return refuse(0, "a profile is open: G20 closes it before G21 opens another");
  if (opens && !modal_.absolute) return refuse(0, "GTL works with absolute dimensions only: G91 is in force (§2.8.10)");
  std::optional<gtl::Element> named;
  int index = 0;
  if (element) {
    const double written = word(element);
    auto n = whole_in(written, 0, gtl::kMaxIndex);
    const gtl::Element* e = n ? g.store.find(kind_of(element), *n) : nullptr;
    if (!e) {
      g.profile.abandon();
      g.refused = true;
      if (n && g.store.failed(kind_of(element), *n)) return;  // its definition's error said it
      return report(DiagId::GtlElementUndefined, element, std::string(1, element), shortest(written));
    }
    named = *e;
    index = *n;
  }
  const bool s2 = has('s') && word('s') == 2;
  const size_t tag = g.first_tag + g.blocks.size();
  g.blocks.push_back(block);
  const gtl::ElementId id{named ? named->kind : gtl::Kind::Point, index};
  if (opens) {
    if (!named)
      return refuse(0,
                    "G21 names the profile's first point p.. (an open profile) or its last element l.. or c.. "
                    "(a closed one) (§2.11.8)");
    const Compensation c = compensation();
    const double radius = c.side ? to_program(c.radius) + system_value(SysVar::Allowance) : 0;
    const int side = c.side == 1 ? 1 : c.side == 2 ? -1 : 0;
    g.opened_at = block.source;
    if (kernel_.path()) kernel_.path()->suspend();  // the profile offsets its elements itself
    if (named->kind == gtl::Kind::Point)
      g.profile.open_at(named->at, tag, side, radius, gtl::Tolerance{gtl_tolerance()});
    else
      g.profile.open_closed(*named, id, s2, tag, side, radius, gtl::Tolerance{gtl_tolerance()});
  } else if (closes) {
    if (!named)
      return refuse(0,
                    "G20 names the profile's last point p.. (an open profile) or its first element again "
                    "(a closed one) (§2.11.8)");
    if (named->kind == gtl::Kind::Point)
      g.profile.close_at(named->at, tag);
    else
      g.profile.close_with(id, tag);
    gtl_moves();
    flush_compensation();
    if (kernel_.path()) kernel_.path()->resume();
    return;
  } else if (named) {
    if (named->kind == gtl::Kind::Point)
      return refuse('p', "a point is named only where the profile opens (G21) or closes (G20) (§2.8.6)");
    g.profile.element(*named, id, s2, tag);
  } else if (fillet) {
    g.profile.fillet(word('r'), tag);
  } else if (chamfer) {
    g.profile.chamfer(word('b'), tag);
  } else if (block.axes) {
    g.profile.hold(tag);
  }
  gtl_moves();
}

// The pieces the profile has made: each a move of its own block, at that block's feed.
void Machine::gtl_moves() {
  GtlState& g = *gtl_;
  const int u = modal_.plane.u, v = modal_.plane.v;
  const std::optional<double> feed = feed_;
  for (const gtl::Piece& p : g.profile.take()) {
    const GtlState::Block& b = g.blocks[p.tag - g.first_tag];
    AxisValues at = to_frame(kernel_.position());
    for (int i = 0; i < kAxisCount; ++i)
      if (b.axes & (1u << i)) at[i] = b.others[i];
    if (p.in_plane) {
      at[u] = axis_units(u, p.to.x());
      at[v] = axis_units(v, p.to.y());
    }
    const AxisValues t = to_machine(at);
    event_source_ = b.source;
    feed_ = b.feed;
    if (p.arc && need_feed("circular interpolation", t)) {
      AxisValues centre = at;
      centre[u] = axis_units(u, p.centre.x());
      centre[v] = axis_units(v, p.centre.y());
      const AxisValues c = to_machine(centre);
      // A mirror on one axis of the plane turns the arc the other way (decision 2).
      const bool clockwise =
          !p.ccw != (kernel_.frame().transformed() && kernel_.frame().mirror[u] != kernel_.frame().mirror[v]);
      arc_move(t, c[u], c[v], clockwise, 'I', 0);
    } else if (!p.arc) {
      linear(t);
    }
    event_source_.reset();
    if (block_.error) {  // reported once: the rest of the profile would repeat it
      g.profile.abandon();
      break;
    }
  }
  feed_ = feed;
  if (auto problem = g.profile.take_problem()) {
    const uint32_t source = g.blocks[problem->tag - g.first_tag].source;
    if (problem->warning)
      issue({DiagId::GtlProfileEnd, diag_message(DiagId::GtlProfileEnd, problem->what), source, -1, -1});
    else
      issue({DiagId::GtlProfile, diag_message(DiagId::GtlProfile, problem->what), source, -1, -1});
  }
  // The blocks no piece waits for any more.
  if (!g.profile.active()) {
    g.first_tag += g.blocks.size();
    g.blocks.clear();
  }
}

void Machine::gtl_unit_end() {
  if (!gtl_->profile.active()) return;
  issue({DiagId::GtlProfile,
         diag_message(DiagId::GtlProfile,
                      "the program ends inside the GTL profile G21 opens here: G20 closes it (§2.11.8)"),
         gtl_->opened_at, -1, -1});
  gtl_->profile = gtl::Profile{};
  gtl_->blocks.clear();
}

uint64_t Machine::gtl_bytes() const { return gtl_->blocks.size() * sizeof(GtlState::Block); }

}  // namespace ncc
