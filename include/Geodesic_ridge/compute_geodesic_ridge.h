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
#include <Geodesic_ridge/lower_envelope.h>
#include <Geodesic_ridge/parameters.h>
#include <Geodesic_ridge/ridge_curve.h>
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
/// Counts of the whole pipeline: what it did and what happened.
struct Geodesic_ridge_statistics
{
  /// the solver's name (`GeodesicSolver::name()`)
  std::string solver;
  /// the tolerance of stage 1
  double tolerance = 0;
  int solves = 0;                 ///< solves of the solver on the extended surface
  int predicted_passes = 0;       ///< fast-marching passes on E that decided the extension steps
  std::size_t outer_copies_winning = 0; ///< at the last solve: copies still winning on a border edge of E (0: E holds every shortest path)
  bool ring_cap_hit = false;      ///< the growth stopped at `maximum_rings` with copies still winning
  int margin_rings = 0;           ///< fast marching: rings grown around the final E (`parameters::fast_marching_margin`)
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

// Per face of M, the copies of E whose three corner distances (`corners`, per
// face of E) are not all >= those of another copy (a dominated copy never
// wins, paper §3.2.2). Into `face_copies`, whose arrays are emptied, not
// freed: every pass fills them again.
template <class Point>
void undominated_copies(const Extended_surface<Point>& E, const std::vector<std::array<double, 3> >& corners,
                        std::size_t number_of_faces, std::vector<Face_copies>& face_copies)
{
  face_copies.resize(number_of_faces);
  for(Face_copies& fc : face_copies)
  {
    fc.copies.clear();
    fc.fields.clear();
    fc.split.clear();
  }
  for(std::size_t c = 0; c < corners.size(); ++c)
  {
    const std::array<double, 3>& d = corners[c];
    Face_copies& fc = face_copies[E.original_face[c]];
    bool dominated = false;
    for(std::size_t i = 0; i < fc.fields.size() && !dominated; ++i)
      dominated = fc.fields[i][0] <= d[0] && fc.fields[i][1] <= d[1] && fc.fields[i][2] <= d[2];
    if(dominated) continue;
    keep_face_copies_if(fc, [&](std::size_t i) {
      return !(d[0] <= fc.fields[i][0] && d[1] <= fc.fields[i][1] && d[2] <= fc.fields[i][2]);
    });
    fc.fields.push_back(d);
    fc.copies.push_back(c);
  }
}

// Whether the linear function c (values c0, c1 at the ends of an edge) comes
// within `slack` of the lowest of `others` somewhere on the edge: the minimum
// of max_j (c - o_j), convex and piecewise linear, lies at an end or where two
// of the others cross.
inline bool lowest_somewhere_on_edge(double c0, double c1, const std::vector<std::array<double, 2> >& others,
                                     double slack)
{
  auto excess = [&](double t) {
    double e = -std::numeric_limits<double>::infinity();
    for(const auto& o : others) e = std::max(e, (c0 + (c1 - c0) * t) - (o[0] + (o[1] - o[0]) * t));
    return e;
  };
  if(others.empty() || excess(0) <= slack || excess(1) <= slack) return true;
  for(std::size_t i = 0; i < others.size(); ++i)
    for(std::size_t j = i + 1; j < others.size(); ++j)
    {
      const double d0 = others[i][0] - others[j][0], d1 = others[i][1] - others[j][1];
      if((d0 < 0) != (d1 < 0) && d0 != d1 && excess(d0 / (d0 - d1)) <= slack) return true;
    }
  return false;
}

// The copies of E (by face index of E) that come within `slack` of the lowest
// copy somewhere on one of their border edges, among the undominated copies of
// both faces of M at that edge: their fronts may go on beyond E.
template <class Point>
std::vector<char> copies_winning_on_border(const Faces_across& across, const Extended_surface<Point>& E,
                                           const std::vector<Face_copies>& face_copies, double slack)
{
  const auto& m = E.mesh;
  std::vector<char> winning(m.number_of_faces(), 0);
  std::vector<std::array<double, 2> > others;
  for(auto b : m.halfedges())
  {
    if(!m.is_border(b)) continue;
    const auto h = m.opposite(b);
    const std::size_t c = std::size_t(m.face(h));
    if(winning[c]) continue;
    int k = 0;
    for(auto x = m.halfedge(m.face(h)); x != h; x = m.next(x)) ++k;
    const std::size_t f = E.original_face[c];
    const Face_copies& fc = face_copies[f];
    const auto it = std::find(fc.copies.begin(), fc.copies.end(), c);
    if(it == fc.copies.end()) continue; // dominated: never the lowest
    const auto& d = fc.fields[std::size_t(it - fc.copies.begin())];
    others.clear();
    for(std::size_t i = 0; i < fc.copies.size(); ++i)
      if(fc.copies[i] != c) others.push_back({{fc.fields[i][k], fc.fields[i][(k + 1) % 3]}});
    const auto [g, kg] = across[f][k];
    if(g == no_face_across) continue; // the border of M: nothing lies beyond
    for(const auto& o : face_copies[g].fields) others.push_back({{o[(kg + 1) % 3], o[kg]}});
    if(lowest_somewhere_on_edge(d[k], d[(k + 1) % 3], others, slack)) winning[c] = 1;
  }
  return winning;
}

// per vertex of M: the smallest distance over its copies in E
template <class Point>
std::vector<double> smallest_over_copies(const Extended_surface<Point>& E, const std::vector<double>& distance,
                                         std::size_t number_of_vertices)
{
  std::vector<double> best(number_of_vertices, std::numeric_limits<double>::infinity());
  for(auto v : E.mesh.vertices()) best[E.original_vertex[v]] = std::min(best[E.original_vertex[v]], distance[v]);
  return best;
}

// per face of E (a copy): the distances at its three corners
template <class Point>
std::vector<std::array<double, 3> > corner_distances(const Extended_surface<Point>& E,
                                                     const std::vector<double>& distance)
{
  std::vector<std::array<double, 3> > out;
  out.reserve(E.mesh.number_of_faces());
  for(auto c : E.mesh.faces())
  {
    auto h = E.mesh.halfedge(c);
    out.push_back({{distance[E.mesh.source(h)], distance[E.mesh.target(h)], distance[E.mesh.target(E.mesh.next(h))]}});
  }
  return out;
}

// Copies of E where a kink inside one sheet can be (those whose cones
// Kink_splitter reads): the copies whose linear field bends by `angle` degrees
// or more against a copy glued to them (a copy that straddles a kink bends
// against the copies on both sides), and the copies glued to those.
template <class Point>
std::vector<char> copies_near_kinks(const Extended_surface<Point>& E, const std::vector<std::array<double, 3> >& corners,
                                    double angle)
{
  typedef typename Extended_surface<Point>::Mesh Mesh;
  const Mesh& m = E.mesh;
  auto corner_points = [&](typename Mesh::Face_index f) {
    const auto h = m.halfedge(f);
    return std::array<Point, 3>{{m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h)))}};
  };
  std::vector<char> bends(m.number_of_faces(), 0);
  for(auto h : m.halfedges())
  {
    const auto o = m.opposite(h);
    if(m.is_border(h) || m.is_border(o) || m.face(h) > m.face(o)) continue; // each inner edge once
    const std::size_t a = std::size_t(m.face(h)), b = std::size_t(m.face(o));
    const Gradient_jump jump = gradient_jump_across_edge(
        m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))), m.point(m.target(m.next(o))),
        field_gradient(corner_points(m.face(h)), corners[a]), field_gradient(corner_points(m.face(o)), corners[b]));
    if(jump.angle >= angle) bends[a] = bends[b] = 1;
  }
  std::vector<char> near = bends;
  for(auto f : m.faces())
    if(bends[std::size_t(f)])
      for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m))
        if(!m.is_border(m.opposite(h))) near[std::size_t(m.face(m.opposite(h)))] = 1;
  return near;
}

