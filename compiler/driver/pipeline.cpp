#include "pipeline.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <deque>
#include <filesystem>
#include <set>
#include <tuple>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check/check.h"
#include "devices/asset_store.h"
#include "devices/nc110_devices.h"
#include "frontend/frontend.h"
#include "lower/lower.h"
#include "runtime/machine.h"
#include "support/text.h"
#include "vm/processes.h"
#include "vm/program_run.h"

namespace ncc {

namespace {

// The steps (blocks, and a cycle's moves beyond its first) a run may take beyond the
// program's blocks (--max-steps sets another bound): a run, long loops included; the dry run of check and compile,
// which runs each block of a CAM file once and the loops of a parametric program (docs/limits.md).
constexpr uint64_t kDefaultExtraSteps = 100'000'000;
constexpr uint64_t kDryRunExtraSteps = 1'000'000;

// A source file named by a bytecode file, read only to quote its lines: never a
// device, a pipe or something huge.
std::string quotable_file(const std::string& path) {
  constexpr FileLimit kQuoted{64 << 20, "a source file a bytecode file names", true};
  int error = 0;
  return program_text(read_file(path, kQuoted, error).value_or(""));
}

}  // namespace

// The module's source files as SourceManager indices (registered on first use). A
// bytecode file names its sources by path; if one has gone, diagnostics still give
// file:line:col, without the quoted line.
std::vector<uint32_t> source_files(Session& s, const vm::Module& m) {
  std::vector<uint32_t> ids;
  for (const std::string& path : m.source_map.files) {
    uint32_t found = UINT32_MAX;
    for (uint32_t i = 0; i < s.sources.size(); ++i)
      if (s.sources.file(i).path() == path) found = i;
    if (found == UINT32_MAX) found = s.sources.add(path, quotable_file(path));
    ids.push_back(found);
  }
  return ids;
}

namespace {

// Turns runtime issues into diagnostics at the block, or the word, they concern.
// A loop meets the same problem again and again: each is reported once. The source
// files are registered (and read, to quote their lines) at the first issue: a run
// without one never reads source. A dry run's step limit is its bound (`bound` says
// which): a warning, not an error of the program.
class IssueReporter final : public RuntimeIssues {
 public:
  IssueReporter(Session& s, const vm::Module& m, bool dry, std::string bound)
      : s_(s), m_(m), dry_(dry), bound_(std::move(bound)) {}

  void issue(const RuntimeIssue& stopped) override {
    RuntimeIssue i = stopped;
    if (dry_ && i.id == DiagId::StepLimit) {
      i.id = DiagId::DryRunBound;
      i.message = bound_;
    }
    if (!seen_.insert({static_cast<int>(i.id), i.source, i.slot, i.code, i.nth}).second) return;
    // In a dry run a block the compiler already rejected would only repeat its errors;
    // a limit of the run stops it there all the same, and says so.
    const SourceMap& map = m_.source_map;
    const std::optional<SourceBlock> block = i.source < map.size() ? std::optional(map.block(i.source)) : std::nullopt;
    const bool run_limit = i.id == DiagId::DryRunBound || i.id == DiagId::RunMemory;
    if (dry_ && block && block->has_errors && !run_limit) return;
    if (!file_ids_) file_ids_ = source_files(s_, m_);
    const std::vector<uint32_t>& file_ids = *file_ids_;
    auto block_range = [&](const SourceBlock& b) {
      uint32_t file = b.file < file_ids.size() ? file_ids[b.file] : 0;
      return SourceRange{file, b.line, b.col, b.end_line, b.end_col};
    };
    SourceRange range;
    if (block) {
      const SourceBlock& b = *block;
      range = block_range(b);
      const uint32_t file = range.file;
      if (i.slot >= 0 || i.code >= 0) {
        int skip = i.nth;
        for (const WordPosition& p : map.words(i.source)) {
          if ((i.code >= 0 ? p.code == i.code : (p.code < 0 && p.slot == i.slot)) && skip-- == 0) {
            range = {file, p.line, p.col, p.line, p.end_col};
            break;
          }
        }
      }
    }
    std::vector<Note> notes;
    for (const auto& [source, text] : i.notes)
      notes.push_back({source < map.size() ? block_range(map.block(source)) : SourceRange{}, text});
    s_.diags.add({i.id, diag_info(i.id).severity, range, i.message, std::move(notes)});
  }

