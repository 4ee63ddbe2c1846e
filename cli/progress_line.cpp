// progress_line.cpp — see progress_line.h.
#include "progress_line.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>

namespace vgc::cli {

namespace {
// The ticker's period: the line's elapsed time moves at least this often.
constexpr auto kTick = std::chrono::milliseconds(500);
}  // namespace

ProgressLine::ProgressLine(bool enabled) : enabled_(enabled), tty_(isatty(STDERR_FILENO) == 1) {
  if (enabled_ && tty_) ticker_ = std::thread([this] { tick(); });
}

ProgressLine::~ProgressLine() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    stop_ = true;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
  finish();
}

void ProgressLine::update(const std::string& text, bool force) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mu_);
  text_ = text;
  const auto now = Clock::now();
  const auto gap = tty_ ? std::chrono::milliseconds(100) : std::chrono::milliseconds(10000);
  if (!force && drawn_ && now - last_ < gap) return;
  draw_locked(now);
}

void ProgressLine::draw_locked(Clock::time_point now) {
  last_ = now;
  const std::string line =
      fmt::format("{}  {:.1f} s", text_, std::chrono::duration<double>(now - start_).count());
  if (tty_) {
    fmt::print(stderr, "\r\033[K{}", line);
  } else {
    fmt::print(stderr, "{}\n", line);
  }
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::tick() {
  std::unique_lock<std::mutex> lock(mu_);
  while (!stop_) {
    wake_.wait_for(lock, kTick);
    if (stop_) break;
    const auto now = Clock::now();
    if (!text_.empty() && now - last_ >= kTick) draw_locked(now);
  }
}

void ProgressLine::finish() {
  // A log keeps its rate limit across finish(): a permanent line printed in
  // between is no reason for another status line.
  if (!enabled_ || !tty_) return;
  std::lock_guard<std::mutex> lock(mu_);
  if (drawn_) {
    fmt::print(stderr, "\r\033[K");
    std::fflush(stderr);
  }
  drawn_ = false;
  text_.clear();
}

}  // namespace vgc::cli
