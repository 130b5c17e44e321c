// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 pass: the ridge inside faces, the envelope's edges between cells
// that are different fronts (cells with equal fields are one front).
// Test: test_ridge_passes.cpp, "envelope_cells and segments_inside_faces: ..."
// and "segments_inside_faces: fields equal within the solver's noise are one
// front".
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_SEGMENTS_INSIDE_FACES_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_SEGMENTS_INSIDE_FACES_H

#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>
#include <Geodesic_ridge/internal/ridge_curve/front_jumps.h>

namespace Geodesic_ridge {
namespace internal {

// Inside faces: the envelope's edges between different fronts.
template <class Ridge>
void segments_inside_faces(Ridge& ridge)
{
  typedef typename Ridge::Segment Segment;
  const Front_jumps<Ridge> jumps(ridge);
  for(std::size_t f = 0; f < ridge.nf; ++f)
  {
    for(const auto& s : ridge.envelope_of[f]->segments)
    {
      const std::size_t ca = ridge.cell_of(f, s.copy_a), cb = ridge.cell_of(f, s.copy_b);
      const std::size_t a = ridge.node_at(f, s.endpoints[0]), b = ridge.node_at(f, s.endpoints[1]);
      // (a boundary of length 0, one surface point, joins no regions and is no ridge)
      if(a == b) continue;
      if(ridge.same_field(ridge.cells[ca].field, ridge.cells[cb].field)) { ridge.fronts.unite(ca, cb); continue; }
      const Gradient_jump j = jumps.front_jump_in_face(f, ca, cb, s.endpoints);
      ridge.segments.push_back(Segment{a, b, ca, cb, j.strength, j.angle, true});
      ++ridge.statistics.envelope_segments;
    }
  }
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_SEGMENTS_INSIDE_FACES_H
