// Throughput of each stage on generated GOST programs (deterministic generators):
//   plain: G01 blocks with X Y Z F words, the bulk of CAM output;
//   arcs:  quarter circles G02/G03 around a square;
//   cycles: G81 drilling on a grid.
// Run: build/bench/ncc_bench (see bench/README.md for the numbers on our machine).
#include <benchmark/benchmark.h>

#include <cstdio>

#include "driver/pipeline.h"

namespace ncc {
namespace {

std::string plain_program(int blocks) {
  std::string s = "%0001\nN0001 G90 G17 G01 X0 Y0 Z0 F1000. S1000 M03\n";
  for (int i = 1; i <= blocks; ++i)
    s += fmt::format("N{:04} X{:.3f} Y{:.3f} Z{:.3f}\n", i % 10000, (i % 500) * 0.25, (i % 333) * 0.125, -(i % 7) * 0.5);
  return s + "N9999 M30\n";
}

std::string arc_program(int blocks) {
  std::string s = "%0001\nN0001 G90 G17 G00 X10. Y0 Z0 F500.\n";
  const char* moves[] = {"G03 X0 Y10. I-10. J0", "G03 X-10. Y0 I0 J-10.", "G03 X0 Y-10. I10. J0", "G03 X10. Y0 I0 J10."};
  for (int i = 1; i <= blocks; ++i) s += fmt::format("N{:04} {}\n", i % 10000, moves[(i - 1) % 4]);
  return s + "N9999 M30\n";
}

std::string cycle_program(int blocks) {
  std::string s = "%0001\nN0001 G90 G17 G00 X0 Y0 Z10. S800 M03\nN0002 G81 X0 Y0 Z-5. R2. F100.\n";
  for (int i = 1; i <= blocks; ++i) s += fmt::format("N{:04} X{} Y{}\n", i % 10000, (i % 50) * 5, (i / 50 % 50) * 5);
  return s + "N9999 G80 M30\n";
}

std::optional<ir::Program> front_end(Session& s, const std::string& text) {
  uint32_t file = s.sources.add("bench.nc", text);
  return analyse(s, file, "gost");
}

template <std::string (*make)(int)>
void FrontEnd(benchmark::State& state) {
  std::string text = make(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Session s;
    auto program = front_end(s, text);
    if (s.diags.has_errors()) state.SkipWithError("the generated program has errors");
    benchmark::DoNotOptimize(program);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <std::string (*make)(int)>
void Lower(benchmark::State& state) {
  Session s;
  auto program = front_end(s, make(static_cast<int>(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(lower_program(s, *program));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <std::string (*make)(int)>
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

}  // namespace
}  // namespace ncc

BENCHMARK_MAIN();
