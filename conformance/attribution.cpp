// attribution.cpp — see attribution.h.
#include "attribution.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <sstream>

#include "clause.h"
#include "command_text.h"
#include "derived_document.h"
#include "number_text.h"
#include "rule_clauses.h"
#include "snapshot.h"

namespace vgc {
namespace {

const Clause* clause_of(Rule r) { return find_clause(rule_clause(r)); }

int strictness(Rule r) {
  const Clause* c = clause_of(r);
  return c ? clause_strictness(c->level) : 0;
}

// "rule vertex.move.keeps_slots (VERTEX-SET-1, MUST)"
std::string rule_label(Rule r) {
  const Clause* c = clause_of(r);
  return "rule " + std::string(rule_name(r)) + " (" + std::string(rule_clause(r)) +
         (c ? ", " + std::string(clause_level_name(c->level)) : "") + ")";
}

// The blame for `candidates` (in the order they explain the difference
// best), with `what` saying what the two sides did. The strictest level
// goes first; ties keep their order.
Blame make_blame(std::vector<Rule> candidates, const std::string& what) {
  std::vector<Rule> rules;
  for (Rule r : candidates)
    if (std::find(rules.begin(), rules.end(), r) == rules.end()) rules.push_back(r);
  if (rules.empty()) rules.push_back(Rule::None);
  std::stable_sort(rules.begin(), rules.end(), [](Rule a, Rule b) { return strictness(a) > strictness(b); });
  Blame b;
  b.rules = rules;
  b.clause = std::string(rule_clause(rules[0]));
  b.explanation = what + " Blamed on " + rule_label(rules[0]) + ": " + std::string(rule_info(rules[0]).says) + ".";
  if (rules.size() > 1) {
    b.explanation += " Also explained by";
    for (std::size_t i = 1; i < rules.size(); ++i)
      b.explanation += (i == 1 ? " " : "; ") + rule_label(rules[i]) + ": " + std::string(rule_info(rules[i]).says);
    b.explanation += "; the strictest level is the one reported.";
  }
  return b;
}

template <class Pred> std::vector<Rule> select(const RuleTrace& trace, Pred pred) {
  std::vector<Rule> out;
  for (Rule r : trace)
    if (pred(rule_info(r))) out.push_back(r);
  return out;
}

std::vector<Rule> with_role(const RuleTrace& trace, RuleRole role, std::uint8_t line) {
  return select(trace, [&](const RuleInfo& i) { return i.role == role && (i.lines & line); });
}

// The rules an applied command applied that change state (not its guards,
// not what it keeps): what an implementation refusing it goes against.
std::vector<Rule> effects(const RuleTrace& trace) {
  return select(trace, [](const RuleInfo& i) {
    return i.role != RuleRole::Guard && i.role != RuleRole::Keep && i.role != RuleRole::Accept;
  });
}

std::string first_word(const std::string& line) { return line.substr(0, line.find(' ')); }

std::map<std::string, std::string> lines_by_key(const std::string& doc) {
  std::map<std::string, std::string> out;
  for (auto& l : split_lines(doc))
    if (!l.empty()) out.emplace(line_key(l), l);
  return out;
}

// The quoted fields of a snapshot line (names and labels), in order.
std::vector<std::string> quoted_parts(const std::string& line) {
  std::vector<std::string> parts;
  for (std::size_t i = line.find('"'); i != std::string::npos;) {
    const std::size_t end = line.find('"', i + 1);
    if (end == std::string::npos) break;
    parts.push_back(line.substr(i + 1, end - i - 1));
    i = line.find('"', end + 1);
  }
  return parts;
}

std::string quoted(const std::string& line) { return "\"" + line + "\""; }

// Whether `line` is an element at the "pick a free id" sentinel of its kind
// (layer and bone 0xFFFF, vertex and polygon 0xFFFFFFFF) and the command
// asked for a pick of that kind (`trace` has its pick rule): the sentinel
// kept as the id, no pick made.
bool kept_pick_sentinel(const std::string& line, const RuleTrace& trace) {
  const std::string kind = first_word(line);
  const std::string key = line_key(line);
  const std::string id = key.substr(kind.size() + 1);  // the snapshot prints the sentinels in hex
  const bool id16 = id == "0xFFFF" || id == "65535", id32 = id == "0xFFFFFFFF" || id == "4294967295";
  if (kind == "layer") return trace.has(Rule::LayerIdPick) && id16;
  if (kind == "bone") return trace.has(Rule::BoneIdPick) && id16;
  if (kind == "vertex") return trace.has(Rule::VertexIdPick) && id32;
  if (kind == "polygon") return trace.has(Rule::PolygonIdPick) && id32;
  return false;
}

std::string written_by(const std::optional<Written>& w) {
  if (!w || w->rule == Rule::None) return "";
  return " (last written by rule " + std::string(rule_name(w->rule)) +
         (w->step == 0 ? " on the fresh node)" : " at command " + std::to_string(w->step) + ")");
}

// The node rule that wrote the crease setting a derived crease rule reads
// (the setting's Written), or Rule::None for a rule that reads no setting.
Rule setting_rule(const Node& node, DerivedRule r) {
  switch (r) {
    case DerivedRule::VertexCreaseConstant:
    case DerivedRule::VertexCreaseLayer:
    case DerivedRule::VertexCreaseLayerMissing:
    case DerivedRule::VertexCreaseInitial: return node.vertex_crease().written.rule;
    case DerivedRule::EdgeCreaseConstant:
    case DerivedRule::EdgeCreaseLayer:
    case DerivedRule::EdgeCreaseLayerMissing:
    case DerivedRule::EdgeCreaseInitial: return node.edge_crease().written.rule;
    case DerivedRule::None:
    case DerivedRule::EdgePerCorner:
    case DerivedRule::BonePoseRoot:
    case DerivedRule::BonePoseParentMissing:
    case DerivedRule::BonePoseChained:
    case DerivedRule::BonePosePerBone:
    case DerivedRule::kCount: break;
  }
  return Rule::None;
}

}  // namespace

Blame blame_verdict(const Command& c, Reason expected, const RuleTrace& trace) {
  const std::string cmd = "`" + print_command(c) + "`";
  if (expected != Reason::Ok) {
    // Every guard that refuses it: the one that decided, then any other
    // that would have refused it too (Node::apply).
    auto guards = select(trace, [](const RuleInfo& i) { return i.role == RuleRole::Guard; });
    return make_blame(guards, "The model refused " + cmd + " (" + std::string(reason_name(expected)) +
                                  "); the implementation applied it.");
  }
  std::string applied;
  for (Rule r : trace) applied += (applied.empty() ? "" : ", ") + std::string(rule_name(r));
  // A value accepted at a guard's boundary (a 15-byte name) is the likeliest
  // reason to refuse it: those rules first, then everything it changes.
  auto cands = select(trace, [](const RuleInfo& i) { return i.role == RuleRole::Accept; });
  const auto changes = effects(trace);
  cands.insert(cands.end(), changes.begin(), changes.end());
  return make_blame(cands, "The model applied " + cmd + " by the rules " + applied + "; the implementation did not.");
}

Blame blame_snapshot(const Node& before, const Node& after, Reason expected, const RuleTrace& trace,
                     const DocumentDifference& d, const std::string& observed) {
  if (expected != Reason::Ok) {
    std::vector<Rule> guards = select(trace, [](const RuleInfo& i) { return i.role == RuleRole::Guard; });
    const std::string guard = guards.empty() ? std::string("?") : std::string(rule_name(guards.back()));
    return make_blame({Rule::RejectedChangesNothing},
                      "The model refused the command (rule " + guard + ") and changed nothing; the implementation " +
                          (d.expected_line.empty() ? "added " + quoted(d.observed_line)
                           : d.observed_line.empty() ? "removed " + quoted(d.expected_line)
                                                     : "changed " + quoted(d.expected_line) + " to " +
                                                           quoted(d.observed_line)) +
                          ".");
  }
  const auto before_lines = lines_by_key(print_snapshot(before));
  const auto after_lines = lines_by_key(print_snapshot(after));
  const auto observed_lines = lines_by_key(observed);
  std::string e = d.expected_line, o = d.observed_line;
  // The first difference pairs lines by their first two words; a line's
  // identity may be one word (crease_vertex) or three (slot <layer> <id>):
  // a line missing on one side whose identity the other side has is a
  // changed line.
  if (o.empty() && !e.empty()) {
    if (auto it = observed_lines.find(line_key(e)); it != observed_lines.end()) o = it->second;
  } else if (e.empty() && !o.empty()) {
    if (auto it = after_lines.find(line_key(o)); it != after_lines.end()) e = it->second;
  }
  const std::string ke = e.empty() ? "" : line_key(e), ko = o.empty() ? "" : line_key(o);
  const std::uint32_t now = after.step();

  std::vector<Rule> cands;
  std::string what;
  const auto add = [&cands](const std::vector<Rule>& rs) { cands.insert(cands.end(), rs.begin(), rs.end()); };

  if (!e.empty() && !o.empty() && ke == ko) {  // the same line, other values
    const std::uint8_t bit = line_kind_bit(first_word(e));
    const auto w = line_written(after, e);
    if (w && w->step == now && w->rule != Rule::None) {
      // A 15-byte name stored cut: the accept rules (every one is about a
      // name) explain a difference only where the names differ.
      if (quoted_parts(e) != quoted_parts(o)) add(with_role(trace, RuleRole::Accept, bit));
      cands.push_back(w->rule);
      what = "The model wrote " + quoted(e) + " by rule " + std::string(rule_name(w->rule)) +
             "; the implementation shows " + quoted(o) + ".";
    } else {
      add(with_role(trace, RuleRole::Keep, bit));
      what = "The command leaves " + quoted(e) + " as it was" + written_by(w) + "; the implementation changed it to " +
             quoted(o) + ".";
    }
  } else {
    if (!e.empty()) {  // the implementation lacks the model's line `ke`
      const std::uint8_t bit = line_kind_bit(first_word(e));
      const auto w = line_written(after, e);
      if (before_lines.count(ke)) {
        add(with_role(trace, RuleRole::Keep, bit));
        if (w && w->step == now) {  // the command re-placed and re-wrote it (a re-typed layer's slot)
          add(with_role(trace, RuleRole::Place, bit));
          cands.push_back(w->rule);
        }
        what = "The model keeps " + quoted(e) + written_by(w) + "; the implementation has no line `" + ke + "`.";
      } else {
        const auto place = with_role(trace, RuleRole::Place, bit);
        // Did the implementation put a line of this kind at another id?
        std::string elsewhere;
        for (const auto& [k, l] : observed_lines)
          if (first_word(l) == first_word(e) && !after_lines.count(k) && !before_lines.count(k)) {
            elsewhere = l;
            break;
          }
        if (!elsewhere.empty() && !place.empty() && kept_pick_sentinel(elsewhere, trace) && w && w->step == now) {
          // No pick at all: the implementation kept the "pick a free id"
          // sentinel as the id. That is no other free id (the pick rule's
          // reading), but an element at an id it cannot have: the rule
          // that creates it is broken (docs/spec_facts.md 5).
          cands.push_back(w->rule);
        } else if (!elsewhere.empty() && !place.empty()) {
          add(place);
        } else {
          add(place);
          if (w && w->step == now && !(bit == kLineSlot && !place.empty())) cands.push_back(w->rule);
        }
        what = "The model created " + quoted(e) + written_by(w) + "; the implementation " +
               (elsewhere.empty() ? "has no line `" + ke + "`."
                : kept_pick_sentinel(elsewhere, trace)
                    ? "created `" + line_key(elsewhere) + "` (" + quoted(elsewhere) + "): it kept the \"pick a free "
                      "id\" sentinel as the id instead of picking one."
                    : "created `" + line_key(elsewhere) + "` instead (" + quoted(elsewhere) + "): the "
                      "command asked for `" + ke + "`.");
      }
    }
    if (!o.empty()) {  // the implementation has a line `ko` the model does not
      const std::uint8_t bit = line_kind_bit(first_word(o));
      std::string extra;
      if (auto it = before_lines.find(ko); it != before_lines.end()) {
        add(with_role(trace, RuleRole::Remove, bit));
        extra = "The model removed " + quoted(it->second) + "; the implementation still has " + quoted(o) + ".";
      } else {
        add(with_role(trace, RuleRole::Place, bit));
        add(with_role(trace, RuleRole::Value, bit));
        extra = "The implementation has " + quoted(o) + ", a line the model does not create.";
      }
      what += (what.empty() ? "" : " ") + extra;
    }
  }
  if (cands.empty()) add(effects(trace));
  return make_blame(cands, what);
}

std::string difference_shape(const Node& after, const DocumentDifference& d) {
  const std::string& line = d.expected_line.empty() ? d.observed_line : d.expected_line;
  std::string shape = first_word(line) + (d.expected_line.empty()   ? " extra"
                                          : d.observed_line.empty() ? " missing"
                                                                    : " changed");
  if (!d.expected_line.empty())
    if (const auto w = line_written(after, d.expected_line); w && w->rule != Rule::None)
      shape += " " + std::string(rule_name(w->rule));
  return shape;
}

std::optional<Blame> blame_subscription_dump(const Node& after, const DocumentDifference& d) {
  const auto e = split_words(d.expected_line), o = split_words(d.observed_line);
  if (e.size() < 4 || o.size() != e.size() || e[0] != "slot" || o[0] != "slot" || e[1] != o[1] || e[2] != o[2])
    return std::nullopt;
  std::uint32_t id = 0;
  if (!parse_uint(e[1], 16, &id)) return std::nullopt;
  const Layer* layer = after.find_layer(static_cast<std::uint16_t>(id));
  const bool real = layer && (layer->type == LayerType::VertexXyz || layer->type == LayerType::VertexReal ||
                              layer->type == LayerType::PolygonCornerReal || layer->type == LayerType::PolygonFaceReal);
  if (!real) return std::nullopt;
  const auto bits = [](double v) {
    std::uint64_t b = 0;
    std::memcpy(&b, &v, sizeof b);
    return b;
  };
  const double def = layer->def_real;
  bool differs_in_bits = false;
  std::string held;  // the model's values that differ from the default in their bits, with both bit patterns
  const auto hex = [](std::uint64_t v) {
    static const char* const kDigits = "0123456789ABCDEF";
    std::string out = "0x";
    for (int shift = 60; shift >= 0; shift -= 4) out += kDigits[(v >> shift) & 0xF];
    return out;
  };
  for (std::size_t i = 3; i < e.size(); ++i) {
    double ev = 0, ov = 0;
    if (!parse_f64(e[i], &ev) || !parse_f64(o[i], &ov)) return std::nullopt;
    if (bits(ov) != bits(def) || !(ev == def)) return std::nullopt;  // shown the default; the model's value equals it
    if (bits(ev) == bits(def)) continue;
    differs_in_bits = true;
    if (held.empty()) held = format_f64(ev) + " (bits " + hex(bits(ev)) + ")";
  }
  if (!differs_in_bits) return std::nullopt;
  Blame b;
  b.rules = {Rule::Subscribe};
  b.clause = std::string(rule_clause(Rule::Subscribe));
  b.explanation = "The newcomer was shown " + quoted(d.observed_line) + ": the layer's default " + format_f64(def) +
                  " (bits " + hex(bits(def)) + ") where the model holds " + held + ", " + quoted(d.expected_line) +
                  ", equal as numbers and not bit for bit; so the "
                  "host sent it nothing for that slot, as for a slot at the default, comparing by value. Every "
                  "watcher was sent the value the model holds: what a new subscriber is sent of a layer is the "
                  "subscription's. Blamed on " + rule_label(Rule::Subscribe) + ": a subscription to a layer is "
                  "sent every slot that is not at its default, bit for bit (docs/adapters.md section 7, the late subscriber).";
  return b;
}

Blame blame_fresh(const Node& fresh, const DocumentDifference& d, bool derived) {
  const std::string& line = d.expected_line.empty() ? d.observed_line : d.expected_line;
  const std::string kind = first_word(line);
  Rule rule = Rule::BaseLayers;
  if (derived) {
    // An effective crease is read from a crease setting: the rule that
    // wrote the setting (on a fresh node, node.initial_creases). A fresh
    // node has no other derived line: any other is the base layers'.
    if (const Rule wrote = setting_rule(fresh, derived_rule_of(fresh, line)); wrote != Rule::None) rule = wrote;
  } else if (const auto w = line_written(fresh, line); w && w->rule != Rule::None) {
    rule = w->rule;
  } else if ((line_kind_bit(kind) & rule_info(Rule::InitialCreases).lines) != 0) {
    rule = Rule::InitialCreases;
  }
  Blame b = make_blame({rule}, "");
  b.explanation.erase(0, 1);  // "Blamed on ...": the difference says what the two sides show
  return b;
}

DerivedBlame blame_derived(const Node& after, const DocumentDifference& d) {
  DerivedBlame b;
  const std::string& line = d.expected_line.empty() ? d.observed_line : d.expected_line;
  // The two sides list different lines (one side lacks a line, or the first
  // difference pairs lines of different identities): for a kind whose
  // lines a derived rule places, the placement is what differs.
  const bool other_lines =
      d.expected_line.empty() || d.observed_line.empty() || line_key(d.expected_line) != line_key(d.observed_line);
  const DerivedRule place = derived_place_rule(d.kind);
  // Bone lines follow the live bones, which the snapshot judged equal
  // first: a bone the model has is blamed on the rule that poses it.
  b.rule = other_lines && place == DerivedRule::EdgePerCorner ? place : derived_rule_of(after, line);
  b.clause = std::string(derived_rule_clause(b.rule));
  const Clause* c = find_clause(b.clause);
  b.explanation = "Blamed on derived rule " + std::string(derived_rule_name(b.rule)) + " (" + b.clause +
                  (c ? ", " + std::string(clause_level_name(c->level)) : "") +
                  "): " + std::string(derived_rule_info(b.rule).says) + ".";
  return b;
}

std::string_view clause_for_derived(const Node& node, std::string_view kind, long bone_id) {
  const std::string line = bone_id < 0 ? std::string(kind) : std::string(kind) + " " + std::to_string(bone_id);
  return derived_rule_clause(derived_rule_of(node, line));
}

const std::vector<std::string_view>& derived_only_clauses() {
  static const std::vector<std::string_view> clauses = [] {
    std::vector<std::string_view> out;
    for (std::size_t i = 1; i < kDerivedRuleCount; ++i) {
      const std::string_view clause = derived_rule_clause(static_cast<DerivedRule>(i));
      if (rules_of_clause(clause).empty() && std::find(out.begin(), out.end(), clause) == out.end())
        out.push_back(clause);
    }
    return out;
  }();
  return clauses;
}

bool slot_at_told_default(const Node& after, const DocumentDifference& d, const std::string& observed) {
  const auto e = split_words(d.expected_line);
  if (e.size() < 4 || e[0] != "slot" || d.observed_line.empty() || line_key(d.expected_line) != line_key(d.observed_line))
    return false;
  std::uint32_t lid = 0, element = 0;
  if (!parse_uint(e[1], 16, &lid) || !parse_uint(e[2], 32, &element)) return false;
  const Layer* layer = after.find_layer(static_cast<std::uint16_t>(lid));
  if (!layer || lid < 2) return false;
  const auto id = static_cast<std::uint16_t>(lid);
  const auto default_line = [id, element](const Layer& l) {  // the line of a slot at `l`'s default
    std::string line = snapshot_slot_line(id, l.type, element, default_slot(l));
    if (!line.empty() && line.back() == '\n') line.pop_back();
    return line;
  };
  if (d.expected_line != default_line(*layer)) return false;
  // The layer line the late subscriber was shown: `layer ID "name" TYPE def_uint def_real subscription`.
  const std::string head = "layer " + e[1] + " ";
  for (const std::string& line : split_lines(observed)) {
    if (line.rfind(head, 0) != 0) continue;
    std::string name;
    std::size_t used = 0, error_at = 0;
    if (!parse_quoted(std::string_view(line).substr(head.size()), &name, &used, &error_at)) return false;
    const auto w = split_words(line.substr(head.size() + used));
    if (w.size() != 4) return false;
    Layer told = *layer;
    std::uint32_t def_uint = 0;
    double def_real = 0;
    if (w[1] != "-" && parse_uint(w[1], 32, &def_uint)) told.def_uint = def_uint;
    if (w[2] != "-" && parse_f64(w[2], &def_real)) told.def_real = def_real;
    const std::string shown = default_line(told);
    return shown == d.observed_line && shown != d.expected_line;
  }
  return false;
}

}  // namespace vgc
