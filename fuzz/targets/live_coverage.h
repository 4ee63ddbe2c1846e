// live_coverage.h — a fuzz target's view of the coverage of the live
// implementation it drives over exec: the shared memory created before the
// program starts (coverage_region.h), cleared before each input and folded
// into libFuzzer's extra counters after it, and the record the campaign
// reads (coverage_record.h).
//
// Spec: docs/fuzzing.md "Coverage of the implementation"; libFuzzer's extra
// counters (compiler-rt lib/fuzzer FuzzerExtraCounters.cpp).
//
// Rationale: the target is run by `vgc fuzz` with these variables (it takes
// no options of ours):
//   VGC_FUZZ_IMPL_COVERAGE      guide (default): the implementation's edges
//                               are libFuzzer features beside the reference's;
//                               guide-counts: its counters with their hit
//                               counts (measured slower, docs/fuzzing.md);
//                               observe: only counted, for an unguided
//                               campaign measured the same way; off: no region
//                               at all (the implementation runs as before).
//   VGC_FUZZ_IMPL_COVERAGE_DIR  where the record is written (<dir>/<pid>.txt);
//                               unset: none.
// Only a program the target starts inherits the region's name: an exec:
// implementation, or a Verse host started by VGC_FUZZ_HOST_CMD (--host-cmd;
// launched_host.h). A Verse host started by the user, or by --restart, is
// not given one. An implementation that was not built with the runtime
// never attaches: the target says once that its coverage is not seen, and
// everything else runs as without this.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "coverage_record.h"
#include "coverage_region.h"
#include "route.h"

namespace vgc::fuzz {

class LiveCoverage {
 public:
  // For a live implementation's route: nullptr when the target does not
  // start it (exec:, or verse: with `host_started`: a program with the
  // region in its environment), when VGC_FUZZ_IMPL_COVERAGE=off, or when
  // the region cannot be made (said on stderr). Call before the
  // implementation starts.
  static std::unique_ptr<LiveCoverage> for_implementation(const Route& route, bool host_started, const char* target);
  ~LiveCoverage();  // finish()

  // After the implementation has started: one line on stderr, what is seen.
  void started();
  void before_input();
  // Folds the counters into libFuzzer's extra counters `extra[0..n)` (guide)
  // or only counts them (observe); the record is rewritten when the count
  // grew and a second has passed.
  void after_input(std::uint8_t* extra, std::size_t n);
  // Writes the record and removes the region's name (before the process
  // ends at a finding: libFuzzer then exits without destructors).
  void finish();

  bool guiding() const { return guide_; }
  const CoverageRegion& region() const { return *region_; }

 private:
  LiveCoverage() = default;
  void write_record();
  std::unique_ptr<CoverageRegion> region_;
  bool guide_ = true;
  bool counts_ = false;  // guide-counts
  bool said_seen_ = false;
  bool finished_ = false;
  std::string target_;
  std::string record_path_;
  CoverageRecord record_;
  std::chrono::steady_clock::time_point last_write_{};
  bool dirty_ = false;
};

}  // namespace vgc::fuzz
