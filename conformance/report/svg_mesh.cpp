// svg_mesh.cpp — see svg_mesh.h.
#include "svg_mesh.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>

namespace vgc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kAzimuth = -30 * kPi / 180;
constexpr double kElevation = 40 * kPi / 180;
constexpr double kMargin = 24;
constexpr std::size_t kMaxLabels = 80;

bool finite(const Point3& p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

struct Projected {
  double x = 0, up = 0, depth = 0;
};

Projected project(const Point3& p) {
  const double x1 = p[0] * std::cos(kAzimuth) - p[1] * std::sin(kAzimuth);
  const double y1 = p[0] * std::sin(kAzimuth) + p[1] * std::cos(kAzimuth);
  return {x1, y1 * std::sin(kElevation) + p[2] * std::cos(kElevation),
          y1 * std::cos(kElevation) - p[2] * std::sin(kElevation)};
}

// Model space to picture pixels: the projection scaled to fit the points
// given to fit(), centred.
class View {
 public:
  View(int width, int height) : width_(width), height_(height) {}
  void fit(const Point3& p) {
    if (!finite(p)) return;
    const Projected q = project(p);
    if (!std::isfinite(q.x) || !std::isfinite(q.up)) return;
    lo_x_ = std::min(lo_x_, q.x), hi_x_ = std::max(hi_x_, q.x);
    lo_y_ = std::min(lo_y_, q.up), hi_y_ = std::max(hi_y_, q.up);
    any_ = true;
  }
  void finish() {
    if (!any_) lo_x_ = hi_x_ = lo_y_ = hi_y_ = 0;
    const double w = hi_x_ - lo_x_, h = hi_y_ - lo_y_;
    const double sx = w > 0 ? (width_ - 2 * kMargin) / w : HUGE_VAL;
    const double sy = h > 0 ? (height_ - 2 * kMargin) / h : HUGE_VAL;
    scale_ = std::min(sx, sy);
    if (!std::isfinite(scale_) || scale_ <= 0) scale_ = 1;
    cx_ = (lo_x_ + hi_x_) / 2, cy_ = (lo_y_ + hi_y_) / 2;
  }
  // Pixels; false when the point cannot be drawn.
  bool at(const Point3& p, double* x, double* y) const {
    if (!finite(p)) return false;
    const Projected q = project(p);
    *x = width_ / 2.0 + (q.x - cx_) * scale_;
    *y = height_ / 2.0 - (q.up - cy_) * scale_;
    return std::isfinite(*x) && std::isfinite(*y);
  }

 private:
  int width_, height_;
  double lo_x_ = HUGE_VAL, hi_x_ = -HUGE_VAL, lo_y_ = HUGE_VAL, hi_y_ = -HUGE_VAL;
  double scale_ = 1, cx_ = 0, cy_ = 0;
  bool any_ = false;
};

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

pugi::xml_node element(pugi::xml_node parent, const char* name, const char* cls) {
  auto e = parent.append_child(name);
  if (cls) e.append_attribute("class") = cls;
  return e;
}

void circle(pugi::xml_node parent, const char* cls, double x, double y, double r, const char* fill,
            const char* stroke, double stroke_width) {
  auto c = element(parent, "circle", cls);
  c.append_attribute("cx") = num(x).c_str();
  c.append_attribute("cy") = num(y).c_str();
  c.append_attribute("r") = num(r).c_str();
  c.append_attribute("fill") = fill;
  if (stroke) {
    c.append_attribute("stroke") = stroke;
    c.append_attribute("stroke-width") = num(stroke_width).c_str();
  }
}

void line(pugi::xml_node parent, const char* cls, double x1, double y1, double x2, double y2, const char* stroke,
          double width, const char* dash = nullptr) {
  auto l = element(parent, "line", cls);
  l.append_attribute("x1") = num(x1).c_str();
  l.append_attribute("y1") = num(y1).c_str();
  l.append_attribute("x2") = num(x2).c_str();
  l.append_attribute("y2") = num(y2).c_str();
  l.append_attribute("stroke") = stroke;
  l.append_attribute("stroke-width") = num(width).c_str();
  l.append_attribute("stroke-linecap") = "round";
  if (dash) l.append_attribute("stroke-dasharray") = dash;
}

void cross(pugi::xml_node parent, const char* cls, double x, double y, double r, const char* stroke) {
  auto g = element(parent, "g", cls);
  line(g, nullptr, x - r, y - r, x + r, y + r, stroke, 3);
  line(g, nullptr, x - r, y + r, x + r, y - r, stroke, 3);
}

// "x,y x,y ..." of the points; false if one cannot be drawn.
bool points_attr(const View& view, const std::vector<Point3>& pts, std::string* out) {
  out->clear();
  for (const auto& p : pts) {
    double x = 0, y = 0;
    if (!view.at(p, &x, &y)) return false;
    *out += (out->empty() ? "" : " ") + num(x) + "," + num(y);
  }
  return !pts.empty();
}

bool valid_index(const MeshPicture& pic, int i) {
  return i >= 0 && static_cast<std::size_t>(i) < pic.positions.size() && finite(pic.positions[static_cast<std::size_t>(i)]);
}

// append_mesh_svg's steps, in drawing order (later ones on top).

// The vertices drawn: the faces' (or every one when there is no face), the
// highlighted ones and the ends of highlighted edges.
std::vector<char> drawn_vertices(const MeshPicture& pic) {
  std::vector<char> used(pic.positions.size(), 0);
  for (const auto& f : pic.faces)
    for (int i : f)
      if (valid_index(pic, i)) used[static_cast<std::size_t>(i)] = 1;
  for (int i : pic.highlight_vertices)
    if (valid_index(pic, i)) used[static_cast<std::size_t>(i)] = 1;
  for (const auto& [a, b] : pic.highlight_edges)
    for (int i : {a, b})
      if (valid_index(pic, i)) used[static_cast<std::size_t>(i)] = 1;
  if (pic.faces.empty()) std::fill(used.begin(), used.end(), 1);
  return used;
}

// Fit what is drawn: the drawn vertices, the highlights, and the overlays.
View fitted_view(const MeshPicture& pic, const std::vector<char>& used, int width, int height) {
  View view(width, height);
  for (std::size_t i = 0; i < used.size(); ++i)
    if (used[i]) view.fit(pic.positions[i]);
  for (const auto& p : pic.observed_marks) view.fit(p);
  for (const auto& o : pic.observed_outlines)
    for (const auto& p : o) view.fit(p);
  for (const auto& p : pic.expected_points) view.fit(p);
  for (const auto& p : pic.observed_points) view.fit(p);
  for (const auto* segs : {&pic.expected_segments, &pic.observed_segments})
    for (const auto& [a, b] : *segs) view.fit(a), view.fit(b);
  view.finish();
  return view;
}

// The <svg> element and its canvas.
pugi::xml_node append_canvas(pugi::xml_node parent, int width, int height) {
  auto svg = parent.append_child("svg");
  svg.append_attribute("width") = width;
  svg.append_attribute("height") = height;
  svg.append_attribute("viewBox") = ("0 0 " + std::to_string(width) + " " + std::to_string(height)).c_str();
  svg.append_attribute("class") = "mesh";
  svg.append_attribute("role") = "img";
  auto bg = element(svg, "rect", "canvas");
  bg.append_attribute("width") = width;
  bg.append_attribute("height") = height;
  bg.append_attribute("fill") = kCanvasColour;
  return svg;
}

// The drawable faces, back to front (mean depth of their corners).
std::vector<std::size_t> faces_back_to_front(const MeshPicture& pic) {
  std::vector<std::size_t> order;
  std::vector<double> depth(pic.faces.size(), 0);
  for (std::size_t f = 0; f < pic.faces.size(); ++f) {
    bool ok = pic.faces[f].size() >= 2;
    for (int i : pic.faces[f]) ok = ok && valid_index(pic, i);
    if (!ok) continue;
    for (int i : pic.faces[f]) depth[f] += project(pic.positions[static_cast<std::size_t>(i)]).depth;
    depth[f] /= static_cast<double>(pic.faces[f].size());
    order.push_back(f);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });
  return order;
}

