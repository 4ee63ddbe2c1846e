// mesh_import_test.cpp — `vgc import` (oracles/mesh_import.h,
// conformance/mesh_program.h): a node written as OBJ by report/obj_writer.h
// and read back is the same node, bit for bit; corners are reversed to the
// node's clockwise front; OFF, PLY and STL are read; a file no reader
// understands (empty, UTF-16, another encoding, an unknown extension, a
// statement CGAL refuses, an empty face, a corner one past the last vertex,
// no face at all) is an error naming file:line where the format has lines;
// --triangulate splits a concave face inside its outline; nothing of a
// file's name becomes a command of the printed file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "command_text.h"
#include "mesh_arrays.h"
#include "mesh_import.h"
#include "node.h"
#include "obj_writer.h"
#include "program_text.h"
#include "snapshot.h"

namespace vgc {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("vgc_mesh_import_test_" + name);
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

Node run(const std::vector<Command>& commands) {
  Node node;
  for (const auto& c : commands) EXPECT_EQ(node.apply(c), Reason::Ok) << print_command(c);
  return node;
}

// import_mesh of `text` written as `name`: the error (line, column, message) or success.
struct Imported {
  bool ok = false;
  MeshProgram mesh;
  MeshFileError error;
};
Imported import_text(const std::string& name, const std::string& text, bool triangulate = false) {
  Imported r;
  const std::string path = write_temp(name, text);
  r.ok = import_mesh(path, MeshImportOptions{triangulate}, &r.mesh, &r.error);
  std::remove(path.c_str());
  return r;
}

TEST(MeshImport, ANodeExportedAndImportedIsTheSameNodeBitForBit) {
  std::vector<Command> commands;
  TextError e;
  ASSERT_TRUE(parse_commands("vertex_set_xyz_real64 0 0 0 0 0\n"
                             "vertex_set_xyz_real64 0 1 1 0 0.1\n"
                             "vertex_set_xyz_real64 0 2 1 1 0.12794\n"
                             "vertex_set_xyz_real64 0 3 0 1 -1e-300\n"
                             "vertex_set_xyz_real64 0 4 0.5 0.5 0.70710678118654757\n"
                             "polygon_set_corner_uint32 1 0 0 1 2 3\n"
                             "polygon_set_corner_uint32 1 1 0 4 1 0xFFFFFFFF\n"
                             "polygon_set_corner_uint32 1 2 1 4 2 0xFFFFFFFF\n"
                             "polygon_set_corner_uint32 1 3 2 4 3 0xFFFFFFFF\n"
                             "polygon_set_corner_uint32 1 4 3 4 0 0xFFFFFFFF\n",
                             &commands, &e))
      << e.message;
  const Node original = run(commands);
  const Imported r = import_text("pyramid.obj", render_obj(extract_mesh(original), "pyramid"));
  ASSERT_TRUE(r.ok) << r.error.message;
  EXPECT_EQ(r.mesh.vertices, 5u);
  EXPECT_EQ(r.mesh.quads, 1u);
  EXPECT_EQ(r.mesh.triangles, 4u);
  EXPECT_EQ(print_snapshot(run(r.mesh.program.commands)), print_snapshot(original));
  for (const auto& c : r.mesh.program.commands)
    EXPECT_TRUE(std::holds_alternative<cmd::VertexSetXyzReal64>(c) || std::holds_alternative<cmd::PolygonSetCornerUint32>(c))
        << print_command(c);
  EXPECT_NE(print_mesh_import(r.mesh, "p.obj").find("OBJ has no creases"), std::string::npos);
}

TEST(MeshImport, NumbersAreReadCorrectlyRounded) {
  // Each of these was read one unit in the last place off by the importer
  // before CGAL's (tinyobjloader's own digit loop).
  const Imported r = import_text("round.obj", "v 0.127940 0.7071067811865476 -0.411917\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ASSERT_TRUE(r.ok) << r.error.message;
  const auto& v = std::get<cmd::VertexSetXyzReal64>(r.mesh.program.commands[0]);
  EXPECT_EQ(v.x, 0.127940);
  EXPECT_EQ(v.y, 0.7071067811865476);
  EXPECT_EQ(v.z, -0.411917);
}

TEST(MeshImport, CornersAreReversedToTheNodesClockwiseFront) {
  for (const char* name : {"tri.obj", "tri.off"}) {
    const Imported r = import_text(name, std::string(name).find("obj") != std::string::npos
                                             ? "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
                                             : "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    ASSERT_TRUE(r.ok) << name << ": " << r.error.message;
    ASSERT_EQ(r.mesh.program.commands.size(), 4u);
    EXPECT_EQ(print_command(r.mesh.program.commands[3]), "polygon_set_corner_uint32 1 0 2 1 0 0xFFFFFFFF") << name;
  }
}

TEST(MeshImport, PlyAndStlAreRead) {
  const Imported ply = import_text("q.ply",
                                   "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                                   "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                   "end_header\n0 0 0\n1 0 0\n1 1 0.1\n0 1 0\n4 0 1 2 3\n");
  ASSERT_TRUE(ply.ok) << ply.error.message;
  EXPECT_EQ(ply.mesh.format, "PLY");
  EXPECT_EQ(ply.mesh.quads, 1u);
  const Imported stl = import_text("t.stl",
                                   "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                                   "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\n"
                                   "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n");
  ASSERT_TRUE(stl.ok) << stl.error.message;
  EXPECT_EQ(stl.mesh.vertices, 4u);  // STL's repeated corners are one vertex
  EXPECT_EQ(stl.mesh.triangles, 2u);
}

void expect_refused(const Imported& r, std::size_t line, std::size_t column, const std::string& words) {
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.error.line, line) << r.error.message;
  if (column) {
    EXPECT_EQ(r.error.column, column) << r.error.message;
  }
  EXPECT_NE(r.error.message.find(words), std::string::npos) << r.error.message;
}

TEST(MeshImport, AFileNoReaderUnderstandsIsRefusedNamingLineAndReason) {
  expect_refused(import_text("empty.obj", ""), 0, 0, "empty");
  expect_refused(import_text("u16.obj", std::string("\xFF\xFEv\0 \0""1\0", 8)), 1, 1, "UTF-16");
  expect_refused(import_text("u16nobom.off", std::string("O\0F\0F\0\n\0", 8)), 1, 2, "NUL");
  expect_refused(import_text("latin1.obj", "v 0 0 0\n# caf\xE9\nv 1 0 0\n"), 2, 6, "not UTF-8");
  expect_refused(import_text("mesh.xyz", "v 0 0 0\n"), 0, 0, "no reader for '.xyz'");
  expect_refused(import_text("l.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n"), 3, 1, "'l'");
  expect_refused(import_text("emptyf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf\nf 1 2 3\n"), 4, 1, "no corners");
  expect_refused(import_text("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), 4, 3, "index 0");
  // One past the last vertex: CGAL's own range check lets it through.
  expect_refused(import_text("past.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\n# c\nf 1 2  4\nf 1 2 3\n"), 5, 8, "corner 3");
  expect_refused(import_text("nan.obj", "v 0 nan 0\n"), 1, 5, "not a finite number");
  expect_refused(import_text("comma.obj", "v 0 0,5 0\n"), 1, 5, "not a number");
  expect_refused(import_text("points.obj", "v 0 0 0\nv 1 0 0\n"), 0, 0, "no face");
  expect_refused(import_text("short.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), 2, 1, "announce");
  expect_refused(import_text("zero.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0\n"), 6, 1, "no corners");
  expect_refused(import_text("two.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n"), 6, 3, "2 corners");
}

TEST(MeshImport, AFaceOfFiveCornersNamesTheOptionThatSplitsIt) {
  const Imported r = import_text("five.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 2 2\n\nf 1 2 3 4 5\n");
  expect_refused(r, 7, 3, "5 corners");
  EXPECT_NE(r.error.message.find("--triangulate"), std::string::npos) << r.error.message;
}

// Twice the signed area of triangle (a, b, c) in the xy plane.
double cross2(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

TEST(MeshImport, TriangulateSplitsAConcaveFaceInsideItsOutline) {
  // An L-shaped hexagon (concave at vertex 4, (1,1)), counter-clockwise; a
  // fan from vertex 0... fine here, so the fan from the reflex corner's
  // neighbour is what a naive split gets wrong: start the face at 5.
  const std::string obj = "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nf 3 4 5 6 1 2\nf 1 2 3\n";
  const Imported r = import_text("ell.obj", obj, true);
  ASSERT_TRUE(r.ok) << r.error.message;
  EXPECT_EQ(r.mesh.split_faces, 1u);
  EXPECT_EQ(r.mesh.triangles, 5u);  // 4 from the hexagon, and the triangle that was one
  std::array<std::array<double, 3>, 6> p{};
  for (int i = 0; i < 6; ++i) {
    const auto& v = std::get<cmd::VertexSetXyzReal64>(r.mesh.program.commands[static_cast<std::size_t>(i)]);
    p[static_cast<std::size_t>(i)] = {v.x, v.y, v.z};
  }
  double area = 0;
  for (std::size_t k = 6; k < 10; ++k) {
    const auto& c = std::get<cmd::PolygonSetCornerUint32>(r.mesh.program.commands[k]);
    // Clockwise in the node (the file's counter-clockwise reversed), so
    // the file's orientation: negative area here, none degenerate.
    const double a = cross2(p[c.v[0]], p[c.v[1]], p[c.v[2]]);
    EXPECT_LT(a, 0) << print_command(r.mesh.program.commands[k]);
    area -= a / 2;
    // Inside the L: the centroid is not in the missing square [1,2]x[1,2].
    const double cx = (p[c.v[0]][0] + p[c.v[1]][0] + p[c.v[2]][0]) / 3, cy = (p[c.v[0]][1] + p[c.v[1]][1] + p[c.v[2]][1]) / 3;
    EXPECT_FALSE(cx > 1 && cy > 1) << print_command(r.mesh.program.commands[k]);
  }
  EXPECT_DOUBLE_EQ(area, 3.0);  // the L's area: the triangles cover it once
  EXPECT_NE(print_mesh_import(r.mesh, "ell.obj").find("--triangulate split 1 faces"), std::string::npos);
}

TEST(MeshImport, NothingOfTheFilesNameBecomesACommand) {
  const Imported r = import_text("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ASSERT_TRUE(r.ok);
  const std::string text = print_mesh_import(r.mesh, "x.obj\nvertex_set_xyz_real64 0 7 1 2 3\r\n#");
  Program parsed;
  TextError error;
  ASSERT_TRUE(parse_program(text, &parsed, &error)) << error.message;
  EXPECT_EQ(parsed.commands.size(), r.mesh.program.commands.size()) << text;
  EXPECT_NE(text.find("x.obj\\x0avertex_set_xyz_real64 0 7 1 2 3\\x0d\\x0a#"), std::string::npos) << text;
}

TEST(MeshImport, AMissingFileIsAnError) {
  MeshProgram mesh;
  MeshFileError error;
  EXPECT_FALSE(import_mesh("/nonexistent/vgc/mesh.obj", {}, &mesh, &error));
  EXPECT_EQ(error.line, 0u);
  EXPECT_NE(error.message.find("cannot read"), std::string::npos) << error.message;
}

}  // namespace
}  // namespace vgc
