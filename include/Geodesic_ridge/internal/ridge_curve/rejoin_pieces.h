// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 pass: merged segments put back, strongest first, where the merge
// cut a branch off (joining two pieces closes no cycle).
// Test: test_ridge_passes.cpp, "... rejoin_pieces puts back a link".
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_REJOIN_PIECES_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_REJOIN_PIECES_H

#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>

#include <algorithm>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// A merge may have cut a branch off the tree: re-add, strongest first, merged
// segments that join two pieces of the ridge. Joining two pieces closes no
// cycle, so no region is split again.
template <class Ridge>
void rejoin_pieces(Ridge& ridge)
{
  typedef typename Ridge::Segment Segment;
  Union_find pieces(ridge.nodes.size() + ridge.number_of_loops);
  ridge.join_border_nodes(pieces); // (a piece on the border is joined to it)
  for(const Segment& sg : ridge.segments) if(sg.ridge) pieces.unite(sg.a, sg.b);
  std::vector<std::size_t> merged;
  for(std::size_t i = 0; i < ridge.segments.size(); ++i)
    if(!ridge.segments[i].ridge && ridge.segments[i].a != ridge.segments[i].b) merged.push_back(i);
  std::stable_sort(merged.begin(), merged.end(),
                   [&](std::size_t a, std::size_t b) { return ridge.segments[a].strength > ridge.segments[b].strength; });
  std::vector<char> on_ridge(ridge.nodes.size(), 0);
  for(const Segment& sg : ridge.segments) if(sg.ridge) on_ridge[sg.a] = on_ridge[sg.b] = 1;
  for(std::size_t i : merged)
  {
    const std::size_t ra = pieces.find(ridge.segments[i].a), rb = pieces.find(ridge.segments[i].b);
    // only segments that touch the ridge at both ends reconnect something
    if(ra == rb || !on_ridge[ridge.segments[i].a] || !on_ridge[ridge.segments[i].b]) continue;
    ridge.segments[i].ridge = true;
    pieces.unite(ra, rb);
    ++ridge.statistics.rejoined_segments;
  }
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_REJOIN_PIECES_H
