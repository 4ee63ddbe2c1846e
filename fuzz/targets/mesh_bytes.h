// mesh_bytes.h — the byte form of a small polygon mesh, the input of the
// mesh fuzz targets (fuzz_mesh_manifold, fuzz_mesh_subdivision).
//
// Spec: 000 section 2.6 (polygons name vertices; vertex and edge creases,
// 2.6.2), 002 (the manifold rules the topology targets check). The byte
// form itself is this suite's (docs/fuzzing.md "Mesh targets").
//
// Rationale: the derived-geometry checks take a MeshArrays, which the node
// cannot always produce (polygons of 5 or 6 corners, out-of-range or
// repeated indices, faces sharing an edge three times). A compact,
// total decoding from bytes lets libFuzzer reach all of these: every byte
// string is some mesh, a mutated byte changes one position, one corner or
// one crease. Positions come from a 4-value lattice so that coincident and
// symmetric vertices are common; creases from a 4-value table (smooth,
// fractional, semi-sharp, infinite).
//
// The format (every byte string decodes; missing bytes read as absent):
//   byte 0            V = byte % 17 vertices (0..16)
//   V vertex bytes    bits 0-1, 2-3, 4-5: x, y, z from kMeshLattice;
//                     bits 6-7: the vertex crease from kMeshCreases.
//                     (Fewer than V bytes left: V shrinks to what is there.)
//   then faces, at most kMeshMaxFaces, while bytes remain:
//     size byte s     corners n = 3 + (s & 3) (3..6); if (s & 0xF0) == 0xF0,
//                     n = s & 3 instead (0..3: degenerate faces).
//     n corner bytes  c < 0xFC: vertex c % max(V, 1) (so repeats are common;
//                     with V = 0 the index 0 is out of range); 0xFC: V,
//                     0xFD: V + 1 (out of range), 0xFE: -1, 0xFF: -2.
//     crease byte k   bit i (i < 6) set: the edge starting at corner i
//                     stores the crease kMeshCreases[k >> 6]; else 0.
//   A face whose corner or crease bytes are cut off by the end of the input
//   is dropped. Bytes after kMeshMaxFaces faces are ignored.
// The mesh's vertex_ids and polygon_ids are 0..V-1 and 0..F-1.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh_arrays.h"

namespace vgc::fuzz {

inline constexpr std::array<double, 4> kMeshLattice = {-1.0, 1.0, 0.0, 0.5};
// 0: smooth; sharpness ~0.5 (fractional blend); ~2.5 (semi-sharp, lasts
// levels 1-2); 0xFFFFFFFF: infinitely sharp (crease_sharpness.h).
inline constexpr std::array<std::uint32_t, 4> kMeshCreases = {0u, 0x0CCCCCCCu, 0x40000000u, 0xFFFFFFFFu};
inline constexpr int kMeshMaxVertices = 16;
inline constexpr int kMeshMaxFaces = 24;

// Decodes `data` as above. Total: every input gives a mesh (possibly with
// invalid faces, which check_mesh reports). Never throws except bad_alloc.
MeshArrays decode_mesh_bytes(const std::uint8_t* data, std::size_t size);

// The bytes that decode to `mesh`, if it is representable: at most
// kMeshMaxVertices vertices and kMeshMaxFaces faces, positions on the
// lattice, creases from the table, face sizes 0..6, each face's corner
// creases all equal or 0, indices in -2..V+1. Returns false otherwise
// (then *out is unspecified). For seeds and tests.
bool encode_mesh_bytes(const MeshArrays& mesh, std::vector<std::uint8_t>* out);

// The mesh as text, one line per vertex ("v INDEX X Y Z crease 0xC") and
// per face ("f INDEX: CORNERS... | creases C..."): what a finding prints.
std::string print_mesh(const MeshArrays& mesh);

// Prints "vgc-fuzz: FINDING in <target>: <what>", then the mesh between
// "----8<---- mesh.txt" markers (print_mesh), and aborts, so libFuzzer
// records the input as a crash.
[[noreturn]] void report_mesh_finding(const char* target, const std::string& what, const MeshArrays& mesh);

}  // namespace vgc::fuzz
