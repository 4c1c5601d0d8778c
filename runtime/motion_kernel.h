// The motion kernel: where the machine is and how long it has run, the coordinates a
// program's positions are in (the frame, the work offsets) and the working envelope.
// It knows no words, modes or dialect: what a block decides (its plane, which origin
// its targets are from) comes as arguments. Machine interprets blocks on top of it.
#pragma once

#include <algorithm>
#include <deque>
#include <map>

#include "contract/machine_config.h"
#include "envelope.h"
#include "frame.h"

namespace ncc {

class MotionKernel {
 public:
  explicit MotionKernel(const MachineConfig& config) : config_(config) {}

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
};

}  // namespace ncc
