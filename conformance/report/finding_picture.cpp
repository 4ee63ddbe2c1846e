// finding_picture.cpp — see finding_picture.h.
#include "finding_picture.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <type_traits>
#include <variant>

#include "capability_documents.h"
#include "document_diff.h"
#include "mesh_topology.h"
#include "number_text.h"

namespace vgc {
namespace {


bool read_u32(const std::vector<std::string>& w, std::size_t i, std::uint32_t* out) {
  return i < w.size() && parse_uint(w[i], 32, out);
}

bool read_point(const std::vector<std::string>& w, std::size_t i, Point3* out) {
  if (i + 2 >= w.size()) return false;
  for (std::size_t k = 0; k < 3; ++k)
    if (!parse_f64(w[i + k], &(*out)[k])) return false;
  return true;
}

// Index maps of the picture's mesh.
struct Indexed {
  std::map<std::uint32_t, int> vertex, face;
};

// (Past 4096 elements, a user's whole mesh: duplicates are let in and
// removed once at the end, dedupe_highlights, instead of a quadratic scan.)
void add_unique(std::vector<int>* v, int i) {
  if (v->size() >= 4096 || std::find(v->begin(), v->end(), i) == v->end()) v->push_back(i);
}

void dedupe_highlights(MeshPicture* pic) {
  for (std::vector<int>* v : {&pic->highlight_vertices, &pic->highlight_faces})
    if (v->size() >= 4096) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
}

// A picture of a large mesh (a user's, certify --mesh) would be a smear of
// 10^5 faces and megabytes of SVG: it keeps the kPictureFaces faces nearest
// to what the finding is about (the first highlighted element, divergent
// point or mark: one compact patch around the first difference; several
// differences spread over the mesh would make a long strip), with every
// point, mark and segment inside its bounding box, and says so. Returns
// the sentence for the caption.
constexpr std::size_t kLargeMesh = 600, kPictureFaces = 64;

Point3 centroid_of(const MeshPicture& pic, const std::vector<int>& f) {
  Point3 c{0, 0, 0};
  for (int v : f)
    for (int k = 0; k < 3; ++k) c[static_cast<std::size_t>(k)] += pic.positions[static_cast<std::size_t>(v)][static_cast<std::size_t>(k)];
  for (auto& x : c) x /= static_cast<double>(std::max<std::size_t>(1, f.size()));
  return c;
}

// What the finding is about: the first finite point among the highlighted
// vertices, faces (centroid) and edges (first end), the divergent points
// and the marks; none when nothing is highlighted.
std::vector<Point3> finding_focus(const MeshPicture& pic) {
  const std::size_t all_faces = pic.faces.size();
  std::vector<Point3> focus;
  auto add_focus = [&](const Point3& p) {
    if (focus.empty() && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) focus.push_back(p);
  };
  for (int v : pic.highlight_vertices)
    if (v >= 0 && static_cast<std::size_t>(v) < pic.positions.size()) add_focus(pic.positions[static_cast<std::size_t>(v)]);
  for (int f : pic.highlight_faces)
    if (f >= 0 && static_cast<std::size_t>(f) < all_faces) add_focus(centroid_of(pic, pic.faces[static_cast<std::size_t>(f)]));
  for (const auto& [a, b] : pic.highlight_edges)
    if (a >= 0 && static_cast<std::size_t>(a) < pic.positions.size()) add_focus(pic.positions[static_cast<std::size_t>(a)]);
  for (int i : pic.divergent_expected)
    if (i >= 0 && static_cast<std::size_t>(i) < pic.expected_points.size()) add_focus(pic.expected_points[static_cast<std::size_t>(i)]);
  for (int i : pic.divergent_observed)
    if (i >= 0 && static_cast<std::size_t>(i) < pic.observed_points.size()) add_focus(pic.observed_points[static_cast<std::size_t>(i)]);
  for (const auto& p : pic.observed_marks) add_focus(p);
  return focus;
}

// The kPictureFaces faces whose centroids are nearest to the focus, in
// face order.
std::vector<std::size_t> faces_nearest(const MeshPicture& pic, const std::vector<Point3>& focus) {
  const std::size_t all_faces = pic.faces.size();
  std::vector<std::pair<double, std::size_t>> by_distance(all_faces);
  for (std::size_t f = 0; f < all_faces; ++f) {
    const Point3 c = centroid_of(pic, pic.faces[f]);
    double best = HUGE_VAL;
    for (const auto& p : focus) {
      const double dx = c[0] - p[0], dy = c[1] - p[1], dz = c[2] - p[2];
      best = std::min(best, dx * dx + dy * dy + dz * dz);
    }
    by_distance[f] = {std::isfinite(best) ? best : HUGE_VAL, f};
  }
  std::nth_element(by_distance.begin(), by_distance.begin() + static_cast<std::ptrdiff_t>(kPictureFaces - 1),
                   by_distance.end());
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < kPictureFaces; ++i) kept.push_back(by_distance[i].second);
  std::sort(kept.begin(), kept.end());
  return kept;
}

// The kept faces as a picture of their own: their vertices renumbered,
// the maps from the old indices, and the bounding box of what is kept.
struct Patch {
  MeshPicture out;
  std::vector<int> new_index, new_face;
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
};

void keep_faces(const MeshPicture& pic, const std::vector<std::size_t>& kept, Patch* patch) {
  const std::size_t all_faces = pic.faces.size();
  MeshPicture& out = patch->out;
  patch->new_index.assign(pic.positions.size(), -1);
  auto keep_vertex = [&](int v) {
    if (v < 0 || static_cast<std::size_t>(v) >= pic.positions.size()) return -1;
    int& n = patch->new_index[static_cast<std::size_t>(v)];
    if (n < 0) {
      n = static_cast<int>(out.positions.size());
      out.positions.push_back(pic.positions[static_cast<std::size_t>(v)]);
      if (pic.vertex_labels.size() == pic.positions.size()) out.vertex_labels.push_back(pic.vertex_labels[static_cast<std::size_t>(v)]);
      for (int k = 0; k < 3; ++k) {
        patch->lo[k] = std::min(patch->lo[k], out.positions.back()[static_cast<std::size_t>(k)]);
        patch->hi[k] = std::max(patch->hi[k], out.positions.back()[static_cast<std::size_t>(k)]);
      }
    }
    return n;
  };
  patch->new_face.assign(all_faces, -1);
  for (std::size_t f : kept) {
    std::vector<int> face;
    for (int v : pic.faces[f]) face.push_back(keep_vertex(v));
    patch->new_face[f] = static_cast<int>(out.faces.size());
    out.faces.push_back(std::move(face));
    if (pic.face_labels.size() == all_faces) out.face_labels.push_back(pic.face_labels[f]);
  }
}

// The highlighted vertices, faces and edges that the patch keeps.
void keep_highlights(const MeshPicture& pic, Patch* patch) {
  const std::vector<int>& new_index = patch->new_index;
  MeshPicture& out = patch->out;
  for (int v : pic.highlight_vertices)
    if (v >= 0 && static_cast<std::size_t>(v) < new_index.size() && new_index[static_cast<std::size_t>(v)] >= 0)
      out.highlight_vertices.push_back(new_index[static_cast<std::size_t>(v)]);
  for (int f : pic.highlight_faces)
    if (f >= 0 && static_cast<std::size_t>(f) < pic.faces.size() && patch->new_face[static_cast<std::size_t>(f)] >= 0)
      out.highlight_faces.push_back(patch->new_face[static_cast<std::size_t>(f)]);
  for (const auto& [a, b] : pic.highlight_edges) {
    const int na = a >= 0 && static_cast<std::size_t>(a) < new_index.size() ? new_index[static_cast<std::size_t>(a)] : -1;
    const int nb = b >= 0 && static_cast<std::size_t>(b) < new_index.size() ? new_index[static_cast<std::size_t>(b)] : -1;
    if (na >= 0 && nb >= 0) out.highlight_edges.push_back({na, nb});
  }
}

// Refined points and normals: those over the patch. What the
// implementation showed instead (marks, outlines) may lie off the
// surface: half the patch's size around it.
void keep_overlays(const MeshPicture& pic, Patch* patch) {
  MeshPicture& out = patch->out;
  double extent = 0;
  for (int k = 0; k < 3; ++k) extent = std::max(extent, patch->hi[k] - patch->lo[k]);
  auto within = [&](const Point3& p, double pad) {
    for (int k = 0; k < 3; ++k)
      if (!(p[static_cast<std::size_t>(k)] >= patch->lo[k] - pad && p[static_cast<std::size_t>(k)] <= patch->hi[k] + pad))
        return false;
    return true;
  };
  auto inside = [&](const Point3& p) { return within(p, extent * 0.05); };
  auto near = [&](const Point3& p) { return within(p, extent * 0.5); };
  for (const auto& p : pic.observed_marks)
    if (near(p)) out.observed_marks.push_back(p);
  for (const auto& o : pic.observed_outlines)
    if (!o.empty() && near(o.front())) out.observed_outlines.push_back(o);
  auto keep_points = [&](const std::vector<Point3>& from, const std::vector<int>& divergent, std::vector<Point3>* to,
                         std::vector<int>* to_divergent) {
    std::vector<int> index(from.size(), -1);
    for (std::size_t i = 0; i < from.size(); ++i)
      if (inside(from[i])) {
        index[i] = static_cast<int>(to->size());
        to->push_back(from[i]);
      }
    for (int i : divergent)
      if (i >= 0 && static_cast<std::size_t>(i) < from.size() && index[static_cast<std::size_t>(i)] >= 0)
        to_divergent->push_back(index[static_cast<std::size_t>(i)]);
  };
  keep_points(pic.expected_points, pic.divergent_expected, &out.expected_points, &out.divergent_expected);
  keep_points(pic.observed_points, pic.divergent_observed, &out.observed_points, &out.divergent_observed);
  for (const auto& s : pic.expected_segments)
    if (inside(s.first)) out.expected_segments.push_back(s);
  for (const auto& s : pic.observed_segments)
    if (inside(s.first)) out.observed_segments.push_back(s);
}

std::string focus_on_finding(MeshPicture* pic) {
  const std::size_t all_faces = pic->faces.size();
  if (all_faces <= kLargeMesh) return {};
  std::vector<Point3> focus = finding_focus(*pic);
  const bool centred = focus.empty();
  if (centred) {  // the middle of the list, when its centroid is finite
    const Point3 c = centroid_of(*pic, pic->faces[all_faces / 2]);
    if (std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])) focus.push_back(c);
  }
  Patch patch;
  keep_faces(*pic, faces_nearest(*pic, focus), &patch);
  keep_highlights(*pic, &patch);
  keep_overlays(*pic, &patch);
  *pic = std::move(patch.out);
  return " The mesh has " + std::to_string(all_faces) + " polygons: the picture shows the " +
         std::to_string(kPictureFaces) +
         (centred ? " in the middle of the list (nothing is highlighted)"
                  : " nearest to the first thing the finding is about") +
         " and what lies within them; the OBJ file below holds the whole mesh.";
}

