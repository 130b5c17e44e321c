// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of the package, all of them, with their defaults. CGAL's
// list of named parameters is closed to outside packages, so our own knobs
// are tag types of our own, and `Named_parameters` (CGAL's type with our
// parameters as members) lets them chain as CGAL's do; CGAL's members
// (vertex_point_map, face_index_map, ...) chain after them:
//   Geodesic_ridge::parameters::solver(s).tolerance(0.01).vertex_point_map(vpm)
// Each also takes the parameters to extend as a last argument:
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
struct solver_t {};
struct initial_rings_t {};
struct extension_step_t {};
struct maximum_rings_t {};
struct minimum_spur_angle_t {};
struct kink_angle_t {};
struct corner_fallback_t {};
struct maximum_solves_t {};
struct tree_from_solver_t {};
struct predicted_extension_t {};
struct fast_marching_margin_t {};
struct field_t {};
struct cone_ridge_tolerance_t {};
struct cone_ridge_t {};
struct vertex_distance_map_t {};
struct disabled_ridge_passes_t {};
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

/// \ingroup PkgGeodesicRidgeRef
/// The distance field inside a face copy: the linear interpolation of its
/// corner distances (the paper's), or the cone of the exact solver's window at
/// the sample point of the copy nearest to the query (`Face_cone`; exact
/// solver only). See the user manual, \ref GeodesicRidgeSecCone.
enum class Field { linear, cone };
/// \var Field::linear
/// the linear interpolation of the corner distances of every copy
/// \var Field::cone
/// the exact solver's cones of every copy


/// \ingroup PkgGeodesicRidgeNamedParameters
/// Default of `parameters::cone_ridge_tolerance` (mean edge lengths): a
/// thousandth of an edge, far below the ridge's own uncertainty where the
/// cones are not exact (faces that several windows share), and reached with
/// few points (the curve bends little inside one face).
constexpr double default_cone_ridge_tolerance = 1e-3;

/// \ingroup PkgGeodesicRidgeNamedParameters
/// Default of `parameters::initial_rings`: three rings everywhere before the
/// first pass; a fixed 3 to 4 rings gave most of the recall on 14 meshes, and
/// the growth rule adds the rest where copies still win.
constexpr int default_initial_rings = 3;
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Default of `parameters::extension_step`: four rings per pass around the
/// copies still winning (or half the depth reached, if more), so that a growth
/// that has far to go needs O(log) passes.
constexpr int default_extension_step = 4;
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Default of `parameters::minimum_spur_angle` (degrees): free ends whose
/// fronts meet at less are the noise of the solver and of the linear field,
/// not a ridge (the reference ridge marks jumps of 10 degrees and more).
constexpr double default_minimum_spur_angle = 15;
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Default of `parameters::maximum_rings`: a safety cap far above the depth
/// the growth rule was measured to reach (15 to 19 rings on the hardest
/// sources of knot_3k), so that it never decides the result.
constexpr int default_maximum_rings = 256;
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Default of `parameters::maximum_solves`: a bound on the solves on E, each
/// about one exact solve on E (O(F^1.9) with the exact solver); the
/// predicted and anchored passes decide the growth between them.
constexpr int default_maximum_solves = 3;
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Default of `parameters::fast_marching_margin`: two rings around the final E
/// with the fast-marching solver, so that every vertex of a copy that wins, and
/// every vertex its value is updated from, has its whole one-ring as on M
/// (user manual, \ref GeodesicRidgeSecGrowth). On the 168 pairs of
/// `bench_ridge_accuracy`, fast marching on E then agrees with fast marching on
/// an E grown from 10 and from 20 rings everywhere.
constexpr int default_fast_marching_margin = 2;
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Default of `parameters::kink_angle` (degrees): the accuracy benchmark's
/// threshold of a major ridge (\ref GeodesicRidgeSecAccuracyMethod).
constexpr double default_kink_angle = 60;

/// \ingroup PkgGeodesicRidgeNamedParameters
/// The named parameters of the package's functions: CGAL's
/// `Named_function_parameters` (so that every CGAL function reads them, and
/// CGAL's own parameters such as `vertex_point_map` chain after them), with
/// the package's parameters as members, so that they chain as CGAL's do:
/// \code
/// Geodesic_ridge::parameters::solver(s).tolerance(0.01).vertex_point_map(vpm)
/// \endcode
/// CGAL's members return CGAL's type, so the package's parameters come first.
template <class T, class Tag, class Base = CGAL::internal_np::No_property>
struct Named_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// \cond SKIP_IN_MANUAL
  typedef CGAL::Named_function_parameters<T, Tag, Base> CGAL_parameters;
  typedef Named_parameters<T, Tag, Base> Self;
  using CGAL_parameters::CGAL_parameters;

