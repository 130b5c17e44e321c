// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The measure of correctness (user manual, "How Accuracy Is Measured"): the
// computed ridge against the exact reference ridge built from CGAL
// Surface_mesh_shortest_path arrival directions (test/support/reference_ridge.h).
// Distances in mean edge lengths.
#include "support/analytic_meshes.h"
#include "support/extension_checks.h"
#include "support/reference_ridge.h"

#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/solvers/Window_propagation_solver.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Mesh;
namespace GT = Geodesic_ridge::testing;

Mesh load(const std::string& name)
{
  Mesh m;
  Geodesic_ridge::IO::read_triangle_mesh(std::string(GEODESIC_RIDGE_DATA_DIR) + "/" + name, m);
  return m;
}

GT::Reference_ridge_options reference_options()
{
  GT::Reference_ridge_options opt;
#ifdef GEODESIC_RIDGE_SANITIZE
  opt.spacing = 0.25; // about 3x fewer SMSP queries under ASan
#else
  opt.spacing = 0.15;
#endif
  return opt;
}

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The exact reference ridge from `source`.
template <class Source>
GT::Reference_ridge<Point_3> exact_reference(const Mesh& m, const Source& source)
{
  auto ref = GT::reference_ridge(m, source, reference_options());
  REQUIRE(ref.failed_samples == 0);
  return ref;
}

// The major ridge at a small tolerance (the ridge `rc`, the polylines it
// reports) against the reference `ref`: prints the counts and the accuracy,
// checks one component, recall and precision p95 within 0.5 mean edge.
template <class Ridge>
void check_major_ridge(const GT::Reference_ridge<Point_3>& ref, const Ridge& rc, const std::string& what)
{
  INFO(what);
  const auto acc = GT::ridge_accuracy(ref, rc.ridge_polylines(), reference_options());
  const auto& r = rc.statistics.ridge;
  std::cout << std::setprecision(3) << what << ": split copies " << r.split_copies << ", recombined "
            << r.recombined_copies << ", joining segments " << r.piece_joining_segments << ", recall p95 "
            << acc.recall_p95 << ", precision p95 " << acc.precision_p95 << "\n";
  REQUIRE(acc.recall_points > 0);
  CHECK(r.components == 1);
  CHECK(acc.recall_p95 <= 0.5);
  CHECK(acc.precision_p95 <= 0.5);
}

} // namespace

// The reference itself, on a case with a known answer: from vertex A of a
// regular tetrahedron the ridge is the "Y" on the opposite face joining its
// centroid G to its corners B, C, D (by symmetry), with direction jumps of
// 120 degrees at G growing to 180 degrees at the corners.
TEST_CASE("reference ridge: regular tetrahedron from a vertex", "[ridge_accuracy]")
{
  Mesh m;
  const Point_3 A(1, 1, 1), B(1, -1, -1), C(-1, 1, -1), D(-1, -1, 1);
  CGAL::make_tetrahedron(A, B, C, D, m);
  Mesh::Vertex_index a;
  for(auto v : m.vertices()) if(m.point(v) == A) a = v;
  GT::Reference_ridge_options opt;
  opt.subdivisions = 20;
  opt.source_exclusion = 0;
  const auto ref = GT::reference_ridge(m, a, opt);
  const double L = ref.mean_edge;
  const Point_3 G = CGAL::centroid(B, C, D);
  std::vector<K::Segment_3> Y = {K::Segment_3(G, B), K::Segment_3(G, C), K::Segment_3(G, D)};
  auto distance_to_Y = [&](const Point_3& p) {
    double d = 1e300;
    for(const auto& s : Y) d = std::min(d, std::sqrt(CGAL::squared_distance(p, s)));
    return d;
  };
  REQUIRE(ref.failed_samples == 0);
  REQUIRE(ref.points.size() > 20); // the Y runs along rows of samples here: few pairs straddle it
  double worst = 0, min_jump = 180;
  for(std::size_t i = 0; i < ref.points.size(); ++i)
  {
    worst = std::max(worst, distance_to_Y(ref.points[i]) / L);
    min_jump = std::min(min_jump, ref.jump_degrees[i]);
  }
  std::cout << "tetrahedron: " << ref.points.size() << " reference points, max distance to the Y " << worst
            << " mean edges, min jump " << min_jump << " deg\n";
  REQUIRE(worst < 1e-6);
  REQUIRE(min_jump > 115);
  // the Y is covered (away from its three ends, where samples thin out)
  double gap = 0;
  for(const auto& s : Y)
    for(int k = 0; k <= 50; ++k)
    {
      const Point_3 p = s.source() + (s.target() - s.source()) * (0.9 * k / 50.0);
      double d = 1e300;
      for(const auto& q : ref.points) d = std::min(d, std::sqrt(CGAL::squared_distance(p, q)));
      gap = std::max(gap, d / L);
    }
  REQUIRE(gap < 0.1);
}