 private:
  Session& s_;
  const vm::Module& m_;
  std::optional<std::vector<uint32_t>> file_ids_;
  bool dry_;
  std::string bound_;
  std::set<std::tuple<int, uint32_t, int, int, int>> seen_;
};

// The profile a module runs with: --machine if given, else the one it was compiled with.
const stdlib::Profile* run_profile(Session& s, const vm::Module& m) {
  if (!s.profile) {
    auto p = stdlib::Profile::parse(s.sources, m.profile_name, m.profile_text, s.diags);
    if (!p) return nullptr;
    s.profile = std::move(*p);
  }
  return &*s.profile;
}

// A run that could not start: the profile, the start block, a sandbox or an input script.
RunResult cannot_start() {
  RunResult r;
  r.ok = false;
  r.usage_error = true;
  return r;
}

// A PLC signal of the input script: a memory of the module, its index, a format
// (BL BY IN LI RE LR; none: the memory's own) and the value, as a program writes
// it: SA12=1, SK250=8, SK2.IN=-5. Why not, when it is not one.
std::string plc_write(const vm::Module& m, std::string_view text, vm::PlcWrite& out) {
  const size_t equals = text.find('=');
  size_t name = 0;
  while (name < std::min(equals, text.size()) && std::isalpha(static_cast<unsigned char>(text[name]))) ++name;
  size_t space = 0;
  while (space < m.spaces.size() && !(m.spaces[space].memory && m.spaces[space].name == text.substr(0, name))) ++space;
  if (equals == std::string_view::npos || space == m.spaces.size()) return "not an answer";
  std::string_view ref = text.substr(name, equals - name), value = text.substr(equals + 1);
  const size_t dot = ref.find('.');
  uint32_t index = 0;
  if (dot != 0 && !ref.empty() && !parse_number<uint32_t>(ref.substr(0, dot))) return "the index is not a whole number";
  if (dot != 0 && !ref.empty()) index = *parse_number<uint32_t>(ref.substr(0, dot));
  static constexpr std::string_view kFormats[] = {"BL", "BY", "IN", "LI", "RE", "LR"};
  out.format = m.spaces[space].format;
  if (dot != std::string_view::npos) {
    const auto* f = std::find(std::begin(kFormats), std::end(kFormats), ref.substr(dot + 1));
    if (f == std::end(kFormats)) return "the format is none of BL BY IN LI RE LR";
    out.format = static_cast<MemFormat>(f - std::begin(kFormats));
  }
  const uint64_t bytes =
      out.format == MemFormat::Bit ? (uint64_t{index} + 8) / 8 : (uint64_t{index} + 1) * mem_size(out.format);
  if (bytes > m.spaces[space].size) return fmt::format("{} has {} bytes", m.spaces[space].name, m.spaces[space].size);
  // What the memory's format holds, as a store would take it (BL: 0 or 1).
  static constexpr VarType kTypes[] = {VarType::Byte, VarType::Byte, VarType::Integer,
                                       VarType::Long, VarType::Real, VarType::LongReal};
  auto v = parse_number<double>(value);
  double kept = v.value_or(0);
  const bool fits = v && (out.format == MemFormat::Bit ? *v == 0 || *v == 1
                                                       : convert_value(kTypes[static_cast<int>(out.format)], 0, kept));
  const bool whole = out.format != MemFormat::Real && out.format != MemFormat::LongReal;
  if (!fits || (whole && kept != *v))
    return fmt::format("'{}' is not a value of format {}", value, kFormats[static_cast<int>(out.format)]);
  out.space = static_cast<uint8_t>(space);
  out.text = text;
  out.index = index;
  out.value = *v;
  return {};
}

// The input script (--input): the operator's answers to INP, a line each, a number, a
// "text" or ENTER (keep the value offered), and the PLC's signals (SA12=1), each given when no
// process can go on without it; blank lines and '#' comments are skipped. Problems
// at their place.
bool read_answers(Session& s, const vm::Module& m, const std::string& path, std::vector<devices::Answer>& answers,
                  std::deque<vm::PlcWrite>& plc) {
  // A line an answer: a run that needs more has stopped long before.
  constexpr FileLimit kInputScript{64 << 20, "an input script"};
  auto text = read_file(path, kInputScript, s.diags);
  if (!text) return false;
  const uint32_t id = s.sources.add(path, std::move(*text));
  const SourceFile& f = s.sources.file(id);
  const uint32_t errors = s.diags.error_count();
  for (uint32_t n = 1; n <= f.line_count(); ++n) {
    std::string_view line = f.line(n);
    const size_t begin = line.find_first_not_of(" \t\r");
    if (begin == std::string_view::npos || line[begin] == '#') continue;
    const size_t end = line.find_last_not_of(" \t\r") + 1;
    std::string_view answer = line.substr(begin, end - begin);
    double v = 0;
    auto [stop, ec] = std::from_chars(answer.data(), answer.data() + answer.size(), v);
    vm::PlcWrite w;
    std::string why;
    if (answer == "ENTER")
      answers.push_back({});
    else if (ec == std::errc() && stop == answer.data() + answer.size() && std::isfinite(v))
      answers.push_back({v, {}});
    else if (answer.size() >= 2 && answer.front() == '"' && answer.back() == '"')
      answers.push_back({{}, std::string(answer.substr(1, answer.size() - 2))});
    else if ((why = plc_write(m, answer, w)).empty())
      plc.push_back(w);
    else
      s.diags.report(DiagId::InputScript, {id, n, static_cast<uint32_t>(begin + 1), n, static_cast<uint32_t>(end + 1)},
                     fmt::format("'{}' is {}: a line is an answer, a number, a \"text\" or ENTER to keep the value "
                                 "offered, or a PLC signal such as SA12=1",
                                 answer, why == "not an answer" ? why : "not a PLC signal: " + why));
  }
  return s.diags.error_count() == errors;
}

}  // namespace

// What a run holds besides its program or processes: the machine configuration, the reporter
// of what it finds, the ASSET sandbox, the operator's answers and the devices'
// state the processes share.
struct ModuleRun::Parts {
  MachineConfig config;
  std::unique_ptr<IssueReporter> reporter;
  std::unique_ptr<asset::Store> store;
  std::vector<devices::Answer> answers;
  devices::Nc110Run devices;
  std::deque<ProcessSink> process_sinks;     // a run of several processes: each event marked with its process
  std::unique_ptr<vm::ProgramRun> program;   // a run without process features (vm::Processes::needed)
  std::unique_ptr<vm::Processes> processes;  // else
};

ModuleRun::ModuleRun(Session& s, const vm::Module& m, const RunSettings& settings, TraceSink& trace, bool dry,
                     bool by_block)
    : trace_(trace), parts_(std::make_unique<Parts>()) {
  const stdlib::Profile* profile = run_profile(s, m);
  if (!profile) return;
  uint32_t errors = s.diags.error_count();
  MachineConfig& config = parts_->config = stdlib::load_machine_config(*profile, s.diags);
  if (s.diags.error_count() != errors) return;
  if (settings.block_skip) config.block_skip = true;
  if (settings.optional_stop) config.optional_stop = true;
  config.trace_machine_frame = settings.trace_machine_frame;
  vm::VmOptions options;
  const uint64_t blocks = m.source_map.size();
  options.max_steps = settings.max_steps.value_or(blocks + (dry ? kDryRunExtraSteps : kDefaultExtraSteps));
  options.max_memory = settings.max_memory ? *settings.max_memory << 20 : config.run_memory;
  parts_->reporter = std::make_unique<IssueReporter>(
      s, m, dry,
      diag_message(DiagId::DryRunBound, options.max_steps,
                   settings.max_steps
                       ? std::string("--max-steps")
                       : fmt::format("the program's {} blocks and {} more, the default; --max-steps N sets another",
                                     blocks, kDryRunExtraSteps)));
  options.trace_blocks = settings.trace_blocks;
  // Each process runs on the motion runtime's Machine.
  auto make_machine = [this, &m, &trace, dry](uint8_t process, RemainingPaths* others) {
    TraceSink& sink = others ? parts_->process_sinks.emplace_back(trace, process) : trace;
    auto machine = std::make_unique<Machine>(m.semantics, parts_->config, sink, *parts_->reporter);
    machine->set_stop_on_error(!dry);
    machine->set_remaining_paths(others);
    machine->power_on();
    return std::unique_ptr<BlockMachine>(std::move(machine));
  };
  // Each process has the NC-110 controller's devices, sharing the run's.
  auto make_devices = [this](uint8_t) -> std::unique_ptr<ServiceHost> {
    return std::make_unique<devices::Nc110Devices>(parts_->devices);
  };
  vm::ProcessSetup setup{m, make_machine, make_devices, *parts_->reporter, options};
  setup.dry = dry;
  setup.by_block = by_block;
  setup.processes = config.processes;
  // ASSET files (NC-110 chapter 5) in the sandbox of --files; a dry run leaves them
  // alone: they are the machine's, not the program's.
  if (!dry) {
    if (!settings.files.empty()) {
      std::string why;
      parts_->store = asset::Store::open(settings.files, {.device_bytes = config.asset.device_bytes}, why);
      if (!parts_->store) {
        s.diags.report(DiagId::FileUnreadable, {}, settings.files, why);
        return;
      }
      if (!parts_->store->prepared()) s.diags.report(DiagId::FilesUnprepared, {}, settings.files);
    }
    if (!settings.input.empty() && !read_answers(s, m, settings.input, parts_->answers, setup.plc)) return;
    parts_->devices.answers = &parts_->answers;
    parts_->devices.store = parts_->store.get();
    parts_->devices.files = true;
    parts_->devices.channels = {.channels = config.asset.channels, .structures = config.asset.structures};
  }

  // Process 1 runs the programs of the medium from the first, or from a main block.
  size_t first = 0;
  if (settings.start_block) {
    std::string name = fmt::format(":{}", *settings.start_block);
    first = m.entries.size();
    for (size_t i = 0; i < m.entries.size() && first == m.entries.size(); ++i)
      if (m.entries[i].name == name) first = i;  // the first on the medium
    if (first == m.entries.size()) {
      s.diags.report(DiagId::StartBlockNotFound, {}, *settings.start_block);
      return;
    }
  }
  bool started = true;
  if (vm::Processes::needed(m)) {
    setup.options.look_ahead = config.look_ahead;  // only processes show it (NC-110 §2.16)
    parts_->processes = std::make_unique<vm::Processes>(std::move(setup));
    started = parts_->processes->begin(first);
  } else {
    setup.options.by_block = by_block;
    parts_->program = std::make_unique<vm::ProgramRun>(m, make_machine(1, nullptr), make_devices(1), *parts_->reporter,
                                                       setup.options, true);
    parts_->program->start(first);
  }
  if (started) {
    state_ = State::Running;
  } else {
    state_ = State::Error;
    trace_.flush();
  }
}

ModuleRun::~ModuleRun() = default;

ModuleRun::State ModuleRun::step() {
  if (state_ != State::Running) return state_;
  if (vm::ProgramRun* program = parts_->program.get()) {
    if (program->running() && program->step() == vm::RunStatus::Error) return end(State::Error);
    return program->running() ? state_ : end(State::Ended);
  }
  switch (parts_->processes->step()) {
    case vm::Processes::Turn::Continue: return parts_->processes->running() ? state_ : end(State::Ended);
    case vm::Processes::Turn::Ended: return end(State::Ended);
    case vm::Processes::Turn::Error: return end(State::Error);
  }
  return state_;
}

ModuleRun::State ModuleRun::stop() { return state_ == State::Running ? end(State::Stopped) : state_; }

ModuleRun::State ModuleRun::end(State how) {
  if (parts_->program)
    parts_->program->finish(how == State::Ended);
  else
    parts_->processes->finish(how == State::Ended);
  trace_.flush();
  return state_ = how;
}

uint64_t ModuleRun::steps() const {
  return parts_->program ? parts_->program->steps() : parts_->processes ? parts_->processes->steps() : 0;
}

const BlockMachine* ModuleRun::machine() const {
  return parts_->program ? &parts_->program->machine() : parts_->processes ? parts_->processes->machine(1) : nullptr;
}

std::optional<uint32_t> ModuleRun::next_block() const {
  if (state_ != State::Running) return std::nullopt;
  return parts_->program ? parts_->program->next_source() : parts_->processes->next_source();
}

const screen::UserScreen* ModuleRun::user_screen() const {
  return parts_->program || parts_->processes ? &parts_->devices.screen : nullptr;
}

void ModuleRun::report(uint32_t source, DiagId id, std::string message) {
  parts_->reporter->issue({id, std::move(message), source});
}

namespace {

RunResult execute(Session& s, const vm::Module& m, const RunSettings& settings, TraceSink& trace, bool dry) {
  ModuleRun run(s, m, settings, trace, dry);
  if (run.state() == ModuleRun::State::NotStarted) return cannot_start();
  ModuleRun::State state = run.state();
  while (state == ModuleRun::State::Running) state = run.step();
  RunResult result;
  result.ok = state == ModuleRun::State::Ended && !s.diags.has_errors();
  result.steps = run.steps();
  if (run.user_screen()->on()) result.screen = run.user_screen()->lines();
  return result;
}

}  // namespace

std::vector<Diagnostic> diagnostics_in_order(const Session& s) {
  std::vector<Diagnostic> list = s.diags.all();
  std::stable_sort(list.begin(), list.end(), [](const Diagnostic& a, const Diagnostic& b) {
    auto key = [](const Diagnostic& d) {
      return std::tuple(!d.range.valid(), d.range.file, d.range.line, d.range.col);
    };
    return key(a) < key(b);
  });
  return list;
}

bool load_profile(Session& s, const std::string& path) {
  auto p = stdlib::Profile::load(s.sources, path, s.diags);
  if (!p) return false;
  s.profile = std::move(*p);
  return true;
}

namespace {

constexpr std::string_view kBytecodeMagic = "NCCB";

// A regular file whose first bytes are a bytecode file's magic.
bool bytecode_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st;
  char magic[4];
  const bool found = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) &&
                     ::pread(fd, magic, sizeof magic, 0) == sizeof magic &&
                     std::string_view(magic, 4) == kBytecodeMagic;
  ::close(fd);
  return found;
}

}  // namespace

