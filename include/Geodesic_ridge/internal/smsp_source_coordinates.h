// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The barycentric coordinates to give CGAL's Surface_mesh_shortest_path (SMSP)
// for a source point: the exact solver's, and the tests' references (the
// reference ridge, the exact distances on M) use the same.
#ifndef GEODESIC_RIDGE_INTERNAL_SMSP_SOURCE_COORDINATES_H
#define GEODESIC_RIDGE_INTERNAL_SMSP_SOURCE_COORDINATES_H

#include <CGAL/config.h> // CGAL_VERSION_NR, CGAL_VERSION_NUMBER

#include <array>

namespace Geodesic_ridge {
namespace internal {

// CGAL before 5.6 expands a source on an edge (one coordinate 0) wrongly (CGAL
// issue #6681, fixed by pull request #6739): on an inner edge no cone starts
// towards the edge's ends (measured on the doubly covered square: distances
// 0.4 mean edges too long; on the flat square up to 0.31 too long, 1.25
// edges); on a BORDER edge the source is put at the mirror image of its
// position along the edge (`expand_edge_root()` passes the edge source's
// coordinate where `face_location()` takes the target's; measured: off by
// |1 - 2t| of the edge). The point is moved into its face by 2^-40 of the
// barycentric range instead, which changes distances by about 1e-13 of an
// edge.
template <class FT>
std::array<FT, 3> smsp_source_coordinates(std::array<FT, 3> w)
{
#if CGAL_VERSION_NR < CGAL_VERSION_NUMBER(5, 6, 0)
  int zeros = 0;
  for(const FT& x : w) zeros += (x == FT(0));
  if(zeros == 1)
  {
    const FT nudge = FT(1) / FT(1099511627776.0);
    for(FT& x : w) x = (x == FT(0)) ? nudge : x * (FT(1) - nudge);
  }
#endif
  return w;
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_SMSP_SOURCE_COORDINATES_H
