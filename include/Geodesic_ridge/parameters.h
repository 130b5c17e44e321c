// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
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
/// Tag of the curvature that draws the cut graph's leaves on (degrees).
struct leaf_curvature_t {};
/// Tag of the curvature a kept branch of the cut graph must enclose (degrees).
struct branch_curvature_t {};
/// Tag of the repair of a mesh read from a file (`IO::read_triangle_mesh()`).
struct repair_t {};
} // namespace internal_np

/// \ingroup PkgGeodesicRidgeNamedParameters
/// Default significance tolerance, as recommended by the paper (§4.4).
constexpr double default_tolerance = 0.025;

/// \ingroup PkgGeodesicRidgeNamedParameters
/// Default curvature that draws a leaf of K on (degrees; see
/// `parameters::leaf_curvature`). It improves the recall of the ridge's tips
/// at the same precision, and reached more corners of the convex test
/// polyhedra than 30 (measured in the user manual,
/// \ref GeodesicRidgeSecAccuracyStage1).
constexpr double default_leaf_curvature = 45;

/// \ingroup PkgGeodesicRidgeNamedParameters
/// Default curvature a kept branch of the dual tree must enclose (degrees;
/// see `parameters::branch_curvature`).
constexpr double default_branch_curvature = 15;

namespace parameters {

// Defines the two overloads of the named parameter `name` (value type `T`, tag
// `internal_np::name##_t`): `name(value)`, and `name(value, np)`, which adds it
// to the named parameters `np` (CGAL's list is closed to other packages).
#define GEODESIC_RIDGE_NAMED_PARAMETER(T, name)                                                         \
  inline CGAL::Named_function_parameters<T, internal_np::name##_t> name(T value)                      \
  {                                                                                                   \
    return CGAL::Named_function_parameters<T, internal_np::name##_t>(value);                          \
  }                                                                                                   \
  template <class NamedParameters>                                                                    \
  CGAL::Named_function_parameters<T, internal_np::name##_t, NamedParameters> name(T value,            \
                                                                                  const NamedParameters& np) \
  {                                                                                                   \
    return CGAL::Named_function_parameters<T, internal_np::name##_t, NamedParameters>(value, np);     \
  }

/// \ingroup PkgGeodesicRidgeNamedParameters
/// Dual edges of the cut locus whose significance is below `t` times the
/// total area are pruned. `t` must be in [0, 0.5).
GEODESIC_RIDGE_NAMED_PARAMETER(double, tolerance)

/// \ingroup PkgGeodesicRidgeNamedParameters
/// Every pruned branch of the dual tree that hangs from the kept structure
/// (or from a branch kept this way) and holds at least `degrees` of Gaussian
/// curvature (2π minus the angle sum, shared among a vertex's faces by angle)
/// is kept too (default `default_leaf_curvature`; 0 turns it off). A leaf of the cut locus of a polyhedral
/// surface is a vertex of positive curvature: this brings K, and so the ridge,
/// to the corners and tips that the tolerance cut off.
GEODESIC_RIDGE_NAMED_PARAMETER(double, leaf_curvature)

/// \ingroup PkgGeodesicRidgeNamedParameters
/// A branch of the dual tree kept by the tolerance is pruned back, from its
/// tip, while the faces beyond its dual edge enclose less than `degrees` of
/// Gaussian curvature (default `default_branch_curvature`; 0 turns it off).
/// Why: those faces are the region between the two shortest paths that reach
/// the ends of the edge; by Gauss-Bonnet they enclose at least the angle
/// between the two paths where they meet, the jump of the arrival direction.
/// A branch enclosing (nearly) no curvature separates two parts of one front:
/// a false branch, which leaves creases where the solver's copies on its two
/// sides meet. On genus 0 the smaller curvature of the two sides counts.
GEODESIC_RIDGE_NAMED_PARAMETER(double, branch_curvature)

/// \ingroup PkgGeodesicRidgeNamedParameters
/// `IO::read_triangle_mesh()` repairs the mesh with `repair_mesh()` (merges
/// vertices at one position, removes faces with fewer than three distinct
/// vertices, duplicate faces, degenerate faces and isolated vertices, splits
/// non-manifold edges and vertices, orients consistently) instead of refusing
/// what the repair fixes (default `false`; polygons are triangulated either
/// way). The returned `File_index_map` says what changed and maps the repaired
/// mesh back to the file's indices.
GEODESIC_RIDGE_NAMED_PARAMETER(bool, repair)

} // namespace parameters

namespace internal {

/// Reads the number parameter `Tag` from `np` (default `default_value`) and
/// checks that it is in [lo, hi] (or [lo, hi) if `open_above`; NaN never is):
/// `Invalid_parameter_error` names the parameter and the range otherwise.
template <class Tag, class NamedParameters>
double get_number_in_range(const NamedParameters& np, double default_value, double lo, double hi,
                           bool open_above, const std::string& what, const std::string& range)
{
  const double x = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, Tag()), default_value);
  if(!(x >= lo && (open_above ? x < hi : x <= hi)))
    throw Invalid_parameter_error(what + " " + std::to_string(x) + " is out of range: it must be in " + range);
  return x;
}

/// Reads the leaf curvature (degrees) from `np` and checks it.
template <class NamedParameters>
double get_leaf_curvature(const NamedParameters& np)
{
  return get_number_in_range<internal_np::leaf_curvature_t>(np, default_leaf_curvature, 0, 720, false,
                                                            "leaf curvature (degrees)", "[0, 720]");
}

/// Reads the branch curvature (degrees) from `np` and checks it.
template <class NamedParameters>
double get_branch_curvature(const NamedParameters& np)
{
  return get_number_in_range<internal_np::branch_curvature_t>(np, default_branch_curvature, 0, 720, false,
                                                              "branch curvature (degrees)", "[0, 720]");
}

/// Reads the tolerance from `np` (default: `default_tolerance`) and checks it.
template <class NamedParameters>
double get_tolerance(const NamedParameters& np)
{
  return get_number_in_range<internal_np::tolerance_t>(np, default_tolerance, 0, 0.5, true, "tolerance",
                                                       "[0, 0.5)");
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_PARAMETERS_H