// The reference on real meshes is consistent with SMSP: at every reference point
// the two fronts agree with the exact distance there (a third, shorter front
// would mean the point is not on the ridge). Measured max 0.025 mean edges (at
// junctions, where a third front cuts the segment between two samples).
TEST_CASE("reference ridge: fronts agree with the exact distance", "[ridge_accuracy]")
{
  const Mesh m = load("bunny_1k.off");
  const auto ref = GT::reference_ridge(m, Mesh::Vertex_index(0), reference_options());
  GT::internal::SMSP_for<Mesh> sp(m);
  sp.add_source_point(Mesh::Vertex_index(0));
  sp.build_sequence_tree();
  std::vector<double> err;
  for(std::size_t i = 0; i < ref.points.size(); ++i)
  {
    auto loc = CGAL::Polygon_mesh_processing::locate_in_face(
        ref.points[i], Mesh::Face_index(static_cast<Mesh::size_type>(ref.faces[i])), m);
    double sum = 0;
    for(double& c : loc.second) { c = std::max(0.0, c); sum += c; }
    for(double& c : loc.second) c /= sum;
    const double d = sp.shortest_distance_to_source_points(loc.first, loc.second).first;
    err.push_back(std::abs(ref.distances[i] - d) / ref.mean_edge);
  }
  REQUIRE(!err.empty());
  const double p99 = GT::internal::quantile(err, 0.99), worst = GT::internal::quantile(err, 1.0);
  std::cout << "bunny_1k reference self-check: |d_fronts - d_exact| p99 " << p99 << ", max " << worst
            << " mean edges over " << err.size() << " points\n";
  // the error grows with the spacing of the samples: measured p99 0.0046 at
  // spacing 0.15 (Release), 0.0117 at 0.25 (sanitizer builds)
  REQUIRE(p99 < 0.1 * reference_options().spacing);
  REQUIRE(worst < 0.1);
}

// Precision at the default tolerance and recall of the major ridge at small
// tolerances (0.005, 0.001), on genus 0, 0, 1, 2, from two sources each
// (vertex 0 and V/2).
TEST_CASE("ridge accuracy against the exact reference ridge", "[slow][ridge_accuracy]")
{
  const std::string name = GENERATE(as<std::string>(), "bunny_1k.off", "armadillo_2k.off", "torus_1k.off", "eight.off");
  const Mesh m = load(name);
  const long genus = (2 - (long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces()))) / 2;
  const GT::Reference_ridge_options ropt = reference_options();

  for(const std::size_t sv : {std::size_t(0), std::size_t(m.number_of_vertices() / 2)})
  {
    const Mesh::Vertex_index s(static_cast<Mesh::size_type>(sv));
    INFO(name << " source vertex " << sv);
    auto t0 = std::chrono::steady_clock::now();
    const auto ref = GT::reference_ridge(m, s, ropt);
    const double t_ref = seconds_since(t0);
    REQUIRE(ref.failed_samples == 0);

    t0 = std::chrono::steady_clock::now();
    const auto rc = Geodesic_ridge::compute_ridge_curve(m, s, Geodesic_ridge::parameters::tolerance(0.025));
    const double t_ridge = seconds_since(t0);
    const auto acc = GT::ridge_accuracy(ref, rc.ridge_polylines(), ropt);

    const auto rc_small = Geodesic_ridge::compute_ridge_curve(m, s, Geodesic_ridge::parameters::tolerance(0.005));
    const auto acc_small = GT::ridge_accuracy(ref, rc_small.ridge_polylines(), ropt);
    const auto rc_tiny = Geodesic_ridge::compute_ridge_curve(m, s, Geodesic_ridge::parameters::tolerance(0.001));
    const auto acc_tiny = GT::ridge_accuracy(ref, rc_tiny.ridge_polylines(), ropt);

    std::cout << std::setprecision(3) << "ridge accuracy " << name << " (F " << m.number_of_faces() << ", genus "
              << genus << ") source v" << sv << " " << m.point(s) << ": reference " << ref.points.size()
              << " points (" << ref.samples << " samples, " << t_ref << " s), ridge " << t_ridge << " s\n"
              << "  tol 0.025: precision (>=30 deg, " << acc.major_samples << " samples) median "
              << acc.precision_median << " p95 " << acc.precision_p95 << " max " << acc.precision_max
              << "; (<30 deg, " << acc.minor_samples << ") median " << acc.precision_minor_median << " p95 "
              << acc.precision_minor_p95 << "; recall (>=60 deg, " << acc.recall_points << ") median "
              << acc.recall_median << " p95 " << acc.recall_p95 << "; outliers > 0.5: " << acc.outliers.size()
              << "\n  tol 0.005: recall median " << acc_small.recall_median << " p95 " << acc_small.recall_p95
              << " max " << acc_small.recall_max << "; precision p95 " << acc_small.precision_p95
              << "\n  tol 0.001: recall median " << acc_tiny.recall_median << " p95 " << acc_tiny.recall_p95
              << " max " << acc_tiny.recall_max << "\n";

    REQUIRE(acc.major_samples > 0);
    REQUIRE(acc.recall_points > 0);
    // Precision target of the issue: p95 <= 0.5 mean edge on the >= 30 degree part.
    // Measured 0.06-0.44 (worst: bunny v0 0.44 since weak ends at corners are
    // kept, eight v0 0.38). An earlier version of
    // the pipeline failed it on eight v0 (0.67): a cycle closed through a staircase of
    // mesh edges 1-1.9 mean edges off the exact ridge; this assertion catches that.
    REQUIRE(acc.precision_p95 <= 0.5);
    // Recall of the major ridge (jump >= 60 degrees). Pruning by significance
    // shortens every leaf branch until the area past its end reaches tol * total
    // area, and >= 60 degree ridge points crowd at sharp tips (ears, toes),
    // exactly where leaves end. Since the cut graph's leaves go on into pruned
    // branches that hold >= 45 degrees of curvature (parameters::leaf_curvature),
    // the ridge reaches most tips. At small tolerances the false branches of
    // the cut, which enclose no curvature (parameters::branch_curvature), are
    // pruned. Measured p95 (mean edges, 2026-12-01): tol 0.025 0.02-0.72
    // (bunny v0; 3.95 before the curvature branches), tol 0.005 0.02-0.54
    // (0.22-4.42 before), tol 0.001 0.02-0.42 (0.26-1.11 before). Precision at
    // tol 0.005: p95 0.07-0.38 (0.26-0.54 with the false branches).
    // Losing a whole major branch (>= 5% of the major points, >= 2 mean edges
    // away) fails these bounds.
    REQUIRE(acc.recall_p95 <= 1.5);
    REQUIRE(acc_small.precision_p95 <= 0.5);
    // Small tolerances: where K lacks a branch of the cut locus, both fronts
    // reach the faces along it inside one sheet of E; one copy is exact at all
    // three corners and its linear field hides the kink. parameters::kink_angle
    // (60 degrees) splits such copies by their cones (Kink_splitter):
    // armadillo_2k v0 at 0.005 was 3.1 without kinks, 1.77 with the gradient
    // test alone; bunny_1k v251 at 0.001 1.34.
    REQUIRE(acc_small.recall_p95 <= 1.0);
    REQUIRE(acc_tiny.recall_p95 <= 1.0);
  }
}