// The element a command names: a vertex or a polygon of the final state
// (not found: nothing). Returns a description, empty when it names none.
template <class T> constexpr bool kVertexValue =
    std::is_same_v<T, cmd::VertexSetXyzReal32> || std::is_same_v<T, cmd::VertexSetXyzReal64> ||
    std::is_same_v<T, cmd::VertexSetUint32> || std::is_same_v<T, cmd::VertexSetReal64> ||
    std::is_same_v<T, cmd::VertexSetReal32> || std::is_same_v<T, cmd::VertexDelete>;
template <class T> constexpr bool kPolygonValue =
    std::is_same_v<T, cmd::PolygonSetCornerReal64> || std::is_same_v<T, cmd::PolygonSetCornerReal32> ||
    std::is_same_v<T, cmd::PolygonSetFaceUint8> || std::is_same_v<T, cmd::PolygonSetFaceUint32> ||
    std::is_same_v<T, cmd::PolygonSetFaceReal64> || std::is_same_v<T, cmd::PolygonSetFaceReal32> ||
    std::is_same_v<T, cmd::PolygonDelete>;

std::string highlight_command(const Command& c, const Indexed& ix, MeshPicture* pic) {
  return std::visit(
      [&](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (kVertexValue<T>) {
          auto it = ix.vertex.find(x.vertex_id);
          if (it == ix.vertex.end())
            return "Its last command names vertex " + std::to_string(x.vertex_id) + ", which the final state lacks.";
          add_unique(&pic->highlight_vertices, it->second);
          return "Highlighted: vertex " + std::to_string(x.vertex_id) + ", which the last command names.";
        } else if constexpr (kPolygonValue<T>) {
          auto it = ix.face.find(x.polygon_id);
          if (it == ix.face.end())
            return "Its last command names polygon " + std::to_string(x.polygon_id) + ", which the final state lacks.";
          add_unique(&pic->highlight_faces, it->second);
          return "Highlighted: polygon " + std::to_string(x.polygon_id) + ", which the last command names.";
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetCornerUint32>) {
          auto it = ix.face.find(x.polygon_id);
          if (it != ix.face.end() && x.layer_id == Node::kPolygonLayer) {
            add_unique(&pic->highlight_faces, it->second);
            return "Highlighted: polygon " + std::to_string(x.polygon_id) + ", which the last command sets.";
          }
          std::string named;
          for (std::uint32_t v : x.v) {
            auto vi = ix.vertex.find(v);
            if (vi == ix.vertex.end()) continue;
            add_unique(&pic->highlight_vertices, vi->second);
            named += (named.empty() ? "" : ", ") + std::to_string(v);
          }
          if (named.empty()) return "";
          return "Highlighted: the vertices the last command's corners name (" + named + "); polygon " +
                 std::to_string(x.polygon_id) + " is not in the final state.";
        } else {
          return "";
        }
      },
      c);
}

