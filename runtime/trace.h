// The trace: one event per runtime call (docs/trace.md), written as text, JSON Lines,
// or LinuxCNC canonical calls by writers of the typed calls the events become. The
// trace is the observable truth of a run: golden tests compare it.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "contract/machine_config.h"
#include "contract/source_map.h"

namespace ncc {

enum class EventKind : uint8_t {
  Units,         // n: 0 mm, 1 inch
  Plane,         // plane
  FeedMode,      // n: 0 inverse time, 1 per minute, 2 per revolution
  FeedRate,      // a: rate in program units
  SpindleMode,   // n: 0 rpm, 1 constant surface speed
  SpindleSpeed,  // a
  SpindleOn,     // n: 1 clockwise, -1 counter-clockwise
  SpindleStop,
  SpindleOrient,     // a: angle
  Rapid,             // pos
  Linear,            // pos
  Arc,               // pos = end; plane; centre = (u, v); rotation; a = radius; b = sweep (degrees)
  Parabola,          // pos = end; control = tangent intersection point
  Thread,            // pos = end; a = pitch; b = pitch change per revolution; c = start angle (NC-110 R)
  Dwell,             // a: seconds
  SelectTool,        // n
  ChangeTool,        // n
  ToolLengthOffset,  // pos: offset per axis (X Y Z ... )
  CutterComp,        // n: 0 off, 1 left, 2 right; a: radius
  WorkOffset,        // n: 0 none, 1..; pos: offset values
  PositionOffset,    // pos: the G92 offset values
  Coolant,           // n: 0 off, 1 mist on, 2 flood on, 3 coolant 3 on, 4 coolant 4 on, 5 coolants 3 and 4 off
  Clamp,             // n: 1 clamp, 0 unclamp, 3 clamp the rotary axes, 2 unclamp them
  Override,          // n: 1 enabled, 0 disabled
  SpindleHold,       // n: 1 on, 0 off
  PathMode,          // n: 0 accelerate, 1 decelerate, 2 tapping, 3 spindle sync, 4 corner slow-down,
                     //    5 continuous, 6 point to point, 7 smooth
  Comment,           // text
  Message,           // text: an operator message the program shows (NC-110 DIS)
  Stop,              // n: 0 program stop, 1 optional stop taken, 2 optional stop skipped, 3 manual retract
  OperatorMove,      // pos: where the operator left the tool (manual retract)
  End,               // n: 0 end of program, 1 end of information
  // NC-110.
  Origin,         // pos: the program zero in machine coordinates
  Transform,      // a: rotation (degrees); n: mirrored axes (bit per axis); pos: scale per axis
  Tolerance,      // n: the axes set (bit per axis); pos: their in-position tolerance
  Limits,         // n: the axes limited (bit per axis); pos: lower, control: upper limits
  Zone,           // rotation: zone number; n: 0 off, 1 on, 2 defined; plane: its axes; pos: lower, control: upper
  Configuration,  // n: 0 milling, 1 turning
  Probe,          // pos: where the probe stopped; n: 1 contact, 0 none
  Spline,         // pos = end; control, control2: the cubic Bezier control points of the span
  SpindleRange,   // n: 0 none forced, -1 automatic, 1.. forced
  PartChange,
  // pp.
  OffsetLoad,     // n: the work offset loaded (0: G53's); pos: its values
  Diameter,       // n: 1 diameter programming, 0 radius programming
  FeedReduction,  // n: 1 the feed is F / 100, 0 as programmed
  Aux,            // text: the auxiliary function the machine's logic carries out ("M23", "H5")
  Block,          // a block starts (--trace-blocks)
  CompLoad,       // n: the compensation entry loaded; a: its length; b: its radius
  // NC-110 ASSET file I/O.
  Asset,    // text: the statement ("read 1 record 3"); n: its code of table 5.2, 0 when it worked
  Input,    // text: the prompt and the value offered; a: the operator's answer (NC-110 INP);
            // n = 1: a text answered, after a line break in text
  Screen,   // text: what the user screen did: "on", "off", "field 2 row 3 column 19 "0"" (NC-110 SCR, OUT)
  Sync,     // text: what a process did with the others: "restart process 2", "wait for process 1" (NC-110 chapter 4)
  Graphic,  // text: the graphic display (NC-110 UCG, CLG, DCG): "field mode 2 X100..150 Y50..250", "clear", "off"
  Tooling,  // text: the tool table or the probe changed (NC-110 RQU, RQP, TOF, DPT); n: what (kTooling*)
  Virtual,  // text: virtual axes (NC-110 UAV): "polar X C as U V min radius 7.8782 at U80 V0 X80 C0", "off at ..."
};

inline bool is_move(EventKind k) { return k == EventKind::Rapid || k == EventKind::Linear || k == EventKind::Arc; }

// What a Tooling event changed, and its text.
constexpr int kToolingCorrector = 1;  // "corrector 1 tool 10 length 75.2 radius 5 [wear 0.2 0]"
constexpr int kToolingUnusable = 2;   // "tool 10 unusable (TOF)", "tool 10 replaced by sister 110"
constexpr int kToolingProbe = 3;      // "probe approach 10 safety 12 feed 600"

struct Event {
  Event() = default;
  explicit Event(EventKind k) : kind(k) {}

