#include "sim/regime.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "stdlib/embedded.h"
#include "stdlib/tables.h"
#include "support/diagnostics.h"
#include "support/text.h"

namespace ncc::sim {
namespace {

constexpr std::string_view kTablePath = "cutting_data.tsv";

// Keys compare without case, '-' standing for '_' ("Carbide-Endmill").
std::string normal_key(std::string_view key) {
  std::string out;
  for (char c : key) out += c == '-' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

template <typename T>
const T* find_key(const std::vector<T>& list, std::string_view key) {
  const std::string k = normal_key(key);
  for (const T& item : list)
    if (normal_key(item.key) == k) return &item;
  return nullptr;
}

std::optional<double> positive(std::string_view cell) {
  auto v = parse_number<double>(cell);
  if (!v || !std::isfinite(*v) || *v <= 0) return std::nullopt;
  return v;
}

double lerp(double a, double b, double t) { return a + (b - a) * t; }

}  // namespace

const CuttingMaterial* CuttingTable::material(std::string_view key) const { return find_key(materials, key); }
const ToolKind* CuttingTable::tool(std::string_view key) const { return find_key(tools, key); }
const CuttingSource* CuttingTable::source(std::string_view key) const { return find_key(sources, key); }

std::vector<const CuttingRow*> CuttingTable::rows_for(std::string_view tool_key, std::string_view material_key) const {
  std::vector<const CuttingRow*> out;
  const std::string t = normal_key(tool_key), m = normal_key(material_key);
  for (const CuttingRow& r : rows)
    if (r.tool == t && r.material == m) out.push_back(&r);
  return out;
}

std::optional<Reference> CuttingTable::reference(std::string_view tool_key, std::string_view material_key,
                                                 double d) const {
  const std::vector<const CuttingRow*> list = rows_for(tool_key, material_key);
  if (list.empty()) return std::nullopt;
  Reference ref;
  auto take = [&](const CuttingRow& r) {
    ref.vc_min = r.vc_min, ref.vc_max = r.vc_max;
    ref.has_feed = r.has_feed;
    ref.f_min = r.f_min, ref.f_max = r.f_max;
    ref.source = r.source;
  };
  for (const CuttingRow* r : list)
    if (r->d_min <= d && d <= r->d_max) {
      ref.below = r;
      take(*r);
      return ref;
    }
  const CuttingRow *below = nullptr, *above = nullptr;
  for (const CuttingRow* r : list) {
    if (r->d_max < d && (!below || r->d_max > below->d_max)) below = r;
    if (r->d_min > d && (!above || r->d_min < above->d_min)) above = r;
  }
  if (below && above) {
    // Linear in D between the upper end of the row below and the lower end of the one above.
    const double t = (d - below->d_max) / (above->d_min - below->d_max);
    ref.how = Reference::How::Interpolated;
    ref.below = below, ref.above = above;
    ref.vc_min = lerp(below->vc_min, above->vc_min, t);
    ref.vc_max = lerp(below->vc_max, above->vc_max, t);
    ref.has_feed = below->has_feed && above->has_feed;
    if (ref.has_feed) {
      ref.f_min = lerp(below->f_min, above->f_min, t);
      ref.f_max = lerp(below->f_max, above->f_max, t);
    }
    ref.source = below->source == above->source ? below->source : below->source + "/" + above->source;
    return ref;
  }
  ref.how = Reference::How::Nearest;
  ref.below = below ? below : above;
  take(*ref.below);
  return ref;
}

CuttingTable parse_cutting_table(std::string_view name, std::string_view text, std::vector<std::string>& errors) {
  Diagnostics diags;
  const stdlib::Table table = stdlib::parse_table(std::string(name), text, 3, diags, 11);
  std::vector<std::pair<uint32_t, std::string>> problems;  // by line, at the end
  for (const Diagnostic& d : diags.all()) {
    // "dialect table: NAME:LINE: what": the table is not a dialect's.
    std::string_view m = d.message;
    if (size_t at = m.find(std::string(name) + ":"); at != std::string_view::npos) m.remove_prefix(at);
    const size_t colon = m.find(':', name.size() + 1);
    problems.emplace_back(parse_number<uint32_t>(m.substr(name.size() + 1, colon - name.size() - 1)).value_or(0), m);
  }
  auto problem = [&](uint32_t line, std::string_view what) {
    problems.emplace_back(line, fmt::format("{}:{}: {}", name, line, what));
  };

  CuttingTable out;
  for (const stdlib::TableRow& row : table.rows) {
    const std::vector<std::string>& c = row.cells;
    const std::string& kind = c[0];
    auto duplicate = [&](const auto& list, const std::string& key) {
      if (!find_key(list, key)) return false;
      problem(row.line, fmt::format("{} '{}' is defined twice", kind, key));
      return true;
    };
    if (kind == "material" || kind == "source") {
      if (c.size() != 3) {
        problem(row.line, fmt::format("a {} row is: {} KEY \"text\"", kind, kind));
      } else if (kind == "material" && !duplicate(out.materials, c[1])) {
        out.materials.push_back({normal_key(c[1]), c[2]});
      } else if (kind == "source" && !duplicate(out.sources, c[1])) {
        out.sources.push_back({c[1], c[2]});
      }
    } else if (kind == "tool") {
      if (c.size() != 4 || (c[2] != "per_tooth" && c[2] != "per_rev")) {
        problem(row.line, "a tool row is: tool KEY per_tooth|per_rev \"text\"");
      } else if (!duplicate(out.tools, c[1])) {
        out.tools.push_back({normal_key(c[1]), c[2] == "per_tooth" ? FeedPer::Tooth : FeedPer::Revolution, c[3]});
      }
    } else if (kind == "cut") {
      if (c.size() < 10) {
        problem(row.line, "a cut row is: cut TOOL MATERIAL D_MIN D_MAX VC_MIN VC_MAX F_MIN F_MAX SOURCE [\"note\"]");
        continue;
      }
      CuttingRow r;
      r.tool = normal_key(c[1]), r.material = normal_key(c[2]);
      r.line = row.line;
      r.source = c[9];
      if (c.size() == 11) r.note = c[10];
      auto d_min = c[3] == "-" ? std::optional<double>(0) : parse_number<double>(c[3]);
      auto d_max = c[4] == "-" ? std::optional<double>(std::numeric_limits<double>::infinity()) : positive(c[4]);
      auto vc_min = positive(c[5]), vc_max = positive(c[6]);
      std::string what;
      if (!d_min || !d_max || !std::isfinite(*d_min) || *d_min < 0 || *d_min > *d_max)
        what = "the diameters must be D_MIN <= D_MAX, not negative (\"-\": no bound)";
      else if (!vc_min || !vc_max || *vc_min > *vc_max)
        what = "the cutting speeds must be positive, VC_MIN <= VC_MAX";
      if (what.empty() && (c[7] != "-" || c[8] != "-")) {
        auto f_min = positive(c[7]), f_max = positive(c[8]);
        if (!f_min || !f_max || *f_min > *f_max)
          what = "the feeds must be positive, F_MIN <= F_MAX (or both \"-\")";
        else
          r.has_feed = true, r.f_min = *f_min, r.f_max = *f_max;
      }
      if (!what.empty()) {
        problem(row.line, what);
        continue;
      }
      r.d_min = *d_min, r.d_max = *d_max, r.vc_min = *vc_min, r.vc_max = *vc_max;
      out.rows.push_back(std::move(r));
    } else {
      problem(row.line, fmt::format("unknown row kind '{}' (material, tool, source, cut)", kind));
    }
  }

  // Every key a row names is defined; a pair's rows do not overlap in diameter.
  std::erase_if(out.rows, [&](const CuttingRow& r) {
    std::string what;
    if (!out.tool(r.tool))
      what = fmt::format("unknown tool kind '{}'", r.tool);
    else if (!out.material(r.material))
      what = fmt::format("unknown material '{}'", r.material);
    else if (!out.source(r.source))
      what = fmt::format("unknown source '{}'", r.source);
    if (!what.empty()) problem(r.line, what);
    return !what.empty();
  });
  for (const CuttingRow& r : out.rows)
    for (const CuttingRow& s : out.rows)
      if (&s != &r && s.line > r.line && s.tool == r.tool && s.material == r.material &&
          std::max(r.d_min, s.d_min) < std::min(r.d_max, s.d_max))
        problem(s.line, fmt::format("its diameters overlap the row on line {}", r.line));
  std::stable_sort(problems.begin(), problems.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [line, message] : problems) errors.push_back(std::move(message));
  return out;
}

CuttingTable load_cutting_table(std::vector<std::string>& errors) {
  auto text = stdlib::embedded_file(kTablePath);
  if (!text) {
    errors.push_back(fmt::format("missing table {}", kTablePath));
    return {};
  }
  return parse_cutting_table(kTablePath, *text, errors);
}

double spindle_speed(double vc, double diameter) { return 1000.0 * vc / (std::numbers::pi * diameter); }
double cutting_speed(double rpm, double diameter) { return std::numbers::pi * diameter * rpm / 1000.0; }
double feed_rate(double feed, int teeth, double rpm) { return feed * teeth * rpm; }

Regime compute_regime(const RegimeInput& in) {
  Regime r;
  r.rpm_wanted = r.rpm = spindle_speed(in.vc, in.diameter);
  if (in.max_rpm > 0 && r.rpm > in.max_rpm) {
    r.rpm = in.max_rpm;
    r.rpm_clamped = true;
  }
  r.vc = cutting_speed(r.rpm, in.diameter);
  // The feed per tooth stays; the feed follows the spindle.
  r.feed_wanted = r.feed_rate = feed_rate(in.feed, in.teeth, r.rpm);
  r.feed = in.feed;
  if (in.max_feed > 0 && r.feed_rate > in.max_feed) {
    r.feed_rate = in.max_feed;
    r.feed = in.max_feed / (in.teeth * r.rpm);
    r.feed_clamped = true;
  }
  return r;
}

BlockWords block_words(const Regime& r, const RegimeInput& in, bool inch) {
  BlockWords w;
  w.s = std::max(1L, std::lround(r.rpm));
  if (in.max_rpm > 0) w.s = std::min(w.s, std::max(1L, static_cast<long>(std::floor(in.max_rpm + 1e-9))));
  const double mm_per_min = feed_rate(r.feed, in.teeth, static_cast<double>(w.s));
  if (inch) {
    w.f = std::round(mm_per_min / 25.4 * 10) / 10;
    if (in.max_feed > 0) w.f = std::min(w.f, std::floor(in.max_feed / 25.4 * 10 + 1e-9) / 10);
    w.text = fmt::format("S{} M3 F{:.1f}", w.s, w.f);
  } else {
    w.f = std::round(mm_per_min);
    if (in.max_feed > 0) w.f = std::min(w.f, std::floor(in.max_feed + 1e-9));
    w.text = fmt::format("S{} M3 F{:.0f}", w.s, w.f);
  }
  return w;
}

}  // namespace ncc::sim
