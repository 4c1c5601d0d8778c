// Machine profiles: TOML files (docs/profile.md) read with toml++. A profile names
// only what differs from the built-in default (stdlib/profiles/default.toml), or from
// the built-in machine its `machine.base` names (stdlib/profiles/fanuc.toml...): a
// scalar setting falls back to the base and then the default one by one; a collection
// table ([tools], [offsets], [work_offsets]) given in the profile replaces the base's.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "contract/machine_config.h"
#include "support/diagnostics.h"

namespace ncc::stdlib {

// A machine profile, and the files it names (tables, a format), are a few kilobytes.
inline constexpr FileLimit kProfileFile{16 << 20, "a machine profile or a file it names"};

class Profile {
 public:
  // Parses a profile file (path "" = the default alone; a name without a path
  // separator or .toml, "haas", is the built-in machine of that name). Syntax errors
  // are reported with their location; the result is empty on error.
  [[nodiscard]] static std::optional<Profile> load(SourceManager& sources, const std::string& path, Diagnostics& diags);
  // Parses profile text already in memory (e.g. stored in a bytecode file).
  [[nodiscard]] static std::optional<Profile> parse(SourceManager& sources, std::string name, std::string text,
                                                    Diagnostics& diags);

  const std::string& name() const { return name_; }
  const std::string& text() const { return text_; }  // the user's text; "" for the default
  std::string resolve_path(std::string_view relative) const;
  // The text of the file the string `key` names (from the profile's folder), and its
  // path; nothing, reported at the key, if it cannot be read.
  [[nodiscard]] std::optional<std::string> file_text(std::string_view key, const std::string& file, std::string& path,
                                                     Diagnostics& diags) const;

  // Typed lookups by dotted key ("gost.format"). A key of the wrong type is
  // reported and treated as absent.
  [[nodiscard]] std::optional<std::string> string(std::string_view key, Diagnostics& diags) const;
  [[nodiscard]] std::optional<double> number(std::string_view key, Diagnostics& diags) const;
  [[nodiscard]] std::optional<bool> boolean(std::string_view key, Diagnostics& diags) const;
  [[nodiscard]] std::optional<std::vector<double>> numbers(std::string_view key, Diagnostics& diags) const;
  // An inline or nested table of numbers or strings: {X = 1, Y = 2}.
  [[nodiscard]] std::optional<std::map<std::string, double>> number_table(std::string_view key,
                                                                          Diagnostics& diags) const;
  [[nodiscard]] std::optional<std::map<std::string, std::string>> string_table(std::string_view key,
                                                                               Diagnostics& diags) const;
  // The keys of a collection table, from the user's profile if it has the table.
  std::vector<std::string> keys(std::string_view table) const;
  // The length of an array ("probe.contacts"); its items are "probe.contacts[0]"...
  size_t array_size(std::string_view key, Diagnostics& diags) const;
  bool is_string(std::string_view key) const;

  // Reports keys of the user's profile that no reader looked up (likely typos). The
  // sections of `others` (the dialects not read now) are theirs to check.
  void report_unused(Diagnostics& diags, const std::vector<std::string_view>& others = {}) const;
  // Reports a bad value of `key` at its place in the profile.
  void report_value(Diagnostics& diags, std::string_view key, std::string_view message) const;
  // Where `key`'s value is written (the user's profile, else the default).
  SourceRange range_of(std::string_view key) const;
  // Whether the user's profile sets `key` (rather than inheriting the default).
  bool user_sets(std::string_view key) const;

  struct Impl;

 private:
  Profile() = default;
  struct Lookup;
  Lookup find(std::string_view key) const;

  std::string name_;
  std::string text_;
  std::string dir_;
  std::shared_ptr<const Impl> user_;
  std::shared_ptr<const Impl> base_;  // the built-in machine user_ extends (machine.base), if any
  std::shared_ptr<const Impl> builtin_;
  mutable std::set<std::string, std::less<>> used_;
};

// The built-in machines `--machine NAME` and `machine.base` name: "default", "fanuc"...
std::vector<std::string> builtin_machines();

// The machine data of a profile: offsets, tools, initial position, switches.
MachineConfig load_machine_config(const Profile& profile, Diagnostics& diags);

}  // namespace ncc::stdlib
