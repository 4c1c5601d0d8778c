// Throughput of each stage on generated programs (deterministic generators):
//   plain: GOST G01 blocks with X Y Z F words, the bulk of CAM output;
//   arcs:  GOST quarter circles G02/G03 around a square;
//   cycles: GOST G81 drilling on a grid;
//   nc110_mixed: NC-110 assignments with expressions, moves by E parameters and
//     three-letter codes (URT, DIS), a quarter each;
//   nc110_loops: NC-110 RPT loops three deep around an assignment and a move: the
//     VM's cost per executed block (n/100 blocks, each run 100 times).
// Run: build/bench/ncc_bench (see bench/README.md for the numbers on our machine).
#include <benchmark/benchmark.h>

#include <cstdio>

#include "driver/pipeline.h"

namespace ncc {
namespace {

struct Generated {
  std::string text;
  const char* dialect = "gost";
};

Generated plain_program(int blocks) {
  std::string s = "%0001\nN0001 G90 G17 G01 X0 Y0 Z0 F1000. S1000 M03\n";
  for (int i = 1; i <= blocks; ++i)
    s += fmt::format("N{:04} X{:.3f} Y{:.3f} Z{:.3f}\n", i % 10000, (i % 500) * 0.25, (i % 333) * 0.125, -(i % 7) * 0.5);
  return {s + "N9999 M30\n"};
}

Generated arc_program(int blocks) {
  std::string s = "%0001\nN0001 G90 G17 G00 X10. Y0 Z0 F500.\n";
  const char* moves[] = {"G03 X0 Y10. I-10. J0", "G03 X-10. Y0 I0 J-10.", "G03 X0 Y-10. I10. J0", "G03 X10. Y0 I0 J10."};
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

}  // namespace
}  // namespace ncc

BENCHMARK_MAIN();
