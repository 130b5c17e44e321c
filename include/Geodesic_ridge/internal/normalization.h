// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every stage computes on the mesh moved and scaled to a unit size, and every
// output is mapped back: the ridge does not depend on the scale or the
// position of the input (issue 41). The stages square and multiply
// coordinates (areas, lengths, planes, cross products): at 1e-100 a squared
// length is below double's range, at 1e160 above it, and the tolerances that
// compare lengths with the mesh's size need the size near 1.
//
// The scale is a power of two, so scaling is exact: a mesh scaled by 2^k gives
// bit for bit the ridge of the mesh (times 2^k). The translation rounds every
// coordinate once, so it is made only where it buys precision: when the mesh
// lies farther from the origin than its own size.
#ifndef GEODESIC_RIDGE_INTERNAL_NORMALIZATION_H
#define GEODESIC_RIDGE_INTERNAL_NORMALIZATION_H

#include <Geodesic_ridge/internal/mesh_maps.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

namespace Geodesic_ridge {
namespace internal {

/// The length of `d`, its components divided by the largest first: no
/// square leaves double's range (a squared 1e-300 is 0, a squared 1e300
/// infinite).
inline double length_at_any_scale(const std::array<double, 3>& d)
{
  const double m = (std::max)({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
  if(!(m > 0) || !std::isfinite(m)) return m;
  return m * std::sqrt((d[0] / m) * (d[0] / m) + (d[1] / m) * (d[1] / m) + (d[2] / m) * (d[2] / m));
}

/// The same for a CGAL vector.
template <class Vector>
double length_at_any_scale(const Vector& d)
{
  return length_at_any_scale(
      std::array<double, 3>{{CGAL::to_double(d.x()), CGAL::to_double(d.y()), CGAL::to_double(d.z())}});
}

/// The map from the input's coordinates to the unit ones the stages compute
/// with: q = (p - centre) * 2^-exponent.
struct Normalization
{
  std::array<double, 3> centre = {{0, 0, 0}};
  int exponent = 0;

  bool identity() const { return exponent == 0 && centre[0] == 0 && centre[1] == 0 && centre[2] == 0; }
  double length_to_unit(double d) const { return std::ldexp(d, -exponent); }
  double length_from_unit(double d) const { return std::ldexp(d, exponent); }
  // may leave double's range (an area of 1e600): then +inf or 0, which is what
  // the number is
  double area_from_unit(double a) const { return std::ldexp(std::ldexp(a, exponent), exponent); }

  // The factor 2^e in two halves: a mesh of subnormal size needs 2^1073,
  // beyond double's range in one factor. Exact either way.
  template <class FT>
  static FT times_power_of_two(const FT& x, int e)
  {
    return x * FT(std::ldexp(1.0, e / 2)) * FT(std::ldexp(1.0, e - e / 2));
  }

  template <class Point>
  Point to_unit(const Point& p) const
  {
    if(identity()) return p;
    typedef typename CGAL::Kernel_traits<Point>::Kernel::FT FT;
    return Point(times_power_of_two(p.x() - FT(centre[0]), -exponent),
                 times_power_of_two(p.y() - FT(centre[1]), -exponent),
                 times_power_of_two(p.z() - FT(centre[2]), -exponent));
  }
  template <class Point>
  Point from_unit(const Point& q) const
  {
    if(identity()) return q;
    typedef typename CGAL::Kernel_traits<Point>::Kernel::FT FT;
    return Point(times_power_of_two(q.x(), exponent) + FT(centre[0]), times_power_of_two(q.y(), exponent) + FT(centre[1]),
                 times_power_of_two(q.z(), exponent) + FT(centre[2]));
  }
};

/// The normalization of points given one by one: their bounding box's
/// largest side becomes a length in [1, 2). Identity if a coordinate is not
/// finite (the validation names it) or all points are one.
class Normalization_of_points
{
public:
  template <class Point>
  void add(const Point& p)
  {
    const std::array<double, 3> x = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
    for(int i = 0; i < 3; ++i)
    {
      finite_ = finite_ && std::isfinite(x[i]);
      lo_[i] = (std::min)(lo_[i], x[i]);
      hi_[i] = (std::max)(hi_[i], x[i]);
    }
  }

  Normalization normalization() const
  {
    Normalization n;
    if(!finite_ || !(lo_[0] <= hi_[0])) return n;
    double half_side = 0, far = 0; // halves: no overflow near double's largest value
    std::array<double, 3> centre;
    for(int i = 0; i < 3; ++i)
    {
      half_side = (std::max)(half_side, hi_[i] / 2 - lo_[i] / 2);
      centre[i] = lo_[i] / 2 + hi_[i] / 2;
      far = (std::max)(far, std::abs(centre[i]));
    }
    if(!(half_side > 0)) return n;
    n.exponent = std::ilogb(half_side) + 1; // the largest side / 2^exponent in [1, 2)
    if(far > 2 * half_side) n.centre = centre;
    return n;
  }

private:
  std::array<double, 3> lo_ = {{HUGE_VAL, HUGE_VAL, HUGE_VAL}}, hi_ = {{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  bool finite_ = true;
};

/// The normalization of the vertices of `tm`.
template <class TriangleMesh, class VertexPointMap>
Normalization normalization_of(const TriangleMesh& tm, const VertexPointMap& vpm)
{
  Normalization_of_points points;
  for(auto v : vertices(tm)) points.add(get(vpm, v));
  return points.normalization();
}

/// The input's vertex point map seen through a `Normalization`: what the
/// stages read.
template <class VertexPointMap>
struct Normalized_point_map
{
  typedef typename boost::property_traits<VertexPointMap>::key_type key_type;
  typedef typename boost::property_traits<VertexPointMap>::value_type value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;

  VertexPointMap vpm;
  Normalization normalization;

  friend value_type get(const Normalized_point_map& m, const key_type& k)
  {
    return m.normalization.to_unit(value_type(get(m.vpm, k)));
  }
};

/// The named parameters `np` with the vertex point map of `tm` seen through
/// its normalization (written to `n`): what an entry point hands the stages.
template <class TriangleMesh, class NamedParameters>
auto unit_parameters(const TriangleMesh& tm, const NamedParameters& np, Normalization& n)
{
  const auto vpm = mesh_maps(tm, np).vpm;
  n = normalization_of(tm, vpm);
  return np.vertex_point_map(Normalized_point_map<std::decay_t<decltype(vpm)> >{vpm, n});
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_NORMALIZATION_H
