#include "settings.h"

#include <cmath>

#include "frontend/frontend.h"
#include "support/text.h"

namespace ncc::iso {

namespace {

// #first..#last onto the runtime's system variables; modal_code takes the runtime
// group of a Fanuc group's codes, modal_word a letter's slot.
void read_system(Settings& s, Diagnostics& diags) {
  auto table = stdlib::load_table("iso", "system_variables.tsv", 5, diags);
  if (!table) return;
  for (const stdlib::TableRow& row : table->rows) {
    const auto& c = row.cells;
    const auto first = parse_number<uint32_t>(c[0]), last = parse_number<uint32_t>(c[1]);
    auto var = sys_by_name(c[2]);
    bool ok = first && last && *first <= *last && *first >= 1000 && var;
    uint32_t index = 0;
    if (ok && *var == SysVar::ModalCode) {
      ok = false;
      for (const auto& [n, code] : s.tables.g_codes)
        if (code.group == c[3] && !code.desc.calls.empty()) {
          index = static_cast<uint32_t>(fn_group(code.desc.calls.front().fn));
          ok = true;
          break;
        }
    } else if (ok && *var == SysVar::ModalWord) {
      ok = c[3].size() == 1 && letter_slot(c[3][0]) >= 0 && letter_slot(c[3][0]) < 26;
      if (ok) index = static_cast<uint32_t>(letter_slot(c[3][0]));
    } else if (ok) {
      auto n = parse_number<uint32_t>(c[3]);
      ok = n.has_value();
      index = n.value_or(0);
    }
    for (uint32_t k = 0; ok && k <= *last - *first; ++k) {
      SysRef ref{*var, static_cast<uint8_t>(index + k)};
      ok = index + k < 256 && ref.valid();
      if (ok) s.system[*first + k] = ref;
    }
    if (!ok) report(diags, *table, row.line, fmt::format("malformed row for #{}", c[0]));
  }
}

}  // namespace

std::optional<Settings> load_settings(const stdlib::Profile& p, Diagnostics& diags) {
  Settings s;
  size_t errors = diags.error_count();
  s.tables = stdlib::load_dialect_tables("iso", diags);
  read_system(s, diags);
  if (diags.error_count() != errors) return std::nullopt;
  diags.set_citations(s.tables.citations);
  s.power_on = s.tables.power_on.at("default");
  bool ok = true;
  // §8.7: the units at the start are an application setting.
  std::string units = "mm";
  if (auto v = p.string("iso.units", diags)) {
    if (*v == "mm" || *v == "inch")
      units = *v;
    else
      ok = (p.report_value(diags, "iso.units", "must be \"mm\" or \"inch\""), false);
  }
  s.power_on.push_back(units == "mm" ? "G21" : "G20");
  if (auto v = p.string("iso.program_library", diags)) s.library = v->empty() ? "" : p.resolve_path(*v);
  if (auto v = p.boolean("iso.semicolon_comments", diags)) s.semicolon_comments = *v;
  // Decision 53: the seed's OXXXX; Haas NGC writes five digits, Fanuc has eight.
  if (auto v = p.number("iso.program_number_digits", diags)) {
    if (*v >= 4 && *v <= 8 && *v == std::trunc(*v)) {
      s.program_digits = static_cast<uint32_t>(*v);
      s.max_program = 1;
      for (uint32_t i = 0; i < s.program_digits; ++i) s.max_program *= 10;
      --s.max_program;
    } else {
      ok = (p.report_value(diags, "iso.program_number_digits", "must be a whole number from 4 to 8"), false);
    }
  }
  // Decision 33: the machine's own codes (a row replaces the seed's code of its number).
  ok &= read_machine_codes(p, "iso", "GM", s.tables, diags);

  s.machine = p.name();
  Conventions& c = s.conventions;
  c.arc_centre = ArcCentre::Incremental;  // §8.2: I J K from the arc's start point
  c.centre_words = CentreWords::PerAxis;
  c.radius_word = 'R';    // §8.2: R+ up to 180 degrees, R- beyond
  c.helix_by_end = true;  // §8.2: a helix is its end point; no lead word
  c.dwell_word = 'P';     // seconds: the reader applies the decimal-point rule
  c.dwell_seconds_per_unit = 1;
  c.peck_word = 'Q';
  c.cycle_level_word = 'R';
  c.fanuc_cycles = true;        // §8.21-§8.27
  c.cycle_repeat_words = "LK";  // §8.23: K may stand for L
  c.peck_clearance = 0.254;     // decision 19
  c.chip_break_retract = 0;     // §8.25: back to the depth of the pass before
  auto length = [&](const char* key, double& out) {
    if (auto v = p.number(key, diags)) {
      if (*v >= 0 && *v <= 100)
        out = *v;
      else
        ok = (p.report_value(diags, key, "must be a length in mm from 0 to 100"), false);
    }
  };
  c.tool_change_iso = true;        // §8.31
  c.fanuc_rules = true;            // §8.8-§8.31 (E-08..E-27)
  c.corners = true;                // §8.3
  c.cutter = CutterStyle::FanucA;  // §8.10
  c.tool_change_retract = true;
  if (auto v = p.boolean("iso.tool_change_retract", diags)) c.tool_change_retract = *v;
  if (auto v = p.number("iso.initial_feed", diags)) {
    // the seed's examples feed without F; a machine may start with a feed.
    if (*v >= 0 && *v <= 100000)
      c.initial_feed = *v;
    else
      ok = (p.report_value(diags, "iso.initial_feed", "must be a feed from 0 (none) to 100000"), false);
  }
  length("iso.peck_clearance", c.peck_clearance);
  length("iso.chip_break_retract", c.chip_break_retract);
  if (auto v = p.string("iso.boring_shift", diags)) {
    if (*v == "+" || *v == "-")
      c.boring_shift = *v == "+" ? 1 : -1;
    else
      ok =
          (p.report_value(diags, "iso.boring_shift", "must be \"+\" or \"-\": the direction of the plane's first axis"),
           false);
  }
  c.tool_offset_axes = "Z";  // §8.11: the length acts along Z only
  c.length_word = 'H';       // §8.10, §8.11: H selects the length offset, D the radius (decision 58)
  c.axes = "XYZ";            // a three-axis vertical machining centre, unless the machine has more
  if (auto v = p.string("iso.axes", diags)) {
    std::string axes;
    for (char letter : kAxisLetters.substr(0, 9))  // canonical order
      if (v->find(letter) != std::string::npos) axes += letter;
    if (axes.size() == v->size() && axes.find("XYZ") == 0)
      c.axes = axes;
    else
      ok = (p.report_value(diags, "iso.axes", "must be X Y Z and any of A B C U V W, each once, e.g. \"XYZA\""), false);
  }
  c.max_call_depth = 20;  // §8.16: 20 nested macros; subprograms share it (decision 13)
  c.arc_tolerance = 0.01;
  if (auto v = p.number("iso.arc_tolerance", diags)) {
    if (*v > 0 && *v <= 1)
      c.arc_tolerance = *v;
    else
      ok = (p.report_value(diags, "iso.arc_tolerance", "must be a length in mm above 0 and at most 1"), false);
  }
  if (!ok) return std::nullopt;
  return s;
}

}  // namespace ncc::iso
