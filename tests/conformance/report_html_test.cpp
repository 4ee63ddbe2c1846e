// report_html_test.cpp — report.html and what it draws: the OBJ writer
// (a known mesh gives a known text), the SVG writer (highlighted elements
// present, labels escaped), the picture of a finding for seeded faults
// (the element or points the finding is about are the ones marked), and
// the page itself (self-contained, verdict, coloured clause table, the
// picture, the replay command), written by write_report with the OBJ files.
// The rendering in a real browser is report_browser_test.cpp.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <fstream>
#include <pugixml.hpp>
#include <set>
#include <sstream>

#include "campaign_html.h"
#include "capability_checks.h"
#include "command_text.h"
#include "faulty_implementation.h"
#include "finding_picture.h"
#include "obj_writer.h"
#include "report.h"
#include "runner.h"
#include "svg_mesh.h"
#include "verdict.h"

namespace vgc {
namespace {

namespace fs = std::filesystem;

const bool kRegistered = (register_capability_checks(), true);

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A quad (polygon 7: vertices 10 11 12 13) and a triangle (polygon 9:
// vertices 11 14 12), ids sparse as a node's are.
MeshArrays two_faces() {
  MeshArrays m;
  m.vertex_ids = {10, 11, 12, 13, 14};
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0.25}};
  m.vertex_creases.assign(5, 0);
  m.polygon_ids = {7, 9};
  m.face_sizes = {4, 3};
  m.face_vertices = {0, 1, 2, 3, 1, 4, 2};
  m.corner_edge_creases.assign(7, 0);
  update_face_offsets(m);
  return m;
}

TEST(ObjWriter, AKnownMeshGivesTheExpectedText) {
  const std::string expected =
      "# vgc counterexample X-1\n"
      "# written by vgc: 5 vertices, 2 faces; corners reversed, so the node's clockwise front is OBJ's front\n"
      "o vgc_counterexample_X-1\n"
      "v 0 0 0\n"
      "v 1 0 0\n"
      "v 1 1 0\n"
      "v 0 1 0\n"
      "v 2 0.5 0.25\n"
      "# OBJ vertex index -> node vertex id: 1=10 2=11 3=12 4=13 5=14\n"
      "# polygon 7\n"
      "f 4 3 2 1\n"
      "# polygon 9\n"
      "f 3 5 2\n";
  EXPECT_EQ(render_obj(two_faces(), "vgc counterexample X-1"), expected);
}

TEST(ObjWriter, ClockwiseFrontFacesAreWrittenCounterClockwise) {
  // The node's front side is the clockwise one (000 2.6): seen from +z,
  // corners (0,0) (0,1) (1,1) (1,0) run clockwise, so the front faces +z,
  // and OBJ (front counter-clockwise) must list them reversed.
  MeshArrays m;
  m.vertex_ids = {0, 1, 2, 3};
  m.positions = {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
  m.vertex_creases.assign(4, 0);
  m.polygon_ids = {0};
  m.face_sizes = {4};
  m.face_vertices = {0, 1, 2, 3};
  m.corner_edge_creases.assign(4, 0);
  update_face_offsets(m);
  const std::string obj = render_obj(m, "t");
  const auto f = obj.find("\nf ");
  ASSERT_NE(f, std::string::npos) << obj;
  std::istringstream in(obj.substr(f + 3));
  int a, b, c;
  in >> a >> b >> c;
  // Newell normal of the OBJ order must point to +z (counter-clockwise seen from +z).
  const auto& p = m.positions;
  const auto& pa = p[static_cast<std::size_t>(a - 1)];
  const auto& pb = p[static_cast<std::size_t>(b - 1)];
  const auto& pc = p[static_cast<std::size_t>(c - 1)];
  const double nz = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0]);
  EXPECT_GT(nz, 0) << obj;
}

pugi::xml_document parse_svg(const std::string& svg) {
  pugi::xml_document doc;
  const auto r = doc.load_string(svg.c_str());
  EXPECT_TRUE(r) << r.description() << "\n" << svg;
  return doc;
}

