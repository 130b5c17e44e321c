// Copyright (c) 2026 Geodesic_ridge developers.
//
// The measure of correctness of DESIGN.md §6: the computed ridge against the
// exact reference ridge built from CGAL Surface_mesh_shortest_path arrival
// directions (test/support/reference_ridge.h). Distances in mean edge lengths.
#include "support/reference_ridge.h"

#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
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
TEST_CASE("ridge accuracy against the exact reference ridge", "[ridge_accuracy]")
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
    const auto acc = GT::ridge_accuracy(ref, rc.polylines, ropt);

    const auto rc_small = Geodesic_ridge::compute_ridge_curve(m, s, Geodesic_ridge::parameters::tolerance(0.005));
    const auto acc_small = GT::ridge_accuracy(ref, rc_small.polylines, ropt);
    const auto rc_tiny = Geodesic_ridge::compute_ridge_curve(m, s, Geodesic_ridge::parameters::tolerance(0.001));
    const auto acc_tiny = GT::ridge_accuracy(ref, rc_tiny.polylines, ropt);

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
    REQUIRE(acc_small.recall_p95 <= 1.0);
    REQUIRE(acc_tiny.recall_p95 <= 1.0);
    REQUIRE(acc_small.precision_p95 <= 0.5);
  }
}
