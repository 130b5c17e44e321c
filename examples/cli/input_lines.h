// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The lines geodesic_ridge reads from files: distance queries (--query) and
// sources (--sources), and the checks that put them on the mesh as read. A
// header of its own so that the query and sources fuzz targets (fuzz/) run
// the very code the program runs.
#ifndef GEODESIC_RIDGE_CLI_INPUT_LINES_H
#define GEODESIC_RIDGE_CLI_INPUT_LINES_H

#include "options.h"

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/file_index_map.h>
#include <Geodesic_ridge/internal/normalization.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace geodesic_ridge_cli {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Mesh;
typedef Mesh::Vertex_index                                  vertex_descriptor;
typedef Mesh::Face_index                                    face_descriptor;
typedef std::pair<face_descriptor, std::array<double, 3> >  Location;
typedef Geodesic_ridge::File_index_map<Mesh>                File_map;
namespace PMP = CGAL::Polygon_mesh_processing;

// The point q of file face `face` as a Face_location (CGAL's order): for a
// polygon, in the triangle of it that holds q. A point farther than 1e-7 of
// the face's size from the face is an error; round-off below that is clamped,
// so that the coordinates are >= 0 and sum to 1.
inline Location locate(const File_map& map, const Mesh& m, std::size_t face, const Point_3& q,
                const std::string& what = "source point")
{
  const std::optional<Location> found = map.locate(face, q, m);
  if(!found)
    throw Geodesic_ridge::Invalid_source_error("face " + std::to_string(face) + " was removed by the repair");
  Location loc = *found; // the coordinates of q's projection on the face's plane
  const face_descriptor f = loc.first;
  const double eps = 1e-7;
  std::array<double, 3>& w = loc.second;
  // the coordinates first: far from the face they are huge or NaN and may sum
  // to 0, on which CGAL's construct_point asserts (found by fuzz/). Lengths
  // without squares: any scale.
  auto on_face = [&] {
    for(double x : w)
      if(!(x >= -eps) || !std::isfinite(x)) return false;
    const double off_plane = Geodesic_ridge::internal::length_at_any_scale(q - PMP::construct_point(loc, m));
    double size = 0;
    for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m))
      size = std::max(size, Geodesic_ridge::internal::length_at_any_scale(m.point(m.source(h)) - m.point(m.target(h))));
    return off_plane <= eps * size;
  };
  if(!on_face())
  {
    std::ostringstream s;
    s.precision(17);
    s << what << " (" << q << ") is not on face " << face;
    throw Geodesic_ridge::Invalid_source_error(s.str());
  }
  for(double& x : w) x = std::max(x, 0.);
  const double sum = w[0] + w[1] + w[2];
  for(double& x : w) x /= sum;
  return loc;
}

// The file face `text` names, checked.
inline std::size_t file_face(const std::string& text, const File_map& map)
{
  const std::size_t face = parse_index("face", text);
  if(face >= map.number_of_file_faces())
    throw Geodesic_ridge::Invalid_parameter_error("face " + text + " is out of range: the mesh has " +
                                                  std::to_string(map.number_of_file_faces()) + " faces");
  return face;
}

// The barycentric query "FACE B0 ... Bn-1": one coordinate per vertex of the
// file face, in file order.
inline Location barycentric_query(const std::vector<std::string>& t, const Mesh& mesh, const File_map& map)
{
  const std::size_t face = file_face(t[0], map);
  const std::size_t n = map.file_face_vertices(face).size();
  if(t.size() != n + 1)
    throw Geodesic_ridge::Invalid_parameter_error(
        n == 3 ? "expected 'FACE B0 B1 B2', got " + std::to_string(t.size()) + " fields"
               : "expected 'FACE' and " + std::to_string(n) + " coordinates (face " + t[0] + " has " +
                     std::to_string(n) + " vertices), got " + std::to_string(t.size()) + " fields");
  std::vector<double> v(n);
  double sum = 0;
  bool negative = false;
  for(std::size_t k = 0; k < n; ++k)
  {
    v[k] = parse_number("coordinate", t[k + 1]);
    sum += v[k];
    negative = negative || v[k] < -1e-9;
  }
  if(std::abs(sum - 1) > 1e-9 || negative)
    throw Geodesic_ridge::Invalid_parameter_error("barycentric coordinates must be >= 0 and sum to 1 within 1e-9");
  for(double& x : v) x = std::max(x, 0.);
  const std::optional<Location> loc = map.location(face, v, mesh);
  if(!loc)
    throw Geodesic_ridge::Invalid_parameter_error("face " + t[0] + " was removed by the repair");
  Location l = *loc;
  for(double& x : l.second) x = std::max(x, 0.);
  return l;
}

// One query of a query file: "FACE X Y Z" or, barycentric, "FACE B0 B1 B2".
inline Location read_query(const std::vector<std::string>& t, const Mesh& mesh, const File_map& map, bool barycentric)
{
  if(barycentric) return barycentric_query(t, mesh, map);
  if(t.size() != 4)
    throw Geodesic_ridge::Invalid_parameter_error("expected 'FACE X Y Z', got " + std::to_string(t.size()) +
                                                  " fields");
  const std::size_t face = file_face(t[0], map);
  std::array<double, 3> v;
  for(int k = 0; k < 3; ++k) v[k] = parse_number("coordinate", t[k + 1]);
  return locate(map, mesh, face, Point_3(v[0], v[1], v[2]), "point");
}

