#include "profile.h"

#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "embedded.h"

namespace ncc::stdlib {

struct Profile::Impl {
  toml::table table;
  uint32_t file = 0;  // SourceManager index
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
                                                const std::string& text, Diagnostics& diags) {
  uint32_t file = sources.add(name, text);
  try {
    auto impl = std::make_shared<Profile::Impl>();
    impl->table = toml::parse(text, name);
    impl->file = file;
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
  }
  return p;
}

std::optional<Profile> Profile::load(SourceManager& sources, const std::string& path, Diagnostics& diags) {
  if (path.empty()) return parse(sources, "", "", diags);
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diags.report(DiagId::FileUnreadable, {}, path, std::strerror(errno));
    return std::nullopt;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  if (text.empty()) text = "\n";  // an empty profile is valid: everything is the default
  return parse(sources, path, std::move(text), diags);
}

std::string Profile::resolve_path(std::string_view relative) const {
  std::filesystem::path p(relative);
  if (p.is_absolute() || dir_.empty()) return p.string();
  return (std::filesystem::path(dir_) / p).string();
}

Profile::Lookup Profile::find(std::string_view key) const {
  used_.emplace(key);
  toml::path path{key};
  if (user_) {
    toml::node_view<const toml::node> v = user_->table.at_path(path);
    if (v) return {v.node(), user_.get()};
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

void Profile::report_unused(Diagnostics& diags) const {
  if (!user_) return;
  std::vector<std::string> leaves;
  collect_leaves(user_->table, "", leaves);
  for (const std::string& key : leaves) {
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

bool axis_values(const Profile& p, const std::string& key, AxisValues& out, Diagnostics& diags) {
  auto table = p.number_table(key, diags);
  if (!table) return false;
  for (const auto& [letter, value] : *table) {
    int axis = letter.size() == 1 ? axis_index(letter[0]) : -1;
    if (axis < 0) {
      p.report_value(diags, key + "." + letter, "is not an axis (X Y Z A B C U V W P Q D)");
      continue;
    }
    out[axis] = value;
  }
  return true;
}

std::optional<int> table_number(const Profile& p, const std::string& table, const std::string& key,
                                Diagnostics& diags) {
  char* end = nullptr;
  long n = std::strtol(key.c_str(), &end, 10);
  if (key.empty() || *end != '\0' || n < 0 || n > 9999) {
    p.report_value(diags, table + "." + key, "must be numbered 0..9999");
    return std::nullopt;
  }
  return static_cast<int>(n);
}

}  // namespace

MachineConfig load_machine_config(const Profile& p, Diagnostics& diags) {
  MachineConfig m;
  if (auto v = p.string("machine.name", diags)) m.name = *v;
  if (auto v = p.boolean("machine.block_skip", diags)) m.block_skip = *v;
  if (auto v = p.boolean("machine.optional_stop", diags)) m.optional_stop = *v;
  axis_values(p, "machine.initial_position", m.initial_position, diags);
  for (const std::string& key : p.keys("work_offsets")) {
    auto n = table_number(p, "work_offsets", key, diags);
    AxisValues values{};
    if (n && axis_values(p, "work_offsets." + key, values, diags)) m.work_offsets[*n] = values;
  }
  for (const std::string& key : p.keys("tools")) {
    auto n = table_number(p, "tools", key, diags);
    if (!n) continue;
    ToolEntry t;
    if (auto v = p.string("tools." + key + ".description", diags)) t.description = *v;
    m.tools[*n] = t;
  }
  for (const std::string& key : p.keys("offsets")) {
    auto n = table_number(p, "offsets", key, diags);
    if (!n) continue;
    OffsetEntry o;
    std::string base = "offsets." + key;
    if (auto v = p.number(base + ".length", diags)) o.length = *v;
    if (auto v = p.number(base + ".radius", diags)) {
      if (*v >= 0) o.radius = *v;
      else p.report_value(diags, base + ".radius", "must not be negative");
    }
    m.offsets[*n] = o;
  }
  return m;
}

}  // namespace ncc::stdlib
