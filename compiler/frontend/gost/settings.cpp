#include "settings.h"

#include <cmath>

#include "frontend/frontend.h"

namespace ncc::gost {

namespace {

// Reads `key` as one of `choices`; reports anything else.
template <typename E>
bool choose(const stdlib::Profile& p, const std::string& key,
            std::initializer_list<std::pair<std::string_view, E>> choices, E& out, Diagnostics& diags) {
  auto v = p.string(key, diags);
  if (!v) return true;
  std::string names;
  for (const auto& [name, value] : choices) {
    if (*v == name) {
      out = value;
      return true;
    }
    names += names.empty() ? std::string(name) : " | " + std::string(name);
  }
  p.report_value(diags, key, fmt::format("must be one of {}", names));
  return false;
}

// An address setting: one letter the format describes, or "" for none. A default
// the user's format lacks means "none": that function is not available.
bool address(const stdlib::Profile& p, const std::string& key, const Format& format, char& out, Diagnostics& diags) {
  auto v = p.string(key, diags);
  if (!v) return true;
  out = 0;
  if (v->empty()) return true;
  if (v->size() == 1 && format.word((*v)[0])) {
    out = (*v)[0];
    return true;
  }
  if (!p.user_sets(key)) return true;
  p.report_value(diags, key, "must be an address letter of the format descriptor, or \"\" for none");
  return false;
}

void set_code(stdlib::DialectTables& t, int number, std::string group, Scope scope, std::vector<FnCall> calls,
              std::string meaning) {
  stdlib::CodeEntry& e = t.g_codes[number];
  e.letter = 'G';
  e.number = number;
  e.group = std::move(group);
  e.desc.name = fmt::format("G{:02}", number);
  e.desc.scope = scope;
  e.desc.calls = std::move(calls);
  if (!meaning.empty()) e.meaning = std::move(meaning);
}

}  // namespace

std::optional<Settings> load_settings(const stdlib::Profile& p, Diagnostics& diags) {
  Settings s;
  s.tables = stdlib::load_dialect_tables("gost", diags);
  diags.set_citations(s.tables.citations);
  bool ok = !diags.has_errors();

  // The format descriptor: inline, or the first non-comment line of a .fmt file.
  std::string format_text;
  std::string format_key = "gost.format";
  if (auto file = p.string("gost.format_file", diags); file && !file->empty()) {
    format_key = "gost.format_file";
    std::string path;
    auto text = p.file_text(format_key, *file, path, diags);
    if (!text) return std::nullopt;
    format_text = std::string(format_line_of_file(*text));
  } else if (auto text = p.string("gost.format", diags)) {
    format_text = *text;
  }
  std::vector<FormatProblem> problems;
  auto format = parse_format(format_text, problems);
  for (const FormatProblem& problem : problems) {
    if (problem.error)
      diags.report(DiagId::FormatInvalid, p.range_of(format_key), problem.item, problem.message);
    else
      diags.report(DiagId::FormatAmbiguous, p.range_of(format_key), problem.item, problem.message);
  }
  if (!format) return std::nullopt;
  s.format = std::move(*format);
  s.decode.decimal_sign = s.format.decimal_sign;

  bool implied = false;
  ok &= choose(p, "gost.ds_integer_rule", {{"standard", false}, {"implied", true}}, implied, diags);
  s.decode.ds_implied = implied;
  ok &= choose(
      p, "gost.mode",
      {{"strict", Mode::Strict}, {"default", Mode::Default}, {"lenient", Mode::Lenient}, {"pedantic", Mode::Pedantic}},
      s.decode.mode, diags);
  if (auto v = p.string("machine.control_type", diags)) {
    if (s.tables.power_on.count(*v))
      s.control_type = *v;
    else
      ok &= (p.report_value(diags, "machine.control_type", "must be positioning, contouring or lathe"), false);
  }

  Conventions& c = s.conventions;
  ok &= choose(p, "gost.angle_unit",
               {{"deg", AngleUnit::Degree}, {"rad", AngleUnit::Radian}, {"rev", AngleUnit::Revolution}}, c.angle_unit,
               diags);
  ok &= choose(p, "gost.arc_center", {{"incremental", ArcCentre::Incremental}, {"absolute", ArcCentre::Absolute}},
               c.arc_centre, diags);
  ok &= choose(p, "gost.helix_lead_per", {{"radian", HelixLead::PerRadian}, {"revolution", HelixLead::PerRevolution}},
               c.helix_lead, diags);
  ok &= choose(p, "gost.parabola_ijk",
               {{"coordinates", ParabolaTangent::Coordinates}, {"incremental", ParabolaTangent::Incremental}},
               c.parabola_tangent, diags);
  ok &= address(p, "gost.dwell_address", s.format, c.dwell_word, diags);
  ok &= address(p, "gost.peck_address", s.format, c.peck_word, diags);
  ok &= address(p, "gost.thread_pitch_change_address", s.format, c.pitch_change_word, diags);
  if (auto v = p.boolean("gost.thread_allow_j", diags)) c.thread_allow_j = *v;
  if (auto v = p.boolean("gost.arc_single_quadrant", diags)) c.arc_single_quadrant = *v;
  if (auto v = p.boolean("gost.m06_stops_spindle", diags)) c.m06_stops_spindle = *v;
  if (auto v = p.number("gost.arc_tolerance", diags)) {
    if (*v >= 0)
      c.arc_tolerance = *v;
    else
      ok &= (p.report_value(diags, "gost.arc_tolerance", "must not be negative"), false);
  }
  if (auto v = p.string("gost.tool_offset_axes", diags)) {
    for (char axis : *v)
      if (std::string_view("XYZUVW").find(axis) == std::string_view::npos) {
        ok &= (p.report_value(diags, "gost.tool_offset_axes", "must list linear axes, e.g. \"Z\""), false);
        break;
      }
    c.tool_offset_axes = *v;
  }
  c.axes.clear();
  for (char axis : std::string_view("XYZABCUVW"))
    if (s.format.word(axis)) c.axes += axis;
  c.cycle_level_word = s.format.word('R') ? 'R' : 0;
  for (char letter : {'I', 'J', 'K'})
    if (const WordFormat* w = s.format.word(letter))
      c.lead_resolution = std::max(c.lead_resolution, std::pow(10.0, -w->frac_digits));

  if (auto split = p.numbers("gost.tool_word_split", diags)) {
    const WordFormat* t = s.format.word('T');
    const auto tool = split->size() == 2 ? whole_in((*split)[0], 1, 9) : std::nullopt;
    const auto offset = split->size() == 2 ? whole_in((*split)[1], 1, 9) : std::nullopt;
    if (tool && offset && t && *tool + *offset == t->int_digits) {
      s.tool_digits = *tool;
      s.offset_digits = *offset;
    } else if (!split->empty()) {
      ok &= (p.report_value(diags, "gost.tool_word_split",
                            "must be [tool digits, offset digits] adding up to the digits of T in the format"),
             false);
    }
  }

  // Table 4 note 2: G04 alone in its block, or a member of group a.
  std::string g04 = "block_only";
  ok &= choose(p, "gost.g04_mode",
               {{"block_only", std::string("block_only")},
                {"group_a", std::string("group_a")},
                {"own_group", std::string("own_group")}},
               g04, diags);
  if (g04 == "group_a") set_code(s.tables, 4, "a", Scope::Modal, {{Fn::MotionDwell}}, "");
  if (g04 == "own_group") set_code(s.tables, 4, "g04", Scope::Block, {{Fn::Dwell}}, "");

  // Table 4 notes 3-4: G43/G44 in group d with G40-G42, or in a group of their own;
  // acting until cancelled or in their block only.
  std::string group = "d", persistence = "modal";
  ok &= choose(p, "gost.g43_g44.group", {{"d", std::string("d")}, {"own", std::string("own")}}, group, diags);
  ok &= choose(p, "gost.g43_g44.persistence", {{"modal", std::string("modal")}, {"block", std::string("block")}},
               persistence, diags);
  Scope length_scope = persistence == "block" ? Scope::Block : Scope::Modal;
  if (group == "own") {
    set_code(s.tables, 41, "d", Scope::Modal, {{Fn::CompLeft}}, "");
    set_code(s.tables, 42, "d", Scope::Modal, {{Fn::CompRight}}, "");
    set_code(s.tables, 43, "g43", length_scope, {{Fn::LengthPlus}}, "");
    set_code(s.tables, 44, "g43", length_scope, {{Fn::LengthMinus}}, "");
  } else {
    s.tables.g_codes[43].desc.scope = length_scope;
    s.tables.g_codes[44].desc.scope = length_scope;
  }

  // §3.2.2: inches need a G code the standard does not number.
  if (auto codes = p.string_table("gost.unit_codes", diags)) {
    for (const auto& [code, unit] : *codes) {
      int number = -1;
      auto digit = [](char ch) { return ch >= '0' && ch <= '9'; };
      if (code.size() == 3 && code[0] == 'G' && digit(code[1]) && digit(code[2]))
        number = (code[1] - '0') * 10 + (code[2] - '0');
      if (number < 0 || (unit != "mm" && unit != "inch")) {
        ok &= (p.report_value(diags, "gost.unit_codes", "maps codes like G71 to \"mm\" or \"inch\""), false);
        continue;
      }
      if (s.tables.g_codes.count(number) && s.tables.g_codes[number].group != "u") {
        ok &= (p.report_value(diags, "gost.unit_codes", fmt::format("{} is already defined by Table 4", code)), false);
        continue;
      }
      set_code(s.tables, number, "u", Scope::Modal, {{unit == "mm" ? Fn::UnitsMm : Fn::UnitsInch}},
               unit == "mm" ? "Dimensions in millimetres" : "Dimensions in inches");
    }
  }

  // A machine builder's own codes (Table 4 note 1, Table 7 note 1).
  ok &= read_machine_codes(p, "gost", "GM", s.tables, diags);
  if (!ok) return std::nullopt;
  return s;
}

}  // namespace ncc::gost
