// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the cones of a face's cone field agree (the cone ridge's numerics,
// `Cone_ridge_tracer`): the point between two cones' regions on a line
// (bisection), and the junction of three cones (Newton's method).
#ifndef GEODESIC_RIDGE_INTERNAL_CONE_AGREEMENT_H
#define GEODESIC_RIDGE_INTERNAL_CONE_AGREEMENT_H

#include <Geodesic_ridge/internal/face_cone_field.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <set>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// `mean_edge`: the scale of the convergence tests.
class Cone_agreement
{
  typedef Face_plane::Point_2 Point_2;
  typedef Face_plane::Vector_2 Vector_2;
  typedef std::array<double, 3> Bary;

public:
  explicit Cone_agreement(double mean_edge) : mean_edge_(mean_edge) {}

  // Root of value(a) - value(b) on x(s) = x0 + s d, s in [lo, hi], where a is
  // lowest at lo and b at hi; false if the sides do not give two copies or a
  // third copy is lower at the root.
  bool bisect(const Face_cone_field& field, const Point_2& x0, const Vector_2& d, double lo, double hi,
              Point_2& root) const
  {
    auto at = [&](double s) { return x0 + s * d; };
    const std::size_t a = field.lowest(at(lo)).first, b = field.lowest(at(hi)).first;
    if(a == b) return false;
    auto g = [&](double s) { return field.value(a, at(s)) - field.value(b, at(s)); };
    if(!(g(lo) < 0 && g(hi) > 0)) return false;
    for(int it = 0; it < 200 && hi - lo > 1e-15 * (std::abs(lo) + std::abs(hi) + mean_edge_); ++it)
    {
      const double mid = 0.5 * (lo + hi);
      (g(mid) < 0 ? lo : hi) = mid;
    }
    root = at(0.5 * (lo + hi));
    const auto best = field.lowest(root);
    const double va = field.value(a, root);
    return best.first == a || best.first == b || best.second >= va - 1e-12 * (va + mean_edge_);
  }

  // the largest s >= 0 with b + s w inside the face (times `margin`)
  static double room(const Bary& b, const Bary& w, double margin)
  {
    double s = std::numeric_limits<double>::infinity();
    for(int k = 0; k < 3; ++k)
      if(w[k] < 0) s = (std::min)(s, -b[k] / w[k]);
    return margin * s;
  }

  // The copies lowest on circles around x, from radius r down to r/256 (the
  // cones' junction may lie just beside the linear one).
  static std::set<std::size_t> copies_around(const Face_cone_field& field, const Point_2& x, double r)
  {
    std::set<std::size_t> around;
    const int directions = 24;
    for(double radius = r; radius >= r / 256; radius /= 4)
      for(int k = 0; k < directions; ++k)
      {
        const double phi = 2 * CGAL_PI * k / directions;
        around.insert(field.lowest(x + radius * Vector_2(std::cos(phi), std::sin(phi))).first);
      }
    return around;
  }

  // Newton on (v_a - v_b, v_a - v_c) = 0 from x for the copies c; the gradient
  // of a cone is the unit vector from its apex. Whether it converged.
  bool where_three_cones_agree(const Face_cone_field& field, const std::vector<std::size_t>& c, Point_2& x) const
  {
    for(int it = 0; it < 50; ++it)
    {
      std::array<Vector_2, 3> u;
      std::array<double, 3> v;
      for(int j = 0; j < 3; ++j)
      {
        const Vector_2 from_apex = x - field.apex(c[j], x);
        const double len = std::sqrt(from_apex.squared_length());
        if(!(len > 0)) return false;
        u[j] = from_apex / len;
        v[j] = field.value(c[j], x);
      }
      // the Jacobian's rows and the Newton step (Cramer's rule)
      const Vector_2 r0 = u[0] - u[1], r1 = u[0] - u[2];
      const double f0 = v[0] - v[1], f1 = v[0] - v[2];
      const double det = CGAL::determinant(r0, r1);
      if(!(std::abs(det) > 1e-12)) return false;
      const Vector_2 step((r1.y() * f0 - r0.y() * f1) / det, (-r1.x() * f0 + r0.x() * f1) / det);
      x = x - step;
      if(std::sqrt(step.squared_length()) <= 1e-14 * (mean_edge_ + std::sqrt((x - CGAL::ORIGIN).squared_length())))
        return true;
    }
    return false;
  }

private:
  double mean_edge_;
};

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_CONE_AGREEMENT_H
