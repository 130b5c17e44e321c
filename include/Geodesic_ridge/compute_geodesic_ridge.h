// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The whole pipeline: rough cut locus -> extended surface -> geodesic solve ->
// exact lower envelope per face -> ridge curve. A free function for one-shot
// use and a result class (`Ridge_curve`) that keeps everything it computed.
#ifndef GEODESIC_RIDGE_COMPUTE_GEODESIC_RIDGE_H
#define GEODESIC_RIDGE_COMPUTE_GEODESIC_RIDGE_H

#include <Geodesic_ridge/cone_ridge.h>
#include <Geodesic_ridge/extended_surface.h>
#include <Geodesic_ridge/internal/extension_growth.h>
#include <Geodesic_ridge/internal/tuning.h>
#include <Geodesic_ridge/lower_envelope.h>
#include <Geodesic_ridge/parameters.h>
#include <Geodesic_ridge/ridge_curve.h>
#include <Geodesic_ridge/internal/ridge_curve/assemble_ridge_curve.h>
#include <Geodesic_ridge/rough_cut_locus.h>
#include <Geodesic_ridge/solvers/Exact_solver.h>
#include <Geodesic_ridge/solvers/Fast_marching_solver.h>
#include <Geodesic_ridge/solvers/solver_traits.h>
#include <Geodesic_ridge/timings.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace Geodesic_ridge {


/// \ingroup PkgGeodesicRidgeRef
/// Counts of the whole pipeline: what it did and what happened (the growth of
/// the extended surface and the solves: `Extension_growth_statistics`).
struct Geodesic_ridge_statistics : Extension_growth_statistics
{
  /// the solver's name (`GeodesicSolver::name()`)
  std::string solver;
  /// the tolerance of stage 1
  double tolerance = 0;
  /// stage 1
  Rough_cut_locus_statistics rough_cut_locus;
  /// the extended surface of the last solve
  Extended_surface_statistics extended_surface;
  /// stage 3
  Ridge_curve_statistics ridge;
  Cone_ridge_statistics cone_ridge; ///< with the cone ridge (`parameters::cone_ridge`)
  bool cone_ridge_traced = false; ///< the cone ridge was traced: `Ridge_curve::ridge_polylines()` is `cone_polylines`
  bool tree_from_solver = false; ///< the tree followed the solver's distances on M (else fast marching)
};

/// \ingroup PkgGeodesicRidgeRef
/// Everything the pipeline computed for one source: the ridge polylines (each
/// point with its surface location), per original face the cells of the
/// region-wise linear distance field, the rough cut locus and the statistics.
template <class TriangleMesh, class Point_3>
struct Ridge_curve
{
  /// polylines of points with their surface locations
  typedef std::vector<std::vector<Ridge_point<Point_3> > > Polylines;
  /// the ridge of the region-wise linear field: the boundaries of its cells
  /// where fronts meet (`regions`, the refined mesh), polylines between
  /// junctions and free ends (a closed one repeats its first point)
  Polylines polylines;
  /// per face of M (by face index): the cells of the lower envelope with their linear fields
  std::vector<std::vector<Ridge_region_cell> > regions;
  /// per vertex of M (by index): the smallest of the solver's distances over its
  /// copies in the extended surface, i.e. the geodesic distance on M when E holds
  /// every shortest path
  std::vector<double> vertex_distances;
  /// with `parameters::field(Field::cone)`, per face of M (by face index): the
  /// cones of its copies that no other copy dominates; empty otherwise
  std::vector<std::vector<Face_cone> > cones;
  /// with `parameters::cone_ridge` (the default with the exact solver): the
  /// ridge where the cones meet, traced from `polylines` (same topology, same
  /// ends but the junctions inside faces; every chord within
  /// `cone_ridge_tolerance` of the curve); empty otherwise
  Polylines cone_polylines;
  /// the result of stage 1 (the cut graph K, its tree and its statistics)
  Rough_cut_locus<TriangleMesh> rough_cut_locus;
  /// counts of every stage
  Geodesic_ridge_statistics statistics;
  /// seconds per step of the pipeline: `tree_distances`, `rough_cut_locus`,
  /// `extended_surface` (growing and materializing E), `solve`,
  /// `envelope_and_dominance` (the undominated copies and the copies still
  /// winning on E's border), `ridge_assembly` (envelopes and ridge, stages 2c
  /// and 3), `cone_ridge`; `rough_cut_locus.timings` splits stage 1
  Timings timings;

