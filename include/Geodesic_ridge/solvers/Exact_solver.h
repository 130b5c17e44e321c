// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact geodesic solver: CGAL's Surface_mesh_shortest_path (MMP/Chen-Han
// style window propagation) on whatever mesh it is given.
#ifndef GEODESIC_RIDGE_SOLVERS_EXACT_SOLVER_H
#define GEODESIC_RIDGE_SOLVERS_EXACT_SOLVER_H

#include <Geodesic_ridge/internal/corner_angles.h>
#include <Geodesic_ridge/solvers/Face_cone.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/smsp_source_coordinates.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeSolvers
/// Model of `GeodesicSolver`: exact polyhedral distances by
/// `CGAL::Surface_mesh_shortest_path` (one sequence tree per call).
/// Meshes with a boundary are fine: window propagation stops at border edges.
struct Exact_solver
{
  /// "exact"
  static const char* name() { return "exact"; }
  /// `true`: exact distances, and the cone query (`Geodesic_solver_traits`)
  static constexpr bool is_exact = true;

  /// Distances from vertex `s` of `tm` to every vertex, written to `distance`,
  /// on the geometry of the named parameter `vertex_point_map` (default: the
  /// mesh's own points).
  template <class TriangleMesh, class VertexDistanceMap,
            class NamedParameters = CGAL::parameters::Default_named_parameters>
  void operator()(const TriangleMesh& tm,
                  typename boost::graph_traits<TriangleMesh>::vertex_descriptor s,
                  VertexDistanceMap distance,
                  const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    with_shortest_paths(tm, np, [&](auto& sp) {
      add_source(tm, sp, s);
      solve(tm, sp, distance);
    });
  }

  /// Distances from the point `loc` (face + barycentric coordinates, CGAL's order).
  /// With \cgal before 5.6, a point on an edge is moved into its face by 2^-40
  /// of the barycentric range (\cgal issue 6681: no cone towards the ends of
  /// the source's edge), which changes distances by about 1e-13 of an edge.
  template <class TriangleMesh, class FT, class VertexDistanceMap,
            class NamedParameters = CGAL::parameters::Default_named_parameters>
  void operator()(const TriangleMesh& tm,
                  const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                  std::array<FT, 3> >& loc,
                  VertexDistanceMap distance,
                  const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    with_shortest_paths(tm, np, [&](auto& sp) {
      add_source(tm, sp, loc);
      solve(tm, sp, distance);
    });
  }

  /// Same (on the mesh's own points), and the cones of the faces: `cones[S * i + j]` is the cone of the
  /// face of index i (`face_index`) at its sample point j
  /// (`cone_samples()`, S of them), read from the shortest path from that
  /// point (its first straight piece and the distance at its first bend), for
  /// every face for which `wanted(i)` is true; `wanted` is called after the
  /// distances are written. The optional query of the `GeodesicSolver` concept
  /// that the cone field needs.
  template <class TriangleMesh, class Source, class VertexDistanceMap, class Wanted>
  void operator()(const TriangleMesh& tm, const Source& s, VertexDistanceMap distance, std::vector<Face_cone>& cones,
                  const Wanted& wanted) const
  {
    (*this)(tm, s, distance, cones, wanted, cone_samples());
  }

  /// Same, at the given sample points instead of `cone_samples()`.
  template <class TriangleMesh, class Source, class VertexDistanceMap, class Wanted>
  void operator()(const TriangleMesh& tm, const Source& s, VertexDistanceMap distance, std::vector<Face_cone>& cones,
                  const Wanted& wanted, const std::vector<std::array<double, 3> >& samples) const
  {
    SMSP<TriangleMesh> sp(tm);
    add_source(tm, sp, s);
    solve(tm, sp, distance);
    face_cones(tm, sp, cones, wanted, samples);
  }

