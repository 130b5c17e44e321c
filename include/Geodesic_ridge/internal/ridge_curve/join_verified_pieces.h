// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 pass: a detached piece of the ridge that holds a verified kink
// (two fronts of one split copy) is a real branch: joined to the main piece.
// Test: test_ridge_accuracy.cpp, "detached pieces with a verified kink: the
// major ridge at a small tolerance".
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_JOIN_VERIFIED_PIECES_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_JOIN_VERIFIED_PIECES_H

#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>
#include <Geodesic_ridge/internal/ridge_curve/link_graph.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// Stage 3 pass: detached pieces that hold a verified kink joined to the main piece.
template <class Ridge>
class Verified_piece_joining
{
  typedef typename Ridge::Segment Segment;
  typedef typename Ridge::Link_graph Link_graph;
  static constexpr std::size_t none = Ridge::none;

public:
  explicit Verified_piece_joining(Ridge& ridge) : ridge(ridge), paths(ridge) {}

  // A piece of the ridge detached from the main one (the longest, or the
  // loops' piece) is dropped, unless it holds a verified kink: a segment
  // between two fronts of one split copy (split at a kink by the solver's
  // cones, `Kink_splitter`, or into the nearer copies' fronts it recombines,
  // `Recombined_copy_splitter`). Such a piece is a real branch whose link to
  // the rest was missed where its fronts meet at a smaller angle than a split
  // needs, or where no cone gave a corner's front (teddy_3k v894 at tolerance
  // 0.002: a branch of 13 mean edges, 3.5 from the main piece, its link 40
  // degrees). It is joined to the main piece, longest first, by the path along
  // the boundaries between cells that is shortest in length over the gradient
  // jump, through no node of another piece: two trees joined by a path close
  // no cycle. A piece with a cycle of its own stays detached (joining it would
  // add one), and so does a piece farther from the main one than its own
  // length: that is a fragment of a branch the tolerance pruned from K
  // (trim_star_10k v1038 at the default tolerance: pieces of 3 mean edges, 18
  // of path along mesh edges each, precision p95 0.07 -> 0.20 when joined).
  void run()
  {
    // a node of each piece not joined (too far in space, no path, a path too
    // long); tried again after a join, which brings the main piece nearer
    std::vector<std::size_t> skipped;
    for(;;)
    {
      Pieces pieces = ridge_pieces();
      std::set<std::size_t> skip;
      for(std::size_t v : skipped) skip.insert(pieces.uf.find(v));
      std::size_t from = none;
      for(const auto& [r, p] : pieces.piece)
        if(r != pieces.main && p.verified && !p.border && p.segments + 1 == p.nodes && !skip.count(r) &&
           (from == none || p.length > pieces.piece.at(from).length))
          from = r;
      if(from == none) return;
      const double piece_length = pieces.piece.at(from).length;
      std::vector<std::size_t> from_nodes;
      for(std::size_t v = 0; v < pieces.in_piece.size(); ++v)
        if(pieces.in_piece[v] && pieces.uf.find(v) == from) from_nodes.push_back(v);
      // (a path is no shorter than the gap in space; with a border, nodes on it
      // come with the links, so the gap is not known before)
      if(ridge.number_of_loops == 0 && !ridge.links && gap_in_space(pieces, from_nodes) > piece_length)
      {
        skipped.push_back(from_nodes.front());
        continue;
      }
      // Without the whole link graph (built by the border join), the links
      // near the piece only: a joining path is no longer than the piece, so
      // it stays within that distance of it in space, and the path taken is
      // the lightest of those near the piece. (The whole graph took 0.2 s on
      // kitten_80k, source 0, fast marching: 40 % of the process. A lighter
      // path through the whole graph that is longer than the piece would have
      // left it detached: on none of bench_ridge_accuracy's 168 pairs.)
      Link_graph near;
      const Link_graph* g = ridge.links ? &*ridge.links : nullptr;
      if(!g)
      {
        const std::size_t nodes_before = ridge.nodes.size();
        near = paths.links_within(from_nodes, piece_length);
        g = &near;
        if(ridge.nodes.size() != nodes_before) pieces = ridge_pieces(); // (the loops' node ids moved)
        from = pieces.uf.find(from_nodes.front());
      }
      auto piece_of = [&](std::size_t v) { return pieces.in_piece[v] ? pieces.uf.find(v) : none; };
      double path_length = 0;
      const std::vector<std::size_t> path = paths.shortest_link_path(
          *g, from_nodes, [&](std::size_t v) { return piece_of(v) == pieces.main; },
          [&](std::size_t v) { return piece_of(v) != none && piece_of(v) != from; }, piece_length, path_length);
      if(path.empty() || path_length > piece_length)
      {
        skipped.push_back(from_nodes.front());
        continue;
      }
      paths.add_ridge_links(*g, path);
      ridge.statistics.piece_joining_segments += path.size();
      skipped.clear();
    }
  }

private:
  // The pieces of the ridge: nodes joined by ridge segments, the loops and
  // the nodes on them; per piece its length, segments and nodes (a tree has
  // one node more), whether it holds a verified kink (two fronts of one split
  // copy) or the border; the main piece (the loops', or the longest).
  struct Piece { double length = 0; std::size_t segments = 0, nodes = 0; bool verified = false, border = false; };
  struct Pieces
  {
    Union_find uf;
    std::vector<char> in_piece; // per node
    std::map<std::size_t, Piece> piece;
    std::size_t main = none;
  };
  Pieces ridge_pieces() const
  {
    const std::size_t n = ridge.nodes.size() + ridge.number_of_loops;
    Pieces x{Union_find(n), std::vector<char>(n, 0), {}, none};
    ridge.join_border_nodes(x.uf);
    for(std::size_t v = 0; v < n; ++v) x.in_piece[v] = v >= ridge.nodes.size() || ridge.node_loop[v] != none;
    for(const Segment& sg : ridge.segments)
      if(sg.ridge && sg.a != sg.b) { x.uf.unite(sg.a, sg.b); x.in_piece[sg.a] = x.in_piece[sg.b] = 1; }
    for(const Segment& sg : ridge.segments)
      if(sg.ridge && sg.a != sg.b)
      {
        Piece& p = x.piece[x.uf.find(sg.a)];
        p.length += ridge.length(sg);
        ++p.segments;
        p.verified = p.verified || (ridge.cells[sg.left].split && ridge.cells[sg.right].split &&
                                    ridge.cells[sg.left].copy == ridge.cells[sg.right].copy);
      }
    for(std::size_t v = 0; v < n; ++v)
      if(x.in_piece[v])
      {
        Piece& p = x.piece[x.uf.find(v)];
        ++p.nodes;
        p.border = p.border || v >= ridge.nodes.size() || ridge.node_loop[v] != none;
      }
    if(ridge.number_of_loops > 0) x.main = x.uf.find(ridge.loop_node(0));
    else
      for(const auto& [r, p] : x.piece) if(x.main == none || p.length > x.piece.at(x.main).length) x.main = r;
    return x;
  }
  // The distance in space from the nodes `from_nodes` to the main piece's
  // (no path along the surface is shorter).
  double gap_in_space(const Pieces& pieces, const std::vector<std::size_t>& from_nodes) const
  {
    double gap = std::numeric_limits<double>::infinity();
    for(std::size_t b = 0; b < ridge.nodes.size(); ++b)
      if(pieces.in_piece[b] && pieces.uf.find(b) == pieces.main)
        for(std::size_t a : from_nodes)
          gap = std::min(gap, CGAL::to_double(CGAL::squared_distance(ridge.nodes[a].point, ridge.nodes[b].point)));
    return std::sqrt(gap);
  }

  Ridge& ridge;
  Link_paths<Ridge> paths;
};

template <class Ridge>
void join_verified_pieces(Ridge& ridge)
{
  Verified_piece_joining<Ridge>(ridge).run();
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_JOIN_VERIFIED_PIECES_H
