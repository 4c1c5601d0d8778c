// The runtime's events as the typed calls of a MachineInterface (the public
// include/ncc/machine_interface.h): the one place the trace meets that interface. A
// host's planner and the trace writers receive the same calls.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ncc/machine_interface.h"
#include "runtime/trace.h"

namespace ncc {

// The runtime's numbers for a feed mode (0 inverse time, 1 per minute, 2 per
// revolution) and a cutter side (0 off, 1 left, 2 right), as the API names them.
api::FeedMode feed_mode_of(int n);
api::CutterSide cutter_side_of(int n);

// The block of `map` at `source` as a call names it, made by `process`.
api::Block block_of(const SourceMap& map, uint32_t source, uint8_t process = 0);

class MachineInterfaceSink final : public TraceSink {
 public:
  // `places` false: the calls name their block by index and process alone, for a
  // machine that prints no places (the canon trace), which then pays no decoding.
  MachineInterfaceSink(api::MachineInterface& machine, const SourceMap& map, bool places = true)
      : machine_(machine), map_(map), places_(places) {}

  void event(const Event& e) override;
  bool wants_events() const override { return !refusal_; }

  // The first call the machine refused: the block, the call, and why. Nothing after
  // it reaches the machine.
  struct Refusal {
    uint32_t source;
    std::string call;
    std::string reason;
  };
  const std::optional<Refusal>& refusal() const { return refusal_; }
  void forget_refusal() { refusal_.reset(); }

 private:
  api::Reply call(const Event& e, const api::Block& b);
  const api::Block& block(const Event& e);

  api::MachineInterface& machine_;
  const SourceMap& map_;
  bool places_;
  std::optional<Refusal> refusal_;
  api::Block block_;
  std::optional<std::pair<uint32_t, uint8_t>> block_of_;  // the source and process block_ is for
};

}  // namespace ncc
