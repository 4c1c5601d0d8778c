// The system variables (system_vars.def) and references to them.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace ncc {

enum class SysVar : uint8_t {
#define SYS(id, name, indices, writable, doc) id,
#include "system_vars.def"
#undef SYS
  Count
};

std::string_view sys_name(SysVar v);
uint32_t sys_indices(SysVar v);
std::optional<SysVar> sys_by_name(std::string_view name);

// A system variable with its index, as the bytecode's `y` operand carries it.
struct SysRef {
  SysVar var = SysVar::DwellTime;
  uint8_t index = 0;
  uint16_t packed() const { return static_cast<uint16_t>(static_cast<unsigned>(var) << 8 | index); }
  static SysRef unpack(uint16_t v) { return {static_cast<SysVar>(v >> 8), static_cast<uint8_t>(v & 0xFF)}; }
  bool valid() const { return var < SysVar::Count && index < sys_indices(var); }
};

// Whether a program may write it (the clock TIM0 and the remaining paths it may not).
bool sys_writable(SysRef ref);

// Why `value` cannot be stored in `ref` ("it is 0 or 1"), or nothing: the rule of
// each variable (NC-110 §2.10), for the run and for constants the compiler sees.
[[nodiscard]] std::optional<std::string_view> sys_value_error(SysRef ref, double value);

}  // namespace ncc
