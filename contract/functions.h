// The canonical functions (functions.def) and the modal groups they set.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace ncc {

enum class FnGroup : uint8_t {
  None,
  Motion,
  Plane,
  Distance,
  Units,
  FeedMode,
  SpindleMode,
  CutterComp,
  ToolLength,
  WorkOffset,
  Cycle,
  Spindle,
  Mist,
  Flood,
  Clamp,
  Override,
  SpindleHold,
  Dynamics,
  Gtl,
  RotaryClamp,
  SpindleRange,
  Diameter,
  Helix,
  Coolant3,
  Coolant4,
  FeedReduction,
  Polar,
  Scaling,
  Rotation,
  CycleReturn,
  Count
};

enum class Fn : uint16_t {
#define FN(id, name, group, doc) id,
#include "functions.def"
#undef FN
  Count
};

std::string_view fn_name(Fn fn);
FnGroup fn_group(Fn fn);
std::optional<Fn> fn_by_name(std::string_view name);
// An NC-110 three-letter function: the block's words are its operands, not a move.
constexpr bool takes_operands(Fn fn) { return fn >= Fn::OriginSelect && fn <= Fn::ProbeSettings; }

// NC-110 UAV (virtual.axes): what each mode 0..4 takes after it, the compiler's check
// and the runtime's (a bytecode file written by hand).
struct VirtualForm {
  size_t real_lo, real_hi, virt_lo, virt_hi, values;
  const char* written;
};
inline constexpr VirtualForm kVirtualForms[5] = {
    {0, 0, 0, 0, 0, "(UAV,0)"},
    {2, 2, 2, 2, 1, "(UAV,1,XC,UV,r): a linear and a rotary axis, two virtual axes, the minimum radius"},
    {1, 1, 1, 1, 1, "(UAV,2,C,V,n): a rotary axis, a virtual axis, the cylinder's radius"},
    {1, 3, 1, 4, 2, "(UAV,3,VWU,XYZ,123,212): 1-3 slaves, 1-4 masters, each slave's master, each slave's mirror"},
    {3, 3, 3, 3, 3, "(UAV,4,XYZ,UVW,a1,a2,a3): three real axes, three virtual axes, three angles"}};

// A function with its argument: offset(3), cycle(2) (index into the cycle table).
struct FnCall {
  Fn fn;
  uint16_t arg = 0;
  bool operator==(const FnCall&) const = default;
};

// When an M function acts relative to the motion of its block (GOST 20999 Table 7).
enum class Timing : uint8_t { None, Before, After };
// Whether a function persists (modal) or acts in its block only.
enum class Scope : uint8_t { Modal, Block };

}  // namespace ncc