void draw_faces(pugi::xml_node svg, const MeshPicture& pic, const View& view, const std::vector<std::size_t>& order) {
  auto faces = element(svg, "g", "faces");
  for (std::size_t f : order) {
    std::vector<Point3> pts;
    for (int i : pic.faces[f]) pts.push_back(pic.positions[static_cast<std::size_t>(i)]);
    std::string attr;
    if (!points_attr(view, pts, &attr)) continue;
    const bool hl = std::find(pic.highlight_faces.begin(), pic.highlight_faces.end(), static_cast<int>(f)) !=
                    pic.highlight_faces.end();
    auto poly = element(faces, "polygon", hl ? "face hl-face" : "face");
    poly.append_attribute("points") = attr.c_str();
    poly.append_attribute("fill") = hl ? "#f5a3cf" : kFaceColour;
    poly.append_attribute("stroke") = hl ? kHighlightColour : kEdgeColour;
    poly.append_attribute("stroke-width") = hl ? "3" : "1.2";
    poly.append_attribute("fill-opacity") = "0.8";
    poly.append_attribute("stroke-linejoin") = "round";
    if (hl) poly.append_attribute("data-index") = static_cast<int>(f);
  }
}

// Edges the finding is about, over the faces.
void draw_highlighted_edges(pugi::xml_node svg, const MeshPicture& pic, const View& view) {
  auto hl_edges = element(svg, "g", "highlighted-edges");
  for (const auto& [a, b] : pic.highlight_edges) {
    double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
    if (!valid_index(pic, a) || !valid_index(pic, b)) continue;
    if (!view.at(pic.positions[static_cast<std::size_t>(a)], &x1, &y1) ||
        !view.at(pic.positions[static_cast<std::size_t>(b)], &x2, &y2))
      continue;
    line(hl_edges, "hl-edge", x1, y1, x2, y2, kHighlightColour, 5);
    hl_edges.last_child().append_attribute("data-index") = (std::to_string(a) + "-" + std::to_string(b)).c_str();
  }
}

