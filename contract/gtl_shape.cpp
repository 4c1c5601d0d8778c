#include "gtl_shape.h"

#include <string_view>

#include <fmt/format.h>

namespace ncc::gtl {

namespace {

// Operand classes of the forms: a point (a reference or coordinates), a line, a
// circle (a reference or I J r), or a scalar.
enum class Class : char { Point = 'P', Line = 'L', Circle = 'C', Angle = 'a', Radius = 'r', Distance = 'd', None = 0 };

Class class_of(Operand op) {
  switch (op) {
    case Operand::PointRef:
    case Operand::Coordinates:
    case Operand::Polar: return Class::Point;
    case Operand::LineRef: return Class::Line;
    case Operand::CircleRef:
    case Operand::Centre: return Class::Circle;
    case Operand::Angle: return Class::Angle;
    case Operand::Radius: return Class::Radius;
    case Operand::Distance: return Class::Distance;
    case Operand::None: break;
  }
  return Class::None;
}

// The forms of §2.11.4-2.11.7 by target and operand classes; `s2`: the form has two
// solutions to choose from.
struct Form {
  Kind target;
  std::string_view sig;
  bool s2;
};
constexpr Form kForms[] = {
    {Kind::Origin, "Pa", false},  {Kind::Point, "P", false},    {Kind::Point, "LL", false},
    {Kind::Point, "LC", true},    {Kind::Point, "CL", true},    {Kind::Point, "CC", true},
    {Kind::Line, "PP", false},    {Kind::Line, "Pa", false},    {Kind::Line, "Ca", false},
    {Kind::Line, "CC", false},    {Kind::Line, "CP", false},    {Kind::Line, "PC", false},
    {Kind::Line, "Ld", false},    {Kind::Circle, "C", false},   {Kind::Circle, "Pr", false},
    {Kind::Circle, "LLr", false}, {Kind::Circle, "LCr", false}, {Kind::Circle, "CLr", false},
    {Kind::Circle, "PLr", false}, {Kind::Circle, "LPr", false}, {Kind::Circle, "CCr", false},
    {Kind::Circle, "PCr", false}, {Kind::Circle, "CPr", false}, {Kind::Circle, "PPr", false},
    {Kind::Circle, "PL", false},  {Kind::Circle, "PC", true},   {Kind::Circle, "PPP", false},
    {Kind::Circle, "Cd", false},
};

std::string_view kind_name(Kind k) {
  switch (k) {
    case Kind::Origin: return "an origin";
    case Kind::Point: return "a point";
    case Kind::Line: return "a line";
    case Kind::Circle: return "a circle";
  }
  return "";
}

std::string class_words(std::string_view sig) {
  std::string out;
  for (size_t i = 0; i < sig.size(); ++i) {
    std::string_view w = sig[i] == 'P'   ? "a point"
                         : sig[i] == 'L' ? "a line"
                         : sig[i] == 'C' ? "a circle"
                         : sig[i] == 'a' ? "an angle"
                         : sig[i] == 'r' ? "a radius"
                                         : "a distance";
    out += i == 0 ? "" : i + 1 == sig.size() ? " and " : ", ";
    out += w;
  }
  return out;
}

std::string_view section(Kind k) {
  switch (k) {
    case Kind::Origin: return "§2.11.4";
    case Kind::Point: return "§2.11.5";
    case Kind::Line: return "§2.11.6";
    case Kind::Circle: return "§2.11.7";
  }
  return "";
}

}  // namespace

char letter(Kind kind) { return "oplc"[static_cast<int>(kind)]; }

int value_count(Operand op) {
  switch (op) {
    case Operand::None: return 0;
    case Operand::PointRef:
    case Operand::LineRef:
    case Operand::CircleRef: return 2;
    case Operand::Coordinates: return 5;
    case Operand::Polar: return 3;
    case Operand::Centre: return 4;
    case Operand::Angle:
    case Operand::Radius:
    case Operand::Distance: return 1;
  }
  return 0;
}

uint16_t Shape::pack() const {
  uint16_t arg = static_cast<uint16_t>(target);
  for (size_t i = 0; i < ops.size(); ++i) arg |= static_cast<uint16_t>(static_cast<unsigned>(ops[i]) << (2 + 4 * i));
  return arg;
}

Shape Shape::unpack(uint16_t arg) {
  Shape s;
  s.target = static_cast<Kind>(arg & 3);
  for (size_t i = 0; i < s.ops.size(); ++i) {
    unsigned op = (arg >> (2 + 4 * i)) & 15;
    s.ops[i] = op <= static_cast<unsigned>(Operand::Distance) ? static_cast<Operand>(op) : Operand::None;
  }
  return s;
}

size_t Shape::value_count() const {
  size_t n = 2;
  for (Operand op : ops) n += static_cast<size_t>(gtl::value_count(op));
  return n;
}

std::string signature(const Shape& s) {
  std::string sig;
  for (Operand op : s.ops)
    if (op != Operand::None) sig += static_cast<char>(class_of(op));
  return sig;
}

std::string form_error(const Shape& shape, bool s2) {
  for (size_t i = 1; i < shape.ops.size(); ++i)
    if (shape.ops[i - 1] == Operand::None && shape.ops[i] != Operand::None)
      return "the definition's operands leave a gap: not a definition the compiler makes";
  const std::string sig = signature(shape);
  for (const Form& f : kForms) {
    if (f.target != shape.target || f.sig != sig) continue;
    if (shape.target == Kind::Origin && shape.ops[0] != Operand::Coordinates)
      return "an origin is given by its coordinates X.. Y.. and an angle a.. (§2.11.4)";
    // A point alone is a point's own coordinates; a circle alone is written I.. J.. r...
    if (sig == "P" && shape.ops[0] == Operand::PointRef) break;
    if (sig == "C" && shape.ops[0] == Operand::CircleRef) break;
    if (s2 && !f.s2)
      return fmt::format("s2 chooses the second of two solutions; {} defined by {} has one ({})",
                         kind_name(shape.target), class_words(sig), section(shape.target));
    return "";
  }
  if (sig.empty())
    return fmt::format("{} needs its definition after '=' ({})", kind_name(shape.target), section(shape.target));
  return fmt::format("{} is not defined by {} ({})", kind_name(shape.target), class_words(sig), section(shape.target));
}

}  // namespace ncc::gtl
