// unstarted_implementation.h — the implementation of a certify run that was
// cancelled while the implementation was still starting (an exec program
// that takes seconds to answer ?hello on a loaded runner, a Verse login).
//
// Spec: docs/certify.md "Cancelling a run".
//
// Rationale (issue 31, item 6): a cancelled run always writes its
// incomplete report, even when nothing was judged yet, so that a CI job
// cancelled during the start still has a report that says so. The run is
// then made with this object in place of the implementation: every call
// fails without sending anything, the runner stops at once (cancel.h), and
// every selected clause is `unchecked`, its property stopped "cancelled by
// SIGTERM after 0 of N cases". It is never used for a run that was not
// cancelled.
#pragma once

#include <string>
#include <utility>

#include "forwarding_implementation.h"

namespace vgc::cli {

// Forwards to nothing: every call fails as a crash with `why`, sending
// nothing (forwarding_implementation.h).
class UnstartedImplementation final : public ForwardingImplementation {
 public:
  UnstartedImplementation(std::string name, std::string why)
      : ForwardingImplementation(nullptr, std::move(name), std::move(why)) {}
};

}  // namespace vgc::cli
