// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3: the ridge curve (user manual, "Stage 3: The Ridge Curve"): what it
// gives (its points, the regions of the linear field, its counts). The passes
// that compute it are in internal/ridge_curve/, run in order by
// `internal::assemble_ridge_curve()` (internal/ridge_curve/assemble_ridge_curve.h).
#ifndef GEODESIC_RIDGE_RIDGE_CURVE_H
#define GEODESIC_RIDGE_RIDGE_CURVE_H

#include <array>
#include <cstddef>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// A point of the ridge: its surface location in M (face index, barycentric
/// coordinates in CGAL's order), its 3D point, and the angle between the two
/// fronts that meet there.
template <class Point_3>
struct Ridge_point
{
  /// the face of M (its index)
  std::size_t face = 0;
  /// barycentric coordinates in the face, in CGAL's corner order
  std::array<double, 3> barycentric = {{0, 0, 0}};
  /// the 3D point
  Point_3 point;
  /// degrees: the largest angle between the arrival directions of the two
  /// fronts over the ridge segments at this point
  double angle = 0;
};

/// \ingroup PkgGeodesicRidgeRef
/// \brief writes the 3D points of every polyline of `polylines` (as
/// `Ridge_curve::polylines` holds them) to `out`, one `std::vector<Point_3>`
/// per polyline: what `IO::write_polylines()` and CGAL's polyline tools take.
template <class Point_3, class OutputIterator>
OutputIterator ridge_polyline_points(const std::vector<std::vector<Ridge_point<Point_3> > >& polylines,
                                     OutputIterator out)
{
  for(const auto& polyline : polylines)
  {
    std::vector<Point_3> points;
    points.reserve(polyline.size());
    for(const Ridge_point<Point_3>& p : polyline) points.push_back(p.point);
    *out++ = std::move(points);
  }
  return out;
}

/// \ingroup PkgGeodesicRidgeRef
/// The linear field of one copy over its cell of an original face.
struct Ridge_region_cell
{
  std::size_t copy = 0;                     ///< face of the extended surface
  std::array<double, 3> field = {{0, 0, 0}}; ///< distances at the face's corners
  std::vector<std::array<double, 3> > polygon; ///< the cell, barycentric (rounded from exact)
};

/// \ingroup PkgGeodesicRidgeRef
/// Counts of stage 3.
struct Ridge_curve_statistics
{
  /// faces of M with more than one undominated copy
  std::size_t faces_with_several_copies = 0;
  std::size_t surviving_copies = 0;       ///< copies not dominated, over all faces
  std::size_t split_copies = 0;           ///< copies split at a kink between their corners' fronts (cones)
  std::size_t envelope_segments = 0;      ///< inside faces, between different fronts
  std::size_t edge_segments = 0;          ///< along mesh edges, between different fronts
  /// edge pieces of thin faces whose two sides are one front by their values
  /// alone (their gradients disagree; a thin face has none to trust)
  std::size_t thin_face_pieces = 0;
  /// thin-face pieces of a first assembly whose ridge lacked a cycle of the
  /// topology (1 component, 2g + b cycles): the ridge was assembled again
  /// without them (0: the first assembly stands)
  std::size_t thin_face_pieces_undone = 0;
  std::size_t regions_before_merge = 0;   ///< components of M minus the raw ridge
  std::size_t merged_segments = 0;        ///< segments removed to merge regions
  std::size_t rejoined_segments = 0;      ///< merged segments put back to join two pieces of the ridge
  /// cell boundaries made ridge to join the pieces that hang from different border loops
  std::size_t border_joining_segments = 0;
  std::size_t dropped_components = 0;     ///< detached pieces dropped
  /// cell boundaries made ridge to join to the main piece the detached pieces
  /// that hold a verified kink (two fronts of one split copy)
  std::size_t piece_joining_segments = 0;
  std::size_t recombined_copies = 0;      ///< copies split into the fronts of nearer copies they recombine
  /// free-end segments with a gradient jump below the minimum angle, pruned
  /// by one of the next three rules (their sum)
  std::size_t pruned_spur_segments = 0;
  /// ... at a vertex without positive curvature, or on the chain of weak
  /// segments behind one (no cut locus ends there)
  std::size_t spurs_at_impossible_ends = 0;
  /// ... with less curvature near the end than a corner has
  std::size_t spurs_away_from_corners = 0;
  /// ... at a corner, but with a jump too small for any corner's
  std::size_t spurs_too_weak_for_corners = 0;
  std::size_t pruned_flat_end_segments = 0; ///< free-end segments with no positive curvature near their end
  /// ridge points computed again (from another face, or a few units of
  /// rounding from a vertex or an edge) that are one node of the ridge
  std::size_t coincident_points = 0;
  /// \name The Ridge
  //@{
  /// The ridge's segments, junctions (points where three or more regions
  /// meet), free ends (not on the border), connected components and
  /// independent cycles of the ridge with the border of M: 1 and 2g + b (b
  /// border loops; 2g on a closed mesh).
  std::size_t ridge_segments = 0, junctions = 0, free_ends = 0, components = 0, cycles = 0;
  //@}
  /// the ridge's total length
  double total_length = 0;
};

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_RIDGE_CURVE_H