  /// the ridge reported: `cone_polylines` if the cone ridge was traced
  /// (`parameters::cone_ridge`), else `polylines`
  const Polylines& ridge_polylines() const { return statistics.cone_ridge_traced ? cone_polylines : polylines; }
};

namespace internal {

// The named parameters of the pipeline beyond those of stage 1, checked.
struct Pipeline_options
{
  int initial_rings, extension_step, maximum_rings, maximum_solves, fast_marching_margin;
  double minimum_angle, kink_angle, cone_ridge_tolerance;
  bool tree_from_solver, predicted, corner_fallback, cone_ridge;
  Field field;
  Ridge_passes ridge_passes; // (all on unless `disabled_ridge_passes` says otherwise)
};

template <class NamedParameters, class Solver>
Pipeline_options pipeline_options(const NamedParameters& np, const Solver& solver)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Pipeline_options o;
  o.initial_rings = choose_parameter(get_parameter(np, internal_np::initial_rings_t()), default_initial_rings);
  o.minimum_angle = choose_parameter(get_parameter(np, internal_np::minimum_spur_angle_t()), default_minimum_spur_angle);
  o.kink_angle = choose_parameter(get_parameter(np, internal_np::kink_angle_t()), default_kink_angle);
  o.extension_step = choose_parameter(get_parameter(np, internal_np::extension_step_t()), default_extension_step);
  o.maximum_rings = choose_parameter(get_parameter(np, internal_np::maximum_rings_t()), default_maximum_rings);
  o.maximum_solves = choose_parameter(get_parameter(np, internal_np::maximum_solves_t()), default_maximum_solves);
  o.field = choose_parameter(get_parameter(np, internal_np::field_t()), Field::linear);
  if(o.field == Field::cone && !Geodesic_solver_traits<std::decay_t<Solver> >::has_cones)
    throw Invalid_parameter_error(std::string("the cone field needs a solver with cones (exact, vtp), not '") + solver.name() + "'");
  o.cone_ridge_tolerance = get_number_in_range<internal_np::cone_ridge_tolerance_t>(
      np, default_cone_ridge_tolerance, std::numeric_limits<double>::min(), 1, false, "cone ridge tolerance", "(0, 1]");
  o.tree_from_solver = choose_parameter(get_parameter(np, internal_np::tree_from_solver_t()), false);
  o.ridge_passes.disabled = choose_parameter(get_parameter(np, internal_np::disabled_ridge_passes_t()), 0u);
  // the cone field's own samples are next to the corners already
  o.corner_fallback = choose_parameter(get_parameter(np, internal_np::corner_fallback_t()), true) &&
                      o.field != Field::cone;
  // the cone ridge: by default with a solver that offers cones
  const bool has_cones = Geodesic_solver_traits<std::decay_t<Solver> >::has_cones;
  o.cone_ridge = choose_parameter(get_parameter(np, internal_np::cone_ridge_t()),
                                  o.field == Field::cone || has_cones);
  if(o.field == Field::cone && !o.cone_ridge)
    throw Invalid_parameter_error("cone_ridge(false) with the cone field: the cone field's ridge is the cone ridge");
  if(o.cone_ridge && !has_cones)
    throw Invalid_parameter_error(std::string("the cone ridge needs a solver with cones (exact, vtp), not '") + solver.name() + "'");
  if(o.initial_rings < 0 || o.maximum_rings < o.initial_rings || o.extension_step < 1)
    throw Invalid_parameter_error("extension rings: need 0 <= initial_rings <= maximum_rings and extension_step >= 1");
  if(o.maximum_solves < 1) throw Invalid_parameter_error("maximum_solves must be at least 1");
  o.predicted = choose_parameter(get_parameter(np, internal_np::predicted_extension_t()), true);
  o.fast_marching_margin =
      choose_parameter(get_parameter(np, internal_np::fast_marching_margin_t()), default_fast_marching_margin);
  if(o.fast_marching_margin < 0) throw Invalid_parameter_error("fast_marching_margin must be at least 0");
  return o;
}