#define GEODESIC_RIDGE_CHAINED_PARAMETER(Type, name)                                                    \
  Named_parameters<Type, internal_np::name##_t, Self> name(Type value) const                          \
  {                                                                                                   \
    return Named_parameters<Type, internal_np::name##_t, Self>(value, *this);                         \
  }
  GEODESIC_RIDGE_CHAINED_PARAMETER(double, tolerance)
  GEODESIC_RIDGE_CHAINED_PARAMETER(double, leaf_curvature)
  GEODESIC_RIDGE_CHAINED_PARAMETER(double, branch_curvature)
  GEODESIC_RIDGE_CHAINED_PARAMETER(bool, repair)
  GEODESIC_RIDGE_CHAINED_PARAMETER(int, initial_rings)
  GEODESIC_RIDGE_CHAINED_PARAMETER(int, extension_step)
  GEODESIC_RIDGE_CHAINED_PARAMETER(int, maximum_rings)
  GEODESIC_RIDGE_CHAINED_PARAMETER(int, maximum_solves)
  GEODESIC_RIDGE_CHAINED_PARAMETER(bool, tree_from_solver)
  GEODESIC_RIDGE_CHAINED_PARAMETER(bool, predicted_extension)
  GEODESIC_RIDGE_CHAINED_PARAMETER(int, fast_marching_margin)
  GEODESIC_RIDGE_CHAINED_PARAMETER(double, minimum_spur_angle)
  GEODESIC_RIDGE_CHAINED_PARAMETER(double, kink_angle)
  GEODESIC_RIDGE_CHAINED_PARAMETER(bool, corner_fallback)
  GEODESIC_RIDGE_CHAINED_PARAMETER(Field, field)
  GEODESIC_RIDGE_CHAINED_PARAMETER(bool, cone_ridge)
  GEODESIC_RIDGE_CHAINED_PARAMETER(double, cone_ridge_tolerance)
  GEODESIC_RIDGE_CHAINED_PARAMETER(unsigned, disabled_ridge_passes)
#undef GEODESIC_RIDGE_CHAINED_PARAMETER

  template <class Solver>
  Named_parameters<Solver, internal_np::solver_t, Self> solver(const Solver& s) const
  {
    return Named_parameters<Solver, internal_np::solver_t, Self>(s, *this);
  }
  template <class PropertyMap>
  Named_parameters<PropertyMap, internal_np::vertex_distance_map_t, Self> vertex_distance_map(PropertyMap m) const
  {
    return Named_parameters<PropertyMap, internal_np::vertex_distance_map_t, Self>(m, *this);
  }
  /// \endcond
};

