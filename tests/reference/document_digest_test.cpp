// document_digest_test.cpp — reference/geometry/document_digest: the digest
// NodeDigest keeps up to date from each command's ChangeLog is, after every
// command of any sequence, the digest of the documents the node prints, and
// the derived lines it reports changed are exactly those that changed.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <map>
#include <set>

#include "arbitrary_command.h"
#include "derived_document.h"
#include "document_digest.h"
#include "snapshot.h"

namespace vgc {
namespace {

// The identity of a derived line: its kind and ids, the value left out.
std::string derived_identity(const std::string& line) {
  const auto last = line.rfind(' ');
  if (line.rfind("bone_pose ", 0) == 0) return line.substr(0, line.find(' ', 10));
  if (line.rfind("edge_crease ", 0) == 0) return line.substr(0, line.find(' ', 12));  // the polygon
  return line.substr(0, last);
}

std::map<std::string, std::string> derived_lines(const std::string& text) {
  std::map<std::string, std::string> out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t j = text.find('\n', i);
    const std::string line = text.substr(i, j - i);
    i = j + 1;
    if (line == "vgc-derived 1" || line == "end") continue;
    out[derived_identity(line)] += line + "\n";
  }
  return out;
}

RC_GTEST_PROP(DocumentDigest, FollowsTheNodeCommandByCommand, ()) {
  const std::size_t limit = *rc::gen::element<std::size_t>(8, 40, std::size_t{1} << 22);
  Node node(NodeLimits{limit});
  NodeDigest digest(node);
  ChangeLog changes;
  const int steps = *rc::gen::inRange(1, 80);
  for (int i = 0; i < steps; ++i) {
    const Command c = *gen::gen_command_for(node);
    const auto before = derived_lines(print_derived(node));
    node.apply(c, nullptr, &changes);
    std::vector<DerivedChange> changed;
    digest.update(node, changes, &changed);
    const std::string snapshot = print_snapshot(node), derived = print_derived(node);
    RC_ASSERT(digest.digests() == digests_of(snapshot, derived));
    // Every derived line that changed is reported, and nothing else.
    const auto after = derived_lines(derived);
    std::set<std::string> expected, reported;
    for (const auto& [k, v] : after)
      if (!before.count(k) || before.at(k) != v) expected.insert(k);
    for (const auto& [k, v] : before)
      if (!after.count(k)) expected.insert(k);
    for (const auto& ch : changed) reported.insert(derived_identity(ch.line.back() == '\n' ? ch.line : ch.line + " x"));
    RC_ASSERT(reported == expected);
  }
  RC_ASSERT(NodeDigest(node).digests() == digest.digests());
}

TEST(DocumentDigest, AFreshNodesDigestIsItsDocumentsDigest) {
  const Node node;
  EXPECT_EQ(NodeDigest().digests(), digests_of(print_snapshot(node), print_derived(node)));
}

TEST(DocumentDigest, TheAnswerLineRoundTripsAndRejectsOtherLines) {
  const DocumentDigests d{0x0123456789abcdefull, 0xfedcba9876543210ull};
  EXPECT_EQ(format_digest_line(d), "digest 0123456789abcdef fedcba9876543210\n");
  DocumentDigests back;
  ASSERT_TRUE(parse_digest_line(format_digest_line(d), &back));
  EXPECT_EQ(back, d);
  for (const char* bad : {"digest 0123456789abcdef", "digest 0123456789ABCDEF fedcba9876543210",
                          "digest 0123456789abcdef  edcba9876543210", "error unknown request ?digest", ""})
    EXPECT_FALSE(parse_digest_line(bad, &back)) << bad;
}

TEST(DocumentDigest, OneChangedLineChangesTheDigest) {
  EXPECT_NE(document_digest("vgc-snapshot 1\nvertex 0 0 0 0\nend\n"),
            document_digest("vgc-snapshot 1\nvertex 0 0 0 1\nend\n"));
  // Order does not matter (the documents are printed in one order anyway).
  EXPECT_EQ(document_digest("a\nb\n"), document_digest("b\na\n"));
}

}  // namespace
}  // namespace vgc
