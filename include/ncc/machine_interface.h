// The boundary between running a program and moving a machine: the typed calls a
// run makes, in the spirit of LinuxCNC's canonical machining functions. The host
// (a controller's trajectory planner, a simulator, a test) implements the calls it
// cares about; each of the others accepts and does nothing. Every call names the
// block that made it.
//
// Positions are those of the controlled point in the active work coordinate system,
// in the program's length unit (mm, or inches after the inch code), rotary axes in
// degrees: what `ncc run` traces (docs/trace.md), and what LinuxCNC's canonical calls
// carry. The offsets come as calls of their own (work_offset, position_offset,
// tool_length_offset); a move ends where the call says and starts where the last
// one ended. The trace writers of `ncc run` are implementations of this interface too.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "export.h"

namespace ncc::api {

// The axes, always twelve, by their letters.
inline constexpr std::string_view kAxisLetters = "XYZABCUVWPQD";
inline constexpr size_t kAxisCount = 12;
using Axes = std::array<double, kAxisCount>;
// A set of axes: bit i is the axis kAxisLetters[i].
using AxisMask = uint16_t;

// A block of the program: where it stands and its number.
struct Block {
  uint32_t index = 0;     // Program::block(index)
  std::string_view file;  // valid while the Program lives
  bool main_file = true;  // the file compiled, not one it includes (the text trace names no file for it)
  uint32_t line = 0, column = 0;
  std::optional<uint32_t> number;  // N12; a main block's :100 (main_block)
  bool main_block = false;
  uint8_t process = 0;  // an NC-110 run of several processes: the one that made the call (0: the only one)
};

// A plane of interpolation by its axes (kAxisLetters indices): XY is {0, 1, 2}.
struct Plane {
  int first = 0, second = 1, normal = 2;
  bool operator==(const Plane&) const = default;
};

// An arc or helix: it ends at `end`, turns about the centre (first, second) in the
// plane, `rotation` times counter-clockwise when positive, clockwise when negative
// (LinuxCNC's ARC_FEED); the normal axis moves linearly to its end.
struct Arc {
  Axes end{};
  AxisMask moved = 0;  // the axes that move (an endless rotary axis may end where it began)
  Plane plane;
  double centre_first = 0, centre_second = 0;
  int rotation = 0;
  double radius = 0;
  double sweep = 0;  // degrees, signed as rotation
};

enum class Units { Millimetres, Inches };
enum class FeedMode { InverseTime, PerMinute, PerRevolution };
enum class SpindleMode { Rpm, ConstantSurfaceSpeed };
enum class Direction { Clockwise, CounterClockwise };
enum class CutterSide { Off, Left, Right };
enum class Coolant { Off, Mist, Flood, Coolant3, Coolant4, Coolants3And4Off };
enum class PathMode { Accelerate, Decelerate, Tapping, SpindleSync, CornerSlowdown, Continuous, PointToPoint, Smooth };
enum class StopKind { Program, OptionalTaken, OptionalSkipped, ManualRetract };
enum class Clamp { Off, On, RotaryOff, RotaryOn };  // all axes, or the rotary ones
enum class ZoneState { Off, On, Defined };
enum class Configuration { Milling, Turning };
enum class ToolingChange { Corrector = 1, Unusable, Probe };

// A host's answer to a call: accepted, or refused with a reason. A refusal stops the
// run with an error at the block that made the call (NC6015), and the host is called
// no more.
class Reply {
 public:
  Reply() = default;
  static Reply refuse(std::string reason) { return Reply(std::move(reason)); }
  bool accepted() const { return !refused_; }
  const std::string& reason() const { return reason_; }

 private:
  explicit Reply(std::string reason) : refused_(true), reason_(std::move(reason)) {}
  bool refused_ = false;
  std::string reason_;
};

class NCC_API MachineInterface {
 public:
  virtual ~MachineInterface();

  // Motion. `moved`: the axes that move, which an endless rotary axis turning whole
  // turns needs (it ends where it began).
  virtual Reply straight_traverse(const Block&, const Axes& /*end*/, AxisMask /*moved*/) { return {}; }
  virtual Reply straight_feed(const Block&, const Axes& /*end*/, AxisMask /*moved*/) { return {}; }
  virtual Reply arc_feed(const Block&, const Arc&) { return {}; }
  // A thread cut along a line at the spindle's speed: pitch per revolution, its change
  // per revolution, the start angle in degrees.
  virtual Reply thread(const Block&, const Axes& /*end*/, double /*pitch*/, double /*pitch_change*/,
                       double /*start_angle*/) {
    return {};
  }
  // A parabola (NC-110, GOST) from where the tool is to `end`, tangent to the lines
  // through `control`.
  virtual Reply parabola(const Block&, const Axes& /*end*/, const Axes& /*control*/) { return {}; }
  // A span of a spline (NC-110 G06) as a cubic Bezier curve.
  virtual Reply spline(const Block&, const Axes& /*end*/, const Axes& /*control1*/, const Axes& /*control2*/) {
    return {};
  }
  // A probing move stopped at `end`, with or without contact.
  virtual Reply probe(const Block&, const Axes& /*end*/, bool /*contact*/) { return {}; }
  virtual Reply dwell(const Block&, double /*seconds*/) { return {}; }

  // Modes.
  virtual Reply units(const Block&, Units) { return {}; }
  virtual Reply plane(const Block&, const Plane&) { return {}; }
  virtual Reply feed_mode(const Block&, FeedMode) { return {}; }
  virtual Reply feed_rate(const Block&, double /*rate*/) {
    return {};
  }  // program units per minute (or as feed_mode says)
  virtual Reply path_mode(const Block&, PathMode) { return {}; }

