// The deterministic VM: runs a verified Module on the motion runtime. Control flow,
// expressions and variables live here; geometry lives in the machine it drives
// (contract/block_machine.h), and a controller's services (files, the keyboard, the
// screen, processes) in the hosts of their devices (contract/services.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "contract/block_machine.h"
#include "contract/services.h"
#include "module.h"
#include "opcodes.h"

namespace ncc::vm {

// What the processes of a run share of the VM's (NC-110 §4.1.3): the memories SYVAR,
// SA and SK (the user screen and the operator's answers are the devices').
struct SharedState {
  std::vector<std::vector<uint8_t>> memories;  // of the memory spaces (empty for the others)
  double written_at =
      0;  // the latest time a process (or the PLC) wrote a memory: a WAI condition met goes on from there
};

struct VmOptions {
  uint64_t max_steps = 0;         // steps before StepLimit: blocks, and moves beyond a block's first; 0 = no limit
  uint64_t max_memory = 0;        // bytes the runtime may hold (Machine::held_bytes) before RunMemory; 0 = no limit
  bool trace_blocks = false;      // a `block` event as each block starts
  ServiceHosts services = {};     // who answers each device's services (contract/services.h)
  SharedState* shared = nullptr;  // none: the VM's own
  bool slice = false;             // resume() runs one block, then returns Yield
  bool by_block = false;          // the same for a host that steps the run (only between blocks)
  // Blocks evaluated ahead of the motion (NC-110 §2.16: the look-ahead of a run of
  // several processes, where it shows); 0: each block once the motion before it ended.
  uint32_t look_ahead = 0;
};

// Released: REL ended the program (NC-110). Yield: the block is done, others may run
// (VmOptions::slice). Blocked: an instruction waits for another process; resume()
// runs it again.
// [[nodiscard]] on a declaration first: clang-format 14 mangles it on the definition.
enum class [[nodiscard]] RunStatus;
enum class RunStatus { UnitEnded, ProgramEnd, EndOfInformation, Error, Released, Yield, Blocked };

class Vm {
 public:
  Vm(const Module& module, BlockMachine& machine, RuntimeIssues& issues, VmOptions options);

  // Runs from entry point `entry` until the unit ends, the program ends (M02), the
  // information ends (M30) or an error stops it.
  RunStatus run(uint32_t entry) {
    start(entry);
    return resume();
  }
  // The same in turns: start, then resume until it returns neither Yield nor Blocked.
  void start(uint32_t entry);
  RunStatus resume();
  uint64_t steps() const { return steps_; }
  uint32_t pc() const { return process_.pc; }          // where the last run stopped (Blocked: the waiting instruction)
  bool waiting() const { return waiting_; }            // the last resume returned Blocked, at pc()
  const std::string& waits() const { return waits_; }  // Blocked: what for ("wait for process 2")
  double blocked_operand() const {
    return process_.stack.empty() ? 0 : process_.stack.back();
  }  // Blocked: the process named
  // When the block being run is evaluated: with a look-ahead, while earlier motion
  // may still run; else when it ended (the machine's clock).
  double eval_time() const { return options_.look_ahead ? eval_ : machine_.clock(); }
  // The process waited for another until `seconds`: it evaluates, and moves, from then on.
  void wait_until(double seconds) {
    eval_ = std::max(eval_, seconds);
    machine_.wait_until(seconds);
  }
  // The PLC writes a memory (SA, SK: a run's input script): index and value fit.
  void write_memory(uint8_t space, MemFormat f, uint32_t index, double value) {
    (void)store_mem(space, f, index, value, 0);  // the script's reader (plc_write) checked index and value
  }

 private:
  struct Arg {
    uint8_t space;
    uint32_t index;
    double value;
  };
  struct Frame {
    uint32_t return_pc;
    size_t loops;  // repeat loops open when the call was made
    bool range = false;
    uint32_t start = 0, end = 0;  // a range: its first instruction and its RangeEnd
    size_t base = 0;              // the open loops its code's loop depth 0 stands for
    uint32_t entry = 0;           // a call: where each of its repetitions starts
    int64_t remaining = 0;        //         the repetitions after this one
    std::vector<double> locals;   //         the caller's local variables
    bool shared = false;          //         keeps the caller's locals (CALLSHARED)
    std::vector<Arg> args;        //         the values each repetition starts with
  };
  struct Loop {
    int64_t remaining;
  };
  // The execution state of the process this VM runs (a run of several processes has
  // a VM for each: processes.h).
  struct Process {
    uint32_t pc = 0;
    std::vector<double> stack;
    std::vector<Frame> frames;
    std::vector<Loop> loops;
  };

