// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3, first pass: the exact lower envelope of every face's copies
// (`compute_lower_envelope`, exact rationals) and its cells.
// Test: test_ridge_passes.cpp, "envelope_cells and segments_inside_faces: ...".
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_ENVELOPE_CELLS_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_ENVELOPE_CELLS_H

#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>

#include <array>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// One copy: its cell is the whole triangle (most faces; no clipping needed),
// made once and shared.
inline Lower_envelope<Exact_number> whole_triangle_envelope()
{
  typedef Exact_number Q;
  Lower_envelope<Q> envelope;
  Envelope_cell<Q> cell;
  cell.copy = 0;
  cell.polygon = {{{Q(1), Q(0), Q(0)}}, {{Q(0), Q(1), Q(0)}}, {{Q(0), Q(0), Q(1)}}};
  cell.edge_label = {triangle_edge_label(0), triangle_edge_label(1), triangle_edge_label(2)};
  envelope.cells.assign(1, cell);
  return envelope;
}

inline std::vector<std::array<double, 3> > polygon_to_double(const std::vector<std::array<Exact_number, 3> >& polygon)
{
  std::vector<std::array<double, 3> > out;
  out.reserve(polygon.size());
  for(const auto& p : polygon) out.push_back({{CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2])}});
  return out;
}

// Pass: per face the lower envelope of its copies, its cells (one per
// surviving copy) and the regions; every cell its own front to begin with.
// The cells of face f are cells[first_cell[f]] to cells[first_cell[f + 1] - 1],
// in the order of its envelope's cells; every array is sized before it is
// filled (one block each, and one per region: most faces have one cell).
template <class Ridge>
void envelope_cells(Ridge& ridge)
{
  typedef typename Ridge::Cell Cell;
  typedef typename Ridge::Q Q;
  ridge.envelope_of.assign(ridge.nf, nullptr);
  ridge.whole_triangle = whole_triangle_envelope();
  ridge.first_cell.assign(ridge.nf + 1, 0);
  for(std::size_t f = 0; f < ridge.nf; ++f)
  {
    const Face_copies& fc = ridge.face_copies[f];
    if(fc.fields.size() == 1) ridge.envelope_of[f] = &ridge.whole_triangle;
    else
    {
      ridge.computed_envelopes.push_back(compute_lower_envelope<Q>(fc.fields));
      ridge.envelope_of[f] = &ridge.computed_envelopes.back();
    }
    if(fc.copies.size() > 1) ++ridge.statistics.faces_with_several_copies;
    ridge.first_cell[f + 1] = ridge.first_cell[f] + ridge.envelope_of[f]->cells.size();
  }
  ridge.statistics.surviving_copies = ridge.first_cell[ridge.nf];
  const std::vector<std::array<double, 3> > whole_polygon = polygon_to_double(ridge.whole_triangle.cells[0].polygon);
  ridge.cells.reserve(ridge.first_cell[ridge.nf]);
  ridge.regions.assign(ridge.nf, {});
  for(std::size_t f = 0; f < ridge.nf; ++f)
  {
    const Face_copies& fc = ridge.face_copies[f];
    const auto cp = ridge.faces.corner_points(f);
    ridge.regions[f].reserve(ridge.envelope_of[f]->cells.size());
    for(const auto& c : ridge.envelope_of[f]->cells)
    {
      const std::array<double, 3>& field = fc.fields[c.copy];
      ridge.cells.push_back(
          Cell{fc.copies[c.copy], field, field_gradient(cp, field), !fc.split.empty() && fc.split[c.copy], c.copy});
      Ridge_region_cell rc;
      rc.copy = fc.copies[c.copy];
      rc.field = field;
      rc.polygon = ridge.envelope_of[f] == &ridge.whole_triangle ? whole_polygon : polygon_to_double(c.polygon);
      ridge.regions[f].push_back(std::move(rc));
    }
  }
  for(std::size_t c = 0; c < ridge.cells.size(); ++c) ridge.fronts.add();
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_ENVELOPE_CELLS_H
