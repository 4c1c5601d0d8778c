// ncc: the command line. Exit status: 0 success, 1 the program has errors, 2 usage
// or I/O errors (a file that cannot be read or written, a bad option or profile, a
// bytecode file that is not sound).
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "driver/pipeline.h"
#include "files.h"
#include "frontend/frontend.h"
#include "progress.h"
#include "regime.h"
#include "simulate.h"
#include "translate/structured.h"
#include "translate/translate.h"

namespace ncc {
namespace {

constexpr int kOk = 0, kProgramErrors = 1, kUsage = 2;

struct Command {
  std::string_view name;
  std::string_view summary;
  std::string_view usage;
  std::string_view options;      // the command's own options, for --help
  std::string_view shared = {};  // options it shares with others
};

constexpr std::string_view kCommonOptions =
    R"(  --dialect NAME            source dialect: gost, nc110, pp, iso (default gost)
  --machine FILE            machine profile (TOML, docs/profile.md); default: built in
  --lib DIR                 program library: where called programs are found (NC-110 CLS, pp G72, iso M98 G65)
  --process N=NAME          NC-110: program NAME[/MPn] of the library starts in process N (2..5) with the run,
                            as the keyboard's SPG selects it (chapter 4); once for each process
  --no-fast-path            read every block with the ANTLR parser (the fast path must give the same IR)
  --no-stream               hold the whole program's IR before checking and lowering it (the stream
                            must give the same module and diagnostics)
  --diagnostics-format F    text | json | sarif (default text)
  --error-limit N           stop after N errors (default 100, 0 = no limit)
  --color WHEN              auto | always | never (default auto)
  -h, --help                show this help
)";

// What a drawing's run takes of `ncc run`'s options.
constexpr std::string_view kSimulationOptions =
    R"(  --block-skip              the block-skip switch is on: '/' parts are skipped
  --optional-stop           the optional-stop switch is on: M01 stops
  --start-block N           start at main block ':N' (GOST 20999 §2.6)
  --max-steps N             stop after N steps (default: the program's blocks + 100000000)
  --max-memory MIB          stop when the runtime holds more for later moves (default: the profile's
                            limits.run_memory_mib, 256)
  --files DIR               NC-110: the ASSET sandbox the run reads
  --input FILE              NC-110: the operator's answers to INP
)";

