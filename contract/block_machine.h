// The boundary between the VM and the machine that runs its blocks: the VM hands a
// machine one block at a time as canonical functions plus word values, and asks it
// what a program may read (system variables, the clock, the block-skip switch). The
// VM knows this interface alone; the runtime's Machine (runtime/machine.h) is the
// machine every run has today, and a test or a host may bring another.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "machine_config.h"
#include "support/diagnostics.h"
#include "system_vars.h"
#include "word_slots.h"

namespace ncc {

// The words of one block by slot (contract/word_slots.h); `present` marks those written.
struct BlockWords {
  std::array<double, kWordSlots> value{};
  std::bitset<kWordSlots> present;

  bool has_slot(int slot) const { return slot >= 0 && slot < kWordSlots && present[slot]; }
  void set(int slot, double v) {
    value[slot] = v;
    present.set(slot);
  }
  void clear() { present.reset(); }
};

struct BlockRequest {
  const uint16_t* codes = nullptr;  // indices into ProgramSemantics::codes, in written order
  size_t code_count = 0;
  const BlockWords* words = nullptr;
  uint32_t source = 0;         // SourceMap::blocks index
  uint64_t dynamic_codes = 0;  // bit i: codes[i] was chosen at run time; check it may share the block
};

// A problem found while running a block. `slot` is the word it concerns (-1 = the
// whole block); the driver turns it into a located diagnostic.
struct RuntimeIssue {
  DiagId id;
  std::string message;
  uint32_t source = 0;
  int slot = -1;
  int code = -1;  // or the G/M code (ProgramSemantics::codes index) it concerns
  int nth = 0;    // of the block's words of `slot`, the one meant (GE2 GE3: 1 is GE3)
  std::vector<std::pair<uint32_t, std::string>> notes = {};  // (source block, text): where else it concerns
};

class RuntimeIssues {
 public:
  virtual ~RuntimeIssues() = default;
  virtual void issue(const RuntimeIssue& issue) = 0;
};

// [[nodiscard]] on a declaration first: clang-format 14 mangles it on the definition.
enum class [[nodiscard]] BlockResult;
enum class BlockResult { Continue, ProgramEnd, EndOfInformation, Error };

// NC-110 RMNpq in a run of several processes: the path a process has still to go on
// an axis (kAxisLetters index) when the block that reads it is evaluated.
class RemainingPaths {
 public:
  virtual ~RemainingPaths() = default;
  virtual double remaining(int process, int axis) = 0;
};

// What a machine holds between blocks, for its host to show (the API's Run::state).
struct MachineState {
  AxisValues position{};  // as the trace gives it: the active work frame, the program's units
  AxisValues machine{};   // machine coordinates, mm and degrees
  bool inch = false;
  bool absolute = true;
  Plane plane;
  int feed_mode = 1;           // 0 inverse time, 1 per minute, 2 per revolution
  std::optional<double> feed;  // as programmed
  double speed = 0;
  int spindle = 0;  // 1 clockwise, -1 counter-clockwise, 0 stopped, 2 oriented
  int tool = 0;     // in the spindle
  int tool_selected = 0;
  int work_offset = 0;  // 0: none
  int cutter_comp = 0;  // 0 off, 1 left, 2 right
  double cutter_radius = 0;
  int length_offset = 0;  // 0 off, 1 plus, -1 minus
  std::string motion;     // the code that set the motion mode ("G01"), "" before one
  bool mist = false, flood = false;
  double clock = 0;  // seconds of the run so far
};

// A machine as the VM drives it. Positions, modes and time are its own; the VM keeps
// the program's variables and control flow.
class BlockMachine {
 public:
  virtual ~BlockMachine() = default;

  // Runs one block. A machine that stops on errors ends the block with Error; the dry
  // run's reports, recovers as if the block had done what it says, and continues.
  virtual BlockResult execute(const BlockRequest& block) = 0;
  // Values the last block measured, by index of the result space (NC-110 G72-G74).
  virtual std::vector<std::pair<uint32_t, double>> take_results() = 0;
  // The end of a program unit: pending multi-block constructs must be complete.
  virtual void end_of_unit(uint32_t source) = 0;
  // The run is over: what waits goes to the trace (after an error as it stands, no
  // exit move made up for it).
  virtual void end_run(bool stopped_by_error) = 0;
  // The program ends without a block that ends it (NC-110 REL): as M02 ends it.
  virtual void end_program(uint32_t source) = 0;

  // What the program shows and meets, for the trace: a comment, a block starting
  // (the trace's `block` events), an operator message (NC-110 DIS), an ASSET statement
  // (NC-110 §5.3; IOSTA takes its code, and the result is true when the run goes on:
  // it worked, or ERR=1), the operator's answer to INP with the prompt and value
  // offered, the user screen changing (NC-110 SCR, OUT), a process meeting the others
  // (NC-110 EXE, REL, WAI, SND: "restart process 2").
  virtual void comment(const std::string& text, uint32_t source) = 0;
  virtual void block_start(uint32_t source) = 0;
  virtual void message(const std::string& text, uint32_t source) = 0;
  [[nodiscard]] virtual bool asset_done(const std::string& what, int code, uint32_t source) = 0;
  virtual void operator_input(const std::string& shown, double answer, uint32_t source) = 0;
  virtual void operator_input(const std::string& shown, const std::string& answer, uint32_t source) = 0;
  virtual void screen_event(const std::string& what, uint32_t source) = 0;
  virtual void sync_event(const std::string& what, uint32_t source) = 0;

  // Seconds of the run so far; a process that waited for another until `seconds` goes
  // on from there (NC-110 chapter 4).
  virtual double clock() const = 0;
  virtual void wait_until(double seconds) = 0;
  // The block-skip switch: '/' blocks are skipped while it is on.
  virtual bool block_skip() const = 0;
  // System variables (contract/system_vars.def), read and written by the program; a
  // value a variable cannot take is reported at `source`.
  virtual double system(SysRef ref) const = 0;
  [[nodiscard]] virtual bool set_system(SysRef ref, double value, uint32_t source) = 0;
  // NC-110 FEP, FEL, FEC (§2.12): field 1..3 of GTL element `index` of kind (gtl::Kind);
  // false if it is not defined.
  [[nodiscard]] virtual bool gtl_field(int kind, double index, double field, double& out) const = 0;
  // The path `axis` has still to go at `seconds`: of the block moving then, linear in
  // time (NC-110 RMN in a run of several processes).
  virtual double remaining_at(int axis, double seconds) const = 0;

  // What the machine holds that grows with the blocks a run makes (the run's memory
  // budget), in bytes and in words; the moves blocks made beyond their first (a
  // cycle's holes and pecks), which the run's step budget counts besides its blocks.
  virtual uint64_t held_bytes() const = 0;
  virtual std::string held_what() const = 0;
  virtual uint64_t moves_beyond_first() const = 0;
  // What it holds between blocks, for a host to show.
  virtual MachineState state() const = 0;
};

}  // namespace ncc