// Issue 10, kinks inside one sheet of E: where the cut graph K lacks a branch
// of the cut locus, both fronts reach the faces along it inside one sheet, and
// only the cones of a copy's samples tell them apart (Kink_splitter). Sources
// whose major ridge was missed at tolerance 0.002 before the copies were split
// at such kinks (recall p95, mean edges): armadillo_2k v0 1.78, v792 1.12;
// bunny_1k v251 1.34 and the random point f434 0.58 (1.11 while the split
// fronts were still glued to their neighbours by the gradient test). With
// parameters::corner_fallback (default: a sample nearer to each corner, where
// the kink passes between the corner and its first sample, so that no
// sample's cone gives the corner's front): armadillo_2k v648 3.54 without it.
TEST_CASE("kinks inside one sheet: the major ridge at a small tolerance", "[slow][ridge_accuracy]")
{
  namespace p = Geodesic_ridge::parameters;
  auto check = [&](const Mesh& m, const auto& source, const std::string& what) {
    INFO(what);
    const auto rc = Geodesic_ridge::compute_ridge_curve(m, source, p::tolerance(0.002));
    check_major_ridge(exact_reference(m, source), rc, "kinks inside one sheet, " + what);
    CHECK(rc.statistics.ridge.split_copies > 0);
  };
  const Mesh armadillo = load("armadillo_2k.off");
  for(const std::size_t v : {0, 792})
    check(armadillo, Mesh::Vertex_index(static_cast<Mesh::size_type>(v)), "armadillo_2k v" + std::to_string(v));
  check(armadillo, Mesh::Vertex_index(648), "armadillo_2k v648 (the corner fallback)");
  const Mesh bunny = load("bunny_1k.off");
  check(bunny, Mesh::Vertex_index(251), "bunny_1k v251");
  // the second of bench_ridge_accuracy's random points (seed 1 + F)
  const auto points = GT::random_face_locations(bunny, 2, 1 + static_cast<unsigned>(bunny.number_of_faces()));
  check(bunny, points[1], "bunny_1k f" + std::to_string(std::size_t(points[1].first)));
  // A fallback front must meet the copy's other fronts at a ridge (no corner's
  // front has a cone below the copy's distance at another corner): without
  // that test the fallback split copies in the shadows of saddle vertices, and
  // teddy_3k from vertex 479 (default tolerance) had overall precision p95
  // 0.58 mean edges (bench_ridge_accuracy; 0.40 with it, 0.13 without the
  // fallback).
  const Mesh teddy = load("teddy_3k.off");
  const Mesh::Vertex_index v479(479);
  const auto acc = GT::ridge_accuracy(exact_reference(teddy, v479),
                                      Geodesic_ridge::compute_ridge_curve(teddy, v479).ridge_polylines(),
                                      reference_options());
  std::cout << std::setprecision(3) << "kinks inside one sheet, teddy_3k v479: precision p95 (all) "
            << acc.precision_all_p95 << ", (>= 30 deg) " << acc.precision_p95 << "\n";
  CHECK(acc.precision_all_p95 <= 0.5);
  CHECK(acc.precision_p95 <= 0.25);
}

