// What a dialect's M06 does besides loading the tool selected, and where a tool's
// offset comes from: a strategy of the Machine, chosen once from the program's
// conventions (ToolChange::make), as the cycle engines are (cycle_engine.h).
#pragma once

#include <memory>

#include "machine.h"

namespace ncc {

class Machine::ToolChange : public Strategy {
 public:
  using Strategy::Strategy;
  // The tool change of the program's conventions: the only place that reads their
  // tool change flags.
  static std::unique_ptr<ToolChange> make(Machine& m, const Conventions& conv);

  // M06 with the tool in the spindle selected again does nothing (ISO §8.31).
  virtual bool same_tool_ignored() const { return false; }
  // What M06 does before the tool is loaded, and after.
  virtual void before(Scope scope, bool emit_events) = 0;
  virtual void after() {}
  // A T word selected `tool` (the programmed one, or its sister): the rest of the word.
  virtual void tool_word(int /*programmed*/) {}
  // The tool's corrector is its offset, D and H words name none (NC-110: D is an axis);
  // it stays in force at the program's end (§2.7.8).
  virtual bool corrector_in_tool() const { return false; }

 protected:
  void stop_spindle_and_coolant(Scope scope, bool emit_events);
};

}  // namespace ncc
