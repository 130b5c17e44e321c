// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The steps of `triangulate_polygons()` and `repair_mesh()` (repair.h) on a
// polygon soup that remembers, for each point and each polygon, the file
// vertex and the file face it comes from. Each step is a function of CGAL's
// Polygon_mesh_processing; what is written here only carries the file indices
// through it.
#ifndef GEODESIC_RIDGE_INTERNAL_SOUP_REPAIR_H
#define GEODESIC_RIDGE_INTERNAL_SOUP_REPAIR_H

#include <Geodesic_ridge/internal/union_find.h>
#include <Geodesic_ridge/internal/soup_validator.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Projection_traits_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {
namespace repair {

namespace PMP = CGAL::Polygon_mesh_processing;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using validation::to_epick;

constexpr std::size_t no_index = (std::numeric_limits<std::size_t>::max)();

// Whether triangle pqr has barycentric coordinates: its corners are not
// collinear (exact predicate) and, in the floating-point kernel, the Gram
// determinant that CGAL's `barycentric_coordinates()` divides by (and asserts
// on) is not zero.
template <class Point_3>
bool has_barycentric_coordinates(const Point_3& p, const Point_3& q, const Point_3& r)
{
  if(CGAL::collinear(p, q, r))
    return false;
  const auto v0 = q - p;
  const auto v1 = r - p;
  return (v0 * v0) * (v1 * v1) - (v0 * v1) * (v0 * v1) != 0;
}

// A polygon that carries the file face it comes from. CGAL's soup functions
// move, swap, erase and reverse whole polygons, so the file face goes along.
struct Tracked_polygon : std::vector<std::size_t>
{
  std::size_t file_face = no_index;

