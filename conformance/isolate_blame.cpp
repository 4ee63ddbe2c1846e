// isolate_blame.cpp — see isolate_blame.h.
#include "isolate_blame.h"

#include <algorithm>
#include <string>

#include "cancel.h"
#include "clause.h"
#include "command_text.h"
#include "confirm_finding.h"
#include "node.h"
#include "rule_clauses.h"
#include "replay_program.h"

namespace vgc {
namespace {

// Shrunk programs longer than this are not tried without each command.
constexpr std::size_t kMaxLeaveOutProgram = 8;

bool explains(const Finding& f, const std::string& clause) {
  return std::any_of(f.rules.begin(), f.rules.end(), [&](Rule r) { return rule_clause(r) == clause; });
}

// Several guards refuse the command in the model, and the implementation
// applied it: each guard alone would explain that.
bool guards_disagree(const Finding& f) {
  return f.rules.size() > 1 &&
         std::all_of(f.rules.begin(), f.rules.end(), [](Rule r) { return rule_info(r).role == RuleRole::Guard; });
}

// What a finding says the two sides did, without the blame: the document
// and its first differing lines; for a verdict the start of the message
// ("`cmd`: expected X, observed Y"), before attribution's account of it,
// which names the rules; for a crash or a time-out its kind.
std::string difference_of(const Finding& f) {
  if (!f.shown_by.empty()) return f.shown_by + "\n" + f.expected_line + "\n" + f.observed_line;
  if (f.status != FindingStatus::Fail) return finding_kind(f);
  std::size_t at = f.message.find(". The model ");
  if (at == std::string::npos) at = f.message.find(" Blamed on rule ");
  return at == std::string::npos ? f.message : f.message.substr(0, at);
}

}  // namespace

bool blame_isolates(const Finding& f) { return f.rules.size() <= 1; }

// Whether clause `a`'s level is at least as strict as `b`'s (MUST, then
// SHOULD, then IMPLEMENTATION-DEFINED); an unknown id counts as the mildest.
static bool stricter_or_equal(const std::string& a, const std::string& b) {
  const auto rank = [](const std::string& id) {
    const Clause* c = find_clause(id);
    return c ? static_cast<int>(c->level) : 3;  // Must 0, Should 1, ImplementationDefined 2
  };
  return rank(a) <= rank(b);
}

ShrinkChoice choose_shrink(const Finding& current, const std::vector<Command>& current_trace,
                           const Finding& candidate, const std::vector<Command>& candidate_trace) {
  if (candidate.status != current.status) return ShrinkChoice::Reject;
  const bool isolates = blame_isolates(candidate);
  if (candidate.clause == current.clause)
    return blame_isolates(current) && !isolates ? ShrinkChoice::Reject : ShrinkChoice::Keep;
  if (!isolates) return ShrinkChoice::Reject;
  // Never to a milder clause: a MUST deviation is not hidden behind a SHOULD
  // or IMPLEMENTATION-DEFINED finding of the same command (an implementation
  // that drops crease_set_vertex whether its layer exists or not breaks the
  // MUST rule of the set layer, not only the reading of a missing one:
  // RouteLimits.AFaultTheSnapshotShowsIsStillCaught).
  if (stricter_or_equal(current.clause, candidate.clause) && !stricter_or_equal(candidate.clause, current.clause))
    return ShrinkChoice::Reject;
  // The difference several guards explained, explained by one of them alone.
  if (guards_disagree(current) && explains(current, candidate.clause)) return ShrinkChoice::Switch;
  // The same difference on the same command, in a smaller program where
  // another rule alone explains it.
  if (!current_trace.empty() && !candidate_trace.empty() &&
      print_command(current_trace.back()) == print_command(candidate_trace.back()) &&
      difference_of(current) == difference_of(candidate))
    return ShrinkChoice::Switch;
  return ShrinkChoice::Reject;
}

std::vector<std::size_t> commands_to_leave_out(const Finding& f, const std::vector<Command>& program,
                                               const std::function<bool(const std::string&)>& found) {
  std::vector<std::size_t> out;
  if (f.status != FindingStatus::Fail || f.rules.size() != 1 || program.size() < 2 ||
      program.size() > kMaxLeaveOutProgram)
    return out;
  for (std::size_t k = 0; k + 1 < program.size(); ++k) {
    Node model;
    RuleTrace trace;
    for (std::size_t i = 0; i < program.size(); ++i)
      if (i != k) model.apply(program[i], i + 1 == program.size() ? &trace : nullptr);
    if (trace.has(f.rules.front())) continue;
    bool other = false;
    for (Rule r : trace) other = other || found(std::string(rule_clause(r)));
    if (other) out.push_back(k);
  }
  return out;
}

std::string isolated_shape(const Finding& f) {
  const std::string& line = f.expected_line.empty() ? f.observed_line : f.expected_line;
  return std::string(f.rules.empty() ? "" : rule_name(f.rules.front())) + " " + f.shown_by + " " +
         line.substr(0, line.find(' '));
}

std::vector<std::vector<Command>> isolating_variants(const Finding& f, const std::vector<Command>& program) {
  std::vector<std::vector<Command>> out;
  if (!guards_disagree(f) || program.empty()) return out;
  const std::vector<Command> prefix(program.begin(), program.end() - 1);
  const auto valid_name = [](const std::string& n) { return !n.empty() && n.size() <= 15 && n.find('\0') == std::string::npos; };
  std::vector<std::vector<Command>> tries;
  const auto with_last = [&](const Command& last, const std::vector<Command>& first = {}) {
    std::vector<Command> p = prefix;
    p.insert(p.end(), first.begin(), first.end());
    p.push_back(last);
    tries.push_back(std::move(p));
  };
  // Each change takes one guard's condition away; every combination of
  // them is tried in the model, and those that leave the blamed guard alone
  // are kept.
  if (const auto* x = std::get_if<cmd::LayerCreate>(&program.back())) {
    for (int mask = 1; mask < 4; ++mask) {
      cmd::LayerCreate c = *x;
      if (mask & 1) c.type = static_cast<std::uint8_t>(LayerType::VertexReal);
      if (mask & 2) c.name = "isolated";
      with_last(c);
    }
  }
  if (const auto* x = std::get_if<cmd::BoneCreate>(&program.back())) {
    for (int mask = 1; mask < 8; ++mask) {
      cmd::BoneCreate c = *x;
      std::vector<Command> first;
      if (mask & 1) c.reference.clear();
      if (mask & 2) c.pos_label.clear(), c.rot_label.clear();
      if (mask & 4) {  // its weight layer created first
        if (!valid_name(x->weight)) continue;
        first.push_back(cmd::LayerCreate{kNone16, x->weight, static_cast<std::uint8_t>(LayerType::VertexReal), 0, 0.0});
      }
      with_last(c, first);
    }
  }
  if (const auto* x = std::get_if<cmd::PolygonSetCornerUint32>(&program.back())) {
    std::vector<Command> vertices;  // every vertex a corner names created first
    for (std::uint32_t v : x->v)
      if (v != kNone32) vertices.push_back(cmd::VertexSetXyzReal64{Node::kVertexLayer, v, 0.0, 0.0, 0.0});
    with_last(*x, vertices);
  }
  const Rule blamed = f.rules.front();
  for (auto& p : tries) {
    Node model;
    RuleTrace trace;
    for (std::size_t i = 0; i < p.size(); ++i) model.apply(p[i], i + 1 == p.size() ? &trace : nullptr);
    std::vector<Rule> guards;
    for (Rule r : trace)
      if (rule_info(r).role == RuleRole::Guard) guards.push_back(r);
    if (guards.size() == 1 && guards.front() == blamed) out.push_back(std::move(p));
  }
  return out;
}

std::vector<std::size_t> explained_elsewhere(const std::vector<const Finding*>& findings) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < findings.size(); ++i) {
    const Finding& f = *findings[i];
    if (!guards_disagree(f)) continue;
    const int severity = finding_severity(f);
    bool explained = false;
    for (const Finding* g : findings)
      explained = explained || (g != &f && g->clause != f.clause && blame_isolates(*g) && explains(f, g->clause) &&
                                finding_severity(*g) >= severity);
    if (explained) out.push_back(i);
  }
  return out;
}

