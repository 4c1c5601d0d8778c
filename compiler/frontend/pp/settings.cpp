#include "settings.h"

#include "frontend/frontend.h"
#include "support/text.h"

namespace ncc::pp {

namespace {

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
      static const std::map<std::string_view, Control> kActions = {{"entry", Control::Entry},
                                                                   {"end", Control::End},
                                                                   {"call_subprogram", Control::CallSubprogram},
                                                                   {"call_macro", Control::CallMacro},
                                                                   {"jump", Control::Jump},
                                                                   {"dwell", Control::Dwell},
                                                                   {"unsupported", Control::Unsupported}};
      auto it = kActions.find(action);
      ok = it != kActions.end();
      if (ok) code.action = it->second;
    }
    const auto& codes = c[0][0] == 'G' ? s.tables.g_codes : s.tables.m_codes;
    auto number = parse_number<int>(std::string_view(c[0]).substr(1));
    ok = ok && number && codes.count(*number);
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
  read_control(s, diags);
  if (diags.error_count() != errors) return std::nullopt;
  diags.set_citations(s.tables.citations);
  s.power_on = s.tables.power_on.at("default");

  // Groups M10..M13 are the machine's (machine constants R56..R59: pp.m_groups), group
  // M14 every other auxiliary function 10..99: the machine's logic carries them out.
  bool ok = true;
  auto aux_code = [&](int n, const std::string& group) {
    stdlib::CodeEntry e;
    e.letter = 'M';
    e.number = n;
    e.conflict_sets = {group};
    e.desc.name = fmt::format("M{:02}", n);
    e.desc.timing = Timing::After;
    e.desc.calls = {FnCall{Fn::Aux, static_cast<uint16_t>(n)}};
    e.meaning = fmt::format("Auxiliary function of group {} (to the machine's logic)", group);
    s.tables.m_codes[n] = e;
  };
  if (auto groups = p.string_table("pp.m_groups", diags)) {
    for (const auto& [group, members] : *groups) {
      const std::string key = "pp.m_groups." + group;
      if (group != "M10" && group != "M11" && group != "M12" && group != "M13") {
        ok = (p.report_value(diags, key, "the machine's groups are M10, M11, M12 and M13"), false);
        continue;
      }
      // "M20 M21+ M22": the codes of the group, '+' on its basic state.
      bool basic_seen = false;
      for (const std::string& piece : split(members, ' ')) {
        std::string_view item = piece;
        if (item.empty()) continue;
        const bool basic = item.back() == '+';
        if (basic) item.remove_suffix(1);
        const int n = item.size() == 3 && item[0] == 'M' ? parse_number<int>(item.substr(1)).value_or(0) : 0;
        std::string problem;
        if (n < 10)
          problem = fmt::format("'{}' is not an M code 10..99", item);
        else if (auto it = s.tables.m_codes.find(n); it != s.tables.m_codes.end())
          problem = fmt::format("M{} is already in group {}", n, it->second.conflict_sets.front());
        else if (basic && basic_seen)
          problem = "a group has one basic state ('+')";
        if (!problem.empty()) {
          ok = (p.report_value(diags, key, problem), false);
          continue;
        }
        aux_code(n, group);
        if (basic) s.power_on.push_back(fmt::format("M{:02}", n));
        basic_seen = basic_seen || basic;
      }
    }
  }
  for (int n = 10; n <= 99; ++n)
    if (!s.tables.m_codes.count(n)) aux_code(n, "M14");
  if (auto v = p.string("pp.axis_letters", diags)) {
    // §2.2.1 a, b: axes 4. and 5. may be A B C U V W, axis 6. A B C.
    bool valid = v->size() == 3 && (*v)[0] != (*v)[1] && (*v)[0] != (*v)[2] && (*v)[1] != (*v)[2];
    for (size_t i = 0; valid && i < 3; ++i)
      valid = std::string_view(i < 2 ? "ABCUVW" : "ABC").find((*v)[i]) != std::string_view::npos;
    if (valid)
      s.axis_letters = *v;
    else
      ok = (p.report_value(
                diags, "pp.axis_letters",
                "must name axes 4., 5., 6. with three different letters: A B C U V W for 4. and 5., A B C for 6."),
            false);
  }
  if (auto v = p.string("pp.macro_library", diags)) s.library = v->empty() ? "" : p.resolve_path(*v);
  if (auto v = p.boolean("pp.require_star", diags)) s.require_star = *v;
  // G93 (decision 23): the manual names no words for the values; the machine may.
  if (auto words = p.string_table("pp.comp_table_words", diags)) {
    for (const auto& [what, word] : *words) {
      const std::string key = "pp.comp_table_words." + what;
      auto entry = word.size() == 1 ? s.tables.addresses.find(word[0]) : s.tables.addresses.end();
      if (what != "length" && what != "radius")
        ok = (p.report_value(diags, key, "the words are `length` and `radius`"), false);
      else if (entry == s.tables.addresses.end() || entry->second.word_class != stdlib::WordClass::Dimension)
        ok = (p.report_value(diags, key, "must be an address of a dimension, such as Z or K"), false);
      else
        (what == "length" ? s.conventions.comp_length_word : s.conventions.comp_radius_word) = word[0];
    }
    if (s.conventions.comp_length_word || s.conventions.comp_radius_word) s.control.erase("G93");
  }

  Conventions& c = s.conventions;
  c.arc_centre = ArcCentre::Incremental;  // I, J from the start point (decision 17)
  c.centre_words = CentreWords::Plane;    // I along the first axis, J the second
  c.helix_lead = HelixLead::PerRevolution;
  c.dwell_word = 'Q';  // G04: Q in 10 ms units (dictionary)
  c.dwell_seconds_per_unit = 0.01;
  c.peck_word = 'I';  // decision 21
  c.cycle_level_word = 'K';
  c.tool_offset_axes = "Z";
  c.axes = "XYZ";
  for (char axis : kAxisLetters)
    if (s.axis_letters.find(axis) != std::string::npos) c.axes += axis;
  c.link_axes = std::string("XYZ") + s.axis_letters[0];  // '&': X Y Z 4. (decision 12)
  c.aux_words = "HP";
  c.feed_limits[1][0] = 1;  // the maximum block format: F(5) mm/min, F(2.3) mm/rev
  c.feed_limits[1][1] = 24000;
  c.feed_limits[2][0] = 0.001;
  c.feed_limits[2][1] = 99.999;
  c.diameter_axis = 'X';
  if (auto v = p.string("pp.diameter_axis", diags)) {
    if (v->size() == 1 && c.axes.find((*v)[0]) != std::string::npos)
      c.diameter_axis = (*v)[0];
    else
      ok = (p.report_value(diags, "pp.diameter_axis", fmt::format("must be one of the machine's axes {}", c.axes)),
            false);
  }
  c.max_call_depth = 8;  // decision 15
  if (auto v = p.number("pp.max_call_depth", diags)) {
    if (auto n = whole_in<uint8_t>(*v, 1, 32))
      c.max_call_depth = *n;
    else
      ok = (p.report_value(diags, "pp.max_call_depth", "must be a whole number from 1 to 32"), false);
  }
  if (!ok) return std::nullopt;
  return s;
}

}  // namespace ncc::pp
