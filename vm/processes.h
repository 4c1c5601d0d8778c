// The processes of a run (NC-110 chapter 4): up to five programs side by side, each
// a ProgramRun (program_run.h) with its own machine, E parameters and devices (its
// ASSET channels), sharing SYVAR, SA, SK (and the devices what their maker shares:
// the user screen). A deterministic scheduler runs them a block at a time, the one
// whose next block is evaluated first (decision 63), and answers the process services
// (EXE, REL, WAI, SND, wait-until) and deadlocks. Only a module that needs it runs
// here (needed()); any other runs on a ProgramRun alone.
#pragma once

#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "program_run.h"
#include "vm.h"

namespace ncc::vm {

// The PLC writes a memory (SA12=1) when no process can go on without it (decision 63).
struct PlcWrite {
  uint8_t space = 0;
  MemFormat format = MemFormat::Byte;
  uint32_t index = 0;
  double value = 0;
  std::string text;  // as the script writes it
};

// A process's machine, powered on, made by whoever runs the module (the VM knows no
// machine): `others` is the scheduler in a run of several processes (RMN reads their
// paths, and the trace marks each event with its process), none in a run of one.
using MachineMaker = std::function<std::unique_ptr<BlockMachine>(uint8_t process, RemainingPaths* others)>;
// A process's devices, made by whoever runs the module as it makes the machines: they
// answer every service but the processes' (contract/services.h), which the scheduler
// answers.
using DevicesMaker = std::function<std::unique_ptr<ServiceHost>(uint8_t process)>;

struct ProcessSetup {
  const Module& module;
  MachineMaker make_machine;
  DevicesMaker make_devices;  // none: the run has no devices
  RuntimeIssues& issues;
  // Each process's VM (its services, shared and slice are set here; look_ahead only in
  // a run of several).
  VmOptions options;
  bool dry = false;  // the dry run of `ncc check`: the machines recover from errors, conditions are assumed met
  uint8_t processes = kMaxProcesses;  // configured (profile)
  std::deque<PlcWrite> plc = {};
  bool by_block = false;  // each step() runs one block (a host steps the run)
};

class Processes final : public ServiceHost, public RemainingPaths {
 public:
  explicit Processes(ProcessSetup setup);
  ~Processes() override;

  // A module needs the scheduler when it has processes or calls a process service.
  static bool needed(const Module& module);

  // Runs entry `first` and the programs after it on the medium in process 1, and the
  // programs selected for other processes, in steps: begin (false: it cannot start,
  // reported), then step until it returns Ended or Error, then finish. With
  // ProcessSetup::by_block a step runs one block.
  // [[nodiscard]] on a declaration first: clang-format 14 mangles it on the definition.
  enum class [[nodiscard]] Turn;
  enum class Turn { Continue, Ended, Error };
  [[nodiscard]] bool begin(size_t first);
  Turn step();
  void finish(bool ok);
  const BlockMachine* machine(uint8_t process) const;  // none before it runs
  bool running() const;                                // a process has a program to go on with
  std::optional<uint32_t> next_source() const;         // the block process 1 runs next (none: it ended)
  uint64_t steps() const;

  // EXE, REL, WAI, SND of the process whose turn it is.
  ServiceResult call(Service service, ServiceCall& call) override;
  double remaining(int process, int axis) override;

 private:
  struct Slot;
  Slot& slot(uint8_t n);  // made (its machine powered on) at first use
  [[nodiscard]] uint8_t number(double process, uint32_t source, const char* what);  // 0: not a process (reported)
  Service waits_in(const Slot& s) const;                                 // the service s is blocked at (Count: none)
  bool waits_at(const Slot& s, Service service, uint8_t partner) const;  // s is blocked at `service` naming `partner`
  void deadlock();
  // Done (a sync event shows it), Wait (the first time, an event shows what it waits
  // for) or Error (reported).
  ServiceResult answer(ServiceCall& call, ServiceResult result, const std::string& done, const std::string& waits);
  ServiceResult start(double process, uint32_t entry, uint32_t source);
  ServiceResult meet(double process, uint32_t source, const char* what, Service partner);
  ServiceResult wait_until(ServiceCall& call);

  ProcessSetup setup_;
  bool several_;  // a run of several processes: turns, and traces marked with the process
  SharedState shared_;
  std::vector<std::unique_ptr<Slot>> slots_;  // index = process number - 1
  uint8_t current_ = 1;                       // the process whose turn it is
  bool assume_ = false;
};

}  // namespace ncc::vm