// Issue 10, copies that recombine nearer sheets' fronts: at small tolerances K
// keeps false branches that the fronts' exact paths cross far upstream, E grows
// far behind them, and a far sheet, reached by both fronts and glued across the
// ridge between them, is the only one exact at the ridge's faces: its linear
// field hid the ridge (Recombined_copy_splitter). Recall p95 at tolerance 0.002
// before the split (mean edges): teddy_3k v383 5.70, bunny_1k v80 2.37, v20
// 1.79, v481 1.11 (bench_ridge_accuracy --sources-per-mesh 25 --seed 7; and
// bunny_7k v1951 10.1). Exact solver, and our window propagation, which has no
// cones (the kink split does not run).
TEST_CASE("copies that recombine nearer sheets' fronts: the major ridge at a small tolerance", "[slow][ridge_accuracy]")
{
  namespace p = Geodesic_ridge::parameters;
  auto check = [&](const Mesh& m, std::size_t v, const std::string& what) {
    const Mesh::Vertex_index source(static_cast<Mesh::size_type>(v));
    INFO(what << " v" << v);
    const auto ref = exact_reference(m, source);
    auto run = [&](const auto& rc, const std::string& solver) {
      INFO(solver);
      check_major_ridge(ref, rc,
                        "recombined copies, " + what + " v" + std::to_string(v) + " (" + solver + ")");
      CHECK(rc.statistics.ridge.recombined_copies > 0);
    };
    run(Geodesic_ridge::compute_ridge_curve(m, source, p::tolerance(0.002)), "exact");
    run(Geodesic_ridge::compute_ridge_curve(m, source,
                                            p::tolerance(0.002, p::solver(Geodesic_ridge::Window_propagation_solver()))),
        "vtp");
  };
  const Mesh teddy = load("teddy_3k.off");
  check(teddy, 383, "teddy_3k");
  const Mesh bunny = load("bunny_1k.off");
  for(const std::size_t v : {20, 80, 481}) check(bunny, v, "bunny_1k");
}

// Issue 10, detached pieces with a verified kink: at small tolerances a real
// branch may be found only in pieces (kinks split by the solver's cones, strong
// jumps) whose link to the rest of the ridge runs where the fronts meet at a
// smaller angle than a split needs, or where no cone gave a corner's front; the
// assembly kept only the longest piece and dropped the branch. A piece that
// holds a verified kink is joined to the main one instead
// (`join_verified_pieces`). Recall p95 at tolerance 0.002 before (mean edges):
// teddy_3k v894 6.38 (a branch of 13 mean edges, 3.5 from the main piece, its
// link 40 degrees), bunny_1k v421 1.10 (bench_ridge_accuracy --sources-per-mesh
// 25 --seed 7).
TEST_CASE("detached pieces with a verified kink: the major ridge at a small tolerance", "[ridge_accuracy]")
{
  auto check = [&](const Mesh& m, std::size_t v, const std::string& what) {
    const Mesh::Vertex_index source(static_cast<Mesh::size_type>(v));
    INFO(what << " v" << v);
    const auto rc = Geodesic_ridge::compute_ridge_curve(m, source, Geodesic_ridge::parameters::tolerance(0.002));
    check_major_ridge(exact_reference(m, source), rc,
                      "joined pieces, " + what + " v" + std::to_string(v));
    CHECK(rc.statistics.ridge.piece_joining_segments > 0);
    CHECK(rc.statistics.ridge.cycles == 0);
  };
  check(load("teddy_3k.off"), 894, "teddy_3k");
  check(load("bunny_1k.off"), 421, "bunny_1k");
}

// Issue 10, the cone ridge (`Ridge_curve::cone_polylines`, the ridge reported
// with the exact solver) at a small tolerance: traced from the linear ridge,
// it keeps that ridge's branches, so the splits that find them run with the
// cones too. Recall p95 at tolerance 0.002 before (mean edges;
// bench_ridge_accuracy --sources-per-mesh 25 --seed 7): bunny_1k v80 0.61 with
// the cone field (a recombined copy: the split did not run with it), v341 1.70
// with the cone field (a kink between a corner and its cone sample at
// barycentric 0.8: the cone field's samples near the corners are at 0.95 now;
// the default cone ridge reads its cones at 0.8, and misses that branch, 1.27,
// as the linear ridge does).
TEST_CASE("the cone ridge: the major ridge at a small tolerance", "[ridge_accuracy]")
{
  namespace p = Geodesic_ridge::parameters;
  const Mesh bunny = load("bunny_1k.off");
  auto check = [&](std::size_t v, bool cone_field) {
    const Mesh::Vertex_index source(static_cast<Mesh::size_type>(v));
    const std::string what = "cone ridge, bunny_1k v" + std::to_string(v) + (cone_field ? ", cone field" : "");
    INFO(what);
    const auto rc = Geodesic_ridge::compute_ridge_curve(
        bunny, source,
        p::tolerance(0.002, p::field(cone_field ? Geodesic_ridge::Field::cone : Geodesic_ridge::Field::linear)));
    REQUIRE(rc.statistics.cone_ridge_traced);
    check_major_ridge(exact_reference(bunny, source), rc, what);
    CHECK_FALSE(rc.cone_polylines.empty()); // (its topology is the linear ridge's, checked above)
    if(v == 80) CHECK(rc.statistics.ridge.recombined_copies > 0);
  };
  check(80, false);
  check(80, true);
  check(341, true);
}

