// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 pass: one region. The regions of M minus the raw ridge are merged,
// weakest ridge segment first, until one is left (no cycle but the 2g + b the
// topology needs).
// Test: test_ridge_passes.cpp, "merge_into_one_region removes the weakest
// segment ...".
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_MERGE_INTO_ONE_REGION_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_MERGE_INTO_ONE_REGION_H

#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>

#include <algorithm>
#include <set>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// One region: merge the regions of M minus the ridge, weakest segment first.
template <class Ridge>
void merge_into_one_region(Ridge& ridge)
{
  std::set<std::size_t> roots;
  for(std::size_t c = 0; c < ridge.cells.size(); ++c) roots.insert(ridge.fronts.find(c));
  ridge.statistics.regions_before_merge = roots.size();
  std::vector<std::size_t> order(ridge.segments.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return ridge.segments[a].strength < ridge.segments[b].strength; });
  for(std::size_t i : order)
    if(ridge.fronts.unite(ridge.segments[i].left, ridge.segments[i].right))
    {
      ridge.segments[i].ridge = false;
      ++ridge.statistics.merged_segments;
    }
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_MERGE_INTO_ONE_REGION_H
