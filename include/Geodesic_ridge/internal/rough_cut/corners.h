// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1, step 3c (with a leaf curvature only): K's ends at the corners, where
// the cut locus ends (vertices of large Gaussian curvature). Leaves just past a
// corner moved onto it, one-edge prongs where K forks at a corner removed, and
// corners off K joined to it by a short path.
#ifndef GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_CORNERS_H
#define GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_CORNERS_H

#include <Geodesic_ridge/internal/corner_angles.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/rough_cut/state.h>
#include <Geodesic_ridge/internal/tuning.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace Geodesic_ridge::internal::rough_cut {

// Leaves at corners. The cut locus ends at vertices of positive curvature
// (generically every such vertex is a leaf: one shortest path reaches it). A
// leaf of K one or two edges past a sharp corner, or a corner left off K (see
// `join_corners`), puts the slit's end beside the ridge's end; the fronts on
// both sides of the corner then come out wrong. So the leaf is moved back
// onto the corner. Measured (bench_ridge_accuracy): trimming at corners of 60
// degrees cut real branches through the 77-90 degree ear tips of bunny_1k
// (recall p95 at tolerance 0.001 0.27 -> 4.5 mean edges), hence the sharper
// threshold here.
inline double corner_curvature() { return radians(tuning::rough_cut::corner_degrees); }
// (a doubly covered square's corners have 180 degrees)
inline double sharp_corner_curvature() { return radians(tuning::rough_cut::sharp_corner_degrees); }
// Dijkstra from a corner over at most `maximum_hops` edges, avoiding the
// source, to the nearest vertex of K; the path as halfedges from K back
// towards the corner (empty if K is farther). Its tables are reset per search
// only where a search touched them.
template <class TriangleMesh, class Maps>
struct Short_path_search
{
  typedef boost::graph_traits<TriangleMesh>  GT;
  typedef typename GT::vertex_descriptor    vertex_descriptor;
  typedef typename GT::halfedge_descriptor  halfedge_descriptor;

  static constexpr int maximum_hops = 3;
  const State<TriangleMesh, Maps>& s;
  std::vector<vertex_descriptor> vertex_of;
  std::vector<double> reach;
  std::vector<int> hops;
  std::vector<halfedge_descriptor> reached_by;
  std::vector<std::size_t> touched;

  explicit Short_path_search(const State<TriangleMesh, Maps>& state)
    : s(state), vertex_of(state.nv), reach(state.nv, std::numeric_limits<double>::infinity()),
      hops(state.nv, 0), reached_by(state.nv, GT::null_halfedge())
  {
    for(vertex_descriptor v : vertices(s.tm)) vertex_of[s.vi(v)] = v;
  }

  std::vector<halfedge_descriptor> operator()(vertex_descriptor c)
  {
    for(std::size_t t : touched) { reach[t] = std::numeric_limits<double>::infinity(); reached_by[t] = GT::null_halfedge(); }
    touched.clear();
    typedef std::pair<double, std::size_t> Entry;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
    reach[s.vi(c)] = 0; hops[s.vi(c)] = 0; touched.push_back(s.vi(c));
    queue.emplace(0.0, s.vi(c));
    vertex_descriptor found = GT::null_vertex();
    while(!queue.empty() && found == GT::null_vertex())
    {
      const double d = queue.top().first;
      const vertex_descriptor u = vertex_of[queue.top().second];
      queue.pop();
      if(d > reach[s.vi(u)]) continue;
      if(s.cut_degree[s.vi(u)] > 0 || s.on_boundary(u)) { found = u; break; }
      if(hops[s.vi(u)] == maximum_hops) continue;
      for(halfedge_descriptor h : CGAL::halfedges_around_target(u, s.tm))
      {
        const vertex_descriptor w = source(h, s.tm);
        if(s.is_seed[s.vi(w)]) continue;
        const double dw = d + distance_between(s.maps.vpm, u, w);
        if(dw >= reach[s.vi(w)]) continue;
        if(reach[s.vi(w)] == std::numeric_limits<double>::infinity()) touched.push_back(s.vi(w));
        reach[s.vi(w)] = dw; hops[s.vi(w)] = hops[s.vi(u)] + 1; reached_by[s.vi(w)] = h;
        queue.emplace(dw, s.vi(w));
      }
    }
    std::vector<halfedge_descriptor> path;
    if(found == GT::null_vertex()) return path;
    for(vertex_descriptor u = found; u != c; u = target(path.back(), s.tm))
      path.push_back(reached_by[s.vi(u)]); // from u back towards c
    return path;
  }
};

