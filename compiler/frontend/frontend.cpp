#include "frontend.h"

#include "gost/gost_frontend.h"
#include "nc110/nc110_frontend.h"

namespace ncc {

namespace {
struct DialectEntry {
  std::string_view name;
  std::unique_ptr<Frontend> (*make)(const stdlib::Profile&, Diagnostics&);
};
constexpr DialectEntry kDialects[] = {
    {"gost", gost::make_gost_frontend},
    {"nc110", nc110::make_nc110_frontend},
};
}  // namespace

void set_power_on(ir::Program& program, const stdlib::DialectTables& tables, const std::vector<std::string>& tokens) {
  auto& codes = program.semantics.codes;
  for (const std::string& token : tokens) {
    CodeDesc desc;
    if (token.size() > 1 && token[0] == 'G') {
      auto it = tables.g_codes.find(std::stoi(token.substr(1)));
      if (it == tables.g_codes.end()) continue;
      desc = it->second.desc;
    } else {
      desc.name = token;
      std::string error;
      stdlib::parse_functions(token, tables.cycles, desc.calls, error);
    }
    uint16_t index = 0;
    while (index < codes.size() && !(codes[index].name == desc.name && codes[index].calls == desc.calls)) ++index;
    if (index == codes.size()) codes.push_back(desc);
    program.semantics.power_on.push_back(index);
  }
}

std::vector<std::string_view> dialect_names() {
  std::vector<std::string_view> names;
  for (const DialectEntry& d : kDialects) names.push_back(d.name);
  return names;
}

std::unique_ptr<Frontend> make_frontend(std::string_view dialect, const stdlib::Profile& profile, Diagnostics& diags) {
  for (const DialectEntry& d : kDialects)
    if (d.name == dialect) return d.make(profile, diags);
  std::string known;
  for (const DialectEntry& d : kDialects) known += (known.empty() ? "" : ", ") + std::string(d.name);
  diags.report(DiagId::DialectUnknown, {}, fmt::format("unknown dialect '{}' (known: {})", dialect, known));
  return nullptr;
}

}  // namespace ncc
