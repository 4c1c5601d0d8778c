// The stages end to end, as the CLI and the tests use them:
//   source --front end--> IR --checks--> IR --lowering--> module --VM + runtime--> trace
// `ncc check` adds a dry run: the program runs on the runtime with no trace and
// every run-time problem it meets becomes a diagnostic (recovering, not stopping).
// A library of callable programs gets none: only a caller gives them their arguments.
#pragma once

#include <optional>
#include <string>

#include "ir/ir.h"
#include "runtime/trace.h"
#include "stdlib/profile.h"
#include "vm/module.h"
#include "vm/vm.h"

namespace ncc::screen {
class UserScreen;
}

namespace ncc {

struct Session {
  SourceManager sources;
  Diagnostics diags;
  std::optional<stdlib::Profile> profile;
  std::string library;                                     // --lib: where called programs are found
  std::vector<std::pair<uint8_t, std::string>> processes;  // --process N=NAME (NC-110 SPG)
  bool fast_path = true;       // --no-fast-path: every block through the ANTLR parser (to compare)
  bool stream = true;          // --no-stream: hold the whole IR before checking and lowering (to compare)
  bool library_input = false;  // the program read is a library of callable programs (ir::Program::library)

  explicit Session(uint32_t error_limit = 100) : diags(error_limit) {}
};

// The session's diagnostics in source order, whichever stage found them; those
// without a place last.
std::vector<Diagnostic> diagnostics_in_order(const Session& s);

// Loads the machine profile; path "" = the built-in default.
[[nodiscard]] bool load_profile(Session& s, const std::string& path);

struct RunSettings {
  std::optional<uint64_t> max_steps;  // default: the program's blocks + 100,000,000; a dry run's: + 1,000,000
  std::optional<uint64_t>
      max_memory;  // MiB the runtime may hold (--max-memory); default: the profile's limits.run_memory_mib
  bool block_skip = false;
  bool optional_stop = false;
  bool trace_blocks = false;
  bool trace_machine_frame = false;     // --trace-frame machine: positions in machine coordinates
  std::optional<uint32_t> start_block;  // a main block ':N' to start at
  std::string files;                    // the ASSET sandbox ("": none, every ASSET statement answers code 18)
  std::string input;                    // the operator's answers to INP, a line each ("": none)
  bool screen = false;                  // print the user screen at the end (NC-110 §5.6)
};

enum class FileKind { Source, Bytecode };
// Reads a file into the session; nullopt (reported) if it cannot be read.
[[nodiscard]] std::optional<std::pair<FileKind, uint32_t>> read_input(Session& s, const std::string& path);

// Front end and checks. The program is returned even with errors (for `ncc ir`).
[[nodiscard]] std::optional<ir::Program> analyse(Session& s, uint32_t file, const std::string& dialect);
vm::Module lower_program(Session& s, const ir::Program& program);
// Front end, checks and lowering at once: the leading blocks of the first unit
// without a flow statement (most of a CAM file) are checked, lowered and
// dropped as they are read, so that compiling holds little of the file's IR; the
// module is the one analyse + lower_program make. Blocks with errors are lowered as
// lower_program does; nothing if the program cannot be read at all.
[[nodiscard]] std::optional<vm::Module> compile_source(Session& s, uint32_t file, const std::string& dialect);
// Sees each block compile_source streams, after its checks and before it is dropped;
// `next` is the block after it where the observer looks ahead from this one.
class StreamObserver {
 public:
  virtual ~StreamObserver() = default;
  virtual void streamed(const ir::Program& program, const ir::Block& block, const ir::Block* next) = 0;
  // False for a block the observer must see with every block after it: streaming
  // stops there, and the rest is held whole.
  virtual bool streams(const ir::Program&, const ir::Block&) const { return true; }
  // True for a block the observer must see with the one after it: it is held (with
  // its expressions) until that one is read.
  virtual bool looks_ahead(const ir::Program&, const ir::Block&) const { return false; }
};
// compile_source, showing `observer` each block it streams, and leaving in `rest` the
// program's IR without them (the units and blocks it holds at the end).
[[nodiscard]] std::optional<vm::Module> compile_source(Session& s, uint32_t file, const std::string& dialect,
                                                       StreamObserver& observer, ir::Program& rest);
// A source read whole again, with no sink and its diagnostics not reported (the
// caller has read it once): for what needs every block at once.
[[nodiscard]] std::optional<ir::Program> read_whole(Session& s, uint32_t file, const std::string& dialect);
// The power-on functions of a dialect with the session's profile (an empty program's).
std::vector<FnCall> power_on_functions(Session& s, const std::string& dialect);
std::vector<FnCall> power_on_functions(Session& s, const std::string& dialect, const stdlib::Profile& profile);
// Runs the module with a null trace, reporting what the runtime finds.
void dry_run(Session& s, const vm::Module& module, const RunSettings& settings);
// Loads a bytecode file (and registers its source files for diagnostics).
[[nodiscard]] std::optional<vm::Module> load_module(Session& s, uint32_t file);

struct [[nodiscard]] RunResult {
  bool ok = true;
  bool usage_error = false;  // the run could not start: profile, start block
  uint64_t steps = 0;
  std::optional<std::vector<std::string>> screen;  // the NC-110 user screen at the end, a line a row (none: off)
};
// The module's source files as SourceManager indices, registered (and read, to quote
// their lines) on first use.
std::vector<uint32_t> source_files(Session& s, const vm::Module& m);
// Reports a problem at a block of a module's source map (what a run finds).
void report_at_block(Session& s, const vm::Module& module, uint32_t source, DiagId id, std::string message);
// The profile a module runs with: --machine if given, else the one it was compiled with.
const stdlib::Profile* module_profile(Session& s, const vm::Module& module);
RunResult run_module(Session& s, const vm::Module& module, const RunSettings& settings, TraceSink& trace);

// A run of a module that its caller drives a step at a time (the API's Run; run_module
// runs one to the end). A step is a block with `by_block`, else as far as the run goes
// before another process's turn.
class ModuleRun {
 public:
  enum class State { NotStarted, Running, Ended, Stopped, Error };
  // NotStarted when it cannot start (the profile, the start block, the sandbox or
  // the input script: reported).
  ModuleRun(Session& s, const vm::Module& m, const RunSettings& settings, TraceSink& trace, bool dry = false,
            bool by_block = false);
  ~ModuleRun();
  State state() const { return state_; }
  [[nodiscard]] State step();
  State stop();  // ends it now: what the runtime holds back goes to the trace as it stands
  uint64_t steps() const;
  const BlockMachine* machine() const;         // process 1's (none if it never started)
  std::optional<uint32_t> next_block() const;  // the source block process 1 runs next
  const screen::UserScreen* user_screen() const;
  // A problem at a block, as the runtime reports one (once).
  void report(uint32_t source, DiagId id, std::string message);

 private:
  struct Parts;
  State end(State how);
  TraceSink& trace_;
  std::unique_ptr<Parts> parts_;
  State state_ = State::NotStarted;
};

}  // namespace ncc
