// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The checks that name the culprit when a ridge is off (issue 10), for tests
// and for `bench_ridge_accuracy --diagnose`:
//
//  * exact copies: the extended surface E holds every shortest path iff every
//    vertex of M has a copy in E whose distance is its distance on M. With the
//    exact solver the reference is SMSP on M (relative 1e-9); with fast
//    marching it is fast marching on M, off the ridge only: on M, fast
//    marching mixes the two fronts in the triangles that straddle the ridge
//    (its update takes one corner from each), which no sheet of E does, so
//    within two rings of the ridge M's value is below every copy's.
//  * ridge fronts: on every face with two or more cells (the ridge crosses
//    it), the lowest winning copy at each corner carries that corner's
//    distance on M: the fronts that meet there are the right ones.
#ifndef GEODESIC_RIDGE_TEST_SUPPORT_EXTENSION_CHECKS_H
#define GEODESIC_RIDGE_TEST_SUPPORT_EXTENSION_CHECKS_H

#include <Geodesic_ridge/solvers/Fast_marching_solver.h>

#include <CGAL/Surface_mesh_shortest_path.h>
#include <Geodesic_ridge/internal/smsp_source_coordinates.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace testing {

/// Distances at the vertices of `tm` (by vertex index) from a vertex or a
/// `Face_location`: exact (CGAL's own SMSP, not the package's wrapper) or fast
/// marching.
template <class Kernel, class TriangleMesh, class Source>
std::vector<double> distances_on_mesh(const TriangleMesh& tm, const Source& source, bool exact)
{
  std::vector<double> d(num_vertices(tm));
  if(exact)
  {
    typedef CGAL::Surface_mesh_shortest_path_traits<Kernel, TriangleMesh> Traits;
    CGAL::Surface_mesh_shortest_path<Traits> sp(tm);
    if constexpr(std::is_same<Source, typename boost::graph_traits<TriangleMesh>::vertex_descriptor>::value)
      sp.add_source_point(source);
    else
    {
      const auto w = Geodesic_ridge::internal::smsp_source_coordinates(source.second);
      sp.add_source_point(source.first, {{w[0], w[1], w[2]}});
    }
    sp.build_sequence_tree();
    for(auto v : vertices(tm)) d[std::size_t(get(CGAL::vertex_index, tm, v))] = sp.shortest_distance_to_source_points(v).first;
  }
  else
  {
    auto map = boost::make_iterator_property_map(d.begin(), get(CGAL::vertex_index, tm));
    Fast_marching_solver()(tm, source, map);
  }
  return d;
}

/// `n` random points inside faces of `tm` as `Face_location`s: a face drawn
/// uniformly by index, a point uniform on it (`std::mt19937(seed)`).
template <class TriangleMesh>
std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor, std::array<double, 3> > >
random_face_locations(const TriangleMesh& tm, std::size_t n, unsigned seed)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  std::vector<face_descriptor> face_of(num_faces(tm));
  for(auto f : faces(tm)) face_of[std::size_t(get(CGAL::face_index, tm, f))] = f;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> face(0, face_of.size() - 1);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<std::pair<face_descriptor, std::array<double, 3> > > out;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double r1 = std::sqrt(unit(rng)), r2 = unit(rng);
    out.emplace_back(face_of[face(rng)], std::array<double, 3>{{1 - r1, r1 * (1 - r2), r1 * r2}});
  }
  return out;
}

/// What `check_extension` found.
struct Extension_check
{
  std::size_t checked_vertices = 0;
  std::vector<std::size_t> missing;  ///< vertices with no copy at their distance on M
  double worst_excess = 0;           ///< largest (best copy - distance on M), in mean edges
  std::size_t front_errors = 0;      ///< corners of ridge faces whose winning copies miss it
};

/// Checks a `Ridge_curve` `rc` of `tm` against `on_mesh`, the distances on M
/// (by vertex index), with tolerance `relative` * (distance + mean edge).
/// Vertices within `skip_rings` rings of a face that the ridge crosses are not
/// checked (0 for the exact solver; fast marching's reference, see above).
template <class TriangleMesh, class RidgeCurve>
Extension_check check_extension(const TriangleMesh& tm, const RidgeCurve& rc, const std::vector<double>& on_mesh,
                                double relative, int skip_rings = 0)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  const auto vpm = get(CGAL::vertex_point, tm);
  double mean_edge = 0;
  for(auto e : edges(tm))
    mean_edge += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(e, tm)), get(vpm, target(e, tm)))));
  mean_edge /= double(num_edges(tm));
  auto vi = [&](typename GT::vertex_descriptor v) { return std::size_t(get(CGAL::vertex_index, tm, v)); };
  auto fi = [&](typename GT::face_descriptor f) { return std::size_t(get(CGAL::face_index, tm, f)); };
  auto tolerance = [&](std::size_t v) { return relative * (on_mesh[v] + mean_edge); };

  // faces the ridge crosses: several cells, or a ridge point on them
  std::vector<char> ridge_face(num_faces(tm), 0);
  for(const auto& cells : rc.regions)
    if(cells.size() > 1) ridge_face[std::size_t(&cells - rc.regions.data())] = 1;
  for(const auto& pl : rc.polylines)
    for(const auto& p : pl) ridge_face[p.face] = 1;
  std::vector<char> near_ridge(num_vertices(tm), 0);
  if(skip_rings > 0)
    for(int ring = 0; ring < skip_rings; ++ring)
    {
      std::vector<char> next = near_ridge;
      for(auto f : faces(tm))
      {
        bool touched = ridge_face[fi(f)] != 0;
        for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) touched = touched || (ring > 0 && near_ridge[vi(v)]);
        if(touched)
          for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) next[vi(v)] = 1;
      }
      near_ridge.swap(next);
    }

  Extension_check out;
  for(auto v : vertices(tm))
  {
    const std::size_t i = vi(v);
    if(near_ridge[i]) continue;
    ++out.checked_vertices;
    const double excess = rc.vertex_distances[i] - on_mesh[i];
    if(excess > tolerance(i))
    {
      out.missing.push_back(i);
      out.worst_excess = std::max(out.worst_excess, excess / mean_edge);
    }
  }
  for(auto f : faces(tm))
  {
    const auto& cells = rc.regions[fi(f)];
    if(cells.size() < 2) continue;
    auto h = halfedge(f, tm);
    for(int k = 0; k < 3; ++k, h = next(h, tm))
    {
      const std::size_t v = vi(source(h, tm));
      if(near_ridge[v]) continue;
      double best = std::numeric_limits<double>::infinity();
      for(const auto& c : cells) best = std::min(best, c.field[k]);
      if(std::abs(best - on_mesh[v]) > tolerance(v)) ++out.front_errors;
    }
  }
  return out;
}

} // namespace testing
} // namespace Geodesic_ridge

#endif