// A snapshot or derived line's element, highlighted; the implementation's
// version of it marked. Returns the description.
std::string highlight_line(const Finding& f, const Node& model, const MeshArrays& mesh, const Indexed& ix,
                           MeshPicture* pic) {
  const std::vector<std::string> e = split_words(f.expected_line), o = split_words(f.observed_line);
  const std::vector<std::string>& w = e.empty() ? o : e;
  if (w.empty()) return "";
  const std::string& kind = w[0];
  const std::string where = "in the " + f.shown_by + " document";
  std::uint32_t id = 0;
  if (kind == "vertex" || kind == "vertex_crease") {
    if (!read_u32(w, 1, &id)) return "";
    std::string text;
    auto it = ix.vertex.find(id);
    if (it != ix.vertex.end()) {
      add_unique(&pic->highlight_vertices, it->second);
      text = "Highlighted: vertex " + std::to_string(id) + ", whose " + kind + " line differs " + where + ".";
    } else {
      text = "Vertex " + std::to_string(id) + " is not in the final state, but the implementation has it.";
    }
    Point3 seen{};
    if (kind == "vertex" && read_point(o, 2, &seen) &&
        (it == ix.vertex.end() || seen != mesh.positions[static_cast<std::size_t>(it->second)])) {
      pic->observed_marks.push_back(seen);
      text += " The orange cross is where the implementation has it.";
    }
    return text;
  }
  if (kind == "polygon") {
    if (!read_u32(w, 1, &id)) return "";
    std::string text;
    auto it = ix.face.find(id);
    if (it != ix.face.end()) {
      add_unique(&pic->highlight_faces, it->second);
      text = "Highlighted: polygon " + std::to_string(id) + ", whose line differs " + where + ".";
    } else {
      text = "Polygon " + std::to_string(id) + " is not in the final state, but the implementation has it.";
    }
    // The implementation's corners, where they are vertices of the state.
    std::vector<Point3> outline;
    bool all = o.size() >= 6;
    for (std::size_t k = 2; all && k < 6; ++k) {
      std::uint32_t v = 0;
      if (!parse_uint(o[k], 32, &v)) all = false;
      else if (v == kNone32) continue;
      else if (auto vi = ix.vertex.find(v); vi != ix.vertex.end())
        outline.push_back(mesh.positions[static_cast<std::size_t>(vi->second)]);
      else all = false;
    }
    if (all && outline.size() >= 2) {
      pic->observed_outlines.push_back(outline);
      text += " The dashed orange outline is the polygon as the implementation has it.";
    }
    return text;
  }
  if (kind == "slot") {
    std::uint32_t layer = 0;
    if (!read_u32(w, 1, &layer) || !read_u32(w, 2, &id)) return "";
    const Layer* l = model.find_layer(static_cast<std::uint16_t>(layer));
    if (!l) return "";
    const bool vertex_stack = l->type == LayerType::VertexXyz || l->type == LayerType::VertexUint32 ||
                              l->type == LayerType::VertexReal;
    const auto& index = vertex_stack ? ix.vertex : ix.face;
    auto it = index.find(id);
    if (it == index.end()) return "";
    add_unique(vertex_stack ? &pic->highlight_vertices : &pic->highlight_faces, it->second);
    return std::string("Highlighted: ") + (vertex_stack ? "vertex " : "polygon ") + std::to_string(id) +
           ", whose slot in layer " + std::to_string(layer) + " differs " + where + ".";
  }
  if (kind == "edge_crease") {
    std::uint32_t corner = 0;
    if (!read_u32(w, 1, &id) || !read_u32(w, 2, &corner)) return "";
    auto it = ix.face.find(id);
    if (it == ix.face.end()) return "";
    const std::size_t f_i = static_cast<std::size_t>(it->second);
    const int size = mesh.face_sizes[f_i], off = mesh.face_offsets[f_i];
    if (corner >= static_cast<std::uint32_t>(size)) {
      add_unique(&pic->highlight_faces, it->second);
      return "Highlighted: polygon " + std::to_string(id) + ", whose corner " + std::to_string(corner) +
             " the two sides disagree on.";
    }
    const int a = mesh.face_vertices[static_cast<std::size_t>(off + static_cast<int>(corner))];
    const int b = mesh.face_vertices[static_cast<std::size_t>(off + (static_cast<int>(corner) + 1) % size)];
    pic->highlight_edges.emplace_back(a, b);
    return "Highlighted: the edge from corner " + std::to_string(corner) + " of polygon " + std::to_string(id) +
           " (vertices " + std::to_string(mesh.vertex_ids[static_cast<std::size_t>(a)]) + " and " +
           std::to_string(mesh.vertex_ids[static_cast<std::size_t>(b)]) + "), whose effective crease differs.";
  }
  return "The difference is in a \"" + kind + "\" line " + where + ", not an element of the mesh.";
}

