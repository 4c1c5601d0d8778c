// The machine as the run sees it: offsets, tools and limits from the machine profile.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ncc {

// X Y Z A B C U V W in LinuxCNC's order, then NC-110's further axes P Q D.
constexpr int kAxisCount = 12;
using AxisValues = std::array<double, kAxisCount>;
constexpr std::string_view kAxisLetters = "XYZABCUVWPQD";
int axis_index(char letter);  // -1 if not an axis letter

// A plane of interpolation: its abscissa u, ordinate v and the axis w along u x v
// (-1 when no axis lies that way), so that "clockwise seen from +w" is the negative
// sense in (u, v) (GOST 20999 S-9.2, NC-110 §2.8.1.4). LinuxCNC orders its arcs' axes
// the same way.
struct Plane {
  int u = 0, v = 1, w = 2;
  bool operator==(const Plane&) const = default;
};
// G17, G18, G19: XY, ZX, YZ.
constexpr Plane kPlanes[3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};
// "XY", "ZU": the letters of abscissa and ordinate.
std::string plane_name(const Plane& p);

// Tools T selects; their length and radius are offsets, numbered by D/H (§3.3.5), or
// the correctors of NC-110's T tool.corrector.
struct ToolEntry {
  std::string description;
  std::vector<int> sisters;  // NC-110 tool life (§2.13.10): the tools that replace it once unusable, in order
  int corrector = 0;         // ... and the corrector a sister brings in place of the programmed one (0: that one)
};

struct OffsetEntry {
  double length = 0;
  double radius = 0;
  char axis = 0;  // the axis the length applies to (0: the dialect's)
  // NC-110 §2.13.8: a corrector may keep the wear RQU adds up (c) and its maxima (m);
  // beyond one, the tool is unusable. No maximum: the corrector keeps none.
  double wear_length = 0, wear_diameter = 0;
  std::optional<double> max_wear_length, max_wear_diameter;
};

// A work offset (GOST G54..G59) or an NC-110 origin (0..99): values of the axes it
// declares, in mm, or in inches when `inch`. ISO's extended work offsets (Fanuc G54.1
// P1-P300, Haas G154 P1-P99) are numbers kExtendedWorkOffset + P.
constexpr int kExtendedWorkOffset = 100;
constexpr int kExtendedWorkOffsets = 300;
struct WorkOffset {
  AxisValues values{};
  uint32_t axes = 0;  // bit i: axis i is declared
  bool inch = false;
};

enum class AxisKind : uint8_t { Linear, Rotary, Indexing };

struct AxisConfig {
  AxisKind kind = AxisKind::Linear;  // A B C are rotary unless the profile says otherwise
  double index_step = 1;             // Indexing: degrees per index (the program counts indexes)
  bool endless = false;              // Rotary: no end; positions show 0..360 and the sign of a target picks the way
  bool diameter = false;             // a lathe's cross axis programmed as a diameter
  double rapid = 10000;              // mm/min, degrees/min
  // The cycle time's models (sim/timing.h, docs/profile.md): the fastest feed (the
  // profile reader makes it `rapid` unless the profile gives it), the acceleration
  // and the jerk, per mm or per degree.
  double max_feed = 10000;           // mm/min, degrees/min
  double acceleration = 2000;        // mm/s², degrees/s²
  double jerk = 50000;               // mm/s³, degrees/s³
  double lower = -1e9, upper = 1e9;  // travel limits, machine coordinates
  double tolerance = 0.01;           // in-position tolerance (NC-110 DTL 0)
  double drive_error = 1;            // the largest tolerance a program may set (NC-110 DTL)
};

// The simulated probe of the measuring cycles (NC-110 G72-G74): what each probing
// touches, in the order the program probes. A point gives the contact's coordinates
// on some axes (the others touch at the nominal point); a circle the hole G73 finds;
// `none` no contact. When the list runs out, contact is at the nominal point.
struct ProbeContact {
  enum class Kind : uint8_t { Point, Circle, None } kind = Kind::Point;
  AxisValues point{};  // Point: the surface point; Circle: the hole's centre
  uint32_t axes = 0;   // the axes given (a circle's centre gives two)
  double radius = 0;   // Circle
};

