// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A polygon soup as read from a file, made into the triangle mesh the
// algorithm takes: polygons triangulated (always), and, on request, dirty
// input repaired. Every change is counted, and the result keeps a map from its
// vertices and faces back to the file's, so that indices given by a user and
// indices written out stay those of the file.
#ifndef GEODESIC_RIDGE_REPAIR_H
#define GEODESIC_RIDGE_REPAIR_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/soup_repair.h>
#include <Geodesic_ridge/mesh_validation.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// What `triangulate_polygons()` and `repair_mesh()` changed, kind by kind.
/// The first three counts are those of the triangulation, done whether or not
/// the mesh is repaired; the others are the repair's.
struct Repair_statistics
{
  /// faces of the file with more than three vertices, split into triangles
  std::size_t triangulated_polygons = 0;
  /// of these, the ones whose vertices are not in one plane (exact predicate):
  /// for them the diagonals chosen change the surface
  std::size_t non_planar_polygons = 0;
  /// the triangles made from the polygons
  std::size_t triangles_from_polygons = 0;
  /// vertices of the file at exactly the position of an earlier vertex,
  /// counted when the mesh is not repaired (the repair merges them:
  /// `merged_vertices`): the mesh is read with a seam there, open or in
  /// several parts where the file's surface may be meant closed and whole
  std::size_t repeated_positions = 0;
  /// `true` if the mesh was repaired (`repair_mesh()`); the counts below are 0 otherwise
  bool repaired = false;
  /// vertices at exactly the position of an earlier vertex, merged into it
  std::size_t merged_vertices = 0;
  /// faces with fewer than three distinct vertices (after the merge), removed
  std::size_t removed_invalid_faces = 0;
  /// faces on the same vertices as an earlier face (either orientation), removed
  std::size_t removed_duplicate_faces = 0;
  /// edges of more than two faces, cut apart
  std::size_t split_non_manifold_edges = 0;
  /// vertices whose faces form several fans, given one vertex per fan
  /// (including the ends of the edges cut apart)
  std::size_t split_non_manifold_vertices = 0;
  /// the vertices added by these splits
  std::size_t added_vertex_copies = 0;
  /// faces with exactly collinear corners, removed (with the mesh around them
  /// re-triangulated where needed), and polygons that could not be triangulated
  std::size_t removed_degenerate_faces = 0;
  /// faces whose orientation was reversed to agree with their neighbours
  std::size_t reoriented_faces = 0;
  /// vertices used by no face (in the file, or once the faces above were
  /// removed), removed
  std::size_t removed_isolated_vertices = 0;

  /// The note about the triangulation, one line (empty if the file has no
  /// polygon): how many polygons, how many were not planar, and the rule.
  std::string triangulation_note() const
  {
    if(triangulated_polygons == 0)
      return std::string();
    return std::to_string(triangulated_polygons) + " polygon" + (triangulated_polygons == 1 ? "" : "s") +
           " triangulated into " + std::to_string(triangles_from_polygons) + " triangles; " +
           std::to_string(non_planar_polygons) +
           " not planar, where the diagonals change the surface (CGAL's triangulate_face rule: a quad split "
           "along the diagonal that maximizes the dot product of its two triangles' normals, a larger polygon "
           "by a constrained Delaunay triangulation in the plane of its normal)";
  }

  /// One line per kind of repair, with its count, in the order the repair
  /// does them (empty if the mesh was not repaired).
  std::vector<std::string> repair_report() const
  {
    if(!repaired)
      return {};
    auto line = [](std::size_t n, const std::string& what) { return "repair: " + std::to_string(n) + " " + what; };
    return {line(merged_vertices, "vertices merged into an earlier vertex at the same position"),
            line(removed_invalid_faces, "faces with fewer than 3 distinct vertices removed"),
            line(removed_duplicate_faces, "duplicate faces removed"),
            line(split_non_manifold_edges, "non-manifold edges split"),
            line(split_non_manifold_vertices, "non-manifold vertices split (" + std::to_string(added_vertex_copies) +
                                                " vertex copies added)"),
            line(removed_degenerate_faces, "degenerate faces removed"),
            line(reoriented_faces, "faces reoriented"),
            line(removed_isolated_vertices, "isolated vertices removed")};
  }
};

/// \ingroup PkgGeodesicRidgeRef
/// A triangle soup made from a file's polygon soup by `triangulate_polygons()`
/// or `repair_mesh()`, with the file index of each of its vertices and faces.
///
/// \tparam Point_3 the point type of the file's soup
template <class Point_3>
struct Repaired_soup
{
  /// the vertices (each one at the position of a file vertex)
  std::vector<Point_3> points;
  /// the faces, as indices into `points`
  std::vector<std::array<std::size_t, 3>> triangles;
  /// the file vertex of each vertex: itself, or, for a vertex that merged
  /// file vertices, the first of them, or, for a copy made by a split, the
  /// file vertex it is a copy of
  std::vector<std::size_t> vertex_to_file;
  /// the file face of each face: a triangle of a polygon is the polygon's
  std::vector<std::size_t> face_to_file;
  /// for each file vertex, the file vertex it was merged into (itself if none):
  /// the mesh vertices of file vertex `V` are those whose `vertex_to_file` is
  /// `file_vertex_merged_into[V]` (none if it was removed)
  std::vector<std::size_t> file_vertex_merged_into;
  /// what was changed
  Repair_statistics statistics;
};