MeshPicture picture_of(const MeshArrays& m) {
  MeshPicture p;
  p.positions = m.positions;
  for (auto id : m.vertex_ids) p.vertex_labels.push_back(std::to_string(id));
  for (int f = 0; f < m.face_count(); ++f) {
    std::vector<int> face;
    for (int k = 0; k < m.face_sizes[static_cast<std::size_t>(f)]; ++k)
      face.push_back(m.face_vertices[static_cast<std::size_t>(m.face_offsets[static_cast<std::size_t>(f)] + k)]);
    p.faces.push_back(face);
  }
  return p;
}

TEST(SvgMesh, TheHighlightedElementsArePresentInTheHighlightColour) {
  MeshPicture p = picture_of(two_faces());
  p.highlight_vertices = {4};
  p.highlight_faces = {1};
  p.highlight_edges = {{0, 1}};
  const auto doc = parse_svg(render_mesh_svg(p, 400, 300));
  EXPECT_EQ(doc.select_nodes("//polygon[@class='face']").size() + doc.select_nodes("//polygon[@class='face hl-face']").size(), 2u);
  const auto v = doc.select_node("//circle[@class='hl-vertex']").node();
  ASSERT_TRUE(v) << "no highlighted vertex";
  EXPECT_STREQ(v.attribute("data-index").value(), "4");
  EXPECT_STREQ(v.attribute("fill").value(), kHighlightColour);
  const auto f = doc.select_node("//polygon[@class='face hl-face']").node();
  ASSERT_TRUE(f) << "no highlighted face";
  EXPECT_STREQ(f.attribute("data-index").value(), "1");
  EXPECT_STREQ(f.attribute("stroke").value(), kHighlightColour);
  const auto e = doc.select_node("//line[@class='hl-edge']").node();
  ASSERT_TRUE(e) << "no highlighted edge";
  EXPECT_STREQ(e.attribute("data-index").value(), "0-1");
  EXPECT_STREQ(e.attribute("stroke").value(), kHighlightColour);
  // Everything drawn lies inside the picture (the view fits the mesh).
  for (const auto& n : doc.select_nodes("//circle")) {
    const double cx = n.node().attribute("cx").as_double(), cy = n.node().attribute("cy").as_double();
    EXPECT_GE(cx, 0);
    EXPECT_LE(cx, 400);
    EXPECT_GE(cy, 0);
    EXPECT_LE(cy, 300);
  }
}

TEST(SvgMesh, NothingHighlightedDrawsNoHighlightAndLabelsAreEscaped) {
  MeshPicture p = picture_of(two_faces());
  p.vertex_labels[0] = "<a&b>";
  const std::string svg = render_mesh_svg(p, 400, 300);
  const auto doc = parse_svg(svg);
  EXPECT_TRUE(doc.select_nodes("//*[contains(@class,'hl-')]").empty()) << svg;
  EXPECT_EQ(svg.find(kHighlightColour), std::string::npos);
  bool found = false;
  for (const auto& t : doc.select_nodes("//text[@class='vertex-label']"))
    found = found || std::string(t.node().child_value()) == "<a&b>";
  EXPECT_TRUE(found) << svg;
}

TEST(SvgMesh, DivergentPointsAreMarkedAndNonFinitePointsLeftOut) {
  MeshPicture p = picture_of(two_faces());
  p.expected_points = {{0.5, 0.5, 0}, {1, 0.5, 0}};
  p.observed_points = {{0.5, 0.5, 0}, {1, 0.7, 0}, {HUGE_VAL, 0, 0}};
  p.divergent_expected = {1};
  p.divergent_observed = {1};
  const auto doc = parse_svg(render_mesh_svg(p, 400, 300));
  EXPECT_EQ(doc.select_nodes("//circle[@class='expected-point']").size(), 2u);
  EXPECT_EQ(doc.select_nodes("//circle[@class='observed-point']").size(), 2u);  // the infinite one is not drawn
  const auto d = doc.select_node("//circle[@class='divergent-expected']").node();
  ASSERT_TRUE(d);
  EXPECT_STREQ(d.attribute("data-index").value(), "1");
  EXPECT_TRUE(doc.select_node("//g[@class='divergent-observed']").node());
}

