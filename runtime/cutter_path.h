// Cutter radius compensation as a stage between the runtime and the trace: the moves
// it receives are the programmed path; it sends on the path of the tool's centre,
// offset by the radius to the side the last CutterComp event set. Each move waits for
// the next, whose direction decides where the two offset moves meet: inside a corner
// at their intersection; outside it as the dialect's rules say (CompRules): around
// the programmed corner by an arc of the radius (ISO §8.10, Fanuc type A), or where
// the offsets meet (NC-110 §2.8.7). A corner may be cut first by a fillet or a
// chamfer of its own block (NC-110 r, b).
#pragma once

#include <memory>
#include <string>

#include "trace.h"

namespace ncc {

// Where the dialects' compensations differ.
struct CompRules {
  bool round_outside = true;  // an outside corner: an arc round it (Fanuc A), or where the offsets meet (NC-110)
  bool cancel_after = false;  // G40: ends with its own block's move (Fanuc), or with the next block's (NC-110)
  bool start_along =
      false;  // G41/G42 in a block of their own: the next move starts up (NC-110), not a right angle (Fanuc)
  bool alarm_codes = true;      // messages name the alarm a rule is (ISO's E-12)
  bool zero_radius_off = true;  // a radius of 0 is no compensation (ISO D0), or a path of radius 0 (NC-110)
};

class CutterPath {
 public:
  // `report(context, source, what)`: a problem of the block `source` (E-12 and its kin).
  using Report = void (*)(void* context, uint32_t source, const std::string& what);
  CutterPath(TraceSink& out, Report report, void* context, CompRules rules = {});
  ~CutterPath();

  // An event of the runtime; `start`: where a move starts (trace coordinates).
  void event(const Event& e, const AxisValues* start);
  // True while moves only pass through (no compensation, nothing waiting): a runtime
  // whose trace drops them need not send them.
  bool passes_moves() const;
  // G28, G29, G53 and the canned cycles move with the vector zeroed (§8.10): the path
  // leaves the offset before their block's moves (suspend) and starts up again with
  // the first move after them (resume).
  void suspend();
  void resume();
  // NC-110 r and b (§2.8.7): the corner between the waiting move and the next is cut
  // by a fillet of signed radius `size` (counter-clockwise when positive; 0 rolls the
  // tool round an outside corner) or a chamfer set back `size` along each move.
  void corner(bool fillet, double size, uint32_t source);
  // The end of the run: a path still waiting leaves at a right angle (`exit`), or just
  // ends beside its last point (a run an error stopped).
  void finish(bool exit = true);
  // A code that changes the axes under the path (NC-110 UAV): a move waiting leaves now,
  // at a right angle back to its programmed end.
  void leave();
  // The events held while a move waits for the next (a loop that never moves in the
  // plane makes them grow), and their bytes.
  size_t held_events() const;
  uint64_t held_bytes() const;

  struct State;  // the geometry (Eigen) stays out of this header

 private:
  std::unique_ptr<State> s_;
};

}  // namespace ncc
