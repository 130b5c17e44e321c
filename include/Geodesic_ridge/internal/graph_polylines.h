// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef GEODESIC_RIDGE_INTERNAL_GRAPH_POLYLINES_H
#define GEODESIC_RIDGE_INTERNAL_GRAPH_POLYLINES_H

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

/// Splits an undirected graph on nodes 0..n-1, given by its edge list, into
/// maximal chains: each chain runs between nodes of degree != 2 (junctions and
/// free ends); a component that is a plain cycle becomes one closed chain
/// (first node repeated at the end). The result is deterministic: chains start
/// at the smallest node index, in increasing order.
inline std::vector<std::vector<std::size_t> >
graph_to_chains(std::size_t n, const std::vector<std::pair<std::size_t, std::size_t> >& edges)
{
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > adj(n); // (neighbour, edge)
  for(std::size_t i = 0; i < edges.size(); ++i)
  {
    adj[edges[i].first].emplace_back(edges[i].second, i);
    adj[edges[i].second].emplace_back(edges[i].first, i);
  }
  std::vector<char> used(edges.size(), 0);
  std::vector<std::vector<std::size_t> > chains;
  auto walk = [&](std::size_t start, std::size_t first_edge_slot) {
    std::vector<std::size_t> chain{start};
    std::size_t cur = start;
    std::size_t slot = first_edge_slot;
    for(;;)
    {
      const auto [nb, e] = adj[cur][slot];
      used[e] = 1;
      chain.push_back(nb);
      cur = nb;
      if(adj[cur].size() != 2) break;
      const std::size_t s0 = used[adj[cur][0].second] ? 1 : 0;
      if(used[adj[cur][s0].second]) break; // closed a cycle
      slot = s0;
    }
    chains.push_back(std::move(chain));
  };
  for(std::size_t v = 0; v < n; ++v)
    if(!adj[v].empty() && adj[v].size() != 2)
      for(std::size_t s = 0; s < adj[v].size(); ++s)
        if(!used[adj[v][s].second]) walk(v, s);
  for(std::size_t v = 0; v < n; ++v) // what is left are plain cycles
    if(adj[v].size() == 2 && !used[adj[v][0].second]) walk(v, 0);
  return chains;
}

} // namespace internal
} // namespace Geodesic_ridge

#endif
