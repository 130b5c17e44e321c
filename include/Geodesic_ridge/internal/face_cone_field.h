// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cone field of one face (`Face_cone_field`): per copy of the face, the
// exact solver's cone of the nearest sample point, or the lowest of the
// window-propagation solver's windows; the field is the lowest over the copies.
#ifndef GEODESIC_RIDGE_INTERNAL_FACE_CONE_FIELD_H
#define GEODESIC_RIDGE_INTERNAL_FACE_CONE_FIELD_H

#include <Geodesic_ridge/solvers/Face_cone.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

/// A face in its own plane: corner 0 at the origin, corner 1 on the x axis at
/// (l, 0), corner 2 at (x2, y2) with y2 > 0. Maps barycentric coordinates (in
/// the order of a `Face_location`) to plane coordinates and back.
struct Face_plane
{
  typedef CGAL::Epick::Point_2 Point_2;
  typedef CGAL::Epick::Vector_2 Vector_2;
  double l = 1, x2 = 0, y2 = 1;

  Face_plane() = default;
  /// from the length of edge 01 and corner 2 in the plane
  Face_plane(double length01, double corner2_x, double corner2_y) : l(length01), x2(corner2_x), y2(corner2_y) {}
  template <class Point_3>
  explicit Face_plane(const std::array<Point_3, 3>& p)
  {
    typedef CGAL::Epick::Vector_3 Vector;
    const Vector e1(CGAL::to_double(p[1].x() - p[0].x()), CGAL::to_double(p[1].y() - p[0].y()),
                    CGAL::to_double(p[1].z() - p[0].z()));
    const Vector e2(CGAL::to_double(p[2].x() - p[0].x()), CGAL::to_double(p[2].y() - p[0].y()),
                    CGAL::to_double(p[2].z() - p[0].z()));
    l = std::sqrt(e1.squared_length());
    x2 = e1 * e2 / l;
    y2 = std::sqrt(CGAL::cross_product(e1, e2).squared_length()) / l;
  }

  Point_2 point(const std::array<double, 3>& b) const { return Point_2(b[1] * l + b[2] * x2, b[2] * y2); }

  /// corner k (0, 1, 2)
  Point_2 corner(int k) const { return k == 0 ? Point_2(0, 0) : k == 1 ? Point_2(l, 0) : Point_2(x2, y2); }

  std::array<double, 3> barycentric(const Point_2& x) const
  {
    const double b2 = x.y() / y2, b1 = (x.x() - b2 * x2) / l;
    return {{1 - b1 - b2, b1, b2}};
  }

  /// the barycentric coordinates of a direction (they sum to 0)
  std::array<double, 3> barycentric(const Vector_2& d) const
  {
    const double b2 = d.y() / y2, b1 = (d.x() - b2 * x2) / l;
    return {{-b1 - b2, b1, b2}};
  }
};

/// A cone's path to plane point `x` of the face: straight from the apex, or
/// for a window (`Face_cone::entry` set) straight if that line crosses the
/// window's part of the entry edge, else around the nearer end of that part
/// (a real path either way). Its apex (the apex, or that end) and length.
inline std::pair<Face_plane::Point_2, double> cone_path(const Face_plane& plane, const Face_cone& cone,
                                                       const Face_plane::Point_2& x)
{
  const Face_plane::Point_2 a = plane.point(cone.apex);
  const double straight = std::sqrt(CGAL::squared_distance(x, a)) + cone.offset;
  if(cone.entry < 0) return {a, straight};
  const int k = cone.entry, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
  const std::array<double, 3> bx = plane.barycentric(x);
  // the apex lies beyond the entry edge (b_k2 <= 0), x on the face's side
  const double alpha = cone.apex[k2], beta = bx[k2];
  if(alpha < beta)
  {
    const double s = -alpha / (beta - alpha);
    const double t = cone.apex[k1] + s * (bx[k1] - cone.apex[k1]); // where it crosses the edge, from corner k
    if(t >= cone.through[0] && t <= cone.through[1]) return {a, straight};
  }
  else if(alpha >= 0)
    return {a, straight}; // the apex on the edge's line (round-off): nothing to go around
  std::pair<Face_plane::Point_2, double> best(a, std::numeric_limits<double>::infinity());
  for(double t : cone.through)
  {
    std::array<double, 3> be = {{0, 0, 0}};
    be[k] = 1 - t;
    be[k1] = t;
    const Face_plane::Point_2 e = plane.point(be);
    const double v = std::sqrt(CGAL::squared_distance(a, e)) + std::sqrt(CGAL::squared_distance(e, x)) + cone.offset;
    if(v < best.second) best = {e, v};
  }
  return best;
}