// ---------------------------------------------------------------------------
// Issue 10: the extended surface holds every shortest path, for every source.
// The check (test/support/extension_checks.h): every vertex of M has a copy in
// E at its exact distance on M (SMSP, relative 1e-9), and on every face the
// ridge crosses the lowest winning copy at each corner carries that corner's
// distance.

namespace {

typedef std::pair<Mesh::Face_index, std::array<double, 3> > Face_location;

template <class RidgeCurve>
void require_every_shortest_path(const Mesh& m, const RidgeCurve& rc, const std::vector<double>& exact)
{
  const GT::Extension_check check = GT::check_extension(m, rc, exact, 1e-9);
  INFO("vertices without an exact copy: " << check.missing.size() << " (worst by " << check.worst_excess
                                         << " mean edges); ridge corners off: " << check.front_errors
                                         << "; E: " << rc.statistics.extended_surface.number_of_faces << " faces, "
                                         << rc.statistics.extended_surface.rings << " rings, "
                                         << rc.statistics.solves << " solves");
  REQUIRE(check.missing.empty());
  REQUIRE(check.front_errors == 0);
  REQUIRE(rc.statistics.outer_copies_winning == 0);
  REQUIRE_FALSE(rc.statistics.ring_cap_hit);
}

} // namespace

TEST_CASE("the extended surface holds every shortest path, from many sources", "[slow][ridge_accuracy][extension]")
{
  const std::string name =
      GENERATE(as<std::string>(), "bunny_1k.off", "eight.off", "armadillo_2k.off", "knot_3k.off", "teddy_3k.off");
  const Mesh m = load(name);
#ifdef GEODESIC_RIDGE_SANITIZE
  const std::size_t n = 3, random = 1;
#else
  const std::size_t n = 10, random = 2;
#endif
  const unsigned seed = 10;
  std::cout << "exact copies: " << name << ", sources vertices i V / " << n << " and " << random
            << " random points (std::mt19937 seed " << seed << ")\n";
  for(std::size_t i = 0; i < n; ++i)
  {
    const Mesh::Vertex_index s(static_cast<Mesh::size_type>(i * m.number_of_vertices() / n));
    INFO(name << " source vertex " << std::size_t(s));
    require_every_shortest_path(m, Geodesic_ridge::compute_ridge_curve(m, s), GT::distances_on_mesh<K>(m, s, true));
  }
  for(const Face_location& s : GT::random_face_locations(m, random, seed))
  {
    INFO(name << " source face " << std::size_t(s.first) << " (" << s.second[0] << ", " << s.second[1] << ", "
              << s.second[2] << ")");
    require_every_shortest_path(m, Geodesic_ridge::compute_ridge_curve(m, s), GT::distances_on_mesh<K>(m, s, true));
  }
}

// The same check with fast marching against itself: E holds fast marching's
// fronts if no vertex gets lower with fast marching on an E grown from many
// more rings everywhere (10 initial rings: 2.3-3.2 times as many faces as E
// with its margin), to
// 1 % of its distance plus a mean edge. (Against fast marching on M the
// check fails near the ridge, where fast marching on M mixes the two fronts
// in the triangles that straddle it: teddy_3k v0 154 vertices within 3 rings
// of the ridge, up to 0.29 mean edges, the same with E 1.8 times larger.)
TEST_CASE("fast marching against itself: a larger E lowers no vertex", "[ridge_accuracy][extension]")
{
  namespace p = Geodesic_ridge::parameters;
  const double relative = 0.01;
  for(const std::string name : {"teddy_3k.off", "armadillo_2k.off"})
  {
    const Mesh m = load(name);
    for(const std::size_t v : {std::size_t(0), std::size_t(m.number_of_vertices() * 3 / 10)})
    {
      const Mesh::Vertex_index s(static_cast<Mesh::size_type>(v));
      INFO(name << " source vertex " << v);
      const auto fmm = p::solver(Geodesic_ridge::Fast_marching_solver());
      const auto rc = Geodesic_ridge::compute_ridge_curve(m, s, fmm);
      const auto larger = Geodesic_ridge::compute_ridge_curve(m, s, p::initial_rings(10, fmm));
      const GT::Extension_check check = GT::check_extension(m, rc, larger.vertex_distances, relative);
      std::cout << "fast marching against itself, " << name << " v" << v << ": E "
                << rc.statistics.extended_surface.number_of_faces << " faces, the larger "
                << larger.statistics.extended_surface.number_of_faces << "; " << check.missing.size()
                << " vertices lower there (worst by " << check.worst_excess << " mean edges)\n";
      CHECK(larger.statistics.extended_surface.number_of_faces > 2 * rc.statistics.extended_surface.number_of_faces);
      CHECK(check.missing.empty());
    }
  }
}

