// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The topology of a ridge as a user reads it back: from a written CGAL
// polylines file (`n x1 y1 z1 ... xn yn zn` per line) and the mesh, with no
// Face_location and no code of the pipeline. Points within `fraction` of the
// bounding box's diagonal are one point (default 1e-12); a point within that
// of a border edge is joined to the edge's border loop, which counts as one
// node and as the cycle it is. A correct ridge with the border is connected
// (1 component) with cycle rank 2g + b.
#ifndef GEODESIC_RIDGE_TEST_SUPPORT_WRITTEN_RIDGE_TOPOLOGY_H
#define GEODESIC_RIDGE_TEST_SUPPORT_WRITTEN_RIDGE_TOPOLOGY_H

#include <CGAL/Bbox_3.h>
#include <CGAL/Kernel_traits.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace testing {

struct Written_ridge_topology
{
  std::size_t points = 0;      ///< distinct points after merging
  std::size_t segments = 0;    ///< distinct segments between them
  std::size_t components = 0;  ///< of the ridge with the border loops
  std::size_t cycles = 0;      ///< cycle rank, the loops counted as cycles
  std::size_t border_loops = 0;
  std::size_t merged_points = 0; ///< points written apart and read as one
  int genus = 0;               ///< of the mesh, from its Euler characteristic
  std::size_t expected_cycles() const { return std::size_t(2 * genus) + border_loops; }
  bool holds() const { return components == 1 && cycles == expected_cycles(); }
};

namespace written_ridge_detail {

struct Disjoint_sets
{
  std::vector<std::size_t> up;
  std::size_t add() { up.push_back(up.size()); return up.size() - 1; }
  std::size_t root(std::size_t x)
  {
    while(up[x] != x) x = up[x] = up[up[x]];
    return x;
  }
  bool join(std::size_t a, std::size_t b)
  {
    a = root(a), b = root(b);
    if(a == b) return false;
    up[a] = b;
    return true;
  }
};

inline double distance_to_segment(const std::array<double, 3>& p, const std::array<double, 3>& a,
                                  const std::array<double, 3>& b)
{
  double ab2 = 0, t = 0;
  for(int k = 0; k < 3; ++k) { ab2 += (b[k] - a[k]) * (b[k] - a[k]); t += (p[k] - a[k]) * (b[k] - a[k]); }
  t = ab2 > 0 ? std::max(0.0, std::min(1.0, t / ab2)) : 0.0;
  double d2 = 0;
  for(int k = 0; k < 3; ++k) { const double q = a[k] + t * (b[k] - a[k]) - p[k]; d2 += q * q; }
  return std::sqrt(d2);
}

} // namespace written_ridge_detail

/// The polylines of a CGAL polylines file (throws std::runtime_error on a malformed line).
inline std::vector<std::vector<std::array<double, 3> > > read_polylines_file(const std::string& file)
{
  std::ifstream in(file);
  if(!in) throw std::runtime_error("cannot open " + file);
  std::vector<std::vector<std::array<double, 3> > > out;
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream is(line);
    std::size_t n = 0;
    if(!(is >> n)) continue; // (an empty line)
    std::vector<std::array<double, 3> > pl(n);
    for(auto& p : pl)
      if(!(is >> p[0] >> p[1] >> p[2])) throw std::runtime_error("short polyline in " + file);
    out.push_back(std::move(pl));
  }
  return out;
}

