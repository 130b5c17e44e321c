// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 2b: the extended surface E grown by the growth rule and solved on
// (`Extension_growth`), and what its passes read of a solve: the undominated
// copies of every face, the copies still winning on E's border, the best copy
// of every vertex. The pipeline (compute_geodesic_ridge.h) runs it between
// stage 1 and the envelopes.
#ifndef GEODESIC_RIDGE_INTERNAL_EXTENSION_GROWTH_H
#define GEODESIC_RIDGE_INTERNAL_EXTENSION_GROWTH_H

#include <Geodesic_ridge/extended_surface.h>
#include <Geodesic_ridge/internal/face_copies.h>
#include <Geodesic_ridge/internal/field_gradients.h>
#include <Geodesic_ridge/internal/tuning.h>
#include <Geodesic_ridge/lower_envelope.h>
#include <Geodesic_ridge/source.h>
#include <Geodesic_ridge/solvers/Face_cone.h>
#include <Geodesic_ridge/solvers/Fast_marching_solver.h>
#include <Geodesic_ridge/solvers/solver_traits.h>
#include <Geodesic_ridge/timings.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace Geodesic_ridge {

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
                   std::vector<double>& vertex_distances, Extension_growth_statistics& st, Timings& timings,
                   std::vector<Face_cone>* cones, const std::vector<std::array<double, 3> >& cone_samples,
                   double cones_near_kinks_only, bool whole_faces)
    : tm_(tm), src_(src), builder_(builder), solver_(solver), schedule_(schedule),
      E_(E), face_copies_(face_copies), vertex_distances_(vertex_distances), st_(st), timings_(timings),
      cones_(cones), cone_samples_(cone_samples), cones_near_kinks_only_(cones_near_kinks_only),
      whole_faces_(whole_faces),
      across_(builder.faces_across_edges()), fast_marching_slack_(tuning::extension::fast_marching_slack * mean_edge),
      exact_slack_(tuning::extension::exact_slack * mean_edge), reopen_margin_(tuning::extension::reopen_margin * mean_edge)
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
  Extension_growth_statistics& st_;
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

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_EXTENSION_GROWTH_H