// The ridge belongs to the surface, not to its triangulation: teddy_3k with
// every edge longer than 1.5 mean edges split at its midpoint (the same
// surface, 3,192 -> 5,094 faces; the vertices keep their indices) gives a
// ridge within half a mean edge of the reference ridge of the original mesh.
// `bench_ridge_accuracy --split-long-edges 1.5` measures it over many sources
// (closed meshes: all within 0.5; the beetle, whose needles become more
// needles, not: user manual, "Ridge Accuracy over Many Sources").
TEST_CASE("re-triangulation: the same surface split otherwise keeps its ridge", "[ridge_accuracy]")
{
  const Mesh m = load("teddy_3k.off");
  Mesh split = m;
  std::vector<Mesh::Edge_index> all(split.edges().begin(), split.edges().end());
  CGAL::Polygon_mesh_processing::split_long_edges(all, 1.5 * GT::mean_edge_length(m), split);
  REQUIRE(split.number_of_faces() > m.number_of_faces() + 1000);
  for(const std::size_t v : {std::size_t(0), std::size_t(799)})
  {
    const Mesh::Vertex_index s(static_cast<Mesh::size_type>(v));
    INFO("teddy_3k source vertex " << v);
    REQUIRE(split.point(s) == m.point(s));
    const auto ref = exact_reference(m, s);
    const auto rc = Geodesic_ridge::compute_ridge_curve(split, s);
    const auto acc = GT::ridge_accuracy(ref, rc.ridge_polylines(), reference_options());
    std::cout << std::setprecision(3) << "teddy_3k v" << v << " split (" << split.number_of_faces()
              << " faces) against the reference of the original: precision p95 " << acc.precision_p95
              << ", recall p95 " << acc.recall_p95 << "\n";
    REQUIRE(acc.major_samples > 0);
    CHECK(rc.statistics.ridge.components == 1);
    CHECK(acc.precision_p95 <= 0.5);
    CHECK(acc.recall_p95 <= 0.5);
  }
}

// Thin faces (caps: three corners nearly on a line) on the same surface. Their
// linear fields' gradients across them are noise, and before two cells that
// agree along a thin face's edge were one front only if their gradients
// agreed: the ridge ran along the caps (teddy_3k with a fifth of its faces
// capped, from vertices 479 and 958, against the reference of the original:
// precision p95 0.48 and 0.54 mean edges before, 0.09 and 0.15 now).
TEST_CASE("thin faces: caps on the same surface keep its ridge", "[slow][ridge_accuracy]")
{
  const Mesh m = load("teddy_3k.off");
  Mesh capped = m;
  const unsigned seed = GT::test_seed(1);
  const std::size_t caps = GT::add_caps(capped, 0.2, seed);
  REQUIRE(caps > 500);
  for(const std::size_t v : {std::size_t(479), std::size_t(958)})
  {
    const Mesh::Vertex_index s(static_cast<Mesh::size_type>(v));
    INFO("teddy_3k source vertex " << v << ", " << caps << " caps, seed " << seed);
    REQUIRE(capped.point(s) == m.point(s));
    const auto ref = exact_reference(m, s);
    const auto rc = Geodesic_ridge::compute_ridge_curve(capped, s);
    const auto acc = GT::ridge_accuracy(ref, rc.ridge_polylines(), reference_options());
    std::cout << std::setprecision(3) << "teddy_3k v" << v << " with " << caps << " caps (seed " << seed
              << ") against the reference of the original: precision p95 " << acc.precision_p95 << ", recall p95 "
              << acc.recall_p95 << "; edge pieces of thin faces made one front " << rc.statistics.ridge.thin_face_pieces
              << "\n";
    REQUIRE(acc.major_samples > 0);
    CHECK(rc.statistics.ridge.components == 1);
    CHECK(rc.statistics.ridge.thin_face_pieces > 0);
    CHECK(acc.precision_p95 <= 0.3);
    CHECK(acc.recall_p95 <= 0.5);
  }
}

// A cycle of the cut locus across thin faces: agreeing values united its two
// fronts, and the ridge lacked a cycle of the topology (3holes_7k with caps
// on 40 % of its faces, seed 7, from a point of face 2909: "1 components and 5
// cycles; expected 1 and 2g + b = 6"; fertility_9k with `bench_ridge_accuracy
// --caps 0.2` from v2696 likewise). Stage 3 then assembles the ridge again
// without the thin-face rule: the ridge of `--without thin-faces`, which the
// exact reference confirms (precision p95 0.25 mean edges).
TEST_CASE("thin faces: a ridge that would lose a cycle is assembled without the rule", "[slow][ridge_accuracy]")
{
  Mesh capped = load("3holes_7k.off");
  const unsigned seed = 7; // (fixed: these caps and this point are the case)
  GT::add_caps(capped, 0.4, seed);
  const auto points = GT::random_face_locations(capped, 1, seed + static_cast<unsigned>(capped.number_of_faces()));
  const auto& source = points.front();
  INFO("3holes_7k with caps (seed " << seed << "), source face " << std::size_t(source.first));
  REQUIRE(std::size_t(source.first) == 2909);
  const auto rc = Geodesic_ridge::compute_ridge_curve(capped, source);
  const auto& r = rc.statistics.ridge;
  std::cout << "3holes_7k with caps (seed " << seed << ") from a point of f2909: thin-face pieces undone "
            << r.thin_face_pieces_undone << ", components " << r.components << ", cycles " << r.cycles << "\n";
  CHECK(r.thin_face_pieces_undone > 0);
  CHECK(r.thin_face_pieces == 0);
  CHECK(r.components == 1);
  CHECK(r.cycles == 6);
  const auto without = Geodesic_ridge::compute_ridge_curve(
      capped, source,
      Geodesic_ridge::parameters::disabled_ridge_passes(static_cast<unsigned>(Geodesic_ridge::internal::Ridge_pass::thin_faces)));
  REQUIRE(without.ridge_polylines().size() == rc.ridge_polylines().size());
  for(std::size_t i = 0; i < rc.ridge_polylines().size(); ++i)
  {
    REQUIRE(without.ridge_polylines()[i].size() == rc.ridge_polylines()[i].size());
    for(std::size_t j = 0; j < rc.ridge_polylines()[i].size(); ++j)
      CHECK(without.ridge_polylines()[i][j].point == rc.ridge_polylines()[i][j].point);
  }
  const auto acc = GT::ridge_accuracy(exact_reference(capped, source), rc.ridge_polylines(), reference_options());
  std::cout << std::setprecision(3) << "  against the exact reference: precision p95 " << acc.precision_p95
            << ", recall p95 " << acc.recall_p95 << "\n";
  REQUIRE(acc.major_samples > 0);
  CHECK(acc.precision_p95 <= 0.5);
  CHECK(acc.recall_p95 <= 0.5);
}

