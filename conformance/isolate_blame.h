// isolate_blame.h — blame that isolates (issue 27, item 5): which
// counterexample the shrinker keeps, and which findings a counterexample
// elsewhere in the run explains.
//
// Spec: the clause catalog (clause.h) reached through the node's rules
// (rule_clauses.h), as attribution.h blames a first difference; every
// clause can be the one concerned.
//
// Rationale: attribution names every rule that could explain a first
// difference and blames the strictest. That is the most one counterexample
// can say, but a run sees many: a difference that one rule explains alone
// elsewhere is that rule's. So
//  * while shrinking (choose_shrink), a smaller counterexample whose first
//    difference one guard alone explains replaces one that several guards
//    explain (a 16-byte name with an unknown type byte, applied), when that
//    guard was among them; a smaller counterexample with the same
//    difference on the same command, explained by another rule alone,
//    moves the finding to that rule (a `-0` default stored as `0`, first
//    seen on a re-created layer, is the create rule's once a program
//    without the earlier create shows it); and once the kept
//    counterexample isolates, only isolating ones are kept;
//  * after shrinking, a finding one rule alone explains whose same
//    difference a smaller program shows by the rule of a clause already
//    found is that finding's again (commands_to_leave_out: the runner
//    replays those smaller programs): it is set aside, and so is its shape
//    for the rest of the property;
//  * after the run, a finding that several guards explain is tried with
//    the other guards' conditions taken away (isolating_variants): where
//    the implementation still deviates, that program is the finding's
//    isolating counterexample; where it then agrees, and another finding
//    of the run isolates one of the other guards (explained_elsewhere),
//    the finding is that one's again and is left out (a 16-byte name with
//    a bad type byte, applied by a host that reads names badly, is the
//    name clause's: the same host refuses the bad type with a good name).
//    Otherwise it stays, with its "Also explained by": no isolating
//    counterexample exists.
// Several effects of one applied command that the implementation did not
// apply (a sparse id and the create: ID-BOUND-1 and VERTEX-SET-1) are one
// effect seen by two rules, not two explanations: they stay as attribution
// blamed them.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "command.h"
#include "finding.h"
#include "implementation.h"
#include "run_result.h"

namespace vgc {

// Whether one rule alone explains `f`'s first difference (f.rules has at
// most one rule: findings no node rule decided count as isolating).
bool blame_isolates(const Finding& f);

enum class ShrinkChoice {
  Reject,  // not a smaller example of the finding being shrunk
  Keep,    // a smaller example of it
  Switch,  // a smaller example, of the rule that alone explains what the current one shared
};

// While shrinking `current` (the last command of `current_trace` showed
// it), what to do with `candidate`, a failure of the smaller program
// `candidate_trace`.
ShrinkChoice choose_shrink(const Finding& current, const std::vector<Command>& current_trace,
                           const Finding& candidate, const std::vector<Command>& candidate_trace);

// The earlier commands of `program` (indexes) without which the model
// would apply its last command by another rule, of a clause `found` says
// already has a finding, and no longer by the rule `f` (one rule alone,
// a wrong answer) is blamed on: the smaller programs to replay, to see
// whether the same difference is that finding's again (a default stored
// without its sign, first found on a new layer, seen again on a re-created
// one). Empty when nothing is worth a replay. Model only: cheap.
std::vector<std::size_t> commands_to_leave_out(const Finding& f, const std::vector<Command>& program,
                                               const std::function<bool(const std::string&)>& found);

// The shape of a finding one rule alone explains, for setting aside the
// same shape again once commands_to_leave_out showed it to be another
// finding's: the rule and the kind of difference ("layer.recreate.same_type
// snapshot layer").
std::string isolated_shape(const Finding& f);

// For a finding that several guards explain (the model refused its last
// command for more than one reason; the implementation applied it): the
// same program with its last command changed so that, in the model, only
// the blamed guard refuses it (a valid type for a 16-byte name with a bad
// type byte; a weight layer created first for a bone with a 16-byte label
// and no weight layer; the missing corner vertices created first). The
// runner replays them: an implementation that applies one too has an
// isolating counterexample for the blamed rule; one that refuses it does
// not break that rule there. Empty when no such change is known.
std::vector<std::vector<Command>> isolating_variants(const Finding& f, const std::vector<Command>& program);

// Of a run's findings, the ones that several guards explain (the model
// refused the command for more than one reason; the implementation applied
// it) while another finding, isolating and of the same kind or worse, is
// blamed on the clause of one of the other guards. Their indexes into
// `findings`.
std::vector<std::size_t> explained_elsewhere(const std::vector<const Finding*>& findings);

// The runner's last step before it decides the clauses: every finding of
// `run` that several guards explain, isolated as above (isolating_variants
// replayed on `sut`, explained_elsewhere), in place.
void isolate_findings(Implementation& sut, RunResult* run);

}  // namespace vgc
