// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Graph distances: Boost.Graph's Dijkstra on the mesh's edges. The cheapest
// solver and the crudest: a path along edges is longer than the geodesic, by
// an excess that depends on the direction (staircase paths), so the field's
// gradient is noisy. A baseline.
#ifndef GEODESIC_RIDGE_SOLVERS_DIJKSTRA_SOLVER_H
#define GEODESIC_RIDGE_SOLVERS_DIJKSTRA_SOLVER_H

#include <Geodesic_ridge/internal/edge_graph_distances.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/solver_from_source.h>
#include <Geodesic_ridge/source.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeSolvers
/// Model of `GeodesicSolver`: shortest paths along the edges of the mesh
/// (Boost.Graph's Dijkstra, edge lengths from the vertex point map). An upper
/// bound of the geodesic distance, too long by a direction-dependent amount
/// (on average 7.5-13 % on the test meshes, `test_solvers.cpp`): a baseline
/// for the accuracy tables, not a solver for precise ridges.
/// A point source's corners start at their straight-line distances from it.
struct Dijkstra_solver : internal::Solver_from_source<Dijkstra_solver>
{
  /// "dijkstra"
  static const char* name() { return "dijkstra"; }

private:
  friend struct internal::Solver_from_source<Dijkstra_solver>;
  template <class TriangleMesh, class VertexDistanceMap, class NamedParameters>
  static void run(const TriangleMesh& tm, const Geodesic_source<TriangleMesh>& src, VertexDistanceMap distance,
                  const NamedParameters& np)
  {
    const auto maps = internal::mesh_maps(tm, np);
    std::vector<double> length, d;
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> parent;
    internal::edge_graph_distances(tm, maps, src.seeds, length, d, parent);
    for(auto v : vertices(tm)) put(distance, v, d[get(maps.vim, v)]);
  }
};

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_SOLVERS_DIJKSTRA_SOLVER_H
