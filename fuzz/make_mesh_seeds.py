#!/usr/bin/env python3
# make_mesh_seeds.py — writes the hand-made seeds of the mesh fuzz targets
# (corpora/fuzz/fuzz_mesh_manifold/ and fuzz_mesh_subdivision/) in the byte
# form of fuzz/targets/mesh_bytes.h. Run from the repository root:
#   python3 fuzz/make_mesh_seeds.py
# tests/fuzz (mesh_bytes_test.cpp) checks that seed-cube.bin decodes to the
# spec's cube as the reference node extracts it (corpora/examples/cube.vgc).
import os

LATTICE = {-1.0: 0, 1.0: 1, 0.0: 2, 0.5: 3}
CREASES = {0: 0, "frac": 1, "semi": 2, "inf": 3}  # kMeshCreases indices


def vertex(x, y, z, crease=0):
    return LATTICE[x] | LATTICE[y] << 2 | LATTICE[z] << 4 | CREASES[crease] << 6


def mesh(vertices, faces):
    """vertices: [(x, y, z[, crease])]; faces: [(corners, crease, mask)],
    corners as ints (-1, -2 and V, V+1 encode as the special bytes)."""
    out = [len(vertices)]
    out += [vertex(*v) for v in vertices]
    n = len(vertices)
    for corners, crease, mask in faces:
        k = len(corners)
        out.append(k - 3 if k >= 3 else 0xF0 | k)
        for c in corners:
            out.append({n: 0xFC, n + 1: 0xFD, -1: 0xFE, -2: 0xFF}.get(c, c))
        out.append((mask & 0x3F) | CREASES[crease] << 6)
    return bytes(out)


def faces(polys, crease=0, mask=0):
    return [(p, crease, mask) for p in polys]


# The spec's cube (000 2.6.4, corpora/examples/cube.vgc): vertices in id
# order, polygons top, bottom, front, right, back, left; every vertex and
# edge crease 0xFFFFFFFF (the defaults it sets).
CUBE_V = [(-1, 1, -1), (1, 1, -1), (1, 1, 1), (-1, 1, 1), (-1, -1, 1), (1, -1, 1), (1, -1, -1), (-1, -1, -1)]
CUBE_F = [[0, 1, 2, 3], [4, 5, 6, 7], [3, 2, 5, 4], [2, 1, 6, 5], [1, 0, 7, 6], [0, 3, 4, 7]]
TET_V = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
TET_F = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]
OCT_V = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
OCT_F = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]

