// minimize_input.h — the input of a raw-bytes fuzz finding, minimized with
// libFuzzer's own crash minimizer before it is written.
//
// Spec: none (fuzzing practice; docs/fuzzing.md "Running a campaign":
// findings are deduplicated and minimized, issue 19 item 9).
//
// Rationale: a finding that names no clause (a sanitizer crash or abort in
// fuzz_text, fuzz_stream, fuzz_verse_packet, fuzz_mesh_*) has no command
// program to shrink the way certify does (minimize_finding.h): its input is
// bytes, often kilobytes of which a few cause the crash. libFuzzer's
// `-minimize_crash=1 -runs=N` mutates it into ever smaller inputs that
// still crash, step by step; it is run with a bounded time (each step at
// most max_total_time, the whole under `timeout`), ASan's dedup token set
// to the top frame (deeper ones differ between libFuzzer's first run and
// its minimizing steps) so that libFuzzer itself stops where the crash
// changes, and its result
// is kept only when it is smaller AND the caller's check (the campaign's
// signature of a fresh run) says it is still the same failure: a
// minimization that wandered into another bug, or was cut off mid-write,
// keeps the original input. Hangs (timeout-*, slow-unit-*) are not
// minimized: each try would cost the whole timeout.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

namespace vgc::fuzz {

struct MinimizedInput {
  bool tried = false;        // libFuzzer's minimizer was run
  bool kept = false;         // a smaller input with the same failure is in `file`
  std::string file;          // the minimized input (when kept)
  std::size_t before = 0, after = 0;  // bytes
  double seconds = 0;        // time spent
  std::string note;          // why it was not kept, when tried and not kept (or not tried)
};

// `run_prefix` is the shell text that runs the target (environment and
// binary, quoted: "A='1' '/path/fuzz_text'"); `input` the crash input;
// `out_file` where the minimized input goes (its directory must exist; a
// log of libFuzzer's output goes beside it, out_file + ".log");
// `same_failure(path)` re-runs a candidate and says whether it fails as
// the original did. Nothing here throws; the time spent ends by `deadline`
// (give it at least a few seconds: libFuzzer starts, then steps).
MinimizedInput minimize_input(const std::string& run_prefix, const std::string& input, const std::string& out_file,
                              const std::function<bool(const std::string&)>& same_failure,
                              std::chrono::steady_clock::time_point deadline);

}  // namespace vgc::fuzz
