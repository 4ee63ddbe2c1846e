// obj_import_test.cpp — `vgc import` (conformance/obj_import.h): a node
// written as OBJ by report/obj_writer.h (the report's exporter, corners
// reversed) and read back is the same node; quads stay quads; a face of 5
// corners and a corner naming no vertex are errors naming line and column;
// no crease is set (the node keeps its smooth defaults).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "command_text.h"
#include "mesh_arrays.h"
#include "node.h"
#include "obj_import.h"
#include "obj_writer.h"
#include "snapshot.h"

namespace vgc {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("vgc_obj_import_test_" + name);
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

Node run(const std::vector<Command>& commands) {
  Node node;
  for (const auto& c : commands) EXPECT_EQ(node.apply(c), Reason::Ok) << print_command(c);
  return node;
}

TEST(ObjImport, ANodeExportedAndImportedIsTheSameNode) {
  // A pyramid: a quad base and four triangles, ids 0.., as the importer numbers them.
  std::vector<Command> commands;
  TextError e;
  ASSERT_TRUE(parse_commands("vertex_set_xyz_real64 0 0 0 0 0\n"
                             "vertex_set_xyz_real64 0 1 1 0 0\n"
                             "vertex_set_xyz_real64 0 2 1 1 0\n"
                             "vertex_set_xyz_real64 0 3 0 1 0\n"
                             "vertex_set_xyz_real64 0 4 0.5 0.5 0.70710678118654757\n"
                             "polygon_set_corner_uint32 1 0 0 1 2 3\n"
                             "polygon_set_corner_uint32 1 1 0 4 1 0xFFFFFFFF\n"
                             "polygon_set_corner_uint32 1 2 1 4 2 0xFFFFFFFF\n"
                             "polygon_set_corner_uint32 1 3 2 4 3 0xFFFFFFFF\n"
                             "polygon_set_corner_uint32 1 4 3 4 0 0xFFFFFFFF\n",
                             &commands, &e))
      << e.message;
  const Node original = run(commands);
  const std::string path = write_temp("pyramid.obj", render_obj(extract_mesh(original), "pyramid"));
  ObjMesh mesh;
  ObjError error;
  ASSERT_TRUE(import_obj(path, &mesh, &error)) << error.message;
  EXPECT_EQ(mesh.vertices, 5u);
  EXPECT_EQ(mesh.quads, 1u);
  EXPECT_EQ(mesh.triangles, 4u);
  // The same polygons and vertex ids; the same positions but for
  // tinyobjloader's own number reading, which is not always correctly
  // rounded (seen here: 0.7071067811865476 read as 0.7071067811865475).
  const MeshArrays a = extract_mesh(run(mesh.program.commands)), b = extract_mesh(original);
  EXPECT_EQ(a.vertex_ids, b.vertex_ids);
  EXPECT_EQ(a.polygon_ids, b.polygon_ids);
  EXPECT_EQ(a.face_sizes, b.face_sizes);
  EXPECT_EQ(a.face_vertices, b.face_vertices);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::size_t i = 0; i < a.positions.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.positions[i][k], b.positions[i][k], 1e-15) << "vertex " << i;
  // No crease is set: only vertices and polygons.
  for (const auto& c : mesh.program.commands)
    EXPECT_TRUE(std::holds_alternative<cmd::VertexSetXyzReal64>(c) || std::holds_alternative<cmd::PolygonSetCornerUint32>(c))
        << print_command(c);
  EXPECT_NE(print_obj_import(mesh, path).find("OBJ has no creases"), std::string::npos);
  std::remove(path.c_str());
}

TEST(ObjImport, CornersAreReversedToTheNodesClockwiseFront) {
  const std::string path = write_temp("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ObjMesh mesh;
  ObjError error;
  ASSERT_TRUE(import_obj(path, &mesh, &error)) << error.message;
  ASSERT_EQ(mesh.program.commands.size(), 4u);
  EXPECT_EQ(print_command(mesh.program.commands[3]), "polygon_set_corner_uint32 1 0 2 1 0 0xFFFFFFFF");
  std::remove(path.c_str());
}

TEST(ObjImport, AFaceOfFiveCornersIsAnErrorNamingItsLine) {
  const std::string path = write_temp("five.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 2 2\n\nf 1 2 3 4 5\n");
  ObjMesh mesh;
  ObjError error;
  EXPECT_FALSE(import_obj(path, &mesh, &error));
  EXPECT_EQ(error.line, 7u);
  EXPECT_EQ(error.column, 3u);
  EXPECT_NE(error.message.find("5 corners"), std::string::npos) << error.message;
  std::remove(path.c_str());
}

TEST(ObjImport, ACornerNamingNoVertexIsAnErrorNamingItsLineAndColumn) {
  const std::string path = write_temp("bad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\n# c\nf 1 2  9\nf 1 2 3\n");
  ObjMesh mesh;
  ObjError error;
  EXPECT_FALSE(import_obj(path, &mesh, &error));
  EXPECT_EQ(error.line, 5u);
  EXPECT_EQ(error.column, 8u);
  EXPECT_NE(error.message.find("corner 3"), std::string::npos) << error.message;
  std::remove(path.c_str());
}

TEST(ObjImport, AMissingFileIsAnError) {
  ObjMesh mesh;
  ObjError error;
  EXPECT_FALSE(import_obj("/nonexistent/vgc/mesh.obj", &mesh, &error));
  EXPECT_EQ(error.line, 0u);
  EXPECT_FALSE(error.message.empty());
}

}  // namespace
}  // namespace vgc