template <class TriangleMesh, class Maps>
void move_leaves_onto_corners(State<TriangleMesh, Maps>& s)
{
  typedef typename State<TriangleMesh, Maps>::GT GT;
  std::vector<typename GT::vertex_descriptor> leaves;
  for(auto v : vertices(s.tm))
    if(s.is_leaf_of_cut(v) && s.curvature(v) < corner_curvature()) leaves.push_back(v);
  for(auto w : leaves)
  {
    // past a sharp corner: walk in through at most two vertices of degree 2
    std::vector<typename GT::halfedge_descriptor> path;
    auto h = s.cut_halfedge_into(w);
    for(int step = 0; step < 2 && h != GT::null_halfedge(); ++step)
    {
      path.push_back(h);
      const auto u = source(h, s.tm);
      // (u keeps a cut edge, so K never becomes empty)
      if(s.curvature(u) >= sharp_corner_curvature() && !s.is_source_vertex(u) && s.cut_degree[s.vi(u)] >= 2)
      {
        for(auto p : path) s.remove_cut(edge(p, s.tm));
        ++s.st.number_of_corner_moves;
        break;
      }
      if(s.cut_degree[s.vi(u)] != 2) break;
      h = s.cut_halfedge_into(u, h); // the other cut edge at u, again pointing outwards
    }
  }
}

// Prongs at a corner where K forks. The dual edges kept around a corner for
// its curvature cross several of its spokes, and the rungs make K fork at
// the corner into one-edge prongs that end at flat vertices beside it (the
// open box's bottom corners: two prongs along the bottom edges). A front that
// crosses such a prong's edge is split between two sheets, and the faces at
// the corner get no copy that carries it at all three corners: the ridge
// forks beside the corner. The cut locus ends at vertices of positive
// curvature, never at a flat vertex one edge from a corner, so at a corner
// (60 degrees or more) where K has three or more edges, every such prong is
// removed while one other edge stays. A corner where K does not fork (a
// branch through it and one edge on, as at bunny_1k's ear tips) is left to
// `move_leaves_onto_corners()`.
template <class TriangleMesh, class Maps>
void remove_prongs_at_corner_forks(State<TriangleMesh, Maps>& s)
{
  for(auto u : vertices(s.tm))
  {
    if(s.cut_degree[s.vi(u)] < 3 || s.curvature(u) < corner_curvature() || s.is_source_vertex(u)) continue;
    std::vector<typename State<TriangleMesh, Maps>::edge_descriptor> prongs;
    for(auto h : CGAL::halfedges_around_target(u, s.tm))
    {
      const auto w = source(h, s.tm);
      if(s.r.is_cut_edge[s.ei(edge(h, s.tm))] && s.is_leaf_of_cut(w) && s.curvature(w) < corner_curvature() &&
         !s.is_source_vertex(w))
        prongs.push_back(edge(h, s.tm));
    }
    if(prongs.empty()) continue;
    if(prongs.size() == s.cut_degree[s.vi(u)]) prongs.pop_back(); // (K keeps an edge at u)
    for(auto e : prongs) s.remove_cut(e);
    ++s.st.number_of_corner_moves;
  }
}

// A corner (60 degrees or more of curvature) off K is joined to K by the
// shortest path of at most three edges through vertices off K (a pendant
// path: K stays a tree plus its 2g rungs); corners of most curvature first.
template <class TriangleMesh, class Maps>
void join_corners(State<TriangleMesh, Maps>& s)
{
  typedef typename State<TriangleMesh, Maps>::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> corners;
  for(auto v : vertices(s.tm))
    if(s.cut_degree[s.vi(v)] == 0 && !s.is_source_vertex(v) && s.curvature(v) >= corner_curvature())
      corners.push_back(v);
  std::stable_sort(corners.begin(), corners.end(), [&](vertex_descriptor a, vertex_descriptor b) {
    return s.curvature(a) > s.curvature(b);
  });
  Short_path_search<TriangleMesh, Maps> search(s);
  for(auto c : corners)
  {
    if(s.cut_degree[s.vi(c)] != 0) continue;
    const auto path = search(c);
    if(path.empty()) continue;
    for(auto h : path)
    {
      s.add_cut(edge(h, s.tm));
      s.r.corner_path_edges.push_back(edge(h, s.tm));
    }
    ++s.st.number_of_corner_moves;
  }
}

} // namespace Geodesic_ridge::internal::rough_cut

#endif
