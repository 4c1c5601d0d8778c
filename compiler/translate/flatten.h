// Flattened translation (`ncc translate --flatten`): the program runs on the VM with
// its trace in machine coordinates, and each motion call becomes a plain block of
// the target. The flattener keeps two machine states: the one the source's run
// wants (from the trace) and the one the blocks written so far have set in the
// target; before each move it writes the codes that make them agree, with every
// function those codes call (pp G94 sets the spindle mode too, GOST M05 turns the
// coolant off). Origins, shifts, rotations and the cutter path are in the
// positions already: the target's work offset is taken off again.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "contract/machine_config.h"
#include "contract/program_semantics.h"
#include "runtime/trace.h"
#include "writer.h"

namespace ncc::translate {

// A construct the target cannot say, at the source block of the event that showed
// it: refused, or dropped when it changes how the machine runs the path, not the
// path (a path mode, the overrides); or a feed, a speed or a dwell rounded (what:
// its letter).
struct Refusal {
  uint32_t source = 0;
  std::string what;
  Finding kind = Finding::Refused;
};

class Flattener final : public TraceSink {
 public:
  // `source` is the source program's semantics (its power-on work offset),
  // `target_machine` the machine the target program runs on (its work offsets).
  Flattener(Writer& writer, const ProgramSemantics& source, const MachineConfig& target_machine,
            std::function<void(const Refusal&)> report);
  void event(const Event& e) override;
  // The target's power-on functions: the path mode it starts in needs no code.
  void set_target_power_on(const std::vector<FnCall>& calls);
  // After the run: the start if no block was written, and the writer's end (a
  // target that must end with M02 adds it when the run made no end).
  void finish();

 private:
  struct Code {
    char letter = 'G';
    int number = 0;
    const CodeDesc* desc = nullptr;
  };
  // The target's code that calls `call`, and otherwise only functions `fits` allows.
  std::optional<Code> code_for(FnCall call, const std::function<bool(FnCall)>& fits = {}) const;
  [[nodiscard]] bool write_code(FnCall call, std::vector<OutWord>& words, uint32_t source, const char* what);
  void write_alone(uint32_t source, FnCall call, const char* what);
  void applied(const Code& code);  // the target state after a code
  void start();
  void sync_state(uint32_t source);
  void sync_spindle(uint32_t source);
  void feed_word(std::vector<OutWord>& words);
  void corrector(uint32_t source);
  void link(uint32_t source);
  void move(const Event& e);
  void arc_to(const Event& e, const AxisValues& end);
  void parabola(const Event& e);
  AxisValues target_point(const AxisValues& pos) const;
  double offset_mm(int axis) const;  // the target's work offset on an axis, mm
  void emit_block(std::vector<OutWord> words, std::string_view comment = {});
  void emit_codes(const std::vector<OutWord>& words);
  double mm(double v, int axis) const;  // a source value of an axis in the target's mm
  double written_length(double mm) const;
  void refuse(uint32_t source, std::string what);
  void drop(uint32_t source, std::string what);

  Writer& w_;
  const Conventions& conv_;
  const MachineConfig& target_;
  std::function<void(const Refusal&)> report_;  // a refusal or a drop
  std::string axes_;                            // the target's axis letters
  bool inch_ = false;                           // the source's unit
  std::optional<double> feed_programmed_;       // F as the source wrote it
  uint32_t source_ = 0;                         // the block of the event being written
  int loaded_ = -1;                             // the tool in the spindle
  bool comp_path_ = false;                      // the source's trace shows the tool centre's path (ISO)
  bool started_ = false;
  bool ended_ = false;
  bool after_end_ = false;

  // What the source's run wants now.
  struct State {
    int plane = 0;  // kPlanes index
    int feed_mode = 1;
    double feed = -1;  // mm/min, mm/rev or 1/min
    bool constant_surface = false;
    double speed = -1;
    int spindle = 0;  // 1 cw, -1 ccw, 0 stop
    bool mist = false, flood = false, coolant3 = false, coolant4 = false;
    int work_offset = 0;
    int tool = -1;         // selected
    int length_entry = 0;  // tool length offset entry (0: none)
    bool length_minus = false;
    AxisValues length_axes{};    // the offset on each axis, as the source's run applies it
    std::optional<Fn> dynamics;  // how blocks join (NC-110 G27-G29, pp G23/G24), once the source says
  };
  State want_;
  // What the target has been told ('unknown' until the first block says it).
  struct Told {
    std::optional<int> plane, feed_mode, spindle, length_entry, motion;
    std::optional<double> feed, speed;
    std::optional<bool> constant_surface, mist, flood, coolant3, coolant4, helix, clamp, rotary_clamp;
    std::optional<int> tool;
    std::optional<Fn> dynamics;
    std::optional<AxisValues> position;  // as written
  };
  Told told_;
  std::optional<Fn> dropped_dynamics_;  // a path mode the target has no code for, said once
  std::vector<OutWord> block_codes_;    // codes of one block only, for the next move
  AxisValues start_{};                  // where the target machine starts, in its frame at the first move
  int target_offset_ = -1;              // the work offset the target has selected (-1: none yet)
};

}  // namespace ncc::translate
