// program.h — a counterexample: the commands from a fresh node, and what
// to ask after them (a capability check), as certify keeps it, a
// counterexample file holds it (program_text.h) and `vgc replay` runs it.
//
// Spec: docs/commands.md (the commands), docs/certify.md "Replaying a
// failure" (the directives); capabilities as in docs/adapters.md section 5.
//
// Rationale: vocabulary at the bottom (issue 29). The parser of
// counterexample files, the mesh importer and the report writers name a
// Program without including the runner that makes most of them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "command.h"
#include "finding.h"

namespace vgc {

// A check of an optional capability (capability.h) to repeat after a
// program's commands: the registered check for `capability`, with the
// variant the case chose (1..3, e.g. the subdivision level) and, for a
// check that draws more (CapabilityCheck::check_drawn, e.g. the edit of
// "edits"), the value drawn (absent: 0).
struct CapabilityRequest {
  std::string capability;  // "manifold", "subdivision", ... (a registry name)
  int variant = 1;
  std::optional<std::uint32_t> draw;
};

struct Program {
  Program() = default;
  Program(std::vector<Command> c, std::optional<CapabilityRequest> r = std::nullopt)
      : commands(std::move(c)), request(std::move(r)) {}

  std::vector<Command> commands;  // from a fresh node
  // Set when the finding is a capability check's: it is shown by that check
  // on the state after the commands, not by a command.
  std::optional<CapabilityRequest> request;
  // Set when the program reproduces a finding that depends on the
  // implementation's history (confirm_finding.h): the kind of failure it
  // brings about (crash, timeout, protocol error, wrong answer; written
  // "#! history KIND" by finding_kind_name). `vgc replay` then blames what
  // it shows as certify did: on STABLE-1 (ACCEPT-1 for a protocol error),
  // not on the command it came on.
  std::optional<FindingKind> history_kind;
  // Set when the program is a user's mesh as `vgc certify --mesh` judged it
  // ("#! mesh"): `vgc replay` then judges it as certify did (mesh_certification.h,
  // replay_mesh_program): a verdict per command and the snapshot once at the
  // end, no ?digest, the answer limits scaled with the mesh.
  bool mesh = false;
};

// One deviation a property showed: the finding and its counterexample.
// A new deviation is shrunk (RapidCheck) to the shortest program whose
// first divergence is in that clause; a tolerated one (known from the
// baseline) keeps the shortest program it was seen on, unshrunk.
struct PropertyFinding {
  Finding finding;
  Program program;
  bool tolerated_from_start = false;  // a baseline clause: seen, not shrunk
  int round = 0;                      // 0: the property's own seed; r: its r-th re-run past findings
};

}  // namespace vgc
