#include "services.h"

namespace ncc {

namespace {
constexpr std::array<ServiceInfo, kServiceCount> kServiceInfo = {{
#define SERVICE(name, printed, format, pop, push, device, doc) {printed, format, pop, push, Device::device, doc},
#include "services.def"
#undef SERVICE
}};
}  // namespace

const ServiceInfo& service_info(Service s) { return kServiceInfo[static_cast<size_t>(s)]; }

std::string_view device_name(Device d) {
  static constexpr std::string_view kNames[] = {"asset", "input", "screen", "process"};
  static_assert(std::size(kNames) == kDeviceCount);
  return kNames[static_cast<size_t>(d)];
}

}  // namespace ncc
