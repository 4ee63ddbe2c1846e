// progress_line.h — one status line on stderr while a long command runs.
//
// Debian packages no C++ progress-bar library (indicators is not packaged),
// and one line needs none. On a terminal the line is redrawn in place when
// the text changes (at most 10 times a second) and, by a ticker thread, at
// least twice a second with the elapsed time, so a run over a slow
// implementation (a case that takes many seconds) still shows it is alive.
// In a log (CI) a plain line is printed at most every 10 seconds, so logs
// stay short; the caller prints its own permanent lines (one per property)
// between them.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace vgc::cli {

class ProgressLine {
 public:
  explicit ProgressLine(bool enabled);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  // Shows `text` followed by the time since construction ("  12.3 s") if
  // enough time has passed since the last update (or `force`). Thread-safe.
  void update(const std::string& text, bool force = false);
  // Clears a redrawn line (terminal) so that normal output can follow; the
  // ticker stays quiet until the next update.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  void draw_locked(Clock::time_point now);
  void tick();

  const bool enabled_;
  const bool tty_;
  const Clock::time_point start_ = Clock::now();
  std::mutex mu_;
  std::condition_variable wake_;
  bool stop_ = false;
  bool drawn_ = false;  // a line was drawn (terminal: it is on screen)
  std::string text_;    // the last text; empty after finish() on a terminal
  Clock::time_point last_{};
  std::thread ticker_;  // terminal only
};

}  // namespace vgc::cli
