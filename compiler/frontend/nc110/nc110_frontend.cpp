// NC-110 front end: the main program and the programs it calls with (CLS), each a
// file of blocks (reader.h), into one IR program.
#include "nc110_frontend.h"

#include <deque>
#include <filesystem>
#include <map>
#include <set>

#include "frontend/limits.h"
#include "reader.h"

namespace ncc::nc110 {

namespace {

namespace fs = std::filesystem;

class Nc110Frontend final : public DialectFrontend<Settings> {
 public:
  explicit Nc110Frontend(Settings settings) : DialectFrontend(std::move(settings)) {
    rules_.max_repeat_depth = 3;        // §2.13.2.1: up to two RPT inside another
    rules_.unique_labels = true;        // decision 14
    rules_.block_ranges = true;         // (EPP,from,to) §2.13.2.3
    rules_.block_number_order = false;  // N numbers may repeat and go down (decision 7)
    rules_.processes = 5;               // chapter 4: up to five processes
  }

  ir::Program read(SourceManager& sources, uint32_t file, Diagnostics& diags, const ReadOptions& options) override {
    ir::Program program = start_program("nc110", file);
    declare_spaces(program);
    program.semantics.system_names.resize(static_cast<size_t>(SysVar::Count));
    for (const auto& [name, entry] : s_.system)
      if (entry.var) program.semantics.system_names[static_cast<size_t>(*entry.var)] = name;
    program.semantics.builtin_names = function_names();

    // The main program, then every program it calls, each read once (§2.13.2.2).
    fs::path main_path = sources.file(file).path();
    std::deque<CallSite> pending;
    auto read_unit = [&](uint32_t f, ir::UnitKind kind, std::string name) {
      ir::Unit unit;
      unit.kind = kind;
      unit.name = std::move(name);
      unit.range = SourceRange::point(f, 1, 1);
      Reader reader(s_, program, sources.file(f), f, diags, options.fast_path,
                    kind == ir::UnitKind::Program ? options.sink : nullptr);
      reader.run(unit);
      program.units.push_back(std::move(unit));
      for (const CallSite& c : reader.calls()) pending.push_back(c);
    };
    if (admit_text(sources.file(file), file, diags)) read_unit(file, ir::UnitKind::Program, main_path.stem().string());
    // Programs selected for other processes (SPG), by name as EXE names them, read
    // first, in the order given.
    std::map<std::string, uint8_t> selected;
    for (auto it = options.processes.rbegin(); it != options.processes.rend(); ++it) {
      const auto& [process, name] = *it;
      size_t slash = name.find('/');
      CallSite site{
          name.substr(0, slash), slash == std::string::npos ? s_.default_device : name.substr(slash + 1), "", {}, 0, 0,
          ir::UnitKind::Process};
      // As EXE names a program (decision 62).
      if (!capitals_and_digits(site.name, 1, 6) || !exe_device(site.device)) {
        diags.report(DiagId::ProcessOption, {}, fmt::format("{}={}", process, name),
                     "a program is 1 to 6 capitals and digits, a letter first, then /MP0 to /MP3 or nothing");
        continue;
      }
      site.entry = site.device + "/" + site.name;
      selected[site.entry] |= static_cast<uint8_t>(1u << (process - 1));
      pending.push_front(site);
    }
    // Each program once as a subprogram (CLS) and once as a process's program (EXE).
    // One that cannot be read is reported once; every call of it has errors.
    std::set<std::pair<ir::UnitKind, std::string>> done;
    std::set<std::string> missing;
    while (!pending.empty() && !diags.limit_reached()) {
      CallSite call = pending.front();
      pending.pop_front();
      // A call of a program that cannot be read has errors (a process's program an
      // option selects has no call).
      auto unread = [&] {
        if (call.range.file != 0 || call.range.line != 0) program.units[call.unit].blocks[call.block].has_errors = true;
      };
      if (missing.count(call.entry)) {
        unread();
        continue;
      }
      if (!done.insert({call.kind, call.entry}).second) continue;
      // Lexically normal, so that messages and the trace name each file one way.
      fs::path root = (!options.library.empty() ? fs::path(options.library)
                       : !s_.library.empty()    ? fs::path(s_.library)
                                                : main_path.parent_path())
                          .lexically_normal();
      // <library>/<device>/<name>, with or without .nc (decision 8).
      std::vector<fs::path> candidates = {root / call.device / call.name, root / call.device / (call.name + ".nc")};
      std::optional<std::string> text;
      fs::path found;
      bool reported = false;
      for (const fs::path& candidate : candidates)
        if ((text = read_called_file(candidate.string(), diags, call.range, reported)) || reported) {
          found = candidate;
          break;
        }
      if (!text) {
        if (!reported)
          diags.report(DiagId::ProgramNotFound, call.range, call.entry,
                       (root / call.device / call.name).string() + "[.nc]");
        missing.insert(call.entry);
        unread();
        continue;
      }
      uint32_t f = sources.add(found.string(), std::move(*text));
      if (!admit_text(sources.file(f), f, diags)) {
        missing.insert(call.entry);
        unread();
        continue;
      }
      program.files.push_back(f);
      read_unit(f, call.kind, call.entry);
      if (auto it = selected.find(call.entry); call.kind == ir::UnitKind::Process && it != selected.end())
        program.units.back().processes = it->second;
    }

    set_power_on(program, s_.tables, s_.power_on);
    add_dynamic_codes(program, s_.tables);
    return program;
  }

 private:
  // E0..E(n-1) typed by Table 2.8, then the byte memories SA, SK, SYVAR.
  void declare_spaces(ir::Program& program) const {
    VarSpace e{"E", s_.e_count, {}};
    for (const ParameterClass& c : s_.classes) {
      e.types.push_back({c.first, c.type});
      if (c.limit) e.limit = c.limit;
    }
    program.spaces.push_back(e);
    for (const Memory& m : s_.memories) {
      VarSpace space{m.name, m.bytes, {}};
      space.memory = true;
      space.format = m.format;
      program.spaces.push_back(space);
    }
  }
};

}  // namespace

std::unique_ptr<Frontend> make_nc110_frontend(const stdlib::Profile& profile, Diagnostics& diags) {
  return make_dialect_frontend<Nc110Frontend>(load_settings(profile, diags));
}

}  // namespace ncc::nc110