seeds = {
    "cube": mesh([v + ("inf",) for v in CUBE_V], faces(CUBE_F, "inf", 0x3F)),
    "cube-smooth": mesh(CUBE_V, faces(CUBE_F)),
    "cube-mixed-creases": mesh([CUBE_V[0] + ("frac",), CUBE_V[1] + ("semi",)] + CUBE_V[2:],
                               [(CUBE_F[0], "semi", 0x3), (CUBE_F[1], "frac", 0x5)] + faces(CUBE_F[2:])),
    "tetrahedron": mesh(TET_V, faces(TET_F)),
    "tetrahedron-creases": mesh([TET_V[0] + ("semi",)] + TET_V[1:], [(TET_F[0], "frac", 0x7)] + faces(TET_F[1:])),
    "octahedron": mesh(OCT_V, [(OCT_F[0], "semi", 0x1)] + faces(OCT_F[1:])),
    # 2 x 2 quads, open: boundary edges, a corner of valence 1.
    "grid": mesh([(x, y, 0) for y in (-1, 0, 1) for x in (-1, 0, 1)],
                 faces([[0, 3, 4, 1], [1, 4, 5, 2], [3, 6, 7, 4], [4, 7, 8, 5]])),
    # A pentagon and a hexagon sharing an edge.
    "ngons": mesh([(-1, -1, 0), (0, -1, 0), (1, -1, 0), (1, 1, 0), (0, 1, 0), (-1, 1, 0), (-1, 0, 0), (0.5, 0, 1)],
                  [([0, 6, 5, 4, 1], 0, 0), ([1, 4, 3, 2, 7, 0], "semi", 0x1)]),
    # Non-manifold: a fin on the cube's edge 0-1 (three faces on it).
    "fin": mesh(CUBE_V + [(0, 0, 0)], faces(CUBE_F + [[0, 1, 8]])),
    # Bow-tie: two tetrahedra sharing vertex 0 only.
    "bowtie": mesh(TET_V + [(0.5, 0.5, 0.5), (0.5, 0, 0), (0, 0.5, 0)],
                   faces(TET_F + [[0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]])),
    # The octahedron with one face flipped: orientable, not consistently oriented.
    "octahedron-flipped": mesh(OCT_V, faces(OCT_F[:3] + [[0, 3, 4]] + OCT_F[4:])),
    # A Moebius strip of 4 quads.
    "moebius": mesh([(x, y, 0) for x in (-1, 0, 1, 0.5) for y in (-1, 1)],
                    faces([[0, 2, 3, 1], [2, 4, 5, 3], [4, 6, 7, 5], [6, 1, 0, 7]])),
    # Invalid input: out of range, negative, repeated, a 2-gon.
    "out-of-range": mesh(TET_V, faces(TET_F[:3] + [[1, 3, 4]])),
    "negative": mesh(TET_V, faces([[0, 1, -1]] + TET_F[1:])),
    "repeated": mesh(TET_V, faces(TET_F[:2] + [[0, 2, 2, 3]])),
    "two-gon": mesh(TET_V, faces(TET_F + [[0, 1]])),
    # An isolated vertex next to a closed mesh.
    "isolated": mesh(TET_V + [(0, 0, 0)], faces(TET_F)),
    # Non-manifold shapes a geometry node can hold (triangles and quads),
    # compared under OpenSubdiv's non-manifold rules (issue 11):
    # a closed "pillow": two triangles on the same three vertices (Loop's
    # centre children share vertices; level 2 has 18 vertices, not 15).
    "pillow": mesh([(-1, -1, 0), (1, -1, 0), (0, 1, 0.5)], faces([[0, 1, 2], [0, 2, 1]])),
    "pillow-quads": mesh([(-1, -1, 0), (1, -1, 0), (1, 1, 0.5), (-1, 1, 0)], faces([[0, 1, 2, 3], [0, 3, 2, 1]])),
    # two triangles using their shared edge 0->1 the same way.
    "same-direction": mesh([(-1, -1, 0), (1, -1, 0), (0, 1, 0), (0, 0, 1)], faces([[0, 1, 2], [0, 1, 3]])),
    # three triangles on edge 0-1 (a fin), open.
    "fin-triangles": mesh([(-1, 0, 0), (1, 0, 0), (0, 1, 0), (0, -1, 0.5), (0, 0, 1)],
                          [([0, 1, 2], "semi", 0x1), ([1, 0, 3], 0, 0), ([0, 1, 4], 0, 0)]),
    # a fin along two edges: vertex 1 on an interior non-manifold crease.
    "fin-spine": mesh([(-1, 0, 0), (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, -1, 0.5), (0, 0.5, 1)],
                      faces([[0, 1, 3], [1, 2, 3], [1, 0, 4], [2, 1, 4], [0, 1, 5], [1, 2, 5]])),
    # two triangle fans sharing vertex 0 only (a bow-tie), with a creased vertex.
    "bowtie-fans": mesh([(0, 0, 0, "semi"), (1, 1, 0), (1, -1, 0), (1, 0, 1), (-1, 1, 0), (-1, -1, 0), (-1, 0, 1)],
                        faces([[0, 1, 2], [0, 2, 3], [0, 4, 5], [0, 5, 6]])),
}

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "corpora", "fuzz")
for target in ("fuzz_mesh_manifold", "fuzz_mesh_subdivision"):
    d = os.path.join(root, target)
    os.makedirs(d, exist_ok=True)
    for name, data in seeds.items():
        with open(os.path.join(d, "seed-%s.bin" % name), "wb") as f:
            f.write(data)
print("wrote %d seeds per mesh target" % len(seeds))