void isolate_findings(Implementation& sut, RunResult* run) {
  std::vector<const Finding*> all;
  std::vector<std::pair<std::size_t, std::size_t>> where;
  for (std::size_t i = 0; i < run->properties.size(); ++i)
    for (std::size_t j = 0; j < run->properties[i].findings.size(); ++j) {
      all.push_back(&run->properties[i].findings[j].finding);
      where.emplace_back(i, j);
    }
  const std::vector<std::size_t> elsewhere = explained_elsewhere(all);
  std::vector<std::pair<std::size_t, std::size_t>> drop;
  for (std::size_t k = 0; k < all.size(); ++k) {
    PropertyFinding& pf = run->properties[where[k].first].findings[where[k].second];
    if (pf.tolerated_from_start || pf.program.request || cancel_signal()) continue;
    bool agrees = false;
    for (const auto& variant : isolating_variants(pf.finding, pf.program.commands)) {
      const ReplayResult r = replay_program(Program{variant, std::nullopt}, sut);
      if (!r.failure) {
        agrees = true;
        continue;
      }
      if (r.failed_at + 1 == static_cast<int>(variant.size()) && r.failure->clause == pf.finding.clause &&
          r.failure->status == pf.finding.status && blame_isolates(*r.failure)) {
        pf.finding = *r.failure;  // the blamed rule alone: its isolating counterexample
        pf.program = Program{variant, std::nullopt};
        agrees = false;
        break;
      }
    }
    if (agrees && blame_isolates(pf.finding) == false &&
        std::find(elsewhere.begin(), elsewhere.end(), k) != elsewhere.end())
      drop.push_back(where[k]);
  }
  for (auto it = drop.rbegin(); it != drop.rend(); ++it) {
    PropertyOutcome& p = run->properties[it->first];
    p.findings.erase(p.findings.begin() + static_cast<std::ptrdiff_t>(it->second));
    if (p.findings.empty() && p.status == PropertyStatus::Fail) p.status = PropertyStatus::Pass;
  }
}

}  // namespace vgc