  Tracked_polygon() = default;
  template <class Iterator>
  Tracked_polygon(Iterator first, Iterator last) : std::vector<std::size_t>(first, last)
  {}
};

// The soup being repaired. Point i is file vertex `point_file[i]` (the repair
// never moves a point: its position is the file's); `representative[V]` is
// the file vertex that file vertex V was merged into (V if none).
struct Soup
{
  std::vector<std::size_t> point_file;
  std::vector<Tracked_polygon> polygons;
  std::vector<std::size_t> representative;
};

template <class Point_3>
Soup make_soup(const std::vector<Point_3>& file_points, const std::vector<std::vector<std::size_t>>& file_polygons)
{
  Soup soup;
  soup.point_file.resize(file_points.size());
  std::iota(soup.point_file.begin(), soup.point_file.end(), std::size_t(0));
  soup.representative = soup.point_file;
  for(std::size_t j = 0; j < file_polygons.size(); ++j)
  {
    soup.polygons.emplace_back(file_polygons[j].begin(), file_polygons[j].end());
    soup.polygons.back().file_face = j;
  }
  return soup;
}

// The positions of the soup's points, in Epick.
template <class Point_3>
std::vector<Epick::Point_3> positions(const std::vector<Point_3>& file_points, const Soup& soup)
{
  std::vector<Epick::Point_3> points;
  points.reserve(soup.point_file.size());
  for(std::size_t v : soup.point_file)
    points.push_back(to_epick(file_points[v]));
  return points;
}

// Points at the same position become one, the first in file order
// (PMP::merge_duplicate_points_in_polygon_soup). CGAL renumbers the polygons
// but says nothing of the points; one more polygon through every point, in
// order, is renumbered with the others and gives the map.
template <class Point_3>
std::size_t merge_duplicate_points(const std::vector<Point_3>& file_points, Soup& soup)
{
  std::vector<Epick::Point_3> points = positions(file_points, soup);
  const std::size_t n = points.size();
  Tracked_polygon tracker;
  tracker.resize(n);
  std::iota(tracker.begin(), tracker.end(), std::size_t(0));
  soup.polygons.push_back(tracker);
  const std::size_t merged = PMP::merge_duplicate_points_in_polygon_soup(points, soup.polygons);
  tracker = std::move(soup.polygons.back());
  soup.polygons.pop_back();
  std::vector<std::size_t> point_file(points.size(), no_index);
  for(std::size_t i = 0; i < n; ++i)
    if(point_file[tracker[i]] == no_index)
      point_file[tracker[i]] = soup.point_file[i]; // CGAL keeps the first point of a group
  for(std::size_t i = 0; i < n; ++i)
    soup.representative[soup.point_file[i]] = point_file[tracker[i]];
  soup.point_file.swap(point_file);
  return merged;
}

// Consecutive repeated corners are dropped, then polygons with fewer than
// three corners are removed (CGAL's own steps of repair_polygon_soup). After
// the merge, a repeated position is a repeated index. Returns the number of
// polygons removed.
template <class Point_3>
std::size_t remove_invalid_polygons(const std::vector<Point_3>& file_points, Soup& soup)
{
  const std::vector<Epick::Point_3> points = positions(file_points, soup);
  PMP::internal::simplify_polygons_in_polygon_soup(points, soup.polygons, Epick());
  return PMP::internal::remove_invalid_polygons_in_polygon_soup(points, soup.polygons);
}

// True if the corners of `polygon` (in `points`) lie in one plane, decided
// with exact predicates; a polygon whose corners are all collinear is planar.
inline bool is_planar(const std::vector<Epick::Point_3>& points, const std::vector<std::size_t>& polygon)
{
  const std::size_t n = polygon.size();
  const Epick::Point_3& a = points[polygon[0]];
  std::size_t b = 1;
  while(b < n && points[polygon[b]] == a)
    ++b;
  std::size_t c = b + 1;
  while(c < n && CGAL::collinear(a, points[polygon[b]], points[polygon[c]]))
    ++c;
  if(c >= n)
    return true;
  for(std::size_t k = 1; k < n; ++k)
    if(!CGAL::coplanar(a, points[polygon[b]], points[polygon[c]], points[polygon[k]]))
      return false;
  return true;
}

// What `triangulate()` did.
struct Triangulation
{
  std::size_t polygons = 0;             // polygons with more than three corners
  std::size_t non_planar = 0;           // of which not planar
  std::size_t triangles = 0;            // the triangles made from them
  std::vector<std::size_t> failed;      // soup indices of the polygons left untriangulated, in order
  std::vector<std::string> why_failed;  // for each of them, why
};

// Whether the outline of corners `c`, projected along `normal` into the
// plane of CGAL's `Projection_traits_3` (the one its triangulation uses), is
// simple: no two corners at one point, no edge touching or crossing another
// but at their common corner. Computed in kernel K: with intervals, which
// throw `Uncertain_conversion_exception` where they cannot decide, or exactly.
template <class K>
bool is_simple_along(const std::vector<Epick::Point_3>& c, const Epick::Vector_3& normal)
{
  using FT = typename K::FT;
  const FT nx(normal.x()), ny(normal.y()), nz(normal.z());
  // the plane's base as CGAL's traits make it, b2 = normal x b1 exactly:
  // b1 x b2 is then a positive multiple of the normal
  const bool z = CGAL::abs(normal.z()) >= CGAL::abs(normal.y());
  const std::array<FT, 3> b1 = z ? std::array<FT, 3>{{nz, FT(0), -nx}} : std::array<FT, 3>{{ny, -nx, FT(0)}};
  const std::array<FT, 3> b2 = {{ny * b1[2] - nz * b1[1], nz * b1[0] - nx * b1[2], nx * b1[1] - ny * b1[0]}};
  std::vector<typename K::Point_2> projected;
  projected.reserve(c.size());
  for(const Epick::Point_3& p : c)
  {
    const FT x(p.x()), y(p.y()), w(p.z());
    projected.emplace_back(x * b1[0] + y * b1[1] + w * b1[2], x * b2[0] + y * b2[1] + w * b2[2]);
  }
  return CGAL::is_simple_2(projected.begin(), projected.end(), K());
}

// Why CGAL's `triangulate_face()` cannot be given the polygon of corners `c`
// (positions in order; `vertex` names them, as file vertices, in the message)
// whose normal, computed as CGAL does, is `normal`; empty if it can. A quad
// is split along a diagonal, which needs only a normal. A larger polygon is
// projected along its normal into a constrained Delaunay triangulation, which
// fails assertions, loops forever or (in a Release build) reads out of bounds
// if two corners coincide or the outline touches or crosses itself there.
// That is decided exactly; and as the triangulation's own rounded predicates
// see it, so that they do not contradict the decision.
inline std::string why_not_triangulable(const std::vector<Epick::Point_3>& c, const Epick::Vector_3& normal,
                                        const std::vector<std::size_t>& vertex)
{
  const std::size_t n = c.size();
  std::size_t b = 1;
  while(b < n && c[b] == c[0])
    ++b;
  std::size_t k = b + 1;
  while(k < n && CGAL::collinear(c[0], c[b], c[k]))
    ++k;
  if(k >= n)
    return "its vertices are collinear";
  if(normal == CGAL::NULL_VECTOR)
    return "its normal is null (its outline encloses no area)";
  if(n == 4)
    return std::string();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return c[i] < c[j]; });
  for(std::size_t i = 1; i < n; ++i)
    if(c[order[i - 1]] == c[order[i]])
    {
      const std::size_t u = (std::min)(vertex[order[i - 1]], vertex[order[i]]);
      const std::size_t v = (std::max)(vertex[order[i - 1]], vertex[order[i]]);
      return u == v ? "it goes twice through vertex " + std::to_string(u)
                    : "its vertices " + std::to_string(u) + " and " + std::to_string(v) + " are at the same position";
    }
  bool simple;
  try
  {
    CGAL::Protect_FPU_rounding<true> rounding; // the intervals' rounding, for all their operations at once
    simple = is_simple_along<CGAL::Simple_cartesian<CGAL::Interval_nt_advanced>>(c, normal);
  }
  catch(const CGAL::Uncertain_conversion_exception&)
  {
    simple = is_simple_along<CGAL::Simple_cartesian<CGAL::Exact_rational>>(c, normal);
  }
  if(!simple || !CGAL::is_simple_2(c.begin(), c.end(), CGAL::Projection_traits_3<Epick>(normal)))
    return "its outline touches or crosses itself";
  return std::string();
}

