#include "services.h"

namespace ncc {

std::string_view device_name(Device d) {
  static constexpr std::string_view kNames[] = {"asset", "input", "screen", "process"};
  static_assert(std::size(kNames) == kDeviceCount);
  return kNames[static_cast<size_t>(d)];
}

}  // namespace ncc
