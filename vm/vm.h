// The deterministic VM: runs a verified Module on the motion runtime. Control flow,
// expressions and variables live here; geometry lives in the runtime (Machine).
#pragma once

#include <cstdint>
#include <vector>

#include "module.h"
#include "runtime/machine.h"

namespace ncc::vm {

struct VmOptions {
  uint64_t max_steps = 0;  // executed blocks before StepLimit; 0 = no limit
  bool block_skip = false;
};

enum class RunStatus { UnitEnded, ProgramEnd, EndOfInformation, Error };

class Vm {
 public:
  Vm(const Module& module, Machine& machine, RuntimeIssues& issues, VmOptions options);

  // Runs from entry point `entry` until the unit ends, the program ends (M02), the
  // information ends (M30) or an error stops it.
  RunStatus run(uint32_t entry);
  uint64_t steps() const { return steps_; }
  uint32_t pc() const { return process_.pc; }  // where the last run stopped

 private:
  struct Frame {
    uint32_t return_pc;
    size_t loops;  // repeat loops open when the call was made
  };
  struct Loop {
    int64_t remaining;
  };
  // The execution state of one process. Multi-process dialects run several.
  struct Process {
    uint32_t pc = 0;
    std::vector<double> stack;
    std::vector<Frame> frames;
    std::vector<Loop> loops;
  };

  template <typename... Args>
  RunStatus fail(uint32_t pc, DiagId id, const Args&... args);
  double load(uint8_t space, double index, uint32_t pc, bool& ok);
  bool store(uint8_t space, double index, double value, uint32_t pc);

  const Module& m_;
  Machine& machine_;
  RuntimeIssues& issues_;
  VmOptions options_;
  uint64_t steps_ = 0;
  std::vector<std::vector<double>> vars_;
  Process process_;
  std::vector<uint16_t> codes_;  // the pending block
  BlockWords words_;
};

}  // namespace ncc::vm
