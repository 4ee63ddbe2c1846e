// document_digest.h — a digest of a node's two documents (the snapshot and
// the derived document) that follows the node command by command at the
// cost of what each command changed, not of the node's size.
//
// Spec: the documents of docs/commands.md 6.1 (snapshot.h) and 6.2
// (derived_document.h); the optional `?digest` request of docs/adapters.md.
//
// Rationale (issue 21): comparing both whole documents after every command
// makes checking a program of n commands cost n^2. The digest of a document
// is the sum, modulo 2^64, of the 64-bit FNV-1a hash of each of its lines
// (without the newline; the header and "end" included). A sum does not
// depend on the order of the lines, so a command that rewrites k lines
// changes the digest by what those k lines change, and NodeDigest keeps it
// up to date from the node's ChangeLog (node.h). Equal digests stand for
// equal documents (a 64-bit collision aside); different digests say only
// "look": the checker then compares the whole documents as before
// (check_step.h), which also decides the differences the comparison
// tolerates (an unused default, bone poses within rounding).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "node.h"

namespace vgc {

std::uint64_t line_hash(std::string_view line);        // FNV-1a 64 of the line, without its "\n"
std::uint64_t document_digest(std::string_view text);  // the sum of line_hash over every line

struct DocumentDigests {
  std::uint64_t snapshot = 0;
  std::uint64_t derived = 0;
  bool operator==(const DocumentDigests& o) const { return snapshot == o.snapshot && derived == o.derived; }
  bool operator!=(const DocumentDigests& o) const { return !(*this == o); }
};

// Of the two documents' texts (for an implementation that prints them).
DocumentDigests digests_of(std::string_view snapshot, std::string_view derived);
// The answer line to `?digest`: "digest <snapshot> <derived>\n", each 16
// lower-case hex digits.
std::string format_digest_line(const DocumentDigests& d);
// Reads such a line (with or without its "\n"); false for anything else.
bool parse_digest_line(std::string_view line, DocumentDigests* out);

// A derived line a command added, removed or rewrote: its kind
// ("vertex_crease", "edge_crease", "bone_pose") and the line (for a removed
// one, its kind and ids only), for exercised_clauses.
struct DerivedChange {
  std::string kind;
  std::string line;
};

class NodeDigest {
 public:
  NodeDigest();  // a fresh node's
  explicit NodeDigest(const Node& node);
  // `node` is the node after a command that recorded `changes` (Node::apply).
  // When `derived_changed` is not null it receives every derived line whose
  // text changed.
  void update(const Node& node, const ChangeLog& changes, std::vector<DerivedChange>* derived_changed = nullptr);
  DocumentDigests digests() const;

 private:
  using Lines = std::map<std::uint64_t, std::uint64_t>;  // identity -> hash of its text
  struct Sum {
    Lines lines;
    std::uint64_t sum = 0;
    // Sets the entry to `text` (none when empty); true when its hash changed.
    bool set(std::uint64_t key, const std::string& text);
    void erase_range(std::uint64_t from, std::uint64_t to);
  };
  void set_layer(const Node& node, std::uint16_t id, bool with_slots);
  void set_slot(const Node& node, std::uint16_t layer_id, std::uint32_t element);
  void derived_element(const Node& node, bool vertex, std::uint32_t id, std::vector<DerivedChange>* changed);
  void derived_all_creases(const Node& node, std::vector<DerivedChange>* changed);
  void derived_bones(const Node& node, std::vector<DerivedChange>* changed);
  Sum snapshot_, derived_;
};

}  // namespace vgc
