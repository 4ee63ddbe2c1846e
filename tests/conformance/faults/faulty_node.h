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

#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <optional>
#include <set>
#include <vector>

#include "command.h"
#include "derived_rule.h"
#include "document_digest.h"
#include "node.h"

namespace vgc::faults {

struct FaultInfo {
  std::string_view name;            // "bone-cycles-accepted"
  std::string_view expected_clause; // the clause certification must name
  std::string_view expected_status; // "fail", "crash", "timeout"
  std::string_view description;
  // The node rule the fault breaks (rule.h), for the faults that break one
  // rule alone: the named bug kinds of issue 17 and one generated fault
  // "rule:<rule name>" per rule (its expected clause is the rule's clause,
  // conformance/rule_clauses.h: empty here, as reference/ and this library
  // stay free of the catalog mapping). Rule::None for the others.
  Rule breaks = Rule::None;
  bool generated = false;  // a "rule:<name>" fault
  // The derived document's rule the fault breaks (derived_rule.h): one
  // generated fault "rule:derived.<...>" per rule, which prints every
  // derived line that rule decides with another value (a value rule), or
  // lists other lines (a placement rule). DerivedRule::None for the others.
  DerivedRule breaks_derived = DerivedRule::None;
};

// Every fault, by index. Index 0 is "none" (the plain reference); the
// generated "rule:<name>" faults come last.
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
  explicit FaultyNode(int fault) : FaultyNode(std::vector<int>{fault}) {}
  explicit FaultyNode(std::vector<int> faults);
  FaultyAnswer apply(const Command& c);  // may abort() or hang, for the crash and hang faults
  std::string snapshot() const;
  std::string derived() const;
  // The optional capability requests (capability_documents.h), with the
  // capability faults applied.
  std::string request(const std::string& line) const;
  // The digests of snapshot() and derived() (document_digest.h): kept up to
  // date command by command while the documents are the node's own, read
  // from the printed documents once a fault rewrites them.
  DocumentDigests digests();
  // Whether its digest is cheap to keep (every fault but those that rewrite
  // the derived document: those are read from the printed documents, which
  // costs their size after every command, so such a node offers no digest
  // and is checked as a route without one).
  bool digest_cheap() const;

 private:
  bool is(std::string_view name) const;
  // The rule-breaking faults (FaultInfo::breaks): apply `c` and misbehave
  // exactly where the node applied the broken rule.
  FaultyAnswer apply_breaking(const Command& c, Rule broken);
  std::string rule_fault_snapshot(std::string text) const;
  // The derived document as a derived-rule fault (FaultInfo::breaks_derived)
  // prints it: `text` with the lines the broken rule decides changed.
  std::string derived_rule_fault(const std::string& text) const;
  FaultyAnswer answer(Reason r) const;
  // layer-kept-at-pick-id: `x` (layer id 0xFFFF) applied to the layer kept at 0xFFFF.
  Reason keep_layer_at_pick_id(cmd::LayerCreate x);
  // bone-kept-at-pick-id: `x` (bone id 0xFFFF) applied to the bone kept at 0xFFFF.
  Reason keep_bone_at_pick_id(cmd::BoneCreate x);
  // node_.apply, logged (history_) and followed by the digest.
  Reason apply_node(const Command& c, RuleTrace* trace = nullptr);
  // node_ replaced or reached into: the digest is computed again when next asked.
  void node_changed() { digest_stale_ = true; }
  // Whether a fault rewrites the documents the node prints now.
  bool documents_rewritten() const;
  // The node as the first `n` commands of history_ built it (the rule
  // faults' state before a command, only when their rule fires: a copy of
  // the node before every command would cost its size each time).
  Node replay(std::size_t n) const;
  std::vector<int> faults_;  // indexes into fault_catalog(); every one is active
  DerivedRule broken_derived_ = DerivedRule::None;  // a derived-rule fault's rule, if one is active
  Node node_;
  std::vector<Command> history_;  // every command node_ was given (the rule faults' path)
  // destroy-missing-ok-double-free and real32-ignored-grow-crash: what the
  // node went through (kept as it goes: a scan of history_ per command
  // would cost a case at scale its square).
  std::set<std::uint16_t> destroyed_layers_;
  bool vertex_deleted_ = false;
  std::optional<std::uint32_t> largest_vertex_id_;
  // grown-polygon-ids-live: the polygon storage's size, and the ids in it
  // that held a polygon or were deleted (the others from 32 on are live to
  // the fault: grown storage filled with 0).
  std::uint32_t polygon_storage_ = 32;
  std::set<std::uint32_t> unused_polygons_;
  // recreated-element-keeps-slots: a deleted element's slots, by (vertex
  // stack, element id, layer id, layer type).
  std::map<std::tuple<bool, std::uint32_t, std::uint16_t, LayerType>, Slot> kept_slots_;
  NodeDigest digest_;
  ChangeLog changes_;
  bool digest_stale_ = false;
  // Rule-breaking faults' lasting effects on the printed snapshot, by line
  // identity ("slot 3 5"): a line shown changed, or hidden, while the node's
  // line still has the step recorded; a removed line still shown while the
  // node has no line with its identity.
  std::map<std::string, std::uint32_t> corrupted_, hidden_;
  std::map<std::string, std::string> ghosts_;
};

}  // namespace vgc::faults