// A bytecode file in a regular file is read when it is loaded, a section at a time
// (load_module): here its path alone is registered. Anything else is read whole (a
// pipe cannot be read twice).
std::optional<std::pair<FileKind, uint32_t>> read_input(Session& s, const std::string& path) {
  if (bytecode_file(path)) return std::pair{FileKind::Bytecode, s.sources.add(path, "")};
  auto text = read_file(path, kProgramFile, s.diags);
  if (!text) return std::nullopt;
  if (text->starts_with(kBytecodeMagic)) return std::pair{FileKind::Bytecode, s.sources.add(path, std::move(*text))};
  return std::pair{FileKind::Source, s.sources.add(path, program_text(std::move(*text)))};
}

namespace {

// The front end of `dialect` over the session's profile, read and checked in full
// (machine data too: a profile with errors stops the command, exit status 2, before
// the program is read).
std::unique_ptr<Frontend> frontend_for(Session& s, const std::string& dialect) {
  if (!s.profile && !load_profile(s, "")) return nullptr;
  uint32_t errors = s.diags.error_count();
  auto frontend = make_frontend(dialect, *s.profile, s.diags);
  stdlib::load_machine_config(*s.profile, s.diags);
  std::vector<std::string_view> others = dialect_names();  // a profile may serve several dialects
  std::erase(others, std::string_view(dialect));
  s.profile->report_unused(s.diags, others);
  if (!frontend || s.diags.error_count() != errors) return nullptr;
  if (!s.processes.empty() && frontend->rules().processes < 2) {
    s.diags.report(DiagId::ProcessOption, {}, fmt::format("{}={}", s.processes[0].first, s.processes[0].second),
                   fmt::format("the {} dialect runs one process", dialect));
    return nullptr;
  }
  return frontend;
}

// Checks and lowers the first unit's leading blocks as the reader hands them over,
// and drops them. It stops for good at the first block with a flow statement (jumps,
// loops, calls, returns: what is decided by blocks read later), and
// at the first error, so that what follows is checked and lowered as a whole program
// would be; what its checks find is reported with the others (StreamChecks).
class Stream final : public BlockSink {
 public:
  Stream(Session& s, const CheckRules& rules, StreamObserver* observer = nullptr)
      : checks(rules), lowering(s.sources), s_(s), rules_(rules), observer_(observer) {}