// the distances from the source over E, by vertex index of E
template <class Point, class Solver>
void solve_on(const Extended_surface<Point>& E, const Solver& solver, std::vector<double>& distance)
{
  if(E.source_is_vertex) solver(E.mesh, E.source_vertex, CGAL::make_property_map(distance));
  else solver(E.mesh, E.source_location, CGAL::make_property_map(distance));
}

// Same, and the cones of the copies for which wanted(copy) is true (called by
// the solver once `distance` is written); the solver must offer cones.
template <class Point, class Solver, class Wanted>
void solve_on(const Extended_surface<Point>& E, const Solver& solver, std::vector<double>& distance,
              std::vector<Face_cone>& cones, const Wanted& wanted, const std::vector<std::array<double, 3> >& samples)
{
  if constexpr(Geodesic_solver_traits<std::decay_t<Solver> >::has_cones)
  {
    if(E.source_is_vertex) solver(E.mesh, E.source_vertex, CGAL::make_property_map(distance), cones, wanted, samples);
    else solver(E.mesh, E.source_location, CGAL::make_property_map(distance), cones, wanted, samples);
  }
  else
    throw Invalid_parameter_error(std::string("the cones (the cone field, the cone ridge) need a solver that offers them (exact, vtp), not '") + solver.name() + "'");
}

