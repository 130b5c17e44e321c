// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1, step 1: the shortest-path tree T from the source (the manual's
// "Stage 1: The Rough Cut Locus"). Dijkstra along mesh edges, or, inside the
// pipeline, a descent of the geodesic field it was given; first the counts
// (genus, border loops) and the element tables every later pass reads.
#ifndef GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_SHORTEST_PATH_TREE_H
#define GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_SHORTEST_PATH_TREE_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/border_loops.h>
#include <Geodesic_ridge/internal/edge_graph_distances.h>
#include <Geodesic_ridge/internal/rough_cut/state.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace Geodesic_ridge::internal::rough_cut {

// The number of loops of border edges; marks the border vertices.
template <class TriangleMesh, class Maps>
std::size_t boundary_loops(State<TriangleMesh, Maps>& s)
{
  const Border_loops loops = border_loops(s.tm, s.maps.vim);
  s.boundary_vertex.assign(s.nv, 0);
  for(std::size_t v = 0; v < s.nv; ++v) s.boundary_vertex[v] = loops.on_border(v);
  return loops.number_of_loops;
}

// The counts of the result (the genus from the Euler characteristic, the border
// loops), the edges and faces by index, the seeds of the source.
template <class TriangleMesh, class Maps>
void count_elements(State<TriangleMesh, Maps>& s)
{
  s.r.source = s.src;
  s.r.tolerance = s.options.tolerance;
  s.st.number_of_vertices = s.nv;
  s.st.number_of_edges = s.ne;
  s.st.number_of_faces = s.nf;
  s.st.number_of_boundary_loops = boundary_loops(s);
  const long chi = static_cast<long>(s.nv) - static_cast<long>(s.ne) + static_cast<long>(s.nf);
  s.st.genus = static_cast<int>((2 - chi - static_cast<long>(s.st.number_of_boundary_loops)) / 2);
  s.edge_of.resize(s.ne);
  for(auto e : edges(s.tm))
  {
    if(s.ei(e) >= s.ne)
      throw Invalid_mesh_error("mesh has removed elements (call collect_garbage() first)");
    s.edge_of[s.ei(e)] = e;
  }
  s.face_of.resize(s.nf);
  for(auto f : faces(s.tm))
  {
    if(s.fi(f) >= s.nf)
      throw Invalid_mesh_error("mesh has removed elements (call collect_garbage() first)");
    s.face_of[s.fi(f)] = f;
  }
  s.is_seed.assign(s.nv, 0);
  for(const auto& seed : s.src.seeds) s.is_seed[s.vi(seed.first)] = 1;
}

// Step 1: Boost's Dijkstra on the mesh graph, several seeds for a surface point.
template <class TriangleMesh, class Maps>
void shortest_path_tree(State<TriangleMesh, Maps>& s)
{
  typedef Geodesic_source<TriangleMesh> Source;
  const double inf = std::numeric_limits<double>::infinity();
  edge_graph_distances(s.tm, s.maps, s.src.seeds, s.length, s.r.distance, s.r.parent);
  // A straight segment from the source is a geodesic (no edge path in R^3 is
  // shorter), so seeds stay roots and a vertex source's neighbours hang from it,
  // whatever ties the floating-point sums produced: the cut never touches the source.
  for(const auto& seed : s.src.seeds)
  {
    s.r.distance[s.vi(seed.first)] = seed.second;
    s.r.parent[s.vi(seed.first)] = seed.first;
  }
  if(s.src.kind == Source::ON_VERTEX)
    for(auto h : CGAL::halfedges_around_target(s.src.vertex, s.tm))
    {
      const auto u = source(h, s.tm);
      s.r.parent[s.vi(u)] = s.src.vertex;
      s.r.distance[s.vi(u)] = s.length[s.ei(edge(h, s.tm))];
    }
  for(auto v : vertices(s.tm))
    if(!(s.r.distance[s.vi(v)] < inf))
      throw Invalid_mesh_error("vertex " + std::to_string(s.vi(v)) + " cannot be reached from the source");
}

// A tree iff every vertex reaches a root (a seed) through its parents.
template <class TriangleMesh, class Maps>
bool parents_form_a_tree(const State<TriangleMesh, Maps>& s)
{
  std::vector<char> state(s.nv, 0); // 0 unknown, 1 in progress, 2 reaches a root
  std::vector<std::size_t> path;   // (reused: no heap block per vertex)
  for(auto v : vertices(s.tm))
  {
    path.clear();
    std::size_t x = s.vi(v);
    while(state[x] == 0 && !s.is_seed[x])
    {
      state[x] = 1;
      path.push_back(x);
      x = s.vi(s.r.parent[x]);
    }
    if(state[x] == 1) return false;
    for(std::size_t y : path) state[y] = 2;
    state[x] = 2;
  }
  return true;
}

// Step 1, with a geodesic field: every vertex hangs from the neighbour u of
// smaller field value that minimizes field(u) + |uv|, so the tree descends the
// true distance instead of Dijkstra's staircase paths, whose anisotropy on
// regular meshes makes significant dual branches far from the real ridge.
// Strictly decreasing values make it a tree; where a vertex has no lower
// neighbour it keeps its Dijkstra parent, and if that mix ever closed a
// cycle, the whole Dijkstra tree is kept.
template <class TriangleMesh, class Maps>
void descend_field(State<TriangleMesh, Maps>& s, const std::vector<double>& field)
{
  typedef Geodesic_source<TriangleMesh> Source;
  const auto dijkstra_parent = s.r.parent;
  for(auto v : vertices(s.tm))
  {
    if(s.is_seed[s.vi(v)]) continue;
    if(s.src.kind == Source::ON_VERTEX && s.r.parent[s.vi(v)] == s.src.vertex && v != s.src.vertex)
      continue; // the source's neighbours stay its children
    double best = std::numeric_limits<double>::infinity();
    for(auto h : CGAL::halfedges_around_target(v, s.tm))
    {
      const auto u = source(h, s.tm);
      if(!(field[s.vi(u)] < field[s.vi(v)])) continue;
      const double value = field[s.vi(u)] + s.length[s.ei(edge(h, s.tm))];
      if(value < best) { best = value; s.r.parent[s.vi(v)] = u; }
    }
  }
  if(!parents_form_a_tree(s)) s.r.parent = dijkstra_parent;
  else
    for(auto v : vertices(s.tm)) s.r.distance[s.vi(v)] = field[s.vi(v)];
}

} // namespace Geodesic_ridge::internal::rough_cut

#endif
