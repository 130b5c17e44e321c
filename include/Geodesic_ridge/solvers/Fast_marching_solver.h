// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fast marching on a triangle mesh (Kimmel & Sethian 1998): a Dijkstra-like
// sweep whose update across a triangle assumes a locally planar front, so the
// distances are first-order accurate and, unlike Dijkstra's on the edge graph,
// nearly isotropic. O(n log n), no system to solve.
#ifndef GEODESIC_RIDGE_SOLVERS_FAST_MARCHING_SOLVER_H
#define GEODESIC_RIDGE_SOLVERS_FAST_MARCHING_SOLVER_H

#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/solver_from_source.h>
#include <Geodesic_ridge/source.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// The kernel of the unfoldings: the mesh's points as doubles.
typedef CGAL::Exact_predicates_inexact_constructions_kernel Fast_marching_kernel;

// The distance at C from a planar front that has value ta at A and tb at B,
// if the front's ray through C crosses the segment AB (upwind); otherwise the
// better of the two edge paths through A or B.
inline double fast_marching_update(const Fast_marching_kernel::Point_3& a, double ta,
                                   const Fast_marching_kernel::Point_3& b, double tb,
                                   const Fast_marching_kernel::Point_3& c)
{
  typedef Fast_marching_kernel K;
  const K::Vector_3 ab = b - a, ac = c - a;
  const double via_edges = (std::min)(ta + std::sqrt(ac.squared_length()), tb + std::sqrt(CGAL::squared_distance(b, c)));
  const double len = std::sqrt(ab.squared_length());
  if(!(len > 0)) return via_edges;
  // the triangle laid out in the plane with A = (0, 0), B = (len, 0), C above AB
  const double cx = ac * ab / len;
  const double cy2 = ac.squared_length() - cx * cx;
  if(!(cy2 > 0)) return via_edges;
  const K::Point_2 A(0, 0), C(cx, std::sqrt(cy2));
  const K::Segment_2 AB(A, K::Point_2(len, 0));
  // circular front: a virtual source S below AB at distances ta, tb from A, B
  // (exact in a flat region around one point source)
  const double sx = (ta * ta - tb * tb + len * len) / (2 * len);
  const double sy2 = ta * ta - sx * sx;
  if(sy2 >= 0)
  {
    const K::Point_2 S(sx, -std::sqrt(sy2));
    if(!CGAL::do_intersect(K::Segment_2(S, C), AB)) return via_edges;
    return (std::min)(via_edges, std::sqrt(CGAL::squared_distance(S, C)));
  }
  // no such S (ta, tb, |AB| violate the triangle inequality): a planar front of
  // unit direction g, which reaches C if its ray back from C crosses AB
  const double gx = (tb - ta) / len;
  if(!(std::abs(gx) < 1)) return via_edges;
  const K::Vector_2 g(gx, std::sqrt(1 - gx * gx));
  if(!CGAL::do_intersect(K::Ray_2(C, -g), AB)) return via_edges;
  return (std::min)(via_edges, ta + g * (C - A));
}

