#include "ncc/run.h"

#include <atomic>

#include "contract/block_machine.h"
#include "host_sink.h"
#include "internal.h"

namespace ncc::api {

struct Run::Impl {
  Impl(std::shared_ptr<const Program::Impl> p, MachineInterface& host, const RunOptions& o)
      : program(std::move(p)), options(o), sink(host, program->module.source_map) {
    for (const auto& [path, text] : program->sources) session.sources.add(path, text);
  }

  // Powered on, at the first block; false if it cannot start (reported).
  bool power_on() {
    session.diags.clear();
    diagnostics_seen = SIZE_MAX;
    sink.reset();
    RunSettings settings;
    settings.block_skip = options.block_skip;
    settings.optional_stop = options.optional_stop;
    settings.max_steps = options.max_steps;
    settings.files = options.files;
    settings.input = options.input;
    run.reset();  // the old run's trace ends before the new one's begins
    run = std::make_unique<ModuleRun>(session, program->module, settings, sink, false, true);
    status = run->state() == ModuleRun::State::Running ? Status::Ready : Status::Error;
    return status == Status::Ready;
  }

  // The status after a step of the run; a call the host refused ends it at its block.
  Status after(ModuleRun::State state) {
    if (const auto& refused = sink.refusal(); refused && !reported_refusal) {
      reported_refusal = true;
      run->report(refused->source, DiagId::MachineRefused,
                  diag_message(DiagId::MachineRefused, refused->call, refused->reason));
      run->stop();
      return status = Status::Error;
    }
    switch (state) {
      case ModuleRun::State::Running: return status = Status::Ready;
      case ModuleRun::State::Ended: return status = Status::Ended;
      case ModuleRun::State::Stopped: return status = Status::Stopped;
      case ModuleRun::State::NotStarted:
      case ModuleRun::State::Error: return status = Status::Error;
    }
    return status;
  }

  bool going() const { return status == Status::Ready || status == Status::Paused; }

  std::shared_ptr<const Program::Impl> program;
  RunOptions options;
  Session session{100};
  HostSink sink;
  std::unique_ptr<ModuleRun> run;
  Status status = Status::Error;
  bool reported_refusal = false;
  std::atomic<bool> pause{false};
  mutable std::vector<Diagnostic> diagnostics;
  mutable size_t diagnostics_seen = SIZE_MAX;  // the session's count they were made from
};

Run::Run(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Run::Run(Run&&) noexcept = default;
Run& Run::operator=(Run&&) noexcept = default;
Run::~Run() = default;

Result<Run> Run::start(const Program& program, MachineInterface& machine, const RunOptions& options) {
  auto impl = std::make_unique<Impl>(ProgramAccess::impl(program), machine, options);
  if (!options.profile.empty() && !load_profile(impl->session, options.profile))
    return Result<Run>(diagnostics_of(impl->session));
  if (!impl->power_on()) return Result<Run>(diagnostics_of(impl->session));
  std::vector<Diagnostic> warnings = diagnostics_of(impl->session);
  return Result<Run>(Run(std::move(impl)), std::move(warnings));
}

Status Run::step() {
  Impl& i = *impl_;
  if (!i.going()) return i.status;
  i.reported_refusal = false;
  return i.after(i.run->step());
}

Status Run::run() {
  Impl& i = *impl_;
  while (step() == Status::Ready)
    if (i.pause.exchange(false)) return i.status = Status::Paused;
  return i.status;
}

void Run::pause() { impl_->pause = true; }

Status Run::stop() {
  Impl& i = *impl_;
  if (i.going()) i.status = i.after(i.run->stop());
  return i.status;
}

void Run::reset() {
  impl_->reported_refusal = false;
  impl_->power_on();
}

Status Run::restart_at(uint32_t block) {
  Impl& i = *impl_;
  if (!i.power_on()) return i.status;
  const uint32_t blocks = i.program->module.source_map.size();
  ModuleRun::State state = i.run->state();
  if (block < blocks) {
    i.sink.mute();
    while (state == ModuleRun::State::Running && i.run->next_block() != block) state = i.run->step();
  }
  if (block < blocks && state == ModuleRun::State::Running) {
    i.sink.unmute();
    return i.after(state);
  }
  i.sink.reset();  // the host hears nothing of it
  if (i.run->state() == ModuleRun::State::Running) i.run->stop();
  std::string what = fmt::format("block {}", block);
  if (block < blocks) {
    const Block b = ProgramAccess::make(i.program).block(block);
    what += fmt::format(" ({}:{})", b.file, b.line);
  }
  i.session.diags.report(DiagId::RestartNotReached, {}, what,
                         block >= blocks                    ? fmt::format("the program has {} blocks", blocks)
                         : state == ModuleRun::State::Error ? "an error stops the run before it"
                                                            : "the run ends before it");
  return i.status = Status::Error;
}

Status Run::status() const { return impl_->status; }

std::optional<Block> Run::next_block() const {
  const Impl& i = *impl_;
  if (!i.going()) return std::nullopt;
  const std::optional<uint32_t> source = i.run->next_block();
  if (!source) return std::nullopt;
  return ProgramAccess::make(i.program).block(*source);
}

State Run::state() const {
  const BlockMachine* machine = impl_->run->machine();
  State out;
  if (!machine) return out;
  const MachineState s = machine->state();
  std::copy(s.position.begin(), s.position.end(), out.position.begin());
  std::copy(s.machine.begin(), s.machine.end(), out.machine_position.begin());
  out.units = s.inch ? Units::Inches : Units::Millimetres;
  out.absolute = s.absolute;
  out.plane = {s.plane.u, s.plane.v, s.plane.w};
  out.feed_mode = feed_mode_of(s.feed_mode);
  out.feed = s.feed;
  out.spindle_speed = s.speed;
  if (s.spindle == 1) out.spindle = Direction::Clockwise;
  if (s.spindle == -1) out.spindle = Direction::CounterClockwise;
  out.tool = s.tool;
  out.tool_selected = s.tool_selected;
  out.work_offset = s.work_offset;
  out.cutter_side = cutter_side_of(s.cutter_comp);
  out.cutter_radius = s.cutter_radius;
  out.tool_length_offset = s.length_offset;
  out.motion = s.motion;
  out.mist = s.mist;
  out.flood = s.flood;
  out.seconds = s.clock;
  return out;
}

std::string Run::axes() const { return impl_->program->module.semantics.conventions.axes; }

uint64_t Run::blocks_run() const { return impl_->run->steps(); }

const std::vector<Diagnostic>& Run::diagnostics() const {
  const Impl& i = *impl_;
  if (i.diagnostics_seen != i.session.diags.all().size()) {
    i.diagnostics = diagnostics_of(i.session);
    i.diagnostics_seen = i.session.diags.all().size();
  }
  return i.diagnostics;
}

}  // namespace ncc::api
