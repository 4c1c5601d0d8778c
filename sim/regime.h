// Cutting conditions (`ncc regime`, the seed simulator's calculator F-29): the spindle
// speed and the feed from the tool's diameter and teeth, the cutting speed and the
// feed per tooth (per revolution for a drill), with reference values for material
// groups and tool kinds from stdlib/cutting_data.tsv, which names its sources.
//   n  = 1000 * Vc / (pi * D)      rpm, Vc in m/min, D in mm
//   Vf = fz * z * n                mm/min, milling (fz per tooth, z teeth)
//   Vf = f * n                     mm/min, drilling (f per revolution)
// Everything here is metric; `ncc regime --inch` converts at its edges.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ncc::sim {

enum class FeedPer : uint8_t { Tooth, Revolution };

struct CuttingMaterial {
  std::string key;  // "structural_steel"
  std::string name;
};

struct ToolKind {
  std::string key;  // "carbide_endmill"
  FeedPer feed_per = FeedPer::Tooth;
  std::string name;
};

struct CuttingSource {
  std::string key;  // "TUNG"
  std::string title;
};

// One `cut` row: what a source gives for a tool kind in a material over diameters.
struct CuttingRow {
  std::string tool, material;
  double d_min = 0, d_max = std::numeric_limits<double>::infinity();  // mm; equal: a value at one diameter
  double vc_min = 0, vc_max = 0;                                      // m/min
  bool has_feed = false;                                              // false: the source gives a speed only
  double f_min = 0, f_max = 0;  // mm per tooth or per revolution, as the tool kind says
  std::string source, note;
  uint32_t line = 0;  // in the table file
};

// The table's values for one tool kind, material and diameter.
struct Reference {
  enum class How : uint8_t {
    Row,           // a row holds the diameter
    Interpolated,  // linear between the rows below and above
    Nearest,       // outside the rows' diameters: the nearest row's values
  };
  How how = How::Row;
  const CuttingRow* below = nullptr;  // Row, Nearest: the row; Interpolated: the two
  const CuttingRow* above = nullptr;
  double vc_min = 0, vc_max = 0;
  bool has_feed = false;
  double f_min = 0, f_max = 0;
  std::string source;  // the rows' source keys, "TUNG" or "A/B"
};

struct CuttingTable {
  std::vector<CuttingMaterial> materials;
  std::vector<ToolKind> tools;
  std::vector<CuttingSource> sources;
  std::vector<CuttingRow> rows;

  // By key, ignoring case, '-' taken for '_'; nullptr if there is none.
  const CuttingMaterial* material(std::string_view key) const;
  const ToolKind* tool(std::string_view key) const;
  const CuttingSource* source(std::string_view key) const;
  // The rows of a tool kind and material, in the table's order.
  std::vector<const CuttingRow*> rows_for(std::string_view tool, std::string_view material) const;
  // The values at diameter `d` (mm); nothing when the table has no row for the pair.
  std::optional<Reference> reference(std::string_view tool, std::string_view material, double d) const;
};

// Parses a table in cutting_data.tsv's form; each problem is added to `errors` as
// "NAME:LINE: what". Rows with problems are left out.
CuttingTable parse_cutting_table(std::string_view name, std::string_view text, std::vector<std::string>& errors);
// stdlib/cutting_data.tsv as compiled in.
CuttingTable load_cutting_table(std::vector<std::string>& errors);

struct RegimeInput {
  double diameter = 0;  // mm
  int teeth = 1;        // cutting edges; 1 for a feed per revolution
  double vc = 0;        // m/min
  double feed = 0;      // mm per tooth (or per revolution with teeth = 1)
  double max_rpm = 0;   // the machine's limits; 0: none
  double max_feed = 0;  // mm/min
};

struct Regime {
  double rpm_wanted = 0;   // 1000 Vc / (pi D)
  double rpm = 0;          // after --max-rpm
  double vc = 0;           // the cutting speed at `rpm` (lower when clamped)
  double feed_wanted = 0;  // feed * teeth * rpm, at the clamped rpm
  double feed_rate = 0;    // Vf after --max-feed, mm/min
  double feed = 0;         // per tooth (revolution) at `feed_rate` (lower when clamped)
  bool rpm_clamped = false;
  bool feed_clamped = false;
};

double spindle_speed(double vc, double diameter);      // rpm
double cutting_speed(double rpm, double diameter);     // m/min
double feed_rate(double feed, int teeth, double rpm);  // mm/min
Regime compute_regime(const RegimeInput& in);

// The words of a block that sets the regime, "S3183 M3 F764": S is the rpm rounded
// to a whole number (not above the limit), F the feed at that S, fz * z * S, rounded
// to a whole mm/min (inch: to 0.1 in/min; not above the limit). M3: spindle on,
// clockwise.
struct BlockWords {
  long s = 0;
  double f = 0;  // mm/min, or in/min when `inch`
  std::string text;
};
BlockWords block_words(const Regime& r, const RegimeInput& in, bool inch);

}  // namespace ncc::sim
