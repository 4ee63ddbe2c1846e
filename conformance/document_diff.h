// document_diff.h — comparing an implementation's snapshot and derived
// documents with the reference's.
//
// Spec: the documents of reference/node/snapshot.h and
// reference/geometry/derived_document.h (docs/commands.md "Snapshot").
//
// Rationale: stored state must match byte for byte (the snapshot is
// canonical), but bone world poses are computed in floating point, where two
// correct implementations may differ in the last bits; those are compared
// within a tolerance, and a rotation q equals -q. A layer's default that its
// type never gives a slot is no state the spec gives meaning to, so it is
// not compared (an implementation need not keep it). A difference is reported as
// the first line that differs, in the reference's order, with both sides, so
// a person can see it without a diff tool.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace vgc {

struct DocumentDifference {
  std::string expected_line;  // empty when the implementation has an extra line
  std::string observed_line;  // empty when the implementation lacks a line
  std::string kind;           // first word of the differing line: "layer", "slot", "bone_pose", ...
  std::string describe() const;
};

// Relative tolerance for bone poses (BONE-DOWNSTREAM-1).
inline constexpr double kPoseTolerance = 1e-9;

// nullopt when the documents agree (exactly, except bone_pose numbers
// within kPoseTolerance, and a snapshot layer line's defaults: only the
// default its type uses is compared, snapshot.h used_defaults; LAYER-DEFAULT-1).
// Precondition: none; malformed text just differs.
std::optional<DocumentDifference> diff_documents(const std::string& expected, const std::string& observed);

// `snapshot` with the subscription column of every layer line (its last
// word) printed as "-": for a route that cannot observe subscriptions
// (RouteLimits::subscriptions), both sides are compared so.
std::string without_subscriptions(const std::string& snapshot);

// The identity of a snapshot or derived line: its kind and the ids after
// it ("slot 3 17", "edge_crease 4 2", "vertex 5", "crease_vertex").
std::string line_key(const std::string& line);

// `document` without its lines whose line_key is one of `keys`: for a
// comparison that leaves out lines whose difference is already accounted
// for (program_checker.h check_late_view), both sides are compared so.
std::string without_keys(const std::string& document, const std::set<std::string>& keys);

// Every difference of the two documents, in the reference's order, one per
// line key (diff_documents' first, then the first among the lines of the
// keys not yet reported, and so on), at most `max`.
std::vector<DocumentDifference> all_differences(const std::string& expected, const std::string& observed,
                                                std::size_t max);

// Splits on '\n' (a trailing "\r" is dropped from each line).
std::vector<std::string> split_lines(const std::string& text);
// The whitespace-separated words of one line.
std::vector<std::string> split_words(const std::string& line);

}  // namespace vgc
