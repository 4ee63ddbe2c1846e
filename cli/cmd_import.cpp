// cmd_import.cpp — `vgc import FILE.obj`: a Wavefront OBJ mesh as a command
// file on stdout (obj_import.h: vertices, triangles, quads; what becomes of
// sharpness), e.g. `vgc import mesh.obj > mesh.vgc`, for `vgc apply`,
// `vgc replay` or a team's own tests.
//
// Exit codes: 0 the mesh was written; 2 the file cannot be read or holds
// what a node cannot (a face of more than 4 corners, a corner naming no
// vertex): the error names file:line:col, its bytes escaped.
#include <memory>
#include <string>

#include "obj_import.h"
#include "subcommand.h"
#include "terminal_text.h"

namespace vgc::cli {
namespace {

int run_import(const std::string& file) {
  ObjMesh mesh;
  ObjError error;
  if (!import_obj(file, &mesh, &error)) {
    if (error.line)
      say(stderr, "{}:{}:{}: error: {}\n", file, error.line, error.column, error.message);
    else
      say(stderr, "{}: error: {}\n", file, error.message);
    return 2;
  }
  for (const auto& w : mesh.warnings) say(stderr, "{}: warning: {}\n", file, w);
  say("{}", print_obj_import(mesh, file));
  return 0;
}

void add_import(CLI::App& app, int* exit_code) {
  auto file = std::make_shared<std::string>();
  auto* sub = app.add_subcommand("import", "Print a Wavefront OBJ mesh as a command file (vertices, polygons)");
  sub->add_option("file", *file, "The OBJ file (triangles and quads; OBJ has no creases)")->required();
  sub->callback([file, exit_code] { *exit_code = run_import(*file); });
}

const Subcommand kImport{add_import};

}  // namespace
}  // namespace vgc::cli