// One in-process certification of a faulty node, restricted to `clauses`.
RunResult certify_fault(const std::string& fault, const std::string& clauses, int cases = 40) {
  faults::FaultyImplementation impl(faults::find_fault(fault));
  RunOptions o;
  o.seed = 5;
  o.cases = cases;
  o.max_size = 20;
  o.clause_glob = clauses;
  return run_certification(impl, o);
}

const ClauseOutcome* outcome(const RunResult& run, const std::string& id) {
  for (const auto& co : run.clauses)
    if (co.clause->id == id && co.finding) return &co;
  return nullptr;
}

TEST(FindingPicture, ASubdivisionFaultMarksSomeButNotAllRefinedPoints) {
  const RunResult run = certify_fault("subdivision-ignores-creases", "SUBD-CATMARK-1");
  const ClauseOutcome* co = outcome(run, "SUBD-CATMARK-1");
  ASSERT_TRUE(co) << "the fault was not found";
  EXPECT_EQ(co->finding->shown_by.rfind("?subdivide ", 0), 0u) << co->finding->shown_by;
  const FindingPicture fp = picture_of_finding(*co);
  ASSERT_TRUE(fp.has_mesh);
  EXPECT_TRUE(fp.highlighted);
  const MeshPicture& p = fp.picture;
  EXPECT_FALSE(p.expected_points.empty());
  EXPECT_EQ(p.expected_points.size(), p.observed_points.size()) << "ignoring creases moves points, adds none";
  EXPECT_FALSE(p.divergent_expected.empty()) << fp.caption;
  EXPECT_FALSE(p.divergent_observed.empty()) << fp.caption;
  // Creases move only the points near them: most points still agree.
  EXPECT_LT(p.divergent_expected.size(), p.expected_points.size()) << fp.caption;
  // The divergent expected points are not in the answer at all.
  for (int i : p.divergent_expected)
    for (const auto& q : p.observed_points) EXPECT_NE(p.expected_points[static_cast<std::size_t>(i)], q);
}

