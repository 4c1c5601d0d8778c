// The motion runtime's block interpreter: modal state and the block cycle (GOST 20999
// S-12; the same shape serves every dialect), on a motion kernel that knows no words,
// modes or dialect (motion_kernel.h: the position and clock, the frame and work
// offsets, the envelope, and the output every event leaves through). The VM hands it
// one block at a time as canonical functions plus word values; it computes the
// motion, checks it and emits trace events through the kernel. Its parts: machine.cpp
// (the block cycle and modal functions), machine_frame.cpp (the functions that set
// origins and transforms, the limits' and zones' messages), machine_motion.cpp (moves,
// arcs, threads, splines, dwells, time, ISO's corner rules), machine_cycles.cpp (what
// the canned cycles share, the measuring cycles), machine_system.cpp (system
// variables). What a dialect does its own way is a strategy chosen once from the
// program's conventions, not a flag asked where it matters: its canned cycles
// (cycle_engine.h), its tool change (tool_change.h), what it forbids a block
// (block_rules.h: ISO's E-08..E-27) and the traced cutter path (cutter_path.h: ISO's,
// NC-110's, or none; the kernel's output goes through it).
#pragma once

#include <algorithm>
#include <array>
#include <bitset>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contract/block_machine.h"
#include "contract/machine_config.h"
#include "contract/program_semantics.h"
#include "contract/system_vars.h"
#include "cutter_path.h"
#include "motion_kernel.h"
#include "support/diagnostics.h"
#include "support/numbers.h"
#include "trace.h"

namespace ncc {

namespace cycle {
struct Step;
}

// The motion runtime as a BlockMachine: what each call does is said there; what it
// holds, and how a block runs, is said here.
class Machine final : public BlockMachine {
 public:
  Machine(const ProgramSemantics& semantics, const MachineConfig& config, TraceSink& trace, RuntimeIssues& issues);
  ~Machine() override;  // in machine.cpp, where its strategies are whole

  // Power-on: position, modal state and registers as the dialect defines them.
  void power_on();
  // With stop_on_error (a real run) an error ends the block; without (the dry run of
  // `ncc check`) the machine reports and recovers.
  void set_stop_on_error(bool on) { stop_on_error_ = on; }
  // A run of several processes: RMN reads the paths they have to go, and this machine
  // keeps its recent moves in time to answer for itself.
  void set_remaining_paths(RemainingPaths* paths) { remaining_paths_ = paths; }

  BlockResult execute(const BlockRequest& block) override;
  std::vector<std::pair<uint32_t, double>> take_results() override { return std::exchange(results_, {}); }
  void end_of_unit(uint32_t source) override;
  void end_run(bool stopped_by_error) override;
  void end_program(uint32_t source) override;

  void comment(const std::string& text, uint32_t source) override;
  void block_start(uint32_t source) override;  // pp P-10.2
  void message(const std::string& text, uint32_t source) override;
  [[nodiscard]] bool asset_done(const std::string& what, int code, uint32_t source) override;  // IOSTA: §5.4
  void operator_input(const std::string& shown, double answer, uint32_t source) override;
  void operator_input(const std::string& shown, const std::string& answer, uint32_t source) override;
  void screen_event(const std::string& what, uint32_t source) override;
  void sync_event(const std::string& what, uint32_t source) override;

  double clock() const override { return kernel_.clock(); }
  void wait_until(double seconds) override { kernel_.wait_until(seconds); }
  bool block_skip() const override { return block_skip_; }
  double system(SysRef ref) const override;
  [[nodiscard]] bool set_system(SysRef ref, double value, uint32_t source) override;
  [[nodiscard]] bool gtl_field(int kind, double index, double field, double& out) const override;
  double remaining_at(int axis, double seconds) const override { return kernel_.remaining_at(axis, seconds); }

  // Held: the events cutter radius compensation and a corner hold back for a later
  // move, the points of a spline (limits.run_memory_mib).
  uint64_t held_bytes() const override;
  std::string held_what() const override;
  uint64_t moves_beyond_first() const override { return moves_beyond_first_; }
  MachineState state() const override;

