#include "settings.h"

#include <algorithm>
#include <tuple>

#include "frontend/frontend.h"
#include "support/text.h"

namespace ncc::nc110 {

namespace {

// "origin dim+", "[factor axis*]": the operand kinds of a code.
bool parse_signature(std::string_view text, std::vector<OperandItem>& out) {
  static const std::map<std::string_view, OperandKind> kKinds = {{"origin", OperandKind::Origin},
                                                                 {"axis", OperandKind::Axis},
                                                                 {"dim", OperandKind::Dim},
                                                                 {"pair", OperandKind::Pair},
                                                                 {"angle", OperandKind::Angle},
                                                                 {"factor", OperandKind::Factor},
                                                                 {"count", OperandKind::Count},
                                                                 {"program", OperandKind::Program},
                                                                 {"label", OperandKind::Label},
                                                                 {"comparand", OperandKind::Comparand},
                                                                 {"item", OperandKind::Item},
                                                                 {"seconds", OperandKind::Seconds},
                                                                 {"zone", OperandKind::Zone},
                                                                 {"turning", OperandKind::Turning},
                                                                 {"condition", OperandKind::Condition},
                                                                 {"mode", OperandKind::Mode},
                                                                 {"tool", OperandKind::Tool},
                                                                 {"corrector", OperandKind::Corrector},
                                                                 {"increment", OperandKind::Increment},
                                                                 {"distance", OperandKind::Distance},
                                                                 {"speed", OperandKind::Speed},
                                                                 {"virtual", OperandKind::Virtual},
                                                                 {"axes", OperandKind::Axes},
                                                                 {"value", OperandKind::Value},
                                                                 {"channel", OperandKind::Channel},
                                                                 {"structure", OperandKind::Structure},
                                                                 {"record", OperandKind::Record},
                                                                 {"records", OperandKind::Records},
                                                                 {"file", OperandKind::File},
                                                                 {"access", OperandKind::Access},
                                                                 {"binding", OperandKind::Binding},
                                                                 {"prompt", OperandKind::Prompt},
                                                                 {"target", OperandKind::Target},
                                                                 {"process", OperandKind::Process},
                                                                 {"wait", OperandKind::Wait},
                                                                 {"field", OperandKind::Field},
                                                                 {"row", OperandKind::Row},
                                                                 {"column", OperandKind::Column},
                                                                 {"format", OperandKind::Format},
                                                                 {"switch", OperandKind::Switch},
                                                                 {"attribute", OperandKind::Attribute}};
  bool group = false;
  size_t i = 0;
  while (i < text.size()) {
    if (text[i] == ' ') {
      ++i;
      continue;
    }
    if (text[i] == '[' || text[i] == ']') {
      if ((text[i] == '[') == group) return false;
      group = text[i] == '[';
      ++i;
      continue;
    }
    size_t end = text.find_first_of(" []?*+~", i);
    if (end == std::string_view::npos) end = text.size();
    auto it = kKinds.find(text.substr(i, end - i));
    if (it == kKinds.end()) return false;
    OperandItem item{it->second, '1', group};
    i = end;
    if (i < text.size() && (text[i] == '?' || text[i] == '*' || text[i] == '+' || text[i] == '~'))
      item.repeat = text[i++];
    out.push_back(item);
  }
  // Only the last item (of the signature or of its group) may repeat.
  for (size_t k = 0; k + 1 < out.size(); ++k)
    if ((out[k].repeat == '*' || out[k].repeat == '+') && out[k + 1].in_group == out[k].in_group) return false;
  return !group;
}

void read_codes(Settings& s, Diagnostics& diags) {
  auto table = stdlib::load_table("nc110", "three_letter_codes.tsv", 4, diags);
  if (!table) return;
  for (const stdlib::TableRow& row : table->rows) {
    const auto& c = row.cells;
    CodeSignature code;
    code.code = c[0];
    code.meaning = c[3];
    bool ok = c[0].size() == 3 && parse_signature(c[1], code.operands);
    std::string_view action = c[2];
    if (action.starts_with("@jump_if(") && action.ends_with(")")) {
      code.action = Action::JumpIf;
      code.comparison = std::string(action.substr(9, action.size() - 10));
      ok = ok && std::string_view("gt lt eq ne ge le").find(code.comparison) != std::string_view::npos &&
           code.comparison.size() == 2;
    } else if ((action.starts_with("@asset(") || action.starts_with("@screen(") || action.starts_with("@process(")) &&
               action.ends_with(")")) {
      static const std::map<std::string_view, std::pair<Action, Service>> kServices = {
          {"asset(open", {Action::Asset, Service::AssetOpen}},
          {"asset(define", {Action::Asset, Service::AssetDefine}},
          {"asset(read", {Action::Asset, Service::AssetRead}},
          {"asset(write", {Action::Asset, Service::AssetWrite}},
          {"asset(close", {Action::Asset, Service::AssetClose}},
          {"asset(create", {Action::Asset, Service::AssetCreate}},
          {"asset(delete", {Action::Asset, Service::AssetDelete}},
          {"screen(switch", {Action::Screen, Service::ScreenOn}},
          {"screen(define", {Action::Screen, Service::ScreenDefineValue}},
          {"screen(show", {Action::Screen, Service::ScreenShow}},
          {"process(start", {Action::Process, Service::ProcessStart}},
          {"process(release", {Action::Process, Service::ProcessRelease}},
          {"process(wait", {Action::Process, Service::ProcessWait}},
          {"process(signal", {Action::Process, Service::ProcessSignal}}};
      auto it = kServices.find(action.substr(1, action.size() - 2));
      ok = ok && it != kServices.end();
      if (it != kServices.end()) std::tie(code.action, code.service) = it->second;
    } else if (action.starts_with("@")) {
      static const std::map<std::string_view, Action> kActions = {
          {"@repeat", Action::Repeat}, {"@end_repeat", Action::EndRepeat},
          {"@call", Action::Call},     {"@call_range", Action::CallRange},
          {"@jump", Action::Jump},     {"@display", Action::Display},
          {"@input", Action::Input}};
      auto it = kActions.find(action);
      ok = ok && it != kActions.end();
      if (it != kActions.end()) code.action = it->second;
    } else {
      auto fn = fn_by_name(action);
      ok = ok && fn.has_value();
      code.fn = fn.value_or(Fn::Count);
    }
    if (!ok) {
      report(diags, *table, row.line, fmt::format("malformed code row '{}'", c[0]));
      continue;
    }
    s.codes[code.code] = std::move(code);
  }
}

void read_system(Settings& s, Diagnostics& diags) {
  auto table = stdlib::load_table("nc110", "system_variables.tsv", 5, diags);
  if (!table) return;
  for (const stdlib::TableRow& row : table->rows) {
    const auto& c = row.cells;
    SystemName n;
    n.name = c[0];
    bool ok = true;
    if (c[1] != "-") {
      n.var = sys_by_name(c[1]);
      ok = n.var.has_value();
    }
    if (c[2] != "-") {
      size_t dots = c[2].find("..");
      uint32_t lo = parse_number<uint32_t>(std::string_view(c[2]).substr(0, dots)).value_or(UINT32_MAX);
      uint32_t hi = dots == std::string::npos
                        ? UINT32_MAX
                        : parse_number<uint32_t>(std::string_view(c[2]).substr(dots + 2)).value_or(UINT32_MAX);
      ok = ok && hi != UINT32_MAX && lo <= hi && (!n.var || hi < sys_indices(*n.var));
      n.numbered = true;
      n.first = lo;
      n.last = hi;
    }
    n.value = c[3];
    ok = ok && std::string_view("BY IN LI RE LR flag expr -").find(n.value) != std::string_view::npos;
    if (!ok) {
      report(diags, *table, row.line, fmt::format("malformed system variable row '{}'", c[0]));
      continue;
    }
    s.system[n.name] = n;
  }
}

void read_classes(Settings& s, Diagnostics& diags) {
  auto table = stdlib::load_table("nc110", "parameters.tsv", 4, diags);
  if (!table) return;
  static const std::map<std::string_view, VarType> kTypes = {{"byte", VarType::Byte},
                                                             {"integer", VarType::Integer},
                                                             {"long", VarType::Long},
                                                             {"real", VarType::Real},
                                                             {"long_real", VarType::LongReal}};
  for (const stdlib::TableRow& row : table->rows) {
    const auto& c = row.cells;
    ParameterClass p;
    p.name = c[0];
    auto first = parse_number<uint32_t>(c[1]);
    auto type = kTypes.find(c[2]);
    bool ok = first && type != kTypes.end() && (s.classes.empty() || *first > s.classes.back().first);
    if (ok && c[3] != "-") {
      auto limit = parse_number<double>(c[3]);
      ok = limit && *limit > 0;
      p.limit = limit.value_or(0);
    }
    if (!ok) {
      report(diags, *table, row.line, "malformed parameter class row");
      continue;
    }
    p.first = *first;
    p.type = type->second;
    s.classes.push_back(p);
  }
}

void read_memories(Settings& s, Diagnostics& diags) {
  auto table = stdlib::load_table("nc110", "memories.tsv", 5, diags);
  if (!table) return;
  static const std::map<std::string_view, MemFormat> kFormats = {
      {"BL", MemFormat::Bit},  {"BY", MemFormat::Byte}, {"IN", MemFormat::Integer},
      {"LI", MemFormat::Long}, {"RE", MemFormat::Real}, {"LR", MemFormat::LongReal}};
  for (const stdlib::TableRow& row : table->rows) {
    const auto& c = row.cells;
    auto format = kFormats.find(c[1]);
    auto bytes = parse_number<uint32_t>(c[2]);
    if (format == kFormats.end() || !bytes || *bytes == 0 || (c[3] != "yes" && c[3] != "no")) {
      report(diags, *table, row.line, "malformed memory row");
      continue;
    }
    s.memories.push_back({c[0], format->second, *bytes, c[3] == "yes"});
  }
}

}  // namespace

const ParameterClass& Settings::class_of(uint32_t e) const {
  const ParameterClass* c = &classes.front();
  for (const ParameterClass& k : classes)
    if (k.first <= e) c = &k;
  return *c;
}

std::optional<Settings> load_settings(const stdlib::Profile& p, Diagnostics& diags) {
  Settings s;
  uint32_t errors = diags.error_count();
  s.tables = stdlib::load_dialect_tables("nc110", diags);
  diags.set_citations(s.tables.citations);
  read_codes(s, diags);
  read_system(s, diags);
  read_classes(s, diags);
  read_memories(s, diags);
  if (s.classes.empty() || diags.error_count() != errors) return std::nullopt;
  // Table 2.3 is "purely indicative": the machine logic adds or changes M codes (and
  // the NC-2xx/3xx add G codes of their own).
  bool ok = read_machine_codes(p, "nc110", "GM", s.tables, diags);
  // G codes of the machine's join or leave classes (Table 2.5): the class pairs anew.
  if (p.user_sets("nc110.tables.g_codes")) stdlib::add_class_pairs(s.tables);

  if (auto v = p.number("nc110.e_count", diags)) {
    if (auto n = whole_in<uint32_t>(*v, 1, 65536))
      s.e_count = *n;
    else
      ok = (p.report_value(diags, "nc110.e_count", "must be a whole number from 1 to 65536"), false);
  }
  if (auto sizes = p.number_table("nc110.memories", diags)) {
    for (const auto& [name, bytes] : *sizes) {
      auto it = std::ranges::find(s.memories, name, &Memory::name);
      if (it == s.memories.end()) {
        ok = (p.report_value(diags, "nc110.memories." + name, "is not a memory (SA, SK, SYVAR)"), false);
      } else if (auto n = whole_in<uint32_t>(bytes, 1, 1 << 20)) {
        it->bytes = *n;
      } else {
        ok = (p.report_value(diags, "nc110.memories." + name, "must be a whole number of bytes, 1 to 1048576"), false);
      }
    }
  }
  if (auto v = p.string("nc110.program_library", diags)) s.library = v->empty() ? "" : p.resolve_path(*v);
  if (auto v = p.string("nc110.default_device", diags)) {
    // As a CLS operand writes it (§2.13.2.2): 2 or 3 capitals and digits, a letter first.
    bool valid = v->size() >= 2 && v->size() <= 3 && std::isupper(static_cast<unsigned char>((*v)[0])) &&
                 std::all_of(v->begin(), v->end(), [](char ch) {
                   return std::isupper(static_cast<unsigned char>(ch)) || std::isdigit(static_cast<unsigned char>(ch));
                 });
    if (valid)
      s.default_device = *v;
    else
      ok = (p.report_value(diags, "nc110.default_device",
                           "must be a device name of 2 or 3 capitals and digits, a letter first (MP0)"),
            false);
  }
  if (auto v = p.string("nc110.mirror", diags)) {
    if (*v == "set" || *v == "toggle")
      s.conventions.mirror_toggles = *v == "toggle";
    else
      ok = (p.report_value(diags, "nc110.mirror", "must be set or toggle"), false);
  }

  // The power-on state: Table 2.2, then the codes the profile puts in their place.
  s.power_on = s.tables.power_on.count("default") ? s.tables.power_on.at("default") : std::vector<std::string>{};
  if (auto v = p.string("nc110.power_on", diags)) {
    size_t at = 0;
    while (at < v->size()) {
      size_t end = v->find(' ', at);
      if (end == std::string::npos) end = v->size();
      std::string code = v->substr(at, end - at);
      at = end + 1;
      if (code.empty()) continue;
      auto number =
          code.size() > 1 && code[0] == 'G' ? parse_number<uint32_t>(std::string_view(code).substr(1)) : std::nullopt;
      auto entry = number ? s.tables.g_codes.find(static_cast<int>(*number)) : s.tables.g_codes.end();
      if (entry == s.tables.g_codes.end()) {
        ok = (p.report_value(diags, "nc110.power_on", fmt::format("'{}' is not a G code of the NC-110", code)), false);
        continue;
      }
      // It replaces the code of its class.
      std::erase_if(s.power_on, [&](const std::string& other) {
        auto n = other.size() > 1 && other[0] == 'G' ? parse_number<uint32_t>(std::string_view(other).substr(1))
                                                     : std::nullopt;
        auto e = n ? s.tables.g_codes.find(static_cast<int>(*n)) : s.tables.g_codes.end();
        return e != s.tables.g_codes.end() && e->second.group == entry->second.group;
      });
      s.power_on.insert(s.power_on.begin(), code);
    }
  }

  Conventions& c = s.conventions;
  c.arc_centre = ArcCentre::Absolute;
  c.helix_lead = HelixLead::PerRevolution;
  c.centre_words = CentreWords::Plane;
  c.radius_word = 'R';
  c.dwell_word = 0;
  c.peck_word = 'I';
  c.peck_factor_word = 'K';
  c.peck_minimum_word = 'J';
  c.tap_pitch_word = 'K';
  c.cycle_level_word = 'R';
  c.cycle_two_levels = true;
  c.cycle_defines_only = true;
  c.cycle_needs_cancel = true;
  c.pitch_change_word = 'I';
  c.corrector_in_tool_word = true;
  c.cutter = CutterStyle::Nc110;  // §2.8.7: the trace shows the tool centre's path
  c.max_call_depth = 2;
  c.result_space = 0;  // E
  c.arc_tolerance = 0.01;
  c.lead_resolution = 0.0001;
  if (auto v = p.number("nc110.arc_tolerance", diags)) {
    if (*v >= 0)
      c.arc_tolerance = *v;
    else
      ok = (p.report_value(diags, "nc110.arc_tolerance", "must not be negative"), false);
  }
  c.axes = "XYZABCUVW";
  if (auto v = p.string("nc110.axes", diags)) {
    std::string axes;
    for (char axis : kAxisLetters)
      if (v->find(axis) != std::string::npos) axes += axis;
    bool valid = !v->empty();
    for (char axis : *v) valid = valid && kAxisLetters.find(axis) != std::string_view::npos;
    if (valid)
      c.axes = axes;
    else
      ok = (p.report_value(diags, "nc110.axes", "must list axis letters of X Y Z A B C U V W P Q D"), false);
  }
  if (auto v = p.string("nc110.tool_offset_axes", diags)) {
    bool valid = !v->empty();
    for (size_t i = 0; i < v->size(); ++i)
      valid = valid && c.axes.find((*v)[i]) != std::string::npos && v->find((*v)[i], i + 1) == std::string::npos;
    if (valid)
      c.tool_offset_axes = *v;
    else
      ok = (p.report_value(diags, "nc110.tool_offset_axes",
                           fmt::format("must list axes of the machine ({}), each once", c.axes)),
            false);
  }
  if (!ok) return std::nullopt;
  return s;
}

}  // namespace ncc::nc110
