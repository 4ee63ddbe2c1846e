// reference_implementation.cpp — see reference_implementation.h.
#include "reference_implementation.h"

#include "capability_documents.h"
#include "derived_document.h"
#include "snapshot.h"

namespace vgc {

const char* call_status_name(CallStatus s) {
  switch (s) {
    case CallStatus::Ok: return "ok";
    case CallStatus::Crash: return "crash";
    case CallStatus::Timeout: return "timeout";
    case CallStatus::ProtocolError: return "protocol-error";
  }
  return "?";
}

Answer ReferenceImplementation::reset() {
  node_ = Node{};
  digest_ = NodeDigest{};
  Answer a;
  a.applied = true;
  return a;
}

Answer ReferenceImplementation::apply(const Command& c) {
  Answer a;
  const Reason r = node_.apply(c, nullptr, &changes_);
  digest_.update(node_, changes_);
  a.applied = r == Reason::Ok;
  if (!a.applied) a.reason = std::string(reason_name(r));
  return a;
}

Document ReferenceImplementation::snapshot() { return {CallStatus::Ok, print_snapshot(node_), {}}; }
Document ReferenceImplementation::derived() { return {CallStatus::Ok, print_derived(node_), {}}; }

Document ReferenceImplementation::request(const std::string& line) {
  auto text = answer_capability_request(node_, line);
  return {CallStatus::Ok, text ? *text : "error unknown request\n", {}};
}

}  // namespace vgc
