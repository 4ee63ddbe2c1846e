// cmd_import.cpp — `vgc import FILE`: a mesh file (OBJ, OFF, PLY, STL) as a
// command file on stdout (oracles/mesh_import.h reads it with CGAL;
// conformance/mesh_program.h says what becomes of it), e.g.
// `vgc import mesh.off > mesh.vgc`, for `vgc apply`, `vgc replay` or a
// team's own tests. --triangulate splits faces of more than 4 corners.
//
// Exit codes: 0 the mesh was written; 2 the file cannot be read or holds
// what a node cannot (a face of more than 4 corners without --triangulate,
// a corner naming no vertex, no face at all): the error names file:line:col
// where the format has lines, the file's name and bytes escaped.
#include <memory>
#include <string>

#include "mesh_import.h"
#include "subcommand.h"
#include "terminal_text.h"

namespace vgc::cli {
namespace {

int run_import(const std::string& file, bool triangulate) {
  MeshProgram mesh;
  MeshFileError error;
  if (!import_mesh(file, MeshImportOptions{triangulate}, &mesh, &error)) {
    if (error.line)
      say(stderr, "{}:{}:{}: error: {}\n", one_line_text(file), error.line, error.column, error.message);
    else
      say(stderr, "{}: error: {}\n", one_line_text(file), error.message);
    return 2;
  }
  for (const auto& w : mesh.warnings) say(stderr, "{}: warning: {}\n", one_line_text(file), w);
  if (mesh.split_faces)
    say(stderr, "{}: --triangulate split {} faces of more than 4 corners into triangles\n", one_line_text(file),
        mesh.split_faces);
  say("{}", print_mesh_import(mesh, file));
  return 0;
}

void add_import(CLI::App& app, int* exit_code) {
  auto file = std::make_shared<std::string>();
  auto triangulate = std::make_shared<bool>(false);
  auto* sub = app.add_subcommand("import", "Print a mesh file (OBJ, OFF, PLY, STL) as a command file");
  sub->add_option("file", *file, "The mesh: .obj, .off, .ply or .stl (triangles and quads; no creases)")->required();
  sub->add_flag("--triangulate", *triangulate,
                "Split faces of more than 4 corners into triangles (CGAL; concave faces included)");
  sub->callback([file, triangulate, exit_code] { *exit_code = run_import(*file, *triangulate); });
}

const Subcommand kImport{add_import};

}  // namespace
}  // namespace vgc::cli
