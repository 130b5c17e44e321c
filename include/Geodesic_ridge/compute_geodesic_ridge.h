// Copyright (c) 2026 Geodesic_ridge developers.
//
// The whole pipeline: rough cut locus -> extended surface -> geodesic solve ->
// exact lower envelope per face -> ridge curve. A free function for one-shot
// use and a result class (`Ridge_curve`) that keeps everything it computed.
#ifndef GEODESIC_RIDGE_COMPUTE_GEODESIC_RIDGE_H
#define GEODESIC_RIDGE_COMPUTE_GEODESIC_RIDGE_H

#include <Geodesic_ridge/extended_surface.h>
#include <Geodesic_ridge/lower_envelope.h>
#include <Geodesic_ridge/parameters.h>
#include <Geodesic_ridge/ridge_curve.h>
#include <Geodesic_ridge/rough_cut_locus.h>
#include <Geodesic_ridge/solvers/Exact_solver.h>
#include <Geodesic_ridge/solvers/Fast_marching_solver.h>

#include <CGAL/Named_function_parameters.h>

#include <chrono>
#include <string>
#include <vector>

namespace Geodesic_ridge {

namespace internal_np {
struct solver_t {};
struct initial_rings_t {};
struct extension_step_t {};
struct maximum_rings_t {};
struct minimum_spur_angle_t {};
struct maximum_solves_t {};
struct guided_extension_t {};
struct tree_from_solver_t {};
struct predicted_extension_t {};
} // namespace internal_np

namespace parameters {
/// \ingroup PkgGeodesicRidgeNamedParameters
/// The geodesic solver run on the extended surface, a model of `GeodesicSolver`
/// (default `Exact_solver`).
template <class Solver>
CGAL::Named_function_parameters<Solver, internal_np::solver_t> solver(const Solver& s)
{
  return CGAL::Named_function_parameters<Solver, internal_np::solver_t>(s);
}
template <class Solver, class NamedParameters>
CGAL::Named_function_parameters<Solver, internal_np::solver_t, NamedParameters>
solver(const Solver& s, const NamedParameters& np)
{
  return CGAL::Named_function_parameters<Solver, internal_np::solver_t, NamedParameters>(s, np);
}
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Extension rings grown everywhere before the first pass (default 3).
GEODESIC_RIDGE_NAMED_PARAMETER(int, initial_rings)
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Rings grown, after a pass, around the outermost copies that still win area
/// of their face, before the next pass (default 4).
GEODESIC_RIDGE_NAMED_PARAMETER(int, extension_step)
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Hard cap on extension rings (default 7, so at most two solves with the
/// default initial rings and step): rings beyond the initial ones grow only
/// where copies of the outermost ring still win area of their face.
GEODESIC_RIDGE_NAMED_PARAMETER(int, maximum_rings)
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Passes on the extended surface at most (default 2): after a pass, E grows
/// again only where copies on its border still win area. With predicted
/// extension the passes are fast marching and the solver runs once more, on
/// the final E.
GEODESIC_RIDGE_NAMED_PARAMETER(int, maximum_solves)
/// \ingroup PkgGeodesicRidgeNamedParameters
/// With `true`, E also grows wherever a front continued across the cut is
/// predicted (by unfolding, against the distance on M) to be still exact at a
/// vertex whose shortest path crosses the cut: the whole shadow of a false
/// branch of K, up to `maximum_rings`.
GEODESIC_RIDGE_NAMED_PARAMETER(bool, guided_extension)
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Which distances on M shape the shortest-path tree of stage 1: with `false`
/// (default) fast marching (`Fast_marching_solver`, a fraction of one exact
/// solve), with `true` the chosen solver (one more solve). Guided extension
/// needs the solver's distances and implies `true`.
GEODESIC_RIDGE_NAMED_PARAMETER(bool, tree_from_solver)
/// \ingroup PkgGeodesicRidgeNamedParameters
/// With `true` (default), the dynamic extension decides where to grow from
/// fast-marching passes on E, and the solver runs once, on the final E; with
/// `false`, every extension step is decided by a solve of the solver.
/// `maximum_solves` bounds the passes of either kind. Guided extension implies
/// `false` (it compares with the solver's distances on M).
GEODESIC_RIDGE_NAMED_PARAMETER(bool, predicted_extension)
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Free ends of the ridge whose gradient jump is below this angle (degrees,
/// default 15) are pruned, repeatedly; 0 keeps every branch.
GEODESIC_RIDGE_NAMED_PARAMETER(double, minimum_spur_angle)
} // namespace parameters

/// \ingroup PkgGeodesicRidgeRef
/// Counts and timings of the whole pipeline (seconds).
struct Geodesic_ridge_statistics
{
  std::string solver;
  double tolerance = 0;
  int solves = 0;                 ///< solves of the solver on the extended surface
  int predicted_passes = 0;       ///< fast-marching passes on E that decided the extension steps
  std::size_t outer_copies_winning = 0; ///< at the last solve: copies on E's border still winning area
  Rough_cut_locus_statistics rough_cut_locus;
  Extended_surface_statistics extended_surface;
  Ridge_curve_statistics ridge;
  bool tree_from_solver = false; ///< the tree followed the solver's distances on M (else fast marching)
  double time_solve_on_mesh = 0; ///< the distances on M that shape the tree of stage 1
  double time_rough_cut_locus = 0, time_extension = 0, time_solve = 0, time_envelope = 0,
         time_assembly = 0, time_total = 0;
};

/// \ingroup PkgGeodesicRidgeRef
/// Everything the pipeline computed for one source: the ridge polylines (each
/// point with its surface location), per original face the cells of the
/// region-wise linear distance field, the rough cut locus and the statistics.
template <class TriangleMesh, class Point_3>
struct Ridge_curve
{
  /// polylines between junctions and free ends (a closed one repeats its first point)
  std::vector<std::vector<Ridge_point<Point_3> > > polylines;
  /// per face of M (by face index): the cells of the lower envelope with their linear fields
  std::vector<std::vector<Ridge_region_cell> > regions;
  Rough_cut_locus<TriangleMesh> rough_cut_locus;
  Geodesic_ridge_statistics statistics;
};

namespace internal {

template <class TriangleMesh, class NamedParameters>
auto ridge_curve_impl(const TriangleMesh& tm, Geodesic_source<TriangleMesh> src, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto t_start = std::chrono::steady_clock::now();
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto eim = CGAL::get_initialized_edge_index_map(tm, np);
  typedef typename boost::property_traits<std::decay_t<decltype(vpm)> >::value_type Point;
  const auto solver = choose_parameter(get_parameter(np, internal_np::solver_t()), Exact_solver());
  const int initial_rings = choose_parameter(get_parameter(np, internal_np::initial_rings_t()), 3);
  const double minimum_angle = choose_parameter(get_parameter(np, internal_np::minimum_spur_angle_t()), 15.0);
  const int extension_step = choose_parameter(get_parameter(np, internal_np::extension_step_t()), 4);
  const int maximum_rings = choose_parameter(get_parameter(np, internal_np::maximum_rings_t()), 7);
  const int maximum_solves = choose_parameter(get_parameter(np, internal_np::maximum_solves_t()), 2);
  const bool guided = choose_parameter(get_parameter(np, internal_np::guided_extension_t()), false);
  const bool tree_from_solver =
      guided || choose_parameter(get_parameter(np, internal_np::tree_from_solver_t()), false);
  if(initial_rings < 0 || maximum_rings < initial_rings || extension_step < 1)
    throw Invalid_parameter_error(
        "extension rings: need 0 <= initial_rings <= maximum_rings and extension_step >= 1");
  if(maximum_solves < 1) throw Invalid_parameter_error("maximum_solves must be at least 1");
  const bool predicted =
      !guided && choose_parameter(get_parameter(np, internal_np::predicted_extension_t()), true);

  Ridge_curve<TriangleMesh, Point> result;
  Geodesic_ridge_statistics& st = result.statistics;
  st.solver = solver.name();

  // Stage 1, on the tree that descends a geodesic distance on M (see
  // rough_cut_locus_impl): fast marching, or the solver itself
  auto t0 = std::chrono::steady_clock::now();
  std::vector<double> field(num_vertices(tm));
  st.tree_from_solver = tree_from_solver;
  if(tree_from_solver)
  {
    auto field_map = boost::make_iterator_property_map(field.begin(), vim);
    if(src.kind == Geodesic_source<TriangleMesh>::ON_VERTEX) solver(tm, src.vertex, field_map);
    else solver(tm, src.location, field_map);
  }
  else
    fast_marching_distances(tm, vpm, vim, src.seeds, field);
  st.time_solve_on_mesh = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  result.rough_cut_locus = rough_cut_locus_impl(tm, src, np, &field);
  const Rough_cut_locus<TriangleMesh>& rcl = result.rough_cut_locus;
  st.tolerance = rcl.tolerance;
  st.rough_cut_locus = rcl.statistics;
  st.time_rough_cut_locus = seconds_since(t0);

  const std::size_t nf = num_faces(tm);
  double mean_edge = 0;
  for(auto e : edges(tm)) mean_edge += distance_between(vpm, source(e, tm), target(e, tm));
  mean_edge /= static_cast<double>(num_edges(tm));
  // a predicted or solved distance within this of the exact one counts as exact
  const double exact_slack = 0.05 * mean_edge;

  // Stage 2: extend (rings everywhere, then, with guided growth, wherever a
  // front is still exact beyond the cut), solve; extend again only where
  // copies on the border of E still win, and solve again.
  t0 = std::chrono::steady_clock::now();
  Extended_surface_builder<TriangleMesh, std::decay_t<decltype(vpm)>, std::decay_t<decltype(vim)>,
                           std::decay_t<decltype(fim)>, std::decay_t<decltype(eim)> >
      builder(tm, rcl, vpm, vim, fim, eim);
  if(guided) builder.set_exact_distance(&field, exact_slack, rcl);
  for(int r = 0; r < initial_rings; ++r) builder.grow_ring();
  if(guided) builder.grow_guided(maximum_rings);
  st.time_extension += seconds_since(t0);

  Extended_surface<Point> E;
  std::vector<Face_copies> face_copies;
  // With predicted extension, fast-marching passes decide where E grows, and
  // the solver runs once, on the final E (the extension only needs to know
  // which border copies still win; fast marching's first-order error is
  // nearly the same for neighbouring fronts).
  bool final_pass = !predicted, grown = true;
  auto passes = [&] { return st.solves + st.predicted_passes; };
  for(;;)
  {
    t0 = std::chrono::steady_clock::now();
    if(grown) builder.materialize(E, src, vim, fim);
    grown = false;
    st.time_extension += seconds_since(t0);

    t0 = std::chrono::steady_clock::now();
    std::vector<double> distance(E.mesh.number_of_vertices());
    auto solve_on_E = [&](const auto& geodesic_solver) {
      if(E.source_is_vertex) geodesic_solver(E.mesh, E.source_vertex, CGAL::make_property_map(distance));
      else geodesic_solver(E.mesh, E.source_location, CGAL::make_property_map(distance));
    };
    if(final_pass) { solve_on_E(solver); ++st.solves; }
    else { solve_on_E(Fast_marching_solver()); ++st.predicted_passes; }
    st.time_solve += seconds_since(t0);
    if(E.source_is_vertex && distance[E.source_vertex] != 0)
      throw Algorithm_error("the solver's distance at the source is not 0");

    // the copies of every face, undominated ones only (a copy whose three corner
    // distances are all >= another's never wins)
    t0 = std::chrono::steady_clock::now();
    face_copies.assign(nf, {});
    for(auto c : E.mesh.faces())
    {
      const auto h = E.mesh.halfedge(c);
      const std::array<double, 3> d = {{distance[E.mesh.source(h)], distance[E.mesh.target(h)],
                                        distance[E.mesh.target(E.mesh.next(h))]}};
      Face_copies& fc = face_copies[E.original_face[c]];
      bool dominated = false;
      for(std::size_t i = 0; i < fc.fields.size() && !dominated; ++i)
        dominated = fc.fields[i][0] <= d[0] && fc.fields[i][1] <= d[1] && fc.fields[i][2] <= d[2];
      if(dominated) continue;
      std::size_t kept = 0;
      for(std::size_t i = 0; i < fc.fields.size(); ++i)
        if(!(d[0] <= fc.fields[i][0] && d[1] <= fc.fields[i][1] && d[2] <= fc.fields[i][2]))
        {
          fc.fields[kept] = fc.fields[i];
          fc.copies[kept] = fc.copies[i];
          ++kept;
        }
      fc.fields.resize(kept);
      fc.copies.resize(kept);
      fc.fields.push_back(d);
      fc.copies.push_back(c);
    }
    // copies on the border of E that win more than 1% of their face and are
    // exact at a border vertex off the cut: their front goes on beyond E
    auto unfinished = [&](std::size_t c) {
      typedef typename Extended_surface<Point>::Mesh::Face_index EF;
      const auto& m = E.mesh;
      const auto h0 = m.halfedge(EF(static_cast<typename Extended_surface<Point>::Mesh::size_type>(c)));
      auto h = h0;
      do
      {
        if(m.is_border(m.opposite(h)))
          for(auto v : {m.source(h), m.target(h)})
          {
            const std::size_t o = E.original_vertex[v];
            if(!builder.on_cut(o) && distance[v] <= field[o] + exact_slack) return true;
          }
        h = m.next(h);
      } while(h != h0);
      return false;
    };
    // Without guided growth: the copies of the outermost ring that win (the
    // rings grow uniformly, so that ring is E's border).
    const int outer = builder.statistics().rings;
    auto frontier = [&](std::size_t c) {
      return guided ? (E.ring[c] > 0 && unfinished(c)) : (outer > 0 && E.ring[c] == outer);
    };
    std::vector<char> grow_from(E.mesh.number_of_faces(), 0);
    std::size_t winning = 0;
    for(std::size_t f = 0; f < nf; ++f)
    {
      const Face_copies& fc = face_copies[f];
      bool candidate = false;
      for(std::size_t c : fc.copies) candidate |= frontier(c);
      if(!candidate) continue;
      const Lower_envelope<double> env = compute_lower_envelope<double>(fc.fields);
      for(const auto& cell : env.cells)
        if(frontier(fc.copies[cell.copy]) && barycentric_area(cell.polygon) > 0.01 * 0.5)
        {
          grow_from[fc.copies[cell.copy]] = 1;
          ++winning;
        }
    }
    st.outer_copies_winning = winning;
    st.time_envelope += seconds_since(t0);
    if(predicted && final_pass) break;
    if(winning == 0 || passes() >= maximum_solves || builder.statistics().rings >= maximum_rings)
    {
      if(!predicted) break;
      final_pass = true; // E is final: the one solve of the solver
      continue;
    }
    // grow a band of `extension_step` rings around them (each ring from the
    // copies the previous one added), then wherever fronts are still exact
    t0 = std::chrono::steady_clock::now();
    for(int step = 0; step < extension_step && builder.statistics().rings < maximum_rings; ++step)
    {
      const std::size_t before = builder.number_of_copies();
      builder.grow_ring(&grow_from);
      grow_from.assign(builder.number_of_copies(), 0);
      for(std::size_t c = before; c < builder.number_of_copies(); ++c) grow_from[c] = 1;
    }
    if(guided) builder.grow_guided(maximum_rings);
    grown = true;
    // at a cap E is final: no pass to decide on further growth
    if(predicted && (passes() >= maximum_solves || builder.statistics().rings >= maximum_rings)) final_pass = true;
    st.time_extension += seconds_since(t0);
  }
  st.extended_surface = E.statistics;

  // Stage 2c + 3: exact envelopes and the ridge curve
  t0 = std::chrono::steady_clock::now();
  assemble_ridge_curve(tm, E, face_copies, mean_edge, minimum_angle, vpm, vim, fim, eim, result.polylines,
                       result.regions, st.ridge);
  st.time_assembly = seconds_since(t0);
  st.ridge.time = st.time_assembly;
  if(st.ridge.components != 1 || st.ridge.cycles != static_cast<std::size_t>(2 * rcl.statistics.genus))
    throw Algorithm_error("the ridge has " + std::to_string(st.ridge.components) + " components and " +
                          std::to_string(st.ridge.cycles) + " cycles; expected 1 and 2g = " +
                          std::to_string(2 * rcl.statistics.genus));
  st.time_total = seconds_since(t_start);
  return result;
}

} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
/// Computes the geodesic ridge of `source` (a vertex, or a `Face_location`
/// `std::pair<face_descriptor, std::array<FT,3>>`) on the closed triangle mesh
/// `tm`, and keeps everything computed on the way.
///
/// \param np named parameters: `Geodesic_ridge::parameters::tolerance(t)`,
///   `solver(s)` (a `GeodesicSolver`, default `Exact_solver`), `initial_rings(k)`
///   (default 3), `extension_step(k)` (default 4), `maximum_rings(k)` (default 7),
///   `maximum_solves(k)` (default 2), `predicted_extension(b)` (default true),
///   `tree_from_solver(b)` (default false), `minimum_spur_angle(deg)` (default 15),
///   the experimental `guided_extension(b)` and `leaf_extension(f)`, then CGAL's `vertex_point_map`,
///   `vertex_index_map`, `face_index_map`, `edge_index_map`.
/// \post the ridge is connected, a tree on a genus-0 surface, with exactly 2g
///   independent cycles on genus g (`Algorithm_error` otherwise).
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto compute_ridge_curve(const TriangleMesh& tm,
                         typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::get_tolerance(np);
  validate_triangle_mesh(tm, np);
  return internal::ridge_curve_impl(tm, make_source(tm, source, np), np);
}

template <class TriangleMesh, class FT, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto compute_ridge_curve(const TriangleMesh& tm,
                         const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                         std::array<FT, 3> >& source,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::get_tolerance(np);
  validate_triangle_mesh(tm, np);
  return internal::ridge_curve_impl(tm, make_source(tm, source, np), np);
}

/// \ingroup PkgGeodesicRidgeRef
/// One-shot version: writes the ridge polylines (`std::vector<Point_3>`) to `out`.
template <class TriangleMesh, class Source, class OutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator compute_geodesic_ridge(const TriangleMesh& tm, const Source& source, OutputIterator out,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto rc = compute_ridge_curve(tm, source, np);
  typedef typename std::decay_t<decltype(rc.polylines[0][0].point)> Point;
  for(const auto& pl : rc.polylines)
  {
    std::vector<Point> points;
    for(const auto& p : pl) points.push_back(p.point);
    *out++ = points;
  }
  return out;
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_COMPUTE_GEODESIC_RIDGE_H