// Fast marching over E from the corners of its first `anchor.size()` copies,
// which keep the given distances (a corner shared by copies, or merged since,
// starts from the smallest): the solver's fronts carried onto the copies grown
// since it ran.
template <class Point>
void fast_marching_from_anchors(const Extended_surface<Point>& E, const std::vector<std::array<double, 3> >& anchor,
                                std::vector<double>& distance)
{
  typedef typename Extended_surface<Point>::Mesh Mesh;
  std::vector<std::pair<typename Mesh::Vertex_index, double> > seeds;
  seeds.reserve(3 * anchor.size());
  for(std::size_t c = 0; c < anchor.size(); ++c)
  {
    auto h = E.mesh.halfedge(typename Mesh::Face_index(static_cast<typename Mesh::size_type>(c)));
    for(int k = 0; k < 3; ++k, h = E.mesh.next(h)) seeds.emplace_back(E.mesh.source(h), anchor[c][k]);
  }
  fast_marching_distances(E.mesh, E.mesh.points(), get(CGAL::vertex_index, E.mesh), seeds, distance);
}

// Fast marching on the grown E resumed from the last pass on it: the corners
// of its first `anchor.size()` copies keep the distances they had (a corner
// shared by copies, or merged since, the smallest), and the sweep restarts from
// those that touch a copy grown since, so that it costs what E grew, not all of
// E. A front that comes back lower by more than `reopen_margin` reopens a kept
// vertex. The same as a pass from scratch where E did not change, up to the
// order in which fast marching met the vertices near the old border.
template <class Point>
void fast_marching_resumed(const Extended_surface<Point>& E, const std::vector<std::array<double, 3> >& anchor,
                           double reopen_margin, std::vector<double>& distance)
{
  typedef typename Extended_surface<Point>::Mesh Mesh;
  const std::size_t nv = E.mesh.number_of_vertices(), nc = E.mesh.number_of_faces();
  distance.assign(nv, std::numeric_limits<double>::infinity());
  std::vector<char> accepted(nv, 0);
  auto corners = [&](std::size_t c) {
    std::array<std::size_t, 3> v;
    auto h = E.mesh.halfedge(typename Mesh::Face_index(static_cast<typename Mesh::size_type>(c)));
    for(int k = 0; k < 3; ++k, h = E.mesh.next(h)) v[k] = E.mesh.source(h);
    return v;
  };
  for(std::size_t c = 0; c < anchor.size(); ++c)
  {
    const auto v = corners(c);
    for(int k = 0; k < 3; ++k)
    {
      distance[v[k]] = (std::min)(distance[v[k]], anchor[c][k]);
      accepted[v[k]] = 1;
    }
  }
  std::vector<std::size_t> trial;
  for(std::size_t c = anchor.size(); c < nc; ++c)
    for(std::size_t v : corners(c))
      if(accepted[v]) { accepted[v] = 0; trial.push_back(v); }
  fast_marching_sweep(E.mesh, E.mesh.points(), get(CGAL::vertex_index, E.mesh), trial, distance, accepted, reopen_margin);
}

// What drives the growth of E (the named parameters of the same names).
struct Growth_schedule
{
  int extension_step, maximum_rings, maximum_solves;
  bool predicted;
  int fast_marching_margin;
};

