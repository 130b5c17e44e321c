// Copyright (c) 2026 Geodesic_ridge developers.
//
// Named parameters of the package. CGAL's list of named parameters is closed
// to outside packages, so our own knobs are tag types of our own; CGAL's
// members (vertex_point_map, face_index_map, ...) still chain after them, and
// our own ones take the parameters to extend as a last argument:
//   Geodesic_ridge::parameters::tolerance(0.01).vertex_point_map(vpm)
//   Geodesic_ridge::parameters::maximum_rings(12, parameters::tolerance(0.01))
#ifndef GEODESIC_RIDGE_PARAMETERS_H
#define GEODESIC_RIDGE_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Geodesic_ridge/exceptions.h>

#include <cmath>
#include <string>

namespace Geodesic_ridge {
namespace internal_np {
/// Tag of the significance tolerance (a fraction of the total area).
struct tolerance_t {};
} // namespace internal_np

/// Default significance tolerance, as recommended by the paper (§4.4).
constexpr double default_tolerance = 0.025;

namespace parameters {

/// \ingroup PkgGeodesicRidgeNamedParameters
/// Dual edges of the cut locus whose significance is below `t` times the
/// total area are pruned. `t` must be in [0, 0.5).
inline CGAL::Named_function_parameters<double, internal_np::tolerance_t>
tolerance(double t)
{
  return CGAL::Named_function_parameters<double, internal_np::tolerance_t>(t);
}

/// Same, added to the named parameters `np`.
template <class NamedParameters>
CGAL::Named_function_parameters<double, internal_np::tolerance_t, NamedParameters>
tolerance(double t, const NamedParameters& np)
{
  return CGAL::Named_function_parameters<double, internal_np::tolerance_t, NamedParameters>(t, np);
}

} // namespace parameters

namespace internal {

/// Reads the tolerance from `np` (default: `default_tolerance`) and checks it.
template <class NamedParameters>
double get_tolerance(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double t = choose_parameter(get_parameter(np, internal_np::tolerance_t()),
                                    default_tolerance);
  if(!(t >= 0.0 && t < 0.5)) // also rejects NaN
    throw Invalid_parameter_error("tolerance " + std::to_string(t) +
                                  " is out of range: it must be in [0, 0.5)");
  return t;
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_PARAMETERS_H
