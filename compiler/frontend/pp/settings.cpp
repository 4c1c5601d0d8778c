#include "settings.h"

#include <charconv>

#include "frontend/frontend.h"

namespace ncc::pp {

namespace {

void report(Diagnostics& diags, const stdlib::Table& t, uint32_t line, std::string_view what) {
  diags.report(DiagId::TableSyntax, {}, fmt::format("{}:{}: {}", t.name, line, what));
}

void read_control(Settings& s, Diagnostics& diags) {
  auto table = stdlib::load_table("pp", "control_codes.tsv", 3, diags);
  if (!table) return;
  for (const stdlib::TableRow& row : table->rows) {
    const auto& c = row.cells;
    ControlCode code;
    std::string_view action = c[1];
    bool ok = true;
    if (action.starts_with("formula(") && action.size() == 10 && action.back() == ')') {
      code.action = Control::Formula;
      code.op = action[8];
      ok = std::string_view("+-*/").find(code.op) != std::string_view::npos;
    } else if (action.starts_with("plane(") && action.size() == 9 && action.back() == ')') {
      code.action = Control::Plane;
      code.plane = {action[6], action[7]};
    } else {
      static const std::map<std::string_view, Control> kActions = {
          {"entry", Control::Entry},         {"end", Control::End},   {"call_subprogram", Control::CallSubprogram},
          {"call_macro", Control::CallMacro}, {"jump", Control::Jump}, {"dwell", Control::Dwell},
          {"unsupported", Control::Unsupported}};
      auto it = kActions.find(action);
      ok = it != kActions.end();
      if (ok) code.action = it->second;
    }
    const auto& codes = c[0][0] == 'G' ? s.tables.g_codes : s.tables.m_codes;
    int number = 0;
    auto [end, ec] = std::from_chars(c[0].data() + 1, c[0].data() + c[0].size(), number);
    ok = ok && ec == std::errc() && end == c[0].data() + c[0].size() && codes.count(number);
    if (!ok) {
      report(diags, *table, row.line, fmt::format("malformed row for '{}'", c[0]));
      continue;
    }
    code.note = c[2];
    s.control[c[0]] = std::move(code);
  }
}

}  // namespace

std::optional<Settings> load_settings(const stdlib::Profile& p, Diagnostics& diags) {
  Settings s;
  size_t errors = diags.error_count();
  s.tables = stdlib::load_dialect_tables("pp", diags);
  // Group M14 is every auxiliary function 10..99 that no other group lists.
  for (int n = 10; n <= 99; ++n)
    if (!s.tables.m_codes.count(n)) {
      stdlib::CodeEntry e;
      e.letter = 'M';
      e.number = n;
      e.conflict_sets = {"M14"};
      e.desc.name = fmt::format("M{:02}", n);
      e.desc.timing = Timing::After;
      e.meaning = "Auxiliary function of group M14 (to the machine's logic)";
      s.tables.m_codes[n] = e;
    }
  read_control(s, diags);
  if (diags.error_count() != errors) return std::nullopt;
  diags.set_citations(s.tables.citations);
  s.power_on = s.tables.power_on.at("default");

  bool ok = true;
  if (auto v = p.string("pp.axis_letters", diags)) {
    // §2.2.1 a, b: axes 4. and 5. may be A B C U V W, axis 6. A B C.
    bool valid = v->size() == 3 && (*v)[0] != (*v)[1] && (*v)[0] != (*v)[2] && (*v)[1] != (*v)[2];
    for (size_t i = 0; valid && i < 3; ++i)
      valid = std::string_view(i < 2 ? "ABCUVW" : "ABC").find((*v)[i]) != std::string_view::npos;
    if (valid) s.axis_letters = *v;
    else ok = (p.report_value(diags, "pp.axis_letters", "must name axes 4., 5., 6. with three different letters: A B C U V W for 4. and 5., A B C for 6."), false);
  }
  if (auto v = p.string("pp.macro_library", diags)) s.library = v->empty() ? "" : p.resolve_path(*v);
  if (auto v = p.boolean("pp.require_star", diags)) s.require_star = *v;

  Conventions& c = s.conventions;
  c.arc_centre = ArcCentre::Incremental;      // I, J from the start point (decision 17)
  c.centre_words = CentreWords::Plane;        // I along the first axis, J the second
  c.helix_lead = HelixLead::PerRevolution;
  c.dwell_word = 'Q';                         // G04: Q in 10 ms units (dictionary)
  c.dwell_seconds_per_unit = 0.01;
  c.peck_word = 'I';                          // decision 21
  c.cycle_level_word = 'K';
  c.tool_offset_axes = "Z";
  c.axes = "XYZ";
  for (char axis : kAxisLetters)
    if (s.axis_letters.find(axis) != std::string::npos) c.axes += axis;
  c.max_call_depth = 8;                       // decision 15
  if (auto v = p.number("pp.max_call_depth", diags)) {
    if (*v >= 1 && *v <= 32 && *v == static_cast<int>(*v)) c.max_call_depth = static_cast<uint8_t>(*v);
    else ok = (p.report_value(diags, "pp.max_call_depth", "must be a whole number from 1 to 32"), false);
  }
  if (!ok) return std::nullopt;
  return s;
}

}  // namespace ncc::pp
