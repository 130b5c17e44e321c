// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shortest paths along the edges of a mesh (Boost.Graph's Dijkstra), from
// seeds with initial distances: the tree of stage 1 and Dijkstra_solver.
#ifndef GEODESIC_RIDGE_INTERNAL_EDGE_GRAPH_DISTANCES_H
#define GEODESIC_RIDGE_INTERNAL_EDGE_GRAPH_DISTANCES_H

#include <Geodesic_ridge/internal/mesh_maps.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/property_map.hpp>

#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

/// Dijkstra on the edge graph of `tm` (edge lengths from `maps.vpm`, written to
/// `length` by edge index) from `seeds` (vertex, initial distance): `distance`
/// and `parent` by vertex index (infinity and the vertex itself where
/// unreachable; a seed is its own parent).
template <class TriangleMesh, class Maps>
void edge_graph_distances(
    const TriangleMesh& tm, const Maps& maps,
    const std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, double> >& seeds,
    std::vector<double>& length, std::vector<double>& distance,
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& parent)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  length.resize(num_edges(tm));
  for(auto e : edges(tm)) length[get(maps.eim, e)] = distance_between(maps.vpm, source(e, tm), target(e, tm));
  const double inf = std::numeric_limits<double>::infinity();
  distance.assign(num_vertices(tm), inf);
  parent.resize(num_vertices(tm));
  for(vertex_descriptor v : vertices(tm)) parent[get(maps.vim, v)] = v;
  std::vector<vertex_descriptor> roots;
  for(const auto& s : seeds)
  {
    double& d = distance[get(maps.vim, s.first)];
    if(s.second < d) d = s.second;
    roots.push_back(s.first);
  }
  boost::dijkstra_shortest_paths_no_init(
      tm, roots.begin(), roots.end(), boost::make_iterator_property_map(parent.begin(), maps.vim),
      boost::make_iterator_property_map(distance.begin(), maps.vim),
      boost::make_iterator_property_map(length.begin(), maps.eim), maps.vim, std::less<double>(),
      boost::closed_plus<double>(inf), 0.0, boost::default_dijkstra_visitor());
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_EDGE_GRAPH_DISTANCES_H
