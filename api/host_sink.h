// A host's MachineInterface behind the runtime's adapter, with the API's own policy
// for a restart.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "runtime/machine_interface_sink.h"

namespace ncc::api {

class HostSink final : public TraceSink {
 public:
  HostSink(MachineInterface& host, const SourceMap& map) : calls_(host, map) {}

  void event(const Event& e) override;
  bool wants_events() const override { return calls_.wants_events(); }

  // The first call the host refused. Nothing after it reaches the host.
  const std::optional<MachineInterfaceSink::Refusal>& refusal() const { return calls_.refusal(); }

  // While muted (a restart runs up to its block) the host is called for nothing; the
  // modes the events set are kept, and unmute() tells the host those in force.
  void mute();
  void unmute();
  void reset();

 private:
  MachineInterfaceSink calls_;
  bool muted_ = false;
  // Muted: the last event of each mode, by when it came (coolants: those since the last off).
  uint64_t seq_ = 0;
  std::map<int, std::pair<uint64_t, Event>> modes_;
  std::vector<std::pair<uint64_t, Event>> coolants_;
};

}  // namespace ncc::api
