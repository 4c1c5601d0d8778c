#include "profile.h"

#include <toml++/toml.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>

#include "embedded.h"
#include "support/numbers.h"
#include "support/text.h"

namespace ncc::stdlib {

struct Profile::Impl {
  toml::table table;
  uint32_t file = 0;     // SourceManager index
  bool builtin = false;  // the files it names are built in too (stdlib/profiles/)
};

struct Profile::Lookup {
  const toml::node* node = nullptr;
  const Impl* owner = nullptr;
};

namespace {

SourceRange region_range(const toml::source_region& r, uint32_t file) {
  return {file, r.begin.line, r.begin.column, r.end.line, r.end.column};
}

std::shared_ptr<const Profile::Impl> parse_toml(SourceManager& sources, const std::string& name,
                                                const std::string& text, Diagnostics& diags, bool builtin = false) {
  uint32_t file = sources.add(name, text);
  try {
    auto impl = std::make_shared<Profile::Impl>();
    impl->table = toml::parse(text, name);
    impl->file = file;
    impl->builtin = builtin;
    return impl;
  } catch (const toml::parse_error& e) {
    diags.report(DiagId::ProfileSyntax, region_range(e.source(), file), std::string(e.description()));
    return nullptr;
  }
}

void collect_leaves(const toml::table& t, const std::string& prefix, std::vector<std::string>& out) {
  for (const auto& [k, v] : t) {
    std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const toml::table* sub = v.as_table(); sub && !sub->is_inline())
      collect_leaves(*sub, key, out);
    else
      out.push_back(key);
  }
}

constexpr std::string_view kBuiltinDir = "profiles/";

// A built-in machine's profile text ("haas": profiles/haas.toml).
std::optional<std::string_view> builtin_profile_text(std::string_view name) {
  if (name.empty() || name.find('/') != std::string_view::npos) return std::nullopt;
  return embedded_file(std::string(kBuiltinDir) + std::string(name) + ".toml");
}

// --machine haas: a name without a path separator or .toml.
bool names_builtin(std::string_view path) {
  return !path.empty() && path.find('/') == std::string_view::npos && !path.ends_with(".toml");
}

}  // namespace

std::vector<std::string> builtin_machines() {
  std::vector<std::string> names;
  for (const EmbeddedFile& f : embedded_files())
    if (f.path.starts_with(kBuiltinDir) && f.path.ends_with(".toml") &&
        f.path.find('/', kBuiltinDir.size()) == std::string_view::npos)
      names.emplace_back(f.path.substr(kBuiltinDir.size(), f.path.size() - kBuiltinDir.size() - 5));
  return names;
}