// The pipeline as its named steps, in the manual's order: the distances on M
// that shape the tree, stage 1, the extended surface grown and solved on
// (stage 2), the kink split, the envelopes and the ridge (stage 2c and 3),
// and the cone ridge. Each step is timed here, in `Ridge_curve::timings`.
template <class TriangleMesh, class NamedParameters, class Solver, class Maps>
class Geodesic_ridge_pipeline
{
  typedef typename Maps::Point Point;
  typedef typename Maps::Vertex_point_map VertexPointMap;
  typedef typename Maps::Face_index_map FaceIndexMap;
  typedef Extended_surface_builder<TriangleMesh, Maps> Builder;
  static constexpr bool solver_has_cones = Geodesic_solver_traits<std::decay_t<Solver> >::has_cones;
  static constexpr bool solver_has_windows = Geodesic_solver_traits<std::decay_t<Solver> >::has_windows;

public:
  // `angles`: the mesh's corner angles, if a batch of sources computed them once
  Geodesic_ridge_pipeline(const TriangleMesh& tm, const Geodesic_source<TriangleMesh>& src, const NamedParameters& np,
                          const Solver& solver, const Maps& maps, const Corner_angles* angles = nullptr)
    : tm_(tm), src_(src), np_(np), solver_(solver), options_(pipeline_options(np, solver)), maps_(maps),
      angles_(angles), st_(result_.statistics), timings_(result_.timings)
  {}

  Ridge_curve<TriangleMesh, Point> run()
  {
    st_.solver = solver_.name();
    const std::vector<double> field = timings_.time("tree_distances", [&] { return distances_on_mesh(); });
    timings_.time("rough_cut_locus", [&] {
      if(!angles_)
      {
        own_angles_ = corner_angles(tm_, maps_.vpm, maps_.vim, maps_.fim);
        angles_ = &own_angles_;
      }
      rough_cut_locus(field);
      // stage 3 needs only the angle sums (the curvature near free ends)
      std::vector<std::array<double, 3> >().swap(own_angles_.angle);
    });
    mean_edge_ = mean_edge_length();
    { // the builder's arrays are freed before the assembly, the peak of memory
      Builder builder(tm_, result_.rough_cut_locus, maps_);
      timings_.time("extended_surface", [&] {
        for(int r = 0; r < options_.initial_rings; ++r) builder.grow_ring();
      });
      grow_and_solve(builder);
    }
    timings_.time("ridge_assembly", [&] { assemble_ridge(); });
    check_ridge_topology();
    if(options_.cone_ridge) timings_.time("cone_ridge", [&] { trace_cones(); });
    return std::move(result_);
  }

private:
  // Stage 1 follows a tree that descends a geodesic distance on M (see
  // `rough_cut::descend_field`): fast marching, or the solver itself.
  std::vector<double> distances_on_mesh()
  {
    std::vector<double> field(num_vertices(tm_));
    st_.tree_from_solver = options_.tree_from_solver;
    if(options_.tree_from_solver)
    {
      auto field_map = boost::make_iterator_property_map(field.begin(), maps_.vim);
      const auto geometry = CGAL::parameters::vertex_point_map(maps_.vpm);
      if(src_.kind == Geodesic_source<TriangleMesh>::ON_VERTEX) solver_(tm_, src_.vertex, field_map, geometry);
      else solver_(tm_, src_.location, field_map, geometry);
    }
    else
      fast_marching_distances(tm_, maps_.vpm, maps_.vim, src_.seeds, field);
    return field;
  }

  void rough_cut_locus(const std::vector<double>& field)
  {
    result_.rough_cut_locus = rough_cut_locus_impl(tm_, src_, np_, &field, angles_);
    st_.tolerance = result_.rough_cut_locus.tolerance;
    st_.rough_cut_locus = result_.rough_cut_locus.statistics;
  }

  double mean_edge_length() const
  {
    double sum = 0;
    for(auto e : edges(tm_)) sum += distance_between(maps_.vpm, source(e, tm_), target(e, tm_));
    return sum / static_cast<double>(num_edges(tm_));
  }

