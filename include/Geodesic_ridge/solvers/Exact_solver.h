// Copyright (c) 2026 Geodesic_ridge developers.
//
// The exact geodesic solver: CGAL's Surface_mesh_shortest_path (MMP/Chen-Han
// style window propagation) on whatever mesh it is given.
#ifndef GEODESIC_RIDGE_SOLVERS_EXACT_SOLVER_H
#define GEODESIC_RIDGE_SOLVERS_EXACT_SOLVER_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/version.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <array>
#include <utility>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeSolvers
/// Model of `GeodesicSolver`: exact polyhedral distances by
/// `CGAL::Surface_mesh_shortest_path` (one sequence tree per call).
/// Meshes with a boundary are fine: window propagation stops at border edges.
struct Exact_solver
{
  static const char* name() { return "exact"; }

  /// Distances from vertex `s` of `tm` to every vertex, written to `distance`.
  template <class TriangleMesh, class VertexDistanceMap>
  void operator()(const TriangleMesh& tm,
                  typename boost::graph_traits<TriangleMesh>::vertex_descriptor s,
                  VertexDistanceMap distance) const
  {
    SMSP<TriangleMesh> sp(tm);
    sp.add_source_point(s);
    solve(tm, sp, distance);
  }

  /// Distances from the point `loc` (face + barycentric coordinates, CGAL's order).
  template <class TriangleMesh, class FT, class VertexDistanceMap>
  void operator()(const TriangleMesh& tm,
                  const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                  std::array<FT, 3> >& loc,
                  VertexDistanceMap distance) const
  {
    SMSP<TriangleMesh> sp(tm);
    std::array<FT, 3> w = loc.second;
#if CGAL_VERSION_NR < CGAL_VERSION_NUMBER(5, 6, 0)
    // CGAL before 5.6 starts no cone towards the ends of the edge that holds a
    // source point (CGAL issue #6681, fixed by pull request #6739): measured on
    // the doubly covered square, distances 0.4 mean edges too long. The point
    // is moved into the face by 2^-40 of its barycentric range instead, which
    // changes distances by about 1e-13 of an edge.
    int zeros = 0;
    for(const FT& x : w) zeros += (x == FT(0));
    if(zeros == 1)
    {
      const FT nudge = FT(1) / FT(1099511627776.0);
      for(FT& x : w) x = (x == FT(0)) ? nudge : x * (FT(1) - nudge);
    }
#endif
    typename SMSP<TriangleMesh>::Barycentric_coordinates b = {{w[0], w[1], w[2]}};
    sp.add_source_point(loc.first, b);
    solve(tm, sp, distance);
  }

private:
  template <class TriangleMesh>
  using Traits = CGAL::Surface_mesh_shortest_path_traits<
      typename CGAL::Kernel_traits<typename boost::property_traits<typename boost::property_map<
          TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel,
      TriangleMesh>;
  template <class TriangleMesh>
  using SMSP = CGAL::Surface_mesh_shortest_path<Traits<TriangleMesh> >;

  template <class TriangleMesh, class Solver, class VertexDistanceMap>
  static void solve(const TriangleMesh& tm, Solver& sp, VertexDistanceMap distance)
  {
    sp.build_sequence_tree();
    for(auto v : vertices(tm)) put(distance, v, CGAL::to_double(sp.shortest_distance_to_source_points(v).first));
  }
};

} // namespace Geodesic_ridge

#endif
