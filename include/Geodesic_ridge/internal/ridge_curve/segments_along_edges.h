// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 pass: the ridge along mesh edges, between the cells of the two
// faces at an edge that are different fronts.
// Test: test_ridge_passes.cpp, "segments_along_edges: an edge between sheets,
// or a kink inside one sheet, is ridge".
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_SEGMENTS_ALONG_EDGES_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_SEGMENTS_ALONG_EDGES_H

#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>
#include <Geodesic_ridge/internal/ridge_curve/front_jumps.h>

#include <vector>

namespace Geodesic_ridge {
namespace internal {

// Stage 3 pass: the ridge along mesh edges. Every inner edge is split at
// the cell boundaries of both its faces; a piece whose two cells are
// different fronts (not glued in E, or kinked, and not one front by their
// values and a small jump) is a ridge segment.
template <class Ridge>
class Edge_segments
{
  typedef typename Ridge::Q Q;
  typedef typename Ridge::Segment Segment;
  typedef typename Ridge::Edge_piece Edge_piece;
  typedef typename Ridge::Cell Cell;
  typedef typename Ridge::halfedge_descriptor halfedge_descriptor;
  static constexpr std::size_t none = Ridge::none;

public:
  explicit Edge_segments(Ridge& ridge) : ridge(ridge), jumps(ridge) {}

  // Along mesh edges: every edge split by both sides' cell boundaries.
  void run()
  {
    std::vector<char> edge_done(num_edges(ridge.tm), 0);
    for(std::size_t f1 = 0; f1 < ridge.nf; ++f1)
    {
      const auto h1s = ridge.faces.corner_halfedges(f1);
      for(int k1 = 0; k1 < 3; ++k1)
      {
        const std::size_t e = get(ridge.maps.eim, edge(h1s[k1], ridge.tm));
        if(edge_done[e]) continue;
        edge_done[e] = 1;
        const halfedge_descriptor h2 = opposite(h1s[k1], ridge.tm);
        if(is_border(h2, ridge.tm)) continue; // the border of M: one side only
        const std::size_t f2 = get(ridge.maps.fim, face(h2, ridge.tm));
        const auto h2s = ridge.faces.corner_halfedges(f2);
        int k2 = 0;
        while(h2s[k2] != h2) ++k2;
        if(!one_sheet_across(f1, k1, f2, k2)) segments_on_edge(f1, k1, f2, k2);
      }
    }
  }

private:
  // Most edges: one cell on either side, glued in E across this edge (one
  // sheet), so one front and no exact arithmetic.
  bool one_sheet_across(std::size_t f1, int k1, std::size_t f2, int k2)
  {
    if(ridge.envelope_of[f1]->cells.size() != 1 || ridge.envelope_of[f2]->cells.size() != 1) return false;
    const std::size_t c1 = ridge.first_cell[f1], c2 = ridge.first_cell[f2];
    if(!ridge.glued_across(c1, k1, c2) || ridge.cells[c1].split || ridge.cells[c2].split ||
       kinked_along(f1, k1, ridge.edge_jump(f1, k1, c1, f2, k2, c2)))
      return false;
    ridge.fronts.unite(c1, c2);
    return true;
  }

  // A kink inside one sheet: glued copies whose gradients jump by at least
  // `kink_angle`. Where the cut graph K lacks a branch of the cut locus, both
  // fronts reach the faces along that branch inside one sheet of E, and only
  // the kink shows the ridge there.
  bool kinked(const Gradient_jump& j) const { return ridge.kink_angle > 0 && j.angle >= ridge.kink_angle; }

  // A kink along edge k of face f, inside one sheet: none at a reflex vertex
  // of the border (angle sum above pi). Shortest paths bend around it, and
  // in its shadow the distance is a cone with its apex there, which the
  // linear fields of the faces at it interpolate as badly as the source's
  // cone: a flat square with a slit in its border (simply connected and flat,
  // so no cut locus) got a one-edge ridge at the slit's end, a linear jump of
  // 66 degrees (issue 38). A generic cut locus meets the border away from its
  // reflex vertices.
  bool kinked_along(std::size_t f, int k, const Gradient_jump& j) const
  {
    if(!kinked(j)) return false;
    const auto h = ridge.faces.corner_halfedges(f);
    for(const auto v : {source(h[k], ridge.tm), target(h[k], ridge.tm)})
    {
      const std::size_t i = get(ridge.maps.vim, v);
      if(ridge.loop_of_vertex[i] != none && ridge.angle_sum[i] > CGAL_PI) return false;
    }
    return true;
  }

  // A ridge segment on each piece where the cells on the two sides are different fronts.
  void segments_on_edge(std::size_t f1, int k1, std::size_t f2, int k2)
  {
    for(const Edge_piece& p : ridge.edge_pieces(f1, k1, f2, k2))
    {
      const auto [a, b] = ridge.piece_nodes(f1, k1, p);
      if(a == b) continue; // (one surface point: joins no regions, no ridge)
      // a front of a split copy is one front with a glued copy only where their fields agree
      const bool glued =
          ridge.glued_across(p.c1, k1, p.c2) && !kinked_along(f1, k1, p.jump) && !ridge.cells[p.c1].split && !ridge.cells[p.c2].split;
      const bool thin = ridge.thin[f1] || ridge.thin[f2];
      if(glued || one_front_along(p.c1, k1, p.c2, k2, p.ta, p.tb, p.jump, thin))
      {
        if(!glued && thin && !one_front_along(p.c1, k1, p.c2, k2, p.ta, p.tb, p.jump, false))
          ++ridge.statistics.thin_face_pieces;
        ridge.fronts.unite(p.c1, p.c2);
        continue;
      }
      const Gradient_jump j = jumps.front_jump_across(f1, k1, f2, k2, p);
      ridge.segments.push_back(Segment{a, b, p.c1, p.c2, j.strength, j.angle, true});
      ++ridge.statistics.edge_segments;
    }
  }

  // One front across the edge piece [ta, tb]: equal values along it and no
  // real gradient jump (below the spur angle: copies of one front, one slightly
  // inexact off the edge). Equal values alone are no test: where the ridge runs
  // along the edge, both fronts agree on it. Except on an edge of a thin face
  // (`thin`, see thin_faces()), whose gradient is no test either.
  bool one_front_along(std::size_t c1, int k1, std::size_t c2, int k2, const Q& ta, const Q& tb,
                       const Gradient_jump& jump, bool thin) const
  {
    auto value = [&](const Cell& c, int k, const Q& tq) { // tq along corner k -> k+1
      const double tt = CGAL::to_double(tq);
      return (1 - tt) * c.field[k] + tt * c.field[(k + 1) % 3];
    };
    auto agree = [&](const Q& t) {
      return std::abs(value(ridge.cells[c1], k1, t) - value(ridge.cells[c2], k2, Q(1) - t)) <= ridge.same_front_tolerance;
    };
    return agree(ta) && agree(tb) && (thin || jump.strength <= tuning::ridge::weak_jump || jump.angle < ridge.minimum_angle);
  }

  Ridge& ridge;
  const Front_jumps<Ridge> jumps;
};

template <class Ridge>
void segments_along_edges(Ridge& ridge)
{
  Edge_segments<Ridge>(ridge).run();
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_SEGMENTS_ALONG_EDGES_H
