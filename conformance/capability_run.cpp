// capability_run.cpp — see capability_run.h.
#include "capability_run.h"

#include "forwarding_implementation.h"
#include "property.h"

namespace vgc {
namespace {

// Forwards every call to `sut` and keeps the last capability request and
// its answer, so a capability finding can carry what the implementation
// answered (Finding::observed_document, for report.html's picture).
class RequestRecorder final : public ForwardingImplementation {
 public:
  explicit RequestRecorder(Implementation& sut) : ForwardingImplementation(&sut) {}
  Document request(const std::string& line) override {
    Document d = ForwardingImplementation::request(line);
    last_request = line;
    last_answer = d.status == CallStatus::Ok ? d.text : std::string();
    return d;
  }
  std::string last_request, last_answer;
};

}  // namespace

// Runs `check` as `request` says: check_drawn with the drawn value (0 when
// absent) for a check that draws, check otherwise.
std::optional<Finding> run_capability_check(const CapabilityCheck& check, const Node& model, Implementation& sut,
                                            const CapabilityRequest& request) {
  RequestRecorder recorder(sut);
  std::optional<Finding> f = check.check_drawn
                                 ? check.check_drawn(model, recorder, request.variant, request.draw.value_or(0))
                                 : check.check(model, recorder, request.variant);
  if (f && f->shown_by.empty() && !recorder.last_request.empty()) {
    f->shown_by = recorder.last_request;
    f->observed_document = recorder.last_answer;
  }
  return f;
}

std::string capability_clauses(const std::string& capability) {
  std::string out;
  for (const PropertySpec& spec : property_catalog()) {
    if (spec.capability != capability) continue;
    for (auto c : spec.clauses)
      if (out.find(std::string(c)) == std::string::npos) out += (out.empty() ? "" : ",") + std::string(c);
  }
  return out;
}

}  // namespace vgc