// Stage 2b: grows E from the builder's rings by the growth rule and solves on
// it; leaves E, the undominated copies of every face and the best copy of every
// vertex from the last solve.
//
// The growth rule (user manual, "The Solve and the Growth Rule"): E grows a
// band of rings around every copy that still comes lowest somewhere on one of
// its border edges, until none does. A shortest path that leaves E crosses E's
// border where its front is exact, so no copy is lower there: without such
// copies E holds every shortest path. Passes on E decide the growth:
//  * predicted: fast marching from the source (cheap; most of the growth);
//  * solve: the solver (its distances make the ridge; its test is within
//    round-off for the exact solver);
//  * anchored: after a solve that still found such copies, fast marching on
//    the grown E seeded with the solver's distances on the copies it solved,
//    so that the growth follows the solver's fronts and the solver runs once
//    more, not once per band. Fast marching from the source misjudges which
//    front wins by up to half an edge (it has no pseudo-sources: fronts that
//    bend around saddle vertices come out late), far more than any slack that
//    would not grow E everywhere (teddy_3k v0: 36 rings short).
// With fast marching as the solver, its passes are the solves.
template <class TriangleMesh, class Builder, class Solver, class Point>
class Extension_growth
{
  enum class Pass { predicted, solve, anchored };
  static constexpr bool solver_is_exact = Geodesic_solver_traits<std::decay_t<Solver> >::is_exact;
  static constexpr bool solver_is_fast_marching = std::is_same<std::decay_t<Solver>, Fast_marching_solver>::value;
  // Whose fronts decide the growth: the solver's if it is exact or fast
  // marching; any other approximate solver (heat, Dijkstra, a user's) solves
  // once on the E that the predicted passes grew. Its errors are larger than
  // fast marching's at E's border (the heat method's boundary condition), so
  // judging the growth by them would grow E by noise (bunny_1k v0, heat-idt:
  // the ring cap, 198 times M).
  static constexpr bool solver_steers_growth = solver_is_exact || solver_is_fast_marching;

public:
  // With `cones`, the solver's cones of the undominated copies are read at
  // the last solve (at `cone_samples`); with `cones_near_kinks_only` > 0 only
  // those of copies near kinks of that many degrees (`copies_near_kinks`),
  // and with `whole_faces` those of every copy of a face that has one.
  Extension_growth(const TriangleMesh& tm, const Geodesic_source<TriangleMesh>& src,
                   Builder& builder, const Solver& solver, const Growth_schedule& schedule,
                   double mean_edge, Extended_surface<Point>& E, std::vector<Face_copies>& face_copies,
                   std::vector<double>& vertex_distances, Geodesic_ridge_statistics& st, Timings& timings,
                   std::vector<Face_cone>* cones, const std::vector<std::array<double, 3> >& cone_samples,
                   double cones_near_kinks_only, bool whole_faces)
    : tm_(tm), src_(src), builder_(builder), solver_(solver), schedule_(schedule),
      E_(E), face_copies_(face_copies), vertex_distances_(vertex_distances), st_(st), timings_(timings),
      cones_(cones), cone_samples_(cone_samples), cones_near_kinks_only_(cones_near_kinks_only),
      whole_faces_(whole_faces),
      across_(builder.faces_across_edges()), fast_marching_slack_(0.02 * mean_edge), exact_slack_(1e-9 * mean_edge),
      reopen_margin_(1e-9 * mean_edge)
  {}

  void run()
  {
    pass_ = schedule_.predicted && !solver_is_fast_marching ? Pass::predicted : Pass::solve;
    bool grown = true;
    for(;;)
    {
      // every E is checked in debug builds, the last one always (below)
      if(grown) timings_.time("extended_surface", [&] { builder_.materialize(E_, src_, false); });
      run_pass();
      grown = grows(st_.solves) && grow_band();
      if(grown)
      {
        if(pass_ == Pass::solve && !solver_is_fast_marching && schedule_.predicted) pass_ = Pass::anchored;
        continue;
      }
      // E is final for now: done if the solver has solved it, else solve
      if(pass_ == Pass::solve || builder_.number_of_copies() == anchor_.size()) break;
      pass_ = Pass::solve;
    }
    st_.ring_cap_hit = st_.outer_copies_winning > 0 && builder_.statistics().rings >= schedule_.maximum_rings;
    if(solver_is_fast_marching && schedule_.fast_marching_margin > 0) grow_margin();
    timings_.time("extended_surface", [&] { Builder::check_valid(E_); });
    // the last solve expected E to grow, and it could not (a leaf's winding
    // bound): read the cones on E as it is, with one more solve
    if(cones_ && !cones_read_) read_cones_on_final_surface();
  }