  // A run-time error of the block at pc; at its word of `slot`, if it has one. fail()
  // is report_error() as the status that stops the run: `return fail(...)`.
  template <typename... Args>
  void report_error(uint32_t pc, DiagIdFor<Args...> id, const Args&... args);
  template <typename... Args>
  RunStatus fail(uint32_t pc, DiagIdFor<Args...> id, const Args&... args);
  template <typename... Args>
  RunStatus fail_at(uint32_t pc, int slot, int nth, DiagIdFor<Args...> id, const Args&... args);
  // The variable `index` names in `space`, or none (reported).
  [[nodiscard]] std::optional<uint32_t> variable(uint8_t space, double index, uint32_t pc);
  double load(uint8_t space, double index, uint32_t pc, bool& ok);
  [[nodiscard]] bool store(uint8_t space, double index, double value, uint32_t pc);
  // A run of `count` bytes of memory `space` at byte `index`, or nullptr (reported).
  [[nodiscard]] uint8_t* bytes(uint8_t space, double index, uint32_t count, uint32_t pc);
  [[nodiscard]] bool load_mem(uint8_t space, MemFormat f, double index, uint32_t pc, double& out);
  [[nodiscard]] bool store_mem(uint8_t space, MemFormat f, double index, double value, uint32_t pc);
  // A memory changed now: a WAI condition it meets goes on from this time.
  void wrote_memory() { shared_.written_at = std::max(shared_.written_at, eval_time()); }
  // SERVICE: the host of the service's device runs it, seeing the VM through a Call.
  class Call;
  ServiceResult call_service(Service service, const uint8_t* operands, uint32_t pc);
  // The look-ahead: the time the block being run is evaluated, and when each of the
  // last look_ahead blocks ended its motion (a ring, by block count).
  void look_ahead();
  static constexpr double kBlockCycle = 0.001;  // seconds
  double eval_ = 0;
  std::vector<double> ends_;
  bool waiting_ = false;    // the instruction at pc waits (Blocked)
  bool mid_block_ = false;  // the last turn ended inside a block (SYNC)
  std::string waits_;       // what for
  // Jumps; a jump out of a range ends it. After Unloop, the loops deeper than the
  // target's depth close.
  void jump_to(uint32_t target);
  std::optional<size_t> landing_depth_;
  size_t calls() const;
  // The local variables of every space, all in one, and reset (a call starts with
  // zeros, or vacant ones), then the call's arguments set.
  std::vector<double> take_locals(const std::vector<Arg>& args);
  void restore_locals(const std::vector<double>& saved);

  const Module& m_;
  BlockMachine& machine_;
  RuntimeIssues& issues_;
  VmOptions options_;
  uint64_t steps_ = 0;
  std::vector<std::vector<double>> vars_;
  SharedState own_;
  SharedState& shared_;  // own_, or the run's
  Process process_;
  std::vector<uint16_t> codes_;  // the pending block
  BlockWords words_;
  std::string message_;                 // the pending operator message
  uint64_t dynamic_codes_ = 0;          // the pending block's codes chosen at run time (bit i: codes_[i])
  std::vector<uint8_t> dynamic_slots_;  // their words' slots, in order (GE1 GE2: G, G)
  std::vector<Arg> args_;               // the next call's arguments
  bool vacancy_ = false;                // a space holds vacant values: a vacant word value or code is omitted
  // Per numbered space, the type of each variable (VarSpace::type_of, looked up once);
  // empty when all are long reals.
  std::vector<std::vector<VarType>> types_;
  VarType type_at(uint8_t space, uint32_t index) const {
    return types_[space].empty() ? VarType::LongReal : types_[space][index];
  }
};

}  // namespace ncc::vm
