// exercised_clauses.cpp — see exercised_clauses.h.
#include "exercised_clauses.h"

#include <algorithm>
#include <map>
#include <string>

#include "attribution.h"
#include "command_text.h"
#include "derived_document.h"
#include "document_diff.h"
#include "snapshot.h"

namespace vgc {
namespace {

// The identity of a document line: its kind and the ids that follow it
// ("slot 3 17", "edge_crease 4 2", "vertex 5"; "crease_vertex" alone).
std::string line_key(const std::string& line) {
  std::size_t words = 2;
  if (line.rfind("slot ", 0) == 0 || line.rfind("edge_crease ", 0) == 0) words = 3;
  if (line.rfind("crease_vertex ", 0) == 0 || line.rfind("crease_edge ", 0) == 0) words = 1;
  std::size_t pos = 0;
  for (std::size_t w = 0; w < words && pos != std::string::npos; ++w) {
    pos = line.find(' ', pos == 0 ? 0 : pos + 1);
  }
  return pos == std::string::npos ? line : line.substr(0, pos);
}

struct LineChange {
  std::string kind;
  std::string line;  // the line on whichever side has it (after, else before)
  bool added = false, removed = false;
};

// Every line that differs between two documents, keyed as line_key says.
std::vector<LineChange> changed_lines(const std::string& before, const std::string& after) {
  std::map<std::string, std::string> a, b;
  for (auto& l : split_lines(before)) a.emplace(line_key(l), l);
  for (auto& l : split_lines(after)) b.emplace(line_key(l), l);
  std::vector<LineChange> out;
  auto kind_of = [](const std::string& l) { return l.substr(0, l.find(' ')); };
  for (const auto& [k, l] : b) {
    auto it = a.find(k);
    if (it == a.end()) out.push_back({kind_of(l), l, true, false});
    else if (it->second != l) out.push_back({kind_of(l), l, false, false});
  }
  for (const auto& [k, l] : a)
    if (!b.count(k)) out.push_back({kind_of(l), l, false, true});
  return out;
}

}  // namespace

void exercised_clauses(const Node& before, const Command& c, Reason expected, const Node& after,
                       bool verdict_reported, std::vector<std::string_view>* out,
                       std::vector<std::string_view>* derived_only) {
  const std::size_t first = out->size();
  out->push_back("ACCEPT-1");
  out->push_back("STABLE-1");
  if (expected != Reason::Ok) {
    out->push_back(clause_for_rejection(c, expected, before));
    out->push_back("ATOMIC-1");
    if (verdict_reported) out->push_back("REASON-1");
  } else {
    out->push_back(clause_for_acceptance(c, before));
    // A line the command added could diverge by its absence or by its
    // values; a changed one by its values; a removed one by its presence.
    for (const auto& ch : changed_lines(print_snapshot(before), print_snapshot(after))) {
      if (!ch.removed) out->push_back(clause_for_snapshot(c, before, after, ch.kind, false));
      if (ch.added || ch.removed) out->push_back(clause_for_snapshot(c, before, after, ch.kind, true));
    }
    std::vector<std::string_view> from_derived;
    for (const auto& ch : changed_lines(print_derived(before), print_derived(after)))
      from_derived.push_back(clause_for_derived(after, ch.kind, bone_id_of(ch.line)));
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
