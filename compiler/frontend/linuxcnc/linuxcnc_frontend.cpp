// linuxcnc front end: the main program file with its subroutines, and the
// subroutines its calls name that the file does not define, each read once from the
// library (`o<name> call` finds name.ngc, M98 P100 finds 100.ngc) into one IR program.
#include "linuxcnc_frontend.h"

#include <deque>
#include <set>

#include "frontend/limits.h"
#include "reader.h"

namespace ncc::linuxcnc {

namespace {

// The file a subroutine of that name is in: o<name> in name.ngc, o100 in 100.ngc.
std::string file_name(const std::string& unit) {
  std::string name = unit.substr(1);
  if (name.size() > 2 && name.front() == '<') name = name.substr(1, name.size() - 2);
  return name;
}

class LinuxcncFrontend final : public DialectFrontend<Settings> {
 public:
  explicit LinuxcncFrontend(Settings settings) : DialectFrontend(std::move(settings)) {
    rules_.block_number_order = false;  // N numbers are labels of nothing: any order
    rules_.recursion = true;            // a subroutine may call itself
  }

  ir::Program read(SourceManager& sources, uint32_t file, Diagnostics& diags, const ReadOptions& options) override {
    ir::Program program = start_program("linuxcnc", file);
    Parameters params;
    // #1-#5602 (#1-#30 local to a call), then the temporaries of a line's settings;
    // the named locals and globals, vacant until set (index 0 is never set: EXISTS).
    params.numbered = 0;
    VarSpace numbered{"#", kMaxParameter + 1, {}};
    numbered.locals = kLocalParameters + 1;
    program.spaces.push_back(numbered);
    params.locals = 1;
    VarSpace locals{"#<", 1, {}};
    locals.vacant = true;
    program.spaces.push_back(locals);
    params.globals = 2;
    VarSpace globals{"#<_", Parameters::kValueReturned + 1, {}};
    globals.vacant = true;
    program.spaces.push_back(globals);

    Reader main(s_, program, params, sources.file(file), file, diags, false);
    if (admit_text(sources.file(file), file, diags)) main.run();
    std::deque<SubCall> pending(main.calls().begin(), main.calls().end());
    const std::string root = library_root(options, s_.library, sources.file(file).path());
    std::set<std::string> known, missing;
    for (const ir::Unit& u : program.units) known.insert(u.name);
    auto mark = [&](const SubCall& call) {
      for (ir::Unit& u : program.units)
        if (u.name == call.unit && call.block < u.blocks.size()) u.blocks[call.block].has_errors = true;
    };
    while (!pending.empty() && !diags.limit_reached()) {
      SubCall call = pending.front();
      pending.pop_front();
      if (missing.count(call.name)) mark(call);
      if (known.count(call.name)) continue;
      const std::string name = file_name(call.name);
      auto f = load_called_file(sources, root, name, {".ngc", ""}, call.name, call.range, diags);
      if (!f) {
        mark(call);
        missing.insert(call.name);
        continue;
      }
      program.files.push_back(*f);
      Reader called(s_, program, params, sources.file(*f), *f, diags, true);
      called.run();
      for (const std::string& d : called.defined()) known.insert(d);
      if (!known.count(call.name)) {
        diags.report(DiagId::ProgramStructure, call.range,
                     fmt::format("{} defines no {} sub", sources.file(*f).path(), call.name));
        mark(call);
        missing.insert(call.name);
      }
      for (const SubCall& c : called.calls()) pending.push_back(c);
    }
    program.spaces[params.numbered].size = kMaxParameter + 1 + params.temporaries;
    program.spaces[params.locals].size = static_cast<uint32_t>(params.local_names.size() + 1);
    program.spaces[params.locals].locals = program.spaces[params.locals].size;
    program.spaces[params.globals].size = static_cast<uint32_t>(params.global_names.size() + 1);
    set_power_on(program, s_.tables, s_.power_on);
    add_dynamic_codes(program, s_.tables, {"M98", "M99"});
    return program;
  }
};

}  // namespace

std::unique_ptr<Frontend> make_linuxcnc_frontend(const stdlib::Profile& profile, Diagnostics& diags) {
  return make_dialect_frontend<LinuxcncFrontend>(load_settings(profile, diags));
}

}  // namespace ncc::linuxcnc