  void take(ir::Program& program, ir::Unit& unit) override {
    if (stopped_ || !program.units.empty()) return;
    size_t n = 0;
    bool held = false;  // the last block waits for the one after it (looks_ahead)
    for (; n < unit.blocks.size(); ++n) {
      ir::Block& b = unit.blocks[n];
      if (s_.diags.error_count() || checks.found_errors() || !settled(b) ||
          (observer_ && !observer_->streams(program, b))) {
        stopped_ = true;
        break;
      }
      const bool ahead = observer_ && observer_->looks_ahead(program, b);
      if (ahead && n + 1 == unit.blocks.size()) {
        held = true;
        break;
      }
      checks.block(program, b);
      lowering.block(program, unit, b);
      if (observer_) observer_->streamed(program, b, ahead ? &unit.blocks[n + 1] : nullptr);
      if (!b.label.empty()) unit.streamed_labels.push_back({*b.number, b.range});
    }
    unit.blocks.erase(unit.blocks.begin(), unit.blocks.begin() + static_cast<std::ptrdiff_t>(n));
    unit.streamed += static_cast<uint32_t>(n);
    // The expressions made since the last time belong to the blocks just dropped
    // (the reader holds none of them when it calls): they go too, but a held block's,
    // the last made, which move down to take their place.
    if (stopped_) return;
    if (expressions_ != SIZE_MAX) {
      if (held)
        move_expressions(program, unit.blocks.front(), expressions_);
      else
        program.exprs.resize(expressions_);
    }
    if (!held) expressions_ = program.exprs.size();
  }

