#include "simulate.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "progress.h"

namespace ncc {

std::optional<Simulation> simulate(Session& s, const vm::Module& m, RunSettings settings, const std::string& progress,
                                   bool output_on_terminal, TraceSink* trace) {
  const stdlib::Profile* profile = module_profile(s, m);
  if (!profile) return std::nullopt;
  Simulation sim;
  const uint32_t errors = s.diags.error_count();
  sim.machine = stdlib::load_machine_config(*profile, s.diags);
  if (s.diags.error_count() != errors) return std::nullopt;
  // Machine coordinates: a move starts where the last one ended, whatever the offsets
  // did between them (the sink measures from the first work zero).
  settings.trace_machine_frame = true;
  sim::ToolpathSink sink(sim.path, sim.machine);
  sim.path.moves.reserve(m.source_map.size());  // a block a move, as CAM output has it
  if (!trace) {
    // Block events tell a loop's iterations apart; a drawing ends where the first block
    // with errors starts.
    settings.trace_blocks = true;
    std::vector<bool> wrong;
    wrong.reserve(m.source_map.size());
    m.source_map.visit([&](const SourceBlock& b, const std::vector<WordPosition>&) { wrong.push_back(b.has_errors); });
    if (std::find(wrong.begin(), wrong.end(), true) != wrong.end()) sink.stop_at(std::move(wrong));
  }
  sim.path.axes = m.semantics.conventions.axes;
  NullSink none;
  TeeSink both(sink, trace ? *trace : none);
  Progress line(progress, both, output_on_terminal);
  sim.result = run_module(s, m, settings, line);
  if (sim.path.full_at) {
    report_at_block(s, m, *sim.path.full_at, DiagId::ToolpathFull, diag_message(DiagId::ToolpathFull, sim::kMaxMoves));
    sim.result.ok = false;
  }
  line.stage(progress + ": timing");
  for (sim::TimeModel model : sim::kTimeModels) sim.times.push_back(sim::cycle_time(sim.path, sim.machine, model));
  return sim;
}

std::vector<std::string> block_labels(const vm::Module& m) {
  std::vector<std::string> names;
  for (const std::string& path : m.source_map.files) names.push_back(std::filesystem::path(path).filename().string());
  std::vector<std::string> labels;
  labels.reserve(m.source_map.size());
  m.source_map.visit([&](const SourceBlock& b, const std::vector<WordPosition>&) {
    std::string label = b.has_number ? fmt::format("N{} ", b.number) : std::string();
    label += fmt::format("{}:{}", b.file < names.size() ? names[b.file] : std::string("?"), b.line);
    labels.push_back(std::move(label));
  });
  return labels;
}

sim::ViewInput view_input(Session& s, const vm::Module& m, const Simulation& sim) {
  sim::ViewInput in;
  in.path = &sim.path;
  in.times = sim.times;
  in.dialect = m.semantics.dialect;
  const std::vector<uint32_t> files = source_files(s, m);
  for (uint32_t id : files) {
    const SourceFile& f = s.sources.file(id);
    in.sources.push_back({std::filesystem::path(f.path()).filename().string(), std::string(f.text())});
  }
  in.blocks.reserve(m.source_map.size());
  m.source_map.visit([&](const SourceBlock& b, const std::vector<WordPosition>&) {
    in.blocks.push_back({b.file, b.line});
  });
  for (const Diagnostic& d : s.diags.all()) {
    sim::ViewDiagnostic v{0,        d.range.line, d.range.col, std::string(severity_name(d.severity)), diag_code(d.id),
                          d.message};
    for (size_t i = 0; i < files.size(); ++i)
      if (d.range.valid() && files[i] == d.range.file) v.file = static_cast<uint32_t>(i);
    in.diagnostics.push_back(std::move(v));
  }
  return in;
}

std::string stock_box(const Simulation& sim, const std::string& text, double min[3], double max[3]) {
  if (!text.empty()) {
    // X0:100,Y0:60,Z-20:0: every axis of the three, lower before upper.
    bool given[3] = {false, false, false};
    size_t at = 0;
    while (at <= text.size()) {
      const size_t end = std::min(text.find(',', at), text.size());
      const std::string item = text.substr(at, end - at);
      const int axis =
          item.empty() ? -1 : axis_index(static_cast<char>(std::toupper(static_cast<unsigned char>(item[0]))));
      const size_t colon = item.find(':');
      if (axis < 0 || axis > 2 || colon == std::string::npos)
        return fmt::format("'{}' is not an axis and its range: --stock takes X0:100,Y0:60,Z-20:0", item);
      auto read = [](std::string_view number, double& out) {
        auto [stop, error] = std::from_chars(number.data(), number.data() + number.size(), out);
        return error == std::errc() && stop == number.data() + number.size();
      };
      const std::string_view view = item;
      if (!read(view.substr(1, colon - 1), min[axis]) || !read(view.substr(colon + 1), max[axis]))
        return fmt::format("'{}': the range of {} needs two numbers, lower:upper", item, item[0]);
      if (!(min[axis] < max[axis]) || !std::isfinite(min[axis]) || !std::isfinite(max[axis]))
        return fmt::format("'{}': the lower end must be below the upper one", item);
      given[axis] = true;
      at = end + 1;
    }
    if (!given[0] || !given[1] || !given[2]) return "--stock needs the ranges of X, Y and Z: X0:100,Y0:60,Z-20:0";
    return {};
  }
  if (sim.machine.stock.set) {
    for (int i = 0; i < 3; ++i) {
      min[i] = sim.machine.stock.min[static_cast<size_t>(i)];
      max[i] = sim.machine.stock.max[static_cast<size_t>(i)];
    }
    return {};
  }
  // Round what the tool cuts: its feed moves, widened by the tool's radius.
  bool any = false;
  for (const sim::Move& mv : sim.path.moves) {
    if (mv.kind == sim::MoveKind::Rapid || mv.programmed) continue;
    const double r = sim.path.tool_radius(mv.tool);
    AxisValues corners[4] = {mv.start, mv.end, mv.start, mv.end};
    if (mv.kind == sim::MoveKind::Arc) {  // the circle's box: enough for a stock
      const int u = mv.plane.u, v = mv.plane.v;
      corners[2][u] = mv.centre[0] - mv.radius, corners[2][v] = mv.centre[1] - mv.radius;
      corners[3][u] = mv.centre[0] + mv.radius, corners[3][v] = mv.centre[1] + mv.radius;
    }
    for (const AxisValues& p : corners)
      for (int i = 0; i < 3; ++i) {
        const double lo = p[i] - (i < 2 ? r : 0), hi = p[i] + (i < 2 ? r : 0);
        min[i] = any ? std::min(min[i], lo) : lo;
        max[i] = any ? std::max(max[i], hi) : hi;
      }
    any = true;
  }
  if (!any) {
    for (int i = 0; i < 3; ++i) min[i] = max[i] = 0;
    min[2] = -10;
  }
  // The top: the work zero, where most programs put it; else the highest cut.
  if (min[2] < 0) max[2] = 0;
  if (max[2] - min[2] < 1) min[2] = max[2] - 1;
  return {};
}

}  // namespace ncc