TEST(FindingPicture, AMissedBoundaryHighlightsExactlyTheBoundaryEdges) {
  const RunResult run = certify_fault("classify-misses-boundary", "MESH-CLASSIFY-1");
  const ClauseOutcome* co = outcome(run, "MESH-CLASSIFY-1");
  ASSERT_TRUE(co) << "the fault was not found";
  const FindingPicture fp = picture_of_finding(*co);
  ASSERT_TRUE(fp.has_mesh);
  const MeshPicture& p = fp.picture;
  // Count, from the faces, the edges used by one face only.
  std::map<std::pair<int, int>, int> uses;
  for (const auto& f : p.faces)
    for (std::size_t k = 0; k < f.size(); ++k) {
      const int a = f[k], b = f[(k + 1) % f.size()];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::set<std::pair<int, int>> boundary;
  for (const auto& [e, n] : uses)
    if (n == 1) boundary.insert(e);
  ASSERT_FALSE(boundary.empty()) << "the counterexample's mesh has no boundary";
  std::set<std::pair<int, int>> highlighted;
  for (const auto& [a, b] : p.highlight_edges) highlighted.insert({std::min(a, b), std::max(a, b)});
  EXPECT_EQ(highlighted, boundary) << fp.caption;
}

TEST(FindingPicture, FlatNormalsDrawExpectedAndObservedNormals) {
  const RunResult run = certify_fault("normals-flat", "NORMALS-SPLIT-1");
  const ClauseOutcome* co = outcome(run, "NORMALS-SPLIT-1");
  ASSERT_TRUE(co) << "the fault was not found";
  const FindingPicture fp = picture_of_finding(*co);
  ASSERT_TRUE(fp.has_mesh);
  EXPECT_FALSE(fp.picture.expected_segments.empty()) << fp.caption;
  EXPECT_EQ(fp.picture.expected_segments.size(), fp.picture.observed_segments.size());
  EXPECT_EQ(fp.picture.highlight_vertices.empty(), false);
}

TEST(FindingPicture, AKeptPolygonIsOutlinedWhereTheImplementationHasIt) {
  const RunResult run = certify_fault("polygon-delete-ignored", "POLY-*", 60);
  const ClauseOutcome* co = outcome(run, "POLY-DELETE-1");
  ASSERT_TRUE(co) << "the fault was not found";
  const FindingPicture fp = picture_of_finding(*co);
  ASSERT_TRUE(fp.has_mesh) << co->finding->message;
  // The snapshot shows a polygon line the reference lacks: drawn as the
  // implementation has it, over the final state.
  EXPECT_EQ(co->finding->shown_by, "snapshot");
  EXPECT_TRUE(co->finding->expected_line.empty()) << co->finding->expected_line;
  EXPECT_EQ(co->finding->observed_line.rfind("polygon ", 0), 0u) << co->finding->observed_line;
  EXPECT_EQ(fp.picture.observed_outlines.size(), 1u) << fp.caption;
}

TEST(FindingPicture, AMovedVertexIsHighlightedAndItsObservedPlaceMarked) {
  // A finding in a "vertex" line: the vertex highlighted, the
  // implementation's position marked (built by hand: no fault moves one).
  ClauseOutcome co;
  co.clause = find_clause("VERTEX-SET-1");
  TextError e;
  ASSERT_TRUE(parse_commands("vertex_set_xyz_real64 0 4 1 2 3\nvertex_set_xyz_real64 0 5 2 2 3\n"
                             "vertex_set_xyz_real64 0 6 1 3 3\npolygon_set_corner_uint32 1 0 4 5 6 0xFFFFFFFF\n",
                             &co.program.commands, &e))
      << e.to_string();
  Finding f{"VERTEX-SET-1", FindingStatus::Fail, "moved"};
  f.shown_by = "snapshot";
  f.expected_line = "vertex 5 2 2 3";
  f.observed_line = "vertex 5 2 2 4";
  co.finding = f;
  const FindingPicture fp = picture_of_finding(co);
  ASSERT_TRUE(fp.has_mesh);
  ASSERT_EQ(fp.picture.highlight_vertices.size(), 1u);
  EXPECT_EQ(fp.mesh.vertex_ids[static_cast<std::size_t>(fp.picture.highlight_vertices[0])], 5u);
  ASSERT_EQ(fp.picture.observed_marks.size(), 1u);
  EXPECT_EQ(fp.picture.observed_marks[0], (Point3{2, 2, 4}));
}

TEST(FindingPicture, ALargeMeshIsCroppedToThePatchAroundTheFinding) {
  // A user's mesh (certify --mesh): a 40x40 grid of quads, 1,600 polygons,
  // with vertex 820 (row 20, column 20) moved. The picture keeps a small
  // patch around it, labelled, instead of a smear of the whole mesh, and
  // says so; the OBJ (fp.mesh) keeps everything.
  ClauseOutcome co;
  co.clause = find_clause("VERTEX-SET-1");
  std::string text;
  for (int j = 0; j <= 40; ++j)
    for (int i = 0; i <= 40; ++i) text += "vertex_set_xyz_real64 0 " + std::to_string(j * 41 + i) + " " +
                                          std::to_string(i) + " " + std::to_string(j) + " 0\n";
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) {
      const int a = j * 41 + i;
      text += "polygon_set_corner_uint32 1 " + std::to_string(j * 40 + i) + " " + std::to_string(a) + " " +
              std::to_string(a + 41) + " " + std::to_string(a + 42) + " " + std::to_string(a + 1) + "\n";
    }
  TextError e;
  ASSERT_TRUE(parse_commands(text, &co.program.commands, &e)) << e.to_string();
  Finding f{"VERTEX-SET-1", FindingStatus::Fail, "moved"};
  f.shown_by = "snapshot";
  f.expected_line = "vertex 840 20 20 0";
  f.observed_line = "vertex 840 20 20 1";
  co.finding = f;
  const FindingPicture fp = picture_of_finding(co);
  ASSERT_TRUE(fp.has_mesh);
  EXPECT_EQ(fp.mesh.face_count(), 1600);
  EXPECT_LE(fp.picture.faces.size(), 100u) << "the picture draws the whole mesh";
  EXPECT_GE(fp.picture.faces.size(), 16u);
  ASSERT_EQ(fp.picture.highlight_vertices.size(), 1u);
  ASSERT_EQ(fp.picture.vertex_labels.size(), fp.picture.positions.size());
  EXPECT_EQ(fp.picture.vertex_labels[static_cast<std::size_t>(fp.picture.highlight_vertices[0])], "840");
  EXPECT_EQ(fp.picture.observed_marks.size(), 1u);
  for (const auto& p : fp.picture.positions) EXPECT_LE(std::hypot(p[0] - 20, p[1] - 20), 8.0);
  EXPECT_NE(fp.caption.find("The mesh has 1600 polygons"), std::string::npos) << fp.caption;
  const std::string svg = render_mesh_svg(fp.picture, 600, 450);
  EXPECT_LT(svg.size(), 100000u);
}

