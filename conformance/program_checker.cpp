// program_checker.cpp — see program_checker.h.
#include "program_checker.h"

#include <utility>

#include "attribution.h"
#include "command_text.h"
#include "derived_document.h"
#include "document_diff.h"
#include "exercised_clauses.h"
#include "rule_clauses.h"
#include "snapshot.h"

namespace vgc {
namespace {

// The digests stand for the documents only on a route that shows both
// whole (RouteLimits): otherwise the documents are compared as the route
// allows, step by step.
bool digest_usable(Implementation& sut) {
  const RouteLimits limits = sut.limits();
  return limits.derived && limits.subscriptions && sut.offers_digest();
}

}  // namespace

ProgramChecker::ProgramChecker(Implementation& sut, bool follow_choices, bool use_digest)
    : sut_(sut), follow_choices_(follow_choices), digest_on_(use_digest && digest_usable(sut)) {}

void ProgramChecker::allow_sparse_reading() {
  if (!digest_on_ && applied_.empty()) sparse_ = true;
}

std::optional<std::size_t> ProgramChecker::removed_slot_at(const std::string& line) const {
  // Each command costs two printed snapshots here: a case at scale (10^4
  // commands and more, which no route with a late view runs today) is not
  // searched.
  constexpr std::size_t kMaxCommandsSearched = 2000;
  if (line.rfind("slot ", 0) != 0 || applied_.size() > kMaxCommandsSearched) return std::nullopt;
  const std::string key = line_key(line);
  // What the node prints: whether it holds `line`, and a line of its key.
  const auto holds = [&line, &key](const Node& n, bool* has_key) {
    bool held = false;
    *has_key = false;
    for (const std::string& l : split_lines(print_snapshot(n))) {
      held = held || l == line;
      *has_key = *has_key || (l.rfind("slot ", 0) == 0 && line_key(l) == key);
    }
    return held;
  };
  bool has_key = false;
  if (holds(model_, &has_key)) return std::nullopt;
  Node node;
  std::optional<std::size_t> removed;
  for (std::size_t i = 0; i < applied_.size(); ++i) {
    const bool held = holds(node, &has_key);
    node.apply(applied_[i]);
    bool after_key = false;
    holds(node, &after_key);
    if (held && !after_key) removed = i;  // command i removed the slot while it held `line`
  }
  return removed;
}

Node ProgramChecker::rebuild(std::size_t commands) const {
  Node node;
  for (std::size_t i = 0; i < commands && i < applied_.size(); ++i) node.apply(applied_[i]);
  return node;
}

StepResult ProgramChecker::full_step(const Command& c, std::vector<DerivedChange>* derived_changed) {
  Node after;
  StepResult r = check_step(model_, c, sut_, &after, follow_choices_);
  if (r.failure && sut_.last_apply_batched() && (!judge_again_ || judge_again_(*r.failure)))
    r = judge_alone(c, std::move(r), &after);
  if (derived_changed && !r.failure && r.not_judged.empty()) *derived_changed = derived_changes(model_, after);
  if (r.not_judged.empty()) {
    applied_.push_back(r.model_command ? *r.model_command : c);
    as_sent_.push_back(c);
    model_ = std::move(after);
  }
  return r;
}

bool ProgramChecker::send_told(const std::vector<Command>& sent, std::size_t n) {
  sut_.expect_commands(std::vector<Command>(sent.begin(), sent.begin() + static_cast<std::ptrdiff_t>(n)));
  bool ok = true;
  for (std::size_t i = 0; ok && i < n; ++i) ok = sut_.apply(sent[i]).status == CallStatus::Ok;
  sut_.expect_commands({});
  return ok;
}

StepResult ProgramChecker::judge_alone(const Command& c, StepResult batched, Node* after) {
  // The program so far from a fresh node (told to the implementation, so a
  // route may send it in batches again: those steps were judged right),
  // then `c` with nothing told: on its own, one round trip, as a route
  // without batches judges it.
  const bool replayed = sut_.reset().status == CallStatus::Ok && send_told(as_sent_, as_sent_.size());
  if (!replayed) return batched;  // the replay itself failed: the batch's judgement stands
  Node again;
  StepResult r = check_step(model_, c, sut_, &again, follow_choices_);
  *after = std::move(again);
  return r;
}

StepResult ProgramChecker::step(const Command& c, std::vector<DerivedChange>* derived_changed) {
  failed_at_ = -1;
  if (!digest_on_ && !sparse_) return full_step(c, derived_changed);
  StepResult result;
  const Answer answer = sut_.apply(c);
  const DocumentDigests digests_before = digest_.digests();
  result.expected = model_.apply(c, &result.rules, &changes_);
  applied_.push_back(c);
  if (sparse_) sent_.push_back(c);
  std::vector<DerivedChange> changed;
  digest_.update(model_, changes_, &changed);
  const bool answered = answer.status == CallStatus::Ok && !answer.not_sent && !answer.malformed;
  const bool cheap = answered && answer.verdict_reported && answer.applied == (result.expected == Reason::Ok);
  // Sparse reading: a `done` answer is judged by the next reading of the
  // documents (bisection finds its command if they differ there).
  if (sparse_ && answered && (cheap || !answer.verdict_reported)) {
    result.verdict_reported = answer.verdict_reported;
    if (derived_changed) *derived_changed = std::move(changed);
    return sparse_step(c, answer, std::move(result));
  }
  // A `done` answer: check_step reads the verdict from the state, and
  // judges the step right exactly when the state after it is the
  // reference's, which equal digests stand for.
  if (cheap || (answered && !answer.verdict_reported)) {
    const DigestAnswer d = sut_.digest();
    if (d.status != CallStatus::Ok) {
      result.failure =
          call_failure("STABLE-1", d.status, "reading the digest after `" + print_command(c) + "`", d.detail);
      return result;
    }
    if (d.digests == digest_.digests()) {  // the documents agree: nothing more to read
      result.verdict_reported = answer.verdict_reported;
      result.implementation_unchanged = !answer.verdict_reported && d.digests == digests_before;
      if (auto note = reason_note(c, result.expected, answer)) result.notes.push_back(std::move(*note));
      if (derived_changed) *derived_changed = std::move(changed);
      return result;
    }
  }
  // Judged exactly as check_step judges it, from the state before `c`.
  const Node before = rebuild(applied_.size() - 1);
  StepResult r = judge_step(before, c, answer, std::move(result), sut_, &model_, follow_choices_);
  if (!r.not_judged.empty()) {  // both sides stay at `before` (model_ is it again)
    applied_.pop_back();
    if (sparse_) sent_.pop_back();
  }
  if (r.model_command) applied_.back() = *r.model_command;
  if (!r.not_judged.empty() || r.model_command) digest_ = NodeDigest(model_);
  if (derived_changed && !r.failure && r.not_judged.empty()) *derived_changed = derived_changes(before, model_);
  if (sparse_) {
    // A difference at this command (its verdict, or the documents read now)
    // may be the consequence of an older one, made since the last reading:
    // the first prefix whose documents differ is found by bisection (which
    // ends on this command when none before it differs).
    if (r.failure && agreed_ + 1 < sent_.size()) {
      const std::size_t now = sent_.size();
      if (auto l = bisect(sent_, agreed_, now); l && l->index + 1 < static_cast<int>(now)) {
        failed_at_ = l->index;
        return std::move(l->step);
      }
    }
    if (!r.failure && r.not_judged.empty() && r.verdict_reported) agreed_ = sent_.size();
    return r;
  }
  // Documents that agree although the digests differ (a difference the
  // comparison tolerates, e.g. bone poses within rounding): the digests
  // would differ after every later command too, so the rest of the program
  // is checked step by step.
  if ((cheap || answer.verdict_reported == false) && answered && !r.failure) digest_on_ = false;
  return r;
}

StepResult ProgramChecker::sparse_step(const Command& c, const Answer& answer, StepResult result) {
  if (auto note = reason_note(c, result.expected, answer)) result.notes.push_back(std::move(*note));
  const std::size_t elements = model_.vertices().size() + model_.polygons().size();
  if (sent_.size() - agreed_ < std::max<std::size_t>(1, elements)) return result;  // not yet: the verdict only
  std::optional<Finding> call;
  std::string difference;
  if (documents_agree(model_, &call, &difference)) {
    agreed_ = sent_.size();
    return result;
  }
  if (call) {
    result.failure = call;
    return result;
  }
  const std::size_t now = sent_.size();
  if (auto l = bisect(sent_, agreed_, now)) {
    if (l->index + 1 < static_cast<int>(now)) failed_at_ = l->index;
    return std::move(l->step);
  }
  result.failure = Finding{"STABLE-1", FindingStatus::Fail,
                           "after `" + print_command(c) + "` the documents differ from the reference's (" + difference +
                               "), but sent again from a fresh node no command of the program makes them differ: "
                               "the implementation does not repeat itself"};
  return result;
}

bool ProgramChecker::documents_agree(const Node& model, std::optional<Finding>* call, std::string* difference) {
  const RouteLimits limits = sut_.limits();
  const Document snap = sut_.snapshot();
  if (snap.status != CallStatus::Ok) {
    *call = call_failure("STABLE-1", snap.status, "reading the snapshot", snap.detail);
    return false;
  }
  const std::string expected = without_keys(print_snapshot(model), masked_);
  const std::string observed = without_keys(snap.text, masked_);
  const auto d = limits.subscriptions
                     ? diff_documents(expected, observed)
                     : diff_documents(without_subscriptions(expected), without_subscriptions(observed));
  if (d) {
    *difference = "snapshot: " + d->describe();
    return false;
  }
  if (!limits.derived) return true;
  const Document derived = sut_.derived();
  if (derived.status != CallStatus::Ok) {
    *call = call_failure("STABLE-1", derived.status, "reading the derived document", derived.detail);
    return false;
  }
  if (auto dd = diff_documents(print_derived(model), derived.text)) {
    *difference = "derived: " + dd->describe();
    return false;
  }
  return true;
}

std::optional<Localized> ProgramChecker::bisect(const std::vector<Command>& sent, std::size_t agreed,
                                                std::size_t differs) {
  if (sent.size() != applied_.size() || differs > sent.size() || agreed >= differs) return std::nullopt;
  // Sends the first `n` commands to a fresh implementation; false when a call fails.
  const auto send_prefix = [&](std::size_t n) {
    if (sut_.reset().status != CallStatus::Ok) return false;
    return send_told(sent, n);
  };
  std::size_t lo = agreed, hi = differs;
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (!send_prefix(mid)) return std::nullopt;
    std::optional<Finding> call;
    std::string difference;
    const bool agree = documents_agree(rebuild(mid), &call, &difference);
    if (call) return std::nullopt;
    (agree ? lo : hi) = mid;
  }
  if (!send_prefix(hi - 1)) return std::nullopt;
  const Node before = rebuild(hi - 1);
  Node after;
  StepResult r = check_step(before, sent[hi - 1], sut_, &after, follow_choices_, &masked_);
  if (!r.failure) return std::nullopt;
  model_ = std::move(after);
  applied_.resize(hi);
  as_sent_.assign(sent.begin(), sent.begin() + static_cast<std::ptrdiff_t>(hi));
  if (sparse_) sent_.resize(hi);
  return Localized{std::move(r), static_cast<int>(hi - 1)};
}

