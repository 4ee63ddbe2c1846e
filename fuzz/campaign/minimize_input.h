// minimize_input.h — the input of a raw-bytes fuzz finding, minimized with
// libFuzzer's own crash-minimizing step before it is written.
//
// Spec: none (fuzzing practice; docs/fuzzing.md "Running a campaign":
// findings are deduplicated and minimized, issue 19 item 9; the same
// finding minimized the same way on an idle or a loaded machine, issue 31).
//
// Rationale: a finding that names no clause (a sanitizer crash or abort in
// fuzz_text, fuzz_stream, fuzz_verse_packet, fuzz_mesh_*) has no command
// program to shrink the way certify does (minimize_finding.h): its input is
// bytes, often kilobytes of which a few cause the crash. libFuzzer's
// minimizer is a loop of steps, each a fresh process that mutates the
// current input into smaller ones until one crashes
// (`-minimize_crash_internal_step=1`). vgc drives that loop itself rather
// than through `-minimize_crash=1`, so that:
//   * each step is bounded by mutations (`-runs`) and seeded
//     (`-seed`), never by wall time: the same input minimizes to the same
//     bytes on an idle or a loaded machine (libFuzzer's own driver bounds a
//     step by `-max_total_time`, which a loaded machine fills with fewer
//     mutations; the minimization used to end larger under load);
//   * the whole is bounded by a number of steps and by the CPU seconds the
//     steps used, both independent of the machine's load; the wall-clock
//     `deadline` is only a guard against a stuck step or a cancelled run;
//   * each step's result is checked by the caller's own signature of a
//     fresh run (`same_failure`), not by ASan's dedup token alone: a step
//     that wandered into another bug ends the minimization and the last
//     input that failed the same way is kept.
// Hangs (timeout-*, slow-unit-*) are not minimized: each try would cost the
// whole timeout.
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
  double seconds = 0;        // wall time spent
  double cpu_seconds = 0;    // CPU time the steps used
  int steps = 0;             // steps run (each a fresh process)
  std::string note;          // why it was not kept, or why it stopped where it did
};

// What bounds a minimization, none of it wall time.
struct MinimizeLimits {
  int max_steps = 200;              // each step shrinks the input at least one byte
  long runs_per_step = 100000;      // mutations a step tries before it gives up
  double cpu_seconds = 120;         // CPU time of all steps together
  unsigned seed = 1;                // step k runs with -seed=seed+k
};

// `run_prefix` is the shell text that runs the target (environment and
// binary, quoted: "A='1' '/path/fuzz_text'"); `input` the crash input;
// `out_file` where the minimized input goes (its directory must exist; a
// log of libFuzzer's output goes beside it, out_file + ".log");
// `same_failure(path)` re-runs a candidate and says whether it fails as
// the original did. Nothing here throws. `deadline` is a guard only (a
// stuck step, a cancelled run): the result does not depend on it unless it
// is reached, and the note then says so.
MinimizedInput minimize_input(const std::string& run_prefix, const std::string& input, const std::string& out_file,
                              const std::function<bool(const std::string&)>& same_failure,
                              const MinimizeLimits& limits, std::chrono::steady_clock::time_point deadline);

}  // namespace vgc::fuzz