TEST(FindingPicture, VerticesAllAtOnePointAreSaidToBe) {
  ClauseOutcome co;
  co.clause = find_clause("POLY-DELETE-1");
  TextError e;
  ASSERT_TRUE(parse_commands("vertex_set_xyz_real32 0 0 -4 -4 -4\nvertex_set_xyz_real32 0 1 -4 -4 -4\n", &co.program.commands,
                             &e));
  co.finding = Finding{"POLY-DELETE-1", FindingStatus::Fail, "x"};
  EXPECT_NE(picture_of_finding(co).caption.find("All 2 vertices are at one point (-4, -4, -4)"), std::string::npos)
      << picture_of_finding(co).caption;
  std::vector<Command> more;
  ASSERT_TRUE(parse_commands("vertex_set_xyz_real32 0 2 -4 -4 -3\n", &more, &e));
  co.program.commands.push_back(more.front());  // a third vertex elsewhere
  EXPECT_EQ(picture_of_finding(co).caption.find("at one point"), std::string::npos);
}

// The page's <body> as XML (the page is HTML5; its body is written as
// well-formed XML by pugixml).
pugi::xml_document page_body(const std::string& html) {
  pugi::xml_document doc;
  const auto a = html.find("<body"), b = html.find("</body>");
  EXPECT_NE(a, std::string::npos);
  EXPECT_NE(b, std::string::npos);
  if (a == std::string::npos || b == std::string::npos) return doc;
  const auto r = doc.load_string(html.substr(a, b + 7 - a).c_str());
  EXPECT_TRUE(r) << r.description();
  return doc;
}