/// The topology of `polylines` on `mesh` (any CGAL FaceGraph with a point per vertex).
template <class Mesh>
Written_ridge_topology written_ridge_topology(const Mesh& mesh,
                                              const std::vector<std::vector<std::array<double, 3> > >& polylines,
                                              double fraction = 1e-12)
{
  using namespace written_ridge_detail;
  auto xyz = [&](auto v) {
    const auto& p = mesh.point(v);
    return std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  CGAL::Bbox_3 box;
  for(auto v : mesh.vertices()) box += mesh.point(v).bbox();
  const double tol = fraction * std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                          CGAL::square(box.zmax() - box.zmin()));
  Written_ridge_topology t;
  const long chi = long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces());

  // border loops: border vertices joined along border edges
  Disjoint_sets sets;
  std::map<std::size_t, std::size_t> node_of_vertex;
  auto vertex_node = [&](auto v) {
    const auto [it, added] = node_of_vertex.emplace(std::size_t(v), 0);
    if(added) it->second = sets.add();
    return it->second;
  };
  std::vector<std::pair<std::array<double, 3>, std::array<double, 3> > > border_edges;
  std::vector<std::size_t> border_edge_node;
  for(auto h : mesh.halfedges())
    if(mesh.is_border(h))
    {
      sets.join(vertex_node(mesh.source(h)), vertex_node(mesh.target(h)));
      border_edges.emplace_back(xyz(mesh.source(h)), xyz(mesh.target(h)));
      border_edge_node.push_back(vertex_node(mesh.source(h)));
    }
  std::set<std::size_t> loops;
  for(const auto& vn : node_of_vertex) loops.insert(sets.root(vn.second));
  t.border_loops = loops.size();
  t.genus = int((2 - long(t.border_loops) - chi) / 2);

  // points: merged within tol by a grid of cells tol wide (neighbour cells searched)
  std::map<std::array<long long, 3>, std::vector<std::size_t> > grid;
  std::vector<std::array<double, 3> > point_of_node;
  std::vector<std::size_t> point_nodes;
  std::size_t written = 0;
  auto point_node = [&](const std::array<double, 3>& p) {
    ++written;
    std::array<long long, 3> c;
    for(int k = 0; k < 3; ++k) c[k] = tol > 0 ? (long long)std::floor(p[k] / tol) : 0;
    std::size_t found = std::size_t(-1);
    for(long long dx = -1; dx <= 1 && found == std::size_t(-1); ++dx)
      for(long long dy = -1; dy <= 1 && found == std::size_t(-1); ++dy)
        for(long long dz = -1; dz <= 1 && found == std::size_t(-1); ++dz)
        {
          const auto it = grid.find({{c[0] + dx, c[1] + dy, c[2] + dz}});
          if(it == grid.end()) continue;
          for(std::size_t i : it->second)
          {
            double d2 = 0;
            for(int k = 0; k < 3; ++k) d2 += (point_of_node[i][k] - p[k]) * (point_of_node[i][k] - p[k]);
            if(std::sqrt(d2) <= tol)
            {
              // chains of near points are one point too (single linkage)
              if(found == std::size_t(-1)) found = i;
              else sets.join(point_nodes[i], point_nodes[found]);
            }
          }
        }
    if(found != std::size_t(-1))
    {
      point_of_node.push_back(p);
      point_nodes.push_back(point_nodes[found]);
      grid[c].push_back(point_of_node.size() - 1);
      return point_nodes[found];
    }
    point_of_node.push_back(p);
    point_nodes.push_back(sets.add());
    grid[c].push_back(point_of_node.size() - 1);
    return point_nodes.back();
  };
  std::vector<std::pair<std::size_t, std::size_t> > raw_segments;
  for(const auto& pl : polylines)
  {
    std::vector<std::size_t> ids;
    for(const auto& p : pl) ids.push_back(point_node(p));
    for(std::size_t i = 0; i + 1 < ids.size(); ++i) raw_segments.emplace_back(ids[i], ids[i + 1]);
  }

  // the merged points (roots) and the distinct segments between them
  std::set<std::size_t> nodes;
  for(std::size_t n : point_nodes) nodes.insert(sets.root(n));
  t.points = nodes.size();
  t.merged_points = written - t.points;
  std::set<std::pair<std::size_t, std::size_t> > links; // (to the loops: one per point)
  std::vector<std::pair<std::size_t, std::size_t> > segments;
  for(const auto& [a0, b0] : raw_segments)
  {
    const std::size_t a = sets.root(a0), b = sets.root(b0);
    if(a != b) segments.emplace_back(a, b);
  }
  t.segments = segments.size();
  for(std::size_t n : nodes)
  {
    // (any one written point of the merged node stands for it)
    std::size_t i = 0;
    while(sets.root(point_nodes[i]) != n) ++i;
    for(std::size_t e = 0; e < border_edges.size(); ++e)
      if(distance_to_segment(point_of_node[i], border_edges[e].first, border_edges[e].second) <= tol)
      {
        links.emplace(n, sets.root(border_edge_node[e]));
        break;
      }
  }
  // components and cycle rank of points + loops, segments + links
  Disjoint_sets graph;
  std::map<std::size_t, std::size_t> index;
  for(std::size_t n : nodes) index.emplace(n, graph.add());
  for(std::size_t l : loops) index.emplace(l, graph.add());
  std::size_t joins = 0;
  for(const auto& [a, b] : segments) joins += graph.join(index.at(a), index.at(b));
  for(const auto& [a, b] : links) joins += graph.join(index.at(a), index.at(b));
  const std::size_t all = index.size();
  t.components = all - joins;
  t.cycles = segments.size() + links.size() + t.components + t.border_loops - all;
  return t;
}

/// The same, read from a written polylines file.
template <class Mesh>
Written_ridge_topology written_ridge_topology(const Mesh& mesh, const std::string& polylines_file,
                                              double fraction = 1e-12)
{
  return written_ridge_topology(mesh, read_polylines_file(polylines_file), fraction);
}

} // namespace testing
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_TEST_SUPPORT_WRITTEN_RIDGE_TOPOLOGY_H