  // per copy of the final E: its corner distances at the last solve
  std::vector<std::array<double, 3> > take_corner_distances() { return std::move(anchor_); }

private:
  // Fast marching: rings around the whole final E, then one more pass
  // (resumed: it costs what E grew). Fast marching updates a vertex from its
  // one-ring, which E's border cuts; where the winning copies reach that
  // border, their values are those of a narrower surface, on which fast
  // marching errs more than on M (kitten_5k v1250: 0.6 mean edge above fast
  // marching on an E grown from 20 rings everywhere, and the same with 3, 5
  // or 10 initial rings). Rings around the undominated copies only were no
  // smaller on large meshes (torus_100k 1.06 F, bunny_70k 1.12 instead of
  // 1.13), and finding them cost more than the rings.
  void grow_margin()
  {
    timings_.time("extended_surface", [&] {
      for(int r = 0; r < schedule_.fast_marching_margin; ++r) builder_.grow_ring();
      builder_.materialize(E_, src_, false);
    });
    st_.margin_rings = schedule_.fast_marching_margin;
    margin_pass_ = true;
    run_pass();
  }

  // The pass on the margin's E runs from scratch, not resumed: resumed, it
  // kept distances in the order fast marching met the vertices near the old
  // border, which followed the faces' orientation (bunny_1k reversed: vertex
  // distances up to 0.008 (1.6 % of the diagonal) apart, 54 polylines against
  // 58; from scratch, bit for bit the same). It costs one sweep of E.
  bool margin_pass_ = false;

  // One pass: its distances, and what they say (the undominated copies of
  // every face, the copies still winning on E's border).
  void run_pass()
  {
    distance_.assign(E_.mesh.number_of_vertices(), 0.0);
    corners_.clear();
    grow_from_.clear();
    winning_ = 0;
    analysed_ = false;
    timings_.time("solve", [&] { compute_distances(); });
    if(pass_ == Pass::solve && E_.source_is_vertex && distance_[E_.source_vertex] != 0)
      throw Algorithm_error("the solver's distance at the source is not 0");
    analyse();
    if(pass_ == Pass::solve)
    {
      st_.outer_copies_winning = winning_;
      vertex_distances_ = smallest_over_copies(E_, distance_, num_vertices(tm_));
      anchor_ = std::move(corners_);
    }
  }

  void compute_distances()
  {
    if(pass_ == Pass::solve && cones_) solve_reading_cones();
    else if(pass_ == Pass::solve && solver_is_fast_marching && !anchor_.empty() && !margin_pass_)
    {
      fast_marching_resumed(E_, anchor_, reopen_margin_, distance_);
      ++st_.solves;
    }
    else if(pass_ == Pass::solve) { solve_on(E_, solver_, distance_); ++st_.solves; }
    else if(pass_ == Pass::predicted) { solve_on(E_, Fast_marching_solver(), distance_); ++st_.predicted_passes; }
    else { fast_marching_from_anchors(E_, anchor_, distance_); ++st_.predicted_passes; }
  }

  // The cones of the undominated copies, read only at a solve after which E
  // stays as it is (the solver calls `wanted` once the distances are in).
  void solve_reading_cones()
  {
    std::vector<char> keep;
    auto wanted = [&](std::size_t copy) {
      if(keep.empty())
      {
        analyse();
        cones_read_ = !grows(st_.solves + 1);
        keep = cones_read_ ? cones_wanted(distance_) : std::vector<char>(E_.mesh.number_of_faces(), 0);
      }
      return keep[copy] != 0;
    };
    solve_on(E_, solver_, distance_, *cones_, wanted, cone_samples_);
    ++st_.solves;
  }