constexpr Command kCommands[] = {
    {"check", "check a program and report every problem", "ncc check [options] FILE",
     R"(  --block-skip              run the dry run with the block-skip switch on
  --optional-stop           run the dry run with the optional-stop switch on
  --max-steps N             stop the dry run after N steps: blocks, and moves beyond a block's first
                            (default: the program's blocks + 1000000), with a warning (NC4092): a long
                            loop is not an error
  --max-memory MIB          stop the dry run when the runtime holds more for later moves (default:
                            the profile's limits.run_memory_mib, 256)
)"},
    {"compile", "compile a program to a bytecode file", "ncc compile [options] FILE -o OUT.ncb",
     R"(  -o FILE                   the bytecode file to write
  --max-steps N             stop the dry run after N steps: blocks, and moves beyond a block's first
                            (default: the program's blocks + 1000000), with a warning (NC4092): a long
                            loop is not an error
  --max-memory MIB          stop the dry run when the runtime holds more for later moves (default:
                            the profile's limits.run_memory_mib, 256)
)"},
    {"run", "run a program (source or .ncb) and write its trace", "ncc run [options] FILE",
     R"(  --trace FILE              write the trace to FILE ('-' = stdout, the default; 'none' = no trace)
  --trace-format F          text | jsonl | canon (default text; docs/trace.md)
  --trace-frame F           work | machine: positions from the active origin (default), or in machine
                            coordinates, offsets and shifts included (to compare runs through other origins)
  --trace-blocks            a 'block' event as each block starts (which blocks ran, how often)
  --max-steps N             stop after N steps: the blocks run, and the moves a block makes beyond its
                            first, a cycle's holes and pecks (default: the program's blocks + 100000000)
  --max-memory MIB          stop when the runtime holds more for later moves (default: the profile's
                            limits.run_memory_mib, 256)
  --block-skip              the block-skip switch is on: '/' parts are skipped
  --optional-stop           the optional-stop switch is on: M01 stops
  --start-block N           start at main block ':N' (GOST 20999 §2.6)
  --files DIR               the ASSET sandbox of NC-110 file I/O (docs/asset.md; 'ncc files init DIR')
  --input FILE              the operator's answers to NC-110 INP, a line each: a number, or ENTER;
                            and the PLC's signals a WAI waits for: SA12=1
  --screen                  after the trace, the NC-110 user screen as the run left it
  --time                    the cycle time of the run: cutting and auxiliary, by each time model (feed,
                            trapezoid, scurve; docs/simulator.md), instead of the trace; with --trace
                            FILE --trace-frame machine, after it
  --time-format F           text | json (default text)
)"},
    {"plot", "draw the tool path of a program (source or .ncb) as SVG", "ncc plot [options] FILE -o OUT.svg",
     R"(  -o FILE                   the drawing to write ('-' = stdout)
  --view V                  xy (from above, the default), xz (from the front), yz (from the right) or iso
  --tolerance MM            the largest distance between an arc and the chords drawn for it where the view
                            does not show it as an arc (default 0.001)
  --size PX                 the drawing's longer side (default 1000)
)",
     kSimulationOptions},
    {"view", "write a page that shows the tool path in 3-D, block by block", "ncc view [options] FILE -o OUT.html",
     R"(  -o FILE                   the page to write ('-' = stdout): one file, no network needed
  --stock RANGES            the stock: X0:100,Y0:60,Z-20:0 (default: the profile's [stock], else the box
                            round the cutting moves up to the work zero)
  --grid MM                 the cell of the machined surface's height map (default: from the stock's size)
  --tolerance MM            how far the drawn path may leave the tool's when moves are merged (default 0.01)
)",
     kSimulationOptions},
    {"regime", "compute spindle speed and feed from the tool and the material", "ncc regime [options]", ""},
    {"translate", "write a program in another dialect",
     "ncc translate [options] --to DIALECT [--flatten] FILE [-o OUT]",
     R"(  --to DIALECT              the target: gost, nc110, pp, iso or linuxcnc (RS274NGC as LinuxCNC 2.9 reads it)
  --flatten                 run the program and write the plain motion blocks it makes (docs/translate.md);
                            without it, the program's parameters, loops and subprograms are kept (iso)
  -o FILE                   the program to write ('-' = stdout, the default); nothing is written when
                            the program has errors or the target cannot say what it does
  --target-machine FILE     the machine profile of the target (default: the source's, --machine)
  --block-skip              the block-skip switch is on while flattening: '/' parts are skipped
  --optional-stop           the optional-stop switch is on while flattening
  --max-steps N             stop flattening after N steps (default: the program's blocks + 100000000)
  --max-memory MIB          stop flattening when the runtime holds more for later moves (default: the
                            profile's limits.run_memory_mib, 256)
  --files DIR               NC-110: the ASSET sandbox the run reads
  --input FILE              NC-110: the operator's answers to INP
)"},
    {"disasm", "print the bytecode of a program (source or .ncb)", "ncc disasm [options] FILE", ""},
    {"ir", "print the intermediate representation of a program", "ncc ir [options] FILE", ""},
    {"files", "make, fill and print the ASSET files of NC-110 file I/O", "ncc files COMMAND DIR ...", ""},
};

void print_main_help(std::FILE* out) {
  std::fprintf(
      out, "ncc - compiler, checker and VM for CNC part programs\n\nusage: ncc COMMAND [options] FILE\n\ncommands:\n");
  for (const Command& c : kCommands)
    std::fprintf(out, "  %-9s %s\n", std::string(c.name).c_str(), std::string(c.summary).c_str());
  std::fprintf(out, "\n'ncc COMMAND --help' describes a command and its options.\n");
  std::fprintf(out, "exit status: 0 success, 1 the program has errors, 2 usage or I/O errors\n");
}

void print_command_help(const Command& c) {
  std::printf("usage: %s\n\n%s.\n\noptions:\n%s%s%s", std::string(c.usage).c_str(), std::string(c.summary).c_str(),
              std::string(c.options).c_str(), std::string(c.shared).c_str(), std::string(kCommonOptions).c_str());
}

struct Options {
  std::string command;
  std::string input;
  std::string output;
  std::string dialect = "gost";
  std::string machine;
  std::string library;
  std::vector<std::pair<uint8_t, std::string>> processes;
  bool fast_path = true;
  bool stream = true;
  std::string trace = "-";
  TraceFormat trace_format = TraceFormat::Text;
  DiagFormat diag_format = DiagFormat::Text;
  uint32_t error_limit = 100;
  std::string color = "auto";
  RunSettings run;
  std::string to;  // translate
  bool flatten = false;
  std::string target_machine;
  bool time = false;  // run --time
  bool time_json = false;
  sim::View view = sim::View::XY;   // plot
  std::optional<double> tolerance;  // plot, view
  double size = 1000;
  std::string stock;  // view
  double grid = 0;
};

// A positive finite number of mm or px.
bool parse_positive(const std::string& text, double& out) {
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
  return error == std::errc() && end == text.data() + text.size() && std::isfinite(out) && out > 0;
}

bool parse_number(const std::string& text, uint64_t& out) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 19) return false;
  out = std::stoull(text);
  return true;
}

// Returns an error message, or "" when the arguments are good.
std::string parse_args(const std::vector<std::string>& args, const Command& command, Options& o) {
  bool trace_given = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= args.size()) return false;
      out = args[++i];
      return true;
    };
    auto number = [&](uint64_t& out) {
      std::string text;
      return value(text) && parse_number(text, out);
    };
    auto allowed = [&](std::string_view option) {
      return command.options.find(option) != std::string_view::npos ||
             command.shared.find(option) != std::string_view::npos;
    };
    std::string text;
    uint64_t n = 0;
    if (a == "--dialect") {
      if (!value(o.dialect)) return "--dialect needs a name";
    } else if (a == "--machine") {
      if (!value(o.machine)) return "--machine needs a file";
    } else if (a == "--lib") {
      if (!value(o.library)) return "--lib needs a directory";
    } else if (a == "--process") {
      // N=NAME: a process 2..5 (1 runs FILE), a program name as EXE writes it.
      if (!value(text) || text.size() < 3 || text[0] < '2' || text[0] > '5' || text[1] != '=')
        return "--process needs N=NAME: a process 2 to 5 and a program of the library";
      for (const auto& [process, name] : o.processes)
        if (process == text[0] - '0')
          return fmt::format("--process {}: process {} already runs {}", text, process, name);
      o.processes.push_back({static_cast<uint8_t>(text[0] - '0'), text.substr(2)});
    } else if (a == "--no-fast-path") {
      o.fast_path = false;
    } else if (a == "--no-stream") {
      o.stream = false;
    } else if (a == "--diagnostics-format") {
      if (!value(text)) return "--diagnostics-format needs text, json or sarif";
      if (text == "text")
        o.diag_format = DiagFormat::Text;
      else if (text == "json")
        o.diag_format = DiagFormat::Json;
      else if (text == "sarif")
        o.diag_format = DiagFormat::Sarif;
      else
        return "--diagnostics-format must be text, json or sarif";
    } else if (a == "--error-limit") {
      if (!number(n) || n > UINT32_MAX) return "--error-limit needs a number";
      o.error_limit = static_cast<uint32_t>(n);
    } else if (a == "--color") {
      if (!value(o.color) || (o.color != "auto" && o.color != "always" && o.color != "never"))
        return "--color must be auto, always or never";
    } else if (a == "-o" && allowed("-o FILE")) {
      if (!value(o.output)) return "-o needs a file";
    } else if (a == "--trace" && allowed("--trace FILE")) {
      if (!value(o.trace)) return "--trace needs a file";
      trace_given = true;
    } else if (a == "--trace-format" && allowed("--trace-format")) {
      if (!value(text)) return "--trace-format needs text, jsonl or canon";
      if (text == "text")
        o.trace_format = TraceFormat::Text;
      else if (text == "jsonl")
        o.trace_format = TraceFormat::Jsonl;
      else if (text == "canon")
        o.trace_format = TraceFormat::Canon;
      else
        return "--trace-format must be text, jsonl or canon";
    } else if (a == "--to" && allowed("--to DIALECT")) {
      if (!value(o.to) || !translate::is_target(o.to)) return "--to needs a dialect: gost, nc110, pp, iso or linuxcnc";
    } else if (a == "--flatten" && allowed("--flatten")) {
      o.flatten = true;
    } else if (a == "--target-machine" && allowed("--target-machine")) {
      if (!value(o.target_machine)) return "--target-machine needs a file";
    } else if (a == "--trace-frame" && allowed("--trace-frame")) {
      if (!value(text) || (text != "work" && text != "machine")) return "--trace-frame must be work or machine";
      o.run.trace_machine_frame = text == "machine";
    } else if (a == "--max-steps" && allowed("--max-steps")) {
      if (!number(n)) return "--max-steps needs a number";
      o.run.max_steps = n;
    } else if (a == "--max-memory" && allowed("--max-memory")) {
      if (!number(n) || n < 1 || n > (1 << 20)) return "--max-memory needs a number of MiB, 1 to 1048576";
      o.run.max_memory = n;
    } else if (a == "--trace-blocks" && allowed("--trace-blocks")) {
      o.run.trace_blocks = true;
    } else if (a == "--block-skip" && allowed("--block-skip")) {
      o.run.block_skip = true;
    } else if (a == "--optional-stop" && allowed("--optional-stop")) {
      o.run.optional_stop = true;
    } else if (a == "--screen" && allowed("--screen")) {
      o.run.screen = true;
    } else if (a == "--input" && allowed("--input FILE")) {
      if (!value(o.run.input)) return "--input needs a file";
    } else if (a == "--files" && allowed("--files DIR")) {
      if (!value(o.run.files)) return "--files needs a directory";
    } else if (a == "--time" && allowed("--time ")) {
      o.time = true;
    } else if (a == "--time-format" && allowed("--time-format")) {
      if (!value(text) || (text != "text" && text != "json")) return "--time-format must be text or json";
      o.time_json = text == "json";
    } else if (a == "--view" && allowed("--view")) {
      if (!value(text) || !sim::parse_view(text, o.view)) return "--view must be xy, xz, yz or iso";
    } else if (a == "--tolerance" && allowed("--tolerance")) {
      double t = 0;
      if (!value(text) || !parse_positive(text, t)) return "--tolerance needs a number of mm greater than 0";
      o.tolerance = t;
    } else if (a == "--size" && allowed("--size")) {
      if (!value(text) || !parse_positive(text, o.size) || o.size < 100 || o.size > 100000)
        return "--size needs a number of px, 100 to 100000";
    } else if (a == "--stock" && allowed("--stock")) {
      if (!value(o.stock)) return "--stock needs the ranges of X, Y and Z: X0:100,Y0:60,Z-20:0";
    } else if (a == "--grid" && allowed("--grid")) {
      if (!value(text) || !parse_positive(text, o.grid)) return "--grid needs a number of mm greater than 0";
    } else if (a == "--start-block" && allowed("--start-block")) {
      if (!number(n) || n > UINT32_MAX) return "--start-block needs a block number";
      o.run.start_block = static_cast<uint32_t>(n);
    } else if (a.size() > 1 && a[0] == '-' && a != "-") {
      return fmt::format("unknown option '{}' for 'ncc {}'", a, command.name);
    } else if (o.input.empty()) {
      o.input = a;
    } else {
      return fmt::format("unexpected argument '{}': one input file is read", a);
    }
  }
  if (o.input.empty()) return "no input file";
  if ((o.command == "compile" || o.command == "plot" || o.command == "view") && o.output.empty())
    return o.command + " needs -o FILE";
  // The time is measured in machine coordinates; a trace from the work zero would need
  // a second run, and a second run would write the ASSET files again.
  // `ncc run --time` prints the time alone. It is measured in machine coordinates; a
  // trace from the work zero beside it would need a second run, and a second run
  // would write the ASSET files again.
  if (o.time && !trace_given) o.trace = "none";
  if (o.time && o.trace != "none" && !o.run.trace_machine_frame)
    return "--time with a trace needs --trace-frame machine";
  if (o.time && o.trace == "none") o.run.trace_machine_frame = true;
  if (o.command == "translate" && o.to.empty()) return "translate needs --to DIALECT";
  return {};
}

