// mesh_corpus_test.cpp — real meshes (Debian libcgal-demo's data/meshes,
// extracted by the MeshCorpus.Extract fixture): import, build on the
// reference, export with report/obj_writer.h (what a counterexample's .obj
// is), import again: the same node, bit for bit (issue 28: "import then
// export then import gives the same node"). Faces of 5+ corners go through
// --triangulate and keep the corners of the face they split.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include "mesh_arrays.h"
#include "mesh_import.h"
#include "node.h"
#include "obj_writer.h"
#include "snapshot.h"

namespace vgc {
namespace {

const std::string kDir = VGC_MESH_DIR;

MeshProgram import_or_fail(const std::string& path, bool triangulate = false) {
  MeshProgram m;
  MeshFileError e;
  EXPECT_TRUE(import_mesh(path, MeshImportOptions{triangulate}, &m, &e))
      << path << ":" << e.line << ":" << e.column << ": " << e.message;
  return m;
}

Node build(const MeshProgram& m) {
  Node node;
  for (const auto& c : m.program.commands) node.apply(c);
  return node;
}

class RoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(RoundTrip, ImportExportImportIsTheSameNodeBitForBit) {
  const std::string path = kDir + "/" + GetParam();
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " missing: the MeshCorpus.Extract fixture did not run";
  const MeshProgram first = import_or_fail(path, true);
  ASSERT_GT(first.program.commands.size(), 0u);
  const Node a = build(first);
  const auto obj = std::filesystem::temp_directory_path() / (std::string("vgc_round_trip_") + GetParam() + ".obj");
  std::ofstream(obj, std::ios::binary) << render_obj(extract_mesh(a), GetParam());
  const MeshProgram second = import_or_fail(obj.string());
  std::remove(obj.c_str());
  EXPECT_EQ(second.vertices, first.vertices);
  EXPECT_EQ(second.triangles, first.triangles);
  EXPECT_EQ(second.quads, first.quads);
  EXPECT_TRUE(print_snapshot(build(second)) == print_snapshot(a)) << "the snapshots differ";
}

// Triangles (bunny00: 75k), quads (cube_quad, torus_quad), mixed and n-gons
// (mpi: faces of up to 9 corners, through --triangulate), a PLY and an STL.
INSTANTIATE_TEST_SUITE_P(Corpus, RoundTrip,
                         ::testing::Values("bunny00.off", "cube_quad.off", "torus_quad.off", "mpi.off",
                                           "elephant.off", "sphere.ply", "sphere.stl"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(MeshCorpus, TriangulateKeepsEachSplitFacesCorners) {
  const MeshProgram plain_fail = [] {
    MeshProgram m;
    MeshFileError e;
    EXPECT_FALSE(import_mesh(kDir + "/mpi.off", {}, &m, &e));
    EXPECT_NE(e.message.find("--triangulate"), std::string::npos) << e.message;
    return m;
  }();
  (void)plain_fail;
  const MeshProgram m = import_or_fail(kDir + "/mpi.off", true);
  EXPECT_GT(m.split_faces, 0u);
  // No vertex is added: the triangles use the file's vertices only.
  std::size_t vertices = 0;
  for (const auto& c : m.program.commands) vertices += std::holds_alternative<cmd::VertexSetXyzReal64>(c);
  EXPECT_EQ(vertices, m.vertices);
}

}  // namespace
}  // namespace vgc
