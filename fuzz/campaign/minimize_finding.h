// minimize_finding.h — the counterexample of a fuzz finding, minimized the
// way certify shrinks one before it is written: the shortest command
// sequence found that still shows the same clause.
//
// Spec: the clause catalog (conformance/clause.h); the replay of
// runner.h (replay_program), which is how `vgc replay` judges a file.
//
// Rationale: a fuzz target prints the command file of the input it ran,
// often with many commands that have nothing to do with the finding (a
// 14-command counterexample for a one-command bug). Before it is written,
// its commands are dropped in runs of halving length (ddmin's complements)
// while a fresh replay still names the same clause with the same status,
// within a bound of replays and time; the capability check, if any, stays.
#pragma once

#include <chrono>
#include <string>

#include "implementation.h"

namespace vgc::fuzz {

struct Minimized {
  bool reproduced = false;  // the whole program showed the clause on replay
  std::string text;         // the minimized command file (print_program), when reproduced
  std::size_t before = 0, after = 0;
  int replays = 0;
};

// `program_text` is a command file (program_text.h); `clause` the clause it
// shows against `impl_spec` ("reference", "plugin:PATH", "exec:CMD",
// "verse:HOST"), opened with `open`. A non-empty `status` ("crash",
// "timeout", "fail") must be shown too: a crash is not minimized into a
// mere divergence at the same clause. A non-empty `host_cmd` (verse: only)
// starts the host first and ends it after (launched_host.h).
Minimized minimize_finding(const std::string& program_text, const std::string& clause, const std::string& impl_spec,
                           std::chrono::steady_clock::time_point deadline, int max_replays = 200,
                           const std::string& status = {}, const OpenOptions& open = {},
                           const std::string& host_cmd = {});

}  // namespace vgc::fuzz
