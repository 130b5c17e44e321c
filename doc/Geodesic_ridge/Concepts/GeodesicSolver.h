// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/*!
\ingroup PkgGeodesicRidgeConcepts
\cgalConcept

A `GeodesicSolver` computes geodesic distances on a triangle mesh from one
source, for every vertex. It knows nothing of ridges: stage 2 of the pipeline
runs it on the extended surface, a `CGAL::Surface_mesh` with a boundary, whose
vertices of cone angle up to 4π (at the ends of the cut) are border vertices.

\cgalHasModel `Geodesic_ridge::Exact_solver` (CGAL `Surface_mesh_shortest_path`)
\cgalHasModel `Geodesic_ridge::Fast_marching_solver` (first-order fast marching)
\cgalHasModel `Geodesic_ridge::Heat_method_solver` (`CGAL::Heat_method_3`, direct or on the intrinsic Delaunay triangulation; vertex sources only)
\cgalHasModel `Geodesic_ridge::Dijkstra_solver` (shortest paths along edges; a baseline)
\cgalHasModel `Geodesic_ridge::Window_propagation_solver` (exact window propagation, VTP)

The named parameter `Geodesic_ridge::parameters::solver()` passes a model to the
pipeline (user manual: \ref GeodesicRidgeSecSolvers). A model of your own is
taken as approximate unless it declares `static constexpr bool is_exact = true`
(`Geodesic_ridge::Geodesic_solver_traits`), in which case it must also offer
`Exact_solver`'s cone query (a wrapper of `Exact_solver` forwards it) unless
it declares `has_cones = false`. A model that declares `has_windows = true`
(`Window_propagation_solver`) offers the cone query with one more argument, a
pointer to a `std::vector<std::vector<Face_cone> >` that it fills with the
windows of every wanted face (`Face_cone::entry` set): the cone field is then
their exact lower envelope;
\ref custom_solver_example.cpp is one in a few lines. Models are copied: keep state that must outlive a call behind a
pointer. This file documents the concept; it is no header to include.
*/
class GeodesicSolver
{
public:
  /// a short name, used in statistics and on the command line (`--solver NAME`)
  static const char* name();

  /// Writes the distance from vertex `s` to every vertex `v` of `tm` with `put(distance, v, d)`.
  /// `VertexDistanceMap` is a writable property map from vertices to `double`.
  /// The geometry is that of the named parameter `vertex_point_map` of `np`
  /// (default: the mesh's own points); the pipeline passes the user's map, so
  /// that every stage sees the same geometry.
  template <class TriangleMesh, class VertexDistanceMap, class NamedParameters>
  void operator()(const TriangleMesh& tm,
                  typename boost::graph_traits<TriangleMesh>::vertex_descriptor s,
                  VertexDistanceMap distance,
                  const NamedParameters& np = CGAL::parameters::default_values()) const;

  /// Same from a surface point: a face and its barycentric coordinates, in the order
  /// `source(halfedge(f))`, `target(halfedge(f))`, `target(next(halfedge(f)))`.
  template <class TriangleMesh, class FT, class VertexDistanceMap, class NamedParameters>
  void operator()(const TriangleMesh& tm,
                  const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                  std::array<FT, 3> >& source,
                  VertexDistanceMap distance,
                  const NamedParameters& np = CGAL::parameters::default_values()) const;
};