  /// \name Sample sets
  /// The points of a face whose shortest paths give its cones: those of
  /// `Cone_samples` (with `Face_cone` in solvers/Face_cone.h, which stage 3
  /// reads without this solver's header).
  /// @{
  /// `Cone_samples::cone_samples()`
  static const std::vector<std::array<double, 3> >& cone_samples() { return Cone_samples::cone_samples(); }
  /// `Cone_samples::cone_ridge_samples()`
  static const std::vector<std::array<double, 3> >& cone_ridge_samples() { return Cone_samples::cone_ridge_samples(); }
  /// `Cone_samples::corner_samples()`
  static const std::vector<std::array<double, 3> >& corner_samples() { return Cone_samples::corner_samples(); }
  /// `Cone_samples::corner_fallback_samples()`
  static const std::vector<std::array<double, 3> >& corner_fallback_samples()
  {
    return Cone_samples::corner_fallback_samples();
  }
  /// `Cone_samples::cone_ridge_fallback_samples()`
  static const std::vector<std::array<double, 3> >& cone_ridge_fallback_samples()
  {
    return Cone_samples::cone_ridge_fallback_samples();
  }
  /// @}

private:
  template <class TriangleMesh>
  using Traits = CGAL::Surface_mesh_shortest_path_traits<
      typename CGAL::Kernel_traits<typename boost::property_traits<typename boost::property_map<
          TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel,
      TriangleMesh>;
  template <class TriangleMesh>
  using SMSP = CGAL::Surface_mesh_shortest_path<Traits<TriangleMesh> >;

  // Calls f with CGAL's shortest-path solver on `tm` with the point map of `np`.
  template <class TriangleMesh, class NamedParameters, class F>
  static void with_shortest_paths(const TriangleMesh& tm, const NamedParameters& np, const F& f)
  {
    const auto vpm = internal::mesh_maps(tm, np).vpm;
    typedef std::decay_t<decltype(vpm)> Vertex_point_map;
    typedef typename CGAL::Kernel_traits<typename boost::property_traits<Vertex_point_map>::value_type>::Kernel K;
    CGAL::Surface_mesh_shortest_path<CGAL::Surface_mesh_shortest_path_traits<K, TriangleMesh>, CGAL::Default,
                                     CGAL::Default, CGAL::Default, Vertex_point_map>
        sp(tm, get(boost::vertex_index, tm), get(boost::halfedge_index, tm), get(boost::face_index, tm), vpm);
    f(sp);
  }

  template <class TriangleMesh, class Solver>
  static void add_source(const TriangleMesh&, Solver& sp,
                         typename boost::graph_traits<TriangleMesh>::vertex_descriptor s)
  {
    sp.add_source_point(s);
  }

  template <class TriangleMesh, class Solver, class FT>
  static void add_source(const TriangleMesh&, Solver& sp,
                         const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                         std::array<FT, 3> >& loc)
  {
    // (before CGAL 5.6, a point on an edge is moved into its face)
    const std::array<FT, 3> w = internal::smsp_source_coordinates(loc.second);
    typename Solver::Barycentric_coordinates b = {{w[0], w[1], w[2]}};
    sp.add_source_point(loc.first, b);
  }

