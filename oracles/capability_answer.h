// capability_answer.h — what the five capability checks share: reading
// an implementation's answer document (oracles/capability_checks.h) and
// comparing a refined level with an oracle's.
//
// Spec: the documents of docs/adapters.md "Optional capabilities"
// (vgc-classify, vgc-subdivision, vgc-normals); the checks themselves are
// check_classify.cpp (MESH-CLASSIFY-1), check_subdivision.cpp
// (SUBD-CATMARK-1), check_normals.cpp (NORMALS-SPLIT-1), check_loop.cpp
// (LOOP-TRIANGLE-1) and check_edits.cpp (EDIT-HIERARCHY-1).
//
// Rationale: one reader per document kind, so that every check reads an
// answer the same way and a malformed answer is the same finding whichever
// capability asked for it. Internal to oracles/ (no other layer includes
// it); like capability_checks.h it names no CGAL or OpenSubdiv header, only
// the plain-typed oracle headers.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "capability.h"
#include "mesh_arrays.h"
#include "osd_subdivision.h"

namespace vgc::capability_answer {

// A finding of `clause` with `status`.
Finding finding(const char* clause, std::string message, FindingStatus st = FindingStatus::Fail);

// A failed call, an "error" answer or a document not of `header`: the finding, else nullopt.
std::optional<Finding> check_answer(const char* clause, const std::string& request, const Document& d,
                                    const char* header);

// "key value" lines of a document (first word -> rest), header and end
// left out: views into `text` (a level-2 answer holds 10^6 lines; a string
// pair per line was most of reading it).
using DocumentLine = std::pair<std::string_view, std::string_view>;
std::vector<DocumentLine> document_lines(std::string_view text);

// The words of `s` (split on spaces).
std::vector<std::string_view> words_of(std::string_view s);

// "(x, y, z)" with the reference's shortest round-trip numbers.
std::string point_text(const std::array<double, 3>& p);

// A ?subdivide-like document: "level", "vertex x y z" lines, optional
// "face i j k ..." lines (indices into the vertex lines), "faces <count>".
struct SubdivisionAnswer {
  long level = -1, faces = -1;
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::vector<int>> face_lines;
};

// Reads `text`; the problem as a message, or nullopt.
std::optional<std::string> read_subdivision(const std::string& text, SubdivisionAnswer* out);

// Pairs every `want` vertex with the nearest unused `got` vertex within
// `tol` (max norm); got_to_want[g] is the partner of got[g] or -1. The
// first want vertex left without a partner, or nullopt when all have one;
// with `all_unmatched`, goes on and lists every want vertex left without.
std::optional<std::size_t> match_vertices(const std::vector<std::array<double, 3>>& got,
                                          const std::vector<std::array<double, 3>>& want, double tol,
                                          std::vector<int>* got_to_want,
                                          std::vector<std::size_t>* all_unmatched = nullptr);

// Whether a and b are within `tol` in every coordinate.
bool near(const std::array<double, 3>& a, const std::array<double, 3>& b, double tol);

// 1e-9 times the largest coordinate magnitude of `positions` (at least 1).
double tolerance_of(const std::vector<std::array<double, 3>>& positions);

// Compares an answer's vertices and face count with a refined level: the
// counts, then the vertices as a bijection. The message, or nullopt.
std::optional<std::string> compare_with_level(const SubdivisionAnswer& got, const std::vector<std::array<double, 3>>& want,
                                              long want_faces, const std::string& oracle, std::vector<int>* got_to_want);

// OpenSubdiv's uniform refinement of `mesh` to `level` with `scheme`, on
// every mesh a node can hold, non-manifold included. nullopt, with *why,
// where OpenSubdiv cannot be asked.
std::optional<OsdResult> oracle_refinement(const MeshArrays& mesh, OsdScheme scheme, int level, std::string* why);

// A case the oracle cannot judge (FindingStatus::NotJudged).
Finding not_judged(const char* clause, const std::string& message);

}  // namespace vgc::capability_answer
