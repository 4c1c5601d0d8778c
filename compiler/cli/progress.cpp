#include "progress.h"

#include <unistd.h>

#include <cstdio>

namespace ncc {

Progress::Progress(std::string what, TraceSink& out, bool output_on_terminal)
    : what_(std::move(what)), out_(out), enabled_(isatty(STDERR_FILENO) && !output_on_terminal) {
  next_ = start_ + std::chrono::seconds(1);
}

Progress::~Progress() {
  if (shown_) std::fprintf(stderr, "\r\033[K");
}

void Progress::event(const Event& e) {
  if (is_move(e.kind)) ++moves_;
  if (out_.wants_events()) out_.event(e);
  // The clock is read every few thousand events: it costs more than an event.
  if (!enabled_ || ++events_ % 4096 != 0) return;
  if (std::chrono::steady_clock::now() >= next_) show();
}

void Progress::show() {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start_).count();
  std::fprintf(stderr, "\r\033[K%s: %llu moves, %.0f s", what_.c_str(), static_cast<unsigned long long>(moves_),
               seconds);
  std::fflush(stderr);
  shown_ = true;
  next_ = now + std::chrono::milliseconds(250);
}

void Progress::stage(const std::string& what) {
  if (!enabled_ || std::chrono::steady_clock::now() < start_ + std::chrono::seconds(1)) return;
  what_ = what;
  show();
}

}  // namespace ncc
