// GTL definitions (§2.11.3-2.11.7): `l1 = X70 Y40, a150`, `c6=o1I-38J-35r10`,
// `p1 = -l4, c3, s2`. The words are grouped into the operands of contract/gtl_shape.h
// (a point's coordinates, a circle's centre and radius, a reference, a scalar), the
// form is checked, and the block becomes a machine action: gtl.define with the shape
// as its argument and every value at the operand slots, in order.
#include <fmt/format.h>

#include "contract/gtl_shape.h"
#include "contract/machine_config.h"
#include "reader.h"

namespace ncc::nc110 {

namespace {

struct GtlValue {
  ir::ExprId value = ir::kNoExpr;
  std::string address, text;  // as written: "X", "-20"
  SourceRange range;
  bool derived = false;  // made up: an absent origin, an axis' number, a direction
};

struct GtlGroup {
  gtl::Operand op = gtl::Operand::None;
  std::vector<GtlValue> values;
  SourceRange range;
  std::string letters;  // the words it has taken: "XY", "IJr", "ma"
  bool complete() const {
    switch (op) {
      case gtl::Operand::Coordinates: return letters.size() == 2;
      case gtl::Operand::Centre: return letters.size() == 3;
      case gtl::Operand::Polar: return letters.size() == 2;
      default: return true;
    }
  }
  bool element() const {
    return op != gtl::Operand::Angle && op != gtl::Operand::Radius && op != gtl::Operand::Distance;
  }
};

gtl::Kind kind_of(char letter) {
  return letter == 'o'   ? gtl::Kind::Origin
         : letter == 'p' ? gtl::Kind::Point
         : letter == 'l' ? gtl::Kind::Line
                         : gtl::Kind::Circle;
}

}  // namespace

// A value of a GTL word: a constant in the address' range, or an E parameter of a class
// it takes; nothing is 0 for coordinates, centres and angles (`l4 = X50 Y, a90`).
std::optional<ir::ExprId> Reader::gtl_value(char letter, bool minus, Nc110Parser::WordValueContext* v, SourceRange r) {
  const std::string written = v ? text(v->getStart(), v->getStop()) : std::string();
  const std::string shown = (minus ? "-" : "") + std::string(1, letter) + written;
  auto fail = [&]<typename... Args>(DiagIdFor<Args...> id, const Args&... args) -> std::optional<ir::ExprId> {
    diags_.report(id, r, args...);
    block_.has_errors = true;
    return std::nullopt;
  };
  auto entry = s_.tables.addresses.find(letter);
  if (entry == s_.tables.addresses.end()) return fail(DiagId::AddressUnknown, fmt::format("'{}'", letter));
  if (!v) {
    if (kGtlElements.find(letter) != std::string_view::npos || letter == 'r' || letter == 's')
      return fail(DiagId::ValueMissing, shown);
    return program_.number(0, r);
  }
  const bool negative = v->sign() && v->sign()->MINUS();
  if (v->EREF()) {
    if (v->sign()) return fail(DiagId::SignedParameter, shown);
    auto index = parameter(v->EREF()->getText(), r);
    if (!index || !check_class(*index, entry->second.params, r, std::string(1, letter))) return std::nullopt;
    return parameter_expr(*index, r);
  }
  if (letter == 's' && (negative || v->NUMBER()->getText() != "2"))
    return fail(DiagId::GtlSyntax, "s2 takes the second solution; the first is taken without s (§2.8.6)");
  auto value = constant(letter, v->NUMBER()->getText(), negative, r, shown);
  if (!value) {
    block_.has_errors = true;
    return std::nullopt;
  }
  return program_.number(*value, r);
}

void Reader::gtl_block(Nc110Parser::GtlBlockContext* ctx) {
  leading(ctx->leading(), true);
  const SourceRange whole = range(ctx->LETTER()->getSymbol(), ctx->getStop());
  auto fail = [&](SourceRange r, const std::string& why) {
    diags_.report(DiagId::GtlSyntax, r, why);
    block_.has_errors = true;
  };
  const char target_letter = ctx->LETTER()->getText()[0];
  const gtl::Kind target = kind_of(target_letter);
  const SourceRange target_range =
      range(ctx->LETTER()->getSymbol(), ctx->wordValue() ? ctx->wordValue()->getStop() : ctx->LETTER()->getSymbol());
  auto index = gtl_value(target_letter, false, ctx->wordValue(), target_range);
  if (!index) return;

  // The words, grouped into operands (§2.11.3): a comma between two elements, optional
  // before a scalar (`X0 Y-60 a180`, `I70 J40, r-25`).
  std::vector<GtlGroup> groups;
  std::optional<GtlValue> origin;
  std::optional<SourceRange> s2;
  bool comma = false;
  auto open_group = [&]() -> GtlGroup* {
    return groups.empty() || groups.back().complete() ? nullptr : &groups.back();
  };
  auto start = [&](gtl::Operand op, SourceRange r) -> bool {
    if (GtlGroup* g = open_group()) {
      fail(g->range,
           g->letters == "A" ? "A is the axis A; the angle of a GTL definition is a lower-case a (§2.11.3)"
           : g->op == gtl::Operand::Coordinates ? "a point is given by both axes of the plane, e.g. X10 Y20 (§2.11.5)"
           : g->op == gtl::Operand::Centre      ? "a circle is given by its centre and radius, I.. J.. r.. (§2.11.7)"
                                           : "a polar point is given by its modulus and angle, m.. a.. (§2.11.5)");
      return false;
    }
    GtlGroup g{op, {}, r, ""};
    const bool coordinates = op == gtl::Operand::Coordinates || op == gtl::Operand::Centre || op == gtl::Operand::Polar;
    if (coordinates) {
      g.values.push_back(origin ? *origin : GtlValue{program_.number(-1, r), "o", "", r, true});
      origin.reset();
    } else if (origin) {
      fail(origin->range,
           fmt::format("o{} gives the origin of the coordinates after it: X.. Y.., I.. J.. or m.. a.. (§2.11.4)",
                       origin->text));
      return false;
    }
    if (g.element() && !groups.empty() && !comma) {
      fail(r, "a comma separates two points, lines or circles of a definition (§2.11.2)");
      return false;
    }
    groups.push_back(std::move(g));
    return true;
  };
  for (auto* item : ctx->gtlItem()) {
    if (block_.has_errors) return;
    if (item->COMMA()) {
      comma = true;
      continue;
    }
    const char letter = item->LETTER()->getText()[0];
    const bool minus = item->MINUS() != nullptr;
    const SourceRange r = range(item);
    const std::string written =
        item->wordValue() ? text(item->wordValue()->getStart(), item->wordValue()->getStop()) : "";
    if (minus && letter != 'l' && letter != 'c') {
      fail(r,
           letter == 'p'
               ? "a point has no direction to reverse: '-' goes before a line or a circle (§2.11.1)"
               : fmt::format(
                     "'-' reverses a line or a circle; a negative value is written after the letter: {}-.. (§2.11.1)",
                     letter));
      return;
    }
    auto value = gtl_value(letter, minus, item->wordValue(), r);
    if (!value) return;
    GtlValue v{*value, std::string(1, letter), written, r, false};
    GtlGroup* g = open_group();
    switch (letter) {
      case 'o':
        if (origin) return fail(r, "one origin o.. before the coordinates it applies to (§2.11.4)");
        origin = v;
        break;
      case 'p':
      case 'l':
      case 'c':
        if (!start(letter == 'p'   ? gtl::Operand::PointRef
                   : letter == 'l' ? gtl::Operand::LineRef
                                   : gtl::Operand::CircleRef,
                   r))
          return;
        groups.back().values = {v, GtlValue{program_.number(minus ? 1 : 0, r), "-", "", r, true}};
        break;
      case 'a':
      case 'r':
      case 'd': {
        // The angle of m.. a.., the radius of I.. J.. r.., or a scalar of its own.
        const bool completes = g && ((letter == 'a' && g->op == gtl::Operand::Polar && g->letters == "m") ||
                                     (letter == 'r' && g->op == gtl::Operand::Centre && g->letters == "IJ"));
        if (completes) {
          g->values.push_back(v);
          g->letters += letter;
          break;
        }
        if (!start(letter == 'a'   ? gtl::Operand::Angle
                   : letter == 'r' ? gtl::Operand::Radius
                                   : gtl::Operand::Distance,
                   r))
          return;
        groups.back().values.push_back(v);
        break;
      }
      case 'm':
        if (!start(gtl::Operand::Polar, r)) return;
        groups.back().values.push_back(v);
        groups.back().letters = "m";
        break;
      case 'I':
      case 'J':
        if (g && g->op == gtl::Operand::Centre && g->letters.size() < 2 &&
            g->letters.find(letter) == std::string::npos && (letter == 'J') == (g->letters == "I")) {
          g->values.push_back(v);
          g->letters += letter;
        } else if (letter == 'I' && start(gtl::Operand::Centre, r)) {
          groups.back().values.push_back(v);
          groups.back().letters = "I";
        } else {
          if (!block_.has_errors) fail(r, "a circle's centre is written I.. J.., in that order (§2.11.7)");
          return;
        }
        break;
      case 's': {
        if (s2) return fail(r, "s2 is written once");
        s2 = r;
        break;
      }
      default: {
        const int axis = axis_index(letter);
        if (letter == 'O')
          return fail(r, "the letter O where the digit 0 is meant: a GTL definition has no O (§2.11.3)");
        if (axis < 0 || letter == 'E') {
          fail(r, fmt::format("'{}' is not a word of a GTL definition: it takes the plane's two axes (X Y, U V...), I "
                              "J, m, a, r, d, "
                              "o, p, l, c and s2 (§2.11.3)",
                              letter));
          return;
        }
        GtlValue axis_number{program_.number(axis, r), "", "", r, true};
        if (g && g->op == gtl::Operand::Coordinates) {
          if (g->letters[0] == letter) return fail(r, fmt::format("{} is written twice in one point", letter));
          g->values.push_back(axis_number);
          g->values.push_back(v);
          g->letters += letter;
        } else if (start(gtl::Operand::Coordinates, r)) {
          groups.back().values.push_back(axis_number);
          groups.back().values.push_back(v);
          groups.back().letters = std::string(1, letter);
        } else {
          return;
        }
      }
    }
    comma = false;
  }
  if (block_.has_errors) return;
  if (GtlGroup* g = open_group()) {
    start(gtl::Operand::Angle, g->range);  // reports what it lacks
    return;
  }
  if (origin)
    return fail(origin->range, fmt::format("o{} gives the origin of the coordinates after it: X.. Y.., I.. J.. "
                                           "or m.. a.. (§2.11.4)",
                                           origin->text));
  if (groups.size() > 3) return fail(groups[3].range, "a definition has at most three operands (§2.11.3)");
  gtl::Shape shape;
  shape.target = target;
  for (size_t i = 0; i < groups.size(); ++i) shape.ops[i] = groups[i].op;
  if (std::string why = gtl::form_error(shape, s2.has_value()); !why.empty()) return fail(whole, why);
  if (target == gtl::Kind::Origin && !groups[0].values[0].derived)
    return fail(groups[0].values[0].range, "an origin is not given from another origin (§2.11.4)");

  // The machine action: the code, then the values at the operand slots.
  const std::string name = std::string(1, target_letter) + "=";
  add_word(0, 0, program_.number(0, whole), "", whole, ir::WordKind::Code,
           program_code(program_, {name, Scope::Block, Timing::None, {{Fn::GtlDefine, shape.pack()}}}));
  block_.words.back().address = name;
  std::vector<GtlValue> values{
      {*index, std::string(1, target_letter),
       ctx->wordValue() ? text(ctx->wordValue()->getStart(), ctx->wordValue()->getStop()) : "", target_range, false},
      {program_.number(s2 ? 1 : 0, s2.value_or(whole)), "s", s2 ? "2" : "", s2.value_or(whole), !s2}};
  for (const GtlGroup& g : groups) values.insert(values.end(), g.values.begin(), g.values.end());
  for (size_t i = 0; i < values.size(); ++i) {
    add_word(values[i].address.empty() ? '#' : values[i].address[0], operand_slot(static_cast<int>(i)), values[i].value,
             values[i].text, values[i].range);
    block_.words.back().derived = values[i].derived;
  }
  block_.stmts.push_back({ir::StmtKind::Machine, block_.range});
}

}  // namespace ncc::nc110
