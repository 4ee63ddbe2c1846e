// coverage_region.h — the shared memory through which a running
// implementation built with clang's SanitizerCoverage and vgc's coverage
// runtime (runtime/vgc_coverage.c) shows its own counters to the fuzz
// target that drives it; read after each input and folded into libFuzzer's
// extra counters, so that inputs reaching new code *in the implementation*
// are kept.
//
// Spec: the region's layout, runtime/vgc_coverage_shm.h; clang
// SanitizerCoverage "Inline 8bit-counters" and "PC-Table"; libFuzzer's
// extra counters (a uint8_t array in the section __libfuzzer_extra_counters,
// cleared before each input and read after it like the inline counters;
// compiler-rt lib/fuzzer FuzzerExtraCounters.cpp, TracePC::CollectFeatures);
// docs/fuzzing.md "Coverage of the implementation".
//
// Rationale: one region per fuzzer process (libFuzzer's fork mode runs
// jobs side by side, each with its own implementation), created before the
// implementation starts and named in VGC_COVERAGE_SHM, which the process
// started inherits (setenv here: the exec adapter starts programs with this
// process's environment). The runtime in the implementation maps its
// counters into the region at start-up; clear() before an input and fold()
// after it (when the implementation has answered its last call, so its
// increments are in) are all there is per input: a memset and a scan of the
// implementation's counters, nothing inside the implementation. The
// implementation may have more counters than libFuzzer's extra array has
// slots: counter i feeds slot i mod n (the largest count wins), which
// merges distant counters but keeps every one seen. By default only whether
// an edge was taken is folded, not how often (docs/fuzzing.md: the hit
// counts of the implementation's loops kept so many inputs that the
// search thinned out). Nothing is attached when
// the implementation was built without the runtime: attached() is false and
// fold() does nothing, and the campaign says the implementation's coverage
// is not seen.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct vgc_coverage_header;

namespace vgc::fuzz {

// A function's entry counter, and where its code is: `offset` from the
// load address of module `module` (modules()' order), which
// symbolize_functions.h turns into a name and a source line.
struct FunctionEntry {
  std::size_t index = 0;     // the counter
  std::uint32_t module = 0;  // modules()[module]
  std::uint32_t offset = 0;  // PC minus the module's load address
};

// At most this many function entries are listed (a record stays small).
inline constexpr std::size_t kMaxFunctionEntries = 65536;

class CoverageRegion {
 public:
  // Creates the region /vgc-coverage-<pid> (a stale one of a dead process
  // of this pid is replaced) for at most `max_counters` counters and sets
  // VGC_COVERAGE_SHM in this process's environment. nullptr and *error
  // when it cannot.
  static std::unique_ptr<CoverageRegion> create(std::size_t max_counters, std::string* error);
  ~CoverageRegion();  // unmaps, unlinks the name, unsets VGC_COVERAGE_SHM
  CoverageRegion(const CoverageRegion&) = delete;
  CoverageRegion& operator=(const CoverageRegion&) = delete;

  const std::string& name() const { return name_; }
  // Whether an implementation process has mapped counters into it.
  bool attached() const;
  std::size_t counters() const;          // counters mapped
  std::size_t dropped_counters() const;  // counters of modules that did not fit
  std::size_t function_entries() const;  // counters that are a function's entry (PC table)
  std::vector<std::string> modules() const;  // "PATH (N counters)"

  // Zeroes the implementation's counters (before an input).
  void clear();
  // Notes every counter that is non-zero as reached, and when `out` is not
  // null, folds them into out[0..n): with `counts`, out[i mod n] =
  // max(out[i mod n], c_i) (libFuzzer then buckets the hit counts); without,
  // out[i mod n] = 1 (the edge was taken, however often).
  // Returns whether a counter was reached for the first time.
  bool collect(std::uint8_t* out, std::size_t n, bool counts = false);

  // Counters reached by any input so far (since create, any process), and
  // reached counters that are function entries.
  std::size_t reached() const { return reached_count_; }
  std::size_t functions_entered() const;
  const std::vector<std::uint8_t>& reached_map() const { return reached_; }  // one byte per counter, 1 = reached
  std::vector<std::uint8_t> entry_map() const;                              // 1 = a function's entry
  // The function entries whose PC the runtime gave (a PC table), in counter
  // order, at most kMaxFunctionEntries.
  std::vector<FunctionEntry> function_entry_list() const;

 private:
  CoverageRegion() = default;
  std::string name_;
  int fd_ = -1;
  std::uint8_t* base_ = nullptr;
  std::size_t size_ = 0;
  vgc_coverage_header* header_ = nullptr;
  std::vector<std::uint8_t> reached_;
  std::size_t reached_count_ = 0;
};

}  // namespace vgc::fuzz
