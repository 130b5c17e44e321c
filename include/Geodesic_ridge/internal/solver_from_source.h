// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The two calls of the GeodesicSolver concept (from a vertex, from a
// Face_location) for a model that works from the validated source.
#ifndef GEODESIC_RIDGE_INTERNAL_SOLVER_FROM_SOURCE_H
#define GEODESIC_RIDGE_INTERNAL_SOLVER_FROM_SOURCE_H

#include <Geodesic_ridge/source.h>

#include <CGAL/Named_function_parameters.h>

#include <array>
#include <utility>

namespace Geodesic_ridge {
namespace internal {

/// Base of the models that compute from a `Geodesic_source` (its vertex, or
/// its seeds: the corners of the faces that hold a point at their straight
/// distances): `Derived` has a static `run(tm, source, distance, np)`.
template <class Derived>
struct Solver_from_source
{
  /// Distances from vertex `s` of `tm` to every vertex, written to `distance`
  /// (infinity where unreachable), on the geometry of the named parameter
  /// `vertex_point_map` (default: the mesh's own points).
  template <class TriangleMesh, class VertexDistanceMap,
            class NamedParameters = CGAL::parameters::Default_named_parameters>
  void operator()(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::vertex_descriptor s,
                  VertexDistanceMap distance, const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    Derived::run(tm, make_source(tm, s, np), distance, np);
  }

  /// Same from the point `loc` (face + barycentric coordinates, CGAL's order;
  /// a point on an edge or at a vertex is that edge's or vertex's).
  template <class TriangleMesh, class FT, class VertexDistanceMap,
            class NamedParameters = CGAL::parameters::Default_named_parameters>
  void operator()(const TriangleMesh& tm,
                  const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                  std::array<FT, 3> >& loc,
                  VertexDistanceMap distance, const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    Derived::run(tm, make_source(tm, loc, np), distance, np);
  }
};

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_SOLVER_FROM_SOURCE_H
