// finding_cause.cpp — see finding_cause.h.
#include "finding_cause.h"

#include <fmt/format.h>

#include <charconv>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <string_view>

#include "confirm_finding.h"    // finding_kind
#include "exercised_clauses.h"  // command_kind
#include "node.h"

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

// The first id of polygon storage past the first 32 (a node that grows its
// storage in chunks grows it there first: r6's VS_G_LAYER_CHUNK).
constexpr std::uint32_t kFirstChunk = 32;

// The polygon id a finding's difference names, if its last command is a
// polygon delete (either form) or its first differing line is a line of
// the implementation's for a polygon (`polygon P ...`, `slot L P ...` of a
// polygon layer).
std::optional<std::uint32_t> named_polygon(const ClauseOutcome& co, const Node& model) {
  const Command& last = co.program.commands.back();
  if (auto* d = std::get_if<cmd::PolygonDelete>(&last)) return d->polygon_id;
  if (auto* c = std::get_if<cmd::PolygonSetCornerUint32>(&last); c && c->layer_id == Node::kPolygonLayer && c->v[0] == kNone32)
    return c->polygon_id;
  // The line's words: "polygon P ..." or "slot L P ...".
  std::vector<std::string_view> words;
  std::string_view line = co.finding->observed_line;
  while (!line.empty() && words.size() < 3) {
    const auto space = line.find(' ');
    words.push_back(line.substr(0, space));
    line = space == std::string_view::npos ? std::string_view() : line.substr(space + 1);
  }
  const auto number = [](std::string_view w) -> std::optional<std::uint32_t> {
    std::uint32_t n = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), n);
    if (ec != std::errc() || end != w.data() + w.size()) return std::nullopt;
    return n;
  };
  if (words.size() >= 2 && words[0] == "polygon") return number(words[1]);
  if (words.size() == 3 && words[0] == "slot") {
    const auto layer = number(words[1]);
    const Layer* l = layer && *layer <= 0xFFFF ? model.find_layer(static_cast<std::uint16_t>(*layer)) : nullptr;
    if (l && !is_vertex_layer_type(l->type)) return number(words[2]);
  }
  return std::nullopt;
}

// Whether `co`'s difference is at a polygon id above the first chunk that
// was never live while its counterexample ran on the reference, though a
// polygon above the first chunk was: an id the implementation took for a
// live polygon when its storage grew ("unused" key).
bool unused_polygon_live(const ClauseOutcome& co) {
  // A shrunk counterexample is short; one of storage.scale's (10^4 to 10^5
  // commands, not shrunk) is not looked at: each step below may scan the
  // node's polygons.
  if (co.program.commands.size() > 2000) return false;
  Node model;
  std::set<std::uint32_t> ever;
  for (const Command& c : co.program.commands) {
    const std::size_t before = model.polygons().size();
    model.apply(c);
    // Only a create on layer 1 makes a polygon live: its own id, or for a
    // pick ("0xFFFFFFFF") the one id new to the node.
    const auto* p = std::get_if<cmd::PolygonSetCornerUint32>(&c);
    if (!p || p->layer_id != Node::kPolygonLayer || p->v[0] == kNone32) continue;
    if (p->polygon_id != kNone32) {
      if (model.polygons().count(p->polygon_id)) ever.insert(p->polygon_id);
    } else if (model.polygons().size() > before) {
      for (const auto& [id, slot] : model.polygons()) ever.insert(id);
    }
  }
  if (ever.empty() || *ever.rbegin() < kFirstChunk) return false;
  const auto p = named_polygon(co, model);
  return p && *p >= kFirstChunk && *p != kNone32 && ever.count(*p) == 0;
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
    if (unused_polygon_live(co)) {
      members.push_back(i);
      keys.push_back({"unused"});
      continue;
    }
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
    bool large = false, unused = false;
    for (std::size_t m : ms) {
      unused = unused || keys[m].front() == "unused";
      g.clauses.push_back(std::string(run.clauses[members[m]].clause->id));
      kinds.insert(command_kind(run.clauses[members[m]].program.commands.back()));
      for (const auto& k : keys[m]) large = large || k == "large";
    }
    std::string kind_list;
    for (const auto& k : kinds) kind_list += (kind_list.empty() ? "`" : ", `") + k + "`";
    g.cause = unused ? fmt::format("one cause: polygon ids that no command created, past the first {}, are live "
                                   "polygons to the implementation; each counterexample makes a polygon past id {} "
                                   "(its storage grows) and then meets such an id ({}), as a node does that fills "
                                   "grown polygon storage with corners in use instead of its unused marker",
                                   kFirstChunk, kFirstChunk - 1, kind_list)
            : large && kinds.size() > 1
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
