// The shapes of NC-110 GTL definitions (§2.11.3-2.11.7): the kind of element a
// definition makes, the kinds of its operands and the forms they may take. The front
// end checks a definition's form and packs its shape into the argument of the
// gtl.define function; the runtime unpacks it and solves it (runtime/gtl.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace ncc::gtl {

enum class Kind : uint8_t { Origin, Point, Line, Circle };
char letter(Kind kind);         // o p l c
constexpr int kMaxIndex = 255;  // §2.11.2: elements 0..255 of each kind

// What a definition is made of, in written order (§2.11.3).
enum class Operand : uint8_t {
  None,
  PointRef,
  LineRef,
  CircleRef,    // p3, [-]l4, [-]c2: index, reversed (1) or not (0)
  Coordinates,  // [om] X.. Y..: origin (-1: none), axis, value, axis, value
  Polar,        // [om] m.. a..: origin, modulus, angle
  Centre,       // [om] I.. J.. r..: origin, abscissa, ordinate, radius
  Angle,
  Radius,
  Distance,  // a.., r.., d..
};
int value_count(Operand op);

// A definition's target and operands; its values are the target's index, 1 if `s2`
// is written (else 0), then each operand's.
struct Shape {
  Kind target = Kind::Point;
  std::array<Operand, 3> ops{};
  uint16_t pack() const;
  static Shape unpack(uint16_t arg);
  size_t value_count() const;
  bool operator==(const Shape&) const = default;
};
// The classes of the operands, the key of a form: "LCr" is a line, a circle and a radius.
std::string signature(const Shape& shape);
// Why the shape is none of the forms of §2.11.4-2.11.7 (with s2 when `s2`), or "".
[[nodiscard]] std::string form_error(const Shape& shape, bool s2);

}  // namespace ncc::gtl