class Cli {
 public:
  explicit Cli(Options o) : o_(std::move(o)), s_(o_.error_limit) {
    s_.library = o_.library;
    s_.processes = o_.processes;
    s_.fast_path = o_.fast_path;
    s_.stream = o_.stream;
    color_ = o_.color == "always" || (o_.color == "auto" && isatty(STDERR_FILENO) && !std::getenv("NO_COLOR"));
  }

  int run() {
    // A bytecode file runs with the profile it holds unless --machine names another;
    // source without --machine gets the built-in default when it is analysed.
    if (!o_.machine.empty() && !load_profile(s_, o_.machine)) return finish(kUsage, stderr);
    auto input = read_input(s_, o_.input);
    if (!input) return finish(kUsage, stderr);
    auto [kind, file] = *input;
    if (o_.command == "check") return check(kind, file);
    if (o_.command == "compile") return compile(kind, file);
    if (o_.command == "run") return run(kind, file);
    if (o_.command == "disasm") return disasm(kind, file);
    if (o_.command == "translate") return translate(kind, file);
    if (o_.command == "plot" || o_.command == "view") return draw(kind, file);
    return ir(kind, file);
  }

 private:
  // Prints the diagnostics and picks the exit status.
  int finish(int status, std::FILE* out) {
    std::string text = format_all(diagnostics_in_order(s_), s_.sources, o_.diag_format, color_ && out == stderr);
    std::fwrite(text.data(), 1, text.size(), out);
    if (status == kOk && s_.diags.has_errors()) status = kProgramErrors;
    return status;
  }