// Vertices (those faces use, or all when there is no face).
void draw_vertices(pugi::xml_node svg, const MeshPicture& pic, const View& view, const std::vector<char>& used) {
  auto verts = element(svg, "g", "vertices");
  for (std::size_t i = 0; i < pic.positions.size(); ++i) {
    double x = 0, y = 0;
    if (!used[i] || !view.at(pic.positions[i], &x, &y)) continue;
    circle(verts, "vertex", x, y, 2.5, kEdgeColour, nullptr, 0);
  }
}

// Expected and observed refined points and normals.
void draw_refined_points(pugi::xml_node overlay, const MeshPicture& pic, const View& view) {
  for (const auto& p : pic.expected_points) {
    double x = 0, y = 0;
    if (view.at(p, &x, &y)) circle(overlay, "expected-point", x, y, 4, "none", kExpectedColour, 1.5);
  }
  for (const auto& p : pic.observed_points) {
    double x = 0, y = 0;
    if (view.at(p, &x, &y)) circle(overlay, "observed-point", x, y, 2.2, kObservedColour, nullptr, 0);
  }
  for (const auto& [a, b] : pic.expected_segments) {
    double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
    if (view.at(a, &x1, &y1) && view.at(b, &x2, &y2))
      line(overlay, "expected-normal", x1, y1, x2, y2, kExpectedColour, 2.5);
  }
  for (const auto& [a, b] : pic.observed_segments) {
    double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
    if (view.at(a, &x1, &y1) && view.at(b, &x2, &y2))
      line(overlay, "observed-normal", x1, y1, x2, y2, kObservedColour, 2.5, "5 3");
  }
}

// The divergent ones among the refined points: a ring on the expected, a
// cross on the observed.
void draw_divergent_points(pugi::xml_node overlay, const MeshPicture& pic, const View& view) {
  for (int i : pic.divergent_expected) {
    double x = 0, y = 0;
    if (i < 0 || static_cast<std::size_t>(i) >= pic.expected_points.size()) continue;
    if (!view.at(pic.expected_points[static_cast<std::size_t>(i)], &x, &y)) continue;
    circle(overlay, "divergent-expected", x, y, 8, "none", kHighlightColour, 3);
    overlay.last_child().append_attribute("data-index") = i;
  }
  for (int i : pic.divergent_observed) {
    double x = 0, y = 0;
    if (i < 0 || static_cast<std::size_t>(i) >= pic.observed_points.size()) continue;
    if (!view.at(pic.observed_points[static_cast<std::size_t>(i)], &x, &y)) continue;
    cross(overlay, "divergent-observed", x, y, 5, kObservedColour);
    overlay.last_child().append_attribute("data-index") = i;
  }
}