namespace {

std::string machine_list() {
  std::string list;
  for (const std::string& name : builtin_machines()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

}  // namespace

std::optional<Profile> Profile::parse(SourceManager& sources, std::string name, std::string text, Diagnostics& diags) {
  Profile p;
  auto builtin_text = embedded_file("profiles/default.toml");
  p.builtin_ = parse_toml(sources, "<builtin>/default.toml", std::string(*builtin_text), diags);
  if (!p.builtin_) return std::nullopt;
  p.name_ = name.empty() ? "default" : name;
  if (!text.empty()) {
    p.user_ = parse_toml(sources, name, text, diags);
    if (!p.user_) return std::nullopt;
    p.text_ = std::move(text);
    p.dir_ = std::filesystem::path(name).parent_path().string();
    // machine.base: a built-in machine this profile changes (the default's settings
    // still fill in what neither gives).
    if (auto base = p.string("machine.base", diags); base && *base != "default") {
      auto base_text = builtin_profile_text(*base);
      if (!base_text) {
        p.report_value(diags, "machine.base", fmt::format("names no built-in machine (built in: {})", machine_list()));
        return std::nullopt;
      }
      p.base_ = parse_toml(sources, fmt::format("<builtin>/{}.toml", *base), std::string(*base_text), diags, true);
      if (!p.base_) return std::nullopt;
    }
  }
  return p;
}

std::optional<Profile> Profile::load(SourceManager& sources, const std::string& path, Diagnostics& diags) {
  if (path.empty() || path == "default") return parse(sources, "", "", diags);
  // A built-in machine is the profile that only names it as its base: what a bytecode
  // file stores of it. A name that is none is a file's.
  if (names_builtin(path) && builtin_profile_text(path))
    return parse(sources, path, fmt::format("[machine]\nbase = \"{}\"\n", path), diags);
  auto read = read_file(path, kProfileFile, diags);
  if (!read) return std::nullopt;
  std::string text = std::move(*read);
  if (text.empty()) text = "\n";  // an empty profile is valid: everything is the default
  return parse(sources, path, std::move(text), diags);
}

std::string Profile::resolve_path(std::string_view relative) const {
  std::filesystem::path p(relative);
  if (p.is_absolute() || dir_.empty()) return p.string();
  return (std::filesystem::path(dir_) / p).string();
}

std::optional<std::string> Profile::file_text(std::string_view key, const std::string& file, std::string& path,
                                              Diagnostics& diags) const {
  if (const Lookup l = find(key); l.owner && l.owner->builtin) {  // a built-in machine's own file
    path = "<builtin>/" + file;
    auto text = embedded_file(std::string(kBuiltinDir) + file);
    if (!text) report_value(diags, key, "names a file that is not built in");
    return text ? std::optional<std::string>(*text) : std::nullopt;
  }
  path = resolve_path(file);
  int error = 0;
  auto text = read_file(path, kProfileFile, error);
  if (!text) report_value(diags, key, "names a file that cannot be read: " + read_error(error, kProfileFile));
  return text;
}

Profile::Lookup Profile::find(std::string_view key) const {
  used_.emplace(key);
  toml::path path{key};
  for (const auto* layer : {&user_, &base_})
    if (*layer) {
      toml::node_view<const toml::node> v = (*layer)->table.at_path(path);
      if (v) return {v.node(), layer->get()};
    }
  toml::node_view<const toml::node> v = builtin_->table.at_path(path);
  return {v.node(), builtin_.get()};
}

SourceRange Profile::range_of(std::string_view key) const {
  Lookup l = find(key);
  return l.node ? region_range(l.node->source(), l.owner->file) : SourceRange{};
}

bool Profile::user_sets(std::string_view key) const {
  return user_ && user_->table.at_path(toml::path{key}).node() != nullptr;
}

void Profile::report_value(Diagnostics& diags, std::string_view key, std::string_view message) const {
  diags.report(DiagId::ProfileValue, range_of(key), fmt::format("'{}' {}", key, message));
}

std::optional<std::string> Profile::string(std::string_view key, Diagnostics& diags) const {
  Lookup l = find(key);
  if (!l.node) return std::nullopt;
  if (l.node->is_string()) return *l.node->value<std::string>();
  report_value(diags, key, "must be a string");
  return std::nullopt;
}

std::optional<double> Profile::number(std::string_view key, Diagnostics& diags) const {
  Lookup l = find(key);
  if (!l.node) return std::nullopt;
  if (l.node->is_number() && std::isfinite(*l.node->value<double>())) return l.node->value<double>();
  report_value(diags, key, "must be a finite number");
  return std::nullopt;
}

std::optional<bool> Profile::boolean(std::string_view key, Diagnostics& diags) const {
  Lookup l = find(key);
  if (!l.node) return std::nullopt;
  if (l.node->is_boolean()) return *l.node->value<bool>();
  report_value(diags, key, "must be true or false");
  return std::nullopt;
}

std::optional<std::vector<double>> Profile::numbers(std::string_view key, Diagnostics& diags) const {
  Lookup l = find(key);
  if (!l.node) return std::nullopt;
  const toml::array* a = l.node->as_array();
  std::vector<double> out;
  if (a)
    for (const toml::node& n : *a) {
      if (!n.is_number() || !std::isfinite(*n.value<double>())) {
        a = nullptr;
        break;
      }
      out.push_back(*n.value<double>());
    }
  if (!a) {
    report_value(diags, key, "must be an array of finite numbers");
    return std::nullopt;
  }
  return out;
}

std::optional<std::map<std::string, double>> Profile::number_table(std::string_view key, Diagnostics& diags) const {
  Lookup l = find(key);
  if (!l.node) return std::nullopt;
  const toml::table* t = l.node->as_table();
  std::map<std::string, double> out;
  if (t)
    for (const auto& [k, v] : *t) {
      if (!v.is_number() || !std::isfinite(*v.value<double>())) {
        t = nullptr;
        break;
      }
      out[std::string(k.str())] = *v.value<double>();
    }
  if (!t) {
    report_value(diags, key, "must be a table of finite numbers, e.g. { X = 0.0, Y = 0.0 }");
    return std::nullopt;
  }
  return out;
}

std::optional<std::map<std::string, std::string>> Profile::string_table(std::string_view key,
                                                                        Diagnostics& diags) const {
  Lookup l = find(key);
  if (!l.node) return std::nullopt;
  const toml::table* t = l.node->as_table();
  std::map<std::string, std::string> out;
  if (t)
    for (const auto& [k, v] : *t) {
      if (!v.is_string()) {
        t = nullptr;
        break;
      }
      out[std::string(k.str())] = *v.value<std::string>();
    }
  if (!t) {
    report_value(diags, key, "must be a table of strings");
    return std::nullopt;
  }
  return out;
}

size_t Profile::array_size(std::string_view key, Diagnostics& diags) const {
  Lookup l = find(key);
  if (!l.node) return 0;
  if (const toml::array* a = l.node->as_array()) return a->size();
  report_value(diags, key, "must be an array");
  return 0;
}

bool Profile::is_string(std::string_view key) const {
  Lookup l = find(key);
  return l.node && l.node->is_string();
}

std::vector<std::string> Profile::keys(std::string_view table) const {
  used_.emplace(table);
  Lookup l = find(table);
  std::vector<std::string> out;
  if (const toml::table* t = l.node ? l.node->as_table() : nullptr)
    for (const auto& [k, v] : *t) {
      out.emplace_back(k.str());
      used_.insert(std::string(table) + "." + std::string(k.str()));
    }
  return out;
}

void Profile::report_unused(Diagnostics& diags, const std::vector<std::string_view>& others) const {
  if (!user_) return;
  std::vector<std::string> leaves;
  collect_leaves(user_->table, "", leaves);
  for (const std::string& key : leaves) {
    if (std::find(others.begin(), others.end(), std::string_view(key).substr(0, key.find('.'))) != others.end())
      continue;
    // A key is used if it, a table holding it, or a key inside it was looked up.
    auto child = used_.lower_bound(key + ".");
    bool used = child != used_.end() && child->compare(0, key.size() + 1, key + ".") == 0;
    for (std::string k = key; !used; k = k.substr(0, k.rfind('.'))) {
      used = used_.count(k) > 0;
      if (k.find('.') == std::string::npos) break;
    }
    if (!used) {
      toml::node_view<const toml::node> v = user_->table.at_path(toml::path{key});
      SourceRange range = v ? region_range(v.node()->source(), user_->file) : SourceRange{};
      diags.report(DiagId::ProfileUnknownKey, range, key);
    }
  }
}

namespace {

// {X = 1, Y = 2}: the axes given and their values; `extra` keys may stand beside them.
bool axis_values(const Profile& p, const std::string& key, AxisValues& out, Diagnostics& diags,
                 uint32_t* given = nullptr, std::initializer_list<std::string_view> extra = {}) {
  std::vector<std::string> keys = p.keys(key);
  bool ok = true;
  for (const std::string& letter : keys) {
    if (std::find(extra.begin(), extra.end(), letter) != extra.end()) continue;
    int axis = letter.size() == 1 ? axis_index(letter[0]) : -1;
    if (axis < 0) {
      p.report_value(diags, key + "." + letter, "is not an axis (X Y Z A B C U V W P Q D)");
      ok = false;
      continue;
    }
    auto v = p.number(key + "." + letter, diags);
    if (!v) {
      ok = false;
      continue;
    }
    out[axis] = *v;
    if (given) *given |= 1u << axis;
  }
  return ok;
}

// The numbers of a collection's key: "7", or a range "1-200" that gives each number
// the entry (a real control's table of untouched entries). In [work_offsets] "P1" or
// "P1-P48" are the extended work offsets of G54.1 P and G154 P (kExtendedWorkOffset + P).
std::optional<std::pair<int, int>> table_numbers(const Profile& p, const std::string& table, const std::string& key,
                                                 Diagnostics& diags) {
  const bool extended = table == "work_offsets" && key.starts_with('P');
  auto number = [&](std::string_view text) -> std::optional<int> {
    if (extended && text.starts_with('P')) text.remove_prefix(1);
    auto n = parse_number<int>(text);
    if (!n || *n < (extended ? 1 : 0) || *n > (extended ? kExtendedWorkOffsets : 9999)) return std::nullopt;
    return extended ? kExtendedWorkOffset + *n : *n;
  };
  const size_t dash = key.find('-');
  auto lo = number(std::string_view(key).substr(0, dash));
  auto hi = dash == std::string::npos ? lo : number(std::string_view(key).substr(dash + 1));
  if (lo && hi && *lo <= *hi) return std::pair{*lo, *hi};
  p.report_value(diags, table + "." + key,
                 extended
                     ? fmt::format("must be an extended work offset P1..P{} or a range P1-P48", kExtendedWorkOffsets)
                     : "must be numbered 0..9999, or a range of them such as 1-200");
  return std::nullopt;
}

// Reads each entry of a collection once (read(key, first number): the entry or
// nothing) into out[n] for each of its numbers: the ranges first, so that an entry of
// its own replaces the range's.
template <typename Entry, typename Read>
void read_entries(const Profile& p, const std::string& table, std::map<int, Entry>& out, Diagnostics& diags,
                  Read read) {
  std::vector<std::string> keys = p.keys(table);
  std::stable_partition(keys.begin(), keys.end(), [](const std::string& k) { return k.find('-') != k.npos; });
  for (const std::string& key : keys)
    if (auto range = table_numbers(p, table, key, diags))
      if (std::optional<Entry> entry = read(key, range->first))
        for (int n = range->first; n <= range->second; ++n) out[n] = *entry;
}

// A number that must be greater than zero (a rate, a time, a distance).
void read_positive(const Profile& p, const std::string& key, double& out, Diagnostics& diags) {
  if (auto v = p.number(key, diags)) {
    if (*v > 0)
      out = *v;
    else
      p.report_value(diags, key, "must be greater than zero");
  }
}

std::optional<Plane> plane_of(const std::string& text) {
  int u = text.size() == 2 ? axis_index(text[0]) : -1;
  int v = text.size() == 2 ? axis_index(text[1]) : -1;
  if (u < 0 || v < 0 || u == v) return std::nullopt;
  for (const Plane& p : kPlanes)
    if (p.u == u && p.v == v) return p;
  return Plane{u, v, -1};
}

void read_axes(const Profile& p, MachineConfig& m, Diagnostics& diags) {
  for (const std::string& letter : p.keys("axes")) {
    std::string base = "axes." + letter;
    int i = letter.size() == 1 ? axis_index(letter[0]) : -1;
    if (i < 0) {
      p.report_value(diags, base, "is not an axis (X Y Z A B C U V W P Q D)");
      continue;
    }
    AxisConfig& a = m.axes[static_cast<size_t>(i)];
    if (auto v = p.string(base + ".kind", diags)) {
      if (*v == "linear")
        a.kind = AxisKind::Linear;
      else if (*v == "rotary")
        a.kind = AxisKind::Rotary;
      else if (*v == "indexing")
        a.kind = AxisKind::Indexing;
      else
        p.report_value(diags, base + ".kind", "must be linear, rotary or indexing");
    }
    auto positive = [&](const char* key, double& out) { read_positive(p, base + "." + key, out, diags); };
    positive("step", a.index_step);
    positive("rapid", a.rapid);
    a.max_feed = a.rapid;  // a feed may be as fast as a rapid unless the profile says
    positive("max_feed", a.max_feed);
    positive("acceleration", a.acceleration);
    positive("jerk", a.jerk);
    positive("tolerance", a.tolerance);
    positive("drive_error", a.drive_error);
    if (auto v = p.boolean(base + ".endless", diags)) a.endless = *v;
    if (auto v = p.boolean(base + ".diameter", diags)) a.diameter = *v;
    if (auto v = p.numbers(base + ".limits", diags)) {
      if (v->size() == 2 && (*v)[0] < (*v)[1]) {
        a.lower = (*v)[0];
        a.upper = (*v)[1];
      } else {
        p.report_value(diags, base + ".limits", "must be [lower, upper] with lower < upper");
      }
    }
  }
}

void read_motion(const Profile& p, MotionConfig& motion, Diagnostics& diags) {
  auto positive = [&](const char* key, double& out) { read_positive(p, std::string("motion.") + key, out, diags); };
  positive("junction_deviation", motion.junction_deviation);
  positive("tool_change", motion.tool_change);
  positive("spindle_acceleration", motion.spindle_acceleration);
  positive("max_velocity", motion.max_velocity);
}

// [stock] min and max: X, Y and Z each, min below max.
void read_stock(const Profile& p, StockConfig& stock, Diagnostics& diags) {
  if (!p.user_sets("stock")) return;
  constexpr uint32_t kXYZ = 0b111;
  AxisValues corner[2]{};
  bool ok = true;
  for (int i = 0; i < 2; ++i) {
    const std::string key = i == 0 ? "stock.min" : "stock.max";
    uint32_t given = 0;
    if (!axis_values(p, key, corner[i], diags, &given))
      ok = false;
    else if (given != kXYZ) {
      p.report_value(diags, key, "must give X, Y and Z in mm and no other axis, e.g. { X = 0.0, Y = 0.0, Z = -20.0 }");
      ok = false;
    }
  }
  if (!ok) return;
  for (int axis = 0; axis < 3; ++axis)
    if (!(corner[0][axis] < corner[1][axis])) {
      p.report_value(diags, "stock.max",
                     fmt::format("must be above stock.min on every axis ({}: {} is not above {})", kAxisLetters[axis],
                                 corner[1][axis], corner[0][axis]));
      return;
    }
  stock.set = true;
  for (int axis = 0; axis < 3; ++axis) {
    stock.min[axis] = corner[0][axis];
    stock.max[axis] = corner[1][axis];
  }
}

void read_asset(const Profile& p, AssetConfig& asset, Diagnostics& diags) {
  auto whole = [&](const char* key, auto lo, auto hi, auto& out) {
    const std::string name = std::string("asset.") + key;
    if (auto v = p.number(name, diags)) {
      if (auto n = whole_in<std::remove_reference_t<decltype(out)>>(*v, lo, hi))
        out = *n;
      else
        p.report_value(diags, name, fmt::format("must be a whole number from {} to {}", lo, hi));
    }
  };
  whole("channels", 1u, 255u, asset.channels);
  whole("structures", 1u, 255u, asset.structures);
  whole("device_bytes", uint64_t{0}, uint64_t{1'000'000'000'000'000}, asset.device_bytes);
}

void read_probe(const Profile& p, MachineConfig& m, Diagnostics& diags) {
  ProbeConfig& probe = m.probe;
  auto positive = [&](const char* key, double& out) { read_positive(p, std::string("probe.") + key, out, diags); };
  positive("approach", probe.approach);
  positive("safety", probe.safety);
  positive("feed", probe.feed);
  size_t n = p.array_size("probe.contacts", diags);
  for (size_t i = 0; i < n; ++i) {
    std::string key = fmt::format("probe.contacts[{}]", i);
    ProbeContact c;
    if (p.is_string(key)) {
      auto v = p.string(key, diags);
      if (v && *v == "none")
        c.kind = ProbeContact::Kind::None;
      else
        p.report_value(diags, key, "must be \"none\" or a table such as { X = 10.02 }");
    } else if (!p.keys(key + ".centre").empty() || p.number(key + ".radius", diags)) {
      c.kind = ProbeContact::Kind::Circle;
      axis_values(p, key + ".centre", c.point, diags, &c.axes);
      if (std::popcount(c.axes) != 2)
        p.report_value(diags, key + ".centre", "must give the centre's two coordinates, e.g. { X = 1, Y = 2 }");
      if (auto r = p.number(key + ".radius", diags); r && *r > 0)
        c.radius = *r;
      else
        p.report_value(diags, key + ".radius", "must be greater than zero");
    } else {
      axis_values(p, key, c.point, diags, &c.axes);
    }
    probe.contacts.push_back(c);
  }
}

}  // namespace

MachineConfig load_machine_config(const Profile& p, Diagnostics& diags) {
  MachineConfig m;
  m.profile = p.name();
  if (auto v = p.string("machine.name", diags)) m.name = *v;
  if (auto v = p.boolean("machine.block_skip", diags)) m.block_skip = *v;
  if (auto v = p.boolean("machine.optional_stop", diags)) m.optional_stop = *v;
  if (auto v = p.number("machine.processes", diags)) {
    if (auto n = whole_in<uint8_t>(*v, 1, 5))
      m.processes = *n;
    else
      p.report_value(diags, "machine.processes", "must be a whole number from 1 to 5");
  }
  if (auto v = p.number("machine.look_ahead", diags)) {
    if (auto n = whole_in<uint32_t>(*v, 1, 64))
      m.look_ahead = *n;
    else
      p.report_value(diags, "machine.look_ahead", "must be a whole number of blocks from 1 to 64");
  }
  if (auto v = p.number("machine.gtl_tolerance", diags)) {
    if (*v > 0 && *v <= 1)
      m.gtl_tolerance = *v;
    else
      p.report_value(diags, "machine.gtl_tolerance", "must be a distance in mm greater than 0 and at most 1");
  }
  if (auto v = p.number("limits.run_memory_mib", diags)) {
    if (auto n = whole_in<uint64_t>(*v, 1, 1 << 20))
      m.run_memory = *n << 20;
    else
      p.report_value(diags, "limits.run_memory_mib", "must be a whole number of MiB from 1 to 1048576");
  }
  if (auto v = p.boolean("machine.spindle_encoder", diags)) m.spindle_encoder = *v;
  if (auto v = p.number("machine.max_rpm", diags)) {
    if (*v >= 0)
      m.max_rpm = *v;
    else
      p.report_value(diags, "machine.max_rpm", "must not be negative");
  }
  if (auto v = p.number("machine.tap_min_travel", diags)) {
    if (*v >= 0)
      m.tap_min_travel = *v;
    else
      p.report_value(diags, "machine.tap_min_travel", "must not be negative");
  }
  if (auto v = p.string("machine.turning_plane", diags); v && !v->empty()) {
    m.turning_plane = plane_of(*v);
    if (!m.turning_plane) p.report_value(diags, "machine.turning_plane", "must name two different axes, e.g. \"ZX\"");
  }
  axis_values(p, "machine.initial_position", m.initial_position, diags);
  axis_values(p, "machine.reference_position", m.reference_position, diags);
  for (int n = 2; n <= 4; ++n)
    axis_values(p, fmt::format("machine.reference_position_{}", n), m.other_references[static_cast<size_t>(n - 2)],
                diags);
  read_entries(p, "work_offsets", m.work_offsets, diags, [&](const std::string& key, int) -> std::optional<WorkOffset> {
    std::string base = "work_offsets." + key;
    WorkOffset w;
    if (!axis_values(p, base, w.values, diags, &w.axes, {"unit"})) return std::nullopt;
    if (auto unit = p.string(base + ".unit", diags)) {
      if (*unit == "inch" || *unit == "mm")
        w.inch = *unit == "inch";
      else
        p.report_value(diags, base + ".unit", "must be mm or inch");
    }
    return w;
  });
  read_entries(p, "tools", m.tools, diags, [&](const std::string& key, int n) -> std::optional<ToolEntry> {
    ToolEntry t;
    if (auto v = p.string("tools." + key + ".description", diags)) t.description = *v;
    if (auto v = p.numbers("tools." + key + ".sisters", diags)) {
      for (double d : *v) {
        auto sister = whole_in(d, 1, 9999);
        if (!sister || *sister == n) {
          p.report_value(diags, "tools." + key + ".sisters", "must list other tools, 1..9999");
          t.sisters.clear();
          break;
        }
        t.sisters.push_back(*sister);
      }
    }
    if (auto v = p.number("tools." + key + ".corrector", diags)) {
      if (auto c = whole_in(*v, 1, 9999))
        t.corrector = *c;
      else
        p.report_value(diags, "tools." + key + ".corrector", "must be a corrector 1..9999");
    }
    return t;
  });
  read_entries(p, "offsets", m.offsets, diags, [&](const std::string& key, int) -> std::optional<OffsetEntry> {
    OffsetEntry o;
    std::string base = "offsets." + key;
    if (auto v = p.number(base + ".length", diags)) o.length = *v;
    if (auto v = p.number(base + ".radius", diags)) {
      if (*v >= 0)
        o.radius = *v;
      else
        p.report_value(diags, base + ".radius", "must not be negative");
    }
    if (auto v = p.string(base + ".axis", diags)) {
      if (v->size() == 1 && axis_index((*v)[0]) >= 0)
        o.axis = (*v)[0];
      else
        p.report_value(diags, base + ".axis", "must be one axis letter");
    }
    if (auto v = p.number(base + ".wear_length", diags)) o.wear_length = *v;
    if (auto v = p.number(base + ".wear_diameter", diags)) o.wear_diameter = *v;
    for (auto [key_name, max] :
         {std::pair{".max_wear_length", &o.max_wear_length}, {".max_wear_diameter", &o.max_wear_diameter}})
      if (auto v = p.number(base + key_name, diags)) {
        if (*v >= 0)
          *max = *v;
        else
          p.report_value(diags, base + key_name, "must not be negative");
      }
    return o;
  });
  for (const auto& [n, t] : m.tools)
    if (t.corrector && !m.offsets.count(t.corrector))
      p.report_value(diags, fmt::format("tools.{}.corrector", n), "must be a corrector of [offsets]");
  read_axes(p, m, diags);
  read_probe(p, m, diags);
  read_asset(p, m.asset, diags);
  read_motion(p, m.motion, diags);
  read_stock(p, m.stock, diags);
  return m;
}

}  // namespace ncc::stdlib
