// finding_cause.cpp — see finding_cause.h.
#include "finding_cause.h"

#include <fmt/format.h>

#include <map>
#include <numeric>
#include <set>

#include "confirm_finding.h"    // finding_kind
#include "exercised_clauses.h"  // command_kind

namespace vgc {
namespace {

// Whether the finding says the implementation took its last command as a
// success and stored nothing.
bool dropped(const Finding& f) {
  if (f.message.find("the state is unchanged (dropped)") != std::string::npos) return true;
  return f.message.find("(ok), snapshot: missing line") != std::string::npos ||
         f.message.find("(done), snapshot: missing line") != std::string::npos;
}

// Whether `c` creates a vertex or polygon at an id of 4,096 or more.
bool large_create(const Command& c) {
  constexpr std::uint32_t kLarge = 4096;
  if (auto* x = std::get_if<cmd::VertexSetXyzReal32>(&c)) return x->layer_id == 0 && x->vertex_id >= kLarge && x->vertex_id != kNone32;
  if (auto* x = std::get_if<cmd::VertexSetXyzReal64>(&c)) return x->layer_id == 0 && x->vertex_id >= kLarge && x->vertex_id != kNone32;
  if (auto* x = std::get_if<cmd::PolygonSetCornerUint32>(&c))
    return x->layer_id == 1 && x->v[0] != kNone32 && x->polygon_id >= kLarge && x->polygon_id != kNone32;
  return false;
}

}  // namespace

std::vector<CauseGroup> group_findings_by_cause(const RunResult& run) {
  // Each eligible finding's keys; findings sharing a key are joined.
  std::vector<std::size_t> members;
  std::vector<std::vector<std::string>> keys;
  for (std::size_t i = 0; i < run.clauses.size(); ++i) {
    const ClauseOutcome& co = run.clauses[i];
    if (!co.finding || co.finding->status != FindingStatus::Fail || co.program.commands.empty() || co.program.request)
      continue;
    if (finding_kind_of(*co.finding) != FindingKind::WrongAnswer || !dropped(*co.finding)) continue;
    const Command& last = co.program.commands.back();
    std::vector<std::string> k{"kind:" + command_kind(last)};
    if (large_create(last)) k.push_back("large");
    members.push_back(i);
    keys.push_back(std::move(k));
  }
  std::vector<std::size_t> parent(members.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&parent](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::map<std::string, std::size_t> first;
  for (std::size_t m = 0; m < members.size(); ++m)
    for (const auto& k : keys[m]) {
      const auto [it, fresh] = first.emplace(k, m);
      if (!fresh) parent[root(m)] = root(it->second);
    }
  std::map<std::size_t, std::vector<std::size_t>> by_root;
  for (std::size_t m = 0; m < members.size(); ++m) by_root[root(m)].push_back(m);
  std::vector<CauseGroup> groups;
  for (const auto& [r, ms] : by_root) {
    if (ms.size() < 2) continue;
    CauseGroup g;
    std::set<std::string> kinds;
    bool large = false;
    for (std::size_t m : ms) {
      g.clauses.push_back(std::string(run.clauses[members[m]].clause->id));
      kinds.insert(command_kind(run.clauses[members[m]].program.commands.back()));
      for (const auto& k : keys[m]) large = large || k == "large";
    }
    std::string kind_list;
    for (const auto& k : kinds) kind_list += (kind_list.empty() ? "`" : ", `") + k + "`";
    g.cause = large && kinds.size() > 1
                  ? fmt::format("one storage bound: each counterexample ends in a new vertex or polygon at an id of "
                                "4,096 or more ({}) that the implementation answered as a success and did not store",
                                kind_list)
                  : fmt::format("one dropped command: each counterexample ends in {} answered as a success with "
                                "nothing stored{}",
                                kind_list, large ? " (ids of 4,096 or more among them)" : "");
    groups.push_back(std::move(g));
  }
  return groups;
}

const CauseGroup* cause_group_of(const std::vector<CauseGroup>& groups, const std::string& clause_id) {
  for (const auto& g : groups)
    for (const auto& c : g.clauses)
      if (c == clause_id) return &g;
  return nullptr;
}

}  // namespace vgc