// The polygons with more than three corners, each as a face of its own (own
// vertices) of a helper mesh; "v:corner" is (polygon, corner) of a vertex.
inline CGAL::Surface_mesh<Epick::Point_3>
polygons_as_separate_faces(const std::vector<Epick::Point_3>& points, const std::vector<Tracked_polygon>& polygons,
                           std::vector<CGAL::SM_Face_index>& faces)
{
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  Mesh mesh;
  auto corner = mesh.add_property_map<Mesh::Vertex_index, std::pair<std::size_t, std::size_t>>("v:corner").first;
  std::vector<Mesh::Vertex_index> vs;
  for(std::size_t j = 0; j < polygons.size(); ++j)
  {
    if(polygons[j].size() <= 3)
      continue;
    vs.clear();
    for(std::size_t k = 0; k < polygons[j].size(); ++k)
    {
      vs.push_back(mesh.add_vertex(points[polygons[j][k]]));
      corner[vs.back()] = {j, k};
    }
    faces.push_back(mesh.add_face(vs));
  }
  return mesh;
}

// Every polygon with more than three corners is split into triangles by
// CGAL's `triangulate_face()`: a quad along the diagonal that maximizes the
// dot product of the two triangles' normals, a larger polygon by a
// constrained Delaunay triangulation in the plane of its normal. The first
// triangle of polygon j takes its place; the others are appended, polygon
// after polygon. A polygon CGAL cannot triangulate (`why_not_triangulable()`,
// or CGAL gives up) stays as it is and is listed in `failed`.
template <class Point_3>
Triangulation triangulate(const std::vector<Point_3>& file_points, Soup& soup)
{
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  const std::vector<Epick::Point_3> points = positions(file_points, soup);
  Triangulation result;
  std::vector<Mesh::Face_index> faces;
  Mesh mesh = polygons_as_separate_faces(points, soup.polygons, faces);
  if(faces.empty())
    return result;
  const auto corner = mesh.property_map<Mesh::Vertex_index, std::pair<std::size_t, std::size_t>>("v:corner").first;
  std::vector<std::string> why(soup.polygons.size());
  std::vector<Epick::Point_3> corners;
  std::vector<std::size_t> vertex;
  for(Mesh::Face_index f : faces)
  {
    const std::size_t j = corner[mesh.target(mesh.halfedge(f))].first;
    corners.clear();
    vertex.clear();
    for(std::size_t i : soup.polygons[j])
    {
      corners.push_back(points[i]);
      vertex.push_back(soup.point_file[i]);
    }
    why[j] = why_not_triangulable(corners, PMP::compute_face_normal(f, mesh), vertex);
    if(why[j].empty())
      PMP::triangulate_face(f, mesh);
  }
  std::vector<std::vector<std::array<std::size_t, 3>>> triangles(soup.polygons.size());
  for(Mesh::Face_index f : mesh.faces())
  {
    std::array<std::size_t, 3> t;
    std::size_t k = 0, j = 0;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      j = corner[v].first;
      if(k < 3)
        t[k] = soup.polygons[j][corner[v].second];
      ++k;
    }
    if(k == 3)
      triangles[j].push_back(t);
    else
      result.failed.push_back(j);
  }
  for(std::size_t j = 0; j < triangles.size(); ++j) // the triangles are appended to soup.polygons
  {
    if(triangles[j].empty())
      continue;
    ++result.polygons;
    result.triangles += triangles[j].size();
    if(!is_planar(points, soup.polygons[j]))
      ++result.non_planar;
    const std::size_t file_face = soup.polygons[j].file_face;
    for(std::size_t i = 0; i < triangles[j].size(); ++i)
    {
      Tracked_polygon t(triangles[j][i].begin(), triangles[j][i].end());
      t.file_face = file_face;
      if(i == 0)
        soup.polygons[j] = std::move(t);
      else
        soup.polygons.push_back(std::move(t));
    }
  }
  std::sort(result.failed.begin(), result.failed.end());
  for(std::size_t j : result.failed)
    result.why_failed.push_back(why[j].empty() ? "CGAL's triangulate_face() fails on it" : why[j]);
  return result;
}

