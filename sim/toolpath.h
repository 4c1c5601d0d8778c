// The tool path of a run, as the simulator draws and times it: a TraceSink that keeps
// the moves (in mm, trace coordinates) with what a picture and a clock need of the
// machine's state at each: the tool, the feed, the block. `ncc plot`, `ncc view` and
// `ncc run --time` read it; nothing here knows how it is drawn or timed.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "contract/machine_config.h"
#include "runtime/trace.h"

namespace ncc::sim {

enum class MoveKind : uint8_t {
  Rapid,   // straight, at the axes' rapid rates
  Line,    // straight, at the feed (a parabola's or a spline's chords too)
  Arc,     // circular in `plane`, helical when the plane's normal axis moves
  Thread,  // straight, with the spindle: `feed` follows from the pitch and the spindle speed
};

struct Move {
  MoveKind kind = MoveKind::Line;
  bool programmed = false;    // the programmed path under cutter compensation (drawn beside the tool centre's)
  uint8_t process = 0;        // NC-110 chapter 4: the process that moved
  int tool = 0;               // the tool in the spindle (0: none)
  uint32_t source = 0;        // SourceMap::blocks index of the block that moved
  uint32_t run = 0;           // which run of a block, counted from 1 (0: the run gave no block events)
  AxisValues start{}, end{};  // mm (linear axes), degrees (rotary)
  double feed = 0;            // mm/min the program asks for (0: a rapid, or no feed); a thread's from its pitch
  // Arc: the plane, the centre in its (u, v) axes, the radius, the sweep in degrees
  // (negative clockwise seen from +w, beyond 360 for several turns).
  Plane plane;
  double centre[2] = {0, 0};
  double radius = 0;
  double sweep = 0;
  bool exact_stop = false;  // the machine stops at its end (exact stop, G61/G09 and their kin)
};

// What takes time without moving, after the moves before it (`after` = their count):
// the machine stands still there.
struct Pause {
  enum class Kind : uint8_t {
    Dwell,       // `seconds`
    ToolChange,  // `tool`
    Spindle,     // the spindle goes from `rpm_from` to `rpm_to` (a start, a stop, a new speed)
    Stop,        // a program stop or the end: the machine comes to rest
  };
  Kind kind = Kind::Dwell;
  uint8_t process = 0;  // NC-110 chapter 4: the process that paused
  uint32_t after = 0;
  uint32_t source = 0;
  uint32_t run = 0;  // as Move::run
  double seconds = 0;
  int tool = 0;
  double rpm_from = 0, rpm_to = 0;
};

// The work offset in force from move `from` on (the view's panel shows it).
struct OffsetChange {
  uint32_t from = 0;
  int number = 0;  // 0: none (machine coordinates)
  AxisValues values{};
};

struct Toolpath {
  // In the order they ran; a programmed move comes before the tool centre's moves it
  // became (compensation waits for the next move to know the corner).
  std::vector<Move> moves;
  std::vector<Pause> pauses;
  std::vector<OffsetChange> offsets;
  std::vector<std::pair<int, double>> tool_radii;  // tool, radius in mm: the profile's or the compensation's
  AxisValues origin{};                 // machine coordinates of the work zero the positions are measured from (mm)
  std::optional<uint32_t> stopped_at;  // the block with errors the path ends before (ToolpathSink::stop_at)
  std::optional<uint32_t> full_at;     // the block whose move found the path full (kMaxMoves)
  std::string axes;                    // the letters the machine has (conventions.axes)

  double tool_radius(int tool) const;  // 0: unknown
};

// How far a move goes, mm: the linear axes' path (an arc's in its plane with the other
// linear axes' travel), or the degrees of a move of rotary axes alone (LinuxCNC's
// rule). What a feed covers; the time models' length.
double move_length(const Move& m, const MachineConfig& machine);

// The most moves a Toolpath keeps (about 1 GiB): a run that makes more, a loop that
// never ends, ends its path there (Toolpath::full_at) and its drawing says so.
inline constexpr size_t kMaxMoves = 4'000'000;

// Builds a Toolpath from the events of a run with the trace in machine coordinates
// (RunSettings::trace_machine_frame), and its block events (trace_blocks) to tell the
// runs of one block apart (a loop's iterations): the positions are moved to the first work zero
// the program selects, so that a program working in one offset shows its own
// coordinates and one working in several shows each part where it is on the machine.
// Inches become mm; parabolas and splines become chords within `chord_tolerance` mm.
class ToolpathSink final : public TraceSink {
 public:
  ToolpathSink(Toolpath& path, const MachineConfig& machine, double chord_tolerance = 0.001,
               size_t max_moves = kMaxMoves);
  void event(const Event& e) override;
  void programmed(const Event& e) override;
  bool wants_programmed() const override { return true; }
  void flush() override;  // the run ended: positions from the work zero (once)
  // The path ends as the first block marked here starts (the compiler found errors in
  // it): a drawing shows what the program does up to its first error. Needs the run's
  // block events (RunSettings::trace_blocks).
  void stop_at(std::vector<bool> blocks_with_errors) { errors_ = std::move(blocks_with_errors); }

 private:
  void add_move(const Event& e, bool programmed);
  AxisValues scaled(const AxisValues& p) const;  // in mm
  double feed(double length) const;              // mm/min
  uint32_t count() const { return static_cast<uint32_t>(path_.moves.size()); }

  Toolpath& path_;
  const MachineConfig& machine_;
  double chord_tolerance_;
  size_t max_moves_;
  double scale_ = 1;   // mm per program unit
  int feed_mode_ = 1;  // FeedMode's n
  double feed_rate_ = 0, rpm_ = 0;
  bool feed_reduced_ = false, exact_stop_ = false, spindle_on_ = false, flushed_ = false;
  int tool_ = 0;
  uint32_t run_ = 0;               // the block events so far
  uint32_t decelerate_run_ = ~0u;  // the block run that decelerates to a stop (G09)
  AxisValues at_[8]{};             // where each process's tool stands; NC-110 has 5
  AxisValues programmed_at_[8]{};
  std::vector<bool> errors_;
};

}  // namespace ncc::sim
