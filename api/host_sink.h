// The runtime's events as the calls of the host's MachineInterface: the one place
// the public API meets the trace.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ncc/machine_interface.h"
#include "runtime/trace.h"

namespace ncc::api {

// The runtime's numbers for a feed mode (0 inverse time, 1 per minute, 2 per
// revolution) and a cutter side (0 off, 1 left, 2 right), as the API names them.
FeedMode feed_mode_of(int n);
CutterSide cutter_side_of(int n);

class HostSink final : public TraceSink {
 public:
  HostSink(MachineInterface& host, const SourceMap& map, std::string axes)
      : host_(host), map_(map), axes_(std::move(axes)) {}

  void event(const Event& e) override;
  bool wants_events() const override { return !refusal_; }

  // The first call the host refused: the block, the call, and why. Nothing after it
  // reaches the host.
  struct Refusal {
    uint32_t source;
    std::string call;
    std::string reason;
  };
  const std::optional<Refusal>& refusal() const { return refusal_; }

  // While muted (a restart runs up to its block) the host is called for nothing; the
  // modes the events set are kept, and unmute() tells the host those in force.
  void mute();
  void unmute();
  void reset();

 private:
  Reply call(const Event& e, const Block& b);
  const Block& block(const Event& e);

  MachineInterface& host_;
  const SourceMap& map_;
  std::string axes_;
  std::optional<Refusal> refusal_;
  Block block_;
  std::optional<std::pair<uint32_t, uint8_t>> block_of_;  // the source and process block_ is for
  bool muted_ = false;
  // Muted: the last event of each mode, by when it came (coolants: those since the last off).
  uint64_t seq_ = 0;
  std::map<int, std::pair<uint64_t, Event>> modes_;
  std::vector<std::pair<uint64_t, Event>> coolants_;
};

}  // namespace ncc::api
