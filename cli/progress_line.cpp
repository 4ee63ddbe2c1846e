// progress_line.cpp — see progress_line.h.
#include "progress_line.h"

#include <fmt/core.h>
#include <unistd.h>

namespace vgc::cli {

ProgressLine::ProgressLine(bool enabled) : enabled_(enabled), tty_(isatty(STDERR_FILENO) == 1) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::update(const std::string& text, bool force) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const auto gap = tty_ ? std::chrono::milliseconds(100) : std::chrono::milliseconds(10000);
  if (!force && drawn_ && now - last_ < gap) return;
  last_ = now;
  if (tty_) {
    fmt::print(stderr, "\r\033[K{}", text);
  } else {
    fmt::print(stderr, "{}\n", text);
  }
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::finish() {
  // A log keeps its rate limit across finish(): a permanent line printed in
  // between is no reason for another status line.
  if (!tty_) return;
  if (enabled_ && drawn_) fmt::print(stderr, "\r\033[K");
  drawn_ = false;
}

}  // namespace vgc::cli