namespace parameters {

// Defines the two overloads of the named parameter `name` (value type `T`, tag
// `internal_np::name##_t`): `name(value)`, and `name(value, np)`, which adds it
// to the named parameters `np`. Both return `Named_parameters`, on which the
// next parameter chains.
#define GEODESIC_RIDGE_NAMED_PARAMETER(T, name)                                                         \
  inline Named_parameters<T, internal_np::name##_t> name(T value)                                      \
  {                                                                                                   \
    return Named_parameters<T, internal_np::name##_t>(value);                                         \
  }                                                                                                   \
  template <class NamedParameters>                                                                    \
  Named_parameters<T, internal_np::name##_t, NamedParameters> name(T value, const NamedParameters& np) \
  {                                                                                                   \
    return Named_parameters<T, internal_np::name##_t, NamedParameters>(value, np);                    \
  }                                                                                                   \
  static_assert(true, "a use ends with ';', as a declaration does")

/// \ingroup PkgGeodesicRidgeNamedParameters
/// Dual edges of the cut locus whose significance is below `t` times the
/// total area are pruned. `t` must be in [0, 0.5).
GEODESIC_RIDGE_NAMED_PARAMETER(double, tolerance);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Every pruned branch of the dual tree that hangs from the kept structure
/// (or from a branch kept this way) and holds at least `degrees` of Gaussian
/// curvature (2π minus the angle sum, shared among a vertex's faces by angle)
/// is kept too (default `default_leaf_curvature`; 0 turns it off). A leaf of the cut locus of a polyhedral
/// surface is a vertex of positive curvature: this brings K, and so the ridge,
/// to the corners and tips that the tolerance cut off.
GEODESIC_RIDGE_NAMED_PARAMETER(double, leaf_curvature);
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
GEODESIC_RIDGE_NAMED_PARAMETER(double, branch_curvature);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// `IO::read_triangle_mesh()` repairs the mesh with `repair_mesh()` (merges
/// vertices at one position, removes faces with fewer than three distinct
/// vertices, duplicate faces, degenerate faces and isolated vertices, splits
/// non-manifold edges and vertices, orients consistently) instead of refusing
/// what the repair fixes (default `false`; polygons are triangulated either
/// way). The returned `File_index_map` says what changed and maps the repaired
/// mesh back to the file's indices.
GEODESIC_RIDGE_NAMED_PARAMETER(bool, repair);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// The geodesic solver run on the extended surface, a model of `GeodesicSolver`
/// (default `Exact_solver`).
template <class Solver>
Named_parameters<Solver, internal_np::solver_t> solver(const Solver& s)
{
  return Named_parameters<Solver, internal_np::solver_t>(s);
}
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Same, added to the named parameters `np`.
template <class Solver, class NamedParameters>
Named_parameters<Solver, internal_np::solver_t, NamedParameters> solver(const Solver& s, const NamedParameters& np)
{
  return Named_parameters<Solver, internal_np::solver_t, NamedParameters>(s, np);
}
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Extension rings grown everywhere before the first pass (default 3).
GEODESIC_RIDGE_NAMED_PARAMETER(int, initial_rings);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Rings grown, after a pass, around the copies that still win on a border
/// edge of E, before the next pass: at least this many (default 4), and half
/// the depth reached when that is more.
GEODESIC_RIDGE_NAMED_PARAMETER(int, extension_step);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// A safety cap on extension rings (default 256): rings beyond the initial ones
/// grow only around copies that still win on a border edge of E, and the growth
/// stops by itself when none does (`statistics.ring_cap_hit` says when the cap
/// stopped it instead).
GEODESIC_RIDGE_NAMED_PARAMETER(int, maximum_rings);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Solves of the solver on E at most (default 3). With predicted extension,
/// fast-marching passes decide the growth and the solver runs on the final E;
/// if copies of its solution still win on E's border, E grows and the solver
/// runs again. Without, every pass is a solve of the solver.
GEODESIC_RIDGE_NAMED_PARAMETER(int, maximum_solves);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Which distances on M shape the shortest-path tree of stage 1: with `false`
/// (default) fast marching (`Fast_marching_solver`, a fraction of one exact
/// solve), with `true` the chosen solver (one more solve). Where fast marching
/// and the exact distance order two paths differently, the tree, and with it
/// the cut, takes the wrong side of a saddle; with the exact solver the solver's
/// tree cuts the worst recall measured (70 sources of 14 meshes) from 3.5 to 0.6
/// mean edges, at about 1.8 times the time.
GEODESIC_RIDGE_NAMED_PARAMETER(bool, tree_from_solver);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// With `true` (default), the dynamic extension decides where to grow from
/// fast-marching passes on E, and the solver runs once, on the final E; with
/// `false`, every extension step is decided by a solve of the solver.
/// `maximum_solves` bounds the passes of either kind.
GEODESIC_RIDGE_NAMED_PARAMETER(bool, predicted_extension);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// With the fast-marching solver, rings grown around the whole final E before
/// its last pass (default `default_fast_marching_margin`, 2; 0 for none).
/// Fast marching updates a vertex from its one-ring; on E's border that ring
/// is cut, and the values there and beyond carry more of its error than on M.
/// Other solvers ignore it.
GEODESIC_RIDGE_NAMED_PARAMETER(int, fast_marching_margin);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Free ends of the ridge whose gradient jump is below this angle (degrees,
/// default 15) are pruned, repeatedly; 0 keeps every branch.
GEODESIC_RIDGE_NAMED_PARAMETER(double, minimum_spur_angle);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Copies glued in E (one sheet) whose gradients jump by at least this angle
/// across a mesh edge (degrees, default 60) still meet at a ridge there: where
/// the cut graph lacks a branch, both fronts reach its faces inside one sheet.
/// With the exact solver, a copy whose corners are reached by fronts (cones of
/// the solver) that arrive this far apart is also split into one copy per
/// front, and the split goes on into the copies glued to it (counted in
/// `Ridge_curve_statistics::split_copies`; user manual, \ref GeodesicRidgeSecStage3).
/// 0 keeps the sheet-only definition (ridges between sheets only).
GEODESIC_RIDGE_NAMED_PARAMETER(double, kink_angle);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// With the exact solver's kink split (`kink_angle`), a copy alone in its face
/// whose corner no sample's front reaches exactly (the kink passes between the
/// corner and its sample) takes that corner's front from one more sample, at
/// barycentric 0.98 of the corner (`Exact_solver::corner_fallback_samples()`),
/// if that front meets the others at a ridge: no corner's front has a cone
/// below the copy's distance at another corner. Default `true`; ignored
/// with the cone field (its samples are next to the corners already) and
/// without cones. On the accuracy benchmark's 168 pairs (user manual,
/// \ref GeodesicRidgeSecCone) it finds the branches that pass between a corner
/// and its sample: recall p95 at tolerance 0.002 within 0.5 mean edge on all
/// of them (167 with `false`; bunny_7k from vertex 697 0.05 instead of 2.8),
/// precision p95 (where fronts meet at 30 degrees or more) within 0.25 mean
/// edge on 164 of them (167 with `false`), at 1.04 times the time.
GEODESIC_RIDGE_NAMED_PARAMETER(bool, corner_fallback);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// `Field::linear` (default) or `Field::cone`: with `cone`, the ridge curve
/// also keeps, per face, the cone of every copy (`Ridge_curve::cones`; the
/// exact solver reads them from its shortest paths), and the distance field
/// evaluates them instead of the linear fields.
GEODESIC_RIDGE_NAMED_PARAMETER(Field, field);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// The ridge reported (`Ridge_curve::ridge_polylines()`, the output of
/// `compute_geodesic_ridge()`) is the cone ridge (`Ridge_curve::cone_polylines`):
/// the ridge of the linear field moved onto the curve where the exact
/// solver's cones meet, with the cones read only on the faces near kinks
/// inside one sheet (`Exact_solver::cone_ridge_samples()`; with
/// `kink_angle(0)` on every copy; with `corner_fallback`, also at
/// `Exact_solver::cone_ridge_fallback_samples()`), and where a copy is split
/// at a kink, on the curve where its fronts' cones meet. Default `true` with a
/// solver that offers cones (`Exact_solver`), and always with
/// `field(Field::cone)`; `false` reports the linear field's ridge
/// (`Ridge_curve::polylines`). The kink split sees the cone ridge's samples
/// too, so the linear field's ridge of a default run may differ slightly
/// from that of `cone_ridge(false)`. On the
/// accuracy benchmark's 168 pairs (user manual, \ref GeodesicRidgeSecCone):
/// precision p95 within 0.25 mean edge on 164 of them instead of 156 with
/// the corner fallback (167 instead of 161 without), at 1.05 times the time
/// summed over its meshes (1.3 on 1k-face meshes).
GEODESIC_RIDGE_NAMED_PARAMETER(bool, cone_ridge);
/// \ingroup PkgGeodesicRidgeNamedParameters
/// The cone ridge (`Ridge_curve::cone_polylines`)
/// is split until the curve is within `t` mean edge lengths of the midpoint of
/// every chord (default `default_cone_ridge_tolerance`; `t` in (0, 1]).
GEODESIC_RIDGE_NAMED_PARAMETER(double, cone_ridge_tolerance);
/// \cond SKIP_IN_MANUAL
/// For measuring, not for use: stage 3's optional passes and spur rules to
/// switch off, a bit each (`internal::Ridge_pass`; `bench_ridge_accuracy
/// --without NAME`). Default 0: every pass runs.
GEODESIC_RIDGE_NAMED_PARAMETER(unsigned, disabled_ridge_passes);
/// \endcond

/// \ingroup PkgGeodesicRidgeNamedParameters
/// Named parameter of `refine_mesh_along_ridge()`: a writable vertex property
/// map of the output mesh that receives the distance at each vertex.
template <class PropertyMap>
Named_parameters<PropertyMap, internal_np::vertex_distance_map_t> vertex_distance_map(PropertyMap m)
{
  return Named_parameters<PropertyMap, internal_np::vertex_distance_map_t>(m);
}
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Same, added to the named parameters `np`.
template <class PropertyMap, class NamedParameters>
Named_parameters<PropertyMap, internal_np::vertex_distance_map_t, NamedParameters>
vertex_distance_map(PropertyMap m, const NamedParameters& np)
{
  return Named_parameters<PropertyMap, internal_np::vertex_distance_map_t, NamedParameters>(m, np);
}

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
