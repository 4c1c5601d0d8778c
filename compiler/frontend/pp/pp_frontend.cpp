// pp front end: the part program with its subprograms, and the macro files its G72
// calls name (and theirs), each read once, into one IR program.
#include "pp_frontend.h"

#include <deque>
#include <set>

#include "frontend/limits.h"
#include "reader.h"

namespace ncc::pp {

namespace {

class PpFrontend final : public DialectFrontend<Settings> {
 public:
  explicit PpFrontend(Settings settings) : DialectFrontend(std::move(settings)) {
    rules_.block_number_order = false;  // unique in the file (the reader), in any order
  }

  ir::Program read(SourceManager& sources, uint32_t file, Diagnostics& diags, const ReadOptions& options) override {
    ir::Program program = start_program("pp", file);
    // R0..R95, one set for the whole run, fixed point to 0.001 (decision 9); the jump
    // counters of G73, local to each call (decision 14).
    Spaces spaces;
    VarSpace r{"R", 96, {{0, VarType::Thousandths}}};
    r.limit = 70000;
    spaces.r = static_cast<uint16_t>(program.spaces.size());
    program.spaces.push_back(r);
    VarSpace counters{"G73", 0, {{0, VarType::Long}}};
    spaces.counters = static_cast<uint16_t>(program.spaces.size());
    program.spaces.push_back(counters);

    Reader main(s_, program, sources.file(file), file, diags, spaces, std::nullopt, options.fast_path, options.sink);
    if (admit_text(sources.file(file), file, diags)) main.run();
    std::deque<MacroCall> pending(main.macro_calls().begin(), main.macro_calls().end());
    // Macros live in files L<nnnn> of the library (§2.3.5, decision 13).
    const std::string root = library_root(options, s_.library, sources.file(file).path());
    // A macro that cannot be read is reported at its first call; every call of it has
    // errors (the check says nothing more of them).
    std::set<uint32_t> done, missing;
    while (!pending.empty() && !diags.limit_reached()) {
      MacroCall call = pending.front();
      pending.pop_front();
      if (missing.count(call.number)) program.units[call.unit].blocks[call.block].has_errors = true;
      if (!done.insert(call.number).second) continue;
      auto f = load_called_file(sources, root, Reader::macro_name(call.number), {"", ".pp"},
                                "L" + std::to_string(call.number), call.range, diags);
      if (!f) {
        program.units[call.unit].blocks[call.block].has_errors = true;
        missing.insert(call.number);
        continue;
      }
      program.files.push_back(*f);
      Reader macro(s_, program, sources.file(*f), *f, diags, spaces, call.number, options.fast_path);
      macro.run();
      for (const MacroCall& c : macro.macro_calls()) pending.push_back(c);
    }
    program.spaces[spaces.counters].size = program.spaces[spaces.counters].locals = spaces.next_counter;
    set_power_on(program, s_.tables, s_.power_on);
    // A code the front end reads itself (G71...) cannot be chosen at run time.
    std::set<std::string> fixed;
    for (const auto& [name, control] : s_.control)
      if (control.action != Control::Dwell) fixed.insert(name);
    add_dynamic_codes(program, s_.tables, fixed);
    return program;
  }
};

}  // namespace

std::unique_ptr<Frontend> make_pp_frontend(const stdlib::Profile& profile, Diagnostics& diags) {
  return make_dialect_frontend<PpFrontend>(load_settings(profile, diags));
}

}  // namespace ncc::pp
