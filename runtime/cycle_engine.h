// The canned cycles of a dialect family as a strategy of the Machine: GOST 20999 (and
// pp), ISO/Fanuc, NC-110, one chosen when the machine is made (CycleEngine::make).
// Nested classes of Machine, not an interface over it: a hole reads words, frames, the
// feed and the spindle, and moves through hole_steps, more than a narrow view would keep.
// The shared pieces stay the machine's: hole_steps, tap_feed and cycle_steps.h.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "machine.h"

namespace ncc {

class Machine::CycleEngine : public Strategy {
 public:
  using Strategy::Strategy;
  // The engine of the program's conventions: the only place that reads their cycle flags.
  static std::unique_ptr<CycleEngine> make(Machine& m, const Conventions& conv);

  // Whether a code of the motion group ends the active cycle (ISO).
  virtual bool motion_ends_cycle() const { return false; }
  // Whether a new cycle, or a code that would disturb one, needs the active one
  // cancelled first (NC-110 §2.8.9 note 4).
  virtual bool needs_cancel() const { return false; }
  // A cycle code stands in the block: the cycle's own block defines it anew (NC-110),
  // or the registers stay (GOST S-7.5).
  virtual void selected() {}
  // The cycle ends (its cancel, a motion code, the program's end): what it held goes.
  virtual void cancelled() = 0;
  // A block while a cycle is active; `drills`: it has an axis word or the level word.
  virtual void block(bool drills) = 0;
};

// Cycles of one level R, whose registers stay in force while the cycle is active and
// which drill in a block with a dimension word (GOST 20999, pp, ISO).
class Machine::OneLevelCycles : public CycleEngine {
 public:
  using CycleEngine::CycleEngine;
  void cancelled() override;  // the registers forgotten: a missing R is said again
  void block(bool drills) final;

 protected:
  virtual void drill() = 0;  // the block's hole (or holes)
  void registers();          // the block's words into the registers
  void no_drilling_axis();   // the plane has no axis along its normal (pp G14-G16)

  struct Registers {
    std::optional<double> depth, level, dwell, peck;  // program units as written
  } registers_;
};

// GOST 20999 Table 6 and pp: one hole a block, from the level the tool is at.
class Machine::GostCycles final : public OneLevelCycles {
 public:
  using OneLevelCycles::OneLevelCycles;

 private:
  void drill() override;
};

// ISO/Fanuc §8.21-8.27: L (or K) holes a block, G98/G99 back to the initial level or R;
// a code of the motion group ends the cycle.
class Machine::IsoCycles final : public OneLevelCycles {
 public:
  using OneLevelCycles::OneLevelCycles;
  bool motion_ends_cycle() const override { return true; }
  void cancelled() override {
    OneLevelCycles::cancelled();
    initial_level_.reset();
  }

 private:
  void drill() override;                 // L (or K) holes
  void drill_one();                      // one
  std::optional<double> initial_level_;  // the drilling axis where the cycle mode began (G98 returns there)
};

// NC-110 §2.8.9: the cycle's block stores it (its depth word names the drilling axis),
// the blocks after it drill; levels R1 and R2.
class Machine::Nc110Cycles final : public CycleEngine {
 public:
  using CycleEngine::CycleEngine;
  bool needs_cancel() const override { return true; }
  void selected() override {
    registers_ = {};
    registers_.defined_here = true;
  }
  void cancelled() override { registers_ = {}; }
  void block(bool drills) override;

 private:
  void registers(bool definition);
  [[nodiscard]] bool define(const CyclePattern& pattern, const std::vector<int>& written);  // the cycle's block
  [[nodiscard]] bool levels_ok(const CyclePattern& pattern);
  [[nodiscard]] bool registers_ok(const CyclePattern& pattern);

  struct Registers {
    int axis = -1;  // the drilling axis; its levels in program coordinates
    std::optional<double> r1, r2, bottom;
    std::optional<double> step, factor, minimum;  // G83 I K J
    std::optional<double> pitch;                  // G84 K (spindle encoder)
    bool defined_here = false;                    // the cycle's own block
  } registers_;
};

}  // namespace ncc
