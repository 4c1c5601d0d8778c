#include "settings.h"

#include "frontend/frontend.h"

namespace ncc::linuxcnc {

std::optional<Settings> load_settings(const stdlib::Profile& p, Diagnostics& diags) {
  Settings s;
  size_t errors = diags.error_count();
  s.tables = stdlib::load_dialect_tables("linuxcnc", diags);
  if (auto table = stdlib::load_table("linuxcnc", "not_run.tsv", 3, diags))
    for (const stdlib::TableRow& row : table->rows) {
      if (row.cells[1].starts_with("ignore") && (row.cells[1].size() == 6 || row.cells[1][6] == '/'))
        s.ignored[row.cells[0]] = row.cells[1].size() > 6 ? row.cells[1].substr(7) : "";
      else if (row.cells[1] == "refuse")
        s.refused[row.cells[0]] = row.cells[2];
      else
        report(diags, *table, row.line,
               fmt::format("action '{}' must be refuse, ignore or ignore/<letters>", row.cells[1]));
    }
  if (diags.error_count() != errors) return std::nullopt;
  s.power_on = s.tables.power_on.at("default");
  bool ok = true;
  if (auto v = p.string("linuxcnc.program_library", diags)) s.library = v->empty() ? "" : p.resolve_path(*v);
  ok &= read_machine_codes(p, "linuxcnc", "GM", s.tables, diags);

  // The machine rs274 assumes without an INI file (tests/diff/linuxcnc/README.md).
  Conventions& c = s.conventions;
  c.arc_centre = ArcCentre::Incremental;  // G91.1, the default; G90.1 is refused
  c.centre_words = CentreWords::PerAxis;
  c.radius_word = 'R';
  c.helix_by_end = true;
  c.dwell_word = 'P';  // seconds, with or without a decimal point
  c.dwell_seconds_per_unit = 1;
  c.peck_word = 'Q';
  c.cycle_level_word = 'R';
  c.fanuc_cycles = true;       // G98/G99, feed out to R then rapid
  c.cycle_repeat_words = "L";  // K is no repeat count in LinuxCNC
  c.peck_clearance = 0.254;    // G83: 0.010 inch above the depth reached
  c.chip_break_retract = 0.254;
  c.m06_stops_spindle = true;  // M06 stops the spindle and keeps the offsets
  c.cutter = CutterStyle::FanucA;
  c.tool_offset_axes = "Z";
  c.axes = "XYZ";
  c.max_call_depth = 0;
  c.arc_tolerance = 0.0721;  // decision 11: rs274 lets the radii differ by 0.0028 inch
  if (auto v = p.number("linuxcnc.arc_tolerance", diags)) {
    if (*v > 0 && *v <= 1)
      c.arc_tolerance = *v;
    else
      ok = (p.report_value(diags, "linuxcnc.arc_tolerance", "must be a length in mm above 0 and at most 1"), false);
  }
  if (!ok) return std::nullopt;
  return s;
}

}  // namespace ncc::linuxcnc