// What `orient()` did, from CGAL's orientation visitor.
struct Orientation
{
  std::set<std::pair<std::size_t, std::size_t>> non_manifold_edges;
  std::size_t non_manifold_vertices = 0;
  std::size_t vertex_copies = 0;
  std::vector<bool> reversed; // per polygon
};

struct Orientation_visitor : public PMP::Default_orientation_visitor
{
  Orientation* result;
  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t)
  {
    result->non_manifold_edges.insert(std::minmax(a, b));
  }
  void non_manifold_vertex(std::size_t, std::size_t) { ++result->non_manifold_vertices; }
  void duplicated_vertex(std::size_t, std::size_t) { ++result->vertex_copies; }
  void polygon_orientation_reversed(std::size_t p) { result->reversed[p] = !result->reversed[p]; }
};

// In each connected component where CGAL reversed most faces (it keeps the
// orientation of the component's first face), every face is reversed back, so
// that the faces reoriented are the fewer. Components are vertex-connected:
// after the orientation, every vertex is manifold.
inline void keep_majority_orientation(Soup& soup, Orientation& o)
{
  Union_find uf(soup.point_file.size());
  for(const Tracked_polygon& p : soup.polygons)
    for(std::size_t k = 1; k < p.size(); ++k)
      uf.unite(p[0], p[k]);
  std::vector<std::size_t> faces(soup.point_file.size(), 0), reversed(soup.point_file.size(), 0);
  for(std::size_t j = 0; j < soup.polygons.size(); ++j)
  {
    const std::size_t c = uf.find(soup.polygons[j][0]);
    ++faces[c];
    reversed[c] += o.reversed[j] ? 1 : 0;
  }
  for(std::size_t j = 0; j < soup.polygons.size(); ++j)
  {
    const std::size_t c = uf.find(soup.polygons[j][0]);
    if(2 * reversed[c] > faces[c])
    {
      std::reverse(soup.polygons[j].begin(), soup.polygons[j].end());
      o.reversed[j] = !o.reversed[j];
    }
  }
}

// Orients the soup consistently and duplicates the points where it is not
// manifold: CGAL's orient_polygon_soup, which cuts the soup along every edge
// of more than two faces and along every edge whose two faces cannot agree,
// then gives each fan of faces around a point a point of its own. An edge of
// four faces, two surfaces touching along it, becomes two manifold edges. It
// only needs the points' count, so it runs on `point_file`: a copy of a point
// is then the same file vertex.
inline Orientation orient(Soup& soup)
{
  Orientation result;
  result.reversed.assign(soup.polygons.size(), false);
  Orientation_visitor visitor;
  visitor.result = &result;
  PMP::orient_polygon_soup(soup.point_file, soup.polygons, CGAL::parameters::visitor(visitor));
  keep_majority_orientation(soup, result);
  return result;
}

