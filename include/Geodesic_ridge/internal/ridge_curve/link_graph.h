// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3: the boundaries between cells as a graph, and the lightest path
// along it (for the joining passes).
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_LINK_GRAPH_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_LINK_GRAPH_H

#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// The boundaries between cells (envelope edges inside faces, pieces of inner
// mesh edges) as a graph of links, and the lightest path along them: how
// the joining passes (`join_border_components`, `join_verified_pieces`) put
// back a piece of ridge where the assembly drew none.
template <class Ridge>
class Link_paths
{
  typedef typename Ridge::Segment Segment;
  typedef typename Ridge::Edge_piece Edge_piece;
  typedef typename Ridge::Link_graph Link_graph;
  typedef typename Ridge::halfedge_descriptor halfedge_descriptor;
  static constexpr std::size_t none = Ridge::none;

public:
  explicit Link_paths(Ridge& ridge) : ridge(ridge) {}

  // The boundaries between cells (`cell_boundary_links()`) as a graph: per
  // node, the links at it. The whole graph is built once (it completes ridge.nodes).
  Link_graph make_link_graph(std::vector<Segment> links) const
  {
    Link_graph g;
    g.links = std::move(links);
    g.at.assign(ridge.nodes.size() + ridge.number_of_loops, {});
    for(std::size_t i = 0; i < g.links.size(); ++i) { g.at[g.links[i].a].push_back(i); g.at[g.links[i].b].push_back(i); }
    return g;
  }
  const Link_graph& link_graph()
  {
    if(!ridge.links) ridge.links = make_link_graph(cell_boundary_links([](std::size_t) { return true; }));
    return *ridge.links;
  }

  // The link graph of the faces that come within `reach` of a node of
  // `around` (their bounding boxes overlap).
  Link_graph links_within(const std::vector<std::size_t>& around, double reach)
  {
    CGAL::Bbox_3 box;
    for(std::size_t v : around) box += ridge.nodes[v].point.bbox();
    box = CGAL::Bbox_3(box.xmin() - reach, box.ymin() - reach, box.zmin() - reach, box.xmax() + reach,
                       box.ymax() + reach, box.zmax() + reach);
    std::vector<char> in(ridge.nf, 0);
    for(std::size_t f = 0; f < ridge.nf; ++f)
    {
      const auto p = ridge.faces.corner_points(f);
      in[f] = CGAL::do_overlap(box, p[0].bbox() + p[1].bbox() + p[2].bbox());
    }
    return make_link_graph(cell_boundary_links([&](std::size_t f) { return in[f] != 0; }));
  }

  // The links from a node of `sources` to the first node with is_goal() that
  // are shortest in length over the gradient jump (the fronts meet where the
  // jump is large), through no node with blocked(), as long as that sum stays
  // within max_weight (it is at most the path's length); and their length.
  // Empty if there is none.
  template <class IsGoal, class IsBlocked>
  std::vector<std::size_t> shortest_link_path(const Link_graph& g, const std::vector<std::size_t>& sources,
                                              const IsGoal& is_goal, const IsBlocked& blocked, double max_weight,
                                              double& path_length) const
  {
    const std::size_t n = g.at.size();
    std::vector<double> dist(n, std::numeric_limits<double>::infinity());
    std::vector<std::size_t> via(n, none);
    typedef std::pair<double, std::size_t> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
    for(std::size_t v : sources) { dist[v] = 0; queue.emplace(0.0, v); }
    std::size_t reached = none;
    while(!queue.empty() && reached == none)
    {
      const auto [d, v] = queue.top();
      queue.pop();
      if(d > dist[v]) continue;
      if(d > max_weight) break;
      if(is_goal(v)) { reached = v; continue; }
      if(via[v] != none && blocked(v)) continue; // (a source is never blocked)
      for(std::size_t i : g.at[v])
      {
        const Segment& link = g.links[i];
        const std::size_t w = link.a == v ? link.b : link.a;
        const double dw = d + ridge.length(link) / std::max(link.angle, 1.0);
        if(dw < dist[w]) { dist[w] = dw; via[w] = i; queue.emplace(dw, w); }
      }
    }
    std::vector<std::size_t> path;
    path_length = 0;
    for(std::size_t v = reached; v != none && via[v] != none;)
    {
      const Segment& link = g.links[via[v]];
      path.push_back(via[v]);
      path_length += ridge.length(link);
      v = link.a == v ? link.b : link.a;
    }
    return path;
  }

  // The links of `path` (indices into the link graph g) made ridge segments.
  void add_ridge_links(const Link_graph& g, const std::vector<std::size_t>& path)
  {
    for(std::size_t i : path)
    {
      ridge.segments.push_back(g.links[i]);
      ridge.segments.back().ridge = true;
    }
  }

private:
  // Every boundary between two cells as a segment: the envelope's edges inside
  // faces, and the pieces of the mesh's inner edges between the cell boundaries
  // of both sides (whole edges where one copy covers each side).
  template <class InFace>
  std::vector<Segment> cell_boundary_links(const InFace& in_face)
  {
    std::vector<Segment> links;
    for(std::size_t f = 0; f < ridge.nf; ++f)
    {
      if(!in_face(f)) continue;
      for(const auto& s : ridge.envelope_of[f]->segments)
      {
        const std::size_t ca = ridge.cell_of(f, s.copy_a), cb = ridge.cell_of(f, s.copy_b);
        const std::size_t a = ridge.node_at(f, s.endpoints[0]), b = ridge.node_at(f, s.endpoints[1]);
        if(a == b) continue;
        const Gradient_jump j = ridge.gradient_jump_in_face(ridge.cells[ca], ridge.cells[cb]);
        links.push_back(Segment{a, b, ca, cb, j.strength, j.angle, false});
      }
    }
    std::vector<char> edge_done(num_edges(ridge.tm), 0);
    for(std::size_t f1 = 0; f1 < ridge.nf; ++f1)
    {
      const auto h1s = ridge.faces.corner_halfedges(f1);
      for(int k1 = 0; k1 < 3; ++k1)
      {
        const std::size_t e = get(ridge.maps.eim, edge(h1s[k1], ridge.tm));
        const halfedge_descriptor h2 = opposite(h1s[k1], ridge.tm);
        if(edge_done[e] || is_border(h2, ridge.tm)) continue;
        edge_done[e] = 1;
        const std::size_t f2 = get(ridge.maps.fim, face(h2, ridge.tm));
        if(!in_face(f1) && !in_face(f2)) continue;
        const auto h2s = ridge.faces.corner_halfedges(f2);
        int k2 = 0;
        while(h2s[k2] != h2) ++k2;
        for(const Edge_piece& p : ridge.edge_pieces(f1, k1, f2, k2))
        {
          const auto [a, b] = ridge.piece_nodes(f1, k1, p);
          if(a != b) links.push_back(Segment{a, b, p.c1, p.c2, p.jump.strength, p.jump.angle, false});
        }
      }
    }
    return links;
  }

  Ridge& ridge;
};

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_LINK_GRAPH_H