  void read_cones_on_final_surface()
  {
    std::vector<double> distance(E_.mesh.number_of_vertices());
    std::vector<char> keep;
    timings_.time("solve", [&] {
      solve_on(E_, solver_, distance, *cones_, [&](std::size_t copy) {
        if(keep.empty()) keep = cones_wanted(distance);
        return keep[copy] != 0;
      }, cone_samples_);
    });
    ++st_.solves;
  }

  // the copies whose cones are read: the undominated ones, or those of them
  // near kinks, or those of faces that have one near kinks
  std::vector<char> cones_wanted(const std::vector<double>& distance) const
  {
    std::vector<char> keep(E_.mesh.number_of_faces(), 0);
    for(const Face_copies& fc : face_copies_)
      for(std::size_t c : fc.copies) keep[c] = 1;
    if(cones_near_kinks_only_ > 0)
    {
      const std::vector<char> near = copies_near_kinks(E_, corner_distances(E_, distance), cones_near_kinks_only_);
      std::vector<char> face_near(whole_faces_ ? face_copies_.size() : 0, 0);
      for(std::size_t c = 0; c < keep.size(); ++c)
      {
        keep[c] = keep[c] && near[c];
        if(whole_faces_ && keep[c]) face_near[E_.original_face[c]] = 1;
      }
      if(whole_faces_)
        for(const Face_copies& fc : face_copies_)
          for(std::size_t c : fc.copies) keep[c] = face_near[E_.original_face[c]];
    }
    return keep;
  }

  void analyse()
  {
    if(analysed_) return;
    timings_.time("envelope_and_dominance", [&] {
      corners_ = corner_distances(E_, distance_);
      undominated_copies(E_, corners_, num_faces(tm_), face_copies_);
      const double slack = pass_ == Pass::solve && solver_is_exact ? exact_slack_ : fast_marching_slack_;
      grow_from_ = copies_winning_on_border(across_, E_, face_copies_, slack);
      winning_ = static_cast<std::size_t>(std::count(grow_from_.begin(), grow_from_.end(), 1));
    });
    analysed_ = true;
  }

  // after this pass, is E grown again (else it is final)?
  bool grows(int solves_done) const
  {
    if(pass_ == Pass::solve && !solver_steers_growth && schedule_.predicted) return false;
    const bool solves_left = pass_ != Pass::solve || solver_is_fast_marching || solves_done < schedule_.maximum_solves;
    return winning_ > 0 && solves_left && builder_.statistics().rings < schedule_.maximum_rings;
  }

  // A band of rings around the copies still winning (each ring from the copies
  // the previous one added): at least `extension_step` rings, and half the
  // depth reached, since a front that crossed a badly placed cut may win far
  // beyond it (knot_3k v304: along the whole tube behind a rung), reached in
  // O(log) passes. Whether E grew (not at a leaf's winding bound).
  bool grow_band()
  {
    return timings_.time("extended_surface", [&] {
      const std::size_t before_band = builder_.number_of_copies();
      const int band = std::max(schedule_.extension_step, builder_.statistics().rings / 2);
      std::size_t first = 0; // the next ring grows from the last one's copies only
      for(int step = 0; step < band && builder_.statistics().rings < schedule_.maximum_rings; ++step)
      {
        const std::size_t before = builder_.number_of_copies();
        builder_.grow_ring(&grow_from_, first);
        grow_from_.assign(builder_.number_of_copies(), 0);
        for(std::size_t c = before; c < builder_.number_of_copies(); ++c) grow_from_[c] = 1;
        first = before;
      }
      return builder_.number_of_copies() > before_band;
    });
  }

  const TriangleMesh& tm_;
  const Geodesic_source<TriangleMesh>& src_;
  Builder& builder_;
  const Solver& solver_;
  const Growth_schedule schedule_;
  Extended_surface<Point>& E_;
  std::vector<Face_copies>& face_copies_;
  std::vector<double>& vertex_distances_;
  Geodesic_ridge_statistics& st_;
  Timings& timings_;
  std::vector<Face_cone>* const cones_;
  const std::vector<std::array<double, 3> >& cone_samples_;
  const double cones_near_kinks_only_;
  const bool whole_faces_;
  const Faces_across& across_; // the builder's
  // a copy that wins on the border by less than this is no winner: noise
  // between neighbouring fronts (fast marching), round-off (the exact solver)
  const double fast_marching_slack_, exact_slack_;
  // a resumed fast-marching pass reopens a kept vertex only if a front comes this much lower
  const double reopen_margin_;
  Pass pass_ = Pass::solve;
  std::vector<std::array<double, 3> > anchor_; // per copy, at the last solve: its corner distances
  bool cones_read_ = false; // at the last solve, for the copies of E now
  // the pass's distances and their analysis
  std::vector<double> distance_;
  std::vector<std::array<double, 3> > corners_;
  std::vector<char> grow_from_;
  std::size_t winning_ = 0;
  bool analysed_ = false;
};