  StreamChecks checks;
  StreamLowering lowering;

 private:
  // Nothing read later changes how this block is checked or lowered. (A code chosen
  // at run time, NC-110 GE1, is not: the codes it may be are added once the whole
  // program is read. Nor is a label that may end a block range, or that must be
  // unique: the unit keeps the others, N and the block's number, Unit::streamed_labels.)
  bool settled(const ir::Block& b) const {
    if (!b.label.empty() && (rules_.block_ranges || rules_.unique_labels || !b.number ||
                             b.label != ir::Unit::StreamedLabel{*b.number, {}}.label()))
      return false;
    for (const ir::Word& w : b.words)
      if (w.code == ir::kDynamicCode) return false;
    for (const ir::Stmt& s : b.stmts)
      if (s.kind != ir::StmtKind::Machine && s.kind != ir::StmtKind::Assign && s.kind != ir::StmtKind::Comment &&
          s.kind != ir::StmtKind::Display &&
          !(s.kind == ir::StmtKind::Service && service_info(s.service).device == Device::Asset))
        return false;
    return true;
  }

  // The expressions of `b`, the last the reader made (from the first it reaches at
  // or past `mark`, operands included), moved down to `mark`, and the pool cut after
  // them.
  static void move_expressions(ir::Program& program, ir::Block& b, size_t mark) {
    size_t first = program.exprs.size();
    std::vector<ir::ExprId> todo;
    std::set<ir::ExprId> seen;
    for_each_expr(b, [&](ir::ExprId id) { todo.push_back(id); });
    while (!todo.empty()) {
      const ir::ExprId id = todo.back();
      todo.pop_back();
      if (id == ir::kNoExpr || id < mark || !seen.insert(id).second) continue;
      first = std::min<size_t>(first, id);
      todo.push_back(program.exprs[id].a);
      todo.push_back(program.exprs[id].b);
    }
    const auto shift = static_cast<ir::ExprId>(first - mark);
    if (shift == 0) return;
    auto moved = [&](ir::ExprId& id) {
      if (id != ir::kNoExpr && id >= first) id -= shift;
    };
    for_each_expr(b, moved);
    for (size_t i = first; i < program.exprs.size(); ++i) {
      ir::Expr e = program.exprs[i];
      moved(e.a);
      moved(e.b);
      program.exprs[i - shift] = e;
    }
    program.exprs.resize(program.exprs.size() - shift);
  }

