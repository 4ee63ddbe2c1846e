// live_coverage.cpp — see live_coverage.h.
#include "live_coverage.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace vgc::fuzz {
namespace {

// The region's size in counters: r6's server and library together have
// some tens of thousands; a large C++ host a few hundred thousand.
constexpr std::size_t kMaxCounters = std::size_t{1} << 20;
constexpr std::size_t kMaxTimeline = 200;

double unix_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace

std::unique_ptr<LiveCoverage> LiveCoverage::for_implementation(const Route& route, bool host_started,
                                                               const char* target) {
  if (route.kind != RouteKind::Exec && !(route.kind == RouteKind::Verse && host_started)) return nullptr;
  const char* mode = std::getenv("VGC_FUZZ_IMPL_COVERAGE");
  const std::string m = mode && *mode ? mode : "guide";
  if (m == "off") return nullptr;
  if (m != "guide" && m != "guide-counts" && m != "observe") {
    std::fprintf(stderr, "%s: VGC_FUZZ_IMPL_COVERAGE=%s: expected guide, guide-counts, observe or off\n", target,
                 m.c_str());
    std::exit(2);
  }
  std::unique_ptr<LiveCoverage> c(new LiveCoverage());
  c->guide_ = m != "observe";
  c->counts_ = m == "guide-counts";
  c->target_ = target;
  std::string error;
  c->region_ = CoverageRegion::create(kMaxCounters, &error);
  if (!c->region_) {
    std::fprintf(stderr, "%s: the implementation's coverage is not seen: %s\n", target, error.c_str());
    return nullptr;
  }
  c->record_.mode = m;
  if (const char* dir = std::getenv("VGC_FUZZ_IMPL_COVERAGE_DIR"); dir && *dir)
    c->record_path_ = std::string(dir) + "/" + std::to_string(getpid()) + ".txt";
  return c;
}

LiveCoverage::~LiveCoverage() { finish(); }

void LiveCoverage::started() {
  if (region_->attached()) {
    said_seen_ = true;
    std::fprintf(stderr,
                 "%s: the implementation's coverage is seen: %zu counters (%zu function entries) in shared memory %s, "
                 "%s\n",
                 target_.c_str(), region_->counters(), region_->function_entries(), region_->name().c_str(),
                 !guide_ ? "counted only (observe)" : counts_ ? "guiding libFuzzer by edges and hit counts"
                                                            : "guiding libFuzzer by edges");
    for (const std::string& m : region_->modules()) std::fprintf(stderr, "%s:   module %s\n", target_.c_str(), m.c_str());
    if (region_->dropped_counters())
      std::fprintf(stderr, "%s:   %zu counters did not fit the shared memory and are not seen\n", target_.c_str(),
                   region_->dropped_counters());
  } else {
    std::fprintf(stderr,
                 "%s: the implementation's coverage is not seen (it was not built with "
                 "-fsanitize-coverage=inline-8bit-counters and -lvgc_coverage; docs/fuzzing.md \"Coverage of the "
                 "implementation\"): libFuzzer is guided by vgc's own code only\n",
                 target_.c_str());
  }
  dirty_ = true;
  write_record();
}

void LiveCoverage::before_input() { region_->clear(); }

void LiveCoverage::after_input(std::uint8_t* extra, std::size_t n) {
  const bool grew = region_->collect(guide_ ? extra : nullptr, n, counts_);
  if (grew) {
    dirty_ = true;
    // One point per second at most (its count the latest), at most kMaxTimeline.
    const double now = unix_now();
    if (!record_.timeline.empty() && now - record_.timeline.back().first < 1)
      record_.timeline.back().second = region_->reached();
    else if (record_.timeline.size() >= kMaxTimeline)
      record_.timeline.back() = {now, region_->reached()};
    else
      record_.timeline.emplace_back(now, region_->reached());
    if (!said_seen_ && region_->attached()) started();  // attached only after a restart
  }
  if (dirty_ && std::chrono::steady_clock::now() - last_write_ >= std::chrono::seconds(1)) write_record();
}

void LiveCoverage::write_record() {
  last_write_ = std::chrono::steady_clock::now();
  if (record_path_.empty() || !dirty_) return;
  dirty_ = false;
  record_.seen = region_->attached() || region_->reached() > 0;
  if (record_.seen) {
    record_.counters = std::min(region_->counters(), region_->reached_map().size());
    record_.reached.assign(region_->reached_map().begin(), region_->reached_map().begin() + record_.counters);
    record_.entries = region_->entry_map();
    record_.entries.resize(record_.counters, 0);
    record_.functions.clear();
    for (const FunctionEntry& f : region_->function_entry_list())
      if (f.index < record_.counters) record_.functions.push_back({f.index, f.module, f.offset});
  } else {
    record_.functions.clear();
    record_.counters = 0;
    record_.reached.clear();
    record_.entries.clear();
  }
  record_.dropped = region_->dropped_counters();
  record_.function_entries = region_->function_entries();
  record_.modules = region_->modules();
  write_coverage_record(record_path_, record_);
}

void LiveCoverage::finish() {
  if (finished_) return;
  finished_ = true;
  dirty_ = true;
  write_record();
  region_.reset();
}

}  // namespace vgc::fuzz
