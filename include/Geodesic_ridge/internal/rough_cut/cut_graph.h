// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1, step 3b: the primal cut graph K on mesh edges. The rungs crossed by
// the kept dual edges reduced to a maximum-significance spanning tree, the 2g
// rungs that close the non-contractible cycles added back, and the one-edge
// teeth of the strip removed.
#ifndef GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_CUT_GRAPH_H
#define GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_CUT_GRAPH_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/rough_cut/state.h>
#include <Geodesic_ridge/internal/union_find.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstddef>
#include <deque>
#include <string>
#include <vector>

namespace Geodesic_ridge::internal::rough_cut {

// The rungs (mesh edges crossed by kept dual edges) reduced to a
// maximum-significance spanning tree (Kruskal).
template <class TriangleMesh, class Maps>
void span_rungs(State<TriangleMesh, Maps>& s)
{
  for(std::size_t d = 0; d < s.nd; ++d)
    if((s.kept[d] || s.extension[d]) && !is_border(s.r.dual_edges[d], s.tm)) s.rungs.push_back(d);
  std::stable_sort(s.rungs.begin(), s.rungs.end(),
                   [&](std::size_t a, std::size_t b) { return s.significance(a) > s.significance(b); });
  s.r.is_cut_edge.assign(s.ne, 0);
  s.cut_degree.assign(s.nv, 0);
  // each border loop is one piece of K ∪ ∂M already: a rung path that joins
  // two loops is no cycle, one that returns to its loop is
  Union_find uf(s.nv);
  for(auto h : halfedges(s.tm))
    if(is_border(h, s.tm)) uf.unite(s.vi(source(h, s.tm)), s.vi(target(h, s.tm)));
  for(std::size_t d : s.rungs)
  {
    const auto e = s.r.dual_edges[d];
    if(uf.unite(s.vi(source(e, s.tm)), s.vi(target(e, s.tm)))) s.add_cut(e);
  }
}

// Whether the two faces of dual edge d stay connected when K and d's edge are
// cut: an alternating BFS from both faces stops after O(smaller side) steps
// when the edge is a bridge.
template <class TriangleMesh, class Maps>
bool faces_stay_connected_without(State<TriangleMesh, Maps>& s, std::size_t d)
{
  const auto e = s.r.dual_edges[d];
  const std::size_t ma = ++s.stamp, mb = ++s.stamp;
  std::deque<std::size_t> qa{s.dual_faces_of[d][0]}, qb{s.dual_faces_of[d][1]};
  s.face_mark[qa.front()] = ma;
  s.face_mark[qb.front()] = mb;
  bool joined = false;
  auto step = [&](std::deque<std::size_t>& q, std::size_t mine, std::size_t other) {
    const std::size_t f = q.front();
    q.pop_front();
    for(auto h : CGAL::halfedges_around_face(halfedge(s.face_of[f], s.tm), s.tm))
    {
      const auto eh = edge(h, s.tm);
      if(s.r.is_cut_edge[s.ei(eh)] || eh == e || is_border(opposite(h, s.tm), s.tm)) continue;
      const std::size_t g = s.fi(face(opposite(h, s.tm), s.tm));
      if(s.face_mark[g] == other) { joined = true; return; }
      if(s.face_mark[g] != mine) { s.face_mark[g] = mine; q.push_back(g); }
    }
  };
  while(!joined && !qa.empty() && !qb.empty())
  {
    step(qa, ma, mb);
    if(!joined && !qb.empty()) step(qb, mb, ma);
  }
  return joined;
}

// Genus g: add back the 2g rungs that close the non-contractible cycles. A
// rung may be added iff the faces stay connected across non-cut edges (its
// dual edge is no bridge), i.e. it closes no contractible cycle. The
// candidates that qualify form a cographic matroid, so greedy is optimal, and
// a connected cut surface with Euler characteristic 1 is a disk.
template <class TriangleMesh, class Maps>
void close_handle_cycles(State<TriangleMesh, Maps>& s)
{
  if(s.st.genus == 0) return;
  const std::size_t wanted = static_cast<std::size_t>(2 * s.st.genus);
  s.face_mark.assign(s.nf, 0);
  for(std::size_t d : s.rungs)
  {
    if(s.st.number_of_closing_rungs == wanted) break;
    const auto e = s.r.dual_edges[d];
    if(s.r.is_cut_edge[s.ei(e)] || !faces_stay_connected_without(s, d)) continue;
    s.add_cut(e);
    ++s.st.number_of_closing_rungs;
  }
  if(s.st.number_of_closing_rungs != wanted)
    throw Algorithm_error("found " + std::to_string(s.st.number_of_closing_rungs) + " of the " +
                          std::to_string(wanted) + " rungs closing the non-contractible cycles");
}

// per dual edge: whether K cuts further out on its branch of T* (always on the 2-core)
template <class TriangleMesh, class Maps>
std::vector<char> cut_further_out(const State<TriangleMesh, Maps>& s)
{
  std::vector<char> cut_beyond(s.nd, 0), face_has_cut_beyond(s.nf + 1, 0);
  for(std::size_t d : s.peel_order)
  {
    const std::size_t c = s.child_face[d];
    cut_beyond[d] = face_has_cut_beyond[c];
    if(cut_beyond[d] || s.r.is_cut_edge[s.ei(s.r.dual_edges[d])]) face_has_cut_beyond[s.across(d, c)] = 1;
  }
  for(std::size_t d = 0; d < s.nd; ++d)
    if(!s.peeled[d]) cut_beyond[d] = 1; // a cycle of the 2-core never ends
  return cut_beyond;
}

// No teeth: a spanning tree of the rungs keeps every zigzag tooth of the strip
// as a one-edge leaf. A leaf of K is a tooth unless its dual edge is the
// outermost cut rung of its branch of T* (nothing cut further out). Removing a
// leaf of K keeps K connected and the cut surface a disk.
template <class TriangleMesh, class Maps>
void remove_teeth(State<TriangleMesh, Maps>& s)
{
  typedef typename State<TriangleMesh, Maps>::vertex_descriptor vertex_descriptor;
  const std::vector<char> cut_beyond = cut_further_out(s);
  std::vector<std::size_t> dual_index_of_edge(s.ne, none);
  for(std::size_t d = 0; d < s.nd; ++d) dual_index_of_edge[s.ei(s.r.dual_edges[d])] = d;
  std::size_t cut_size = 0;
  for(std::size_t i = 0; i < s.ne; ++i) cut_size += s.r.is_cut_edge[i];
  std::vector<vertex_descriptor> leaves;
  for(auto v : vertices(s.tm))
    if(s.is_leaf_of_cut(v)) leaves.push_back(v);
  while(!leaves.empty() && (cut_size > 1 || s.has_boundary()))
  {
    const auto w = leaves.back();
    leaves.pop_back();
    if(!s.is_leaf_of_cut(w)) continue;
    const auto hw = s.cut_halfedge_into(w);
    if(!cut_beyond[dual_index_of_edge[s.ei(edge(hw, s.tm))]]) continue; // the end of a branch: keep it
    s.remove_cut(edge(hw, s.tm));
    --cut_size;
    const auto u = source(hw, s.tm);
    if(s.is_leaf_of_cut(u)) leaves.push_back(u);
    ++s.st.number_of_teeth_pruned;
  }
}

} // namespace Geodesic_ridge::internal::rough_cut

#endif