  // Every expression a settled block refers to (its words and its statements').
  template <typename F>
  static void for_each_expr(ir::Block& b, F&& f) {
    for (ir::Word& w : b.words) f(w.value);
    for (ir::Stmt& s : b.stmts) {
      f(s.target);
      f(s.value);
      f(s.cond);
      for (auto& item : s.items) f(item.value);
      for (auto& arg : s.args) f(arg.value);
    }
  }

  Session& s_;
  const CheckRules& rules_;
  StreamObserver* observer_;
  bool stopped_ = false;
  size_t expressions_ = SIZE_MAX;  // the program's expressions after the last blocks taken
};

}  // namespace

namespace {

// A module runs only verified, whether it was loaded or compiled here: what the
// compiler makes, the verifier checks as it checks a file (a failure is ncc's fault).
std::optional<vm::Module> verified(Session& s, uint32_t file, vm::Module m) {
  const std::string why = vm::verify(m);
  if (why.empty()) return m;
  s.diags.report(DiagId::BytecodeInvalid, {}, s.sources.file(file).path() + " (compiled)", why);
  return std::nullopt;
}

}  // namespace

std::optional<ir::Program> analyse(Session& s, uint32_t file, const std::string& dialect) {
  auto frontend = frontend_for(s, dialect);
  if (!frontend) return std::nullopt;
  ir::Program program = frontend->read(s.sources, file, s.diags, {s.library, s.fast_path, nullptr, s.processes});
  if (!s.diags.limit_reached()) check(program, frontend->rules(), s.diags);
  return program;
}