// "vertex x y z" lines of a refinement document.
std::vector<Point3> refined_points(const std::string& text) {
  std::vector<Point3> out;
  for (const auto& l : split_lines(text)) {
    const auto w = split_words(l);
    Point3 p{};
    if (w.size() == 4 && w[0] == "vertex" && read_point(w, 1, &p)) out.push_back(p);
  }
  return out;
}

// Pairs each expected point with the nearest unused observed one within
// `tol` (max norm); the unpaired ones on each side are divergent.
void divergent_points(const std::vector<Point3>& want, const std::vector<Point3>& got, double tol,
                      std::vector<int>* want_left, std::vector<int>* got_left) {
  std::vector<std::size_t> order(got.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return got[a][0] < got[b][0]; });
  std::vector<double> xs;
  for (std::size_t i : order) xs.push_back(got[i][0]);
  std::vector<char> used(got.size(), 0);
  for (std::size_t w = 0; w < want.size(); ++w) {
    const Point3& p = want[w];
    std::size_t best = got.size();
    double best_d = tol;
    for (auto it = std::lower_bound(xs.begin(), xs.end(), p[0] - tol); it != xs.end() && *it <= p[0] + tol; ++it) {
      const std::size_t g = order[static_cast<std::size_t>(it - xs.begin())];
      if (used[g]) continue;
      const double d = std::max({std::fabs(got[g][0] - p[0]), std::fabs(got[g][1] - p[1]), std::fabs(got[g][2] - p[2])});
      if (d <= best_d) best = g, best_d = d;
    }
    if (best == got.size()) want_left->push_back(static_cast<int>(w));
    else used[best] = 1;
  }
  for (std::size_t g = 0; g < got.size(); ++g)
    if (!used[g] && std::isfinite(got[g][0]) && std::isfinite(got[g][1]) && std::isfinite(got[g][2]))
      got_left->push_back(static_cast<int>(g));
}

