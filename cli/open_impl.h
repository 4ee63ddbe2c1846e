// open_impl.h — the implementation a subcommand certifies or replays
// against (--impl and --timeout), and the oracle checks it is judged with.
//
// Spec: docs/adapters.md (the three routes), docs/certify.md (--impl,
// --timeout); optional capabilities: docs/adapters.md section 5.
//
// Rationale: certify and replay must open an implementation and register
// the capability checks the same way, or a counterexample certify wrote
// could replay differently; one function each keeps them in step.
#pragma once

#include <memory>
#include <string>

#include "implementation.h"

namespace vgc::cli {

// The time limits of an out-of-process implementation: --timeout per
// call, --start-timeout per start (OpenOptions).
struct TimeLimits {
  double timeout_seconds = 5;
  double start_timeout_seconds = 60;
};

// Opens `spec` ("reference", "exec:CMD", "plugin:PATH", "verse:HOST[:PORT]") with
// those limits. On failure prints "vgc <subcommand>: <why>"
// to stderr and returns nullptr (the caller exits 2).
// verse_bone_form: --verse-bone-form (auto | spec | r6; docs/verse_wire.md section 4).
std::unique_ptr<Implementation> open_impl_or_report(const char* subcommand, const std::string& spec,
                                                    TimeLimits limits, const std::string& verse_bone_form = "auto");

// Registers the optional-capability checks of the oracles
// (oracles/capability_checks.h) when this vgc is built with them; returns
// whether it was. Without them a claimed capability cannot be judged.
bool register_oracle_checks();

}  // namespace vgc::cli
