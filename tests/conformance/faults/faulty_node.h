// faulty_node.h — the reference node with one or several seeded faults, for
// proving that the conformance suite has teeth (issue 3, item 6), also when
// an implementation deviates in many places at once (issue 9).
//
// Spec: each fault breaks one clause of the catalog (conformance/clause.h);
// kFaults lists which, and the kill test checks that certification names it.
//
// Rationale: a fault is written as a wrapper around the real reference node:
// it rewrites a command before the node sees it, answers differently, or
// rewrites a document afterwards, the way a real implementation's bug would
// show from outside. The reference itself stays free of test code.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "command.h"
#include "node.h"

namespace vgc::faults {

struct FaultInfo {
  std::string_view name;            // "bone-cycles-accepted"
  std::string_view expected_clause; // the clause certification must name
  std::string_view expected_status; // "fail", "crash", "timeout"
  std::string_view description;
};

// Every fault, by index. Index 0 is "none" (the plain reference).
const std::vector<FaultInfo>& fault_catalog();
// Index of `name` in fault_catalog(), or -1.
int find_fault(std::string_view name);
// Parses a comma-separated list of fault names ("a,b,c"; "" and "none" are
// the plain reference). On an unknown name returns false and sets *error.
bool parse_fault_list(std::string_view list, std::vector<int>* out, std::string* error);
// "a,b,c" for a list of indexes ("none" when empty).
std::string fault_list_name(const std::vector<int>& faults);

// What a faulty node answers: applied, or rejected with a reason name.
struct FaultyAnswer {
  bool applied = false;
  std::string reason;
};

class FaultyNode {
 public:
  explicit FaultyNode(int fault) : faults_{fault} {}
  explicit FaultyNode(std::vector<int> faults) : faults_(std::move(faults)) {}
  FaultyAnswer apply(const Command& c);  // may abort() or hang, for the crash and hang faults
  std::string snapshot() const;
  std::string derived() const;
  // The optional capability requests (capability_documents.h), with the
  // capability faults applied.
  std::string request(const std::string& line) const;

 private:
  bool is(std::string_view name) const;
  FaultyAnswer answer(Reason r) const;
  std::vector<int> faults_;  // indexes into fault_catalog(); every one is active
  Node node_;
};

}  // namespace vgc::faults
