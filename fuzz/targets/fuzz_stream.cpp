// fuzz_stream.cpp — binary command streams into the reference node, every
// node invariant checked after every command.
//
// Spec: 000 section 2.6 and README, through node_invariants.h; the binary
// stream format of reference/node/command_binary.h.
//
// Per input: decode commands one at a time (stop at the first malformed
// one); check that re-encoding each gives back its bytes; apply it. Cheap
// checks after each command, exact ones once per input:
//   after each command: check_touched (node_invariants.h): the invariants
//     a command can break, where it touched (its elements, layers, bones,
//     and every layer's header and slot count); for a rejected command,
//     touched_digest before and after (what it names must not change);
//   at the end: the whole check_node; the commands that were applied,
//     replayed alone on a fresh node, are applied again and end in the same
//     state_digest (so no rejected command changed anything, anywhere);
//     print_snapshot twice gives the same text; print_derived runs (it reads
//     crease layers by the node's ids, so a broken invariant there throws,
//     which is a crash).
// Only when a check fails is the input re-run with the full check_node and
// state_digest after every command, to name the first command that broke
// it. Findings abort with the command file up to that command (report_finding.h).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "command_binary.h"
#include "derived_document.h"
#include "report_finding.h"
#include "node.h"
#include "node_invariants.h"
#include "snapshot.h"
#include "stream_mutator_hooks.h"

namespace {
constexpr const char* kTarget = "fuzz_stream";
}

namespace {

using namespace vgc;

// The exact path: every invariant and the whole state's digest after every
// command; reports the first command that breaks one. Returns when none
// does (a failure the fast path saw that this does not, e.g. one only the
// end-of-input checks see, is reported by the caller).
void localize(const std::vector<Command>& commands) {
  Node node;
  std::vector<Command> done;
  std::uint64_t before = fuzz::state_digest(node);
  for (const Command& c : commands) {
    done.push_back(c);
    const Reason r = node.apply(c);
    if (std::string e = fuzz::check_node(node); !e.empty())
      fuzz::report_finding(kTarget, std::string("invariant broken after a command answered ") +
                                        std::string(reason_name(r)) + ": " + e, done);
    const std::uint64_t after = fuzz::state_digest(node);
    if (std::string e = fuzz::check_step(r == Reason::Ok, before, after); !e.empty())
      fuzz::report_finding(kTarget, e + " (" + std::string(reason_name(r)) + ")", done);
    before = after;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Node node;
  std::vector<Command> done;
  std::vector<bool> applied;
  bool suspect = false;  // a cheap check failed: localize
  std::size_t pos = 0;
  std::string encoded;  // one buffer for the whole input
  for (;;) {
    const std::size_t start = pos;
    Command c;
    if (decode_command(data, size, &pos, &c) != DecodeStatus::Ok) break;
    done.push_back(c);
    encoded.clear();
    if (!encode_command(c, &encoded) ||
        std::string_view(encoded) != std::string_view(reinterpret_cast<const char*>(data + start), pos - start))
      fuzz::report_finding(kTarget, "re-encoding a decoded command changed its bytes", done);
    const fuzz::Touched t = fuzz::touched_by(c);
    const std::uint64_t before = fuzz::touched_digest(node, t);
    const Reason r = node.apply(c);
    applied.push_back(r == Reason::Ok);
    if (!fuzz::check_touched(node, t).empty()) suspect = true;
    if (r != Reason::Ok && fuzz::touched_digest(node, t) != before) suspect = true;
    if (suspect) break;
  }
  if (!suspect && !fuzz::check_node(node).empty()) suspect = true;
  if (!suspect) {
    // Rejected commands change nothing: the applied ones alone, from a
    // fresh node, are all applied again and end in the same state.
    Node again;
    for (std::size_t i = 0; i < done.size() && !suspect; ++i)
      if (applied[i] && again.apply(done[i]) != Reason::Ok) suspect = true;
    if (!suspect && fuzz::state_digest(again) != fuzz::state_digest(node)) suspect = true;
  }
  if (suspect) {
    localize(done);
    fuzz::report_finding(kTarget,
                         "the end-of-input check failed (the applied commands alone, from a fresh node, do not "
                         "give the same answers and state) but no single command broke an invariant",
                         done);
  }
  const std::string snapshot = print_snapshot(node);
  if (std::string e = fuzz::check_deterministic(snapshot, print_snapshot(node)); !e.empty())
    fuzz::report_finding(kTarget, e, done);
  const std::string derived = print_derived(node);
  if (derived.size() < 4 || derived.compare(derived.size() - 4, 4, "end\n") != 0)
    fuzz::report_finding(kTarget, "print_derived does not end in \"end\"", done);
  return 0;
}
