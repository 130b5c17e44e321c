// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3, last passes: the main component kept, its topology counted, and
// its chains written as polylines.
// Test: test_ridge_passes.cpp, "keep_main_component, count_topology and
// chains_as_polylines on a closed surface".
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_MAIN_COMPONENT_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_MAIN_COMPONENT_H

#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>
#include <Geodesic_ridge/internal/graph_polylines.h>

#include <map>
#include <set>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// Keep the main component: on a closed mesh the longest one, with a border
// every piece joined to the border (K ∪ ∂M is connected, and so is the ridge
// with the border); drop degenerate segments. Its segments as node pairs.
template <class Ridge>
std::vector<std::pair<std::size_t, std::size_t> > keep_main_component(Ridge& ridge)
{
  typedef typename Ridge::Segment Segment;
  Union_find comp(ridge.nodes.size() + ridge.number_of_loops);
  ridge.join_border_nodes(comp); // (a piece on the border is joined to it)
  for(const Segment& s : ridge.segments) if(s.ridge && s.a != s.b) comp.unite(s.a, s.b);
  std::map<std::size_t, double> comp_length;
  for(const Segment& s : ridge.segments) if(s.ridge && s.a != s.b) comp_length[comp.find(s.a)] += ridge.length(s);
  std::set<std::size_t> main;
  for(std::size_t loop = 0; loop < ridge.number_of_loops; ++loop) main.insert(comp.find(ridge.loop_node(loop)));
  double best = -1;
  if(ridge.number_of_loops == 0)
    for(const auto& [r, l] : comp_length) if(l > best) { best = l; main = {r}; }
  ridge.statistics.dropped_components = 0;
  for(const auto& rl : comp_length) ridge.statistics.dropped_components += main.count(rl.first) == 0;

  std::vector<std::pair<std::size_t, std::size_t> > graph;
  for(const Segment& s : ridge.segments)
    if(s.ridge && s.a != s.b && main.count(comp.find(s.a)))
    {
      graph.emplace_back(s.a, s.b);
      ridge.nodes[s.a].angle = std::max(ridge.nodes[s.a].angle, s.angle);
      ridge.nodes[s.b].angle = std::max(ridge.nodes[s.b].angle, s.angle);
      ridge.statistics.total_length += ridge.length(s);
    }
  return graph;
}

// Junctions, free ends, and the components and cycle rank of the ridge with
// the border: each loop collapsed to a node, joined to the ridge nodes on it,
// and counted again as the cycle it is.
template <class Ridge>
void count_topology(Ridge& ridge, const std::vector<std::pair<std::size_t, std::size_t> >& graph)
{
  std::vector<std::size_t> degree(ridge.nodes.size(), 0);
  for(const auto& [a, b] : graph) { ++degree[a]; ++degree[b]; }
  ridge.statistics.ridge_segments = graph.size();
  Union_find uf(ridge.nodes.size() + ridge.number_of_loops);
  ridge.join_border_nodes(uf); // (a piece on the border is joined to it)
  std::size_t used_nodes = 0, border_links = 0;
  for(std::size_t v = 0; v < ridge.nodes.size(); ++v)
  {
    if(degree[v] == 0) continue;
    ++used_nodes;
    border_links += ridge.node_loop[v] != Ridge::none;
    ridge.statistics.junctions += degree[v] >= 3;
    ridge.statistics.free_ends += degree[v] == 1 && ridge.node_loop[v] == Ridge::none;
  }
  for(const auto& [a, b] : graph) uf.unite(a, b);
  std::set<std::size_t> components;
  for(std::size_t v = 0; v < ridge.nodes.size(); ++v) if(degree[v] > 0) components.insert(uf.find(v));
  for(std::size_t loop = 0; loop < ridge.number_of_loops; ++loop) components.insert(uf.find(ridge.loop_node(loop)));
  ridge.statistics.components = components.size();
  // rank = edges - vertices + components, of the graph with the loop nodes, plus the b loops
  if(ridge.statistics.components > 0)
    ridge.statistics.cycles = graph.size() + border_links + ridge.statistics.components - used_nodes;
}

// The main component's chains (between junctions, free ends and the border)
// as polylines of ridge points.
template <class Ridge>
void chains_as_polylines(const Ridge& ridge, const std::vector<std::pair<std::size_t, std::size_t> >& graph,
                         std::vector<std::vector<Ridge_point<typename Ridge::Point> > >& polylines)
{
  polylines.clear();
  for(const auto& chain : graph_to_chains(ridge.nodes.size(), graph))
  {
    std::vector<Ridge_point<typename Ridge::Point> > pl;
    for(std::size_t v : chain) pl.push_back(ridge.nodes[v]);
    polylines.push_back(std::move(pl));
  }
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_MAIN_COMPONENT_H
