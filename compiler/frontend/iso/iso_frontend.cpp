// iso front end: the main program file with its O subprograms and macros, and the O
// programs its M98 and G65 calls name that the file does not hold, each read once from
// the program library into one IR program.
#include "iso_frontend.h"

#include <deque>
#include <set>

#include "frontend/limits.h"
#include "reader.h"

namespace ncc::iso {

namespace {

class IsoFrontend final : public DialectFrontend<Settings> {
 public:
  explicit IsoFrontend(Settings settings) : DialectFrontend(std::move(settings)) {
    rules_.block_number_order = false;  // any order; GOTO finds its block by number
    rules_.recursion = true;            // a macro may call itself until a condition stops it
  }

  ir::Program read(SourceManager& sources, uint32_t file, Diagnostics& diags, const ReadOptions& options) override {
    ir::Program program = start_program("iso", file);
    // #0..#999 (decision 3): #1-#33 local to each macro call, all vacant at the start.
    VarSpace vars{"#",
                  1000,
                  {{0, VarType::LongReal},
                   {34, VarType::Unavailable},
                   {100, VarType::LongReal},
                   {200, VarType::Unavailable},
                   {500, VarType::LongReal}}};
    vars.locals = 34;
    vars.vacant = true;
    const auto space = static_cast<uint16_t>(program.spaces.size());
    program.spaces.push_back(vars);

    Reader main(s_, program, sources.file(file), file, diags, space, std::nullopt, options.fast_path, options.sink);
    if (admit_text(sources.file(file), file, diags)) main.run();
    std::deque<ProgramCall> pending(main.calls().begin(), main.calls().end());
    // Called programs the file does not hold: O<nnnn>[.nc] in the library (decision 12).
    const std::string root = library_root(options, s_.library, sources.file(file).path());
    std::set<std::string> known, missing;
    for (const ir::Unit& u : program.units) known.insert(u.name);
    while (!pending.empty() && !diags.limit_reached()) {
      ProgramCall call = pending.front();
      pending.pop_front();
      if (missing.count(call.name)) program.units[call.unit].blocks[call.block].has_errors = true;
      if (!known.insert(call.name).second) continue;
      auto f =
          load_called_file(sources, root, call.name, {"", ".nc", ".ngc", ".tap", ".txt"}, call.name, call.range, diags);
      if (!f) {
        program.units[call.unit].blocks[call.block].has_errors = true;
        missing.insert(call.name);
        continue;
      }
      program.files.push_back(*f);
      Reader called(s_, program, sources.file(*f), *f, diags, space, call.name, options.fast_path);
      called.run();
      for (const ProgramCall& c : called.calls()) pending.push_back(c);
    }
    set_power_on(program, s_.tables, s_.power_on);
    add_dynamic_codes(program, s_.tables, {"G65", "M97", "M98", "M99"});
    return program;
  }
};

}  // namespace

std::unique_ptr<Frontend> make_iso_frontend(const stdlib::Profile& profile, Diagnostics& diags) {
  return make_dialect_frontend<IsoFrontend>(load_settings(profile, diags));
}

}  // namespace ncc::iso
