// System variables: the runtime state a program reads and writes by name.
#include <cmath>
#include <cstdlib>
#include <limits>

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
    case SysVar::ClockMs: return std::round(kernel_.clock() * 1000 - clock_base_ * 1000);
    case SysVar::ClockHours: return (kernel_.clock() - clock_base_) / 3600;
    case SysVar::ModalCode: {
      // The number of the program's code that sets the group's state now.
      const FnCall now = current(static_cast<FnGroup>(ref.index));
      // Vacant (NaN) when no code of the program sets it.
      for (const CodeDesc& c : sem_.codes)
        if (!c.calls.empty() && c.calls.front() == now && c.name.size() > 1)
          return parse_number<double>(std::string_view(c.name).substr(1))
              .value_or(std::numeric_limits<double>::quiet_NaN());
      return std::numeric_limits<double>::quiet_NaN();
    }
    case SysVar::ModalWord:
      switch ('A' + ref.index) {
        case 'D': return offset_number_;
        case 'H': return length_number_;
        case 'F': return feed_ ? *feed_ : std::numeric_limits<double>::quiet_NaN();
        case 'S': return speed_;
        case 'T': return tool_selected_;
        default: return std::numeric_limits<double>::quiet_NaN();
      }
    case SysVar::Position: {
      const int axis = ref.index % 16, kind = ref.index / 16;
      if (axis >= kAxisCount) return 0;
      if (kind == 3) return skip_position_ ? (*skip_position_)[axis] : std::numeric_limits<double>::quiet_NaN();
      const AxisValues p = kind == 1 ? kernel_.position() : motion_event(EventKind::Linear, kernel_.position()).pos;
      return kind == 1 ? program_axis(axis, p[axis]) : p[axis];
    }
    case SysVar::WorkOffsetValue: {
      const int axis = ref.index % 16, n = ref.index / 16;
      return axis < kAxisCount ? program_axis(axis, kernel_.offset_value(n, axis)) : 0;
    }
    case SysVar::OptionalStop: return optional_stop_ ? 1 : 0;
    case SysVar::FeedOverride: return modal_.override_enabled ? 1 : 0;
    case SysVar::Timer:
      if (ref.index == 0) return static_cast<float>(kernel_.clock());
      break;
    // RMNpq: process p, axis q (1: X); a run of one process moves nothing while a
    // block is evaluated.
    case SysVar::RemainingPath:
      return remaining_paths_ && ref.index % 10 >= 1 ? remaining_paths_->remaining(ref.index / 10, ref.index % 10 - 1)
                                                     : 0;
    default: break;
  }
  auto it = system_.find(ref.packed());
  if (it != system_.end()) return it->second;
  return ref.var == SysVar::TapReturn ? 100 : 0;
}

bool Machine::set_system(SysRef ref, double value, uint32_t source) {
  auto fail = [&](const std::string& why) {
    issues_.issue({DiagId::SystemValue, diag_message(DiagId::SystemValue, system_name(ref), shortest(value), why),
                   source, -1, -1});
    return !stop_on_error_;  // a dry run goes on without the value
  };
  if (std::isnan(value)) return fail("the value is vacant");
  if (auto why = sys_value_error(ref, value)) return fail(std::string(*why));
  switch (ref.var) {
    case SysVar::Timer:
    case SysVar::TotalTime: value = static_cast<float>(value); break;  // RE
    case SysVar::BlockEnable: block_skip_ = value == 0; return true;
    case SysVar::OptionalStop: optional_stop_ = value == 1; return true;
    case SysVar::Alarm:
      issues_.issue({DiagId::Alarm, diag_message(DiagId::Alarm, shortest(value)), source, -1, -1});
      return false;
    case SysVar::ClockMs:
    case SysVar::ClockHours:
      clock_base_ = kernel_.clock() - (ref.var == SysVar::ClockMs ? value / 1000 : value * 3600);
      return true;
    case SysVar::WorkOffsetValue: {
      // #5221...: the offset of G54-G59 on one axis, in the program's unit.
      const int axis = ref.index % 16, n = ref.index / 16;
      if (axis >= kAxisCount || n < 1 || n > 6) return fail("it names no work offset");
      WorkOffset& w = kernel_.offsets()[n];
      w.values[axis] = w.inch && is_linear(axis) ? axis_units(axis, value) / 25.4 : axis_units(axis, value);
      w.axes |= 1u << axis;
      kernel_.refresh_origins();
      if (n == modal_.work_offset) {
        // The active one: positions are measured from the new zero.
        Event e{EventKind::WorkOffset};
        e.n = n;
        for (int i = 0; i < kAxisCount; ++i) e.pos[i] = program_axis(i, kernel_.offset_value(n, i));
        e.source = source;
        kernel_.out(e);
      }
      return true;
    }
    case SysVar::FeedOverride: {
      modal_.override_enabled = value == 1;
      Event e{EventKind::Override};
      e.n = modal_.override_enabled;
      e.source = source;
      kernel_.out(e);
      return true;
    }
    default: break;
  }
  system_[ref.packed()] = value;
  return true;
}

}  // namespace ncc
