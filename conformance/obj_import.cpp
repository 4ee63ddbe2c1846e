// obj_import.cpp — see obj_import.h.
#include "obj_import.h"

#include <tiny_obj_loader.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "bounded_text.h"
#include "program_text.h"

namespace vgc {
namespace {

// Where each face line ("f ...") is: its line number and the column of each
// corner's token. Only to name a line in an error: tinyobjloader reads the
// file; this only finds which line held face j.
struct FaceLine {
  std::size_t line = 0;
  std::vector<std::size_t> columns;
};

std::vector<FaceLine> face_lines(const std::string& path) {
  std::vector<FaceLine> out;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line[i] != 'f' || i + 1 >= line.size() || (line[i + 1] != ' ' && line[i + 1] != '\t'))
      continue;
    FaceLine f;
    f.line = n;
    for (i += 1; i < line.size();) {
      i = line.find_first_not_of(" \t\r", i);
      if (i == std::string::npos) break;
      f.columns.push_back(i + 1);
      i = line.find_first_of(" \t\r", i);
      if (i == std::string::npos) break;
    }
    out.push_back(std::move(f));
  }
  return out;
}

// tinyobjloader's messages name a line as "line N" or "line: N".
std::size_t line_of(const std::string& message) {
  static const std::regex re(R"(line:? (\d+))");
  std::smatch m;
  return std::regex_search(message, m, re) ? std::stoul(m[1].str()) : 0;
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace

bool import_obj(const std::string& path, ObjMesh* out, ObjError* error) {
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) {
      error->message = "cannot read the file";
      return false;
    }
  }
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // quads stay quads; larger faces are refused below
  config.vertex_color = false;
  config.mtl_search_path = "";
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    error->message = bounded_text(trimmed(reader.Error()));  // it may quote the file's bytes
    if (error->message.empty()) error->message = "tinyobjloader could not read it";
    error->line = line_of(error->message);
    error->column = error->line ? 1 : 0;
    return false;
  }
  std::istringstream warnings(reader.Warning());
  for (std::string w; std::getline(warnings, w);)
    if (!w.empty() && w.find("out of bounds") == std::string::npos) out->warnings.push_back(w);
  const auto& v = reader.GetAttrib().vertices;
  const std::size_t nv = v.size() / 3;
  out->vertices = nv;
  for (std::size_t i = 0; i < nv; ++i) {
    cmd::VertexSetXyzReal64 c;
    c.layer_id = 0;
    c.vertex_id = static_cast<std::uint32_t>(i);
    c.x = v[3 * i], c.y = v[3 * i + 1], c.z = v[3 * i + 2];
    out->program.commands.push_back(c);
  }
  const std::vector<FaceLine> lines = face_lines(path);
  std::size_t face = 0;
  for (const auto& shape : reader.GetShapes()) {
    std::size_t at = 0;
    for (const unsigned char n : shape.mesh.num_face_vertices) {
      const FaceLine* where = face < lines.size() ? &lines[face] : nullptr;
      auto fail = [&](std::size_t corner, const std::string& message) {
        error->line = where ? where->line : 0;
        error->column = where ? (corner < where->columns.size() ? where->columns[corner] : 1) : 0;
        error->message = message + (where ? "" : " (face " + std::to_string(face + 1) + " of the file)");
        return false;
      };
      if (n < 3 || n > 4)
        return fail(0, "a face of " + std::to_string(n) +
                           " corners: a node's polygon has 3 or 4 (000 section 2.6); split it into triangles or "
                           "quads first");
      cmd::PolygonSetCornerUint32 c;
      c.layer_id = 1;
      c.polygon_id = static_cast<std::uint32_t>(face);
      c.v = {kNone32, kNone32, kNone32, kNone32};
      for (std::size_t k = 0; k < n; ++k) {
        const int vi = shape.mesh.indices[at + k].vertex_index;
        if (vi < 0 || static_cast<std::size_t>(vi) >= nv)
          return fail(k, "corner " + std::to_string(k + 1) + " names a vertex the file does not have (it has " +
                             std::to_string(nv) + ")");
        c.v[n - 1 - k] = static_cast<std::uint32_t>(vi);  // reversed: OBJ's front is counter-clockwise
      }
      at += n;
      (n == 3 ? out->triangles : out->quads) += 1;
      out->program.commands.push_back(c);
      ++face;
    }
  }
  return true;
}

std::string print_obj_import(const ObjMesh& mesh, const std::string& path) {
  std::string out = "# vgc import " + path + ": " + std::to_string(mesh.vertices) + " vertices, " +
                    std::to_string(mesh.triangles) + " triangles, " + std::to_string(mesh.quads) + " quads\n";
  out += "# OBJ vertex k is vertex id k-1 (layer 0), face j polygon id j-1 (layer 1), corners reversed\n"
         "# (OBJ's front side is counter-clockwise, the node's clockwise).\n"
         "# OBJ has no creases: no crease is set, so the node is smooth everywhere (its default\n"
         "# settings, docs/commands.md 4.7); smoothing groups, normals, texture coordinates and\n"
         "# materials are not imported.\n";
  return out + print_program(mesh.program);
}

}  // namespace vgc