template <class Point_3>
std::size_t count_degenerate_triangles(const std::vector<Point_3>& file_points, const Soup& soup)
{
  const std::vector<Epick::Point_3> points = positions(file_points, soup);
  return static_cast<std::size_t>(
    std::count_if(soup.polygons.begin(), soup.polygons.end(), [&](const Tracked_polygon& p) {
      return p.size() == 3 && CGAL::collinear(points[p[0]], points[p[1]], points[p[2]]);
    }));
}

// The file vertex of each point of the soup and the soup's triangles as a
// mesh, with the file vertex ("v:file") and the file face ("f:file") of each
// vertex and face. The soup must be a polygon mesh (after `orient()`).
template <class Point_3>
CGAL::Surface_mesh<Epick::Point_3> soup_as_mesh(const std::vector<Point_3>& file_points, const Soup& soup)
{
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(positions(file_points, soup), soup.polygons, mesh);
  auto vfile = mesh.add_property_map<Mesh::Vertex_index, std::size_t>("v:file", no_index).first;
  auto ffile = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:file", no_index).first;
  // polygon_soup_to_polygon_mesh adds point i as vertex i and polygon j as face j
  for(std::size_t i = 0; i < soup.point_file.size(); ++i)
    vfile[Mesh::Vertex_index(static_cast<Mesh::size_type>(i))] = soup.point_file[i];
  for(std::size_t j = 0; j < soup.polygons.size(); ++j)
    ffile[Mesh::Face_index(static_cast<Mesh::size_type>(j))] = soup.polygons[j].file_face;
  return mesh;
}

// True if every corner of face f of `mesh` is a corner of file face `file_face`.
template <class Point_3>
bool corners_are_in_file_face(const CGAL::Surface_mesh<Epick::Point_3>& mesh, CGAL::SM_Face_index f,
                              std::size_t file_face, const std::vector<Point_3>& file_points,
                              const std::vector<std::vector<std::size_t>>& file_polygons)
{
  if(file_face == no_index)
    return false;
  for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
  {
    const auto& corners = file_polygons[file_face];
    if(std::none_of(corners.begin(), corners.end(),
                    [&](std::size_t c) { return to_epick(file_points[c]) == mesh.point(v); }))
      return false;
  }
  return true;
}

// The file face of a face that CGAL's degenerate-face removal made or changed
// (a flip, a vertex removed, a hole re-triangulated): the file face of the
// triangle, before the removal, that holds its centroid, among the triangles
// at its corners. `before` is the soup before the removal.
template <class Point_3>
std::size_t file_face_of_centroid(const CGAL::Surface_mesh<Epick::Point_3>& mesh, CGAL::SM_Face_index f,
                                  const std::vector<Point_3>& file_points, const Soup& before,
                                  const std::vector<std::vector<std::size_t>>& triangles_at_file_vertex)
{
  const auto vfile = mesh.property_map<CGAL::SM_Vertex_index, std::size_t>("v:file").first;
  std::vector<Epick::Point_3> corners;
  std::vector<std::size_t> candidates;
  for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
  {
    corners.push_back(mesh.point(v));
    const auto& at = triangles_at_file_vertex[vfile[v]];
    candidates.insert(candidates.end(), at.begin(), at.end());
  }
  const Epick::Point_3 centroid = CGAL::centroid(corners[0], corners[1], corners[2]);
  std::size_t best = no_index;
  double best_score = -std::numeric_limits<double>::infinity();
  for(std::size_t t : candidates)
  {
    const Tracked_polygon& p = before.polygons[t];
    const std::array<Epick::Point_3, 3> c{{to_epick(file_points[before.point_file[p[0]]]),
                                           to_epick(file_points[before.point_file[p[1]]]),
                                           to_epick(file_points[before.point_file[p[2]]])}};
    if(!has_barycentric_coordinates(c[0], c[1], c[2]))
      continue; // a degenerate face holds no point
    const auto b = PMP::barycentric_coordinates(c[0], c[1], c[2], centroid);
    const double score = (std::min)({b[0], b[1], b[2]});
    if(score > best_score)
    {
      best_score = score;
      best = p.file_face;
    }
  }
  return best;
}