// CAD faces: a box whose sides are fans of long faces (`make_fan_box`, as
// `bench_ridge_accuracy --boxes`). The cut graph K follows the fans' edges,
// and two sheets of E that carry one front (one reaching some corners around
// a vertex of K, a little longer) meet along it; their linear fields, each
// inexact at a corner, jump by 30-90 degrees there, and a ridge was drawn
// where none is. The fronts' arrival directions from the solver's cones jump
// by a few degrees there. Precision p95 (>= 30 degrees) from vertices 0, 7,
// 37 and 44 before: 1.14, 1.07, 0.74 and 0.65 mean edges; now 0.06-0.14.
TEST_CASE("CAD faces: a ridge segment's jump is its fronts' arrival directions", "[ridge_accuracy]")
{
  const Mesh m = GT::make_fan_box(2, 1, 0.7, 6).mesh;
  for(const std::size_t v : {std::size_t(0), std::size_t(7), std::size_t(37), std::size_t(44)})
  {
    const Mesh::Vertex_index s(static_cast<Mesh::size_type>(v));
    INFO("box 2 x 1 x 0.7 of fans (" << m.number_of_faces() << " faces), source vertex " << v);
    const auto rc = Geodesic_ridge::compute_ridge_curve(m, s);
    const auto acc = GT::ridge_accuracy(exact_reference(m, s), rc.ridge_polylines(), reference_options());
    std::cout << std::setprecision(3) << "box of fans v" << v << ": precision p95 " << acc.precision_p95
              << ", recall p95 " << acc.recall_p95 << ", free ends " << rc.statistics.ridge.free_ends << "\n";
    REQUIRE(acc.major_samples > 0);
    CHECK(rc.statistics.ridge.components == 1);
    CHECK(acc.precision_p95 <= 0.3);
    CHECK(acc.recall_p95 <= 0.5);
  }
}

// The margin of fast marching (`parameters::fast_marching_margin`): without
// it, bunny_1k's two random sources of `bench_ridge_accuracy` had 8 and 4
// vertices 0.20 and 0.38 mean edges lower with fast marching on an E grown
// from 10 rings everywhere: where the winning copies reach E's border, fast
// marching's one-ring updates are cut and it errs more than on M.
TEST_CASE("fast marching against itself: the margin around E", "[ridge_accuracy][extension]")
{
  namespace p = Geodesic_ridge::parameters;
  const Mesh m = load("bunny_1k.off");
  const unsigned seed = 1 + static_cast<unsigned>(m.number_of_faces()); // the benchmark's rule
  std::size_t lower_without_margin = 0;
  for(const Face_location& s : GT::random_face_locations(m, 2, seed))
  {
    INFO("bunny_1k source face " << std::size_t(s.first) << " (" << s.second[0] << ", " << s.second[1] << ", "
                                 << s.second[2] << "), seed " << seed);
    const auto fmm = p::solver(Geodesic_ridge::Fast_marching_solver());
    const auto rc = Geodesic_ridge::compute_ridge_curve(m, s, fmm);
    const auto bare = Geodesic_ridge::compute_ridge_curve(m, s, p::fast_marching_margin(0, fmm));
    const auto larger = Geodesic_ridge::compute_ridge_curve(m, s, p::initial_rings(10, p::fast_marching_margin(0, fmm)));
    const GT::Extension_check check = GT::check_extension(m, rc, larger.vertex_distances, 0.01);
    const GT::Extension_check bare_check = GT::check_extension(m, bare, larger.vertex_distances, 0.01);
    std::cout << "fast marching's margin, bunny_1k f" << std::size_t(s.first) << ": E " << bare.statistics.extended_surface.number_of_faces
              << " -> " << rc.statistics.extended_surface.number_of_faces << " faces, vertices lower on the larger E "
              << bare_check.missing.size() << " -> " << check.missing.size() << "\n";
    CHECK(rc.statistics.margin_rings == Geodesic_ridge::default_fast_marching_margin);
    CHECK(bare.statistics.margin_rings == 0);
    CHECK(rc.statistics.extended_surface.number_of_faces > bare.statistics.extended_surface.number_of_faces);
    CHECK(check.missing.empty());
    lower_without_margin += bare_check.missing.size();
  }
  CHECK(lower_without_margin > 0);
  // the exact solver ignores the margin
  const Mesh::Vertex_index s0(0);
  CHECK(Geodesic_ridge::compute_ridge_curve(m, s0, p::fast_marching_margin(5)).statistics.margin_rings == 0);
  CHECK_THROWS_AS(Geodesic_ridge::compute_ridge_curve(m, s0, p::fast_marching_margin(-1)), Geodesic_ridge::Invalid_parameter_error);
}

