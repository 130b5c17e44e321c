// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks that an input mesh is one the algorithm supports, before any work is
// done, so that a bad mesh ends with a one-line message instead of a crash, a
// hang or a silently wrong ridge.
#ifndef GEODESIC_RIDGE_MESH_VALIDATION_H
#define GEODESIC_RIDGE_MESH_VALIDATION_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/soup_validator.h>
#include <Geodesic_ridge/internal/union_find.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
///
/// \brief checks that a triangle soup, as read from a file, describes a mesh
/// that the package supports, and throws `Invalid_mesh_error` otherwise.
///
/// Vertex `i` is `points[i]` and face `j` is `polygons[j]` (the file order);
/// messages use these indices. The rules are checked in the following order,
/// and the first one that fails gives the message (one line, naming the
/// problem and the first offending index in vertex / face order):
///
/// 1. the mesh is not empty: it has at least one vertex and one face;
/// 2. every face is a triangle. Other polygons are rejected here; a file's
///    polygons are triangulated by `IO::read_triangle_mesh()`, and a soup's by
///    `triangulate_polygons()` or `repair_mesh()`, which keep the map from each
///    triangle back to its polygon;
/// 3. every face index is in `[0, points.size())`;
/// 4. no face repeats a vertex;
/// 5. every coordinate is finite (no NaN, no infinity);
/// 6. no vertex is isolated (every vertex is used by a face): the algorithm
///    computes a distance per vertex, and an isolated vertex has none;
/// 7. no two faces are on the same three vertices (whatever their orientation);
/// 8. every edge is shared by at most two faces (edge-manifold);
/// 9. (edges of one face are the border: surfaces with boundary are supported);
/// 10. the orientation is consistent: the two faces of an edge traverse it in
///     opposite directions;
/// 11. every vertex is manifold: its faces form a single fan (its link, walked
///     face to face, is one cycle), so that two surfaces touching at a vertex
///     are rejected;
/// 12. the mesh is connected (one connected component): the algorithm runs on
///     one component, which `extract_connected_component()` copies out of a
///     mesh of several (`IO::read_triangle_mesh()` skips this rule);
/// 13. no face is degenerate: its corners are not collinear, decided with the
///     exact predicate `CGAL::collinear()` of
///     `CGAL::Exact_predicates_inexact_constructions_kernel`, without
///     epsilon (coordinates of another kernel are first converted to `double`).
///
/// Each rule relies on the previous ones (for instance the fan walk of rule 11
/// needs oriented, edge-manifold input). The cost is
/// O(V + F) time and memory (bucket sorts, no hash map): a 200k-face
/// mesh validates in a few tens of milliseconds.
///
/// \tparam Point_3 a point type of a \cgal kernel (`CGAL::Kernel_traits` is used
///         only through `x()`, `y()`, `z()` and `CGAL::to_double()`)
/// \tparam Polygon a random access range of integer indices, such as
///         `std::vector<std::size_t>`; negative indices are out of range
///
/// \param points the vertex positions
/// \param polygons the faces, as indices into `points`
///
/// \throws Repairable_mesh_error (a subclass of `Invalid_mesh_error`) if a
///         rule that `repair_mesh()` fixes fails: rules 2, 4, 6, 7, 8, 10, 11
///         and 13
/// \throws Invalid_mesh_error if another rule fails
template <class Point_3, class Polygon>
void validate_triangle_soup(const std::vector<Point_3>& points, const std::vector<Polygon>& polygons)
{
  internal::validation::Triangle_soup_validator<Point_3, Polygon>(points, polygons).run();
}

/// \ingroup PkgGeodesicRidgeRef
///
/// \brief checks that a mesh given through the API (for example a
/// `CGAL::Surface_mesh` built by the user) is one the package supports, with the
/// same rules as `validate_triangle_soup()`, and throws `Invalid_mesh_error`
/// otherwise.
///
/// Vertex `i` and face `j` in the messages are the `i`-th element of
/// `vertices(tm)` and the `j`-th element of `faces(tm)`: for a `CGAL::Surface_mesh`
/// without removed elements, these are its vertex and face indices.
/// A halfedge data structure cannot represent some of the rules' violations
/// (an out-of-range index, a non-manifold edge, an inconsistent orientation),
/// but it can represent all the others (non-triangle faces, isolated vertices,
/// boundaries, two faces glued on the same three vertices, non-finite
/// coordinates, several components, degenerate faces).
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam NamedParameters a sequence of named parameters (\ref GeodesicRidgeSecParameters)
///
/// \param tm the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_mesh_error if a rule fails
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
void validate_triangle_mesh(const TriangleMesh& tm,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  namespace iv = internal::validation;

  const auto maps = internal::mesh_maps(tm, np);
  using Point_3 = typename decltype(maps)::Point;
  const auto& vpm = maps.vpm;
  const auto& vim = maps.vim;

  // Flatten to a soup in iteration order and reuse the soup checks: one set
  // of rules and messages for both entry points. The index map may be sparse
  // (a Surface_mesh with removed vertices), hence the position table.
  std::vector<Point_3> points;
  std::vector<vertex_descriptor> vds;
  std::size_t max_index = 0;
  for(vertex_descriptor v : vertices(tm))
  {
    vds.push_back(v);
    points.push_back(get(vpm, v));
    max_index = (std::max)(max_index, static_cast<std::size_t>(get(vim, v)));
  }
  std::vector<std::size_t> position(vds.empty() ? 0 : max_index + 1, iv::invalid_index);
  for(std::size_t i = 0; i < vds.size(); ++i)
    position[static_cast<std::size_t>(get(vim, vds[i]))] = i;

  // Triangles (the usual case) as arrays: no heap block per face.
  bool all_triangles = true;
  for(auto f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    all_triangles = all_triangles && next(h, tm) != h && next(next(next(h, tm), tm), tm) == h;
  }
  if(all_triangles)
  {
    std::vector<std::array<std::size_t, 3>> triangles;
    triangles.reserve(static_cast<std::size_t>(num_faces(tm)));
    for(auto f : faces(tm))
    {
      const auto h = halfedge(f, tm);
      triangles.push_back({{position[static_cast<std::size_t>(get(vim, source(h, tm)))],
                            position[static_cast<std::size_t>(get(vim, target(h, tm)))],
                            position[static_cast<std::size_t>(get(vim, target(next(h, tm), tm)))]}});
    }
    validate_triangle_soup(points, triangles);
    return;
  }
  std::vector<std::vector<std::size_t>> polygons;
  for(auto f : faces(tm))
  {
    polygons.emplace_back();
    for(vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
      polygons.back().push_back(position[static_cast<std::size_t>(get(vim, v))]);
  }
  validate_triangle_soup(points, polygons);
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_MESH_VALIDATION_H
