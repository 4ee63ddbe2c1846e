// replay_program.cpp — see replay_program.h.
#include "replay_program.h"

#include <algorithm>
#include <set>

#include "capability.h"
#include "capability_run.h"
#include "check_step.h"
#include "confirm_finding.h"
#include "program_checker.h"
#include "scale_mesh.h"

namespace vgc {

ReplayResult replay_program(const Program& program, Implementation& sut) {
  ReplayResult r;
  // As in certify, ?capabilities is asked first, before the node is reset:
  // for the claim, and for the profile an exec program declares in its
  // answer (declared_profile.h), which the checks below follow.
  const auto names = query_capabilities(sut);
  const bool claimed =
      program.request && std::find(names.begin(), names.end(), program.request->capability) != names.end();
  if (auto f = reset_and_check_fresh(sut)) {
    r.failure = f;
    return r;
  }
  ProgramChecker checker(sut, /*follow_choices=*/true);
  // A program at scale (a case of storage.scale, a history reproducer) is
  // read as certify reads it: the documents every so often, a difference
  // bisected back to its command (program_checker.h); reading both after
  // each of 10^4 commands costs the node's size squared on a route without
  // ?digest.
  if (program.commands.size() >= kScaleMinElements / 2) checker.allow_sparse_reading();
  // The program is told ahead (a route may send several commands before one
  // round trip; a step judged wrong on a batch is judged again alone).
  sut.expect_commands(program.commands);
  struct Forget {
    Implementation& sut;
    ~Forget() { sut.expect_commands({}); }
  } forget{sut};
  for (std::size_t i = 0; i < program.commands.size(); ++i) {
    StepResult s = checker.step(program.commands[i]);
    for (auto& n : s.notes) r.notes.push_back(n);
    if (s.failure) {
      const std::size_t at = checker.failed_at() >= 0 ? static_cast<std::size_t>(checker.failed_at()) : i;
      r.failure = blame_as_history(program, *s.failure, at).value_or(*s.failure);
      r.failed_at = static_cast<int>(at);
      return r;
    }
  }
  if (auto l = checker.finish(program.commands)) {  // a ?digest that does not stand for the documents
    r.failure = l->step.failure;
    r.failed_at = l->index;
    return r;
  }
  // What a late subscriber is sent: every difference of a shape of its
  // own, in the reference's order (the first is the failure, the others
  // also failed), then the subscription kept in two formats, so that a
  // replay shows each finding certify showed, whichever clause it
  // tolerated first.
  std::set<std::string> shapes;
  std::vector<Localized> late;
  const auto one_per_shape = [&shapes](const std::string& shape) { return shapes.insert(shape).second; };
  const auto collect = [&late](const std::string&, const Localized& l) {
    late.push_back(l);
    return true;
  };
  if (auto l = checker.check_late_view(program.commands, one_per_shape, collect)) late.push_back(std::move(*l));
  if (!late.empty()) {
    r.failure = late.front().step.failure;
    r.failed_at = late.front().index;
    for (std::size_t i = 1; i < late.size(); ++i)
      if (late[i].step.failure->clause != r.failure->clause || late[i].step.failure->difference != r.failure->difference)
        r.also_failed.push_back(*late[i].step.failure);
    return r;
  }
  const Node& model = checker.model();
  if (!program.request) return r;
  const CapabilityRequest& q = *program.request;
  std::string clauses = capability_clauses(q.capability);
  if (clauses.empty()) clauses = "no clause of this vgc";
  if (!claimed) {
    r.not_judged = sut.name() + " does not claim the capability \"" + q.capability + "\" (certify reports " +
                   clauses + " as not-claimed)";
    return r;
  }
  const CapabilityCheck* check = find_capability_check(q.capability);
  if (!check) {
    r.not_judged = "this vgc has no oracle linked for the capability \"" + q.capability + "\" (" + clauses +
                   " cannot be judged)";
    return r;
  }
  if (auto f = run_capability_check(*check, model, sut, q)) {
    if (f->status == FindingStatus::NotJudged) {
      r.not_judged = "not judged (" + f->clause + "): " + f->message;
      return r;
    }
    r.failure = f;
    r.failed_at = static_cast<int>(program.commands.size());
  }
  return r;
}

}  // namespace vgc
