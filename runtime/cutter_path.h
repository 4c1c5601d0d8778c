// Cutter radius compensation as a stage between the runtime and the trace (ISO §8.10,
// Fanuc type A): the moves it receives are the programmed path; it sends on the path
// of the tool's centre, offset by the radius to the side the last CutterComp event
// set. Each move waits for the next, whose direction decides where the two offset
// moves meet: inside a corner at their intersection, outside it around the
// programmed corner by an arc of the radius.
#pragma once

#include <memory>
#include <string>

#include "trace.h"

namespace ncc {

class CutterPath {
 public:
  // `report(context, source, what)`: a problem of the block `source` (E-12 and its kin).
  using Report = void (*)(void* context, uint32_t source, const std::string& what);
  CutterPath(TraceSink& out, Report report, void* context);
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
  // The end of the run: a path still waiting leaves at a right angle (`exit`), or just
  // ends beside its last point (a run an error stopped).
  void finish(bool exit = true);
  // The events held while a move waits for the next (a loop that never moves in the
  // plane makes them grow), and their bytes.
  size_t held_events() const;
  uint64_t held_bytes() const;

  struct State;  // the geometry (Eigen) stays out of this header

 private:
  std::unique_ptr<State> s_;
};

}  // namespace ncc