 private:
  struct Modal {
    Fn motion = Fn::MotionLinear;
    Plane plane;
    bool absolute = true;
    bool inch = false;
    int feed_mode = 1;  // 0 inverse time, 1 per minute, 2 per revolution
    bool constant_surface = false;
    int comp = 0;    // 0 off, 1 left, 2 right
    int length = 0;  // 0 off, 1 plus, -1 minus
    int work_offset = 0;
    int cycle = -1;   // index into cycles; -1 = none
    int spindle = 0;  // 1 cw, -1 ccw, 0 stopped, 2 oriented
    bool mist = false, flood = false;
    int clamp = -1;  // -1 unknown
    int rotary_clamp = -1;
    bool override_enabled = true;
    bool spindle_hold = false;
    int dynamics =
        -1;  // -1 none, 0 corner slow-down (G27), 1 continuous (G28), 2 point to point (G29), 3 smooth (pp G23)
    bool gtl = false;
    int spindle_range = 0;  // 0 none forced, -1 automatic, 1..n forced
    // pp.
    bool diameter = false;  // the diameter axis programmed as a diameter (G74)
    bool helix = true;      // an arc may move its normal axis (pp: only under G09)
    bool coolant3 = false, coolant4 = false;
    bool feed_reduced = false;      // M37: the feed is F / 100
    std::array<uint8_t, 4> link{};  // '&': per axis of link_axes, 0 none, 1 plus, 2 minus the tool length
    // ISO.
    bool cycle_return_level = false;  // G99: canned cycles return to R, not the initial level
    bool polar = false, scaling = false, rotation = false;
  };

  // The compensation in effect: side, radius, signed length.
  struct Compensation {
    int side = 0;
    double radius = 0;
    AxisValues length{};  // per axis
  };

  // The spline between BSP and ESP (NC-110 G06): its plane, end conditions and points.
  struct Spline {
    bool active = false;
    int u = 0, v = 1, ends = 0;
    bool lead_in = false;            // the lead-in move has been made
    AxisValues lead_in_from{};       // where the lead-in started (its direction is the entry tangent)
    std::vector<AxisValues> points;  // machine coordinates: Q0 (the lead-in's end), then the G06 points
    std::vector<uint32_t> sources;   // the block of each point
  };

  // One block being executed.
  struct BlockState {
    const BlockRequest* request = nullptr;
    std::bitset<kWordSlots> used;  // words the block's functions read
    bool error = false;
    bool dwell = false, dwell_code = false, set_position = false, end = false, end_information = false;
    bool dwell_end = false, machine_frame = false, spindle_sync = false, decelerate = false;
    Fn measure = Fn::Count;     // a measuring cycle of this block
    Compensation compensation;  // in effect when the block started (or last reported)
    int stop = 0;               // 1 program stop, 2 optional stop taken, 3 skipped
    int code = -1;              // the code being applied, for messages about it
    std::string code_name;
    int block_offset = -1;        // a block-only preset offset (G53): the frame of this block's targets
    std::vector<FnCall> restore;  // modal functions to restore after a block-only code
    bool moved = false;           // the block made a feed move
    bool rapid_moved = false;     // ... a rapid move
    uint32_t moves = 0;           // the moves it made
    bool operands = false;        // a three-letter function took the block's words
    bool reference = false;       // pp G30: the named axes go to the reference point
    bool offset_load = false;     // pp G92: the axis words load a work offset
    bool comp_load = false;       // pp G93: D names the compensation entry to load
    int load_entry = -1;          // ... the one the block names (-1: the active one)
    int reference_trip =
        0;  // 1 to the reference point by the intermediate one (ISO G28), 2 back (G29), n + 1 to the n-th (G30 P2..P4)
    bool local_offset = false;                     // ISO G52: the axis words shift the work zero
    bool data_set = false;                         // ISO G10: the words load a work or tool offset
    bool set_position_after = false;               // ISO G92 after a motion: its values are the second words
    bool scaling_on = false, rotation_on = false;  // ISO G51, G68: the block's words define them
    bool cycle_set = false;                        // a cycle code stands in the block
    int comp_before = 0;                           // the cutter compensation when the block started
    AxisValues length_before{};                    // ... and the tool length offset
    double radius_before = 0;                      // ... and the cutter radius
    int gtl_define = -1;                           // NC-110: a GTL definition of this shape (gtl::Shape::pack)
  };

