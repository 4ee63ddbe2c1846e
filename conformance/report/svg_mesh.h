// svg_mesh.h — a drawing of a mesh as SVG, with the part a finding is about
// highlighted, for report.html (report_html.cpp).
//
// Spec: none (reporting). The mesh is a node's live polygons (000 section
// 2.6: 3 or 4 corners referencing vertices); the overlays are the refined
// points of the derived-geometry capabilities (docs/adapters.md section 5).
//
// Rationale: a finding about a shape (a vertex stored wrongly, a face the
// implementation kept, a boundary ?classify missed, a subdivided point in
// the wrong place) is quicker to see than to read. The view is fixed (an
// axonometric projection, z up, seen from azimuth -30 degrees and 40 degrees
// above) and scaled to fit everything drawn, so two pictures of one mesh
// always look the same; faces are painted back to front, a little
// translucent so what is behind shows through. Colours are fixed
// (kHighlightColour etc.) so a test can find them in a screenshot. The SVG
// is built with pugixml, which escapes labels and attributes.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace pugi {
class xml_node;
}

namespace vgc {

using Point3 = std::array<double, 3>;

inline constexpr const char* kHighlightColour = "#e6007e";  // what the finding is about
inline constexpr const char* kObservedColour = "#ff8c00";   // what the implementation showed instead
inline constexpr const char* kExpectedColour = "#1f4e9e";   // expected points (derived geometry)
inline constexpr const char* kCanvasColour = "#fbfbf4";     // the picture's background
inline constexpr const char* kFaceColour = "#cfe3f7";       // faces
inline constexpr const char* kEdgeColour = "#4a6fa5";       // edges

struct MeshPicture {
  // The mesh: points and faces (indices into positions; any that names no
  // point, or a point that is not finite, is left out of the drawing).
  std::vector<Point3> positions;
  std::vector<std::string> vertex_labels;  // empty, or one per position (shown up to 80 points)
  std::vector<std::vector<int>> faces;
  std::vector<std::string> face_labels;    // empty, or one per face (shown at its centre)

  // What the finding is about (kHighlightColour).
  std::vector<int> highlight_vertices;
  std::vector<int> highlight_faces;
  std::vector<std::pair<int, int>> highlight_edges;  // pairs of position indices

  // What the implementation showed instead (kObservedColour): points (a
  // vertex where it has it) and outlines (a polygon as it has it).
  std::vector<Point3> observed_marks;
  std::vector<std::vector<Point3>> observed_outlines;

  // Derived geometry: the expected and the observed refined points drawn
  // over each other; the divergent ones (indices into each list) marked.
  std::vector<Point3> expected_points, observed_points;
  std::vector<int> divergent_expected, divergent_observed;
  // Short segments (normals) from a point: expected ones in
  // kExpectedColour, observed ones in kObservedColour.
  std::vector<std::pair<Point3, Point3>> expected_segments, observed_segments;
};

// The picture as an <svg> element appended to `parent` (width x height
// pixels, a viewBox of the same size). Elements carry classes a reader (or
// a test) can find: "face", "edge", "vertex", "hl-vertex", "hl-face",
// "hl-edge", "observed", "observed-outline", "expected-point",
// "observed-point", "divergent-expected", "divergent-observed",
// "expected-normal", "observed-normal"; highlighted elements also carry
// data-index (the position or face index).
void append_mesh_svg(pugi::xml_node parent, const MeshPicture& picture, int width, int height);

// The same as a standalone SVG document (with the xmlns attribute).
std::string render_mesh_svg(const MeshPicture& picture, int width, int height);

}  // namespace vgc
