// fast_check.cpp — see fast_check.h.
#include "fast_check.h"

#include "derived_document.h"
#include "document_diff.h"
#include "snapshot.h"

namespace vgc {
namespace {

// True when the fast path sees no difference.
bool agrees(const std::vector<Command>& commands, Implementation& sut) {
  if (sut.reset().status != CallStatus::Ok) return false;
  Node ref;
  for (const Command& c : commands) {
    const Reason r = ref.apply(c);
    const Answer a = sut.apply(c);
    if (a.status != CallStatus::Ok || a.malformed) return false;
    // A `done` answer says nothing about the verdict: the documents at the
    // end show it (or the exact path does, if a later command hid it).
    if (a.verdict_reported && a.applied != (r == Reason::Ok)) return false;
  }
  // What the route does not show (RouteLimits) is not compared, as
  // check_step does not.
  const RouteLimits limits = sut.limits();
  const Document snap = sut.snapshot();
  if (snap.status != CallStatus::Ok) return false;
  const std::string expected = print_snapshot(ref);
  if (limits.subscriptions ? diff_documents(expected, snap.text).has_value()
                           : diff_documents(without_subscriptions(expected), without_subscriptions(snap.text)).has_value())
    return false;
  if (!limits.derived) return true;
  const Document derived = sut.derived();
  if (derived.status != CallStatus::Ok || diff_documents(print_derived(ref), derived.text)) return false;
  return true;
}

}  // namespace

ReplayResult check_program_exact(const std::vector<Command>& commands, Implementation& sut) {
  return replay_program(Program{commands, std::nullopt}, sut);
}

FastCheckResult check_program_fast(const std::vector<Command>& commands, Implementation& sut) {
  FastCheckResult r;
  if (agrees(commands, sut)) return r;
  r.exact_ran = true;
  r.replay = check_program_exact(commands, sut);
  return r;
}

}  // namespace vgc
