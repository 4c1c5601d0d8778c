// One program's run: a VM on one machine with its devices, running the programs of
// the medium in order from an entry. A run without process features is this alone
// (the driver's ModuleRun); the scheduler of processes.h runs one in each process.
#pragma once

#include <memory>
#include <optional>

#include "vm.h"

namespace ncc::vm {

class ProgramRun {
 public:
  // `options.services` the run leaves unset, `devices` answers (none: no devices).
  // `medium`: a program's end goes on with the next program on the medium (process 1).
  ProgramRun(const Module& module, std::unique_ptr<BlockMachine> machine, std::unique_ptr<ServiceHost> devices,
             RuntimeIssues& issues, VmOptions options, bool medium);

  void start(size_t entry);  // from entry `entry` (past the entries: runs nothing)
  // One turn of the VM while running() (with VmOptions::by_block or slice, a block);
  // after it, running() says whether a program goes on. Error: reported.
  RunStatus step();
  void finish(bool ok) { machine_->end_run(!ok); }
  bool running() const { return running_; }     // a program is loaded (it may wait: vm().waiting())
  std::optional<uint32_t> next_source() const;  // the block it runs next (none: it ended)
  uint64_t steps() const { return vm_->steps(); }
  BlockMachine& machine() const { return *machine_; }
  Vm& vm() const { return *vm_; }

 private:
  bool next_program();

  const Module& module_;
  std::unique_ptr<BlockMachine> machine_;
  std::unique_ptr<ServiceHost> devices_;
  std::unique_ptr<Vm> vm_;
  bool medium_;
  bool running_ = false;
  size_t entry_ = 0;  // the entry running (process 1: its place on the medium)
};

}  // namespace ncc::vm
