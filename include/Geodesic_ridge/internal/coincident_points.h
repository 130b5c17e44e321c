// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One surface point, one node. The ridge's points are computed from several
// faces' exact envelopes of rounded fields: one surface point (a node on an
// edge seen from its two faces, an envelope edge that ends 1e-12 of an edge
// from a vertex, a junction traced twice) comes back as several points a few
// units of rounding apart. Kept apart, they let the written ridge, read back
// and merged where its points coincide, have another topology than the
// library's graph (a cycle through a pinched vertex: issue 38, 13 of 96 runs
// on armadillo_2k and teddy_3k). `Coincident_points` gives every point within
// `coincident_tolerance` of an earlier one that earlier one's id.
#ifndef GEODESIC_RIDGE_INTERNAL_COINCIDENT_POINTS_H
#define GEODESIC_RIDGE_INTERNAL_COINCIDENT_POINTS_H

#include <Geodesic_ridge/internal/normalization.h>

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

/// Points closer than this fraction of the bounding box's diagonal are one
/// surface point. Far below any feature of a ridge (a mean edge is 1e-4 to
/// 1e-1 of the diagonal on the meshes measured) and above the rounding of a
/// point computed in several faces: 1e-17 to 1e-13 of the diagonal measured
/// on armadillo_2k and teddy_3k, but a junction at a vertex of high valence,
/// where fronts meet at small angles, moves by the rounding of the fields
/// divided by their angle: 1.6e-10 to 4.1e-10 on the teapot's pole (40
/// faces) with caps, whose three copies made a cycle of the ridge that the
/// topology has not (`bench_ridge_accuracy --repair --caps 0.2`, teapot from
/// v160, with 1e-10). Above 1e-12, the coincidence a reader of the written
/// polylines may assume.
constexpr double coincident_fraction = 1e-9;

/// the absolute tolerance of `coincident_fraction` for a box
inline double coincident_tolerance(const CGAL::Bbox_3& box)
{
  // halves and no squares: right at any scale (a squared 1e-300 is 0, a
  // squared 1e300 infinite)
  return 2 * coincident_fraction *
         length_at_any_scale(
             {{box.xmax() / 2 - box.xmin() / 2, box.ymax() / 2 - box.ymin() / 2, box.zmax() / 2 - box.zmin() / 2}});
}

/// the absolute tolerance of `coincident_fraction` for the vertices of `tm`
template <class TriangleMesh, class VertexPointMap>
double coincident_tolerance(const TriangleMesh& tm, VertexPointMap vpm)
{
  CGAL::Bbox_3 box;
  for(auto v : vertices(tm)) box += get(vpm, v).bbox();
  return coincident_tolerance(box);
}

/// Points by id, each found again by any point within the tolerance
/// (Euclidean): a hash grid of cells as wide as the tolerance.
class Coincident_points
{
public:
  explicit Coincident_points(double tolerance) : tolerance_(tolerance) {}

  /// the id of a point within the tolerance of `p`, or `none`
  std::size_t find(const std::array<double, 3>& p) const
  {
    return find(p, [](std::size_t) { return true; });
  }

  /// the id of a point within the tolerance of `p` for which `accept(id)`
  /// holds (on a surface that touches itself, points of two sheets may
  /// coincide in space and still be two points of the surface), or `none`
  template <class Accept>
  std::size_t find(const std::array<double, 3>& p, const Accept& accept) const
  {
    std::size_t found = none;
    for_each_near(p, [&](std::size_t id) {
      if(!accept(id)) return false;
      found = id;
      return true;
    });
    return found;
  }

  /// calls `visit(id)` for the points within the tolerance of `p` (an id
  /// inserted twice may come twice) until it returns true
  template <class Visit>
  void for_each_near(const std::array<double, 3>& p, const Visit& visit) const
  {
    if(!(tolerance_ > 0)) return;
    const std::array<std::int64_t, 3> c = cell(p);
    for(std::int64_t dx = -1; dx <= 1; ++dx)
      for(std::int64_t dy = -1; dy <= 1; ++dy)
        for(std::int64_t dz = -1; dz <= 1; ++dz)
        {
          const auto it = grid_.find(key({{c[0] + dx, c[1] + dy, c[2] + dz}}));
          if(it == grid_.end()) continue;
          for(std::size_t id : it->second)
            if(within_tolerance(points_[id], p) && visit(id)) return;
        }
  }

  /// `p` as the point of `id` (ids are the caller's; a point may be moved
  /// within the tolerance by inserting it again)
  void insert(std::size_t id, const std::array<double, 3>& p)
  {
    if(points_.size() <= id) points_.resize(id + 1);
    points_[id] = p;
    if(tolerance_ > 0) grid_[key(cell(p))].push_back(id);
  }

  static constexpr std::size_t none = std::size_t(-1);

private:
  bool within_tolerance(const std::array<double, 3>& a, const std::array<double, 3>& b) const
  {
    return length_at_any_scale({{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}) <= tolerance_;
  }
  std::array<std::int64_t, 3> cell(const std::array<double, 3>& p) const
  {
    std::array<std::int64_t, 3> c;
    for(int k = 0; k < 3; ++k)
    {
      // (clamped: a cell index beyond 2^62 only makes neighbours share cells)
      const double x = std::floor(p[k] / tolerance_);
      c[k] = std::int64_t(std::max(-4.0e18, std::min(4.0e18, std::isfinite(x) ? x : 0.0)));
    }
    return c;
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c)
  {
    std::uint64_t h = 1469598103934665603ull;
    for(std::int64_t v : c) h = (h ^ std::uint64_t(v)) * 1099511628211ull;
    return h;
  }

  double tolerance_;
  std::vector<std::array<double, 3> > points_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t> > grid_; // (hash collisions only add candidates)
};

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_COINCIDENT_POINTS_H
