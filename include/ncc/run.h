// A run of a program on a machine the host implements (machine_interface.h): a block
// at a time, or to the end; paused, stopped, reset, restarted at a block. A run is
// deterministic: the same program, profile and options make the same calls.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "diagnostic.h"
#include "export.h"
#include "machine_interface.h"
#include "program.h"

namespace ncc::api {

struct RunOptions {
  std::string profile;                // a machine profile file; "": the one the program was compiled with
  bool block_skip = false;            // blocks starting with '/' are skipped
  bool optional_stop = false;         // M01 stops
  std::optional<uint64_t> max_steps;  // blocks before the run stops with NC4021; default: the program's and 10^8 more
  std::string files;                  // NC-110 ASSET files: the sandbox folder (ncc files init); "": none
  std::string input;                  // NC-110 INP: a file of the operator's answers; "": none
};

enum class Status {
  Ready,    // between blocks: step() or run() goes on
  Paused,   // run() returned at pause(): the same as Ready
  Ended,    // the program ended (M02, M30, its last block)
  Stopped,  // stop() ended it
  Error,    // an error stopped it (diagnostics()); the host refused a call, or the program failed
};

// What the machine holds between blocks.
struct State {
  Axes position{};          // the active work frame, the program's units (as the calls give positions)
  Axes machine_position{};  // machine coordinates, mm and degrees
  Units units = Units::Millimetres;
  bool absolute = true;
  Plane plane;
  FeedMode feed_mode = FeedMode::PerMinute;
  std::optional<double> feed;  // as programmed
  double spindle_speed = 0;
  std::optional<Direction> spindle;  // none: stopped (or oriented)
  int tool = 0;                      // in the spindle
  int tool_selected = 0;
  int work_offset = 0;  // 0: none
  CutterSide cutter_side = CutterSide::Off;
  double cutter_radius = 0;
  int tool_length_offset = 0;  // 0 off, 1 plus, -1 minus
  std::string motion;          // the code of the motion mode ("G01"); "" before one
  bool mist = false, flood = false;
  double seconds = 0;  // the run's time so far, by the runtime's model
};

class NCC_API Run {
 public:
  // A run of `program` (which must outlive it) calling `machine`, powered on and
  // ready at its first block; none if it cannot start (the profile, the files).
  static Result<Run> start(const Program& program, MachineInterface& machine, const RunOptions& options = {});
  Run(Run&&) noexcept;
  Run& operator=(Run&&) noexcept;
  ~Run();

  [[nodiscard]] Status step();  // one block
  [[nodiscard]] Status run();   // to the end, an error or pause()
  // run() returns Paused after the block it is in; callable from another thread.
  void pause();
  Status stop();  // ends the run now; the host is told nothing more
  // Back to power-on, ready at the first block (the host is told nothing).
  void reset();
  // Runs up to `block` without calling the host, then tells the host the modes in
  // force there (units, plane, feed, spindle, tool, offsets, coolant), and is ready
  // at it. Error if the run never reaches it (an error, or the end, before it).
  [[nodiscard]] Status restart_at(uint32_t block);

  Status status() const;
  std::optional<Block> next_block() const;  // the block step() runs next; none once over
  State state() const;
  std::string axes() const;                            // the machine's axis letters ("XYZ", "XYZA")
  uint64_t blocks_run() const;                         // blocks (and a cycle's moves beyond the first) since power-on
  const std::vector<Diagnostic>& diagnostics() const;  // every problem the run met, once

 private:
  struct Impl;
  explicit Run(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace ncc::api
