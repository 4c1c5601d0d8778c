// The processes of a run (NC-110 chapter 4): up to five programs side by side, each
// with its own machine, E parameters, ASSET channels and VM, sharing SYVAR, SA, SK
// and the user screen. A deterministic scheduler runs them a block at a time, the
// one whose next block is evaluated first (decision 63); a run with no Process entry
// is process 1 alone, run to the end in one go.
#pragma once

#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "devices/asset_channels.h"
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

struct ProcessSetup {
  const Module& module;
  MachineMaker make_machine;
  RuntimeIssues& issues;
  // Each process's VM (its asset, shared, processes, process and slice are set here;
  // look_ahead only in a run of several).
  VmOptions options;
  bool dry = false;  // the dry run of `ncc check`: the machines recover from errors, conditions are assumed met
  uint8_t processes = kMaxProcesses;  // configured (profile)
  // ASSET files: a process's channels are its own, the files open are the run's.
  asset::Store* store = nullptr;
  bool files = false;  // the statements act (a real run)
  asset::Channels::Settings channels = {};
  std::deque<PlcWrite> plc = {};
  bool by_block = false;  // each step() runs one block (a host steps the run)
};

class Processes final : public ProcessHost, public RemainingPaths {
 public:
  explicit Processes(ProcessSetup setup);
  ~Processes() override;

  // Runs entry `first` and the programs after it on the medium in process 1, and the
  // programs selected for other processes; false if an error stopped the run.
  [[nodiscard]] bool run(size_t first);
  // The same in steps, as a host drives a run: begin (false: it cannot start,
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
  const screen::UserScreen& user_screen() const { return shared_.screen; }

  Answer start(double process, uint32_t entry, uint32_t pc) override;
  Answer wait_for(double process, uint32_t pc) override;
  Answer signal(double process, uint32_t pc) override;
  bool assume_met() override { return assume_; }
  double remaining(int process, int axis) override;

 private:
  struct Slot;
  Slot& slot(uint8_t n);  // made (its machine powered on) at first use
  [[nodiscard]] uint8_t number(double process, uint32_t pc, const char* what);  // 0: not a process (reported)
  bool waits_at(const Slot& s, Op op, uint8_t partner) const;                   // s is blocked at `op` naming `partner`
  bool next_program(Slot& s);  // process 1: the next program on the medium
  void deadlock();
  Answer meet(double process, uint32_t pc, const char* what, Op partner);

  ProcessSetup setup_;
  bool several_;  // a run of several processes: turns, and traces marked with the process
  SharedState shared_;
  asset::OpenFiles open_files_;
  std::vector<std::unique_ptr<Slot>> slots_;  // index = process number - 1
  uint8_t current_ = 1;                       // the process whose turn it is
  bool assume_ = false;
};

}  // namespace ncc::vm
