// The services a controller's host gives a program (services.def), and the one
// general call through which the VM reaches them: on a SERVICE instruction the VM
// calls the ServiceHost of the service's device with a ServiceCall, through which the
// service reads its operands and the program's variables, takes and gives values and
// names its block, as a Lua C function receives the interpreter's state. The VM knows
// no device; whoever runs a module brings them (the NC-110 devices of devices/, the
// scheduler of processes).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "block_machine.h"
#include "support/diagnostics.h"
#include "variables.h"

namespace ncc {

// Who answers a service: each has its ServiceHost in a run.
enum class Device : uint8_t { Asset, Input, Screen, Process, Count };
constexpr size_t kDeviceCount = static_cast<size_t>(Device::Count);

// An X-macro list, then Count: clang-format would indent Count as a continuation.
// clang-format off
enum class Service : uint8_t {
#define SERVICE(name, printed, format, pop, push, device, doc) name,
#include "services.def"
#undef SERVICE
  Count
};
// clang-format on
constexpr size_t kServiceCount = static_cast<size_t>(Service::Count);

struct ServiceInfo {
  std::string_view name;    // as the disassembler prints it: "asset.open"
  std::string_view format;  // its operands, in the operand letters of vm/opcodes.h
  uint8_t pop;
  uint8_t push;
  Device device;
  std::string_view doc;
};
// (Inline, as the verifier reads it for every operand.)
inline constexpr ServiceInfo kServiceInfo[] = {
#define SERVICE(name, printed, format, pop, push, device, doc) {printed, format, pop, push, Device::device, doc},
#include "services.def"
#undef SERVICE
};
constexpr const ServiceInfo& service_info(Service s) { return kServiceInfo[static_cast<size_t>(s)]; }
// The most values a service pushes.
inline constexpr size_t kMaxServicePush = [] {
  size_t most = 0;
  for (const ServiceInfo& s : kServiceInfo) most = std::max<size_t>(most, s.push);
  return most;
}();
std::string_view device_name(Device d);

// What a service did. Wait: it cannot be done yet (a process waits for another); the
// VM leaves the instruction to run again, its operands on the stack, and the turn ends
// (the scheduler runs it again). Release: the program ended and its process is free.
enum class ServiceResult : uint8_t { Done, Wait, Error, Release };

// What a service sees of the VM that runs it. The values it pops are the `pop` its
// catalogue line gives (the verifier has checked the stack holds them); they stay on
// the stack until it is done, so that a service that waits finds them again. Every
// access that can fail reports the run-time error at the block and says so.
class ServiceCall {
 public:
  // Operand i of the service's format, as the bytecode holds it (an index, a number).
  virtual uint32_t operand(size_t i) const = 0;
  virtual const std::string& string(uint32_t index) const = 0;  // of the module's strings
  virtual const std::string& entry_name(uint32_t index) const = 0;
  virtual double pop() = 0;
  virtual void push(double value) = 0;
  // The program's variables: numbered ones by their space's type, memories by format
  // and as bytes (nullptr: out of range, reported).
  virtual const VarSpace& space(uint8_t space) const = 0;
  virtual VarType type_of(uint8_t space, uint32_t index) const = 0;
  virtual bool load(uint8_t space, double index, double& out) = 0;
  virtual bool store(uint8_t space, double index, double value) = 0;
  virtual bool load_mem(uint8_t space, MemFormat format, double index, double& out) = 0;
  virtual bool store_mem(uint8_t space, MemFormat format, double index, double value) = 0;
  virtual uint8_t* bytes(uint8_t space, double index, uint32_t count) = 0;
  virtual void wrote_memory() = 0;  // after writing through bytes(): a WAI condition may hold from now
  // The block the service runs in (a source map index), on the machine of its process.
  virtual uint32_t block() const = 0;
  virtual BlockMachine& machine() = 0;
  // The service waited the last time it ran: this is its next try.
  virtual bool waited() const = 0;
  // Before returning Wait: what it waits for ("wait for process 2"), for a deadlock's notes.
  virtual void waits_for(std::string what) = 0;
  virtual void report(DiagId id, std::string message) = 0;
  // A run-time error at the block (the run stops): false, to return at once.
  template <typename... Args>
  bool fail(DiagIdFor<Args...> id, const Args&... args) {
    report(id.id(), diag_message(id, args...));
    return false;
  }

 protected:
  ~ServiceCall() = default;
};

class ServiceHost {
 public:
  virtual ~ServiceHost() = default;
  virtual ServiceResult call(Service service, ServiceCall& call) = 0;
};

// The host of each device in a run (by Device); none: the run has no such device, and
// the VM reports the service as one it cannot run.
using ServiceHosts = std::array<ServiceHost*, kDeviceCount>;

}  // namespace ncc