  int source_only(FileKind kind) {
    if (kind == FileKind::Source) return kOk;
    s_.diags.report(DiagId::InputKind, {}, o_.input, o_.command);
    return kUsage;
  }

  // A module from either kind of input: bytecode is loaded and verified, source is
  // compiled (and must have no errors).
  std::optional<vm::Module> module(FileKind kind, uint32_t file, int& status) {
    if (kind == FileKind::Bytecode) {
      if (!o_.processes.empty()) {  // compiled in: the module holds its processes' programs
        s_.diags.report(DiagId::ProcessOption, {}, fmt::format("{}={}", o_.processes[0].first, o_.processes[0].second),
                        "a bytecode file holds the programs it was compiled with: give --process to ncc compile");
        status = kUsage;
        return std::nullopt;
      }
      auto m = load_module(s_, file);
      if (!m) status = kUsage;
      return m;
    }
    auto m = compile_source(s_, file, o_.dialect);
    if (!m || s_.diags.has_errors()) {
      status = m ? kProgramErrors : kUsage;
      return std::nullopt;
    }
    return m;
  }

  int check(FileKind kind, uint32_t file) {
    // The report goes to stdout; when the check cannot run at all, stderr.
    if (int st = source_only(kind)) return finish(st, stderr);
    auto m = compile_source(s_, file, o_.dialect);
    if (!m) return finish(kUsage, stderr);
    if (!s_.diags.limit_reached()) dry_run(s_, *m, o_.run);
    int status = finish(kOk, stdout);
    if (o_.diag_format == DiagFormat::Text)
      std::printf("%s: %u error%s, %u warning%s\n", o_.input.c_str(), s_.diags.error_count(),
                  s_.diags.error_count() == 1 ? "" : "s", s_.diags.warning_count(),
                  s_.diags.warning_count() == 1 ? "" : "s");
    return status;
  }