  // Stage 2: solve, extend again only where copies on the border of E still
  // win, solve again. The exact solver's cones tell the fronts of a copy's
  // corners apart (kinks inside one sheet). They are read only near copies
  // whose linear field bends by a quarter of the kink angle against a glued
  // copy's: measured on 6 sources of bunny_1k, armadillo_2k and teddy_3k, the
  // same ridges (a few split copies fewer, recall and precision unchanged), in
  // half the time on 10k-face meshes (path queries for every copy cost about
  // one more solve). The cone ridge reads them on every undominated copy of
  // such a face (its two sides' lowest copies both need cones); the cone
  // field on every undominated copy.
  void grow_and_solve(Builder& builder)
  {
    const double kink_filter_share = tuning::extension::kink_filter_share;
    const bool cone_field = options_.field == Field::cone;
    const Growth_schedule schedule{options_.extension_step, options_.maximum_rings, options_.maximum_solves,
                                   options_.predicted, options_.fast_marching_margin};
    Extension_growth<TriangleMesh, Builder, Solver, Point> growth(
        tm_, src_, builder, solver_, schedule, mean_edge_, E_, face_copies_, result_.vertex_distances, st_,
        timings_, options_.cone_ridge || split_at_kinks() ? &copy_cones_ : nullptr, cone_samples(),
        cone_field ? 0 : kink_filter_share * options_.kink_angle, options_.cone_ridge);
    growth.run();
    copy_corners_ = growth.take_corner_distances();
    st_.extended_surface = E_.statistics;
    if(!options_.cone_ridge) return;
    // per face of M, the cones of its undominated copies, where they were read
    const bool windows = cone_field && solver_has_windows;
    std::vector<std::vector<Face_cone> >& cones = cone_field && !windows ? result_.cones : face_cones_;
    cones.assign(num_faces(tm_), {});
    for(std::size_t f = 0; f < face_copies_.size(); ++f)
      for(std::size_t c : face_copies_[f].copies) append_sampled_cones(c, cones[f]);
    if(windows) timings_.time("cone_field", [&] { windows_on_mesh(); });
  }

  // The cone field of a solver with windows: its windows on M, whose lower
  // envelope is the distance on M, each its own copy (`locate()` names the
  // window). Not E's: E holds every shortest path to a vertex, not to every
  // point (armadillo_2k from vertex 0: 3e-3 too long at a point of face 1492,
  // whose shortest path enters through an edge of E's border).
  void windows_on_mesh()
  {
    if constexpr(solver_has_windows)
    {
      std::vector<double> distance(num_vertices(tm_));
      std::vector<Face_cone> no_samples;
      const auto np = CGAL::parameters::vertex_point_map(maps_.vpm).vertex_index_map(maps_.vim).face_index_map(maps_.fim);
      const auto map = boost::make_iterator_property_map(distance.begin(), maps_.vim);
      auto every = [](std::size_t) { return true; };
      const std::vector<std::array<double, 3> > samples;
      if(src_.kind == Geodesic_source<TriangleMesh>::ON_VERTEX)
        solver_(tm_, src_.vertex, map, no_samples, every, samples, &result_.cones, np);
      else solver_(tm_, src_.location, map, no_samples, every, samples, &result_.cones, np);
      for(std::vector<Face_cone>& face : result_.cones)
      {
        for(std::size_t i = 0; i < face.size(); ++i) face[i].copy = static_cast<std::uint32_t>(i);
        if(face.empty()) // another connected component: unreachable
        {
          face.emplace_back();
          face.back().apex = {{1, 0, 0}};
          face.back().offset = std::numeric_limits<double>::infinity();
          face.back().copy = 0;
        }
      }
    }
  }

  // copy c's cones at the samples, if the solver read them
  void append_sampled_cones(std::size_t c, std::vector<Face_cone>& cones) const
  {
    if(!cones_read(c)) return;
    const std::size_t samples = cone_samples().size();
    cones.insert(cones.end(), copy_cones_.begin() + std::ptrdiff_t(samples * c),
                 copy_cones_.begin() + std::ptrdiff_t(samples * (c + 1)));
  }

