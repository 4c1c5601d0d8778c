#include "processes.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "support/numbers.h"
#include "support/text.h"

namespace ncc::vm {

// A process: its program's run, and what the scheduler keeps of it.
struct Processes::Slot {
  ProgramRun run;
  bool delivered = false;  // a partner met its WAI or SND: it completes when it runs again
  double free_at = 0;      // when its last program ended
};

Processes::Processes(ProcessSetup setup) : setup_(std::move(setup)) {
  const auto& entries = setup_.module.entries;
  several_ = std::any_of(entries.begin(), entries.end(), [](const Entry& e) { return e.kind == EntryKind::Process; });
  slots_.resize(std::max<size_t>(setup_.processes, 1));
}

Processes::~Processes() = default;

bool Processes::needed(const Module& module) {
  return module.calls(Device::Process) || std::any_of(module.entries.begin(), module.entries.end(), [](const Entry& e) {
           return e.kind == EntryKind::Process || e.processes;
         });
}

Processes::Slot& Processes::slot(uint8_t n) {
  std::unique_ptr<Slot>& s = slots_[n - 1];
  if (s) return *s;
  VmOptions options = setup_.options;
  options.services[static_cast<size_t>(Device::Process)] = this;
  options.shared = &shared_;
  options.slice = several_;
  options.by_block = setup_.by_block;
  if (!several_) options.look_ahead = 0;
  s = std::make_unique<Slot>(
      Slot{ProgramRun(setup_.module, setup_.make_machine(n, several_ ? this : nullptr),
                      setup_.make_devices ? setup_.make_devices(n) : nullptr, setup_.issues, options, n == 1)});
  return *s;
}

bool Processes::begin(size_t first) {
  const auto& entries = setup_.module.entries;
  Slot& one = slot(1);
  for (size_t i = 0; i < entries.size(); ++i)
    for (uint8_t n = 2; n <= kMaxProcesses; ++n) {
      if (!(entries[i].processes >> (n - 1) & 1)) continue;
      if (n > slots_.size()) {  // selected for a process this machine lacks: number() reports it
        (void)number(n, setup_.module.source_of(entries[i].pc), "--process");
        return false;
      }
      slot(n).run.start(i);
    }
  one.run.start(first);
  return true;
}

Processes::Turn Processes::step() {
  // The process whose next block is evaluated first runs it (decision 63); one that
  // still waits lets the next one try.
  // (At most five: sorted in place, ties to the lower number, nothing allocated.)
  std::pair<double, size_t> by_time[kMaxProcesses];
  size_t count = 0;
  for (size_t i = 0; i < slots_.size(); ++i)
    if (slots_[i] && slots_[i]->run.running()) by_time[count++] = {slots_[i]->run.vm().eval_time(), i};
  if (count == 0) return Turn::Ended;
  for (size_t a = 1; a < count; ++a)
    for (size_t b = a; b > 0 && by_time[b] < by_time[b - 1]; --b) std::swap(by_time[b], by_time[b - 1]);
  std::span<const std::pair<double, size_t>> order(by_time, count);
  for (auto [time, i] : order) {
    Slot& s = *slots_[i];
    current_ = static_cast<uint8_t>(i + 1);
    Vm& vm = s.run.vm();
    const bool was_waiting = vm.waiting();
    const uint32_t was_at = vm.pc();
    const RunStatus status = s.run.step();
    if (status == RunStatus::Error) return Turn::Error;
    const bool progress = status != RunStatus::Blocked || !was_waiting || vm.pc() != was_at;
    if (!s.run.running()) s.free_at = s.run.machine().clock();
    if (progress) {
      assume_ = false;
      return Turn::Continue;
    }
  }
  // No process can go on: the PLC's next signal, in the dry run a condition taken
  // as met, else a deadlock.
  Slot* waiter = nullptr;  // the first that waits for a condition
  for (auto [time, i] : order)
    if (!waiter && waits_in(*slots_[i]) == Service::ProcessWaitUntil) waiter = slots_[i].get();
  if (waiter && !setup_.plc.empty()) {
    const PlcWrite w = setup_.plc.front();
    setup_.plc.pop_front();
    // It comes once every process stopped, and shows at the first that waits for a condition.
    for (auto [time, i] : order) shared_.written_at = std::max(shared_.written_at, time);
    waiter->run.machine().sync_event("PLC " + w.text, setup_.module.source_of(waiter->run.vm().pc()));
    waiter->run.vm().write_memory(w.space, w.format, w.index, w.value);
  } else if (waiter && setup_.dry && !assume_) {
    assume_ = true;
  } else {
    deadlock();
    return Turn::Error;
  }
  return Turn::Continue;
}

void Processes::finish(bool ok) {
  for (const auto& s : slots_)
    if (s) s->run.finish(ok);
}

bool Processes::running() const {
  return std::any_of(slots_.begin(), slots_.end(), [](const auto& s) { return s && s->run.running(); });
}

const BlockMachine* Processes::machine(uint8_t n) const {
  return n >= 1 && n <= slots_.size() && slots_[n - 1] ? &slots_[n - 1]->run.machine() : nullptr;
}

std::optional<uint32_t> Processes::next_source() const {
  return slots_.empty() || !slots_[0] ? std::nullopt : slots_[0]->run.next_source();
}

uint64_t Processes::steps() const {
  uint64_t n = 0;
  for (const auto& s : slots_)
    if (s) n += s->run.steps();
  return n;
}

uint8_t Processes::number(double process, uint32_t source, const char* what) {
  std::string why;
  const std::optional<uint8_t> n = whole_in<uint8_t>(process, 1, static_cast<uint8_t>(slots_.size()));
  if (!n)
    why =
        fmt::format("{} names no process: the machine has processes 1 to {} (machine.processes)", what, slots_.size());
  else if (*n == current_)
    why = fmt::format("{} names the process that runs it", what);
  if (why.empty()) return *n;
  setup_.issues.issue({DiagId::ProcessError, diag_message(DiagId::ProcessError, shortest(process), why), source});
  return 0;
}

Service Processes::waits_in(const Slot& s) const {
  const uint8_t* at = setup_.module.code.data() + s.run.vm().pc();
  return static_cast<Op>(at[0]) == Op::Service ? static_cast<Service>(at[1]) : Service::Count;
}

// (A process a partner met already waits only to run again.)
bool Processes::waits_at(const Slot& s, Service service, uint8_t partner) const {
  return s.run.running() && s.run.vm().waiting() && !s.delivered && waits_in(s) == service &&
         s.run.vm().blocked_operand() == partner;
}

ServiceResult Processes::call(Service service, ServiceCall& call) {
  const uint32_t source = call.block();
  if (service == Service::ProcessRelease) {
    call.machine().sync_event("release", source);
    call.machine().end_program(source);
    return ServiceResult::Release;
  }
  if (service == Service::ProcessWaitUntil) return wait_until(call);
  const double n = call.pop();
  const std::string process = shortest(n);
  switch (service) {
    case Service::ProcessStart: {
      const uint32_t entry = call.operand(0);
      const std::string& name = call.entry_name(entry);
      return answer(call, start(n, entry, source), fmt::format("start process {} {}", process, name),
                    fmt::format("start process {} {}: waits until it is free", process, name));
    }
    case Service::ProcessWait:
      return answer(call, meet(n, source, "(WAI)", Service::ProcessSignal), "restarted by process " + process,
                    "wait for process " + process);
    case Service::ProcessSignal:
      return answer(call, meet(n, source, "(SND)", Service::ProcessWait), "restart process " + process,
                    fmt::format("restart process {}: waits until it waits for process {}", process, current_));
    default: return ServiceResult::Error;  // not the scheduler's: the VM hands it only its own
  }
}

ServiceResult Processes::answer(ServiceCall& call, ServiceResult result, const std::string& done,
                                const std::string& waits) {
  if (result == ServiceResult::Wait) {
    if (!call.waited()) call.machine().sync_event(waits, call.block());
    call.waits_for(waits);
  }
  if (result == ServiceResult::Done) call.machine().sync_event(done, call.block());
  return result;
}

// WAI on a memory: met when the memory there relates to the value as the instruction
// says; in the dry run, also when no process can go on (assume_). A condition met
// after waiting goes on once the memory was written.
ServiceResult Processes::wait_until(ServiceCall& call) {
  const double value = call.pop(), index = call.pop();
  double now = 0;
  if (!call.load_mem(static_cast<uint8_t>(call.operand(0)), static_cast<MemFormat>(call.operand(1)), index, now))
    return ServiceResult::Error;
  const uint32_t relation = call.operand(2);
  const bool holds = (relation == 1   ? now == value
                      : relation == 2 ? now < value
                      : relation == 3 ? now > value
                                      : now != value) ||
                     (call.waited() && assume_);
  if (holds && call.waited()) slot(current_).run.vm().wait_until(shared_.written_at);
  const std::string& condition = call.string(call.operand(3));
  return answer(call, holds ? ServiceResult::Done : ServiceResult::Wait, condition + " holds",
                "wait until " + condition);
}

// EXE: the program starts when its process is free (decision 63), at the time of
// the process that starts it.
ServiceResult Processes::start(double process, uint32_t entry, uint32_t source) {
  const uint8_t n = number(process, source, "(EXE)");
  if (!n) return ServiceResult::Error;
  Slot& target = slot(n);
  if (target.run.running()) return ServiceResult::Wait;
  Vm& starter = slot(current_).run.vm();
  starter.wait_until(target.free_at);
  target.run.vm().wait_until(starter.eval_time());
  target.run.start(entry);
  return ServiceResult::Done;
}

// RMNpq: at the time the reading block is evaluated, of the block process p moves then.
double Processes::remaining(int process, int axis) {
  if (process < 1 || process > static_cast<int>(slots_.size()) || !slots_[process - 1] || axis >= kAxisCount) return 0;
  return slots_[process - 1]->run.machine().remaining_at(axis, slot(current_).run.vm().eval_time());
}

// WAI n and SND n meet (a rendezvous, decision 63): whichever comes first waits for
// the other; both go on, at the later of their times. This process's WAI or SND
// `what` meets process `process` if that one waits at `partner` naming this one; else
// it waits, until that one comes and marks it met.
ServiceResult Processes::meet(double process, uint32_t source, const char* what, Service partner) {
  const uint8_t n = number(process, source, what);
  if (!n) return ServiceResult::Error;
  Slot& me = slot(current_);
  if (me.delivered) {
    me.delivered = false;
    return ServiceResult::Done;
  }
  Slot* other = slots_[n - 1].get();
  if (!other || !waits_at(*other, partner, current_)) return ServiceResult::Wait;
  other->delivered = true;
  const double t = std::max(me.run.vm().eval_time(), other->run.vm().eval_time());
  me.run.vm().wait_until(t);
  other->run.vm().wait_until(t);
  return ServiceResult::Done;
}

// Every process that runs waits, and nothing will change that: reported at the
// first, with a note at each.
void Processes::deadlock() {
  RuntimeIssue issue{DiagId::Deadlock, "", 0};
  bool condition = false, first = true;
  for (size_t i = 0; i < slots_.size(); ++i) {
    if (!slots_[i] || !slots_[i]->run.running()) continue;
    const Slot& s = *slots_[i];
    const uint32_t source = setup_.module.source_of(s.run.vm().pc());
    if (first) issue.source = source;
    first = false;
    const Service service = waits_in(s);
    condition = condition || service == Service::ProcessWaitUntil;
    // The process it waits for may run nothing, and never will.
    const double partner = s.run.vm().blocked_operand();
    const bool idle =
        (service == Service::ProcessWait || service == Service::ProcessSignal) && partner >= 1 &&
        partner <= static_cast<double>(slots_.size()) &&
        !(slots_[static_cast<size_t>(partner) - 1] && slots_[static_cast<size_t>(partner) - 1]->run.running());
    issue.notes.push_back(
        {source, fmt::format("process {} waits here: {}{}", i + 1, s.run.vm().waits(),
                             idle ? fmt::format(" (process {} runs no program)", shortest(partner)) : "")});
  }
  issue.message = diag_message(DiagId::Deadlock,
                               condition ? "every process that runs waits, and the input script has no PLC signal left "
                                           "(ncc run --input FILE: a line such as SA12=1)"
                                         : "every process that runs waits for another");
  setup_.issues.issue(issue);
}

}  // namespace ncc::vm