// Faces whose corners are exactly collinear are removed with CGAL's
// `remove_degenerate_faces()` on a mesh of the (oriented, manifold) soup; it
// collapses, flips and re-triangulates around them. Faces it made or changed
// get their file face from `file_face_of_centroid()`. Returns the number of
// degenerate faces removed. CGAL asserts that the mesh is valid: a soup that
// does not make one (a point of no polygon: remove them first) is left as it
// is, its degenerate faces to the validation.
template <class Point_3>
std::size_t remove_degenerate_faces(const std::vector<Point_3>& file_points,
                                    const std::vector<std::vector<std::size_t>>& file_polygons, Soup& soup)
{
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  const std::size_t degenerate = count_degenerate_triangles(file_points, soup);
  if(degenerate == 0 || !PMP::is_polygon_soup_a_polygon_mesh(soup.polygons))
    return 0;
  Mesh mesh = soup_as_mesh(file_points, soup);
  if(!CGAL::is_valid_polygon_mesh(mesh) || !CGAL::is_triangle_mesh(mesh))
    return 0;
  const auto vfile = mesh.property_map<Mesh::Vertex_index, std::size_t>("v:file").first;
  const auto ffile = mesh.property_map<Mesh::Face_index, std::size_t>("f:file").first;
  // a vertex CGAL adds (splitting an edge, or at the centre of a patch it
  // re-triangulates) is at the position of a vertex: its file vertex is that one's
  std::map<Epick::Point_3, std::size_t> file_vertex_at;
  for(Mesh::Vertex_index v : mesh.vertices())
    file_vertex_at.emplace(mesh.point(v), vfile[v]);
  mesh.set_recycle_garbage(false); // a face CGAL adds has no file face yet
  PMP::remove_degenerate_faces(mesh);
  mesh.collect_garbage();
  for(Mesh::Vertex_index v : mesh.vertices())
    if(vfile[v] == no_index)
    {
      const auto at = file_vertex_at.find(mesh.point(v));
      if(at == file_vertex_at.end())
        return 0; // (a new position: the soup is left as it was)
      vfile[v] = at->second;
    }

  std::vector<std::vector<std::size_t>> triangles_at_file_vertex(file_points.size());
  for(std::size_t t = 0; t < soup.polygons.size(); ++t)
    for(std::size_t i : soup.polygons[t])
      triangles_at_file_vertex[soup.point_file[i]].push_back(t);
  const Soup before = soup;
  soup.point_file.clear();
  for(Mesh::Vertex_index v : mesh.vertices())
    soup.point_file.push_back(vfile[v]);
  soup.polygons.clear();
  for(Mesh::Face_index f : mesh.faces())
  {
    Tracked_polygon p;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      p.push_back(static_cast<std::size_t>(v));
    p.file_face = corners_are_in_file_face(mesh, f, ffile[f], file_points, file_polygons)
                    ? ffile[f]
                    : file_face_of_centroid(mesh, f, file_points, before, triangles_at_file_vertex);
    soup.polygons.push_back(std::move(p));
  }
  return degenerate - count_degenerate_triangles(file_points, soup);
}

// Points used by no polygon are removed (CGAL's
// remove_isolated_points_in_polygon_soup, which only moves points: it runs on
// `point_file`).
inline std::size_t remove_isolated_points(Soup& soup)
{
  return PMP::remove_isolated_points_in_polygon_soup(soup.point_file, soup.polygons);
}

// Puts the points in the order of their file vertices (a copy right after the
// vertex it copies) and the polygons in the order of their file faces (a
// polygon's triangles together), whatever order the steps left them in.
inline void sort_in_file_order(Soup& soup)
{
  const std::size_t n = soup.point_file.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return soup.point_file[a] < soup.point_file[b]; });
  std::vector<std::size_t> new_index(n), point_file(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    new_index[order[i]] = i;
    point_file[i] = soup.point_file[order[i]];
  }
  soup.point_file.swap(point_file);
  for(Tracked_polygon& p : soup.polygons)
    for(std::size_t& v : p)
      v = new_index[v];
  std::stable_sort(soup.polygons.begin(), soup.polygons.end(),
                   [](const Tracked_polygon& a, const Tracked_polygon& b) { return a.file_face < b.file_face; });
}

} // namespace repair
} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_SOUP_REPAIR_H