  // Words.
  bool has(char letter) const { return has_slot(letter_slot(letter)); }
  bool has_slot(int slot) const { return block_.request->words->has_slot(slot); }
  double word(char letter) { return slot_value(letter_slot(letter)); }
  double slot_value(int slot) {
    block_.used.set(slot);
    return block_.request->words->value[slot];
  }
  std::optional<double> word_if(char letter) {
    if (!letter || !has(letter)) return std::nullopt;
    return word(letter);
  }
  std::optional<double> slot_if(int slot) {
    if (!has_slot(slot)) return std::nullopt;
    return slot_value(slot);
  }
  double length_units(double v) const { return modal_.inch ? v * 25.4 : v; }
  double to_program(double mm) const { return modal_.inch ? mm / 25.4 : mm; }
  double angle_degrees(double v) const;
  [[nodiscard]] std::optional<int> whole_number(char letter, const char* what);  // T, D, H
  bool is_linear(int axis) const { return config_.axes[static_cast<size_t>(axis)].kind == AxisKind::Linear; }
  // A written axis value in machine units (mm, degrees), and back.
  double axis_units(int axis, double v) const;
  double program_axis(int axis, double v) const { return kernel_.in_units(axis, v, modal_.inch); }
  AxisValues in_program_units(AxisValues v) const { return kernel_.in_units(v, modal_.inch); }

  // Issues, and events, belong to the block being run, or to the one a deferred move
  // belongs to (a GTL element's).
  uint32_t source() const { return event_source_ ? *event_source_ : block_.request ? block_.request->source : 0; }
  template <typename... Args>
  void report(DiagIdFor<Args...> id, char word, const Args&... args) {
    issue({id.id(), diag_message(id, args...), source(), word ? letter_slot(word) : -1, -1});
  }
  template <typename... Args>
  void report_slot(DiagIdFor<Args...> id, int slot, const Args&... args) {
    issue({id.id(), diag_message(id, args...), source(), slot, -1});
  }
  // A problem with the code being applied (located at its word).
  template <typename... Args>
  void report_code(DiagIdFor<Args...> id, const Args&... args) {
    issue({id.id(), diag_message(id, args...), source(), -1, block_.code});
  }
  void issue(const RuntimeIssue& i) {
    issues_.issue(i);
    if (diag_info(i.id).severity == Severity::Error) block_.error = true;
  }
  // A problem every block has until something changes (no F: NC4001, no R: NC4018) is
  // said once, at its first block, with how many more blocks had it: held until the
  // change (release) or the end of the run.
  template <typename... Args>
  void report_repeated(DiagIdFor<Args...> id, const Args&... args) {
    if (stop_on_error_) return report(id, 0, args...);  // a run stops at the first: nothing to count
    if (auto it = repeated_.find(id.id()); it != repeated_.end())
      ++it->second.more;
    else
      repeated_.emplace(id.id(), Repeated{{id.id(), diag_message(id, args...), source(), -1, -1}});
    block_.error = true;
  }
  void release(DiagId id);
  void release_repeated();  // all of them

  // The block cycle (machine.cpp).
  void reset_state();
  FnCall current(FnGroup group) const;  // the function a modal group holds now
  void apply(FnCall call, Scope scope, bool emit);
  void apply_codes(Timing timing);  // the block's codes with this timing, in written order
  void check_dynamic_codes();
  void registers();
  void check_profile_rules();
  void action();
  void finish();
  void emit(Event e);  // an event of the block, unless it has failed
  void plane_event();
  void path_event(int mode);
  void tool_length_event();
  void link();  // pp '&'
  void cutter_comp_event();
  Compensation compensation() const;
  void flush_compensation();
  // What M02/M30 reset; the trace shows what changed.
  struct ResetState {
    Modal modal;
    Frame frame;
    AxisValues position_offset;
    Envelope envelope;
    AxisValues tolerance;
    bool turning;
  };
  void emit_reset(const ResetState& before);

