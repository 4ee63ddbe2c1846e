// forwarding_implementation.h — the one base of every decorator of an
// Implementation: it forwards each of the interface's calls to the
// implementation it wraps, so a decorator overrides only what it changes.
//
// Spec: the adapter boundary (implementation.h); docs/adapters.md.
//
// Rationale (issue 29, "one forwarding base for decorators"): the
// decorators (a recorder of the history since an instance started, one of
// capability requests, a host restarted by the user's command, a command
// the wire fuzzer already sent, an implementation a cancelled run never
// started) each forwarded a different subset of the interface by hand, so
// a call one of them left out quietly took the interface's default instead
// of the wrapped route's answer (a recorder that hid the route's limits, a
// restarted host that lost its late view). Forwarding everything here, a
// decorator says what it changes and nothing else. With nothing to forward
// to (no session after a failed restart, an implementation that never
// started), every call fails as a crash that says why, without sending
// anything.
#pragma once

#include <string>
#include <utility>

#include "implementation.h"

namespace vgc {

class ForwardingImplementation : public Implementation {
 public:
  std::string name() const override { return to_ ? to_->name() : name_; }
  Answer reset() override { return to_ ? to_->reset() : unanswered(); }
  Answer apply(const Command& c) override { return to_ ? to_->apply(c) : unanswered(); }
  Document snapshot() override { return to_ ? to_->snapshot() : undocumented(); }
  Document derived() override { return to_ ? to_->derived() : undocumented(); }
  std::string identity() const override { return to_ ? to_->identity() : name(); }
  std::string merge_identity() const override { return to_ ? to_->merge_identity() : name(); }
  Answer restart() override { return to_ ? to_->restart() : unanswered(); }
  std::uint64_t instance() const override { return to_ ? to_->instance() : 0; }
  RouteLimits limits() const override { return to_ ? to_->limits() : RouteLimits{}; }
  Document request(const std::string& line) override { return to_ ? to_->request(line) : undocumented(); }
  bool offers_digest() override { return to_ && to_->offers_digest(); }
  void expect_answer_bytes(std::size_t bytes) override {
    if (to_) to_->expect_answer_bytes(bytes);
  }
  DigestAnswer digest() override { return to_ ? to_->digest() : DigestAnswer{CallStatus::Crash, {}, why_}; }
  bool offers_late_view() override { return to_ && to_->offers_late_view(); }
  void use_late_view(bool on) override {
    if (to_) to_->use_late_view(on);
  }
  std::string late_view_wrong_format() override { return to_ ? to_->late_view_wrong_format() : std::string(); }
  void expect_commands(std::vector<Command> next) override {
    if (to_) to_->expect_commands(std::move(next));
  }
  bool last_apply_batched() const override { return to_ && to_->last_apply_batched(); }

 protected:
  // Forwards to `to` (not owned; may be null: see forward_to). `name` is
  // the name() and `why` the detail of every call while there is nothing
  // to forward to.
  explicit ForwardingImplementation(Implementation* to, std::string name = {}, std::string why = "no implementation")
      : to_(to), name_(std::move(name)), why_(std::move(why)) {}
  void forward_to(Implementation* to) { to_ = to; }
  Implementation* forwarded() const { return to_; }
  void set_why(std::string why) { why_ = std::move(why); }
  const std::string& why() const { return why_; }
  // A call that reached nothing: a crash, with why.
  Answer unanswered() const {
    Answer a;
    a.status = CallStatus::Crash;
    a.detail = why_;
    return a;
  }
  Document undocumented() const { return {CallStatus::Crash, {}, why_}; }

 private:
  Implementation* to_;
  std::string name_;
  std::string why_;
};

}  // namespace vgc
