// A progress line on the terminal for a run that takes more than a second: moves so
// far and seconds, on stderr, rewritten in place and wiped at the end. Nothing when
// stderr is not a terminal, or when the run's own output goes to the same terminal.
#pragma once

#include <chrono>
#include <string>

#include "runtime/trace.h"

namespace ncc {

class Progress final : public TraceSink {
 public:
  // `what`: "running part.nc"; `out`: the sink the events go on to.
  Progress(std::string what, TraceSink& out, bool output_on_terminal);
  ~Progress() override;
  void event(const Event& e) override;
  void flush() override { out_.flush(); }
  bool wants_events() const override { return enabled_ || out_.wants_events(); }
  void programmed(const Event& e) override { out_.programmed(e); }
  bool wants_programmed() const override { return out_.wants_programmed(); }
  // A stage after the run ("writing the page"): shown as it starts, if the line is.
  void stage(const std::string& what);

 private:
  void show();

  std::string what_;
  TraceSink& out_;
  bool enabled_ = false, shown_ = false;
  uint64_t moves_ = 0, events_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), next_ = start_;
};

}  // namespace ncc