  int compile(FileKind kind, uint32_t file) {
    if (int st = source_only(kind)) return finish(st, stderr);
    auto compiled = compile_source(s_, file, o_.dialect);
    if (!compiled) return finish(kUsage, stderr);
    const vm::Module& m = *compiled;
    if (!s_.diags.limit_reached()) dry_run(s_, m, o_.run);
    if (s_.diags.has_errors()) return finish(kProgramErrors, stderr);
    // Write the whole file or nothing: a temporary file renamed into place.
    std::string temp = o_.output + ".tmp";
    std::FILE* f = std::fopen(temp.c_str(), "wb");
    bool ok = f && vm::write_module(m, f);
    ok = f && std::fclose(f) == 0 && ok;
    ok = ok && std::rename(temp.c_str(), o_.output.c_str()) == 0;
    if (!ok) {
      s_.diags.report(DiagId::FileUnwritable, {}, o_.output, std::strerror(errno));
      std::remove(temp.c_str());
      return finish(kUsage, stderr);
    }
    return finish(kOk, stderr);
  }

  int run(FileKind kind, uint32_t file) {
    int status = kOk;
    auto m = module(kind, file, status);
    if (!m) return finish(status, stderr);
    std::FILE* out = stdout;
    bool close = false;
    if (o_.trace != "-" && o_.trace != "none") {
      out = std::fopen(o_.trace.c_str(), "wb");
      if (!out) {
        s_.diags.report(DiagId::FileUnwritable, {}, o_.trace, std::strerror(errno));
        return finish(kUsage, stderr);
      }
      close = true;
    }
    NullSink none;
    auto writer = o_.trace == "none"
                      ? nullptr
                      : make_trace_writer(o_.trace_format, out, m->source_map, m->semantics.conventions.axes);
    TraceSink& trace = writer ? *writer : static_cast<TraceSink&>(none);
    const bool on_terminal = out == stdout && isatty(STDOUT_FILENO);
    RunResult result;
    if (o_.time) {
      auto sim = simulate(s_, *m, o_.run, "running " + o_.input, on_terminal, &trace);
      if (!sim) return finish(kUsage, stderr);
      result = sim->result;
      writer.reset();
      const std::string text =
          o_.time_json ? sim::time_json(sim->path, sim->times) : sim::time_text(sim->path, sim->times);
      std::fwrite(text.data(), 1, text.size(), stdout);
    } else {
      Progress line("running " + o_.input, trace, on_terminal);
      result = run_module(s_, *m, o_.run, line);
    }
    writer.reset();
    if (o_.run.screen && !result.screen) std::fprintf(out, "--- screen off\n");
    if (o_.run.screen && result.screen) {
      // The rows up to the last one written, numbered as DEF numbers them.
      const std::vector<std::string>& lines = *result.screen;
      size_t rows = lines.size();
      while (rows > 0 && lines[rows - 1].empty()) --rows;
      std::fprintf(out, "--- screen\n");
      // Memory never written shows as zeros: escaped, as the trace escapes them.
      for (size_t r = 0; r < rows; ++r) std::fprintf(out, "%2zu |%s\n", r + 1, json_escape(lines[r], false).c_str());
    }
    if (close && std::fclose(out) != 0) s_.diags.report(DiagId::FileUnwritable, {}, o_.trace, std::strerror(errno));
    return finish(result.usage_error ? kUsage : result.ok ? kOk : kProgramErrors, stderr);
  }

