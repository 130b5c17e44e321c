// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The heat method (Crane, Weischedel & Wardetzky 2013) through CGAL's
// Heat_method_3: heat diffused from the source for a short time, its
// normalized gradient integrated back by a Poisson solve. Smooth and
// approximate: the field is rounded off where fronts meet (at the ridge
// itself), by about the mean edge length that sets CGAL's time step.
#ifndef GEODESIC_RIDGE_SOLVERS_HEAT_METHOD_SOLVER_H
#define GEODESIC_RIDGE_SOLVERS_HEAT_METHOD_SOLVER_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/solver_from_source.h>
#include <Geodesic_ridge/source.h>

#include <CGAL/config.h>
#ifndef CGAL_EIGEN3_ENABLED
#error "Geodesic_ridge/solvers/Heat_method_solver.h needs Eigen 3 (Debian: libeigen3-dev; CMake: Eigen3::Eigen)"
#endif
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/exceptions.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
/// \ingroup PkgGeodesicRidgeSolvers
/// Model of `GeodesicSolver`: the heat method of `CGAL::Heat_method_3`, on the
/// mesh as it is (`Mode` = `CGAL::Heat_method_3::Direct`, name "heat") or on
/// its intrinsic Delaunay triangulation (`CGAL::Heat_method_3::Intrinsic_Delaunay`,
/// name "heat-idt": better on meshes with obtuse or sliver triangles).
///
/// \cgal 5.5 fixes the time step (the squared mean edge length) and takes
/// vertex sources only. A `Face_location` at a vertex is that vertex; any other
/// `Face_location` is refused with `Invalid_source_error` (spreading the heat
/// over the face's corners would move the source by up to an edge, more than
/// the method's own error: we would rather say so than blur it silently).
/// A failed sparse factorization throws `Algorithm_error`.
template <class Mode = CGAL::Heat_method_3::Direct>
struct Heat_method_solver : internal::Solver_from_source<Heat_method_solver<Mode> >
{
  static_assert(std::is_same<Mode, CGAL::Heat_method_3::Direct>::value ||
                    std::is_same<Mode, CGAL::Heat_method_3::Intrinsic_Delaunay>::value,
                "Mode: CGAL::Heat_method_3::Direct or CGAL::Heat_method_3::Intrinsic_Delaunay");

  /// "heat" or "heat-idt"
  static const char* name()
  {
    return std::is_same<Mode, CGAL::Heat_method_3::Direct>::value ? "heat" : "heat-idt";
  }

private:
  friend struct internal::Solver_from_source<Heat_method_solver<Mode> >;
  template <class TriangleMesh, class VertexDistanceMap, class NamedParameters>
  static void run(const TriangleMesh& tm, const Geodesic_source<TriangleMesh>& src, VertexDistanceMap distance,
                  const NamedParameters& np)
  {
    if(src.kind != Geodesic_source<TriangleMesh>::ON_VERTEX)
      throw Invalid_source_error(std::string("the ") + name() +
                                 " solver takes a vertex as the source (CGAL 5.5's heat method has no point "
                                 "sources): give a vertex, or choose the exact, fmm or dijkstra solver");
    // CGAL 5.5's intrinsic Delaunay mode reads the mesh's own points whatever
    // map it is given, and the heat method takes its kernel from the point
    // type: run it on a copy with the user's points as doubles
    typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Double_mesh;
    const auto maps = internal::mesh_maps(tm, np);
    Double_mesh copy;
    std::vector<typename Double_mesh::Vertex_index> copy_of(num_vertices(tm));
    for(auto v : vertices(tm))
    {
      const auto& p = get(maps.vpm, v);
      copy_of[get(maps.vim, v)] =
          copy.add_vertex(CGAL::Epick::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
    }
    for(auto f : faces(tm))
    {
      std::array<typename Double_mesh::Vertex_index, 3> c;
      int k = 0;
      for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) c[k++] = copy_of[get(maps.vim, v)];
      if(copy.add_face(c[0], c[1], c[2]) == Double_mesh::null_face())
        throw Algorithm_error("the heat method: the mesh could not be copied (not a manifold triangle mesh)");
    }
    std::vector<double> d(copy.number_of_vertices(), 0);
    // CGAL reports a failed factorization through CGAL_error_msg, which
    // throws under CGAL's default error behaviour
    try
    {
      CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Double_mesh, Mode> heat(copy);
      heat.add_source(copy_of[get(maps.vim, src.vertex)]);
      heat.estimate_geodesic_distances(CGAL::make_property_map(d));
    }
    catch(const CGAL::Failure_exception& e)
    {
      throw Algorithm_error(std::string("the heat method failed: ") + e.message());
    }
    for(auto v : vertices(tm)) put(distance, v, d[std::size_t(copy_of[get(maps.vim, v)])]);
  }
};

/// \ingroup PkgGeodesicRidgeSolvers
/// The heat method on the intrinsic Delaunay triangulation ("heat-idt").
typedef Heat_method_solver<CGAL::Heat_method_3::Intrinsic_Delaunay> Heat_method_idt_solver;

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_SOLVERS_HEAT_METHOD_SOLVER_H