std::optional<Localized> ProgramChecker::judge_at(const std::vector<Command>& sent, std::size_t index) {
  if (index >= sent.size() || sent.size() != applied_.size() || sut_.reset().status != CallStatus::Ok)
    return std::nullopt;
  if (!send_told(sent, index)) return std::nullopt;
  const Node before = rebuild(index);
  std::optional<Finding> call;
  std::string difference;
  if (!documents_agree(before, &call, &difference)) return std::nullopt;
  Node after;
  StepResult r = check_step(before, sent[index], sut_, &after, follow_choices_, &masked_);
  if (!r.failure) return std::nullopt;
  model_ = std::move(after);
  applied_.resize(index + 1);
  as_sent_.assign(sent.begin(), sent.begin() + static_cast<std::ptrdiff_t>(index + 1));
  if (sparse_) sent_.resize(index + 1);
  return Localized{std::move(r), static_cast<int>(index)};
}

void ProgramChecker::drop_last() {
  if (applied_.empty()) return;
  applied_.pop_back();
  if (!as_sent_.empty()) as_sent_.pop_back();
  if (sparse_ && !sent_.empty()) sent_.pop_back();
  agreed_ = std::min(agreed_, sent_.size());
  model_ = rebuild(applied_.size());
  digest_ = NodeDigest(model_);
}