std::string highlight_refinement(const Finding& f, const Node& model, MeshPicture* pic) {
  const auto expected_text = answer_capability_request(model, f.shown_by);
  if (!expected_text || expected_text->rfind("error", 0) == 0)
    return "The reference gives no refinement for \"" + f.shown_by + "\" here, so no points are drawn.";
  pic->expected_points = refined_points(*expected_text);
  pic->observed_points = refined_points(f.observed_document);
  double scale = 1;
  for (const auto& p : pic->expected_points)
    for (double c : p) scale = std::max(scale, std::fabs(c));
  divergent_points(pic->expected_points, pic->observed_points, 1e-9 * scale, &pic->divergent_expected,
                   &pic->divergent_observed);
  return "The answer to \"" + f.shown_by + "\" drawn over the expected refinement (the reference's, which the test " +
         "suite checks against OpenSubdiv): blue rings are expected points, orange dots the answer's. " +
         std::to_string(pic->divergent_expected.size()) + " of " + std::to_string(pic->expected_points.size()) +
         " expected points have no answer point within " + format_f64(1e-9 * scale) + " (magenta rings); " +
         std::to_string(pic->divergent_observed.size()) + " of the answer's " +
         std::to_string(pic->observed_points.size()) + " points match none (orange crosses).";
}

