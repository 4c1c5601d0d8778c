// What a compiled program tells the runtime about its dialect: the G/M codes it uses
// with their canonical functions and timing, the canned-cycle patterns, the
// power-on state and the conventions its words follow. The compiler fills this from
// the dialect tables and the machine profile; the bytecode file stores it.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "conventions.def"
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
// Cutter radius compensation: the trace shows the programmed path (GOST, pp: the
// machine offsets it), or the tool centre's by ISO's rules (Fanuc type A, §8.10) or
// NC-110's (§2.8.7, runtime/cutter_path.h CompRules).
enum class CutterStyle : uint8_t { Programmed, FanucA, Nc110 };

constexpr uint8_t kNoSpace = 255;

// The feeds F may give in each feed mode (inverse time, per minute, per revolution):
// lo, hi; 0, 0 = any.
using FeedRanges = std::array<std::array<double, 2>, 3>;

// What the conventions.def checks mean: what a convention may hold.
namespace convention {
struct Flag {};
struct Letter {};
struct Letters {};
struct Axis {};
struct Axes {};
struct Count {};
struct Space {};
struct Sign {};
struct Length {};
struct Positive {};
struct FeedLimits {};
template <typename E>
struct Enum {
  E last;
};
template <typename E>
Enum(E) -> Enum<E>;
}  // namespace convention

// Word conventions: which address carries what, and how to read it (conventions.def).
// Addresses are letters; 0 means "none".
struct Conventions {
#define NCC_CONVENTION_FIELD(name, type, init, check, doc) type name = init;
  NCC_CONVENTIONS(NCC_CONVENTION_FIELD)
#undef NCC_CONVENTION_FIELD
  bool comp_path() const { return cutter != CutterStyle::Programmed; }
  bool operator==(const Conventions&) const = default;
};

// A code a program selects at run time by its number (NC-110 `GE1`).
// The number a code table keys a code by: a whole code (G01) is its number 0..999; a
// code with one decimal (G54.1, Fanuc's and the machine tables' decimal codes) is
// kDecimalCode + ten times it (10541), above every whole code. Nothing for any other
// value.
constexpr int kDecimalCode = 10000;
inline std::optional<int> code_key(double v) {
  if (!(v >= 0 && v < 1000)) return std::nullopt;
  if (v == std::trunc(v)) return static_cast<int>(v);
  const double tenths = std::round(v * 10);
  if (std::fabs(tenths - v * 10) > 1e-6) return std::nullopt;
  return kDecimalCode + static_cast<int>(tenths);
}

// The code's value as written: 54.1 for the key 10541.
inline double code_value(int key) { return key >= kDecimalCode ? (key - kDecimalCode) / 10.0 : key; }

struct NumberedCode {
  uint8_t slot = 0;     // the letter's word slot
  uint16_t number = 0;  // code_key
  uint16_t code = 0;    // index into codes
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