std::optional<Localized> ProgramChecker::finish(const std::vector<Command>& sent) {
  if (!digest_on_ && !sparse_) return std::nullopt;
  if (sparse_ && agreed_ == sent_.size()) return std::nullopt;
  const int last = static_cast<int>(sent.size()) - 1;
  std::optional<Finding> call;
  std::string difference;
  if (documents_agree(model_, &call, &difference)) {
    agreed_ = sent_.size();
    return std::nullopt;
  }
  if (call) {
    StepResult r;
    r.failure = call;
    return Localized{std::move(r), last};
  }
  if (auto l = bisect(sent, sparse_ ? agreed_ : 0, sent.size())) return l;
  StepResult r;
  Finding f;
  f.clause = digest_on_ ? "ACCEPT-1" : "STABLE-1";
  f.message = "after the last command the documents differ from the reference's (" + difference + ")" +
              (digest_on_ ? " although every ?digest answer matched the reference's documents: the digest does "
                            "not stand for the documents the implementation prints (docs/adapters.md ?digest)"
                          : ", but sent again from a fresh node no command of the program makes them differ: the "
                            "implementation does not repeat itself");
  r.failure = f;
  return Localized{std::move(r), last};
}

}  // namespace vgc

namespace vgc {

std::optional<Localized> ProgramChecker::check_late_view(
    const std::vector<Command>& sent, const std::function<bool(const std::string&)>& localize,
    const std::function<bool(const std::string&, const Localized&)>& goes_on) {
  late_shape_.clear();
  if (sent.empty() || sent.size() != applied_.size() || !sut_.offers_late_view()) return std::nullopt;
  struct LateView {  // on for this call only, however it returns
    Implementation& sut;
    explicit LateView(Implementation& s) : sut(s) { sut.use_late_view(true); }
    ~LateView() { sut.use_late_view(false); }
  } on(sut_);
  const Document late = sut_.snapshot();
  if (late.status != CallStatus::Ok) return std::nullopt;
  // What a REAL32-then-REAL64 subscriber of layer 0 was sent during the
  // case (the late subscriber's watch): a REAL32 value means the host kept
  // both subscriptions, and a subscription's format is replaced by the next
  // one (layer.subscribe). No command of the case decides it; the case is
  // its program. Judged after the document (a difference there is reported
  // first, so that a replay shows what certify showed), and a shape of its
  // own ("subscription both-formats") that `localize` may spare.
  late_format_.reset();
  if (const std::string wrong = sut_.late_view_wrong_format(); !wrong.empty()) {
    Finding f;
    f.clause = std::string(rule_clause(Rule::Subscribe));
    f.rules = {Rule::Subscribe};
    f.late_view = true;
    f.message = std::string(kLateViewPrefix) +
                ": a session that subscribed to layer 0 at REAL32 and then at REAL64 before the case was sent `" +
                wrong + "` during it, a REAL32 value after its REAL64 subscription: the host kept both subscriptions "
                "(every value then comes twice). Blamed on rule layer.subscribe (" + f.clause +
                "): the layer's subscription becomes REAL32 or REAL64 (4.4).";
    late_format_ = f;
  }
  const auto format_finding = [&]() -> std::optional<Localized> {
    late_shape_.clear();
    if (!late_format_ || (localize && !localize("subscription both-formats"))) return std::nullopt;
    late_shape_ = "subscription both-formats";
    late_format_->difference = late_shape_;
    StepResult r;
    r.expected = Reason::Ok;
    r.failure = late_format_;
    return Localized{std::move(r), static_cast<int>(sent.size()) - 1};
  };
  const RouteLimits limits = sut_.limits();
  const std::string expected = print_snapshot(model_);
  // At most this many differences (one per line key) are told apart: each
  // one is searched for a removed slot (removed_slot_at), and one of a new
  // shape costs a localization.
  constexpr std::size_t kMaxDifferences = 32;
  const std::vector<DocumentDifference> diffs =
      limits.subscriptions
          ? all_differences(expected, late.text, kMaxDifferences)
          : all_differences(without_subscriptions(expected), without_subscriptions(late.text), kMaxDifferences);
  // The checker as it is now: localizing a difference moves it to the
  // prefix that showed it; a difference gone on from puts it back.
  const Node model = model_;
  const std::vector<Command> applied = applied_, as_sent = as_sent_, sparse_sent = sent_;
  const auto keys_of = [](const DocumentDifference& d) {
    std::set<std::string> keys;
    for (const std::string* line : {&d.expected_line, &d.observed_line})
      if (!line->empty()) keys.insert(line_key(*line));
    return keys;
  };
  for (std::size_t k = 0; k < diffs.size(); ++k) {
    const DocumentDifference& d = diffs[k];
    // A slot at the layer's default, shown at the default the host told
    // the newcomer: that layer line's difference (left out while it is
    // localized), not one of its own.
    if (slot_at_told_default(model, d, late.text)) continue;
    // A slot the model removed with its element, shown again as it was (a
    // deleted element's value back on an element created at its id), is
    // another kind of difference than a value the model never held there,
    // whichever rule wrote the model's line: a finding of its own.
    const std::optional<std::size_t> stale = removed_slot_at(d.observed_line);
    std::string shape = difference_shape(model, d);
    if (stale) shape += " (" + std::string(kRemovedSlotKept) + ")";
    if (localize && !localize(shape)) continue;
    // This difference alone: the lines of every other one left out.
    masked_.clear();
    for (std::size_t o = 0; o < diffs.size(); ++o)
      if (o != k) masked_.merge(keys_of(diffs[o]));
    for (const std::string& key : keys_of(d)) masked_.erase(key);
    std::optional<Localized> l = localize_late(sent, d, stale);
    masked_.clear();
    if (!l) continue;
    late_shape_ = shape;
    if (!goes_on || !goes_on(shape, *l)) return l;
    model_ = model;
    applied_ = applied;
    as_sent_ = as_sent;
    sent_ = sparse_sent;
  }
  return format_finding();
}

std::optional<Localized> ProgramChecker::localize_late(const std::vector<Command>& sent, const DocumentDifference& d,
                                                       std::optional<std::size_t> stale) {
  // Provenance first: the command that last wrote the model's line is
  // where a host that stored something else most likely began to differ.
  // Checked (the view agrees before it and differs after it); otherwise,
  // and for a line the model does not have, bisection.
  const Node model = model_;
  const std::string removed_by = stale && *stale < applied_.size() ? print_command(applied_[*stale]) : "";
  std::optional<Localized> l;
  if (!d.expected_line.empty())
    if (const auto w = line_written(model, d.expected_line); w && w->step >= 1 && w->step <= sent.size())
      l = judge_at(sent, w->step - 1);
  if (!l) l = bisect(sent, 0, sent.size());
  if (!l || !l->step.failure) return std::nullopt;
  Finding& f = *l->step.failure;
  f.late_view = true;
  f.message = std::string(kLateViewPrefix) +
              ": a session that subscribed to the node and every layer (REAL32 and REAL64) after this command was "
              "sent another node than the session that watched it all along, which agreed with the model; " +
              f.message;
  // A slot shown at the default where the model's value equals it only as
  // a number is the subscription's, whichever write made it.
  if (const auto b = blame_subscription_dump(rebuild(static_cast<std::size_t>(l->index) + 1),
                                             DocumentDifference{f.expected_line, f.observed_line, "slot"})) {
    // Said as what differs: the state both watchers hold did change (the
    // late view compares a slot the host left out as the default).
    const std::string sent_to_watchers =
        f.host_sent.empty() ? std::string() : " (every session watching the layer was sent `" + f.host_sent.front() + "`)";
    f.message = std::string(kLateViewPrefix) + ": after `" + print_command(sent[static_cast<std::size_t>(l->index)]) +
                "`" + sent_to_watchers + ", a session that subscribed to the node and every layer then was sent no "
                "value for that slot. " + b->explanation;
    f.clause = b->clause;
    f.rules = b->rules;
    f.difference = kDefaultByValue;
  }
  if (stale) {
    f.message += " The slot shown, `" + d.observed_line + "`, is one the model held until command " +
                 std::to_string(*stale + 1) + " of the case (`" + removed_by +
                 "`) removed it: the implementation kept it, and gave it to the element made at its id.";
    f.difference = kRemovedSlotKept;
  }
  return l;
}

}  // namespace vgc