std::string highlight_classify(const Finding& f, const Node& model, const MeshArrays& mesh, MeshPicture* pic) {
  const auto d = diff_documents(print_classify(model), f.observed_document);
  const std::string key = d ? d->kind : std::string();
  const MeshTopology topo = classify_mesh(mesh);
  if (topo.status != MeshStatus::Ok) return "The polygons do not form valid input to the classification.";
  std::string what;
  auto mark_edges = [&](auto pick) {
    int n = 0;
    for (const MeshEdge& e : topo.edges)
      if (pick(e)) pic->highlight_edges.emplace_back(e.a, e.b), ++n;
    return n;
  };
  if (key == "boundary_loops" || key == "closed") {
    const int n = mark_edges([](const MeshEdge& e) { return e.use_count == 1; });
    what = "the " + std::to_string(n) + " boundary edges (one polygon each)";
  } else if (key == "oriented") {
    const int n = mark_edges([](const MeshEdge& e) { return e.use_count == 2 && e.forward_count != 1; });
    what = "the " + std::to_string(n) + " edges whose two polygons run the same way";
  } else if (key == "components") {
    for (std::size_t face = 0; face < topo.face_component.size(); ++face)
      if (topo.face_component[face] > 0) add_unique(&pic->highlight_faces, static_cast<int>(face));
    what = "every component but the first (" + std::to_string(topo.component_count) + " in all)";
  } else {
    const int n = mark_edges([](const MeshEdge& e) {
      return e.use_count != 2 || e.forward_count != 1;
    });
    for (int v : topo.non_manifold_vertices) add_unique(&pic->highlight_vertices, v);
    what = "the " + std::to_string(n) + " edges that are boundary, non-manifold or wrongly oriented, and the " +
           std::to_string(topo.non_manifold_vertices.size()) + " non-manifold vertices";
  }
  return "The answer's \"" + (key.empty() ? std::string("?classify") : key) +
         "\" differs from the expected classification. Highlighted: " + what + ".";
}

std::string highlight_normals(const Finding& f, const Node& model, const MeshArrays& mesh, const Indexed& ix,
                              MeshPicture* pic) {
  const std::string expected_text = print_normals(model);
  // "corner <polygon> <corner> x y z" -> normal.
  auto read = [](const std::string& text) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, Point3> out;
    for (const auto& l : split_lines(text)) {
      const auto w = split_words(l);
      std::uint32_t p = 0, k = 0;
      Point3 n{};
      if (w.size() == 6 && w[0] == "corner" && read_u32(w, 1, &p) && read_u32(w, 2, &k) && read_point(w, 3, &n))
        out[{p, k}] = n;
    }
    return out;
  };
  const auto want = read(expected_text), got = read(f.observed_document);
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& p : mesh.positions)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[static_cast<std::size_t>(k)]), hi[k] = std::max(hi[k], p[static_cast<std::size_t>(k)]);
  double diag = 0;
  for (int k = 0; k < 3; ++k) diag = std::max(diag, hi[k] - lo[k]);
  const double len = diag > 0 ? diag * 0.2 : 1;
  int differing = 0;
  for (const auto& [key, n] : want) {
    auto g = got.find(key);
    const bool same = g != got.end() && std::fabs(g->second[0] - n[0]) <= 1e-9 && std::fabs(g->second[1] - n[1]) <= 1e-9 &&
                      std::fabs(g->second[2] - n[2]) <= 1e-9;
    if (same) continue;
    auto fi = ix.face.find(key.first);
    if (fi == ix.face.end()) continue;
    const std::size_t face = static_cast<std::size_t>(fi->second);
    if (key.second >= static_cast<std::uint32_t>(mesh.face_sizes[face])) continue;
    const int v = mesh.face_vertices[static_cast<std::size_t>(mesh.face_offsets[face]) + key.second];
    const Point3& at = mesh.positions[static_cast<std::size_t>(v)];
    ++differing;
    add_unique(&pic->highlight_vertices, v);
    pic->expected_segments.push_back({at, {at[0] + len * n[0], at[1] + len * n[1], at[2] + len * n[2]}});
    if (g != got.end())
      pic->observed_segments.push_back(
          {at, {at[0] + len * g->second[0], at[1] + len * g->second[1], at[2] + len * g->second[2]}});
  }
  return "?normals: " + std::to_string(differing) + " of " + std::to_string(want.size()) +
         " corners differ from the reference's split normals (spec 003). Highlighted: their vertices, with the " +
         "expected normal in blue and the answer's dashed in orange.";
}

}  // namespace