TEST(ReportHtml, WriteReportWritesASelfContainedPageAndTheObjFiles) {
  setenv("VGC_FAULT", "subdivision-ignores-creases", 1);
  const RunResult run = certify_fault("subdivision-ignores-creases", "SUBD-CATMARK-1,LAYER-BASE-*");
  const Verdict v = judge(run, nullptr);
  ASSERT_EQ(v.name, "not-conformant");
  const fs::path root = fs::temp_directory_path() / ("vgc_report_html_test_" + std::to_string(::getpid()));
  fs::remove_all(root);
  ReportContext ctx;
  ctx.implementation_spec = "plugin:libfault.so";
  ctx.command_line = "vgc certify --impl plugin:libfault.so";
  ctx.started = "2026-01-02T03:04:05Z";
  ctx.run_dir = default_run_dir(root.string(), run, ctx);
  std::string error;
  ASSERT_TRUE(write_report(root.string(), run, v, ctx, &error)) << error;
  unsetenv("VGC_FAULT");
  const fs::path dir = ctx.run_dir;
  const std::string html = read(dir / "report.html");
  ASSERT_FALSE(html.empty());
  // Self-contained: nothing to fetch, no script.
  for (const char* banned : {"src=", "<script", "<link", "url(", "@import", "http://", "https://"})
    EXPECT_EQ(html.find(banned), std::string::npos) << banned;
  EXPECT_NE(html.find("Content-Security-Policy"), std::string::npos);
  const auto doc = page_body(html);
  EXPECT_STREQ(doc.select_node("//h1/span[@class='verdict not-conformant']").node().child_value(), "NOT CONFORMANT");
  // The clause table: the failing clause in the fail colour, the others passing.
  const auto row = doc.select_node("//table[@class='clauses']/tr[td/a='SUBD-CATMARK-1']").node();
  ASSERT_TRUE(row);
  EXPECT_TRUE(row.select_node("td/span[@class='st st-fail']").node());
  EXPECT_TRUE(doc.select_node("//table[@class='clauses']/tr[td='LAYER-BASE-1']/td/span[@class='st st-pass']").node());
  // The failure: spec sentence, reading, observed, picture with divergent points, commands, replay with env.
  const auto sec = doc.select_node("//section[@id='finding-SUBD-CATMARK-1']").node();
  ASSERT_TRUE(sec);
  EXPECT_TRUE(sec.child("blockquote"));
  EXPECT_TRUE(sec.select_node(".//svg[@class='mesh']//circle[@class='divergent-expected']").node());
  EXPECT_TRUE(sec.select_node(".//a[@href='counterexamples/SUBD-CATMARK-1.obj']").node());
  const std::string replay = sec.select_node(".//pre[@class='replay']").node().child_value();
  EXPECT_EQ(replay.rfind("VGC_FAULT='subdivision-ignores-creases' ./vgc replay ", 0), 0u) << replay;
  EXPECT_NE(std::string(sec.select_node(".//pre[@class='program']").node().child_value()).find("#! capability"),
            std::string::npos);
  // The OBJ file: the final mesh's vertices and faces.
  const std::string obj = read(dir / "counterexamples" / "SUBD-CATMARK-1.obj");
  const FindingPicture fp = picture_of_finding(*outcome(run, "SUBD-CATMARK-1"));
  std::istringstream in(obj);
  std::string line;
  int vs = 0, fs_ = 0;
  while (std::getline(in, line)) vs += line.rfind("v ", 0) == 0, fs_ += line.rfind("f ", 0) == 0;
  EXPECT_EQ(vs, fp.mesh.vertex_count());
  EXPECT_EQ(fs_, fp.mesh.face_count());
  EXPECT_GT(fs_, 0);
  fs::remove_all(root);
}

// The points of a plot's polyline, "x,y x,y ...".
std::vector<std::pair<double, double>> polyline_points(const pugi::xml_node& svg) {
  std::vector<std::pair<double, double>> out;
  std::istringstream in(svg.select_node(".//polyline[@class='series']").node().attribute("points").value());
  std::string xy;
  while (in >> xy) out.emplace_back(std::stod(xy.substr(0, xy.find(','))), std::stod(xy.substr(xy.find(',') + 1)));
  return out;
}