namespace internal {
namespace repair {

template <class Point_3>
Repaired_soup<Point_3> finish(const std::vector<Point_3>& file_points, const Soup& soup, const Repair_statistics& st)
{
  Repaired_soup<Point_3> result;
  result.statistics = st;
  result.vertex_to_file = soup.point_file;
  for(std::size_t v : soup.point_file)
    result.points.push_back(file_points[v]);
  for(const Tracked_polygon& p : soup.polygons)
  {
    if(p.size() != 3)
      throw Algorithm_error("a polygon of " + std::to_string(p.size()) + " vertices is left after the "
                            "triangulation; please report this bug");
    result.triangles.push_back({{p[0], p[1], p[2]}});
    result.face_to_file.push_back(p.file_face);
  }
  result.file_vertex_merged_into = soup.representative;
  return result;
}

template <class Point_3, class Polygon>
std::vector<std::vector<std::size_t>> as_size_t(const std::vector<Polygon>& polygons)
{
  std::vector<std::vector<std::size_t>> result;
  result.reserve(polygons.size());
  for(const Polygon& p : polygons)
  {
    result.emplace_back();
    for(const auto i : p)
      result.back().push_back(static_cast<std::size_t>(i));
  }
  return result;
}

inline void add_triangulation(const Triangulation& t, Repair_statistics& st)
{
  st.triangulated_polygons += t.polygons;
  st.non_planar_polygons += t.non_planar;
  st.triangles_from_polygons += t.triangles;
}

} // namespace repair
} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
///
/// \brief splits every face of a polygon soup that has more than three
/// vertices into triangles, and keeps the map from each triangle back to its
/// polygon.
///
/// The rule is \cgal's `CGAL::Polygon_mesh_processing::triangulate_face()`: a
/// quad is split along the diagonal that maximizes the dot product of the two
/// triangles' normals; a larger polygon is triangulated by a constrained
/// Delaunay triangulation in the plane of its normal, which takes it only if
/// its vertices are at distinct positions and its outline, seen along its
/// normal, neither touches nor crosses itself (exact predicates). No vertex
/// is added. The triangles keep the polygon's orientation. For a polygon
/// whose vertices are not in one plane the diagonals change the surface;
/// such polygons are counted (`Repair_statistics::non_planar_polygons`).
///
/// Face numbering: the first triangle of face `j` is triangle `j`; the other
/// triangles of the polygons come after the file's faces, polygon after
/// polygon. Vertices are unchanged.
///
/// The soup is checked first for what the triangulation needs: at least one
/// face, indices in range, finite coordinates, at least three vertices per
/// face, no vertex repeated in a face. The other rules of
/// `validate_triangle_soup()` are left to it (the result is not validated).
///
/// \tparam Point_3 a point type of a \cgal kernel
/// \tparam Polygon a random access range of integer indices
///
/// \param points the vertex positions
/// \param polygons the faces, as indices into `points`
///
/// \throws Invalid_mesh_error if the soup is empty, has an index out of range
///         or a non-finite coordinate
/// \throws Repairable_mesh_error if a face has fewer than three vertices,
///         repeats a vertex, or cannot be triangulated (its vertices are
///         collinear; or, with more than four, two are at the same position,
///         or its outline touches or crosses itself): `repair_mesh()` removes
///         such faces
template <class Point_3, class Polygon>
Repaired_soup<Point_3> triangulate_polygons(const std::vector<Point_3>& points, const std::vector<Polygon>& polygons)
{
  namespace ir = internal::repair;
  internal::validation::Triangle_soup_validator<Point_3, Polygon>(points, polygons).run_polygon_rules();
  // Only triangles (most files): the soup as it is, without the copies the
  // triangulation works on.
  if(std::all_of(polygons.begin(), polygons.end(), [](const Polygon& p) { return p.size() == 3; }))
  {
    Repaired_soup<Point_3> result;
    result.points = points;
    result.triangles.reserve(polygons.size());
    for(const Polygon& p : polygons)
      result.triangles.push_back({{static_cast<std::size_t>(p[0]), static_cast<std::size_t>(p[1]),
                                   static_cast<std::size_t>(p[2])}});
    result.vertex_to_file.resize(points.size());
    std::iota(result.vertex_to_file.begin(), result.vertex_to_file.end(), std::size_t(0));
    result.file_vertex_merged_into = result.vertex_to_file;
    result.face_to_file.resize(polygons.size());
    std::iota(result.face_to_file.begin(), result.face_to_file.end(), std::size_t(0));
    return result;
  }
  ir::Soup soup = ir::make_soup(points, ir::as_size_t<Point_3>(polygons));
  const ir::Triangulation t = ir::triangulate(points, soup);
  if(!t.failed.empty())
  {
    const std::size_t j = t.failed.front();
    throw Repairable_mesh_error("face " + std::to_string(j) + " (" + std::to_string(polygons[j].size()) +
                                " vertices) cannot be triangulated: " + t.why_failed.front());
  }
  Repair_statistics st;
  ir::add_triangulation(t, st);
  return ir::finish(points, soup, st);
}

