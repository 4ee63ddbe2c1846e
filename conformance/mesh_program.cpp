// mesh_program.cpp — see mesh_program.h.
#include "mesh_program.h"

#include "display_text.h"
#include "program_text.h"

namespace vgc {

bool program_from_soup(const PolygonSoup& soup, MeshProgram* out, MeshFileError* error) {
  out->format = soup.format;
  const std::size_t nv = soup.points.size();
  if (nv > 0xFFFFFFFEu || soup.polygons.size() > 0xFFFFFFFEu) {
    error->message = "more vertices or faces than a node's 32-bit ids can name";
    return false;
  }
  out->vertices = nv;
  out->program.commands.reserve(nv + soup.polygons.size());
  for (std::size_t i = 0; i < nv; ++i) {
    cmd::VertexSetXyzReal64 c;
    c.layer_id = 0;
    c.vertex_id = static_cast<std::uint32_t>(i);
    c.x = soup.points[i][0], c.y = soup.points[i][1], c.z = soup.points[i][2];
    out->program.commands.push_back(c);
  }
  for (std::size_t face = 0; face < soup.polygons.size(); ++face) {
    const auto& p = soup.polygons[face];
    auto fail = [&](const std::string& message) {
      error->line = face < soup.polygon_lines.size() ? soup.polygon_lines[face] : 0;
      error->column = face < soup.polygon_columns.size() ? soup.polygon_columns[face] : 0;
      error->message = message + (error->line ? "" : " (face " + std::to_string(face + 1) + " of the file)");
      return false;
    };
    const std::size_t n = p.size();
    if (n < 3)
      return fail("a face of " + std::to_string(n) + " corner" + (n == 1 ? "" : "s") +
                  ": a polygon has 3 or 4 (000 section 2.6); remove it or give it its corners");
    if (n > 4)
      return fail("a face of " + std::to_string(n) +
                  " corners: a node's polygon has 3 or 4 (000 section 2.6); give --triangulate to split such "
                  "faces into triangles, or split them first");
    cmd::PolygonSetCornerUint32 c;
    c.layer_id = 1;
    c.polygon_id = static_cast<std::uint32_t>(face);
    c.v = {kNone32, kNone32, kNone32, kNone32};
    for (std::size_t k = 0; k < n; ++k) {
      if (p[k] >= nv)
        return fail("corner " + std::to_string(k + 1) + " names vertex " + std::to_string(p[k]) +
                    " (0-based) and the file has " + std::to_string(nv));
      c.v[n - 1 - k] = static_cast<std::uint32_t>(p[k]);  // reversed: the file's front is counter-clockwise
    }
    (n == 3 ? out->triangles : out->quads) += 1;
    out->program.commands.push_back(c);
  }
  return true;
}

std::string one_line_text(const std::string& text) {
  std::string out;
  for (char c : escape_unprintable(text)) {
    if (c == '\n') out += "\\x0a";
    else out += c;
  }
  return out;
}

std::string print_mesh_import(const MeshProgram& mesh, const std::string& path) {
  std::string out = "# vgc import " + one_line_text(path) + " (" + mesh.format + "): " + std::to_string(mesh.vertices) +
                    " vertices, " + std::to_string(mesh.triangles) + " triangles, " + std::to_string(mesh.quads) +
                    " quads\n";
  if (mesh.split_faces)
    out += "# --triangulate split " + std::to_string(mesh.split_faces) + " faces of more than 4 corners into triangles\n";
  out += "# Vertex k of the file is vertex id k (layer 0), face j polygon id j (layer 1), corners reversed\n"
         "# (the file's front side is counter-clockwise, the node's clockwise).\n"
         "# OBJ has no creases (nor OFF, PLY, STL): no crease is set, so the node is smooth everywhere (its\n"
         "# default settings, docs/commands.md 4.7); smoothing groups, normals, texture coordinates,\n"
         "# colours and materials are not imported.\n";
  return out + print_program(mesh.program);
}

}  // namespace vgc