/// The sweep of fast marching over the triangle mesh `tm` with points `vpm`:
/// `distance` (by vertex index) holds the known distances, `accepted` the
/// vertices whose distance is final, and the vertices of `trial` (with finite
/// distances, not accepted) start the sweep. An accepted vertex reached by a
/// front lower by more than `reopen_margin` is reopened (infinity: never, as
/// in fast marching from scratch).
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap>
void fast_marching_sweep(const TriangleMesh& tm, const VertexPointMap& vpm, const VertexIndexMap& vim,
                         const std::vector<std::size_t>& trial_vertices, std::vector<double>& distance,
                         std::vector<char>& accepted, double reopen_margin)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  const std::size_t nv = num_vertices(tm);
  std::vector<Fast_marching_kernel::Point_3> p(nv);
  std::vector<vertex_descriptor> vertex_of(nv);
  for(vertex_descriptor v : vertices(tm))
  {
    const auto& q = get(vpm, v);
    p[get(vim, v)] = Fast_marching_kernel::Point_3(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
    vertex_of[get(vim, v)] = v;
  }
  const bool reopens = reopen_margin < std::numeric_limits<double>::infinity();
  typedef std::pair<double, std::size_t> Entry;
  std::vector<Entry> initial;
  initial.reserve(trial_vertices.size());
  for(std::size_t i : trial_vertices) initial.emplace_back(distance[i], i);
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > trial(std::greater<Entry>(), std::move(initial));
  auto relax = [&](std::size_t w, double value) {
    if(!(value < distance[w])) return;
    if(accepted[w])
    {
      if(!(value < distance[w] - reopen_margin)) return;
      accepted[w] = 0;
    }
    distance[w] = value;
    trial.push(Entry(value, w));
  };
  while(!trial.empty())
  {
    const Entry top = trial.top();
    trial.pop();
    const std::size_t v = top.second;
    if(accepted[v] || top.first > distance[v]) continue;
    accepted[v] = 1;
    for(auto h : CGAL::halfedges_around_target(vertex_of[v], tm))
    {
      const std::size_t a = get(vim, source(h, tm));
      relax(a, distance[v] + std::sqrt(CGAL::squared_distance(p[a], p[v])));
      if(is_border(h, tm)) continue;
      // the face (a, v, b): a front known at v and one other corner updates the third
      const std::size_t b = get(vim, target(next(h, tm), tm));
      if(accepted[b] && !accepted[a]) relax(a, fast_marching_update(p[v], distance[v], p[b], distance[b], p[a]));
      else if(accepted[a] && !accepted[b]) relax(b, fast_marching_update(p[v], distance[v], p[a], distance[a], p[b]));
      else if(reopens && accepted[a] && accepted[b])
      {
        // all three accepted: a front that comes across (v, b) after both
        // (causal: not below them) may lower a, and likewise b
        const double ua = fast_marching_update(p[v], distance[v], p[b], distance[b], p[a]);
        if(ua >= (std::max)(distance[v], distance[b])) relax(a, ua);
        const double ub = fast_marching_update(p[v], distance[v], p[a], distance[a], p[b]);
        if(ub >= (std::max)(distance[v], distance[a])) relax(b, ub);
      }
    }
  }
}

/// Fast-marching distances from `seeds` (vertex index, initial distance) over
/// the triangle mesh `tm` with points `vpm`, written to `distance` by vertex
/// index (infinity where unreachable).
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap>
void fast_marching_distances(const TriangleMesh& tm, const VertexPointMap& vpm, const VertexIndexMap& vim,
                             const std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor,
                                                         double> >& seeds,
                             std::vector<double>& distance)
{
  const std::size_t nv = num_vertices(tm);
  distance.assign(nv, std::numeric_limits<double>::infinity());
  std::vector<char> accepted(nv, 0);
  std::vector<std::size_t> trial;
  trial.reserve(seeds.size());
  for(const auto& s : seeds)
  {
    const std::size_t i = get(vim, s.first);
    if(s.second < distance[i]) { distance[i] = s.second; trial.push_back(i); }
  }
  fast_marching_sweep(tm, vpm, vim, trial, distance, accepted, std::numeric_limits<double>::infinity());
}

} // namespace internal

/// \ingroup PkgGeodesicRidgeSolvers
/// Model of `GeodesicSolver`: first-order fast marching (Kimmel & Sethian).
/// The update across a triangle takes a circular front (a virtual point source
/// below the known edge, at the two known distances) where its ray to the
/// third corner crosses that edge, else a planar front, else the edge paths
/// (obtuse triangles are not unfolded). Much cheaper than the exact solver; errors of the order of the
/// edge length near the source. The pipeline uses it to shape the tree of
/// stage 1 (only the direction of descent matters there).
/// A point source's corners start at their straight-line distances from it.
struct Fast_marching_solver : internal::Solver_from_source<Fast_marching_solver>
{
  /// "fmm"
  static const char* name() { return "fmm"; }

private:
  friend struct internal::Solver_from_source<Fast_marching_solver>;
  template <class TriangleMesh, class VertexDistanceMap, class NamedParameters>
  static void run(const TriangleMesh& tm, const Geodesic_source<TriangleMesh>& src, VertexDistanceMap distance,
                  const NamedParameters& np)
  {
    const auto maps = internal::mesh_maps(tm, np);
    std::vector<double> d;
    internal::fast_marching_distances(tm, maps.vpm, maps.vim, src.seeds, d);
    for(auto v : vertices(tm)) put(distance, v, d[get(maps.vim, v)]);
  }
};

} // namespace Geodesic_ridge

#endif