  int translate(FileKind kind, uint32_t file) {
    int status = kOk;
    // Structured translation reads the source itself (its checks and dry run with it).
    std::optional<vm::Module> m;
    if (!o_.flatten) {
      if (int st = source_only(kind)) return finish(st, stderr);
      if (!s_.profile && !load_profile(s_, "")) return finish(kUsage, stderr);
    } else if (!(m = module(kind, file, status))) {
      return finish(status, stderr);
    }
    translate::Request request;
    request.to = o_.to;
    request.header = {o_.input, m ? m->semantics.dialect : o_.dialect, {}, o_.flatten, {}};
    request.run = o_.run;
    std::optional<stdlib::Profile> target_profile;
    if (!o_.target_machine.empty()) {
      target_profile = stdlib::Profile::load(s_.sources, o_.target_machine, s_.diags);
      if (!target_profile) return finish(kUsage, stderr);
      request.target_profile = &*target_profile;
    } else {
      request.target_profile = m ? module_profile(s_, *m) : &*s_.profile;
      if (!request.target_profile) return finish(kUsage, stderr);
    }
    // The whole program or nothing: a temporary file renamed into place.
    const bool to_stdout = o_.output.empty() || o_.output == "-";
    std::string temp = o_.output + ".tmp";
    std::FILE* out = to_stdout ? std::tmpfile() : std::fopen(temp.c_str(), "wb");
    if (!out) {
      s_.diags.report(DiagId::FileUnwritable, {}, to_stdout ? std::string("a temporary file") : temp,
                      std::strerror(errno));
      return finish(kUsage, stderr);
    }
    bool ok = o_.flatten ? translate::flatten(s_, *m, request, out)
                         : translate::structured(s_, file, o_.dialect, request, out);
    if (to_stdout) {
      if (ok) {
        std::rewind(out);
        char buffer[1 << 16];
        for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, out)) > 0;) std::fwrite(buffer, 1, n, stdout);
      }
      std::fclose(out);
    } else {
      const bool written = std::fclose(out) == 0;
      if (ok && (!written || std::rename(temp.c_str(), o_.output.c_str()) != 0)) {
        s_.diags.report(DiagId::FileUnwritable, {}, o_.output, std::strerror(errno));
        std::remove(temp.c_str());
        return finish(kUsage, stderr);
      }
      if (!ok) std::remove(temp.c_str());
    }
    return finish(ok ? kOk : s_.diags.has_errors() ? kProgramErrors : kUsage, stderr);
  }

  int disasm(FileKind kind, uint32_t file) {
    int status = kOk;
    auto m = module(kind, file, status);
    if (!m) return finish(status, stderr);
    std::string text = vm::disassemble(*m);
    std::fwrite(text.data(), 1, text.size(), stdout);
    return finish(kOk, stderr);
  }

  // ncc plot, ncc view: what the program does up to its first error is drawn, and the
  // errors are reported (a page lists them too).
  int draw(FileKind kind, uint32_t file) {
    std::optional<vm::Module> m;
    if (kind == FileKind::Bytecode) {
      int status = kOk;
      if (!(m = module(kind, file, status))) return finish(status, stderr);
    } else if (!(m = compile_source(s_, file, o_.dialect))) {
      return finish(kUsage, stderr);
    }
    const std::string what = (o_.command == "plot" ? "plotting " : "viewing ") + o_.input;
    auto sim = simulate(s_, *m, o_.run, what, false);
    if (!sim) return finish(kUsage, stderr);
    std::string text;
    if (o_.command == "plot") {
      sim::PlotInput in{&sim->path, block_labels(*m), o_.input, o_.view, o_.tolerance.value_or(0.001), o_.size};
      text = sim::write_svg(in);
    } else {
      sim::ViewInput in = view_input(s_, *m, *sim);
      in.title = o_.input;
      in.tolerance = o_.tolerance.value_or(in.tolerance);
      in.grid = o_.grid;
      if (std::string why = stock_box(*sim, o_.stock, in.stock_min, in.stock_max); !why.empty()) {
        std::fprintf(stderr, "ncc view: error: %s\n", why.c_str());
        return kUsage;
      }
      sim::write_view(text, in);
    }
    if (!write_whole(o_.output, text)) return finish(kUsage, stderr);
    return finish(sim->result.usage_error ? kUsage : sim->result.ok ? kOk : kProgramErrors, stderr);
  }

  // The whole file or nothing: a temporary file renamed into place.
  bool write_whole(const std::string& path, std::string_view text) {
    if (path == "-") return std::fwrite(text.data(), 1, text.size(), stdout) == text.size();
    const std::string temp = path + ".tmp";
    std::FILE* f = std::fopen(temp.c_str(), "wb");
    bool ok = f && std::fwrite(text.data(), 1, text.size(), f) == text.size();
    ok = f && std::fclose(f) == 0 && ok;
    ok = ok && std::rename(temp.c_str(), path.c_str()) == 0;
    if (!ok) {
      s_.diags.report(DiagId::FileUnwritable, {}, path, std::strerror(errno));
      std::remove(temp.c_str());
    }
    return ok;
  }

  int ir(FileKind kind, uint32_t file) {
    if (int st = source_only(kind)) return finish(st, stderr);
    auto program = analyse(s_, file, o_.dialect);
    if (!program) return finish(kUsage, stderr);
    std::string text = ir::print(*program, s_.sources);
    std::fwrite(text.data(), 1, text.size(), stdout);
    return finish(kOk, stderr);
  }

  Options o_;
  Session s_;
  bool color_ = false;
};