std::optional<vm::Module> compile_source(Session& s, uint32_t file, const std::string& dialect) {
  auto frontend = frontend_for(s, dialect);
  if (!frontend) return std::nullopt;
  Stream stream(s, frontend->rules());
  stream.lowering.expect(s.sources.file(file).text().size());
  ir::Program program =
      frontend->read(s.sources, file, s.diags, {s.library, s.fast_path, s.stream ? &stream : nullptr, s.processes});
  if (!s.diags.limit_reached()) check(program, frontend->rules(), s.diags, &stream.checks);
  s.library_input = program.library;
  return verified(s, file, stream.lowering.finish(program, *s.profile));
}

std::optional<vm::Module> compile_source(Session& s, uint32_t file, const std::string& dialect,
                                         StreamObserver& observer, ir::Program& rest) {
  auto frontend = frontend_for(s, dialect);
  if (!frontend) return std::nullopt;
  Stream stream(s, frontend->rules(), &observer);
  stream.lowering.expect(s.sources.file(file).text().size());
  rest = frontend->read(s.sources, file, s.diags, {s.library, s.fast_path, s.stream ? &stream : nullptr, s.processes});
  if (!s.diags.limit_reached()) check(rest, frontend->rules(), s.diags, &stream.checks);
  s.library_input = rest.library;
  return verified(s, file, stream.lowering.finish(rest, *s.profile));
}

