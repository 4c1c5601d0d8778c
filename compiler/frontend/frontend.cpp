#include "frontend.h"

#include "gost/gost_frontend.h"

namespace ncc {

namespace {
struct DialectEntry {
  std::string_view name;
  std::unique_ptr<Frontend> (*make)(const stdlib::Profile&, Diagnostics&);
};
constexpr DialectEntry kDialects[] = {
    {"gost", gost::make_gost_frontend},
};
}  // namespace

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