int run_command(const Command& command, const std::vector<std::string>& rest) {
  if (command.name == "files") return files_command(rest);
  if (command.name == "regime") return regime_command(rest);
  for (const std::string& a : rest)
    if (a == "-h" || a == "--help") {
      print_command_help(command);
      return kOk;
    }
  Options options;
  options.command = std::string(command.name);
  if (std::string error = parse_args(rest, command, options); !error.empty()) {
    std::fprintf(stderr, "ncc %s: error: %s\nusage: %s\n", options.command.c_str(), error.c_str(),
                 std::string(command.usage).c_str());
    return kUsage;
  }
  return Cli(std::move(options)).run();
}

}  // namespace
}  // namespace ncc

int main(int argc, char** argv) {
  using namespace ncc;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
    print_main_help(args.empty() ? stderr : stdout);
    return args.empty() ? kUsage : kOk;
  }
  if (args[0] == "--version") {
    std::printf("ncc 0.1.0 (bytecode format %u)\n", vm::kFormatVersion);
    return kOk;
  }
  const Command* command = nullptr;
  for (const Command& c : kCommands)
    if (c.name == args[0]) command = &c;
  if (!command) {
    std::fprintf(stderr, "ncc: error: unknown command '%s' (try 'ncc --help')\n", args[0].c_str());
    return kUsage;
  }
  // Sizes an input gives are checked before they are allocated; an allocation that
  // fails all the same ends the command, not the process.
  try {
    return run_command(*command, {args.begin() + 1, args.end()});
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "ncc: error: out of memory\n");
    return kUsage;
  }
}
