// The cost of the public API's host interface: runs a bytecode file through
// ncc::api with a host that counts the calls it receives, to set against
// `ncc run FILE.ncb --trace none` under callgrind (bench/README.md, "The API").
//   api_host FILE.ncb [--step]    --step: a block at a time, as a controller's cycle would
#include <ncc/ncc.h>

#include <cstdio>
#include <cstring>

namespace api = ncc::api;

namespace {

class Counter final : public api::MachineInterface {
 public:
  unsigned long moves = 0, others = 0;
  api::Reply straight_traverse(const api::Block&, const api::Axes&, api::AxisMask) override {
    return ++moves, api::Reply{};
  }
  api::Reply straight_feed(const api::Block&, const api::Axes&, api::AxisMask) override {
    return ++moves, api::Reply{};
  }
  api::Reply arc_feed(const api::Block&, const api::Arc&) override { return ++moves, api::Reply{}; }
  api::Reply feed_rate(const api::Block&, double) override { return ++others, api::Reply{}; }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: api_host FILE.ncb [--step]\n");
    return 2;
  }
  const bool step = argc > 2 && std::strcmp(argv[2], "--step") == 0;
  api::Result<api::Program> program = api::Program::load(argv[1]);
  for (const api::Diagnostic& d : program.diagnostics()) std::fputs(d.text.c_str(), stderr);
  if (!program) return 1;
  Counter host;
  api::Result<api::Run> run = api::Run::start(*program, host);
  if (!run) return 1;
  api::Status status;
  if (step) {
    while ((status = run->step()) == api::Status::Ready) {}
  } else {
    status = run->run();
  }
  std::printf("%lu moves, %lu feed rates, %llu blocks\n", host.moves, host.others,
              static_cast<unsigned long long>(run->blocks_run()));
  return status == api::Status::Ended ? 0 : 1;
}