/// \ingroup PkgGeodesicRidgeRef
///
/// \brief repairs a polygon soup with \cgal's Polygon_mesh_processing, counts
/// every kind of repair, and keeps the map from the repaired mesh's vertices
/// and faces back to the soup's.
///
/// The steps, in order, each one a \cgal function:
/// 1. vertices at exactly the same position are merged into the first one
///    (`merge_duplicate_points_in_polygon_soup()`);
/// 2. repeated consecutive vertices are dropped from the faces, and faces left
///    with fewer than three vertices are removed (the soup simplification of
///    `repair_polygon_soup()`);
/// 3. polygons are triangulated as by `triangulate_polygons()`; a polygon
///    that cannot be (collinear vertices; or, with more than four, one that
///    goes twice through a vertex or whose outline touches or crosses itself)
///    is removed as degenerate, and so are the triangles of a quad that went
///    twice through a vertex, if they repeat it;
/// 4. faces on the same three vertices as an earlier face, in either
///    orientation, are removed (`merge_duplicate_polygons_in_polygon_soup()`);
/// 5. the faces are oriented consistently and the non-manifold edges and
///    vertices are split (`orient_polygon_soup()`): the soup is cut along
///    every edge of more than two faces, so two surfaces that touch along an
///    edge become two manifold surfaces, and each fan of faces around a vertex
///    gets its own copy of the vertex. In each connected component the
///    orientation of most faces is kept: the faces reoriented are the fewer;
/// 6. faces with exactly collinear corners are removed
///    (`remove_degenerate_faces()`, which collapses, flips and re-triangulates
///    the faces around them); a face it changes gets the file face that holds
///    its centroid;
/// 7. vertices used by no face are removed
///    (`remove_isolated_points_in_polygon_soup()`; also before step 6, whose
///    \cgal function needs a valid polygon mesh).
///
/// Order: the vertices of the result are in the order of their file vertices
/// (a copy made by a split right after the vertex it copies), and its faces in
/// the order of their file faces (the triangles of a polygon together), so
/// that repairing a mesh that needs no repair changes nothing but the order of
/// the triangles of its polygons.
///
/// The repair never moves a vertex nor adds one at a new position. It makes no
/// mesh closed or connected: a repaired mesh may still have boundary edges or
/// several components (step 5 may even make some), which
/// `validate_triangle_soup()` refuses.
///
/// \tparam Point_3 a point type of a \cgal kernel
/// \tparam Polygon a random access range of integer indices
///
/// \param points the vertex positions
/// \param polygons the faces, as indices into `points`
///
/// \throws Invalid_mesh_error if the soup is empty, has an index out of range
///         or a non-finite coordinate (nothing to repair there)
template <class Point_3, class Polygon>
Repaired_soup<Point_3> repair_mesh(const std::vector<Point_3>& points, const std::vector<Polygon>& polygons)
{
  namespace ir = internal::repair;
  internal::validation::Triangle_soup_validator<Point_3, Polygon>(points, polygons).run_polygon_rules(false);
  const std::vector<std::vector<std::size_t>> file_polygons = ir::as_size_t<Point_3>(polygons);
  ir::Soup soup = ir::make_soup(points, file_polygons);
  Repair_statistics st;
  st.repaired = true;
  st.merged_vertices = ir::merge_duplicate_points(points, soup);
  st.removed_invalid_faces = ir::remove_invalid_polygons(points, soup);
  const ir::Triangulation t = ir::triangulate(points, soup);
  ir::add_triangulation(t, st);
  for(auto j = t.failed.rbegin(); j != t.failed.rend(); ++j)
    soup.polygons.erase(soup.polygons.begin() + static_cast<std::ptrdiff_t>(*j));
  st.removed_degenerate_faces = t.failed.size();
  st.removed_invalid_faces += ir::remove_invalid_polygons(points, soup);
  st.removed_duplicate_faces = CGAL::Polygon_mesh_processing::merge_duplicate_polygons_in_polygon_soup(
    ir::positions(points, soup), soup.polygons);
  const ir::Orientation o = ir::orient(soup);
  st.split_non_manifold_edges = o.non_manifold_edges.size();
  st.split_non_manifold_vertices = o.non_manifold_vertices;
  st.added_vertex_copies = o.vertex_copies;
  st.reoriented_faces = static_cast<std::size_t>(std::count(o.reversed.begin(), o.reversed.end(), true));
  st.removed_isolated_vertices = ir::remove_isolated_points(soup); // CGAL's step 6 needs a valid mesh
  st.removed_degenerate_faces += ir::remove_degenerate_faces(points, file_polygons, soup);
  st.removed_isolated_vertices += ir::remove_isolated_points(soup);
  ir::sort_in_file_order(soup);
  return ir::finish(points, soup, st);
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_REPAIR_H