  EventKind kind = EventKind::Comment;
  uint8_t process = 0;  // of a run of several processes, the one it happened in (NC-110 chapter 4)
  uint32_t source = 0;  // SourceMap::blocks index
  int n = 0;
  double a = 0, b = 0, c = 0;
  int rotation = 0;
  uint16_t moved = 0;  // a move: bit i, axis i moves (an endless rotary axis may end where it began)
  Plane plane;
  AxisValues pos{};
  double centre[2] = {0, 0};
  AxisValues control{};
  AxisValues control2{};
  std::string text;
};

class TraceSink {
 public:
  virtual ~TraceSink() = default;
  virtual void event(const Event& e) = 0;
  virtual void flush() {}
  // False when every event is dropped: the runtime then builds none it need not.
  virtual bool wants_events() const { return true; }
  // A move of the programmed path while cutter radius compensation offsets it (event()
  // receives the tool centre's path), for a sink that draws both: the simulator's.
  virtual void programmed(const Event&) {}
  virtual bool wants_programmed() const { return false; }
};

class NullSink final : public TraceSink {
 public:
  void event(const Event&) override {}
  bool wants_events() const override { return false; }
};

// Keeps every event (tests, the dry run of `ncc check`).
class CollectSink final : public TraceSink {
 public:
  void event(const Event& e) override { events.push_back(e); }
  std::vector<Event> events;
};

// Stamps each event with a process's number for the sink of the run (a run of
// several processes, NC-110 chapter 4).
class ProcessSink final : public TraceSink {
 public:
  ProcessSink(TraceSink& out, uint8_t process) : out_(out), process_(process) {}
  void event(const Event& e) override {
    Event stamped = e;
    stamped.process = process_;
    out_.event(stamped);
  }
  bool wants_events() const override { return out_.wants_events(); }
  void programmed(const Event& e) override {
    Event stamped = e;
    stamped.process = process_;
    out_.programmed(stamped);
  }
  bool wants_programmed() const override { return out_.wants_programmed(); }

 private:
  TraceSink& out_;
  uint8_t process_;
};

// Hands each event to two sinks (the simulator's tool path and a trace writer).
class TeeSink final : public TraceSink {
 public:
  TeeSink(TraceSink& first, TraceSink& second) : first_(first), second_(second) {}
  void event(const Event& e) override {
    if (first_.wants_events()) first_.event(e);
    if (second_.wants_events()) second_.event(e);
  }
  void flush() override {
    first_.flush();
    second_.flush();
  }
  bool wants_events() const override { return first_.wants_events() || second_.wants_events(); }
  void programmed(const Event& e) override {
    first_.programmed(e);
    second_.programmed(e);
  }
  bool wants_programmed() const override { return first_.wants_programmed() || second_.wants_programmed(); }

 private:
  TraceSink& first_;
  TraceSink& second_;
};

enum class TraceFormat { Text, Jsonl, Canon };

// A sink writing `format` to `out` through a buffer: a writer of the typed calls of
// include/ncc/machine_interface.h behind the adapter that makes the events those
// calls. `axes` are the letters the machine has (conventions.axes).
[[nodiscard]] std::unique_ptr<TraceSink> make_trace_writer(TraceFormat format, std::FILE* out, const SourceMap& map,
                                                           std::string axes);

}  // namespace ncc