// One item per line of `filename` (`kind`: "query", "source"), made by
// `read(tokens, line number)`; '#' starts a comment. Errors name the file and the line.
template <class Read>
auto read_lines(const std::string& filename, const std::string& kind, const Read& read)
{
  std::ifstream is(filename);
  if(!is) throw Geodesic_ridge::Invalid_parameter_error("cannot open " + kind + " file '" + filename + "'");
  std::vector<decltype(read(std::vector<std::string>(), std::size_t()))> items;
  std::string line;
  for(std::size_t number = 1; std::getline(is, line); ++number)
  {
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line.erase(hash);
    std::istringstream tokens(line);
    std::vector<std::string> t;
    for(std::string x; tokens >> x;) t.push_back(x);
    if(t.empty()) continue;
    try
    {
      items.push_back(read(t, number));
    }
    catch(const Geodesic_ridge::Error& e)
    {
      throw Geodesic_ridge::Invalid_parameter_error(kind + " file '" + filename + "' line " + std::to_string(number) +
                                                    ": " + e.what());
    }
  }
  if(is.bad()) throw Geodesic_ridge::Invalid_parameter_error("cannot read " + kind + " file '" + filename + "'");
  return items;
}

inline std::vector<Location> read_queries(const std::string& filename, const Mesh& mesh, const File_map& map,
                                   bool barycentric)
{
  return read_lines(filename, "query", [&](const std::vector<std::string>& t, std::size_t) {
    return read_query(t, mesh, map, barycentric);
  });
}

// The mesh vertex of the file's source vertex, said on stderr when the repair
// merged or split it.
inline vertex_descriptor source_vertex(const Mesh& mesh, const File_map& map, std::size_t v)
{
  if(v >= map.number_of_file_vertices())
    throw Geodesic_ridge::Invalid_source_error("source vertex " + std::to_string(v) +
                                               " is out of range: the mesh has " +
                                               std::to_string(map.number_of_file_vertices()) + " vertices");
  const std::optional<vertex_descriptor> found = map.vertex(v, mesh);
  if(!found)
    throw Geodesic_ridge::Invalid_source_error("source vertex " + std::to_string(v) +
                                               " was removed by the repair (no face of the repaired mesh uses it)");
  const std::size_t copies = map.vertices(v).size(), merged_into = map.file_vertex(*found, mesh);
  if(merged_into != v)
    std::cerr << "geodesic_ridge: note: source vertex " << v << " was merged by the repair into vertex "
              << merged_into << " (same position)\n";
  if(copies > 1)
    std::cerr << "geodesic_ridge: note: source vertex " << v << " was split by the repair into " << copies
              << " copies; the source is the copy with the largest incident area\n";
  return *found;
}

// The point q of file face `face`, checked: the face is the file's and the
// repair kept it, q is on it.
inline Location source_point(const Mesh& mesh, const File_map& map, std::size_t face, const Point_3& q)
{
  if(face >= map.number_of_file_faces())
    throw Geodesic_ridge::Invalid_source_error("source face " + std::to_string(face) +
                                               " is out of range: the mesh has " +
                                               std::to_string(map.number_of_file_faces()) + " faces");
  if(map.faces(face).empty())
    throw Geodesic_ridge::Invalid_source_error("source face " + std::to_string(face) +
                                               " was removed by the repair (degenerate, duplicate, or with "
                                               "fewer than 3 distinct vertices)");
  return locate(map, mesh, face, q);
}

// --sources: a line 'V' (a file vertex) or 'FACE X Y Z' (a point of a file
// face). Its syntax is checked when the file is read (a bad line refuses the
// file); whether the mesh has that vertex, or the point on that face, is the
// source's own success or failure (resolve()).
struct Source_line
{
  std::string text;             // the line, for the outputs
  std::size_t line = 0;         // its number in the file
  std::size_t index = 0;        // V, or FACE
  std::optional<Point_3> point; // X Y Z
};

inline Source_line read_source_line(const std::vector<std::string>& t, std::size_t line)
{
  if(t.size() != 1 && t.size() != 4)
    throw Geodesic_ridge::Invalid_parameter_error("expected 'V' or 'FACE X Y Z', got " + std::to_string(t.size()) +
                                                  " fields");
  Source_line s;
  s.text = t[0];
  for(std::size_t k = 1; k < t.size(); ++k) s.text += " " + t[k];
  s.line = line;
  s.index = parse_index(t.size() == 1 ? "source vertex" : "source face", t[0]);
  if(t.size() == 4)
    s.point = Point_3(parse_number("coordinate", t[1]), parse_number("coordinate", t[2]),
                      parse_number("coordinate", t[3]));
  return s;
}

// The source on the mesh as read (a vertex as a corner of a face of it).
inline Location resolve(const Source_line& s, const Mesh& mesh, const File_map& map)
{
  if(s.point) return source_point(mesh, map, s.index, *s.point);
  return PMP::locate_vertex<double>(source_vertex(mesh, map, s.index), mesh);
}

} // namespace geodesic_ridge_cli

#endif // GEODESIC_RIDGE_CLI_INPUT_LINES_H