  // Coordinates (machine_frame.cpp, with the kernel's).
  // The origin this block's positions are from: G79 and G53 blocks are not
  // transformed (NC-110 §2.13.1.5: "not rotated").
  int block_origin() const { return block_.machine_frame ? MotionKernel::kMachineZero : block_.block_offset; }
  AxisValues target_frame() const { return kernel_.block_origins(block_origin()); }
  AxisValues to_machine(const AxisValues& program) const {  // apply the frame
    return kernel_.to_machine(program, modal_.plane, block_origin());
  }
  AxisValues to_frame(const AxisValues& machine) const {  // undo it: program coordinates
    return kernel_.to_frame(machine, modal_.plane, block_origin());
  }
  AxisValues target();          // of this block's axis words, machine units
  AxisValues program_target();  // the same, program coordinates
  double tool_radius() const;   // of the offset in force, mm
  bool has_axis_word() const;
  bool frame_function(FnCall call);    // the NC-110 three-letter functions
  bool tooling_function(FnCall call);  // ... of the tool table and the probe (machine_tooling.cpp)
  // Operand i, reported unless whole in lo..hi.
  [[nodiscard]] std::optional<int> whole_operand(int i, int lo, int hi, const char* what);
  // The corrector or offset entry n in force: for the length, the radius or both (a
  // dialect with a length word: ISO H gives the length, D the radius).
  enum class OffsetUse : uint8_t { Both, Length, Radius };
  void select_offset(int n, OffsetUse use = OffsetUse::Both);
  int usable_tool(int tool);  // tool, or the sister that replaces it once unusable
  // NC-110 UAV (machine_virtual.cpp).
  bool virtual_function(FnCall call);
  void virtual_event(const std::string& what);
  void virtual_off();                            // the real axes where the virtual ones took them
  [[nodiscard]] bool virtual_axes_programmed();  // a driven axis programmed: reported
  // Mode 1: outside the minimum radius; C's turns.
  [[nodiscard]] bool virtual_path(const std::vector<AxisValues>& path);
  static constexpr double kChord = 1e-4;  // mm: the largest sagitta of the chords an arc's path checks use
  void origin_event();
  void transform_event();
  // A position's range, limits and protected zones.
  [[nodiscard]] bool path_allowed(const std::vector<AxisValues>& path);
  [[nodiscard]] bool position_in_range(int axis, double v);  // false (reported) beyond any machine's reach
  void set_position();
  void load_offset();                              // pp G92
  void load_compensation();                        // pp G93
  void reference_approach();                       // pp G30
  void reference_return(const AxisValues& point);  // ISO G28, G30
  void reference_leave();                          // ISO G29
  void set_local_offset();                         // ISO G52
  void data_set();                                 // ISO G10
  void offset_loaded(int n);                       // work offset n changed: its events
  void comp_entry_loaded(int n);                   // offset entry n changed: in force at once, its event
  void length_zeroed(bool zero);                   // ISO G28/G29: the length offset's event, zero or back
  void scaling_on();                               // ISO G51
  void rotation_on();                              // ISO G68
  bool block_has(Fn fn) const;                     // a code of the block calls fn
  void position_offset_event();

  // Motions (machine_motion.cpp).
  void move_to(const AxisValues& machine_target);
  Event motion_event(EventKind kind, const AxisValues& machine_target) const {
    return kernel_.motion_event(kind, machine_target, modal_.inch);
  }
  void rapid(const AxisValues& t);
  [[nodiscard]] bool need_feed(const char* what, const AxisValues& t);
  double block_seconds();
  void linear(const AxisValues& t);
  void arc(const AxisValues& t, bool clockwise);
  void arc_move(const AxisValues& t, double centre_u, double centre_v, bool clockwise, char pu, char pw);
  void parabola(const AxisValues& t);
  void thread(const AxisValues& t);
  void thread_variable(const AxisValues& t);
  void spline_point(const AxisValues& t);
  void spline_finish(const AxisValues& lead_out_end);
  void dwell();
  void dwell_seconds(double seconds);
  double timer_dwell();  // the dwell time variable in seconds, reported if out of range
  std::string dwell_address() const;
  double spindle_rpm() const;
  double feed_time(double length_mm);  // at the block's feed

