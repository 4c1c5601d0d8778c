// Throughput of each stage on generated programs (deterministic generators):
//   plain: GOST G01 blocks with X Y Z F words, the bulk of CAM output;
//   arcs:  GOST quarter circles G02/G03 around a square;
//   cycles: GOST G81 drilling on a grid;
//   nc110_mixed: NC-110 assignments with expressions, moves by E parameters and
//     three-letter codes (URT, DIS), a quarter each;
//   nc110_loops: NC-110 RPT loops three deep around an assignment and a move: the
//     VM's cost per executed block (n/100 blocks, each run 100 times);
//   <dialect>_plain: the plain blocks of every dialect, for the front end with its
//     hand-written fast path (second argument 1) and with ANTLR for every block (0);
//   Scan: the bare plain-word scanner alone over the ISO plain blocks, the ceiling of
//     the fast path;
//   Bytecode: writing the .ncb of the ISO plain blocks (second argument 0), reading
//     and verifying it (1).
// Run: build/bench/ncc_bench (see bench/README.md for the numbers on our machine).
#include <benchmark/benchmark.h>

#include <cstdio>

#include "driver/pipeline.h"
#include "frontend/plain_words.h"

namespace ncc {
namespace {

struct Generated {
  std::string text;
  const char* dialect = "gost";
};

Generated plain_program(int blocks) {
  std::string s = "%0001\nN0001 G90 G17 G01 X0 Y0 Z0 F1000. S1000 M03\n";
  for (int i = 1; i <= blocks; ++i)
    s +=
        fmt::format("N{:04} X{:.3f} Y{:.3f} Z{:.3f}\n", i % 10000, (i % 500) * 0.25, (i % 333) * 0.125, -(i % 7) * 0.5);
  return {s + "N9999 M30\n"};
}

Generated arc_program(int blocks) {
  std::string s = "%0001\nN0001 G90 G17 G00 X10. Y0 Z0 F500.\n";
  const char* moves[] = {"G03 X0 Y10. I-10. J0", "G03 X-10. Y0 I0 J-10.", "G03 X0 Y-10. I10. J0",
                         "G03 X10. Y0 I0 J10."};
  for (int i = 1; i <= blocks; ++i) s += fmt::format("N{:04} {}\n", i % 10000, moves[(i - 1) % 4]);
  return {s + "N9999 M30\n"};
}

Generated cycle_program(int blocks) {
  std::string s = "%0001\nN0001 G90 G17 G00 X0 Y0 Z10. S800 M03\nN0002 G81 X0 Y0 Z-5. R2. F100.\n";
  for (int i = 1; i <= blocks; ++i) s += fmt::format("N{:04} X{} Y{}\n", i % 10000, (i % 50) * 5, (i / 50 % 50) * 5);
  return {s + "N9999 G80 M30\n"};
}

Generated nc110_mixed_program(int blocks) {
  std::string s = "G1 X0 Y0 Z0 F1000\nE25=0\n";
  for (int i = 1; i <= blocks; ++i) {
    switch (i % 4) {
      case 0: s += fmt::format("E25=E25+{}*0.01\n", i % 7); break;
      case 1: s += "E30=(E25*SIN(E25)+12.5)/SQR(16)\n"; break;
      case 2: s += "G1 XE25 YE30 Z-1\n"; break;
      default: s += i % 8 == 3 ? "(URT,E25)\n" : "(DIS,\"E30=\",E30)\n"; break;
    }
  }
  return {s + "(URT,0)\nM30\n", "nc110"};
}

Generated nc110_loop_program(int blocks) {
  // Three loops of 10 around two blocks: 2000 blocks a pass, `blocks / 2000` passes.
  std::string s = "G1 X0 Y0 F1000\nE30=0\n";
  for (int pass = 0; pass < blocks / 2000; ++pass)
    s += "(RPT,10)\n(RPT,10)\n(RPT,10)\nE30=E30+0.001\nG1 XE30\n(ERP)\n(ERP)\n(ERP)\n";
  return {s + "M30\n", "nc110"};
}

// `head`, then X Y Z F moves (a bounded walk, three decimals), each numbered by `number`.
Generated plain_blocks(int blocks, const char* dialect, std::string head, const char* number, std::string tail) {
  std::string s = std::move(head);
  for (int i = 1; i <= blocks; ++i)
    s += fmt::format("{}G1 X{:.3f} Y{:.3f} Z{:.3f} F{}\n", number[0] ? fmt::format(fmt::runtime(number), i + 1) : "",
                     (i % 500) * 0.25 - 60, (i % 333) * 0.125, -(i % 7) * 0.5, 800 + i % 5 * 100);
  return {s + tail, dialect};
}
Generated iso_plain(int blocks) { return plain_blocks(blocks, "iso", "G17 G21 G90 G94\nS1000 M03\n", "", "M30\n"); }
Generated gost_plain(int blocks) {
  return plain_blocks(blocks, "gost", "%0001\nN0001 G90 G17 S1000 M03\n", "N{:04} ", "N9999 M30\n");
}
Generated pp_plain(int blocks) {
  return plain_blocks(blocks, "pp", "%1\nN1 G90 G17 S1000 M03\n", "N{} ", "N99999999 M30\n*\n");
}
Generated nc110_plain(int blocks) { return plain_blocks(blocks, "nc110", "G17\nG90 S1000 M3\n", "", "M5\nM30\n"); }

std::optional<ir::Program> front_end(Session& s, const Generated& g) {
  uint32_t file = s.sources.add("bench.nc", g.text);
  return analyse(s, file, g.dialect);
}

template <Generated (*make)(int)>
void FrontEnd(benchmark::State& state) {
  Generated g = make(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Session s;
    auto program = front_end(s, g);
    if (s.diags.has_errors()) state.SkipWithError("the generated program has errors");
    benchmark::DoNotOptimize(program);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * g.text.size()));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// Front end and checks with (range 1 = 1) or without the fast path.
template <Generated (*make)(int)>
void FrontEndPath(benchmark::State& state) {
  Generated g = make(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Session s;
    s.fast_path = state.range(1) != 0;
    auto program = front_end(s, g);
    if (s.diags.has_errors() || s.diags.warning_count()) state.SkipWithError("the generated program is not clean");
    benchmark::DoNotOptimize(program);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * g.text.size()));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void Scan(benchmark::State& state) {
  Generated g = iso_plain(static_cast<int>(state.range(0)));
  static constexpr PlainRules kRules{"ABCDEFGHIJKLMNPQRSTUVWXYZ", true, true, true};
  PlainBlock block;
  for (auto _ : state) {
    size_t words = 0;
    for (std::string_view rest = g.text; !rest.empty();) {
      const size_t eol = std::min(rest.find('\n'), rest.size());
      if (scan_plain_words(rest.substr(0, eol), kRules, block)) words += block.words.size();
      rest.remove_prefix(std::min(eol + 1, rest.size()));
    }
    benchmark::DoNotOptimize(words);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * g.text.size()));
}

template <Generated (*make)(int)>
void Lower(benchmark::State& state) {
  Session s;
  auto program = front_end(s, make(static_cast<int>(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(lower_program(s, *program));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <Generated (*make)(int)>
void Run(benchmark::State& state) {
  Session s;
  auto program = front_end(s, make(static_cast<int>(state.range(0))));
  vm::Module m = lower_program(s, *program);
  NullSink none;
  for (auto _ : state)
    if (!run_module(s, m, {}, none).ok) state.SkipWithError("the generated program does not run cleanly");
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The bytecode file: writing it (range 1 = 0), or reading and verifying it (1), as
// `ncc compile` and `ncc run X.ncb` do.
template <Generated (*make)(int)>
void Bytecode(benchmark::State& state) {
  Session s;
  auto program = front_end(s, make(static_cast<int>(state.range(0))));
  const vm::Module m = lower_program(s, *program);
  const std::string bytes = vm::write_module(m);
  for (auto _ : state) {
    if (state.range(1) == 0) {
      benchmark::DoNotOptimize(vm::write_module(m));
    } else if (!vm::read_module(bytes, "bench.ncb", s.diags)) {
      state.SkipWithError("the module does not load");
    }
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * bytes.size()));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void RunWithTextTrace(benchmark::State& state) {
  Session s;
  auto program = front_end(s, plain_program(static_cast<int>(state.range(0))));
  vm::Module m = lower_program(s, *program);
  std::FILE* null = std::fopen("/dev/null", "w");
  for (auto _ : state) {
    auto writer = make_trace_writer(TraceFormat::Text, null, m.source_map, m.semantics.conventions.axes);
    if (!run_module(s, m, {}, *writer).ok) state.SkipWithError("the generated program does not run cleanly");
  }
  std::fclose(null);
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

BENCHMARK(FrontEnd<plain_program>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(FrontEnd<arc_program>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(FrontEnd<cycle_program>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(Lower<plain_program>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(Run<plain_program>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(Run<arc_program>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(Run<cycle_program>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(RunWithTextTrace)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(FrontEnd<nc110_mixed_program>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(Run<nc110_mixed_program>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(Run<nc110_loop_program>)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(Scan)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(FrontEndPath<iso_plain>)->Args({10000, 1})->Args({10000, 0})->Unit(benchmark::kMillisecond);
// GOST numbers N0002..N9001 (the default format is N04).
BENCHMARK(FrontEndPath<gost_plain>)->Args({9000, 1})->Args({9000, 0})->Unit(benchmark::kMillisecond);
BENCHMARK(FrontEndPath<pp_plain>)->Args({10000, 1})->Args({10000, 0})->Unit(benchmark::kMillisecond);
BENCHMARK(FrontEndPath<nc110_plain>)->Args({10000, 1})->Args({10000, 0})->Unit(benchmark::kMillisecond);
BENCHMARK(Run<iso_plain>)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(Bytecode<iso_plain>)->Args({10000, 0})->Args({10000, 1})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ncc

BENCHMARK_MAIN();
