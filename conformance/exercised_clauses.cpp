// exercised_clauses.cpp — see exercised_clauses.h.
#include "exercised_clauses.h"

#include <algorithm>
#include <map>
#include <string>

#include "attribution.h"
#include "command_text.h"
#include "derived_document.h"
#include "derived_rule.h"
#include "document_diff.h"
#include "rule_clauses.h"
#include "snapshot.h"

namespace vgc {
namespace {

// Every line that differs between two documents, keyed as line_key says.
std::vector<DerivedChange> changed_lines(const std::string& before, const std::string& after) {
  std::map<std::string, std::string> a, b;
  for (auto& l : split_lines(before)) a.emplace(line_key(l), l);
  for (auto& l : split_lines(after)) b.emplace(line_key(l), l);
  std::vector<DerivedChange> out;
  auto kind_of = [](const std::string& l) { return l.substr(0, l.find(' ')); };
  for (const auto& [k, l] : b) {
    auto it = a.find(k);
    if (it == a.end() || it->second != l) out.push_back({kind_of(l), l});
  }
  for (const auto& [k, l] : a)
    if (!b.count(k)) out.push_back({kind_of(l), l});
  return out;
}

}  // namespace

std::vector<DerivedChange> derived_changes(const Node& before, const Node& after) {
  return changed_lines(print_derived(before), print_derived(after));
}

void exercised_clauses(const std::vector<DerivedChange>& derived_changed, const Command& c, Reason expected,
                       const RuleTrace& rules, const Node& after, bool verdict_reported,
                       std::vector<std::string_view>* out, std::vector<std::string_view>* derived_only) {
  (void)c;
  const std::size_t first = out->size();
  out->push_back("ACCEPT-1");
  out->push_back("STABLE-1");
  for (Rule r : rules) out->push_back(rule_clause(r));
  if (expected != Reason::Ok) {
    if (verdict_reported) out->push_back("REASON-1");
  } else {
    std::vector<std::string_view> from_derived;
    for (DerivedRule r : derived_rules_changed(derived_changed, rules, after))
      from_derived.push_back(derived_rule_clause(r));
    if (!derived_only) {
      out->insert(out->end(), from_derived.begin(), from_derived.end());
    } else {
      std::sort(from_derived.begin(), from_derived.end());
      from_derived.erase(std::unique(from_derived.begin(), from_derived.end()), from_derived.end());
      for (auto clause : from_derived)
        if (std::find(out->begin() + static_cast<std::ptrdiff_t>(first), out->end(), clause) == out->end())
          derived_only->push_back(clause);
    }
  }
  std::sort(out->begin() + static_cast<std::ptrdiff_t>(first), out->end());
  out->erase(std::unique(out->begin() + static_cast<std::ptrdiff_t>(first), out->end()), out->end());
}

std::vector<DerivedRule> derived_rules_changed(const std::vector<DerivedChange>& derived_changed, const RuleTrace& rules,
                                               const Node& after) {
  std::vector<DerivedRule> out;
  const auto add = [&out](DerivedRule r) {
    if (r != DerivedRule::None && std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
  };
  for (const auto& ch : derived_changed) {
    // A change is one element's lines (a polygon's edges are one change):
    // the rule that decided them; and a polygon's edges were placed anew
    // when the command gave it its corners.
    add(derived_rule_of(after, ch.line));
    if (ch.kind == "edge_crease" && (rules.has(Rule::PolygonCreate) || rules.has(Rule::PolygonRedefine)))
      add(derived_place_rule(ch.kind));
  }
  std::sort(out.begin(), out.end());
  return out;
}

const std::vector<std::string_view>& fresh_node_clauses() {
  static const std::vector<std::string_view> clauses = {"LAYER-BASE-1", "CREASE-INITIAL-1", "STABLE-1"};
  return clauses;
}

std::string command_kind(const Command& c) {
  std::string text = print_command(c);
  text.resize(std::min(text.find(' '), text.size()));
  return text;
}

}  // namespace vgc
