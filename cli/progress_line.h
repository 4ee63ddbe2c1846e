// progress_line.h — one status line on stderr while a long command runs.
//
// Debian packages no C++ progress-bar library (indicators is not packaged),
// and one line needs none: on a terminal the line is redrawn in place at
// most 10 times a second; in a log (CI) a plain line is printed at most
// every 10 seconds, so logs stay short.
#pragma once

#include <chrono>
#include <string>

namespace vgc::cli {

class ProgressLine {
 public:
  explicit ProgressLine(bool enabled);
  ~ProgressLine();
  // Shows `text` if enough time has passed since the last update (or `force`).
  void update(const std::string& text, bool force = false);
  // Clears a redrawn line (terminal) so that normal output can follow.
  void finish();

 private:
  bool enabled_;
  bool tty_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace vgc::cli