  // The cone ridge's cones of each face with a copy split at a kink: per front
  // of a split copy one copy whose every sample gives the front's cone,
  // instead of the copy's samples.
  void cones_with_fronts(const std::map<std::size_t, std::vector<Face_cone> >& front_cones)
  {
    const std::size_t samples = cone_samples().size();
    std::vector<char> has_front(num_faces(tm_), 0);
    for(const auto& cf : front_cones) has_front[E_.original_face[cf.first]] = 1;
    for(std::size_t f = 0; f < face_copies_.size(); ++f)
    {
      if(!has_front[f]) continue;
      std::vector<Face_cone>& cones = face_cones_[f];
      cones.clear();
      std::vector<std::size_t> done; // a copy split before comes once per front
      for(std::size_t c : face_copies_[f].copies)
      {
        if(std::find(done.begin(), done.end(), c) != done.end()) continue;
        done.push_back(c);
        const auto it = front_cones.find(c);
        if(it == front_cones.end()) append_sampled_cones(c, cones);
        else
          for(const Face_cone& front : it->second) cones.insert(cones.end(), samples, front);
      }
    }
  }

  // whether the solver read copy c's cones (an unread cone has no apex)
  bool cones_read(std::size_t c) const
  {
    const std::size_t samples = cone_samples().size();
    if(samples * (c + 1) > copy_cones_.size()) return false;
    const auto& apex = copy_cones_[samples * c].apex;
    return std::abs(apex[0] + apex[1] + apex[2] - 1) <= 0.5;
  }

  bool split_at_kinks() const { return solver_has_cones && options_.kink_angle > 0; }
  bool corner_fallback() const { return options_.corner_fallback; }
  const std::vector<std::array<double, 3> >& cone_samples() const
  {
    if(options_.field == Field::cone) return Exact_solver::cone_samples();
    if(options_.cone_ridge)
      return corner_fallback() ? Exact_solver::cone_ridge_fallback_samples() : Exact_solver::cone_ridge_samples();
    return corner_fallback() ? Exact_solver::corner_fallback_samples() : Exact_solver::corner_samples();
  }

  // Stage 3 (with the copy splitters before the envelopes): the ridge curve.
  void assemble_ridge()
  {
    // the cone ridge (not the cone field's, whose cones are its queries') sees
    // the fronts of a split copy as copies: it moves the kink's points too
    const bool fronts_as_copies = options_.cone_ridge && options_.field != Field::cone;
    const Ridge_curve_input in{face_copies_, copy_corners_, copy_cones_, cone_samples(), angles_->angle_sum,
                               mean_edge_, options_.minimum_angle, options_.kink_angle, split_at_kinks(),
                               corner_fallback(), fronts_as_copies, options_.ridge_passes, expected_cycles()};
    std::map<std::size_t, std::vector<Face_cone> > front_cones;
    assemble_ridge_curve(tm_, E_, maps_, in, result_.polylines, result_.regions, st_.ridge, front_cones);
    if(!front_cones.empty()) cones_with_fronts(front_cones);
  }

  // the ridge with the border: connected, with 2g + b independent cycles
  std::size_t expected_cycles() const
  {
    const Rough_cut_locus_statistics& s = result_.rough_cut_locus.statistics;
    return static_cast<std::size_t>(2 * s.genus) + s.number_of_boundary_loops;
  }

  void check_ridge_topology() const
  {
    const Rough_cut_locus_statistics& s = result_.rough_cut_locus.statistics;
    const std::size_t cycles = expected_cycles();
    if(st_.ridge.components != 1 || st_.ridge.cycles != cycles)
      throw Algorithm_error("the ridge" + std::string(s.number_of_boundary_loops > 0 ? " with the border" : "") +
                            " has " + std::to_string(st_.ridge.components) + " components and " +
                            std::to_string(st_.ridge.cycles) + " cycles; expected 1 and 2g + b = " +
                            std::to_string(cycles));
  }

  void trace_cones()
  {
    result_.cone_polylines = trace_cone_ridge(tm_, maps_.vpm, maps_.vim, maps_.fim, result_.polylines,
                                              options_.field == Field::cone && !solver_has_windows ? result_.cones
                                                                                                   : face_cones_,
                                              cone_samples(), options_.cone_ridge_tolerance * mean_edge_, mean_edge_,
                                              st_.cone_ridge);
    st_.cone_ridge_traced = true;
    std::vector<std::vector<Face_cone> >().swap(face_cones_);
  }