  // GTL (machine_gtl.cpp, NC-110 §2.11).
  struct GtlState;
  struct GtlDelete {
    void operator()(GtlState* s) const;
  };
  std::unique_ptr<GtlState, GtlDelete> gtl_;
  std::optional<uint32_t> event_source_;  // the block a deferred move belongs to
  void gtl_init();
  bool gtl_open() const;         // a profile is open
  double gtl_tolerance() const;  // program units
  void gtl_define(uint16_t shape);
  void gtl_block();
  void gtl_moves();
  void gtl_unit_end();
  uint64_t gtl_bytes() const;

  // What a dialect does its own way, chosen once from the program's conventions: a
  // strategy serves its one machine and is not copied.
  class Strategy {
   public:
    explicit Strategy(Machine& m) : m_(m) {}
    virtual ~Strategy() = default;
    Strategy(const Strategy&) = delete;
    Strategy& operator=(const Strategy&) = delete;

   protected:
    Machine& m_;
  };
  // Canned cycles: the program's engine (cycle_engine.h), chosen once; the steps of a
  // hole and the tap's moves are shared (machine_cycles.cpp).
  class CycleEngine;
  class OneLevelCycles;
  class GostCycles;
  class IsoCycles;
  class Nc110Cycles;
  std::unique_ptr<CycleEngine> cycles_;
  // The tool change: the program's (tool_change.h), chosen once.
  class ToolChange;
  class PlainToolChange;
  class IsoToolChange;
  class Nc110ToolChange;
  std::unique_ptr<ToolChange> tool_change_;
  // What the dialect forbids a block (block_rules.h): plain, or ISO's; chosen once.
  class BlockRules;
  class IsoBlockRules;
  class Nc110BlockRules;
  std::unique_ptr<BlockRules> rules_;
  void cancel_cycle();  // the active cycle ends
  // `pitch`: a tap's (NC-110 G84 K), synchronised with the spindle.
  void hole_steps(const std::vector<cycle::Step>& steps, const AxisValues& hole, int d, int u, bool program,
                  std::optional<double> pitch = std::nullopt);
  void tap_feed(const AxisValues& t, bool out, int d, std::optional<double> pitch);
  void measure();
  void skip();  // Fanuc G31

  const ProgramSemantics& sem_;
  const Conventions& conv_;
  const MachineConfig& config_;
  TraceSink& trace_;
  RuntimeIssues& issues_;
  bool stop_on_error_ = true;

  MotionKernel kernel_;  // where the machine is, its coordinates, envelope and event output
  Modal modal_;
  std::map<int, OffsetEntry> tool_offsets_;  // the compensation table (pp G93 loads it, NC-110 RQU changes it)
  OffsetEntry offset_;         // the entry in force (its radius): a change to the table takes effect when selected
  OffsetEntry length_offset_;  // ... and the one whose length is in force (the same but under ISO's H)
  std::optional<AxisValues> intermediate_;  // ISO G28's intermediate point (machine coordinates), for G29
  double last_rotation_ = 0;                // ISO G68: the angle G91 adds to (it outlives G69)

