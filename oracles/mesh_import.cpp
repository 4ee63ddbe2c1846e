// mesh_import.cpp — see mesh_import.h.
#include "mesh_import.h"

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "mesh_text_scan.h"
#include "polygon_triangulation.h"

namespace vgc {
namespace {

using Point = CGAL::Simple_cartesian<double>::Point_3;

bool fail(MeshFileError* error, std::size_t line, std::string message) {
  error->line = line, error->column = line ? 1 : 0, error->message = std::move(message);
  return false;
}

std::string extension_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

// CGAL's reader for `format` on `bytes`; what it wrote to std::cerr and
// std::cout (its reasons, its notes) goes to *said, not to the terminal.
bool cgal_read(const std::string& format, const std::string& bytes, PolygonSoup* soup, std::string* said) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::istringstream in(bytes, std::ios::in | std::ios::binary);
  std::ostringstream captured;
  std::streambuf* err = std::cerr.rdbuf(captured.rdbuf());
  std::streambuf* out = std::cout.rdbuf(captured.rdbuf());
  const auto np = CGAL::parameters::verbose(true);
  bool ok = false;
  try {
    if (format == "OBJ") ok = CGAL::IO::read_OBJ(in, points, polygons, np);
    else if (format == "OFF") ok = CGAL::IO::read_OFF(in, points, polygons, np);
    else if (format == "PLY") ok = CGAL::IO::read_PLY(in, points, polygons, np);
    else if (format == "STL") ok = CGAL::IO::read_STL(in, points, polygons, np);
  } catch (const std::exception& e) {
    captured << e.what();
    ok = false;
  }
  std::cerr.rdbuf(err);
  std::cout.rdbuf(out);
  *said = captured.str();
  while (!said->empty() && (said->back() == '\n' || said->back() == ' ')) said->pop_back();
  std::replace(said->begin(), said->end(), '\n', ';');
  soup->format = format;
  soup->points.clear();
  soup->points.reserve(points.size());
  for (const Point& p : points) soup->points.push_back({p.x(), p.y(), p.z()});
  soup->polygons = std::move(polygons);
  return ok;
}

// CGAL's reading against the scan's: the same points, bit for bit, and
// polygons; the first difference as an error.
bool same_reading(const PolygonSoup& cgal, const PolygonSoup& scan, MeshFileError* error) {
  if (cgal.points.size() != scan.points.size())
    return fail(error, 0,
                "CGAL's " + cgal.format + " reader read " + std::to_string(cgal.points.size()) +
                    " vertices where the file's lines hold " + std::to_string(scan.points.size()));
  for (std::size_t i = 0; i < cgal.points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (std::memcmp(&cgal.points[i][k], &scan.points[i][k], sizeof(double)) != 0)
        return fail(error, 0,
                    "CGAL's " + cgal.format + " reader read coordinate " + std::to_string(k + 1) + " of vertex " +
                        std::to_string(i) + " otherwise than correctly rounded parsing: not certified on an "
                        "inexact reading");
  if (cgal.polygons.size() != scan.polygons.size())
    return fail(error, 0,
                "CGAL's " + cgal.format + " reader read " + std::to_string(cgal.polygons.size()) +
                    " faces where the file's lines hold " + std::to_string(scan.polygons.size()));
  for (std::size_t f = 0; f < cgal.polygons.size(); ++f)
    if (cgal.polygons[f] != scan.polygons[f])
      return fail(error, scan.polygon_lines[f],
                  "CGAL's " + cgal.format + " reader reads this face's corners otherwise (" +
                      std::to_string(cgal.polygons[f].size()) + " corners) than the line says (" +
                      std::to_string(scan.polygons[f].size()) + ")");
  return true;
}

// The bytes of `path`, a UTF-8 byte-order mark removed.
bool read_bytes(const std::string& path, std::string* bytes, MeshFileError* error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(error, 0, std::string("cannot read the file: ") + std::strerror(errno));
  bytes->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) return fail(error, 0, "cannot read the file (an I/O error)");
  if (bytes->rfind("\xEF\xBB\xBF", 0) == 0) bytes->erase(0, 3);
  return true;
}

// Whether a PLY or STL file is text (its header says so).
bool is_text(const std::string& format, const std::string& bytes) {
  if (format == "OBJ") return true;
  if (format == "OFF") return bytes.substr(0, bytes.find('\n')).find("BINARY") == std::string::npos;
  if (format == "PLY") return bytes.find("format ascii") < bytes.find("end_header");
  if (format == "STL") return bytes.rfind("solid", 0) == 0 && bytes.find('\0') == std::string::npos;
  return false;
}

bool has_faces(const PolygonSoup& soup, MeshFileError* error) {
  if (soup.points.empty()) return fail(error, 0, "no vertex in the file: no mesh to certify");
  if (soup.polygons.empty())
    return fail(error, 0, "no face in the file (" + std::to_string(soup.points.size()) +
                              " vertices): vgc certifies polygon meshes, not point clouds");
  return true;
}

// The file as a polygon soup read by CGAL and, for OBJ and OFF text, checked
// line by line (mesh_text_scan.h).
bool read_soup(const std::string& path, PolygonSoup* soup, MeshFileError* error) {
  const std::string ext = extension_of(path);
  std::string format = ext == "obj" ? "OBJ" : ext == "off" ? "OFF" : ext == "ply" ? "PLY" : ext == "stl" ? "STL" : "";
  if (format.empty())
    return fail(error, 0,
                (ext.empty() ? std::string("the file name has no extension") : "no reader for '." + ext + "' files") +
                    ": vgc reads OBJ, OFF, PLY and STL, chosen by the name's extension (.obj, .off, .ply, .stl)");
  std::string bytes;
  if (!read_bytes(path, &bytes, error)) return false;
  if (bytes.empty()) return fail(error, 0, "the file is empty (0 bytes): no mesh to read");
  if (bytes.rfind("\xFF\xFE", 0) == 0 || bytes.rfind("\xFE\xFF", 0) == 0 || is_text(format, bytes))
    if (!check_text_encoding(bytes, error)) return false;
  PolygonSoup scan;
  bool complete = false;
  if (format == "OBJ") {
    std::replace(bytes.begin(), bytes.end(), '\t', ' ');  // CGAL skips to the next ' ' after a corner
    if (!scan_obj_text(bytes, &scan, error)) return false;
    complete = true;
  } else if (format == "OFF" && is_text(format, bytes)) {
    if (!scan_off_text(bytes, &scan, &complete, error)) return false;
  }
  if (complete && !has_faces(scan, error)) return false;
  std::string said;
  if (!cgal_read(format, bytes, soup, &said))
    return fail(error, 0, "CGAL's " + format + " reader cannot read it" + (said.empty() ? "" : " (" + said + ")"));
  if (complete) {
    if (!same_reading(*soup, scan, error)) return false;
    soup->polygon_lines = std::move(scan.polygon_lines);
    soup->polygon_columns = std::move(scan.polygon_columns);
  }
  return has_faces(*soup, error);
}

}  // namespace

bool import_mesh(const std::string& path, const MeshImportOptions& options, MeshProgram* out, MeshFileError* error) {
  PolygonSoup soup;
  if (!read_soup(path, &soup, error)) return false;
  std::size_t split = 0;
  if (options.triangulate && !triangulate_large_faces(&soup, &split, error)) return false;
  if (!program_from_soup(soup, out, error)) return false;
  out->split_faces = split;
  return true;
}

}  // namespace vgc