  const TriangleMesh& tm_;
  const Geodesic_source<TriangleMesh> src_;
  const NamedParameters& np_;
  const Solver solver_;
  const Pipeline_options options_;
  const Maps maps_;
  const Corner_angles* angles_;
  Corner_angles own_angles_; // when no batch gave them: for stage 1, then the sums for stage 3
  Ridge_curve<TriangleMesh, Point> result_;
  Geodesic_ridge_statistics& st_;
  Timings& timings_;
  double mean_edge_ = 0;
  Extended_surface<Point> E_;
  std::vector<Face_copies> face_copies_;
  std::vector<Face_cone> copy_cones_;
  std::vector<std::vector<Face_cone> > face_cones_; // for the cone ridge without the cone field
  std::vector<std::array<double, 3> > copy_corners_; // per copy of E, at the last solve
};

template <class TriangleMesh, class NamedParameters>
auto ridge_curve_impl(const TriangleMesh& tm, const Geodesic_source<TriangleMesh>& src, const NamedParameters& np,
                      const Corner_angles* angles = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto solver = choose_parameter(get_parameter(np, internal_np::solver_t()), Exact_solver());
  return Geodesic_ridge_pipeline(tm, src, np, solver, mesh_maps(tm, np), angles).run();
}

// Everything the pipeline computed on the unit mesh, in the input's units:
// points, distances, cone offsets, stage 1's lengths and areas. A point is
// mapped alone, so points that are one stay one.
template <class TriangleMesh, class Point>
void map_from_unit(Ridge_curve<TriangleMesh, Point>& rc, const Normalization& n)
{
  if(n.identity()) return;
  for(auto* lines : {&rc.polylines, &rc.cone_polylines})
    for(auto& line : *lines)
      for(auto& p : line) p.point = n.from_unit(p.point);
  for(auto& cells : rc.regions)
    for(auto& cell : cells)
      for(double& d : cell.field) d = n.length_from_unit(d);
  for(double& d : rc.vertex_distances) d = n.length_from_unit(d);
  for(auto& cones : rc.cones)
    for(Face_cone& c : cones) c.offset = n.length_from_unit(c.offset);
  rc.statistics.cone_ridge.tolerance = n.length_from_unit(rc.statistics.cone_ridge.tolerance);
  map_from_unit(rc.rough_cut_locus, n);
}

