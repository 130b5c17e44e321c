// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The gradient of a linear field on a triangle, and its jump across an edge:
// how the growth of E (extension_growth.h) finds kinks, and how stage 3
// (ridge_curve.h) compares fronts.
#ifndef GEODESIC_RIDGE_INTERNAL_FIELD_GRADIENTS_H
#define GEODESIC_RIDGE_INTERNAL_FIELD_GRADIENTS_H

#include <CGAL/Kernel/global_functions_3.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Origin.h>
#include <CGAL/number_utils.h>
#include <CGAL/number_type_basic.h>

#include <array>
#include <cmath>
#include <cstdlib>

namespace Geodesic_ridge {
namespace internal {

// Gradient of the linear field with values d at corners p (in the face's plane).
template <class Point_3>
std::array<double, 3> field_gradient(const std::array<Point_3, 3>& p, const std::array<double, 3>& d)
{
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3 Vector;
  // N = (p1 - p0) x (p2 - p0), |N|^2 = (2A)^2
  const Vector n = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
  const double nn = CGAL::to_double(n.squared_length());
  Vector g = CGAL::NULL_VECTOR;
  // grad λ_k = (N x e_k) / |N|^2, e_k the edge opposite corner k
  for(int k = 0; k < 3; ++k) g = g + CGAL::cross_product(n, p[(k + 2) % 3] - p[(k + 1) % 3]) * d[k] / nn;
  return {{CGAL::to_double(g.x()), CGAL::to_double(g.y()), CGAL::to_double(g.z())}};
}

// The jump of a linear field's gradient across the edge [a, b] shared by two
// triangles whose third corners are c1 and c2: g2 is unfolded into the first
// triangle's plane (in the frame t along the edge, n1 into the first triangle,
// it is (g2.t, -g2.n2)). The size of the jump (strength) and the angle between
// the two gradients (degrees).
struct Gradient_jump { double strength, angle; };

template <class Point>
Gradient_jump gradient_jump_across_edge(const Point& a, const Point& b, const Point& c1, const Point& c2,
                                        const std::array<double, 3>& g1, const std::array<double, 3>& g2)
{
  typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
  auto unit = [](const Vector& v) { return v / std::sqrt(CGAL::to_double(v.squared_length())); };
  const Vector t = unit(b - a);
  // unit, in the plane of the edge and c, normal to the edge, towards c
  auto inward = [&](const Point& c) { const Vector w = c - a; return unit(w - (w * t) * t); };
  const Vector v1(g1[0], g1[1], g1[2]), v2(g2[0], g2[1], g2[2]);
  const double x1 = CGAL::to_double(v1 * t), y1 = CGAL::to_double(v1 * inward(c1));
  const double x2 = CGAL::to_double(v2 * t), y2 = -CGAL::to_double(v2 * inward(c2));
  return Gradient_jump{std::sqrt((x1 - x2) * (x1 - x2) + (y1 - y2) * (y1 - y2)),
                       std::atan2(std::abs(x1 * y2 - y1 * x2), x1 * x2 + y1 * y2) * 180 / CGAL_PI};
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_FIELD_GRADIENTS_H
