// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the pipeline asks of a solver beyond the GeodesicSolver concept: is it
// exact, does it offer cones? Read from the model, so that a user's wrapper of
// an exact solver keeps the exact treatment.
#ifndef GEODESIC_RIDGE_SOLVERS_SOLVER_TRAITS_H
#define GEODESIC_RIDGE_SOLVERS_SOLVER_TRAITS_H

#include <type_traits>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeSolvers
/// The properties of a model of `GeodesicSolver` that the pipeline uses.
/// `is_exact` is `Solver::is_exact` where the model declares it (as
/// `static constexpr bool`), else `false`: an exact model's distances are
/// trusted to round-off (its solves steer E's growth by the exact test).
/// `has_cones` is `Solver::has_cones` where declared, else `is_exact`: such a
/// model offers the cone query of `Exact_solver`, which the cone field and the
/// kink split use. `has_windows` is `Solver::has_windows` where declared, else
/// `false`: such a model also gives every face's windows
/// (`Window_propagation_solver`), and the cone field is their exact lower
/// envelope. A wrapper of `Exact_solver` declares `is_exact` and forwards
/// that call.
template <class Solver, class = void>
struct Geodesic_solver_traits
{
  /// whether the model gives exact polyhedral distances
  static constexpr bool is_exact = false;
  /// whether the model offers `Exact_solver`'s cone query
  static constexpr bool has_cones = false;
  /// whether the model gives the windows of the faces (`Window_propagation_solver`)
  static constexpr bool has_windows = false;
};

#ifndef DOXYGEN_RUNNING
namespace internal {
template <class Solver, class = void>
struct Declared_cones
{
  static constexpr bool value = Solver::is_exact;
};
template <class Solver>
struct Declared_cones<Solver, std::void_t<decltype(Solver::has_cones)> >
{
  static constexpr bool value = Solver::has_cones;
};
template <class Solver, class = void>
struct Declared_windows
{
  static constexpr bool value = false;
};
template <class Solver>
struct Declared_windows<Solver, std::void_t<decltype(Solver::has_windows)> >
{
  static constexpr bool value = Solver::has_windows;
};
} // namespace internal

template <class Solver>
struct Geodesic_solver_traits<Solver, std::void_t<decltype(Solver::is_exact)> >
{
  static constexpr bool is_exact = Solver::is_exact;
  static constexpr bool has_cones = internal::Declared_cones<Solver>::value;
  static constexpr bool has_windows = internal::Declared_windows<Solver>::value;
};
#endif

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_SOLVERS_SOLVER_TRAITS_H