  // ISO ,C and ,R (§8.3): the move before a corner is held back in the kernel (with
  // every event after it) until the next block's move shows where the corner is cut.
  struct Corner {
    bool fillet = false;
    double size = 0;      // program units
    uint32_t source = 0;  // the block that asks for it
    int slot = 0;         // its word
    size_t incoming = 0;  // index in held_ of the move it ends
    AxisValues start{};   // where that move starts (trace coordinates)
    bool inch = false;    // the units of its block
  };
  std::optional<Corner> corner_;
  uint64_t moves_beyond_first_ = 0;
  std::optional<AxisValues> chained_start_;  // a corner's T2, when the next move has a corner too
  void text_event(EventKind kind, const std::string& text, uint32_t source, int n = 0, double a = 0);
  // The traced cutter path: the runtime offsets the path itself (ISO, NC-110), or there
  // is none and G41/G42 reach the trace as events, for the machine to compensate.
  // Chosen once from the conventions, for the kernel's output (kernel_.path()); the
  // sites ask only whether it is there.
  std::unique_ptr<CutterPath> cutter_path(TraceSink& trace);
  uint64_t path_bytes() const;  // what it holds (held_bytes)
  bool corner_requested() const;
  void corner_begin(const AxisValues& start);
  void corner_finish(bool another, size_t block_from);
  void corner_codes();  // E-06: what the block after a corner may hold
  void release();
  std::optional<double> feed_;  // mm/min, mm/rev, or 1/min (inverse time) as programmed
  struct Repeated {
    RuntimeIssue issue;
    uint32_t more = 0;  // blocks after the first that had it
  };
  std::map<DiagId, Repeated> repeated_;  // report_repeated's, not yet said
  std::optional<double> helix_pitch_;    // pp G10 K: the pitch of the helices after it
  double speed_ = 0;
  int tool_selected_ = 0;
  int corrector_selected_ = 0;
  int tool_loaded_ = 0;
  int offset_number_ = 0;                      // of offset_ (ISO D)
  int length_number_ = 0;                      // of length_offset_ (ISO H)
  int spindle_direction_ = 0;                  // the last direction set (canned cycles restart the spindle in it)
  std::string motion_name_;                    // the code that set the motion group, for messages
  std::optional<AxisValues> parabola_middle_;  // first block of a three-point parabola
  BlockState block_;

  // NC-110 state.
  AxisValues tolerance_{};        // DTL; 0 = the machine's
  bool turning_ = false;          // CTL
  uint32_t locked_ = 0;           // M10/M12: axes that must not move
  bool profile_running_ = false;  // a G27/G28 profile is running: no M, S or T
  bool graphic_cleared_ = false;  // CLG since the last UCG (DCG comes after it)
  Spline spline_;
  uint64_t spline_bytes() const;             // of its points (held_bytes)
  size_t next_contact_ = 0;                  // the simulated probe's next contact
  std::optional<AxisValues> skip_position_;  // where G31's skip signal came, work coordinates
  ProbeConfig probe_;                        // the probe's distances and speed (DPT changes them)
  struct Unusable {
    std::string why;        // "TOF", "RQU: ..."
    bool reported = false;  // selected with no sister left: said once
  };
  std::map<int, Unusable> unusable_;  // tools declared unusable
  // UAV (§2.17-2.19): the program moves `virt`, `real` follow (mode 3: the masters
  // `virt` are programmed, the slaves `real` follow).
  struct VirtualAxes {
    int mode = 0;  // 0 none, 1 polar, 2 cylinder, 3 parallel, 4 rotation in space
    std::vector<int> real, virt;
    double value = 0;                  // mm: 1 the minimum radius, 2 the cylinder's radius
    std::array<int, 3> master{};       // mode 3: each slave's master
    std::array<int, 3> sign{1, 1, 1};  // mode 3: -1 mirrored; mode 1: [0] the side of X the tool started on
    std::array<double, 9> rotation{};  // mode 4: real = R virtual, row-major
    AxisValues saved{};                // machine positions at activation (the letters the virtual axes borrow)
    AxisValues zero{};                 // the origins at activation: the virtual and real axes' zeros
    double angle = 0;                  // mode 1: how far C has turned, unwrapped, radians
  } virtual_axes_;

  // Switches and system variables.
  bool block_skip_ = false;
  bool optional_stop_ = false;
  RemainingPaths* remaining_paths_ = nullptr;
  BlockResult run_block(const BlockRequest& block);
  double clock_base_ = 0;              // ISO #3001/#3002: where the program set them to 0
  std::map<uint16_t, double> system_;  // the stored system variables, by SysRef::packed()
  std::vector<std::pair<uint32_t, double>> results_;
  std::string system_name(SysRef ref) const;
  double system_value(SysVar v) const { return system(SysRef{v, 0}); }
};

}  // namespace ncc
