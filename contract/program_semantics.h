// What a compiled program tells the runtime about its dialect: the G/M codes it uses
// with their canonical functions and timing, the canned-cycle patterns, the
// power-on state and the conventions its words follow. The compiler fills this from
// the dialect tables and the machine profile; the bytecode file stores it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "functions.h"
#include "word_slots.h"

namespace ncc {

// One G or M code as the program uses it, e.g. G81 -> cycle(0), M05 -> spindle.stop
// + coolant.off, after the motion.
struct CodeDesc {
  std::string name;
  Scope scope = Scope::Modal;
  Timing timing = Timing::None;
  std::vector<FnCall> calls;
};

// A canned cycle as a pattern of moves (GOST 20999 Table 6 and its kin).
struct CyclePattern {
  // ISO adds: ChipBreak (G73), TapCw/TapCcw (G84/G74: the spindle set that way in,
  // reversed out), Back (G87: back boring from R up to the bottom); OrientShift (G76:
  // an oriented stop and a shift off the wall).
  enum class In : uint8_t { Feed, Peck, SpindleFeed, ChipBreak, TapCw, TapCcw, Back };
  enum class Bottom : uint8_t { None, Reverse, Stop, OrientShift };
  enum class Out : uint8_t { Rapid, Feed, Manual };
  std::string name;
  In in = In::Feed;
  bool dwell = false;
  Bottom bottom = Bottom::None;
  Out out = Out::Rapid;
};

enum class ArcCentre : uint8_t { Incremental, Absolute };
enum class HelixLead : uint8_t { PerRadian, PerRevolution };
enum class ParabolaTangent : uint8_t { Coordinates, Incremental };
enum class AngleUnit : uint8_t { Degree, Radian, Revolution };
// Which words give an arc's centre: I J K along X Y Z (GOST 20999), or I the
// abscissa and J the ordinate of the plane, K the helix pitch (NC-110).
enum class CentreWords : uint8_t { PerAxis, Plane };
// The drilling axis of a canned cycle: the plane's normal, or the axis of the depth
// word (NC-110 §2.8.9).

// Cutter radius compensation: the trace shows the programmed path (GOST, pp: the
// machine offsets it), or the tool centre's by ISO's rules (Fanuc type A, §8.10) or
// NC-110's (§2.8.7, runtime/cutter_path.h CompRules).
enum class CutterStyle : uint8_t { Programmed, FanucA, Nc110 };

// Word conventions: which address carries what, and how to read it. Addresses are
// letters; 0 means "none".
constexpr uint8_t kNoSpace = 255;

struct Conventions {
  ArcCentre arc_centre = ArcCentre::Incremental;
  HelixLead helix_lead = HelixLead::PerRadian;
  ParabolaTangent parabola_tangent = ParabolaTangent::Coordinates;
  AngleUnit angle_unit = AngleUnit::Degree;
  char dwell_word = 'P';
  double dwell_seconds_per_unit = 1.0;
  char peck_word = 'Q';
  char cycle_level_word = 'R';
  char pitch_change_word = 0;
  bool thread_allow_j = false;
  bool arc_single_quadrant = false;
  double arc_tolerance = 0.002;  // mm
  // The resolution of the helix lead words I/J/K (program units): a lead written to
  // that precision is exact enough over the whole sweep.
  double lead_resolution = 0;
  bool m06_stops_spindle = false;
  std::string tool_offset_axes = "Z";
  std::string axes = "XYZ";         // the machine's axes, in canonical order XYZABCUVWPQD
  uint8_t max_call_depth = 0;       // subprogram calls that may be open at once; 0 = the VM's limit
  uint8_t result_space = kNoSpace;  // the variable space measured values go to
  CentreWords centre_words = CentreWords::PerAxis;
  char radius_word = 0;              // an arc by its radius: R+ up to 180 degrees, R- beyond
  bool helix_by_end = false;         // a helix is given by its end point alone: no lead word (ISO)
  bool cycle_two_levels = false;     // R, then R' (its second value): approach and return levels
  bool cycle_defines_only = false;   // a cycle's own block stores it; the blocks after it drill
  bool cycle_needs_cancel = false;   // a new cycle needs the active one cancelled first
  bool fanuc_cycles = false;         // G98/G99 return, feed out to R then rapid, repeats (ISO)
  std::string cycle_repeat_words;    // the words that repeat a cycle block (ISO "LK")
  double peck_clearance = 0;         // ISO G83: the rapid back down stops this far above the depth reached (mm)
  double chip_break_retract = 0;     // ISO G73: the retract after a peck (mm); 0 = back to the depth before it
  int8_t boring_shift = 1;           // ISO G76/G87: Q shifts along the plane's first axis, + or -
  bool tool_change_iso = false;      // ISO M06: ignored for the tool in the spindle; stops spindle and
                                     // coolant, ends both compensations
  bool tool_change_retract = false;  // ... and first rapids the tool axis to the reference point
  double initial_feed = 0;           // the feed in force at the start (0: none until F is programmed)
  bool fanuc_rules = false;          // ISO E-08..E-27: what G51/G68, G91 and cutter compensation forbid
  bool corners = false;              // ISO ,C and ,R (the second C and R words): a chamfer or fillet after the move
  CutterStyle cutter = CutterStyle::Programmed;  // what G41/G42 do to the path the trace shows
  bool comp_path() const { return cutter != CutterStyle::Programmed; }
  char peck_factor_word = 0;            // G83: the factor on the peck, down to
  char peck_minimum_word = 0;           //      the smallest peck (NC-110 K, J)
  char tap_pitch_word = 0;              // tapping with a spindle encoder: the pitch (NC-110 K)
  bool corrector_in_tool_word = false;  // T tool.corrector: the corrector takes effect at M06
  bool mirror_toggles = false;          // a mirror code on a mirrored axis turns it back
  // pp.
  char diameter_axis = 0;                           // the axis a diameter code (G74) programs as a diameter
  std::string link_axes;                            // the axes of the digits of the length link '&', in order
  std::string aux_words;                            // addresses the machine's logic takes as auxiliary functions (H P)
  char comp_length_word = 0, comp_radius_word = 0;  // what loads a compensation entry (pp G93)
  // The feeds F may give in each feed mode (inverse time, per minute, per revolution):
  // lo, hi; 0, 0 = any.
  double feed_limits[3][2] = {};
};

// A code a program selects at run time by its number (NC-110 `GE1`).
struct NumberedCode {
  uint8_t slot = 0;  // the letter's word slot
  uint16_t number = 0;
  uint16_t code = 0;  // index into codes
  bool operator==(const NumberedCode&) const = default;
};

// Two codes that must not share a block: by the compatibility matrix (NC-110 Table
// 2.4), or because both control `function` (an M conflict set).
struct CodePair {
  uint16_t a = 0, b = 0;
  std::string function;
};

// The values an address takes, checked when a parameter gives the value at run time
// (pp `Q R5`): lo..hi, whole numbers only when `whole`.
struct ValueRule {
  std::string address;
  double lo = 0, hi = 0;
  bool whole = false;
};

struct ProgramSemantics {
  std::string dialect;
  std::vector<CodeDesc> codes;
  std::vector<CyclePattern> cycles;
  std::vector<uint16_t> power_on;  // indices into codes, applied in order
  Conventions conventions;
  std::vector<std::string> system_names;   // the dialect's name of each SysVar ("TMR"), for messages
  std::vector<std::string> builtin_names;  // ... of each Builtin ("SQR"); empty: its own name
  std::vector<NumberedCode> numbered;      // the codes a program may select at run time
  std::vector<CodePair> incompatible;      // codes that must not share a block
  std::vector<ValueRule> value_rules;      // for Check
};

}  // namespace ncc
