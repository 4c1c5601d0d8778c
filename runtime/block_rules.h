// What a dialect forbids a block beyond its codes' own checks, and how a dwell shares
// a block with a move: a strategy of the Machine, chosen once from the program's
// conventions (BlockRules::make), as the cycle engines (cycle_engine.h) and the tool
// change (tool_change.h) are. The base is the plain rules of GOST 20999, pp and
// NC-110, which forbid none of ISO's but an arc under unequal scale factors (no longer
// a circle); ISO/Fanuc's (E-08..E-27) are block_rules.cpp's.
#pragma once

#include <memory>

#include "machine.h"

namespace ncc {

class Machine::BlockRules : public Strategy {
 public:
  using Strategy::Strategy;
  // The rules of the program's conventions: the only place that reads fanuc_rules
  // (and cutter, for NC-110's).
  static std::unique_ptr<BlockRules> make(Machine& m, const Conventions& conv);

  // What a code of the block asks before it acts: false, reported at the code, where
  // the rules forbid it.
  // May it run while the frame is scaled or rotated (G28, G29, G52, G53, G54-G59, G92, M06)?
  [[nodiscard]] virtual bool may_run_scaled_or_rotated() { return true; }
  // May it change the coordinates of the path, the frame or the units, while cutter
  // compensation is on?
  [[nodiscard]] virtual bool may_change_coordinates() { return true; }
  // May the plane become `plane`?
  [[nodiscard]] virtual bool may_change_plane(const Plane& /*plane*/) { return true; }
  // May the block's words be machine coordinates (G53)?
  [[nodiscard]] virtual bool may_use_machine_coordinates() { return true; }
  // May the block, between G41/G42 and G40, hold what it holds (reported at the word)?
  [[nodiscard]] virtual bool may_stand_in_compensated_path() { return true; }
  // Does a corner word (r, b) join two moves of the compensated path?
  virtual bool joins_path_corners() const { return false; }

  // A block with axis words under G02/G03, about to move: what it changed that an arc
  // may not (reported).
  virtual void check_arc() {}
  // A dwell in a block with a move dwells after it; else the block only dwells (the
  // axis words reported).
  virtual bool dwells_after_move() const { return false; }
  // An arc under unequal scale factors in its plane is drawn; else it is refused.
  virtual bool scales_arcs_unequally() const { return false; }
};

}  // namespace ncc