// The public entry: the pipeline on the unit mesh (internal/normalization.h).
template <class TriangleMesh, class SourceLocation, class NamedParameters>
auto ridge_curve_of(const TriangleMesh& tm, const SourceLocation& source, const NamedParameters& np)
{
  Normalization n;
  const auto unit_np = unit_parameters(tm, np, n);
  auto rc = ridge_curve_impl(tm, checked_source(tm, source, unit_np), unit_np);
  map_from_unit(rc, n);
  return rc;
}

} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
/// \brief computes the geodesic ridge of the vertex `source` on the triangle
/// mesh `tm` (closed or with a border), and returns a `Ridge_curve<TriangleMesh, Point_3>`
/// (`Point_3` the value type of the vertex point map) with everything
/// computed on the way.
///
/// Runs the three stages of the user manual (\ref Chapter_GeodesicRidge):
/// the rough cut locus, the extended surface grown by the growth rule and
/// solved on, then the exact lower envelope of every face and the ridge curve.
///
/// \tparam TriangleMesh a model of `FaceListGraph` (`CGAL::Surface_mesh`, for example)
/// \tparam NamedParameters a sequence of named parameters
///         (\ref GeodesicRidgeSecParameters)
///
/// \param tm the mesh
/// \param source the source: a vertex of `tm`, or (second overload) a surface
///        point of `tm` as a `Face_location`, a face and its barycentric
///        coordinates in the order `source(halfedge(f))`,
///        `target(halfedge(f))`, `target(next(halfedge(f)))`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \pre `tm` is a connected, manifold (closed or with a border), consistently oriented triangle
///      mesh with finite coordinates, no isolated vertex, no duplicate face and
///      no zero-area face (checked first by `validate_triangle_mesh()`:
///      `Invalid_mesh_error` otherwise).
/// \pre `source` is a vertex of `tm`, or a face of `tm` with finite,
///      non-negative barycentric coordinates that sum to 1 within 1e-9
///      (`Invalid_source_error` otherwise).
/// \pre Every named parameter is in its range; `field(Field::cone)` and
///      `cone_ridge(true)` come with the exact solver (a solver with cones),
///      and `cone_ridge(false)` without the cone field (`Invalid_parameter_error` otherwise, thrown
///      before any work).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{tolerance}
///     \cgalParamDescription{stage 1 keeps the dual edges whose significance is at least this fraction of the total area}
///     \cgalParamType{`double`, in [0, 0.5)}
///     \cgalParamDefault{`default_tolerance` (0.025)}
///   \cgalParamNEnd
///   \cgalParamNBegin{branch_curvature}
///     \cgalParamDescription{degrees: kept branches of the dual tree that enclose less Gaussian curvature are false and pruned back; 0 is the paper's pruning}
///     \cgalParamType{`double`, in [0, 720]}
///     \cgalParamDefault{`default_branch_curvature` (15)}
///   \cgalParamNEnd
///   \cgalParamNBegin{leaf_curvature}
///     \cgalParamDescription{degrees: pruned branches that hold this much Gaussian curvature are kept, so that the cut graph reaches the tips of the ridge; 0 turns it off}
///     \cgalParamType{`double`, in [0, 720]}
///     \cgalParamDefault{`default_leaf_curvature` (45)}
///   \cgalParamNEnd
///   \cgalParamNBegin{solver}
///     \cgalParamDescription{the geodesic solver run on the extended surface}
///     \cgalParamType{a model of `GeodesicSolver`}
///     \cgalParamDefault{`Exact_solver()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{tree_from_solver}
///     \cgalParamDescription{the shortest-path tree of stage 1 follows the solver's distances on `tm` (one more solve) instead of fast marching: with the exact solver, fewer cuts on the wrong side of a saddle (worst recall measured 0.6 instead of 3.5 mean edges) at about 1.8 times the time}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{initial_rings}
///     \cgalParamDescription{extension rings grown everywhere before the first pass}
///     \cgalParamType{`int`, at least 0 and at most `maximum_rings`}
///     \cgalParamDefault{3}
///   \cgalParamNEnd
///   \cgalParamNBegin{extension_step}
///     \cgalParamDescription{rings grown after a pass around the copies that still win on a border edge of the extended surface (or half the depth reached, if more)}
///     \cgalParamType{`int`, at least 1}
///     \cgalParamDefault{4}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_rings}
///     \cgalParamDescription{a safety cap on extension rings (`Geodesic_ridge_statistics::ring_cap_hit` says when it stopped the growth)}
///     \cgalParamType{`int`, at least `initial_rings`}
///     \cgalParamDefault{`default_maximum_rings` (256)}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_solves}
///     \cgalParamDescription{solves of the solver on the extended surface at most}
///     \cgalParamType{`int`, at least 1}
///     \cgalParamDefault{`default_maximum_solves` (3)}
///   \cgalParamNEnd
///   \cgalParamNBegin{predicted_extension}
///     \cgalParamDescription{fast-marching passes decide where the extended surface grows and the solver runs on the final one; with `false` every pass is a solve}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{fast_marching_margin}
///     \cgalParamDescription{with the fast-marching solver, rings grown around the whole final extended surface before its last pass}
///     \cgalParamType{`int`, at least 0}
///     \cgalParamDefault{`default_fast_marching_margin` (2)}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_spur_angle}
///     \cgalParamDescription{degrees: free ends of the ridge whose gradient jump is below it are pruned, repeatedly (0 keeps every branch); fronts whose gradients across a mesh edge differ by less are one front}
///     \cgalParamType{`double`}
///     \cgalParamDefault{15}
///   \cgalParamNEnd
///   \cgalParamNBegin{kink_angle}
///     \cgalParamDescription{degrees: copies glued across a mesh edge whose gradients jump by this much are different fronts, and with the exact solver copies are split at kinks between their corners' fronts; 0 turns both off}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`default_kink_angle` (60)}
///   \cgalParamNEnd
///   \cgalParamNBegin{corner_fallback}
///     \cgalParamDescription{with the exact solver's kink split, a corner that no sample's front reaches exactly takes its front from a sample nearer to it, if that front meets the others at a ridge: the branches that pass between a corner and its sample are found}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///     \cgalParamExtra{ignored with the cone field and with solvers without cones}
///   \cgalParamNEnd
///   \cgalParamNBegin{cone_ridge}
///     \cgalParamDescription{the ridge reported (`Ridge_curve::ridge_polylines()`, `compute_geodesic_ridge()`) is the cone ridge (`Ridge_curve::cone_polylines`), where the exact solver's cones meet, read on the faces near kinks; `false`: the linear field's (`Ridge_curve::polylines`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true` with a solver that offers cones (`Exact_solver`); always with `field(Field::cone)`}
///     \cgalParamExtra{`true` needs a solver with cones}
///   \cgalParamNEnd
///   \cgalParamNBegin{field}
///     \cgalParamDescription{`Field::cone` also keeps the cones of every undominated copy (`Ridge_curve::cones`), for the cone field of `make_distance_field()`}
///     \cgalParamType{`Field`}
///     \cgalParamDefault{`Field::linear`}
///     \cgalParamExtra{`Field::cone` needs the exact solver}
///   \cgalParamNEnd
///   \cgalParamNBegin{cone_ridge_tolerance}
///     \cgalParamDescription{the cone ridge is split until the curve is within this many mean edge lengths of every chord's midpoint}
///     \cgalParamType{`double`, in (0, 1]}
///     \cgalParamDefault{`default_cone_ridge_tolerance` (0.001)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in [0, `num_vertices(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in [0, `num_faces(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
///                    as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in [0, `num_edges(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
///                    as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \post the ridge is connected, a tree on a genus-0 surface, with exactly 2g
///   independent cycles on genus g (`Algorithm_error` otherwise).
/// \post unless the ridge curve's `statistics.outer_copies_winning > 0` (a cap
///   stopped the growth), the extended surface holds a shortest path to every
///   vertex: `Ridge_curve::vertex_distances` are the solver's distances on M.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto compute_ridge_curve(const TriangleMesh& tm,
                         typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::ridge_curve_of(tm, source, np);
}