  // The cones of the wanted faces, from the shortest paths from their sample
  // points: a path runs straight (in the unfolding) from the sample to its
  // first bend (a saddle or border vertex, or the source vertex) or to the
  // source point, the apex; the apex lies along the path's first piece at the
  // length of the path up to it, and the apex's distance is the offset. A path
  // goes straight through a flat vertex (angle sum 2π within 1e-9: on a
  // lattice, paths meet vertices exactly), so that is no bend.
  template <class TriangleMesh, class Solver, class Wanted>
  static void face_cones(const TriangleMesh& tm, Solver& sp, std::vector<Face_cone>& cones, const Wanted& wanted,
                         const std::vector<std::array<double, 3> >& samples)
  {
    typedef typename Solver::Point_3 Point_3;
    const auto vpm = get(CGAL::vertex_point, tm);
    const auto fim = get(CGAL::face_index, tm);
    const std::vector<char> bends = bending_vertices(tm);
    const std::size_t S = samples.size();
    cones.assign(S * num_faces(tm), Face_cone());
    for(auto f : faces(tm))
    {
      if(!wanted(static_cast<std::size_t>(get(fim, f)))) continue;
      const auto h = halfedge(f, tm);
      const Point_3 p[3] = {get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm))};
      for(std::size_t i = 0; i < S; ++i) cones[S * get(fim, f) + i] = cone_at(tm, sp, bends, f, p, samples[i]);
    }
  }

  // The vertices where a shortest path may bend: border vertices and those
  // whose angle sum is not 2π (within 1e-9: on a lattice, paths meet flat
  // vertices exactly and go straight through).
  template <class TriangleMesh>
  static std::vector<char> bending_vertices(const TriangleMesh& tm)
  {
    const auto vim = get(CGAL::vertex_index, tm);
    const internal::Corner_angles angles =
        internal::corner_angles(tm, get(CGAL::vertex_point, tm), vim, get(CGAL::face_index, tm));
    std::vector<char> bends(num_vertices(tm), 1);
    for(auto v : vertices(tm))
      bends[get(vim, v)] = is_border(v, tm) || std::abs(angles.curvature(get(vim, v))) > 1e-9 * 2 * CGAL_PI;
    return bends;
  }

  // thrown at the first bend: the visitor of Surface_mesh_shortest_path
  // cannot stop a walk, and the rest of the path (to the source) is not needed
  struct Apex_found {};

  // thrown where the path crosses an edge at one of its ends (within
  // `through_vertex` of the edge) at a vertex that does not bend it: the walk
  // goes on from that vertex. SMSP's walk cannot go on by itself: past a
  // crossing at a vertex its next ray can be parallel to the next edge, and its
  // assertion `bool(cgalIntersection)` fails (with NDEBUG it dereferences an
  // empty optional). Found by the pipeline fuzzer (fuzz/corpus/pipeline/
  // smsp_first_bend_no_intersection: a path along a border of E).
  template <class Vertex>
  struct Through_vertex { Vertex v; };

  // an edge crossing this close to an end (a fraction of the edge) passes
  // through the end: SMSP's crossings there are off by about 1e-16
  static constexpr double through_vertex = 1e-12;

  // A visitor of the path from a sample point that stops at its first bend.
  template <class TriangleMesh, class Solver>
  struct First_bend
  {
    typedef typename Solver::Point_3 Point_3;
    typedef boost::graph_traits<TriangleMesh> GT;
    typedef typename GT::vertex_descriptor vertex_descriptor;
    const TriangleMesh& tm;
    Solver& sp;
    const std::vector<char>& bends;
    typename boost::property_map<TriangleMesh, CGAL::vertex_index_t>::const_type vim;
    Point_3 last;              // the previous point of the path
    bool have_direction = false;
    Point_3 towards = last;    // a point of the first straight piece
    double length = 0;         // of the path so far
    double apex_distance = 0;  // the distance at the first bend
    vertex_descriptor start = GT::null_vertex(); // the vertex a walk goes on from

    void step(const Point_3& p)
    {
      length += std::sqrt(CGAL::to_double(CGAL::squared_distance(last, p)));
      last = p;
      if(!have_direction) { towards = p; have_direction = true; }
    }
    // at vertex v: the apex if the path bends there; otherwise on from v
    // (through_edge_end) or on with SMSP's walk (a pseudo-source node)
    bool bends_at(vertex_descriptor v)
    {
      step(sp.point(v));
      apex_distance = CGAL::to_double(sp.shortest_distance_to_source_points(v).first);
      return bends[get(vim, v)] || apex_distance <= 0;
    }
    void operator()(typename GT::halfedge_descriptor h, typename Solver::FT t)
    {
      const double s = CGAL::to_double(t); // the weight of the edge's target
      if(s > through_vertex && s < 1 - through_vertex) { step(sp.point(h, t)); return; }
      const vertex_descriptor v = s <= through_vertex ? source(h, tm) : target(h, tm);
      if(v == start) { apex_distance = CGAL::to_double(sp.shortest_distance_to_source_points(v).first); throw Apex_found(); }
      if(bends_at(v)) throw Apex_found();
      throw Through_vertex<vertex_descriptor>{v};
    }
    void operator()(vertex_descriptor v)
    {
      if(v == start) return; // the walk's first call
      if(bends_at(v)) throw Apex_found();
      // straight through a flat vertex that SMSP made a pseudo-source
    }
    void operator()(typename GT::face_descriptor f, typename Solver::Barycentric_coordinates b)
    {
      const Point_3 p = sp.point(f, b);
      if(p == last && length == 0 && !have_direction) return; // the query point itself
      step(p);
      apex_distance = 0; // the source point
      throw Apex_found();
    }
  };

  // The cone of face f (corners p) at the sample point of barycentric sb.
  template <class TriangleMesh, class Solver>
  static Face_cone cone_at(const TriangleMesh& tm, Solver& sp, const std::vector<char>& bends,
                           typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                           const typename Solver::Point_3 (&p)[3], const std::array<double, 3>& sb)
  {
    typedef typename Solver::Point_3 Point_3;
    typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
    const typename Solver::Barycentric_coordinates at = {{sb[0], sb[1], sb[2]}};
    const Point_3 q = sp.point(f, at);
    First_bend<TriangleMesh, Solver> bend{tm, sp, bends, get(CGAL::vertex_index, tm), q};
    Face_cone cone;
    cone.apex = sb;
    try
    {
      // no apex found: no path (another component), or a source at q
      cone.offset = CGAL::to_double(sp.shortest_path_sequence_to_source_points(f, at, bend).first);
      return cone;
    }
    catch(const Apex_found&) {}
    catch(const Through_vertex<vertex_descriptor>& through)
    {
      // on from each flat vertex the path runs through; the distance falls
      // along the path, so this ends (the bound only guards against rounding)
      bend.start = through.v;
      for(std::size_t walks = 1; walks <= num_vertices(tm); ++walks)
      {
        try
        {
          sp.shortest_path_sequence_to_source_points(bend.start, bend);
          break; // no apex past the vertex: it is the apex (offset set there)
        }
        catch(const Apex_found&) { break; }
        catch(const Through_vertex<vertex_descriptor>& next) { bend.start = next.v; }
      }
    }
    const auto w = bend.towards - q;
    const double wl = std::sqrt(CGAL::to_double(w.squared_length()));
    cone.offset = bend.apex_distance;
    if(wl == 0) return cone; // the sample is the apex
    cone.apex = barycentric_in_plane(p, q + w * bend.length / wl);
    return cone;
  }

  // Barycentric coordinates of x (in the plane of triangle p) in the triangle.
  template <class Point_3>
  static std::array<double, 3> barycentric_in_plane(const Point_3 (&p)[3], const Point_3& x)
  {
    const auto a = p[1] - p[0], b = p[2] - p[0], c = x - p[0];
    // solve c = u a + v b in the least-squares sense (x lies in the plane)
    const double aa = CGAL::to_double(a * a), bb = CGAL::to_double(b * b), ab = CGAL::to_double(a * b),
                 ca = CGAL::to_double(c * a), cb = CGAL::to_double(c * b);
    const double det = aa * bb - ab * ab;
    const double u = (ca * bb - cb * ab) / det, v = (cb * aa - ca * ab) / det;
    return {{1 - u - v, u, v}};
  }

  template <class TriangleMesh, class Solver, class VertexDistanceMap>
  static void solve(const TriangleMesh& tm, Solver& sp, VertexDistanceMap distance)
  {
    sp.build_sequence_tree();
    for(auto v : vertices(tm)) put(distance, v, CGAL::to_double(sp.shortest_distance_to_source_points(v).first));
  }
};

} // namespace Geodesic_ridge

#endif