// The named parameters of the pipeline beyond those of stage 1, checked.
struct Pipeline_options
{
  int initial_rings, extension_step, maximum_rings, maximum_solves, fast_marching_margin;
  double minimum_angle, kink_angle, cone_ridge_tolerance;
  bool tree_from_solver, predicted, corner_fallback, cone_ridge;
  Field field;
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
  // `Rough_cut_locus_builder::descend_field`): fast marching, or the solver itself.
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
    const double kink_filter_share = 0.25;
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

  // Stage 2c + 3: copies split at kinks, exact envelopes and the ridge curve.
  void assemble_ridge()
  {
    std::size_t split_copies = 0;
    // without a split, the copies as they are (no copy of them: they are a few
    // heap blocks per face, at the peak of memory)
    std::vector<Face_copies> split_fronts;
    // Copies that recombine nearer sheets' fronts: a corner's owner within a
    // tenth of a mean edge of the copy's distance (0.05 missed teddy_3k v383
    // and bunny_1k v80 at tolerance 0.002, 0.25 placed teddy_3k v383's ridge
    // worse), owners 30 degrees apart (the fronts meet where the precision is
    // measured). With the cone field too: the cone ridge is traced from the
    // linear one and keeps its branches (bunny_7k v1951 and f6223, bunny_1k
    // v80 at tolerance 0.002: recall p95 2.52, 2.34 and 0.61 mean edges
    // without the split, 0.23, 0.21 and 0.10 with it).
    const double witness_tolerance = 0.1 * mean_edge_, recombined_split_angle = 30;
    st_.ridge.recombined_copies = Recombined_copy_splitter<TriangleMesh, VertexPointMap, FaceIndexMap, Point>(
        tm_, maps_.vpm, maps_.fim, E_, copy_corners_, witness_tolerance, recombined_split_angle)(face_copies_);
    std::vector<std::array<double, 3> >().swap(copy_corners_);
    // the cone ridge (not the cone field's, whose cones are its queries') sees
    // the fronts of a split copy as copies: it moves the kink's points too
    std::map<std::size_t, std::vector<Face_cone> > front_cones;
    const bool fronts_as_copies = options_.cone_ridge && options_.field != Field::cone;
    if(split_at_kinks())
    {
      split_fronts = Kink_splitter<TriangleMesh, VertexPointMap, FaceIndexMap, Point>(
          tm_, maps_.vpm, maps_.fim, E_, copy_cones_, cone_samples(), options_.kink_angle, mean_edge_,
          corner_fallback())(face_copies_, split_copies, fronts_as_copies ? &front_cones : nullptr);
      if(!front_cones.empty()) cones_with_fronts(front_cones);
    }
    // the cone ridge's cones (the copies' and the split fronts') give the
    // fronts' arrival directions at the ridge segments
    const Copy_cones cones{&copy_cones_, &front_cones, &cone_samples()};
    assemble_ridge_curve(tm_, E_, split_at_kinks() ? split_fronts : face_copies_, mean_edge_, options_.minimum_angle,
                         options_.kink_angle, maps_, angles_->angle_sum, result_.polylines, result_.regions, st_.ridge,
                         fronts_as_copies ? &cones : nullptr);
    st_.ridge.split_copies = split_copies;
  }

  void check_ridge_topology() const
  {
    // the ridge with the border: connected, with 2g + b independent cycles
    const Rough_cut_locus_statistics& s = result_.rough_cut_locus.statistics;
    const std::size_t cycles = static_cast<std::size_t>(2 * s.genus) + s.number_of_boundary_loops;
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
