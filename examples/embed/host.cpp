// A host of ncc's VM: it compiles a program, runs it a block at a time, and hands each
// move to its planner. Here the planner is a fake one that prints what it receives,
// refuses to go below a floor (`embed part.nc -5`), and keeps the feed it was given.
#include <ncc/ncc.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace api = ncc::api;

namespace {

class Planner final : public api::MachineInterface {
 public:
  explicit Planner(double floor) : floor_(floor) {}

  api::Reply straight_traverse(const api::Block& b, const api::Axes& end, api::AxisMask moved) override {
    return move(b, "rapid", end, moved);
  }
  api::Reply straight_feed(const api::Block& b, const api::Axes& end, api::AxisMask moved) override {
    return move(b, "feed ", end, moved);
  }
  api::Reply arc_feed(const api::Block& b, const api::Arc& arc) override {
    std::printf("  line %u: arc   to X%.3f Y%.3f Z%.3f about X%.3f Y%.3f, %s, at F%g\n", b.line, arc.end[0], arc.end[1],
                arc.end[2], arc.centre_first, arc.centre_second, arc.rotation < 0 ? "clockwise" : "counter-clockwise",
                feed_);
    return {};
  }
  api::Reply feed_rate(const api::Block&, double rate) override {
    feed_ = rate;
    return {};
  }
  api::Reply tool_change(const api::Block& b, int tool) override {
    std::printf("  line %u: tool %d in the spindle\n", b.line, tool);
    return {};
  }
  api::Reply spindle_start(const api::Block& b, api::Direction d) override {
    std::printf("  line %u: spindle on, %s\n", b.line,
                d == api::Direction::Clockwise ? "clockwise" : "counter-clockwise");
    return {};
  }

 private:
  api::Reply move(const api::Block& b, const char* what, const api::Axes& end, api::AxisMask moved) {
    if (end[2] < floor_) {
      char why[64];
      std::snprintf(why, sizeof why, "Z%.3f is below the floor Z%.3f", end[2], floor_);
      return api::Reply::refuse(why);
    }
    std::printf("  line %u: %s to X%.3f Y%.3f Z%.3f", b.line, what, end[0], end[1], end[2]);
    // A rotary axis that moved, even one a full turn brought back where it began.
    for (size_t i = 3; i < 6; ++i)
      if (moved >> i & 1) std::printf(" %c%.3f", api::kAxisLetters[i], end[i]);
    std::printf(what[0] == 'f' ? " at F%g\n" : "\n", feed_);
    return {};
  }

  double floor_;
  double feed_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: embed PROGRAM.nc [FLOOR]\n");
    return 2;
  }
  api::CompileOptions options;
  options.dialect = "iso";
  api::Result<api::Program> program = api::Program::compile_file(argv[1], options);
  for (const api::Diagnostic& d : program.diagnostics()) std::fputs(d.text.c_str(), stderr);
  if (!program) return 1;

  Planner planner(argc > 2 ? std::atof(argv[2]) : -1e9);
  api::Result<api::Run> run = api::Run::start(*program, planner);
  if (!run) return 1;
  // A block at a time, as a controller's cycle would: the next block, then its calls.
  while (std::optional<api::Block> next = run->next_block()) {
    std::printf("block at line %u%s\n", next->line, next->number ? (" N" + std::to_string(*next->number)).c_str() : "");
    if (run->step() != api::Status::Ready) break;
  }
  for (const api::Diagnostic& d : run->diagnostics()) std::fputs(d.text.c_str(), stderr);
  if (run->status() != api::Status::Ended) return 1;
  const api::State state = run->state();
  std::printf("ended at X%.3f Y%.3f Z%.3f after %.2f s\n", state.position[0], state.position[1], state.position[2],
              state.seconds);
  return 0;
}
