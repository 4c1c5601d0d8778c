#include "program_run.h"

namespace ncc::vm {

ProgramRun::ProgramRun(const Module& module, std::unique_ptr<BlockMachine> machine,
                       std::unique_ptr<ServiceHost> devices, RuntimeIssues& issues, VmOptions options, bool medium)
    : module_(module), machine_(std::move(machine)), devices_(std::move(devices)), medium_(medium) {
  for (ServiceHost*& host : options.services)
    if (!host) host = devices_.get();
  vm_ = std::make_unique<Vm>(module_, *machine_, issues, options);
}

void ProgramRun::start(size_t entry) {
  entry_ = entry;
  running_ = entry < module_.entries.size();  // a file without a program runs nothing
  if (running_) vm_->start(static_cast<uint32_t>(entry));
}

RunStatus ProgramRun::step() {
  const RunStatus status = vm_->resume();
  switch (status) {
    case RunStatus::Yield:
    case RunStatus::Blocked:
    case RunStatus::Error: break;
    case RunStatus::UnitEnded: machine_->end_of_unit(module_.source_of(vm_->pc())); [[fallthrough]];
    case RunStatus::ProgramEnd: running_ = medium_ && next_program(); break;
    case RunStatus::EndOfInformation:
    case RunStatus::Released: running_ = false; break;
  }
  return status;
}

std::optional<uint32_t> ProgramRun::next_source() const {
  if (!running_) return std::nullopt;
  return module_.source_of(vm_->pc());
}

// Programs run in the order of the medium, each after the previous one ended (M02);
// M30 ends the information.
bool ProgramRun::next_program() {
  const auto& entries = module_.entries;
  for (size_t i = entry_ + 1; i < entries.size(); ++i)
    if (entries[i].kind == EntryKind::Program) {
      start(i);
      return true;
    }
  return false;
}

}  // namespace ncc::vm