std::optional<ir::Program> read_whole(Session& s, uint32_t file, const std::string& dialect) {
  Diagnostics quiet(0);
  auto frontend = s.profile ? make_frontend(dialect, *s.profile, quiet) : nullptr;
  if (!frontend) return std::nullopt;
  return frontend->read(s.sources, file, quiet, {s.library, s.fast_path, nullptr, s.processes});
}

std::vector<FnCall> power_on_functions(Session& s, const std::string& dialect) {
  return s.profile ? power_on_functions(s, dialect, *s.profile) : std::vector<FnCall>{};
}

std::vector<FnCall> power_on_functions(Session& s, const std::string& dialect, const stdlib::Profile& profile) {
  std::vector<FnCall> calls;
  Diagnostics quiet(0);
  auto frontend = make_frontend(dialect, profile, quiet);
  if (!frontend) return calls;
  const uint32_t empty = s.sources.add("<power-on>", "");
  const ir::Program program = frontend->read(s.sources, empty, quiet, {s.library, s.fast_path, nullptr, s.processes});
  for (uint16_t i : program.semantics.power_on)
    calls.insert(calls.end(), program.semantics.codes[i].calls.begin(), program.semantics.codes[i].calls.end());
  return calls;
}

vm::Module lower_program(Session& s, const ir::Program& program) { return lower(program, s.sources, *s.profile); }

void dry_run(Session& s, const vm::Module& module, const RunSettings& settings) {
  if (s.library_input) return;  // its programs run when a caller calls them (decision 71 of iso)
  NullSink none;
  (void)execute(s, module, settings, none, true);  // its problems are the session's diagnostics
}

std::optional<vm::Module> load_module(Session& s, uint32_t file) {
  const SourceFile& f = s.sources.file(file);
  if (!f.text().empty()) return vm::read_module(f.text(), f.path(), s.diags);
  const int fd = ::open(f.path().c_str(), O_RDONLY | O_CLOEXEC);
  struct stat st;
  int error = fd < 0 || ::fstat(fd, &st) != 0 ? errno : 0;
  if (!error && static_cast<uint64_t>(st.st_size) > kProgramFile.bytes) error = EFBIG;
  std::optional<vm::Module> m;
  if (error)
    s.diags.report(DiagId::FileUnreadable, {}, f.path(), read_error(error, kProgramFile));
  else
    m = vm::read_module(fd, static_cast<uint64_t>(st.st_size), f.path(), s.diags);
  if (fd >= 0) ::close(fd);
  return m;
}

void report_at_block(Session& s, const vm::Module& module, uint32_t source, DiagId id, std::string message) {
  IssueReporter(s, module, false, {}).issue({id, std::move(message), source, -1, -1});
}

const stdlib::Profile* module_profile(Session& s, const vm::Module& module) { return run_profile(s, module); }

RunResult run_module(Session& s, const vm::Module& module, const RunSettings& settings, TraceSink& trace) {
  return execute(s, module, settings, trace, false);
}

}  // namespace ncc
