// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 pass: marks the thin faces, whose linear fields' gradients are
// noise (read by `segments_along_edges`).
// Test: test_ridge_passes.cpp, "thin_faces: ..."; on real meshes with caps,
// bench_ridge_accuracy --caps 0.2 (--without thin-faces).
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_THIN_FACES_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_THIN_FACES_H

#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>

#include <algorithm>
#include <cmath>

namespace Geodesic_ridge {
namespace internal {

// Thin faces: height over the longest edge below `thin_face_ratio` of that
// edge (caps, three corners nearly on a line, and needles). A linear field
// interpolates the distance along the long edge from its two ends only, and
// the corner across it lies a small height h away: the gradient across the
// face is their difference divided by h, so the interpolation's error
// (which grows with the square of the length) becomes a gradient that may
// point anywhere. Two cells on either side of such a face's edge that agree
// along it were then a ridge along the edge (the gradients disagree) that
// is no ridge: on bunny_1k and teddy_3k with caps added (their surfaces
// unchanged, `bench_ridge_accuracy --caps 0.2`), 80-90 % of the ridge samples
// more than half a mean edge off lay on caps, and the beetle's needles
// likewise (user manual, \ref GeodesicRidgeSecThinFaces).
template <class Ridge>
void thin_faces(Ridge& ridge)
{
  const double thin_face_ratio = tuning::ridge::thin_face_ratio;
  for(std::size_t f = 0; f < ridge.nf; ++f)
  {
    const auto p = ridge.faces.corner_points(f);
    double longest2 = 0;
    for(int k = 0; k < 3; ++k)
      longest2 = (std::max)(longest2, CGAL::to_double(CGAL::squared_distance(p[k], p[(k + 1) % 3])));
    // twice the area is the longest edge times the height over it
    const double twice_area = std::sqrt(CGAL::to_double(CGAL::squared_area(p[0], p[1], p[2]))) * 2;
    ridge.thin[f] = twice_area < thin_face_ratio * longest2;
  }
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_THIN_FACES_H