/// \ingroup PkgGeodesicRidgeRef
/// \brief computes the geodesic ridge of the surface point `source` (a
/// `Face_location`) on the triangle mesh `tm` (closed or with a border), and returns a
/// `Ridge_curve<TriangleMesh, Point_3>` with everything computed on the way.
/// A location on an edge or at a vertex is handled as such.
///
/// \copydetails compute_ridge_curve(const TriangleMesh&, typename boost::graph_traits<TriangleMesh>::vertex_descriptor, const NamedParameters&)
template <class TriangleMesh, class FT, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto compute_ridge_curve(const TriangleMesh& tm,
                         const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                         std::array<FT, 3> >& source,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::ridge_curve_of(tm, source, np);
}

/// \ingroup PkgGeodesicRidgeRef
/// \brief computes the geodesic ridge of `source` (a vertex or a
/// `Face_location`) on `tm` and writes its polylines (`std::vector<Point_3>`,
/// between junctions and free ends; `Ridge_curve::ridge_polylines()`) to
/// `out`: the one-shot version of `compute_ridge_curve()`.
///
/// \tparam OutputIterator an output iterator accepting `std::vector<Point_3>`
/// \param out the output iterator
/// \returns `out` past the last polyline
///
/// \copydetails compute_ridge_curve(const TriangleMesh&, typename boost::graph_traits<TriangleMesh>::vertex_descriptor, const NamedParameters&)
template <class TriangleMesh, class Source, class OutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator compute_geodesic_ridge(const TriangleMesh& tm, const Source& source, OutputIterator out,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  return ridge_polyline_points(compute_ridge_curve(tm, source, np).ridge_polylines(), out);
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_COMPUTE_GEODESIC_RIDGE_H
