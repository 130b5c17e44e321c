// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1, step 4: K collected into the result, and the check that runs always:
// cutting the mesh along K gives one topological disk with the source strictly
// inside (`Algorithm_error` otherwise, with what failed).
#ifndef GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_CHECKS_H
#define GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_CHECKS_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/rough_cut/state.h>
#include <Geodesic_ridge/internal/union_find.h>

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cstddef>
#include <string>

namespace Geodesic_ridge::internal::rough_cut {

// K and the dual edge lists of the result, by increasing edge index
template <class TriangleMesh, class Maps>
void collect_cut_edges(State<TriangleMesh, Maps>& s)
{
  typedef typename State<TriangleMesh, Maps>::edge_descriptor edge_descriptor;
  for(std::size_t i = 0; i < s.ne; ++i)
    if(s.r.is_cut_edge[i]) s.r.cut_edges.push_back(s.edge_of[i]);
  auto by_index = [&](edge_descriptor a, edge_descriptor b) { return s.ei(a) < s.ei(b); };
  std::sort(s.r.dual_edges.begin(), s.r.dual_edges.end(), by_index);
  std::sort(s.r.kept_dual_edges.begin(), s.r.kept_dual_edges.end(), by_index);
  std::sort(s.r.leaf_extension_edges.begin(), s.r.leaf_extension_edges.end(), by_index);
  std::sort(s.r.corner_path_edges.begin(), s.r.corner_path_edges.end(), by_index);
  s.st.number_of_cut_edges = s.r.cut_edges.size();
}

// whether K touches the source: its vertex, or the edge it lies on
template <class TriangleMesh, class Maps>
bool source_on_cut(const State<TriangleMesh, Maps>& s)
{
  typedef Geodesic_source<TriangleMesh> Source;
  if(s.src.kind == Source::ON_VERTEX) return s.cut_degree[s.vi(s.src.vertex)] > 0;
  if(s.src.kind == Source::ON_EDGE) return s.r.is_cut_edge[s.ei(edge(s.src.edge_halfedge, s.tm))] != 0;
  return false;
}

// Step 4, always: K ∪ ∂M (K on a closed mesh) is connected with cycle rank
// 2g + b, the cut surface is connected with Euler characteristic 1 (so a
// disk), the source is off K.
template <class TriangleMesh, class Maps>
void check_disk(State<TriangleMesh, Maps>& s)
{
  std::size_t split_vertices = 0; // vertex copies in the cut surface beyond one per vertex
  std::size_t graph_vertices = 0, graph_edges = s.st.number_of_cut_edges;
  for(auto v : vertices(s.tm))
  {
    const std::size_t k = s.cut_degree[s.vi(v)];
    if(k > 0) ++s.st.number_of_cut_vertices;
    if(s.is_leaf_of_cut(v)) ++s.st.number_of_cut_leaves;
    // k cut edges split an inner vertex into k sectors, a border vertex into k + 1
    split_vertices += s.on_boundary(v) ? k : (k > 0 ? k - 1 : 0);
    graph_vertices += (k > 0 || s.on_boundary(v));
  }
  Union_find kuf(s.nv);
  for(auto e : s.r.cut_edges) kuf.unite(s.vi(source(e, s.tm)), s.vi(target(e, s.tm)));
  for(auto h : halfedges(s.tm))
    if(is_border(h, s.tm)) { kuf.unite(s.vi(source(h, s.tm)), s.vi(target(h, s.tm))); ++graph_edges; }
  const std::size_t k_components = kuf.number_of_sets() - (s.nv - graph_vertices);
  s.st.cut_cycle_rank = graph_edges + k_components - graph_vertices;
  Union_find fuf(s.nf);
  for(auto e : edges(s.tm))
    if(!s.r.is_cut_edge[s.ei(e)] && !is_border(e, s.tm))
    {
      const auto h = halfedge(e, s.tm);
      fuf.unite(s.fi(face(h, s.tm)), s.fi(face(opposite(h, s.tm), s.tm)));
    }
  const long cut_chi = static_cast<long>(s.nv + split_vertices) -
                       static_cast<long>(s.ne + s.st.number_of_cut_edges) + static_cast<long>(s.nf);
  const std::size_t rank = static_cast<std::size_t>(2 * s.st.genus) + s.st.number_of_boundary_loops;
  const std::string graph = s.has_boundary() ? "K with the border" : "the cut graph";
  std::string why;
  if(graph_edges == 0) why = "the cut graph is empty";
  else if(k_components != 1) why = graph + " has " + std::to_string(k_components) + " components";
  else if(s.st.cut_cycle_rank != rank)
    why = graph + " has cycle rank " + std::to_string(s.st.cut_cycle_rank) + ", not 2g + b = " + std::to_string(rank);
  else if(fuf.number_of_sets() != 1)
    why = "cutting along K splits the surface into " + std::to_string(fuf.number_of_sets()) + " parts";
  else if(cut_chi != 1)
    why = "the cut surface has Euler characteristic " + std::to_string(cut_chi) + ", not 1";
  else if(source_on_cut(s))
    why = "the source lies on the cut";
  if(!why.empty()) throw Algorithm_error("rough cut locus: cutting along K does not give a disk: " + why);
}

} // namespace Geodesic_ridge::internal::rough_cut

#endif
