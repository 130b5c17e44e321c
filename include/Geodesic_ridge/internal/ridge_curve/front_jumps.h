// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3: the angle between two fronts where they meet, from the arrival
// directions the solver's cones give (else from the linear fields).
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_FRONT_JUMPS_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_FRONT_JUMPS_H

#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>

#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace Geodesic_ridge {
namespace internal {

// The jump of a ridge segment between its two fronts (`segments_inside_faces`,
// `segments_along_edges`), from the solver's cones where it read them.
template <class Ridge>
class Front_jumps
{
  typedef typename Ridge::Q Q;
  typedef typename Ridge::Point Point;
  typedef typename Ridge::Cell Cell;
  typedef typename Ridge::Edge_piece Edge_piece;

public:
  explicit Front_jumps(const Ridge& ridge) : ridge(ridge) {}

  // The jump of a ridge segment: between the arrival directions of its two
  // fronts, read from the solver's cones, where both cells give one; else
  // between their linear fields. A linear field is exact at its copy's
  // corners only: a copy inexact at one corner (a sheet of E that reaches it
  // around a vertex of the cut K, a little longer) has a gradient that points
  // anywhere. Two sheets of one front then met at an envelope edge (or a mesh
  // edge) whose linear jump was 30-90 degrees, drawn as a strong ridge where
  // none is: on CAD models, whose K follows the grid lines of flat faces
  // (`bench_ridge_accuracy --boxes`, box_fans from v0: a ridge line along a
  // grid line, precision p95 1.1 mean edges; the cones' jump there 1-5
  // degrees). Measured in `segments_inside_faces` and `segments_on_edge`.
  Gradient_jump front_jump_in_face(std::size_t f, std::size_t ca, std::size_t cb,
                                   const std::array<std::array<Q, 3>, 2>& ends) const
  {
    std::array<double, 3> mid;
    for(int k = 0; k < 3; ++k) mid[k] = CGAL::to_double((ends[0][k] + ends[1][k]) / 2);
    std::array<double, 3> da, db;
    if(arrival_direction(f, ca, mid, da) && arrival_direction(f, cb, mid, db)) return ridge.jump_between(da, db);
    return ridge.gradient_jump_in_face(ridge.cells[ca], ridge.cells[cb]);
  }

  // the jump across the piece p of edge k1 of f1 (edge k2 of f2), at its
  // middle, as `front_jump_in_face`
  Gradient_jump front_jump_across(std::size_t f1, int k1, std::size_t f2, int k2, const Edge_piece& p) const
  {
    const double t = CGAL::to_double((p.ta + p.tb) / 2);
    std::array<double, 3> at1 = {{0, 0, 0}}, at2 = at1; // the middle, barycentric in f1 and in f2
    at1[k1] = 1 - t;
    at1[(k1 + 1) % 3] = t;
    at2[k2] = t;
    at2[(k2 + 1) % 3] = 1 - t;
    std::array<double, 3> d1, d2;
    if(ridge.at_source(f1, k1) || ridge.at_source(f2, k2) || !arrival_direction(f1, p.c1, at1, d1) ||
       !arrival_direction(f2, p.c2, at2, d2))
      return p.jump;
    const auto cp1 = ridge.faces.corner_points(f1), cp2 = ridge.faces.corner_points(f2);
    return gradient_jump_across_edge(cp1[k1], cp1[(k1 + 1) % 3], cp1[(k1 + 2) % 3], cp2[(k2 + 2) % 3], d1, d2);
  }

private:
  // The arrival direction (unit) of cell c's front at the point `at`
  // (barycentric) of its face f: from the apex of the cone of the sample
  // nearest to it, if the solver read the copy's cones and those of all its
  // samples point within `consistent_angle` of it there. A copy whose
  // samples' cones point apart straddles a kink (the sample nearest to the
  // segment may lie beyond it); the cones of one front's windows around a
  // vertex of K point a few degrees apart. Measured (`bench_ridge_accuracy`,
  // exact solver; precision p95 (>= 30 degrees) <= 0.25 / <= 0.5; pairs whose
  // recall at the default tolerance is above a mean edge): any cone, 168
  // pairs 167 / 168 and 4 (bunny_7k v3136 lost a branch of 90-degree jumps:
  // the nearest samples of unsplit copies lay beyond a kink), real models 60
  // / 68; within 5 degrees 165 / 168 and 1, real 56 / 67; within 15 degrees
  // 166 / 168 and 2, real 59 / 70.
  bool arrival_direction(std::size_t f, std::size_t c, const std::array<double, 3>& at,
                         std::array<double, 3>& direction) const
  {
    typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
    const double consistent_angle = tuning::ridge::consistent_arrival_degrees;
    if(!ridge.cones) return false;
    const std::size_t S = ridge.cones->samples->size();
    const Cell& cell = ridge.cells[c];
    const Face_cone* split_front = nullptr; // a front of a copy split at a kink: its cone everywhere
    if(cell.split)
    {
      const auto it = ridge.cones->split_fronts->find(cell.copy);
      if(it == ridge.cones->split_fronts->end()) return false; // (split into nearer copies' fronts)
      const std::vector<std::size_t>& entries = ridge.face_copies[f].copies;
      const std::size_t front = std::size_t(std::count(entries.begin(), entries.begin() + cell.entry, cell.copy));
      if(front >= it->second.size()) return false;
      split_front = &it->second[front];
    }
    else if(S * (cell.copy + 1) > ridge.cones->per_copy->size()) return false;
    auto cone_at_sample = [&](std::size_t i) -> const Face_cone& {
      return split_front ? *split_front : (*ridge.cones->per_copy)[S * cell.copy + i];
    };
    std::size_t nearest = 0;
    double nearest_d2 = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < S; ++i)
    {
      const std::array<double, 3>& q = (*ridge.cones->samples)[i];
      double d2 = 0;
      for(int k = 0; k < 3; ++k) d2 += (q[k] - at[k]) * (q[k] - at[k]);
      if(d2 < nearest_d2) { nearest_d2 = d2; nearest = i; }
    }
    const auto p = ridge.faces.corner_points(f);
    const Point x = barycentric_to_point(at, p[0], p[1], p[2]);
    auto from_apex = [&](std::size_t i, Vector& v) {
      const Face_cone& cone = cone_at_sample(i);
      // not read, or the source (or an apex) at the sample
      if(std::abs(cone.apex[0] + cone.apex[1] + cone.apex[2] - 1) > 0.5 ||
         (!split_front && cone.apex == (*ridge.cones->samples)[i]))
        return false;
      v = x - barycentric_to_point(cone.apex, p[0], p[1], p[2]);
      return v != CGAL::NULL_VECTOR;
    };
    Vector v;
    if(!from_apex(nearest, v)) return false;
    for(std::size_t i = 0; i < S; ++i)
    {
      Vector w;
      if(!from_apex(i, w) || CGAL::to_double(CGAL::approximate_angle(v, w)) > consistent_angle) return false;
    }
    const double length = std::sqrt(CGAL::to_double(v.squared_length()));
    direction = {{CGAL::to_double(v.x()) / length, CGAL::to_double(v.y()) / length, CGAL::to_double(v.z()) / length}};
    return true;
  }

  const Ridge& ridge;
};

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_FRONT_JUMPS_H