  // Spindle, tools and offsets.
  virtual Reply spindle_mode(const Block&, SpindleMode) { return {}; }
  virtual Reply spindle_speed(const Block&, double /*speed*/) { return {}; }
  virtual Reply spindle_start(const Block&, Direction) { return {}; }
  virtual Reply spindle_stop(const Block&) { return {}; }
  virtual Reply spindle_orient(const Block&, double /*angle*/) { return {}; }
  virtual Reply tool_select(const Block&, int /*tool*/) { return {}; }
  virtual Reply tool_change(const Block&, int /*tool*/) { return {}; }
  virtual Reply tool_length_offset(const Block&, const Axes& /*offset*/) { return {}; }
  virtual Reply cutter_compensation(const Block&, CutterSide, double /*radius*/) { return {}; }
  virtual Reply work_offset(const Block&, int /*number*/, const Axes& /*offset*/) { return {}; }  // 0: none
  virtual Reply position_offset(const Block&, const Axes& /*offset*/) { return {}; }              // G92
  virtual Reply coolant(const Block&, Coolant) { return {}; }

  // The program and its operator.
  virtual Reply comment(const Block&, std::string_view /*text*/) { return {}; }
  virtual Reply message(const Block&, std::string_view /*text*/) { return {}; }
  virtual Reply stop(const Block&, StopKind) { return {}; }
  virtual Reply program_end(const Block&, bool /*end_of_information*/) { return {}; }  // M02; M30

  // The operator.
  virtual Reply operator_move(const Block&, const Axes& /*to*/) { return {}; }  // left after a manual retract
  // NC-110 INP: the prompt with the value offered, and the operator's answer.
  virtual Reply input(const Block&, std::string_view /*prompt*/, double /*answer*/) { return {}; }
  virtual Reply input_text(const Block&, std::string_view /*prompt*/, std::string_view /*answer*/) { return {}; }

  // The machine's own functions.
  virtual Reply clamp(const Block&, Clamp) { return {}; }
  virtual Reply override_enable(const Block&, bool /*enabled*/) { return {}; }  // feed and speed overrides
  virtual Reply spindle_hold(const Block&, bool /*on*/) { return {}; }
  virtual Reply spindle_range(const Block&, int /*range*/) { return {}; }        // 0 none forced, -1 automatic, 1..
  virtual Reply aux(const Block&, std::string_view /*function*/) { return {}; }  // "M23", "H5": the machine's logic
  // A block starts (`ncc run --trace-blocks`: which blocks ran; a Run makes none).
  virtual Reply block_start(const Block&) { return {}; }

  // Frames and the working space (NC-110).
  virtual Reply origin(const Block&, const Axes& /*zero*/) { return {}; }  // the program zero in machine coordinates
  // A rotation in degrees, the mirrored axes, a scale per axis.
  virtual Reply transform(const Block&, double /*rotation*/, AxisMask /*mirrored*/, const Axes& /*scale*/) {
    return {};
  }
  // The in-position tolerance of the axes set (those of `axes`, the others unchanged).
  virtual Reply tolerance(const Block&, AxisMask /*axes*/, const Axes& /*tolerance*/) { return {}; }
  // The limits of the axes of `axes`: none cancels all.
  virtual Reply limits(const Block&, AxisMask /*axes*/, const Axes& /*lower*/, const Axes& /*upper*/) { return {}; }
  // A zone switched off or on, or defined by its bounds on the axes of `plane`.
  virtual Reply zone(const Block&, int /*zone*/, ZoneState, const Plane&, const Axes& /*lower*/,
                     const Axes& /*upper*/) {
    return {};
  }
  virtual Reply configuration(const Block&, Configuration) { return {}; }
  virtual Reply part_change(const Block&) { return {}; }
  // Virtual axes (NC-110 UAV): "polar X C as U V min radius 7.8782 at U80 V0 X80 C0", "off at ...".
  virtual Reply virtual_axes(const Block&, std::string_view /*what*/) { return {}; }

  // Tables: a work offset loaded (0: G53's), a compensation entry, the tool table or
  // probe changed (NC-110 RQU, RQP, TOF, DPT: "corrector 1 tool 10 length 75.2 radius 5").
  virtual Reply offset_load(const Block&, int /*number*/, const Axes& /*offset*/) { return {}; }
  virtual Reply comp_load(const Block&, int /*entry*/, double /*length*/, double /*radius*/) { return {}; }
  virtual Reply tooling(const Block&, ToolingChange, std::string_view /*what*/) { return {}; }
  // Programming modes: diameters instead of radii; the feed as F / 100.
  virtual Reply diameter(const Block&, bool /*on*/) { return {}; }
  virtual Reply feed_reduction(const Block&, bool /*on*/) { return {}; }

  // NC-110 services: an ASSET file statement ("read 1 record 3") and its code of table
  // 5.2 (0: it worked); the user screen ("field 2 row 3 column 19 "0""); a process's
  // dealings with the others ("wait for process 1"); the graphic display ("clear").
  virtual Reply asset(const Block&, std::string_view /*statement*/, int /*code*/) { return {}; }
  virtual Reply screen(const Block&, std::string_view /*what*/) { return {}; }
  virtual Reply sync(const Block&, std::string_view /*what*/) { return {}; }
  virtual Reply graphic(const Block&, std::string_view /*what*/) { return {}; }
};

}  // namespace ncc::api
