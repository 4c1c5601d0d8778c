// System variables: the runtime state a program reads and writes by name.
#include <cmath>

#include "machine.h"
#include "support/text.h"

namespace ncc {

std::string Machine::system_name(SysRef ref) const {
  auto i = static_cast<size_t>(ref.var);
  std::string name = i < sem_.system_names.size() && !sem_.system_names[i].empty() ? sem_.system_names[i]
                                                                                 : std::string(sys_name(ref.var));
  if (sys_indices(ref.var) > 1) name += std::to_string(ref.index);
  return name;
}

double Machine::system(SysRef ref) const {
  switch (ref.var) {
    case SysVar::BlockEnable: return block_skip_ ? 0 : 1;
    case SysVar::InchMode: return modal_.inch ? 1 : 0;
    case SysVar::OptionalStop: return optional_stop_ ? 1 : 0;
    case SysVar::FeedOverride: return modal_.override_enabled ? 1 : 0;
    case SysVar::Timer:
      if (ref.index == 0) return static_cast<float>(clock_);
      break;
    case SysVar::RemainingPath: return 0;  // one process: nothing moves while a block is evaluated
    default: break;
  }
  auto it = system_.find(ref.packed());
  if (it != system_.end()) return it->second;
  return ref.var == SysVar::TapReturn ? 100 : 0;
}

bool Machine::set_system(SysRef ref, double value, uint32_t source) {
  auto fail = [&](const std::string& why) {
    issues_.issue({DiagId::SystemValue, diag_message(DiagId::SystemValue, system_name(ref), shortest(value), why), source,
                   -1, -1});
    return !stop_on_error_;  // a dry run goes on without the value
  };
  if (auto why = sys_value_error(ref, value)) return fail(std::string(*why));
  switch (ref.var) {
    case SysVar::Timer:
    case SysVar::TotalTime: value = static_cast<float>(value); break;  // RE
    case SysVar::BlockEnable:
      block_skip_ = value == 0;
      return true;
    case SysVar::OptionalStop:
      optional_stop_ = value == 1;
      return true;
    case SysVar::FeedOverride: {
      modal_.override_enabled = value == 1;
      Event e{EventKind::Override};
      e.n = modal_.override_enabled;
      e.source = source;
      trace_.event(e);
      return true;
    }
    default: break;
  }
  system_[ref.packed()] = value;
  return true;
}

}  // namespace ncc