// What the implementation showed instead: dashed outlines and crosses.
void draw_observed_shapes(pugi::xml_node overlay, const MeshPicture& pic, const View& view) {
  for (const auto& o : pic.observed_outlines) {
    std::vector<Point3> closed = o;
    if (!closed.empty()) closed.push_back(closed.front());
    std::string attr;
    if (!points_attr(view, closed, &attr)) continue;
    auto pl = element(overlay, "polyline", "observed-outline");
    pl.append_attribute("points") = attr.c_str();
    pl.append_attribute("fill") = "none";
    pl.append_attribute("stroke") = kObservedColour;
    pl.append_attribute("stroke-width") = "3";
    pl.append_attribute("stroke-dasharray") = "8 5";
  }
  for (const auto& p : pic.observed_marks) {
    double x = 0, y = 0;
    if (view.at(p, &x, &y)) cross(overlay, "observed", x, y, 7, kObservedColour);
  }
}

// Highlighted vertices on top.
void draw_highlighted_vertices(pugi::xml_node overlay, const MeshPicture& pic, const View& view) {
  for (int i : pic.highlight_vertices) {
    double x = 0, y = 0;
    if (!valid_index(pic, i) || !view.at(pic.positions[static_cast<std::size_t>(i)], &x, &y)) continue;
    circle(overlay, "hl-vertex", x, y, 7, kHighlightColour, "#ffffff", 1.5);
    overlay.last_child().append_attribute("data-index") = i;
  }
}

// Labels: vertex ids (few enough to read), face ids at face centres.
void draw_labels(pugi::xml_node svg, const MeshPicture& pic, const View& view, const std::vector<char>& used,
                 const std::vector<std::size_t>& order) {
  auto labels = element(svg, "g", "labels");
  labels.append_attribute("font-family") = "sans-serif";
  labels.append_attribute("font-size") = "11";
  labels.append_attribute("fill") = "#222222";
  const std::size_t shown = static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  if (pic.vertex_labels.size() == pic.positions.size() && shown <= kMaxLabels)
    for (std::size_t i = 0; i < pic.positions.size(); ++i) {
      double x = 0, y = 0;
      if (!used[i] || !view.at(pic.positions[i], &x, &y)) continue;
      auto t = element(labels, "text", "vertex-label");
      t.append_attribute("x") = num(x + 5).c_str();
      t.append_attribute("y") = num(y - 5).c_str();
      t.text().set(pic.vertex_labels[i].c_str());
    }
  if (pic.face_labels.size() == pic.faces.size() && order.size() <= kMaxLabels)
    for (std::size_t f : order) {
      double sx = 0, sy = 0;
      bool ok = true;
      for (int i : pic.faces[f]) {
        double x = 0, y = 0;
        ok = ok && view.at(pic.positions[static_cast<std::size_t>(i)], &x, &y);
        sx += x, sy += y;
      }
      if (!ok) continue;
      auto t = element(labels, "text", "face-label");
      t.append_attribute("x") = num(sx / static_cast<double>(pic.faces[f].size())).c_str();
      t.append_attribute("y") = num(sy / static_cast<double>(pic.faces[f].size())).c_str();
      t.append_attribute("fill") = "#6b6b6b";
      t.append_attribute("text-anchor") = "middle";
      t.text().set(pic.face_labels[f].c_str());
    }
}

}  // namespace

void append_mesh_svg(pugi::xml_node parent, const MeshPicture& pic, int width, int height) {
  const std::vector<char> used = drawn_vertices(pic);
  const View view = fitted_view(pic, used, width, height);
  auto svg = append_canvas(parent, width, height);
  const std::vector<std::size_t> order = faces_back_to_front(pic);
  draw_faces(svg, pic, view, order);
  draw_highlighted_edges(svg, pic, view);
  draw_vertices(svg, pic, view, used);
  auto overlay = element(svg, "g", "overlay");
  draw_refined_points(overlay, pic, view);
  draw_divergent_points(overlay, pic, view);
  draw_observed_shapes(overlay, pic, view);
  draw_highlighted_vertices(overlay, pic, view);
  draw_labels(svg, pic, view, used, order);
}

std::string render_mesh_svg(const MeshPicture& picture, int width, int height) {
  pugi::xml_document doc;
  append_mesh_svg(doc, picture, width, height);
  doc.first_child().prepend_attribute("xmlns") = "http://www.w3.org/2000/svg";
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default | pugi::format_no_declaration | pugi::format_no_empty_element_tags);
  return out.str();
}

}  // namespace vgc
