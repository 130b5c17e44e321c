// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 pass: with several border loops, the pieces of the ridge that hang
// from different loops joined into one.
// Test: test_ridge_curve.cpp, "surfaces with several border loops: the pieces
// hanging from different loops are joined".
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_JOIN_BORDER_COMPONENTS_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_JOIN_BORDER_COMPONENTS_H

#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>
#include <Geodesic_ridge/internal/ridge_curve/link_graph.h>

#include <limits>
#include <set>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// With a border, the ridge with the border is one connected graph (so is
// K ∪ ∂M). Where two fronts meet at a small angle, or where a split copy's
// front continues a glued one, the assembly may have united them as one front
// and drawn no segment: the ridge then hangs from the loops in pieces and
// M minus the pieces is no disk. Each other piece is joined to the main one
// by the path along the boundaries between cells (envelope edges inside
// faces, pieces of mesh edges) that is shortest in length over the gradient
// jump (the fronts meet where the jump is large). Joining two pieces closes
// no cycle, so the cycle rank is kept.
template <class Ridge>
void join_border_components(Ridge& ridge)
{
  typedef typename Ridge::Segment Segment;
  typedef typename Ridge::Link_graph Link_graph;
  Link_paths<Ridge> paths(ridge);
  if(ridge.number_of_loops < 2) return;
  auto unite_pieces = [&](Union_find& uf) {
    ridge.join_border_nodes(uf);
    for(const Segment& sg : ridge.segments) if(sg.ridge && sg.a != sg.b) uf.unite(sg.a, sg.b);
  };
  {
    Union_find uf(ridge.nodes.size() + ridge.number_of_loops);
    unite_pieces(uf);
    std::set<std::size_t> roots;
    for(std::size_t loop = 0; loop < ridge.number_of_loops; ++loop) roots.insert(uf.find(ridge.loop_node(loop)));
    if(roots.size() < 2) return;
  }
  const Link_graph& g = paths.link_graph(); // (node ids as in unite_pieces: ridge.nodes is complete now)
  const std::size_t n = g.at.size();
  for(;;)
  {
    Union_find uf(n);
    unite_pieces(uf);
    const std::size_t main = uf.find(ridge.loop_node(0));
    std::set<std::size_t> other_loops;
    for(std::size_t loop = 1; loop < ridge.number_of_loops; ++loop)
      if(uf.find(ridge.loop_node(loop)) != main) other_loops.insert(uf.find(ridge.loop_node(loop)));
    if(other_loops.empty()) return;
    // from the main piece to the nearest node of a piece with a loop
    std::vector<std::size_t> sources;
    for(std::size_t v = 0; v < n; ++v) if(uf.find(v) == main) sources.push_back(v);
    double path_length = 0;
    const std::vector<std::size_t> path = paths.shortest_link_path(
        g, sources, [&](std::size_t v) { return other_loops.count(uf.find(v)) > 0; },
        [](std::size_t) { return false; }, std::numeric_limits<double>::infinity(), path_length);
    if(path.empty()) return; // (the check of the topology reports it)
    paths.add_ridge_links(g, path);
    ridge.statistics.border_joining_segments += path.size();
  }
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_JOIN_BORDER_COMPONENTS_H
