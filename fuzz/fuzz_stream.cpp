// fuzz_stream.cpp — binary command streams into the reference node, every
// node invariant checked after every command.
//
// Spec: 000 section 2.6 and README, through node_invariants.h; the binary
// stream format of reference/command_binary.h.
//
// Per input: decode commands one at a time (stop at the first malformed
// one); check that re-encoding each gives back its bytes; apply it; check
// check_node() and, for a rejected command, that the state did not change
// (state_digest, the fingerprint of all print_snapshot prints; the text
// itself is compared at the end, see node_invariants.h for why). At the
// end: print_snapshot twice gives the same text, and
// print_derived runs (it reads crease layers by the node's ids, so a broken
// invariant there throws, which is a crash). Findings abort with the
// command file so far (finding.h).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "command_binary.h"
#include "finding.h"
#include "node.h"
#include "node_invariants.h"
#include "snapshot.h"
#include "stream_mutator_hooks.h"

namespace {
constexpr const char* kTarget = "fuzz_stream";
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vgc;
  Node node;
  std::vector<Command> done;
  std::uint64_t before = fuzz::state_digest(node);
  std::size_t pos = 0;
  for (;;) {
    const std::size_t start = pos;
    Command c;
    if (decode_command(data, size, &pos, &c) != DecodeStatus::Ok) break;
    done.push_back(c);
    std::string encoded;
    if (!encode_command(c, &encoded) ||
        encoded != std::string(reinterpret_cast<const char*>(data + start), pos - start))
      fuzz::report_finding(kTarget, "re-encoding a decoded command changed its bytes", done);
    const Reason r = node.apply(c);
    if (std::string e = fuzz::check_node(node); !e.empty())
      fuzz::report_finding(kTarget, std::string("invariant broken after a command answered ") +
                                        std::string(reason_name(r)) + ": " + e, done);
    const std::uint64_t after = fuzz::state_digest(node);
    if (std::string e = fuzz::check_step(r == Reason::Ok, before, after); !e.empty())
      fuzz::report_finding(kTarget, e + " (" + std::string(reason_name(r)) + ")", done);
    before = after;
  }
  const std::string snapshot = print_snapshot(node);
  if (std::string e = fuzz::check_deterministic(snapshot, print_snapshot(node)); !e.empty())
    fuzz::report_finding(kTarget, e, done);
  const std::string derived = print_derived(node);
  if (derived.size() < 4 || derived.compare(derived.size() - 4, 4, "end\n") != 0)
    fuzz::report_finding(kTarget, "print_derived does not end in \"end\"", done);
  return 0;
}