FindingPicture picture_of_finding(const ClauseOutcome& co) {
  FindingPicture out;
  if (!co.finding) return out;
  Node model;
  for (const Command& c : co.program.commands) model.apply(c);
  out.mesh = extract_mesh(model);
  if (out.mesh.vertex_count() == 0) return out;
  out.has_mesh = true;

  MeshPicture& pic = out.picture;
  Indexed ix;
  pic.positions = out.mesh.positions;
  for (int i = 0; i < out.mesh.vertex_count(); ++i) {
    ix.vertex[out.mesh.vertex_ids[static_cast<std::size_t>(i)]] = i;
    pic.vertex_labels.push_back(std::to_string(out.mesh.vertex_ids[static_cast<std::size_t>(i)]));
  }
  for (int f = 0; f < out.mesh.face_count(); ++f) {
    ix.face[out.mesh.polygon_ids[static_cast<std::size_t>(f)]] = f;
    const int off = out.mesh.face_offsets[static_cast<std::size_t>(f)];
    std::vector<int> face;
    for (int k = 0; k < out.mesh.face_sizes[static_cast<std::size_t>(f)]; ++k)
      face.push_back(out.mesh.face_vertices[static_cast<std::size_t>(off + k)]);
    pic.faces.push_back(std::move(face));
    pic.face_labels.push_back("p" + std::to_string(out.mesh.polygon_ids[static_cast<std::size_t>(f)]));
  }

  const Finding& f = *co.finding;
  std::string what;
  if (co.program.request) {
    if (f.shown_by.empty() || f.observed_document.empty()) {
      what = "The implementation gave no document to draw (" + f.message.substr(0, 200) + ").";
    } else if (f.shown_by.rfind("?classify", 0) == 0) {
      what = highlight_classify(f, model, out.mesh, &pic);
    } else if (f.shown_by.rfind("?normals", 0) == 0) {
      what = highlight_normals(f, model, out.mesh, ix, &pic);
    } else if (f.shown_by.rfind("?subdivide", 0) == 0) {
      what = highlight_refinement(f, model, &pic);
    }
  } else if (!f.expected_line.empty() || !f.observed_line.empty()) {
    what = highlight_line(f, model, out.mesh, ix, &pic);
  } else if (!co.program.commands.empty()) {
    what = highlight_command(co.program.commands.back(), ix, &pic);
  }
  out.highlighted = !pic.highlight_vertices.empty() || !pic.highlight_faces.empty() ||
                    !pic.highlight_edges.empty() || !pic.observed_marks.empty() || !pic.observed_outlines.empty() ||
                    !pic.divergent_expected.empty() || !pic.divergent_observed.empty() ||
                    !pic.observed_segments.empty() || !pic.expected_segments.empty();
  dedupe_highlights(&pic);
  what += focus_on_finding(&pic);
  // Shrinking often leaves every vertex at one point: say so, or the
  // picture (one dot) would look broken.
  bool one_point = out.mesh.vertex_count() > 1;
  for (const auto& p : out.mesh.positions) one_point = one_point && p == out.mesh.positions.front();
  if (one_point) {
    const auto& p = out.mesh.positions.front();
    what += " All " + std::to_string(out.mesh.vertex_count()) + " vertices are at one point (" + format_f64(p[0]) +
            ", " + format_f64(p[1]) + ", " + format_f64(p[2]) + "), so the drawing shows a single point.";
  }
  out.caption = "The final state of the counterexample (the reference's, after its " +
                std::to_string(co.program.commands.size()) + " commands): " + std::to_string(out.mesh.vertex_count()) +
                " vertices, " + std::to_string(out.mesh.face_count()) + " polygons, labelled with their ids. " +
                (what.empty() ? "Nothing in it is what the finding is about." : what);
  return out;
}

}  // namespace vgc