TEST(CampaignHtml, CoverageAndCorpusArePlottedOverTimeAndFindingsListed) {
  CampaignReport r;
  r.target = "fuzz_differential";
  r.run = "20260101T000000Z-seed1";
  r.implementation = "reference";
  r.command = "fuzz_differential -seed=1 <corpus>";
  // Coverage rises then stays; corpus grows steadily.
  for (int i = 0; i <= 10; ++i) r.samples.push_back({i * 1.0, i * 100LL, std::min(i, 5) * 20LL, i * 30LL, i * 3LL});
  CampaignFinding f;
  f.signature = "differential: BONE-FOREST-1 <cycle> & more";
  f.inputs = 2;
  f.counterexample = "counterexamples/crash-1.vgc";
  f.counterexample_text = "bone_create 1 \"w\" \"\" 1 0 0 0 \"\" 0 0 0 1 \"\"\n";
  f.replay = "vgc apply counterexamples/crash-1.vgc";
  f.replay_fuzzer = "fuzz_differential crash-abc";
  r.findings.push_back(f);
  const std::string html = render_campaign_html(r);
  for (const char* banned : {"src=", "<script", "<link", "url(", "http://", "https://"})
    EXPECT_EQ(html.find(banned), std::string::npos) << banned;
  const auto doc = page_body(html);
  const auto cov = doc.select_node("//svg[@class='plot coverage']").node();
  const auto corp = doc.select_node("//svg[@class='plot corpus']").node();
  ASSERT_TRUE(cov);
  ASSERT_TRUE(corp);
  const auto c = polyline_points(cov), k = polyline_points(corp);
  ASSERT_EQ(c.size(), 11u);
  ASSERT_EQ(k.size(), 11u);
  // Time runs left to right; the coverage line is flat after 5 s, the corpus line keeps rising (y down).
  for (std::size_t i = 1; i < c.size(); ++i) EXPECT_GT(c[i].first, c[i - 1].first);
  EXPECT_LT(c[5].second, c[0].second);
  EXPECT_EQ(c[10].second, c[5].second);
  EXPECT_LT(k[10].second, k[5].second);
  // The finding: its signature (escaped by the writer, read back intact) and its replay command.
  EXPECT_STREQ(doc.select_node("//section[@class='finding']/h3").node().child_value(), f.signature.c_str());
  EXPECT_TRUE(doc.select_node("//pre[@class='replay'][.='vgc apply counterexamples/crash-1.vgc']").node());
  EXPECT_STREQ(doc.select_node("//h1/span").node().child_value(), "1 FINDING");
}

TEST(CampaignHtml, TheImplementationsOwnCoverageIsARowAndAPlot) {
  CampaignReport r;
  for (int i = 0; i <= 10; ++i) r.samples.push_back({i * 1.0, i * 100LL, 50, 60, 7});
  const auto without = page_body(render_campaign_html(r));
  EXPECT_FALSE(without.select_node("//svg[@class='plot implementation']").node());
  EXPECT_FALSE(without.select_node("//th[.='implementation coverage']").node());
  r.implementation_coverage = "599 of 941 counters reached (63.7 %), 26 of 27 functions entered; guiding libFuzzer by edges";
  for (int i = 0; i <= 4; ++i) r.implementation_samples.push_back({i * 2.0, 0, 300 + i * 50LL, 0, 0});
  const auto doc = page_body(render_campaign_html(r));
  EXPECT_TRUE(doc.select_node(
      "//tr[th='implementation coverage']/td[starts-with(., '599 of 941 counters reached')]").node());
  const auto impl = polyline_points(doc.select_node("//svg[@class='plot implementation']").node());
  ASSERT_EQ(impl.size(), 5u);
  EXPECT_LT(impl[4].second, impl[0].second);  // rising (y down)
}

TEST(CampaignHtml, ALongCampaignIsThinnedToAThousandPointsKeepingTheLast) {
  CampaignReport r;
  for (int i = 0; i < 5000; ++i) r.samples.push_back({i * 0.1, i, i, i, i == 4999 ? 1'000'000 : i});
  const auto doc = page_body(render_campaign_html(r));
  const auto k = polyline_points(doc.select_node("//svg[@class='plot corpus']").node());
  EXPECT_EQ(k.size(), 1000u);
  ASSERT_FALSE(k.empty());
  // The last sample (the highest corpus) is the top of the plot.
  for (const auto& pt : k) EXPECT_GE(pt.second, k.back().second);
}

TEST(CampaignHtml, WrittenWholeNextToTheSummary) {
  const fs::path dir = fs::temp_directory_path() / ("vgc_campaign_html_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  CampaignReport r;
  r.target = "fuzz_text";
  std::string error;
  ASSERT_TRUE(write_campaign_html(dir.string(), r, &error)) << error;
  EXPECT_NE(read(dir / "report.html").find("NOTHING FOUND"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / ".report.html.partial"));
  fs::remove_all(dir);
  // A directory that does not exist: an error, no file.
  EXPECT_FALSE(write_campaign_html((dir / "missing").string(), r, &error));
  EXPECT_NE(error.find("cannot write"), std::string::npos) << error;
}

}  // namespace
}  // namespace vgc
