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

std::optional<double> Machine::system(SysRef ref, uint32_t) {
  switch (ref.var) {
    case SysVar::BlockEnable: return block_skip_ ? 0 : 1;
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
  auto flag = [&] { return value == 0 || value == 1; };
  switch (ref.var) {
    case SysVar::RemainingPath: return fail("it is read-only");
    case SysVar::Timer:
      if (ref.index == 0) return fail("it is the clock, read-only");
      value = static_cast<float>(value);
      break;
    case SysVar::TotalTime: value = static_cast<float>(value); break;
    case SysVar::BlockEnable:
      if (!flag()) return fail("it is 0 or 1");
      block_skip_ = value == 0;
      return true;
    case SysVar::OptionalStop:
      if (!flag()) return fail("it is 0 or 1");
      optional_stop_ = value == 1;
      return true;
    case SysVar::FeedOverride: {
      if (!flag()) return fail("it is 0 or 1");
      modal_.override_enabled = value == 1;
      Event e{EventKind::Override};
      e.n = modal_.override_enabled;
      e.source = source;
      trace_.event(e);
      return true;
    }
    case SysVar::RapidRun:
    case SysVar::AxesDisconnected:
    case SysVar::PositionErrors:
      if (!flag()) return fail("it is 0 or 1");
      break;
    case SysVar::AxisDisplay:
      // 3: the remaining path (§2.10.10, "after the command UCV=3").
      if (value != 0 && value != 1 && value != 2 && value != 3) return fail("it is 0, 1, 2 or 3");
      break;
    case SysVar::TapReturn:
      if (!(value >= 0 && value <= 255) || value != std::trunc(value)) return fail("it is a whole percentage 0..255");
      break;
    case SysVar::CornerDeviation:
      if (!(value >= 0 && value <= 2)) return fail("it lies between 0 and 2");
      break;
    case SysVar::DwellTime:
    case SysVar::FormTolerance:
      if (!(value >= 0)) return fail("it must not be negative");
      break;
    default: break;
  }
  system_[ref.packed()] = value;
  return true;
}

}  // namespace ncc