// One regression per cause found (issue 10). Each names the source that
// showed it; the comment says what E lacked before.
TEST_CASE("extension regressions: each cause of a missing shortest path", "[slow][ridge_accuracy][extension]")
{
  namespace p = Geodesic_ridge::parameters;
  auto run = [](const Mesh& m, std::size_t v) {
    const Mesh::Vertex_index s(static_cast<Mesh::size_type>(v));
    const auto rc = Geodesic_ridge::compute_ridge_curve(m, s);
    require_every_shortest_path(m, rc, GT::distances_on_mesh<K>(m, s, true));
    return rc;
  };
  SECTION("a cap on rings stopped a growth that was not finished")
  {
    // With the former cap (7 rings, 2 passes) E missed the exact copies of 220,
    // 103 and 211 vertices (by up to 2.16 mean edges) from these knot_3k
    // sources; the growth itself finished at 19-27 rings. v304 needs copies
    // far along the tube behind a cycle of the cut: 100+ rings.
    const Mesh m = load("knot_3k.off");
    for(std::size_t v : {1371, 110, 207, 304})
    {
      INFO("knot_3k v" << v);
      const auto rc = run(m, v);
      CHECK(rc.statistics.extended_surface.rings > 7);
      // the check names the culprit: with the old cap the statistics say so
      const auto capped = Geodesic_ridge::compute_ridge_curve(m, Mesh::Vertex_index(static_cast<Mesh::size_type>(v)),
                                                              p::maximum_rings(7));
      CHECK(capped.statistics.ring_cap_hit);
      CHECK_FALSE(GT::check_extension(m, capped, GT::distances_on_mesh<K>(m, Mesh::Vertex_index(static_cast<Mesh::size_type>(v)), true), 1e-9).missing.empty());
    }
  }
  SECTION("fast marching misjudged which front wins, and the leaf winding bound starved a slit's two sheets")
  {
    // teddy_3k v0: fast-marching passes stopped at 19 rings while the exact
    // fronts win 36 rings further (only the solver's own distances tell);
    // and with two turns at a leaf of K the sheets grown from the two sides
    // of the slit used up the fan (248 vertices without their exact copy).
    const Mesh m = load("teddy_3k.off");
    const auto rc = run(m, 0);
    CHECK(rc.statistics.solves >= 2);
    CHECK(rc.statistics.extended_surface.rings > 19);
  }
  SECTION("a fan that could not close stopped the growth around it")
  {
    // Closing these fans would have wound a neighbour past its star (one face
    // of the cover reached twice); refused, they blocked their fronts: 115
    // vertices lost their exact copy (teddy_3k v958), 1 (bunny_1k v200).
    // They are left open now, and E grows on around them.
    const Mesh teddy = load("teddy_3k.off"), bunny = load("bunny_1k.off");
    CHECK(run(teddy, 958).statistics.extended_surface.open_fans > 0);
    CHECK(run(bunny, 200).statistics.extended_surface.open_fans > 0);
  }
}

TEST_CASE("lowest somewhere on an edge: the convex minimum at the ends or a crossing", "[extension]")
{
  using Geodesic_ridge::internal::lowest_somewhere_on_edge;
  typedef std::vector<std::array<double, 2> > Lines;
  CHECK(lowest_somewhere_on_edge(1, 1, Lines{}, 0));                          // alone: lowest
  CHECK(lowest_somewhere_on_edge(0, 2, Lines{{{1, 1}}}, 0));                  // lower at t = 0
  CHECK_FALSE(lowest_somewhere_on_edge(2, 2, Lines{{{1, 1}}}, 0));            // above everywhere
  CHECK(lowest_somewhere_on_edge(2, 2, Lines{{{1, 1}}}, 1));                  // within the slack
  // two others crossing at t = 0.5 (value 1.5): c = 1.4 constant is lowest there only
  CHECK(lowest_somewhere_on_edge(1.4, 1.4, Lines{{{1, 2}}, {{2, 1}}}, 0));
  CHECK_FALSE(lowest_somewhere_on_edge(1.6, 1.6, Lines{{{1, 2}}, {{2, 1}}}, 0));
  CHECK(lowest_somewhere_on_edge(1.5, 1.5, Lines{{{1, 2}}, {{2, 1}}}, 0));    // a tie counts
}
