// open_impl.h — the implementation a subcommand certifies, replays, fuzzes
// or serves: the --impl option family (--impl, --timeout, --start-timeout,
// --verse-bone-form, --restart, --host-cmd), declared once for certify,
// replay, fuzz and serve; opening the implementation it names; and the oracle checks
// it is judged with.
//
// Spec: docs/adapters.md (the routes), docs/certify.md (--impl,
// --timeout, --start-timeout, --verse-bone-form, --restart), docs/fuzzing.md
// (--impl of a campaign); optional capabilities: docs/adapters.md section 5.
//
// Rationale: certify and replay must open an implementation and register
// the capability checks the same way, or a counterexample certify wrote
// could replay differently; one function each keeps them in step. The
// --impl value is read once, when the command line is parsed, into a Route
// (route.h): a value that names no route is a usage error (exit 2, naming
// --impl and the forms it takes) before anything runs, and every later
// decision asks the route, not the text.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "implementation.h"
#include "route.h"

namespace vgc::cli {

// The --impl option family's values.
struct ImplOptions {
  Route route;                           // --impl, read (default: reference)
  double timeout = 5;                    // --timeout: seconds per call (OpenOptions)
  double start_timeout = 60;             // --start-timeout: seconds per start
  std::string verse_bone_form = "auto";  // --verse-bone-form: auto | spec | r6
  std::string restart;                   // --restart: a shell command starting a fresh host ("" none)
  std::string host_cmd;                  // --host-cmd: the command running the host, which vgc starts ("" none)
  // Which were given on the command line (a subcommand's default may differ
  // from "not given": fuzz passes only what was given to its target).
  bool impl_given = false, timeout_given = false, bone_form_given = false;
};

// The members of the family a subcommand takes besides --impl.
enum ImplOption : unsigned {
  kTimeout = 1,       // --timeout
  kStartTimeout = 2,  // --start-timeout
  kBoneForm = 4,      // --verse-bone-form
  kRestart = 8,       // --restart
  kHostCmd = 16,      // --host-cmd (launched_host.h)
};

// Declares --impl (help: `impl_help`, the routes the subcommand takes) and
// the members `which` on `sub`, storing into *o (which must outlive the
// parse). A value of --impl that names no route fails the parse (exit 2,
// "--impl: unknown implementation ...; expected reference, exec:CMD ...").
void add_impl_options(CLI::App* sub, ImplOptions* o, unsigned which, const std::string& impl_help);

// After the parse: a member given that the route does not take
// (--verse-bone-form, --restart and --host-cmd are for verse: only;
// --host-cmd replaces --restart), said as a usage error; "" when there is
// none.
std::string impl_options_misuse(const ImplOptions& o);

// The OpenOptions of these values.
OpenOptions open_options_of(const ImplOptions& o);

// Opens o.route with o's limits (and, on a route that does not restart by
// itself, o.restart: restartable_host.h; with o.host_cmd, the host started
// first: launched_host.h). On failure prints
// "vgc <subcommand>: <why>" and what to do to stderr and returns nullptr
// (the caller exits 2).
std::unique_ptr<Implementation> open_impl_or_report(const char* subcommand, const ImplOptions& o);

// Registers the optional-capability checks of the oracles
// (oracles/capability_checks.h) when this vgc is built with them; returns
// whether it was. Without them a claimed capability cannot be judged.
bool register_oracle_checks();

}  // namespace vgc::cli
