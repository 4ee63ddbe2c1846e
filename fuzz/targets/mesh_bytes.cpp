// mesh_bytes.cpp — see mesh_bytes.h.
#include "mesh_bytes.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace vgc::fuzz {

namespace {

int lattice_index(double x) {
  for (std::size_t i = 0; i < kMeshLattice.size(); ++i)
    if (kMeshLattice[i] == x) return static_cast<int>(i);
  return -1;
}

int crease_index(std::uint32_t c) {
  for (std::size_t i = 0; i < kMeshCreases.size(); ++i)
    if (kMeshCreases[i] == c) return static_cast<int>(i);
  return -1;
}

}  // namespace

MeshArrays decode_mesh_bytes(const std::uint8_t* data, std::size_t size) {
  MeshArrays m;
  std::size_t pos = 0;
  int vertices = size > 0 ? data[pos++] % (kMeshMaxVertices + 1) : 0;
  if (static_cast<std::size_t>(vertices) > size - pos) vertices = static_cast<int>(size - pos);
  for (int v = 0; v < vertices; ++v) {
    const std::uint8_t b = data[pos++];
    m.vertex_ids.push_back(static_cast<std::uint32_t>(v));
    m.positions.push_back({kMeshLattice[b & 3u], kMeshLattice[(b >> 2) & 3u], kMeshLattice[(b >> 4) & 3u]});
    m.vertex_creases.push_back(kMeshCreases[b >> 6]);
  }
  const int modulus = vertices > 0 ? vertices : 1;
  while (pos < size && m.face_count() < kMeshMaxFaces) {
    const std::uint8_t s = data[pos++];
    const int n = (s & 0xF0u) == 0xF0u ? (s & 3) : 3 + (s & 3);
    if (size - pos < static_cast<std::size_t>(n) + 1) break;  // cut off: dropped
    std::vector<int> corners;
    for (int c = 0; c < n; ++c) {
      const std::uint8_t b = data[pos++];
      switch (b) {
        case 0xFC: corners.push_back(vertices); break;
        case 0xFD: corners.push_back(vertices + 1); break;
        case 0xFE: corners.push_back(-1); break;
        case 0xFF: corners.push_back(-2); break;
        default: corners.push_back(b % modulus); break;
      }
    }
    const std::uint8_t k = data[pos++];
    m.polygon_ids.push_back(static_cast<std::uint32_t>(m.face_count()));
    m.face_offsets.push_back(static_cast<int>(m.face_vertices.size()));
    m.face_sizes.push_back(n);
    for (int c = 0; c < n; ++c) {
      m.face_vertices.push_back(corners[static_cast<std::size_t>(c)]);
      m.corner_edge_creases.push_back((k >> c) & 1u ? kMeshCreases[k >> 6] : 0u);
    }
  }
  return m;
}

bool encode_mesh_bytes(const MeshArrays& m, std::vector<std::uint8_t>* out) {
  out->clear();
  const int vertices = m.vertex_count();
  if (vertices > kMeshMaxVertices || m.face_count() > kMeshMaxFaces) return false;
  if (m.vertex_creases.size() != m.positions.size() || m.face_offsets.size() != m.face_sizes.size() ||
      m.corner_edge_creases.size() != m.face_vertices.size())
    return false;
  out->push_back(static_cast<std::uint8_t>(vertices));
  for (int v = 0; v < vertices; ++v) {
    int byte = 0;
    for (int a = 0; a < 3; ++a) {
      const int i = lattice_index(m.positions[static_cast<std::size_t>(v)][static_cast<std::size_t>(a)]);
      if (i < 0) return false;
      byte |= i << (2 * a);
    }
    const int c = crease_index(m.vertex_creases[static_cast<std::size_t>(v)]);
    if (c < 0) return false;
    out->push_back(static_cast<std::uint8_t>(byte | c << 6));
  }
  int offset = 0;
  for (int f = 0; f < m.face_count(); ++f) {
    const int n = m.face_sizes[static_cast<std::size_t>(f)];
    if (m.face_offsets[static_cast<std::size_t>(f)] != offset || n < 0 || n > 6 ||
        offset + n > static_cast<int>(m.face_vertices.size()))
      return false;
    out->push_back(static_cast<std::uint8_t>(n >= 3 ? n - 3 : 0xF0 | n));
    int mask = 0, value = -1;
    for (int c = 0; c < n; ++c) {
      const int idx = m.face_vertices[static_cast<std::size_t>(offset + c)];
      if (idx >= 0 && idx < vertices) out->push_back(static_cast<std::uint8_t>(idx));
      else if (idx == vertices) out->push_back(0xFC);
      else if (idx == vertices + 1) out->push_back(0xFD);
      else if (idx == -1) out->push_back(0xFE);
      else if (idx == -2) out->push_back(0xFF);
      else return false;
      const std::uint32_t crease = m.corner_edge_creases[static_cast<std::size_t>(offset + c)];
      if (crease == 0) continue;
      const int ci = crease_index(crease);
      if (ci < 0 || (value >= 0 && value != ci)) return false;
      value = ci;
      mask |= 1 << c;
    }
    out->push_back(static_cast<std::uint8_t>(mask | (value < 0 ? 0 : value) << 6));
    offset += n;
  }
  return offset == static_cast<int>(m.face_vertices.size());
}

std::string print_mesh(const MeshArrays& m) {
  std::ostringstream o;
  o << "# " << m.vertex_count() << " vertices, " << m.face_count() << " faces\n";
  for (int v = 0; v < m.vertex_count(); ++v) {
    const auto& p = m.positions[static_cast<std::size_t>(v)];
    char crease[16];
    std::snprintf(crease, sizeof crease, "0x%08X",
                  static_cast<unsigned>(v < static_cast<int>(m.vertex_creases.size()) ? m.vertex_creases[static_cast<std::size_t>(v)] : 0));
    o << "v " << v << ' ' << p[0] << ' ' << p[1] << ' ' << p[2] << " crease " << crease << '\n';
  }
  for (int f = 0; f < m.face_count(); ++f) {
    const int off = f < static_cast<int>(m.face_offsets.size()) ? m.face_offsets[static_cast<std::size_t>(f)] : -1;
    const int n = m.face_sizes[static_cast<std::size_t>(f)];
    o << "f " << f << ':';
    std::ostringstream creases;
    for (int c = 0; c < n; ++c) {
      const int i = off + c;
      if (off < 0 || i >= static_cast<int>(m.face_vertices.size())) {
        o << " ?";
        continue;
      }
      o << ' ' << m.face_vertices[static_cast<std::size_t>(i)];
      char crease[16];
      std::snprintf(crease, sizeof crease, " 0x%08X",
                    static_cast<unsigned>(i < static_cast<int>(m.corner_edge_creases.size()) ? m.corner_edge_creases[static_cast<std::size_t>(i)] : 0));
      creases << crease;
    }
    o << " | creases" << creases.str() << '\n';
  }
  return o.str();
}

void report_mesh_finding(const char* target, const std::string& what, const MeshArrays& mesh) {
  const std::string text = print_mesh(mesh);
  std::fprintf(stderr,
               "vgc-fuzz: FINDING in %s: %s\n"
               "vgc-fuzz: the mesh (v INDEX X Y Z crease; f INDEX: CORNERS | per-corner edge creases):\n"
               "----8<---- mesh.txt\n%s----8<----\n",
               target, what.c_str(), text.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace vgc::fuzz