/// The cone field of one face. Sampled cones (`Exact_solver`): `count`
/// cones, S per copy (copy-major), S the number of `samples`
/// (`Cone_samples::cone_samples()`, or
/// `Cone_samples::cone_ridge_fallback_samples()` for the cone ridge alone); a
/// copy's value at a point is its cone of the nearest sample. Windows
/// (`Window_propagation_solver`, `Face_cone::copy` set): a copy's value is the
/// lowest of its windows', each the length of a real path (straight from the
/// apex through the window's part of its entry edge, else around the nearer
/// end of that part), so the lowest over the copies is the exact distance.
class Face_cone_field
{
public:
  Face_cone_field(const Face_plane& plane, const Face_cone* cones, std::size_t count,
                  const std::vector<std::array<double, 3> >& samples = Cone_samples::cone_samples())
      : plane_(plane), cones_(cones), count_(count), samples_(&samples)
  {
    windows_ = count > 0 && cones[0].copy != Face_cone::no_copy;
    if(windows_)
      for(std::size_t i = 0; i < count; ++i) copies_ = (std::max)(copies_, std::size_t(cones[i].copy) + 1);
    else
      copies_ = count / samples.size();
  }

  std::size_t number_of_copies() const { return copies_; }

  /// The distance by copy `c` at plane point `x`.
  double value(std::size_t c, const Face_plane::Point_2& x) const { return of_copy(c, x).second; }

  /// The copy lowest at `x` (the first of equals) and its distance.
  std::pair<std::size_t, double> lowest(const Face_plane::Point_2& x) const
  {
    std::pair<std::size_t, double> best(0, std::numeric_limits<double>::infinity());
    if(windows_)
    {
      for(std::size_t i = 0; i < count_; ++i)
      {
        const double v = cone_path(plane_, cones_[i], x).second;
        if(v < best.second || (v == best.second && cones_[i].copy < best.first)) best = {cones_[i].copy, v};
      }
      return best;
    }
    const std::size_t S = samples().size();
    for(std::size_t c = nearest_sample(x); c < count_; c += S)
    {
      const double v = cone_value(cones_[c], x);
      if(v < best.second) best = {c / S, v};
    }
    return best;
  }

  /// The apex (in the plane) of the cone that copy `c` uses at `x`: where the
  /// straight way to `x` starts (for a window reached around an end, that end).
  Face_plane::Point_2 apex(std::size_t c, const Face_plane::Point_2& x) const
  {
    if(windows_) return of_copy(c, x).first;
    return plane_.point(cones_[c * samples().size() + nearest_sample(x)].apex);
  }

  const Face_plane& plane() const { return plane_; }

private:
  const std::vector<std::array<double, 3> >& samples() const { return *samples_; }

  // copy c's apex and value at x
  std::pair<Face_plane::Point_2, double> of_copy(std::size_t c, const Face_plane::Point_2& x) const
  {
    if(!windows_)
    {
      const Face_cone& cone = cones_[c * samples().size() + nearest_sample(x)];
      return {plane_.point(cone.apex), cone_value(cone, x)};
    }
    std::pair<Face_plane::Point_2, double> best(x, std::numeric_limits<double>::infinity());
    for(std::size_t i = 0; i < count_; ++i)
      if(cones_[i].copy == c)
      {
        const auto v = cone_path(plane_, cones_[i], x);
        if(v.second < best.second) best = v;
      }
    return best;
  }

  std::size_t nearest_sample(const Face_plane::Point_2& x) const
  {
    std::size_t nearest = 0;
    double nearest_d2 = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < samples().size(); ++i)
    {
      const double d2 = CGAL::squared_distance(x, plane_.point(samples()[i]));
      if(d2 < nearest_d2) { nearest_d2 = d2; nearest = i; }
    }
    return nearest;
  }

  double cone_value(const Face_cone& cone, const Face_plane::Point_2& x) const
  {
    return std::sqrt(CGAL::squared_distance(x, plane_.point(cone.apex))) + cone.offset;
  }

private:
  Face_plane plane_;
  const Face_cone* cones_;
  std::size_t count_;
  const std::vector<std::array<double, 3> >* samples_;
  bool windows_ = false;
  std::size_t copies_ = 0;
};

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_FACE_CONE_FIELD_H
