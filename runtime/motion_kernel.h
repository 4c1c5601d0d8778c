// The motion kernel: where the machine is and how long it has run, the coordinates a
// program's positions are in (the frame, the work offsets), the working envelope, and
// the output every event leaves through (held for a corner, through the cutter path,
// to the trace). It knows no words, modes or dialect: what a block decides (its
// plane, inch or mm, which origin its targets are from) comes as arguments. Machine
// interprets blocks on top of it.
#pragma once

#include <algorithm>
#include <deque>
#include <map>
#include <memory>
#include <vector>

#include "contract/machine_config.h"
#include "cutter_path.h"
#include "envelope.h"
#include "frame.h"

namespace ncc {

class MotionKernel {
 public:
  // `path`: the traced cutter path, or none (the machine compensates G41/G42 itself).
  MotionKernel(const MachineConfig& config, TraceSink& trace, std::unique_ptr<CutterPath> path);
  ~MotionKernel();

  // Where the controlled point is: machine coordinates, mm / degrees.
  const AxisValues& position() const { return position_; }
  void move_to(const AxisValues& machine) { position_ = machine; }
  void place(int axis, double machine) { position_[axis] = machine; }  // no move: a virtual axis takes a letter

  // Seconds of the run so far.
  double clock() const { return clock_; }
  void advance_clock(double seconds) { clock_ += seconds; }
  void wait_until(double seconds) { clock_ = std::max(clock_, seconds); }

  // The recent moves, for a run of several processes (RMN): a block that took time
  // went from `from` at `from_t` to where the machine is now.
  void record_move(double from_t, const AxisValues& from);
  double remaining_at(int axis, double seconds) const;  // of the path still to go

  // The coordinates. After frame().base or offsets() change, refresh_origins().
  Frame& frame() { return frame_; }
  const Frame& frame() const { return frame_; }
  std::map<int, WorkOffset>& offsets() { return offsets_; }
  const std::map<int, WorkOffset>& offsets() const { return offsets_; }
  void refresh_origins();
  void reset_coordinates();        // M02/M30: origin 0, no transform, shift or local zero
  void select_work_offset(int n);  // on every axis, with the local zero it keeps (ISO G52)
  std::map<int, AxisValues>& local_offsets() { return local_offsets_; }  // ISO G52: per work offset
  AxisValues& position_offset() { return position_offset_; }             // G92, as last shown
  const AxisValues& position_offset() const { return position_offset_; }

  double offset_value(int offset, int axis) const;  // machine units
  // Of the active frame; hot: every move asks.
  double origin(int axis) const { return base_origin_[axis] + frame_.shift[axis] + frame_.local[axis]; }
  AxisValues origins() const;
  AxisValues shown_origins() const;                // what the trace's positions are from
  AxisValues frame_offset(int work_offset) const;  // a work offset + the shift and local zero

  // Which origin a block's positions are from: the active one (transformed by the
  // frame), the machine's zero, or work offset n for this block only (not transformed).
  static constexpr int kActiveOrigin = -1, kMachineZero = 0;
  AxisValues block_origins(int origin) const;
  bool transforms(int origin) const { return origin == kActiveOrigin && frame_.transformed(); }
  AxisValues to_machine(const AxisValues& program, const Plane& plane, int origin) const;
  AxisValues to_frame(const AxisValues& machine, const Plane& plane, int origin) const;

  // The working limits and protected zones the path of every move is checked against.
  Envelope& envelope() { return envelope_; }
  const Envelope& envelope() const { return envelope_; }

  // A machine position in program units (`inch`), and a move's event: positions from
  // the shown origin, endless rotary axes wrapped.
  double in_units(int axis, double machine, bool inch) const;
  AxisValues in_units(AxisValues machine, bool inch) const;
  Event motion_event(EventKind kind, const AxisValues& machine_target, bool inch) const;

  // The output. Whether an event of this kind goes anywhere: to the trace, the held
  // events, or the cutter path (which follows every plane and compensation change,
  // and moves while it offsets them). Hot: every move asks.
  bool wanted(EventKind kind) const {
    return events_wanted_ || holding_ || (path_ && (!is_move(kind) || !path_->passes_moves()));
  }
  // An event out; a move starts where the machine stands (it moves after its event),
  // which only the cutter path needs to know.
  void emit(const Event& e, bool inch) {
    if (!is_move(e.kind) || !path_ || path_->passes_moves()) return out(e);
    const AxisValues start = motion_event(EventKind::Linear, position_, inch).pos;
    out(e, &start);
  }
  void out(const Event& e, const AxisValues* start = nullptr) {  // to the trace, or held back
    if (!holding_) return to_path(e, start);
    held_.push_back(e);
  }
  CutterPath* path() const { return path_.get(); }
  // The hold (ISO's chamfers and fillets): from hold() every event waits in held()
  // until it is passed on; `start` is where the first held move starts (trace
  // coordinates), unless the kernel holds already.
  void hold(const AxisValues& start) {
    if (!holding_) hold_start_ = start;
    holding_ = true;
  }
  bool holding() const { return holding_; }
  std::vector<Event>& held() { return held_; }
  const std::vector<Event>& held() const { return held_; }
  void pass_on(size_t count);  // the first `count` held events, on
  void release();              // all of them, and no more holding

 private:
  const MachineConfig& config_;
  AxisValues position_{};
  double clock_ = 0;
  struct Move {
    double from_t, to_t;
    AxisValues from, to;
  };
  std::deque<Move> moves_;  // the last blocks that moved

  Frame frame_;
  std::map<int, WorkOffset> offsets_;  // the work offsets (NC-110 RQO changes them)
  AxisValues base_origin_{};           // each axis' offsets_ value at frame_.base: origin() is hot
  std::map<int, AxisValues> local_offsets_;
  AxisValues position_offset_{};
  Envelope envelope_;  // NC-110 DLO, DSA

  TraceSink& trace_;
  const bool events_wanted_;
  std::unique_ptr<CutterPath> path_;
  std::vector<Event> held_;
  bool holding_ = false;
  AxisValues hold_start_{};                               // where the first held move starts
  void to_path(const Event& e, const AxisValues* start);  // through the cutter path, if there is one
};

}  // namespace ncc
