// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the pipeline asks of a solver beyond the GeodesicSolver concept: is it
// exact? Read from the model, so that a user's wrapper of an exact solver keeps
// the exact treatment.
#ifndef GEODESIC_RIDGE_SOLVERS_SOLVER_TRAITS_H
#define GEODESIC_RIDGE_SOLVERS_SOLVER_TRAITS_H

#include <type_traits>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeSolvers
/// The properties of a model of `GeodesicSolver` that the pipeline uses.
/// `is_exact` is `Solver::is_exact` where the model declares it (as
/// `static constexpr bool`), else `false`. An exact model's distances are
/// trusted to round-off (E grows by an exact test, the kink split runs) and
/// it must offer the cone query of `Exact_solver` (the cone field and the
/// kink split use it): a wrapper of `Exact_solver` declares `is_exact` and
/// forwards that call.
template <class Solver, class = void>
struct Geodesic_solver_traits
{
  /// whether the model gives exact polyhedral distances and cones
  static constexpr bool is_exact = false;
};

#ifndef DOXYGEN_RUNNING
template <class Solver>
struct Geodesic_solver_traits<Solver, std::void_t<decltype(Solver::is_exact)> >
{
  static constexpr bool is_exact = Solver::is_exact;
};
#endif

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_SOLVERS_SOLVER_TRAITS_H
