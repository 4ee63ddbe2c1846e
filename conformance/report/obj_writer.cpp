// obj_writer.cpp — see obj_writer.h.
#include "obj_writer.h"

#include "number_text.h"

namespace vgc {

std::string render_obj(const MeshArrays& mesh, const std::string& title) {
  std::string name;
  for (char c : title) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
                    c == '_' || c == '.';
    name += ok ? c : '_';
  }
  if (name.empty()) name = "mesh";
  std::string out;
  std::string first = title;
  for (char& c : first)
    if (c == '\n' || c == '\r') c = ' ';
  out += "# " + first + "\n";
  out += "# written by vgc: " + std::to_string(mesh.vertex_count()) + " vertices, " +
         std::to_string(mesh.face_count()) + " faces; corners reversed, so the node's clockwise front is OBJ's front\n";
  out += "o " + name + "\n";
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    const auto& p = mesh.positions[static_cast<std::size_t>(i)];
    out += "v " + format_f64(p[0]) + " " + format_f64(p[1]) + " " + format_f64(p[2]) + "\n";
  }
  out += "# OBJ vertex index -> node vertex id:";
  for (int i = 0; i < mesh.vertex_count(); ++i)
    out += " " + std::to_string(i + 1) + "=" + std::to_string(mesh.vertex_ids[static_cast<std::size_t>(i)]);
  out += "\n";
  for (int f = 0; f < mesh.face_count(); ++f) {
    const int size = mesh.face_sizes[static_cast<std::size_t>(f)];
    const int offset = mesh.face_offsets[static_cast<std::size_t>(f)];
    out += "# polygon " + std::to_string(mesh.polygon_ids[static_cast<std::size_t>(f)]) + "\nf";
    for (int k = size - 1; k >= 0; --k)
      out += " " + std::to_string(mesh.face_vertices[static_cast<std::size_t>(offset + k)] + 1);
    out += "\n";
  }
  return out;
}

}  // namespace vgc
