// A program's values are doubles. Every integer made from one (a variable number, a
// code, a count, an index, an address, a block number) is made here: C++ leaves the
// conversion of a double outside the integer type undefined, and a value that wraps
// names another variable or code silently (docs/limits.md, "Numbers and run-time limits").
#pragma once

#include <cmath>
#include <concepts>
#include <limits>
#include <optional>

namespace ncc {

// The whole number `v` is, if it lies in [lo, hi]; none for a fraction, a NaN, an
// infinity or a value outside.
template <std::integral T>
requires(!std::same_as<T, bool>) std::optional<T> whole_in(double v, T lo, T hi) {
  // T's whole range as doubles, both ends exact: [min, 2^digits).
  constexpr double kMin = static_cast<double>(std::numeric_limits<T>::min());
  constexpr double kEnd = 2.0 * static_cast<double>(std::numeric_limits<T>::max() / 2 + 1);
  if (!(v >= kMin && v < kEnd) || v != std::trunc(v)) return std::nullopt;
  const T t = static_cast<T>(v);
  if (t < lo || t > hi) return std::nullopt;
  return t;
}

}  // namespace ncc
