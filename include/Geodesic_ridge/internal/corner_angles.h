// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Corner angles of a triangle mesh and the angle sum at every vertex, from
// which the discrete Gaussian curvature 2π − angle sum follows. Stage 1 shares
// the curvature among faces (curvature branches of the cut), stage 3 sums it
// around free ends of the ridge (flat ends, corners).
#ifndef GEODESIC_RIDGE_INTERNAL_CORNER_ANGLES_H
#define GEODESIC_RIDGE_INTERNAL_CORNER_ANGLES_H

#include <CGAL/number_type_config.h>
#include <CGAL/number_utils.h>
#include <CGAL/Kernel/global_functions.h>

#include <array>
#include <cmath>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

struct Corner_angles
{
  /// per face (by face index): the angle at corner k = source(next^k(halfedge(f)))
  std::vector<std::array<double, 3> > angle;
  /// per vertex (by vertex index): the sum of its corner angles
  std::vector<double> angle_sum;
  /// 2π − angle sum at vertex v (by index): its Gaussian curvature
  double curvature(std::size_t v) const { return 2 * CGAL_PI - angle_sum[v]; }
};

inline double radians(double degrees) { return degrees * CGAL_PI / 180; }

template <class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap>
Corner_angles corner_angles(const TriangleMesh& tm, const VertexPointMap& vpm, const VertexIndexMap& vim,
                            const FaceIndexMap& fim)
{
  Corner_angles r;
  r.angle.assign(num_faces(tm), {{0, 0, 0}});
  r.angle_sum.assign(num_vertices(tm), 0.0);
  for(auto f : faces(tm))
  {
    const auto h0 = halfedge(f, tm);
    const std::array<decltype(h0), 3> h = {{h0, next(h0, tm), next(next(h0, tm), tm)}};
    for(int k = 0; k < 3; ++k)
    {
      const auto& o = get(vpm, source(h[k], tm));
      const auto& a = get(vpm, target(h[k], tm));
      const auto& b = get(vpm, source(h[(k + 2) % 3], tm));
      const auto u = a - o, v = b - o;
      const double angle = std::atan2(std::sqrt(CGAL::to_double(CGAL::cross_product(u, v).squared_length())),
                                      CGAL::to_double(u * v));
      r.angle[get(fim, f)][k] = angle;
      r.angle_sum[get(vim, source(h[k], tm))] += angle;
    }
  }
  return r;
}

} // namespace internal
} // namespace Geodesic_ridge

#endif