struct ProbeConfig {
  double approach = 10;  // mm before the nominal point the probe starts feeding (Qa)
  double safety = 12;    // mm past it the probe gives up (Qs)
  double feed = 1000;    // mm/min (Vm)
  std::vector<ProbeContact> contacts;
};

// NC-110 ASSET files (chapter 5): what the process characterisation (PGCFIL CHN, STR)
// and the devices allow.
struct AssetConfig {
  uint32_t channels = 8;            // channels 1..channels
  uint32_t structures = 16;         // record structures 1..structures
  uint64_t device_bytes = 1 << 20;  // the files of one device together, at most
};

// What the cycle time needs beyond the axes (sim/timing.h, docs/profile.md [motion]).
struct MotionConfig {
  double junction_deviation = 0.01;    // mm: how far a corner may be rounded at speed (grbl's)
  double tool_change = 5;              // s per tool change, chip to chip
  double spindle_acceleration = 4000;  // rpm/s: a start, stop or speed change takes |Δrpm| / this
  // mm/min: the speed along the path, rapids and feeds (LinuxCNC's [TRAJ]
  // MAX_LINEAR_VELOCITY); infinity: the axes alone limit it.
  double max_velocity = std::numeric_limits<double>::infinity();
};

// The blank `ncc view` draws: a box, mm, in the coordinates the view shows (from the
// first work zero the program selects; docs/profile.md [stock]).
struct StockConfig {
  bool set = false;
  std::array<double, 3> min{}, max{};  // X Y Z
};

struct MachineConfig {
  std::string name = "default";
  std::string profile = "default";         // how --machine named it ("haas", "mill.toml"), for messages
  std::map<int, WorkOffset> work_offsets;  // GOST G54..G59 = 1..6; NC-110 origins 0..99
  std::map<int, ToolEntry> tools;
  std::map<int, OffsetEntry> offsets;  // D/H offset numbers, NC-110 correctors
  std::array<AxisConfig, kAxisCount> axes = default_axes();
  AxisValues initial_position{};
  AxisValues reference_position{};               // the machine's reference point (pp G30)
  std::array<AxisValues, 3> other_references{};  // the 2nd to 4th reference points (ISO G30 P2..P4)
  bool block_skip = false;                       // run-time switches
  bool optional_stop = false;
  bool spindle_encoder = true;         // threading and rigid tapping need one
  double max_rpm = 0;                  // constant cutting speed stays below (0: no limit)
  double tap_min_travel = 0;           // mm a floating tap needs to speed up and slow down
  std::optional<Plane> turning_plane;  // NC-110 (CTL,T): the turning configuration's plane
  ProbeConfig probe;
  AssetConfig asset;
  MotionConfig motion;
  StockConfig stock;
  uint8_t processes = 5;         // NC-110 chapter 4: the processes configured (PGCFIL), 1..5
  double gtl_tolerance = 0.001;  // mm: NC-110 GTL points this close are one point (§2.11)
  uint32_t look_ahead = 64;      // blocks a process evaluates ahead of its motion (NC-110 §1.1.1, §2.16), 1..64
  // Bytes a process's runtime may hold back for later moves (Machine::held_bytes) before
  // the run stops (limits.run_memory_mib): a real program holds a few events.
  uint64_t run_memory = uint64_t{256} << 20;
  // The trace shows positions in machine coordinates (in program units), not from
  // the active origin: runs of programs that reach the same points through different
  // origins (a translation) compare move for move (`ncc run --trace-frame machine`).
  bool trace_machine_frame = false;

  static std::array<AxisConfig, kAxisCount> default_axes() {
    std::array<AxisConfig, kAxisCount> a{};
    for (int i : {3, 4, 5}) a[i].kind = AxisKind::Rotary;
    return a;
  }
};

// The numbers of a table, as ranges: "1-3, 7, 10-200"; "none" for an empty one. Work
// offsets: from 1 (0 is the machine's zero), the extended ones as "P1-P48".
std::string number_ranges(const std::vector<int>& sorted, bool work_offsets = false);
template <typename T>
std::string number_ranges(const std::map<int, T>& table, bool work_offsets = false) {
  std::vector<int> keys;
  for (const auto& entry : table)
    if (!work_offsets || entry.first != 0) keys.push_back(entry.first);
  return number_ranges(keys, work_offsets);
}

}  // namespace ncc
