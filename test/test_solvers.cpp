// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The geodesic solvers (models of GeodesicSolver) against known distances:
//  * the top sheet of a doubly covered square, where geodesics between top
//    vertices are straight segments (Euclidean distances);
//  * the exact solver on real meshes;
//  * Face_location sources: the corners start at their straight distances;
//  * meshes with a boundary (an extended surface), and the pipeline's
//    schedules that use fast marching (the tree of stage 1, the extension);
//  * the baselines: Dijkstra on the edges (an upper bound of the exact
//    distance) and the heat method (smooth, a few per cent off);
//  * our exact window propagation against CGAL's exact solver, on every mesh
//    of data/ and on crafted hard cases, from vertices, edges and faces.
#include "support/analytic_meshes.h"

#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/compute_geodesic_ridges.h>
#include <Geodesic_ridge/solvers/Exact_solver.h>
#include <Geodesic_ridge/solvers/Dijkstra_solver.h>
#include <Geodesic_ridge/solvers/Fast_marching_solver.h>
#include <Geodesic_ridge/solvers/Heat_method_solver.h>
#include <Geodesic_ridge/solvers/Window_propagation_solver.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <CGAL/convex_hull_3.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace Geodesic_ridge::testing;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index   face_descriptor;

Mesh load(const std::string& name)
{
  Mesh m;
  Geodesic_ridge::IO::read_triangle_mesh(std::string(GEODESIC_RIDGE_DATA_DIR) + "/" + name, m);
  return m;
}

// The convex hull of n random points of the unit sphere: obtuse corners and
// slivers.
Mesh random_sphere_hull(int n, unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  std::vector<Point_3> points;
  for(int i = 0; i < n; ++i)
  {
    const Vector_3 v(normal(random), normal(random), normal(random));
    points.push_back(CGAL::ORIGIN + v / std::sqrt(v.squared_length()));
  }
  Mesh m;
  CGAL::convex_hull_3(points.begin(), points.end(), m);
  return m;
}

template <class Solver, class Source>
std::vector<double> distances_from(const Mesh& m, const Source& s, const Solver& solver)
{
  std::vector<double> d(m.number_of_vertices(), -1);
  solver(m, s, CGAL::make_property_map(d));
  return d;
}

} // namespace

TEST_CASE("fast marching: straight distances on the flat top sheet of a doubly covered square", "[solvers]")
{
  for(double perturbation : {0.0, 0.3})
  {
    const unsigned seed = test_seed(7);
    const Doubly_covered_square sq = make_doubly_covered_square(16, perturbation, seed);
    const vertex_descriptor s = sq.top[5 + (sq.n + 1) * 6];
    INFO("n 16, perturbation " << perturbation << ", seed " << seed);
    const std::vector<double> fmm = distances_from(sq.mesh, s, Geodesic_ridge::Fast_marching_solver());
    // Dijkstra on the edge graph (the tree of stage 1 without a field): the
    // staircase anisotropy that fast marching removes
    const auto rcl = Geodesic_ridge::compute_rough_cut_locus(sq.mesh, s);
    double worst_fmm = 0, worst_dijkstra = 0;
    for(vertex_descriptor v : sq.top)
    {
      const double exact = std::sqrt(CGAL::squared_distance(sq.mesh.point(s), sq.mesh.point(v)));
      worst_fmm = std::max(worst_fmm, std::abs(fmm[v] - exact));
      worst_dijkstra = std::max(worst_dijkstra, std::abs(rcl.distance[v] - exact));
    }
    const double h = mean_edge_length(sq.mesh);
    std::cout << "[solvers] top sheet, n 16, perturbation " << perturbation << ": worst error of fast marching "
              << worst_fmm / h << ", of Dijkstra " << worst_dijkstra / h << " mean edges\n";
    CHECK(fmm[s] == 0);
    // the circular-front update is exact in a flat region with one point
    // source, as long as every update ray crosses its triangle's edge
    if(perturbation == 0) CHECK(worst_fmm <= 1e-9 * h);
    // measured 0.20 on the perturbed grid (edge paths where a ray misses)
    CHECK(worst_fmm <= 0.3 * h);
    CHECK(worst_fmm <= 0.5 * worst_dijkstra);
  }
}

namespace {

struct Relative_errors
{
  double mean = 0, worst = 0, lowest = 0; // (solver - exact) / exact over the vertices but the source
};

template <class Solver>
Relative_errors against_exact(const Mesh& m, vertex_descriptor s, const Solver& solver)
{
  const std::vector<double> d = distances_from(m, s, solver);
  const std::vector<double> exact = distances_from(m, s, Geodesic_ridge::Exact_solver());
  Relative_errors r;
  std::size_t counted = 0;
  for(vertex_descriptor v : m.vertices())
  {
    REQUIRE(std::isfinite(d[v]));
    if(v == s) continue;
    const double rel = (d[v] - exact[v]) / exact[v];
    r.mean += std::abs(rel);
    r.worst = std::max(r.worst, std::abs(rel));
    r.lowest = std::min(r.lowest, rel);
    ++counted;
  }
  r.mean /= counted;
  CHECK(d[s] == 0);
  return r;
}

} // namespace

TEST_CASE("fast marching against the exact solver on real meshes", "[solvers]")
{
  for(const std::string name : {"bunny_1k.off", "torus_1k.off", "eight.off", "knot_3k.off"})
  {
    const Mesh m = load(name);
    const vertex_descriptor s(static_cast<Mesh::size_type>(m.number_of_vertices() / 3));
    const Relative_errors r = against_exact(m, s, Geodesic_ridge::Fast_marching_solver());
    std::cout << "[solvers] fast marching vs exact, " << name << " from " << s << ": mean relative error "
              << r.mean << ", worst " << r.worst << ", lowest " << r.lowest << "\n";
    INFO(name);
    // measured: mean 0.005-0.026, worst 0.015-0.27 (bunny_1k: obtuse
    // triangles, where rays miss and edge paths are taken), lowest -0.02
    CHECK(r.mean < 0.035);
    CHECK(r.worst < 0.35);
    CHECK(r.lowest > -0.05);
  }
}

TEST_CASE("Dijkstra on the edges: an upper bound of the exact distance, exact along a straight edge path", "[solvers]")
{
  for(const std::string name : {"bunny_1k.off", "torus_1k.off", "knot_3k.off"})
  {
    const Mesh m = load(name);
    const vertex_descriptor s(static_cast<Mesh::size_type>(m.number_of_vertices() / 3));
    const Relative_errors r = against_exact(m, s, Geodesic_ridge::Dijkstra_solver());
    std::cout << "[solvers] dijkstra vs exact, " << name << " from " << s << ": mean relative error " << r.mean
              << ", worst " << r.worst << ", lowest " << r.lowest << "\n";
    INFO(name);
    // measured: mean 0.075-0.13, worst 0.18-0.53
    CHECK(r.lowest > -1e-12); // no path along edges is shorter than the geodesic
    CHECK(r.mean < 0.2);
  }
  // the flat square's grid: along a grid line the edge path is the segment,
  // across the diagonal of the cells it is longer by the staircase's excess
  const Doubly_covered_square sq = make_doubly_covered_square(8, 0, 0);
  const std::vector<double> d = distances_from(sq.mesh, sq.top[0], Geodesic_ridge::Dijkstra_solver());
  CHECK(d[sq.top[8]] == Approx(1.0).epsilon(1e-12));
  CHECK(d[sq.top[4 + 9 * 2]] >= std::hypot(0.5, 0.25) - 1e-12);
  // from a point inside a face, its corners start at their straight distances
  const face_descriptor f(3);
  const auto h = sq.mesh.halfedge(f);
  const std::array<double, 3> w = {{0.2, 0.3, 0.5}};
  const std::vector<double> dp =
      distances_from(sq.mesh, std::make_pair(f, w), Geodesic_ridge::Dijkstra_solver());
  const Point_3 p = CGAL::barycenter(sq.mesh.point(sq.mesh.source(h)), w[0], sq.mesh.point(sq.mesh.target(h)), w[1],
                                     sq.mesh.point(sq.mesh.target(sq.mesh.next(h))), w[2]);
  CHECK(dp[sq.mesh.source(h)] == Approx(std::sqrt(CGAL::squared_distance(p, sq.mesh.point(sq.mesh.source(h))))));
}

TEST_CASE("the heat method against the exact solver, direct and on the intrinsic Delaunay triangulation", "[solvers]")
{
  for(const std::string name : {"bunny_1k.off", "torus_1k.off", "knot_3k.off"})
  {
    const Mesh m = load(name);
    const vertex_descriptor s(static_cast<Mesh::size_type>(m.number_of_vertices() / 3));
    const Relative_errors direct = against_exact(m, s, Geodesic_ridge::Heat_method_solver<>());
    const Relative_errors idt = against_exact(m, s, Geodesic_ridge::Heat_method_idt_solver());
    std::cout << "[solvers] heat vs exact, " << name << " from " << s << ": mean relative error " << direct.mean
              << ", worst " << direct.worst << "; heat-idt: " << idt.mean << ", worst " << idt.worst << "\n";
    INFO(name);
    // measured: mean 0.035-0.078, worst 0.21-0.55
    CHECK(direct.mean < 0.1);
    CHECK(idt.mean < 0.1);
  }
  // a point source inside a face is refused (CGAL 5.5: vertex sources only)
  const Mesh m = load("bunny_1k.off");
  std::vector<double> d(m.number_of_vertices());
  CHECK_THROWS_AS(Geodesic_ridge::Heat_method_solver<>()(m, std::make_pair(face_descriptor(0), std::array<double, 3>{{0.2, 0.3, 0.5}}),
                                                         CGAL::make_property_map(d)),
                  Geodesic_ridge::Invalid_source_error);
}

// The convex hull of random points on the unit sphere: a closed mesh with
// obtuse triangles and slivers (the hull of random points has both), where
// the polyhedral distance converges to the great-circle distance. Every
// solver is compared with the great circle, on the vertices farther than 0.3
// from the source (near it the polyhedral error is a larger fraction).
TEST_CASE("every solver against great-circle distances on a sphere with obtuse and sliver triangles", "[solvers]")
{
  const unsigned seed = test_seed(20261203);
  const Mesh m = random_sphere_hull(3000, seed);
  std::size_t obtuse = 0, slivers = 0;
  for(face_descriptor f : m.faces())
  {
    const auto h = m.halfedge(f);
    const Point_3 p[3] = {m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h)))};
    double smallest = 180;
    for(int k = 0; k < 3; ++k)
    {
      const double a = CGAL::approximate_angle(p[(k + 1) % 3], p[k], p[(k + 2) % 3]);
      obtuse += a > 110;
      smallest = std::min(smallest, a);
    }
    slivers += smallest < 10;
  }
  INFO("seed " << seed << ", " << m.number_of_faces() << " faces, " << obtuse << " obtuse (> 110 deg), " << slivers
                << " slivers (< 10 deg)");
  REQUIRE(obtuse > 10);
  REQUIRE(slivers > 10);
  const vertex_descriptor s(0);
  const Vector_3 ps = m.point(s) - CGAL::ORIGIN;
  auto great_circle_error = [&](const std::vector<double>& d) {
    double sum = 0, worst = 0;
    std::size_t n = 0;
    for(vertex_descriptor v : m.vertices())
    {
      const double c = std::max(-1.0, std::min(1.0, ps * (m.point(v) - CGAL::ORIGIN)));
      const double arc = std::acos(c);
      if(arc < 0.3) continue;
      const double rel = std::abs(d[v] - arc) / arc;
      sum += rel;
      worst = std::max(worst, rel);
      ++n;
    }
    return std::make_pair(sum / n, worst);
  };
  const auto exact = great_circle_error(distances_from(m, s, Geodesic_ridge::Exact_solver()));
  const auto fmm = great_circle_error(distances_from(m, s, Geodesic_ridge::Fast_marching_solver()));
  const auto heat = great_circle_error(distances_from(m, s, Geodesic_ridge::Heat_method_solver<>()));
  const auto idt = great_circle_error(distances_from(m, s, Geodesic_ridge::Heat_method_idt_solver()));
  const auto dijkstra = great_circle_error(distances_from(m, s, Geodesic_ridge::Dijkstra_solver()));
  const auto vtp = great_circle_error(distances_from(m, s, Geodesic_ridge::Window_propagation_solver()));
  CHECK(std::abs(vtp.first - exact.first) <= 1e-9);
  CHECK(std::abs(vtp.second - exact.second) <= 1e-9);
  std::cout << "[solvers] sphere, seed " << seed << ", " << m.number_of_faces() << " faces, " << obtuse
            << " obtuse corners, " << slivers << " slivers; mean / worst relative error against the great circle: exact "
            << exact.first << " / " << exact.second << ", fmm " << fmm.first << " / " << fmm.second << ", heat "
            << heat.first << " / " << heat.second << ", heat-idt " << idt.first << " / " << idt.second
            << ", dijkstra " << dijkstra.first << " / " << dijkstra.second << "\n";
  // measured (seed 20261203: 5,996 faces, 1,059 obtuse corners, 398 slivers),
  // mean / worst: exact 0.0010 / 0.0019 (the polyhedron is shorter than the
  // sphere), fmm 0.0030 / 0.015, heat and heat-idt 0.017 / 0.060 (the same:
  // the hull of points on a sphere is Delaunay already), dijkstra 0.056 / 0.16
  CHECK(exact.second < 0.005);
  CHECK(fmm.first < 0.01);
  CHECK(fmm.second < 0.05);
  CHECK(heat.first < 0.04);
  CHECK(idt.first < 0.04);
  CHECK(dijkstra.first < 0.1);
}

TEST_CASE("fast marching from a Face_location and on a mesh with a boundary", "[solvers]")
{
  const Mesh m = load("bunny_1k.off");
  const face_descriptor f(17);
  const std::array<double, 3> b = {{0.2, 0.3, 0.5}};
  const std::vector<double> d = distances_from(m, std::make_pair(f, b), Geodesic_ridge::Fast_marching_solver());
  const auto h = m.halfedge(f);
  const Point_3 p = CGAL::barycenter(m.point(m.source(h)), b[0], m.point(m.target(h)), b[1],
                                     m.point(m.target(m.next(h))), b[2]);
  for(vertex_descriptor c : {m.source(h), m.target(h), m.target(m.next(h))})
    CHECK(d[c] == Approx(std::sqrt(CGAL::squared_distance(p, m.point(c)))).epsilon(1e-12));
  // an extended surface: a mesh with a boundary and cone angles up to 4π at the ends of the cut
  const auto rcl = Geodesic_ridge::compute_rough_cut_locus(m, vertex_descriptor(0));
  const auto E = Geodesic_ridge::build_extended_surface(m, rcl, 3);
  const std::vector<double> dE = distances_from(E.mesh, E.source_vertex, Geodesic_ridge::Fast_marching_solver());
  const std::vector<double> dM = distances_from(m, vertex_descriptor(0), Geodesic_ridge::Exact_solver());
  std::size_t below = 0;
  for(auto v : E.mesh.vertices())
  {
    REQUIRE(std::isfinite(dE[v]));
    // paths in E are paths in M: fast marching's error aside, never much shorter
    if(dE[v] < 0.9 * dM[E.original_vertex[v]] - 1e-9) ++below;
  }
  CHECK(dE[E.source_vertex] == 0);
  CHECK(below == 0);
}

// The exact solver from a point on an edge, against the doubly covered
// square's oracle on the bottom sheet (mirror images): CGAL before 5.6 starts
// no cone towards the ends of a source's edge and came out 0.03 (0.4 mean
// edges) too long here; the solver moves the point into its face by 2^-40.
TEST_CASE("the exact solver from a point on an edge", "[solvers]")
{
  const Doubly_covered_square sq = make_doubly_covered_square(12, 0.25, test_seed(20260301));
  const Mesh& m = sq.mesh;
  const face_descriptor f(40);
  REQUIRE(!sq.bottom_face[f]);
  const auto h = m.halfedge(f);
  const Point_3 p0 = m.point(m.source(h)), p1 = m.point(m.target(h)), p2 = m.point(m.target(m.next(h)));
  for(const std::array<double, 3>& w : {std::array<double, 3>{{0.2, 0.3, 0.5}}, std::array<double, 3>{{0.35, 0.65, 0}},
                                        std::array<double, 3>{{0, 0.35, 0.65}}, std::array<double, 3>{{0.35, 0, 0.65}}})
  {
    INFO("source face 40, barycentric " << w[0] << " " << w[1] << " " << w[2] << ", seed " << sq.seed);
    const Doubly_covered_square_oracle oracle(w[0] * p0.x() + w[1] * p1.x() + w[2] * p2.x(),
                                              w[0] * p0.y() + w[1] * p1.y() + w[2] * p2.y());
    const std::vector<double> d = distances_from(m, std::make_pair(f, w), Geodesic_ridge::Exact_solver());
    double worst = 0;
    for(vertex_descriptor v : m.vertices())
    {
      const bool bottom_only = std::find(sq.top.begin(), sq.top.end(), v) == sq.top.end();
      if(!bottom_only) continue;
      worst = std::max(worst, std::abs(d[v] - oracle.bottom_distance({{m.point(v).x(), m.point(v).y()}})));
    }
    CHECK(worst <= 1e-9);
  }
}

TEST_CASE("pipeline schedules: predicted extension and the tree's distances", "[solvers][ridge_curve]")
{
  namespace p = Geodesic_ridge::parameters;
  for(const std::string name : {"bunny_1k.off", "torus_1k.off", "eight.off"})
  {
    const Mesh m = load(name);
    const long chi = static_cast<long>(m.number_of_vertices()) - static_cast<long>(m.number_of_edges()) +
                     static_cast<long>(m.number_of_faces());
    const std::size_t g = static_cast<std::size_t>((2 - chi) / 2);
    const vertex_descriptor s(static_cast<Mesh::size_type>(m.number_of_vertices() / 2));
    std::size_t faces[2][2] = {{0, 0}, {0, 0}};
    for(int tree_from_solver = 0; tree_from_solver < 2; ++tree_from_solver)
      for(int predicted = 0; predicted < 2; ++predicted)
      {
        INFO(name << " source " << s << ", tree from solver " << tree_from_solver << ", predicted "
                  << predicted);
        const auto rc = Geodesic_ridge::compute_ridge_curve(
            m, s, p::tree_from_solver(tree_from_solver != 0, p::predicted_extension(predicted != 0)));
        const auto& st = rc.statistics;
        CHECK(st.ridge.components == 1);
        CHECK(st.ridge.cycles == 2 * g);
        CHECK(st.tree_from_solver == (tree_from_solver != 0));
        // the solver runs on E, and again on a grown E while copies of its
        // solution still win on E's border, at most maximum_solves times
        CHECK(st.solves >= 1);
        CHECK(st.solves <= Geodesic_ridge::default_maximum_solves);
        if(predicted)
        {
          CHECK(st.predicted_passes >= 1);
          CHECK(st.outer_copies_winning == 0); // E holds every shortest path
        }
        else CHECK(st.predicted_passes == 0);  // every band costs a solve: maximum_solves may stop it
        faces[tree_from_solver][predicted] = st.extended_surface.number_of_faces;
      }
    // the predicted extension grows about as much as the solved one
    for(int t = 0; t < 2; ++t)
    {
      INFO(name << ": E " << faces[t][1] << " faces predicted, " << faces[t][0] << " solved");
      CHECK(double(faces[t][1]) >= 0.8 * double(faces[t][0]));
      CHECK(double(faces[t][1]) <= 1.25 * double(faces[t][0]));
    }
  }
}

TEST_CASE("fast marching resumed on a grown extended surface: kept where nothing changed, as good as from scratch",
          "[solvers][extended_surface]")
{
  // The growth of E with fast marching resumes each pass from the last one's
  // corner distances (internal::fast_marching_resumed). Measured (2026-12-05,
  // E from 0 -> 3 and 2 -> 6 rings): the best copy's mean error against the
  // exact distance on M moves by at most 0.015 mean edges either way (0.09 to
  // 0.49 from scratch), its worst by at most 0.17; hundreds of kept vertices
  // are reopened by fronts that come back lower through the grown copies.
  for(const std::string name : {"bunny_1k.off", "teddy_3k.off", "knot_3k.off"})
  {
    const Mesh m = load(name);
    double mean_edge = 0;
    for(auto e : m.edges()) mean_edge += std::sqrt(CGAL::squared_distance(m.point(m.source(m.halfedge(e))),
                                                                          m.point(m.target(m.halfedge(e)))));
    mean_edge /= double(m.number_of_edges());
    for(int source : {0, 100})
    {
      const vertex_descriptor s(static_cast<Mesh::size_type>(source));
      const auto rcl = Geodesic_ridge::compute_rough_cut_locus(m, s);
      const std::vector<double> exact = distances_from(m, s, Geodesic_ridge::Exact_solver());
      for(const auto& [r1, r2] : {std::pair<int, int>(0, 3), std::pair<int, int>(2, 6), std::pair<int, int>(4, 4)})
      {
        INFO(name << " source " << s << ", E from " << r1 << " to " << r2 << " rings");
        typedef Geodesic_ridge::Extended_surface<Point_3> ES;
        const ES E1 = Geodesic_ridge::build_extended_surface(m, rcl, r1);
        const ES E2 = Geodesic_ridge::build_extended_surface(m, rcl, r2);
        const std::vector<double> d1 = distances_from(E1.mesh, E1.source_vertex, Geodesic_ridge::Fast_marching_solver());
        const std::vector<double> d2 = distances_from(E2.mesh, E2.source_vertex, Geodesic_ridge::Fast_marching_solver());
        // the last pass's corner distances per copy: E1's copies are E2's first ones
        std::vector<std::array<double, 3> > anchor(E1.mesh.number_of_faces());
        for(auto f : E1.mesh.faces())
        {
          auto h = E1.mesh.halfedge(f);
          for(int k = 0; k < 3; ++k, h = E1.mesh.next(h)) anchor[f.idx()][k] = d1[E1.mesh.source(h).idx()];
        }
        std::vector<double> resumed;
        Geodesic_ridge::internal::fast_marching_resumed(E2, anchor, 1e-9 * mean_edge, resumed);
        REQUIRE(resumed.size() == E2.mesh.number_of_vertices());
        CHECK(resumed[E2.source_vertex.idx()] == 0);
        if(r1 == r2)
        {
          CHECK(resumed == d1); // nothing grew: nothing to do
          continue;
        }
        std::size_t reopened = 0;
        for(std::size_t c = 0; c < anchor.size(); ++c)
        {
          auto h = E2.mesh.halfedge(face_descriptor(static_cast<Mesh::size_type>(c)));
          for(int k = 0; k < 3; ++k, h = E2.mesh.next(h))
          {
            const double r = resumed[E2.mesh.source(h).idx()];
            CHECK(r <= anchor[c][k]); // a kept distance only comes down
            reopened += r < anchor[c][k] - 1e-6 * mean_edge;
          }
        }
        CHECK(reopened > 0);
        // the best copy of every vertex of M against the exact distance
        auto error = [&](const std::vector<double>& d) {
          std::vector<double> best(m.number_of_vertices(), std::numeric_limits<double>::infinity());
          for(auto v : E2.mesh.vertices())
          {
            REQUIRE(std::isfinite(d[v.idx()]));
            double& b = best[E2.original_vertex[v.idx()]];
            b = std::min(b, d[v.idx()]);
          }
          double mean = 0, worst = 0;
          for(std::size_t i = 0; i < best.size(); ++i)
          {
            const double e = std::abs(best[i] - exact[i]) / mean_edge;
            mean += e / double(best.size());
            worst = std::max(worst, e);
          }
          return std::make_pair(mean, worst);
        };
        const auto from_scratch = error(d2), from_last = error(resumed);
        std::cout << "[solvers] fast marching on E (" << name << ", v" << source << ", " << r1 << " -> " << r2
                  << " rings), best copy against exact, mean / worst in mean edges: from scratch "
                  << from_scratch.first << " / " << from_scratch.second << ", resumed " << from_last.first << " / "
                  << from_last.second << "\n";
        CHECK(from_last.first <= from_scratch.first + 0.03);
        CHECK(from_last.second <= from_scratch.second + 0.3);
      }
    }
  }
}

// parameters::solver(s).tolerance(0.01), a CGAL user's first try, did not
// compile: only the nested form solver(s, tolerance(0.01)) did.
TEST_CASE("the named parameters chain as CGAL's do, and CGAL's chain after them", "[solvers][parameters]")
{
  namespace p = Geodesic_ridge::parameters;
  const Mesh m = load("torus_1k.off");
  const vertex_descriptor s(0);
  const Geodesic_ridge::Fast_marching_solver fmm;
  const auto chained = Geodesic_ridge::compute_ridge_curve(
      m, s, p::solver(fmm).tolerance(0.01).kink_angle(50).fast_marching_margin(1).vertex_point_map(get(CGAL::vertex_point, m)));
  const auto nested =
      Geodesic_ridge::compute_ridge_curve(m, s, p::solver(fmm, p::tolerance(0.01, p::kink_angle(50, p::fast_marching_margin(1)))));
  const auto plain = Geodesic_ridge::compute_ridge_curve(m, s, p::solver(fmm));
  CHECK(chained.statistics.tolerance == 0.01);
  CHECK(chained.statistics.margin_rings == 1);
  CHECK(plain.statistics.margin_rings == 2);
  CHECK(chained.vertex_distances == nested.vertex_distances);
  CHECK(chained.ridge_polylines().size() == nested.ridge_polylines().size());
  // nested, then chained on; every parameter is read through the chain
  CHECK_THROWS_AS(Geodesic_ridge::compute_ridge_curve(m, s, p::solver(fmm, p::maximum_rings(8)).tolerance(0.7)),
                  Geodesic_ridge::Invalid_parameter_error);
  CHECK_THROWS_AS(Geodesic_ridge::compute_ridge_curve(m, s, p::tolerance(0.01).solver(fmm).fast_marching_margin(-1)),
                  Geodesic_ridge::Invalid_parameter_error);
  CHECK_THROWS_AS(Geodesic_ridge::compute_ridge_curve(m, s, p::tolerance(0.01).cone_ridge_tolerance(0)),
                  Geodesic_ridge::Invalid_parameter_error);
}

TEST_CASE("a user's vertex point map reaches the solvers and every stage", "[solvers][ridge_curve]")
{
  // mesh A's own points are bunny_1k's; the map gives those of B, bunny_1k
  // scaled, turned and moved: on A with the map, everything must be as on B
  Mesh a = load("bunny_1k.off");
  Mesh b = a;
  auto b_point = [](const Point_3& p) { return Point_3(2 * p.y() + 1, -2 * p.x(), 2 * p.z() - 3); };
  for(vertex_descriptor v : b.vertices()) b.point(v) = b_point(a.point(v));
  auto map = a.add_property_map<vertex_descriptor, Point_3>("v:geometry").first;
  for(vertex_descriptor v : a.vertices()) map[v] = b.point(v);
  const vertex_descriptor s(17);
  const auto on_a = CGAL::parameters::vertex_point_map(map);

  std::vector<double> da(a.number_of_vertices()), db(b.number_of_vertices());
  Geodesic_ridge::Exact_solver()(a, s, CGAL::make_property_map(da), on_a);
  Geodesic_ridge::Exact_solver()(b, s, CGAL::make_property_map(db));
  CHECK(da == db);
  Geodesic_ridge::Fast_marching_solver()(a, s, CGAL::make_property_map(da), on_a);
  Geodesic_ridge::Fast_marching_solver()(b, s, CGAL::make_property_map(db));
  CHECK(da == db);
  // (the map is not a no-op: A's own points give other distances)
  std::vector<double> own(a.number_of_vertices());
  Geodesic_ridge::Fast_marching_solver()(a, s, CGAL::make_property_map(own));
  CHECK(own != db);

  for(bool tree_from_solver : {false, true})
  {
    INFO("tree_from_solver " << tree_from_solver);
    const auto ra = Geodesic_ridge::compute_ridge_curve(
        a, s, Geodesic_ridge::parameters::tree_from_solver(tree_from_solver).vertex_point_map(map));
    const auto rb =
        Geodesic_ridge::compute_ridge_curve(b, s, Geodesic_ridge::parameters::tree_from_solver(tree_from_solver));
    CHECK(ra.rough_cut_locus.cut_edges == rb.rough_cut_locus.cut_edges);
    CHECK(ra.vertex_distances == rb.vertex_distances);
    REQUIRE(ra.polylines.size() == rb.polylines.size());
    for(std::size_t i = 0; i < ra.polylines.size(); ++i)
    {
      REQUIRE(ra.polylines[i].size() == rb.polylines[i].size());
      for(std::size_t j = 0; j < ra.polylines[i].size(); ++j) CHECK(ra.polylines[i][j].point == rb.polylines[i][j].point);
    }
  }
}

// ---------------------------------------------------------------------------
// Many sources at once: the batch gives, per source and in order, what a
// single call gives, bit for bit, serially and in parallel (with TBB).

namespace {

template <class Result>
void check_same_ridge(const Result& batch, const Result& single, const std::string& what)
{
  INFO(what);
  CHECK(batch.statistics.solves == single.statistics.solves);
  CHECK(batch.statistics.extended_surface.number_of_faces == single.statistics.extended_surface.number_of_faces);
  CHECK(batch.vertex_distances == single.vertex_distances);
  REQUIRE(batch.polylines.size() == single.polylines.size());
  for(std::size_t i = 0; i < single.polylines.size(); ++i)
  {
    REQUIRE(batch.polylines[i].size() == single.polylines[i].size());
    for(std::size_t j = 0; j < single.polylines[i].size(); ++j)
      CHECK(batch.polylines[i][j].point == single.polylines[i][j].point);
  }
}

} // namespace

TEST_CASE("a batch of sources gives what single calls give, serially and in parallel", "[solvers][batch]")
{
  namespace p = Geodesic_ridge::parameters;
  typedef std::pair<face_descriptor, std::array<double, 3> > Face_location;
#ifdef CGAL_LINKED_WITH_TBB
  std::cout << "[batch] TBB: yes\n";
#else
  std::cout << "[batch] TBB: no (the parallel runs are serial)\n";
#endif
  for(const std::string name : {"bunny_1k.off", "eight.off"})
  {
    const Mesh m = load(name);
    std::vector<vertex_descriptor> vertices;
    for(std::size_t i = 0; i < 9; ++i)
      vertices.push_back(vertex_descriptor(static_cast<Mesh::size_type>(i * m.number_of_vertices() / 9)));
    const auto np = p::solver(Geodesic_ridge::Fast_marching_solver());
    typedef decltype(Geodesic_ridge::compute_ridge_curve(m, vertices[0], np)) Result;
    std::vector<Result> serial, parallel;
    Geodesic_ridge::compute_ridge_curves<CGAL::Sequential_tag>(m, vertices, std::back_inserter(serial), np);
    Geodesic_ridge::compute_ridge_curves<CGAL::Parallel_if_available_tag>(m, vertices, std::back_inserter(parallel), np);
    REQUIRE(serial.size() == vertices.size());
    REQUIRE(parallel.size() == vertices.size());
    for(std::size_t i = 0; i < vertices.size(); ++i)
    {
      const Result single = Geodesic_ridge::compute_ridge_curve(m, vertices[i], np);
      const std::string what = name + " source vertex " + std::to_string(std::size_t(vertices[i]));
      check_same_ridge(serial[i], single, what + " (serial)");
      check_same_ridge(parallel[i], single, what + " (parallel)");
    }
    // Face_locations, the exact solver, and the polylines-only version
    const std::vector<Face_location> points = {{face_descriptor(3), {{0.2, 0.3, 0.5}}},
                                               {face_descriptor(40), {{0.5, 0.5, 0.0}}}};
    std::vector<std::vector<std::vector<Point_3> > > ridges;
    Geodesic_ridge::compute_geodesic_ridges(m, points, std::back_inserter(ridges));
    REQUIRE(ridges.size() == points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      std::vector<std::vector<Point_3> > single;
      Geodesic_ridge::compute_geodesic_ridge(m, points[i], std::back_inserter(single));
      CHECK(ridges[i] == single);
    }
  }
  // a bad source is reported before any work, with the type of a single call's error
  const Mesh m = load("bunny_1k.off");
  std::vector<Face_location> bad = {{face_descriptor(3), {{0.2, 0.3, 0.5}}}, {face_descriptor(5), {{0.7, 0.7, 0.7}}}};
  std::size_t written = 0;
  CHECK_THROWS_AS(Geodesic_ridge::compute_geodesic_ridges(m, bad, boost::make_function_output_iterator([&](const auto&) { ++written; })),
                  Geodesic_ridge::Invalid_source_error);
  CHECK(written == 0);
  CHECK_THROWS_AS(Geodesic_ridge::compute_geodesic_ridges(m, std::vector<vertex_descriptor>{vertex_descriptor(0)},
                                                          boost::make_function_output_iterator([&](const auto&) { ++written; }),
                                                          p::tolerance(0.7)),
                  Geodesic_ridge::Invalid_parameter_error);
  // no sources: nothing written, nothing thrown
  std::vector<std::vector<std::vector<Point_3> > > none;
  Geodesic_ridge::compute_geodesic_ridges(m, std::vector<vertex_descriptor>(), std::back_inserter(none));
  CHECK(none.empty());
}

namespace {

// The window-propagation solver's distances against the exact solver's on
// mesh m, from vertices 0, V/3 and 2V/3, a point inside a face, a point on
// an edge and a Face_location at a vertex (seeded): every vertex within 1e-9
// relative (absolute in mean edges near the source), the same unreachable
// vertices. Returns the worst relative difference.
double check_window_propagation(const Mesh& m, const std::string& what, unsigned seed)
{
  typedef std::pair<face_descriptor, std::array<double, 3> > Location;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.05, 1.0);
  const std::size_t nv = m.number_of_vertices(), nf = m.number_of_faces();
  const face_descriptor f1(static_cast<Mesh::size_type>(random() % nf)), f2(static_cast<Mesh::size_type>(random() % nf));
  const double a = unit(random), b = unit(random), c = unit(random), t = 0.1 + 0.8 * (unit(random) - 0.05) / 0.95;
  const std::vector<Location> points = {{f1, {{a / (a + b + c), b / (a + b + c), c / (a + b + c)}}},
                                        {f2, {{0., t, 1 - t}}},
                                        {f2, {{1., 0., 0.}}}};
  const double h = mean_edge_length(m);
  double worst = 0;
  auto compare = [&](const std::vector<double>& vtp, const std::vector<double>& exact, const std::string& source) {
    INFO(what << ", source " << source << ", seed " << seed);
    std::size_t bad = 0, unreachable = 0;
    for(vertex_descriptor v : m.vertices())
    {
      if(!std::isfinite(exact[v]))
      {
        ++unreachable;
        bad += std::isfinite(vtp[v]);
        continue;
      }
      const double difference = std::abs(vtp[v] - exact[v]) / std::max(exact[v], h);
      worst = std::max(worst, difference);
      bad += !(difference <= 1e-9);
    }
    CHECK(bad == 0);
  };
  for(std::size_t i : {std::size_t(0), nv / 3, 2 * nv / 3})
  {
    const vertex_descriptor s(static_cast<Mesh::size_type>(i));
    compare(distances_from(m, s, Geodesic_ridge::Window_propagation_solver()),
            distances_from(m, s, Geodesic_ridge::Exact_solver()), "vertex " + std::to_string(i));
  }
  const char* kinds[] = {"inside face ", "on an edge of face ", "at a corner of face "};
  for(std::size_t k = 0; k < points.size(); ++k)
    compare(distances_from(m, points[k], Geodesic_ridge::Window_propagation_solver()),
            distances_from(m, points[k], Geodesic_ridge::Exact_solver()),
            kinds[k] + std::to_string(std::size_t(points[k].first)));
  std::cout << "[solvers] vtp against the exact solver, " << what << " (seed " << seed
            << "): worst relative difference " << worst << "\n";
  return worst;
}

} // namespace

TEST_CASE("window propagation gives the exact solver's distances on every mesh of data/", "[solvers][vtp]")
{
  const unsigned seed = test_seed(20261204);
  for(const char* name : {"torus_1k.off", "eight.off", "bunny_1k.off", "knot_3k.off", "teddy_3k.off",
                          "armadillo_2k.off", "3holes_7k.off", "boundary/open_box.off", "boundary/flat_annulus.off"})
    check_window_propagation(load(name), name, seed);
}

TEST_CASE("window propagation on hard cases: holes and pinched vertices, corners, saddles, slivers", "[solvers][vtp]")
{
  const unsigned seed = test_seed(20261205);
  SECTION("a mesh with many holes, some vertices pinched between them")
  {
    Mesh m = load("bunny_1k.off");
    std::vector<face_descriptor> removed;
    for(face_descriptor f : m.faces())
      if(std::size_t(f) % 5 == 3) removed.push_back(f);
    for(face_descriptor f : removed) CGAL::Euler::remove_face(m.halfedge(f), m);
    m.collect_garbage();
    check_window_propagation(m, "bunny_1k without every fifth face", seed);
  }
  SECTION("convex polyhedra: cone corners, flat vertices on faces and edges")
  {
    check_window_propagation(make_subdivided_polyhedron(box_corners_and_faces(1, 2, 3), 5, 0.2, seed).mesh,
                             "box 1 x 2 x 3, n 5, perturbed", seed);
    check_window_propagation(make_subdivided_polyhedron(regular_tetrahedron_corners_and_faces(), 6).mesh,
                             "regular tetrahedron, n 6", seed);
  }
  SECTION("valence-3 vertices: every other face split at a raised or sunk centre")
  {
    Mesh m = load("torus_1k.off");
    std::vector<face_descriptor> split;
    for(face_descriptor f : m.faces())
      if(std::size_t(f) % 2 == 0) split.push_back(f);
    for(face_descriptor f : split)
    {
      const auto h = m.halfedge(f);
      const Point_3 p[3] = {m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h)))};
      const Vector_3 n = CGAL::unit_normal(p[0], p[1], p[2]);
      const double lift = (std::size_t(f) % 4 == 0 ? 0.3 : -0.3) * std::sqrt(CGAL::squared_distance(p[0], p[1]));
      const auto g = CGAL::Euler::add_center_vertex(h, m);
      m.point(m.target(g)) = CGAL::centroid(p[0], p[1], p[2]) + lift * n;
    }
    check_window_propagation(m, "torus_1k with raised and sunk valence-3 centres", seed);
  }
  SECTION("needles and caps: the convex hull of random points on a sphere")
  {
    check_window_propagation(random_sphere_hull(1500, seed), "sphere hull of 1500 random points", seed);
  }
  SECTION("a face with collinear corners is refused")
  {
    Mesh m = load("torus_1k.off");
    const auto h = m.halfedge(face_descriptor(7));
    m.point(m.target(m.next(h))) = m.point(m.source(h)); // exactly collinear
    CHECK_THROWS_AS(distances_from(m, vertex_descriptor(0), Geodesic_ridge::Window_propagation_solver()),
                    Geodesic_ridge::Invalid_mesh_error);
  }
  SECTION("the doubly covered square from a point on an edge: the mirror images")
  {
    const Doubly_covered_square sq = make_doubly_covered_square(12, 0.25, seed);
    const face_descriptor f(40);
    REQUIRE(!sq.bottom_face[f]);
    const auto h = sq.mesh.halfedge(f);
    const Point_3 p0 = sq.mesh.point(sq.mesh.source(h)), p1 = sq.mesh.point(sq.mesh.target(h));
    const std::array<double, 3> w = {{0.35, 0.65, 0.}};
    const Doubly_covered_square_oracle oracle(w[0] * p0.x() + w[1] * p1.x(), w[0] * p0.y() + w[1] * p1.y());
    const std::vector<double> d =
        distances_from(sq.mesh, std::make_pair(f, w), Geodesic_ridge::Window_propagation_solver());
    double worst = 0;
    for(vertex_descriptor v : sq.mesh.vertices())
      if(std::find(sq.top.begin(), sq.top.end(), v) == sq.top.end())
        worst = std::max(worst, std::abs(d[v] - oracle.bottom_distance({{sq.mesh.point(v).x(), sq.mesh.point(v).y()}})));
    INFO("seed " << seed);
    CHECK(worst <= 1e-9);
  }
}

namespace {

// An exact solver as the pipeline sees it without cones (so no kink split,
// no cone ridge): the two exact solvers, compared on distances alone.
template <class Solver>
struct Without_cones
{
  static const char* name() { return Solver::name(); }
  static constexpr bool is_exact = true;
  static constexpr bool has_cones = false;
  template <class... Args>
  void operator()(Args&&... args) const
  {
    Solver()(std::forward<Args>(args)...);
  }
};

} // namespace

TEST_CASE("window propagation drives the pipeline like the exact solver", "[solvers][vtp][ridge_curve]")
{
  namespace p = Geodesic_ridge::parameters;
  // without the kink split (which reads the solvers' cones), the two exact
  // solvers grow the same E and give the same ridge
  static_assert(Geodesic_ridge::Geodesic_solver_traits<Geodesic_ridge::Window_propagation_solver>::is_exact);
  static_assert(Geodesic_ridge::Geodesic_solver_traits<Geodesic_ridge::Window_propagation_solver>::has_cones);
  static_assert(Geodesic_ridge::Geodesic_solver_traits<Geodesic_ridge::Window_propagation_solver>::has_windows);
  static_assert(Geodesic_ridge::Geodesic_solver_traits<Geodesic_ridge::Exact_solver>::has_cones);
  static_assert(!Geodesic_ridge::Geodesic_solver_traits<Geodesic_ridge::Exact_solver>::has_windows);
  for(const char* name : {"torus_1k.off", "bunny_1k.off", "eight.off"})
  {
    const Mesh m = load(name);
    for(vertex_descriptor s : {vertex_descriptor(0), vertex_descriptor(static_cast<Mesh::size_type>(m.number_of_vertices() / 2))})
    {
      INFO(name << " source " << std::size_t(s));
      const auto exact = Geodesic_ridge::compute_ridge_curve(m, s, p::solver(Without_cones<Geodesic_ridge::Exact_solver>()));
      const auto vtp =
          Geodesic_ridge::compute_ridge_curve(m, s, p::solver(Without_cones<Geodesic_ridge::Window_propagation_solver>()));
      CHECK(vtp.statistics.solver == std::string("vtp"));
      CHECK(vtp.statistics.extended_surface.number_of_faces == exact.statistics.extended_surface.number_of_faces);
      CHECK(vtp.statistics.solves == exact.statistics.solves);
      CHECK(vtp.polylines.size() == exact.polylines.size());
      double length_exact = 0, length_vtp = 0;
      for(const auto& pl : exact.polylines)
        for(std::size_t i = 1; i < pl.size(); ++i) length_exact += std::sqrt(CGAL::squared_distance(pl[i - 1].point, pl[i].point));
      for(const auto& pl : vtp.polylines)
        for(std::size_t i = 1; i < pl.size(); ++i) length_vtp += std::sqrt(CGAL::squared_distance(pl[i - 1].point, pl[i].point));
      CHECK(length_vtp == Approx(length_exact).epsilon(1e-6));
    }
  }
  // the cone field needs cones
  const Mesh m = load("torus_1k.off");
  CHECK_THROWS_AS(Geodesic_ridge::compute_ridge_curve(
                      m, vertex_descriptor(0),
                      p::field(Geodesic_ridge::Field::cone,
                               p::solver(Without_cones<Geodesic_ridge::Window_propagation_solver>()))),
                  Geodesic_ridge::Invalid_parameter_error);
}

namespace {

// The two solvers' cones at every sample of every face of m: the largest
// relative difference of their values at the sample, and how many have the
// same apex (within 1e-6).
struct Cone_agreement
{
  double worst = 0;
  std::size_t same_apex = 0, all = 0;
};

Cone_agreement compare_cones(const Mesh& m, const std::vector<Geodesic_ridge::Face_cone>& exact,
                             const std::vector<Geodesic_ridge::Face_cone>& vtp,
                             const std::vector<std::array<double, 3> >& samples)
{
  Cone_agreement r;
  for(auto f : m.faces())
  {
    const auto h = m.halfedge(f);
    const Geodesic_ridge::internal::Face_plane plane(
        std::array<Point_3, 3>{{m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h)))}});
    for(std::size_t j = 0; j < samples.size(); ++j)
    {
      const auto x = plane.point(samples[j]);
      const auto& a = exact[samples.size() * std::size_t(f) + j];
      const auto& b = vtp[samples.size() * std::size_t(f) + j];
      const double da = std::sqrt(CGAL::squared_distance(x, plane.point(a.apex))) + a.offset;
      const double db = std::sqrt(CGAL::squared_distance(x, plane.point(b.apex))) + b.offset;
      r.worst = std::max(r.worst, std::abs(da - db) / da);
      r.same_apex += CGAL::squared_distance(plane.point(a.apex), plane.point(b.apex)) < 1e-12;
      ++r.all;
    }
  }
  return r;
}

} // namespace

TEST_CASE("window propagation gives the cones of the exact solver at the samples", "[solvers][vtp]")
{
  // the cone of a sample is the apex and offset of its shortest path's last
  // straight piece: both solvers' cones give the exact distance there, and
  // the same apex where the sample is not near a boundary between windows
  for(const char* name : {"bunny_1k.off", "torus_1k.off"})
  {
    const Mesh m = load(name);
    const vertex_descriptor s(7);
    std::vector<double> d_exact(m.number_of_vertices()), d_vtp(m.number_of_vertices());
    std::vector<Geodesic_ridge::Face_cone> exact, vtp;
    std::vector<std::vector<Geodesic_ridge::Face_cone> > windows;
    auto every = [](std::size_t) { return true; };
    const auto& samples = Geodesic_ridge::Exact_solver::cone_samples();
    Geodesic_ridge::Exact_solver()(m, s, CGAL::make_property_map(d_exact), exact, every);
    Geodesic_ridge::Window_propagation_solver()(m, s, CGAL::make_property_map(d_vtp), vtp, every, samples, &windows);
    REQUIRE(exact.size() == vtp.size());
    REQUIRE(windows.size() == m.number_of_faces());
    for(auto f : m.faces()) CHECK(!windows[std::size_t(f)].empty());
    const Cone_agreement c = compare_cones(m, exact, vtp, samples);
    INFO(name << ": largest relative difference at the samples " << c.worst << ", same apex " << c.same_apex
              << " of " << c.all);
    CHECK(c.worst <= 1e-9);
    CHECK(c.same_apex >= 0.95 * c.all);
  }
}

TEST_CASE("the exact solver's cones where shortest paths run through vertices along edges", "[solvers][cones]")
{
  // Found by the pipeline fuzzer (fuzz/corpus/pipeline/
  // smsp_first_bend_no_intersection): an octahedron's faces all in z = 0, a
  // closed surface folded flat whose two layers overlap. From vertex 0 the
  // paths of some samples of the extended surface run through a vertex and on
  // along an edge; SMSP's walk past such a crossing failed its assertion
  // `bool(cgalIntersection)` (and read an empty optional with NDEBUG). The
  // walk now stops at the vertex and goes on from it.
  namespace p = Geodesic_ridge::parameters;
  const std::vector<Point_3> points = {Point_3(1, 0, 0),  Point_3(-1, 0, 0),      Point_3(-2, 1, 0),
                                       Point_3(0, -1, 0), Point_3(0, 0.84375, 0), Point_3(0.09375, 0, 0)};
  const std::vector<std::array<std::size_t, 3> > triangles = {{{0, 2, 4}}, {{2, 1, 4}}, {{1, 3, 4}}, {{3, 0, 4}},
                                                              {{2, 0, 5}}, {{1, 2, 5}}, {{3, 1, 5}}, {{0, 3, 5}}};
  Mesh m;
  for(const Point_3& x : points) m.add_vertex(x);
  for(const auto& t : triangles)
    REQUIRE(m.add_face(vertex_descriptor(Mesh::size_type(t[0])), vertex_descriptor(Mesh::size_type(t[1])),
                       vertex_descriptor(Mesh::size_type(t[2]))) != Mesh::null_face());
  for(const Geodesic_ridge::Field field : {Geodesic_ridge::Field::linear, Geodesic_ridge::Field::cone})
  {
    INFO("field " << (field == Geodesic_ridge::Field::cone ? "cone" : "linear"));
    const auto exact = Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(0), p::field(field));
    const auto vtp = Geodesic_ridge::compute_ridge_curve(
        m, vertex_descriptor(0), p::field(field, p::solver(Geodesic_ridge::Window_propagation_solver())));
    for(const auto* r : {&exact, &vtp})
    {
      CHECK(r->statistics.ridge.components == 1);
      CHECK(r->statistics.ridge.cycles == 0);
      CHECK(!r->polylines.empty());
    }
  }
  // on M, every sample's cone (the walks through vertices included) gives
  // the exact distance there, as window propagation's cones do
  std::vector<double> d_exact(m.number_of_vertices()), d_vtp(m.number_of_vertices());
  std::vector<Geodesic_ridge::Face_cone> exact, vtp;
  auto every = [](std::size_t) { return true; };
  const auto& samples = Geodesic_ridge::Exact_solver::cone_samples();
  Geodesic_ridge::Exact_solver()(m, vertex_descriptor(0), CGAL::make_property_map(d_exact), exact, every);
  Geodesic_ridge::Window_propagation_solver()(m, vertex_descriptor(0), CGAL::make_property_map(d_vtp), vtp, every,
                                              samples);
  REQUIRE(exact.size() == vtp.size());
  const Cone_agreement c = compare_cones(m, exact, vtp, samples);
  INFO("largest relative difference at the samples " << c.worst);
  CHECK(c.worst <= 1e-9);
}

// ---------------------------------------------------------------------------
// Invariance (issue 41): every stage computes on the mesh moved and scaled to
// a unit size (internal/normalization.h), by a power of two, so a mesh scaled
// by 2^k has bit for bit the ridge times 2^k.

namespace {

Mesh transformed(const Mesh& m, double scale, int exponent, const Vector_3& move)
{
  Mesh out = m;
  for(auto v : out.vertices())
  {
    const Point_3& p = out.point(v);
    out.point(v) = Point_3(std::ldexp(p.x() * scale, exponent) + move.x(), std::ldexp(p.y() * scale, exponent) + move.y(),
                           std::ldexp(p.z() * scale, exponent) + move.z());
  }
  return out;
}

template <class Solver>
void check_power_of_two_scales(const Mesh& m, const std::string& name, const Solver& solver,
                               const std::vector<int>& exponents)
{
  namespace p = Geodesic_ridge::parameters;
  const auto base = Geodesic_ridge::compute_ridge_curve(m, *m.vertices().begin(), p::solver(solver));
  for(int k : exponents)
  {
    INFO(name << ", solver " << solver.name() << ", scaled by 2^" << k);
    const Mesh scaled = transformed(m, 1, k, Vector_3(0, 0, 0));
    const auto r = Geodesic_ridge::compute_ridge_curve(scaled, *scaled.vertices().begin(), p::solver(solver));
    const auto& a = base.ridge_polylines();
    const auto& b = r.ridge_polylines();
    REQUIRE(a.size() == b.size());
    for(std::size_t i = 0; i < a.size(); ++i)
    {
      REQUIRE(a[i].size() == b[i].size());
      for(std::size_t j = 0; j < a[i].size(); ++j)
      {
        const Point_3& q = a[i][j].point;
        REQUIRE(b[i][j].point == Point_3(std::ldexp(q.x(), k), std::ldexp(q.y(), k), std::ldexp(q.z(), k)));
        REQUIRE(b[i][j].face == a[i][j].face);
        REQUIRE(b[i][j].barycentric == a[i][j].barycentric);
      }
    }
    REQUIRE(b.size() > 0);
    for(std::size_t v = 0; v < base.vertex_distances.size(); ++v)
      REQUIRE(r.vertex_distances[v] == std::ldexp(base.vertex_distances[v], k));
    REQUIRE(r.rough_cut_locus.cut_edges == base.rough_cut_locus.cut_edges);
  }
}

// The largest distance from a point of one ridge's segments (5 per segment)
// to the other ridge, `b`'s points mapped back by `back` first.
template <class Polylines, class Back>
double ridge_distance_mapped(const Polylines& a, const Polylines& b, const Back& back)
{
  std::vector<std::vector<Point_3> > x, y;
  for(const auto& line : a)
  {
    x.emplace_back();
    for(const auto& q : line) x.back().push_back(q.point);
  }
  for(const auto& line : b)
  {
    y.emplace_back();
    for(const auto& q : line) y.back().push_back(back(q.point));
  }
  auto one_way = [](const std::vector<std::vector<Point_3> >& from, const std::vector<std::vector<Point_3> >& to) {
    double worst = 0;
    for(const auto& line : from)
      for(std::size_t i = 0; i + 1 < line.size(); ++i)
        for(int s = 0; s <= 4; ++s)
        {
          const Point_3 p = CGAL::barycenter(line[i], 4 - s, line[i + 1], s);
          double best = std::numeric_limits<double>::infinity();
          for(const auto& other : to)
            for(std::size_t j = 0; j + 1 < other.size(); ++j)
              best = (std::min)(best, std::sqrt(CGAL::squared_distance(p, CGAL::Epick::Segment_3(other[j], other[j + 1]))));
          worst = (std::max)(worst, best);
        }
    return worst;
  };
  return (std::max)(one_way(x, y), one_way(y, x));
}

// The same, `b` mapped back from `scale` and `move`.
template <class Polylines>
double ridge_distance(const Polylines& a, const Polylines& b, double scale, const Vector_3& move)
{
  return ridge_distance_mapped(a, b, [&](const Point_3& q) {
    const Point_3 back = q - move;
    return Point_3(back.x() / scale, back.y() / scale, back.z() / scale);
  });
}

// m with its vertices and faces in a shuffled order (vertex i of m is vertex
// new_index[i]), every face's orientation reversed if `reverse`.
Mesh renumbered(const Mesh& m, unsigned seed, bool reverse, std::vector<vertex_descriptor>& new_index)
{
  std::mt19937 random(seed);
  new_index.assign(m.vertices().begin(), m.vertices().end());
  std::shuffle(new_index.begin(), new_index.end(), random);
  std::vector<vertex_descriptor> old_index(new_index.size());
  for(std::size_t i = 0; i < new_index.size(); ++i) old_index[new_index[i]] = vertex_descriptor(i);
  Mesh out;
  for(vertex_descriptor v : old_index) out.add_vertex(m.point(v));
  std::vector<face_descriptor> faces(m.faces().begin(), m.faces().end());
  std::shuffle(faces.begin(), faces.end(), random);
  for(face_descriptor f : faces)
  {
    std::vector<vertex_descriptor> corners;
    for(vertex_descriptor v : CGAL::vertices_around_face(m.halfedge(f), m)) corners.push_back(new_index[v]);
    if(reverse) std::reverse(corners.begin(), corners.end());
    out.add_face(corners);
  }
  return out;
}

// The rotation by `angle` about the unit vector `axis` (Rodrigues).
CGAL::Aff_transformation_3<CGAL::Epick> rotation_about(const Vector_3& u, double angle)
{
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  return CGAL::Aff_transformation_3<CGAL::Epick>(
      t * u.x() * u.x() + c, t * u.x() * u.y() - s * u.z(), t * u.x() * u.z() + s * u.y(),
      t * u.x() * u.y() + s * u.z(), t * u.y() * u.y() + c, t * u.y() * u.z() - s * u.x(),
      t * u.x() * u.z() - s * u.y(), t * u.y() * u.z() + s * u.x(), t * u.z() * u.z() + c);
}

} // namespace

TEST_CASE("scaled by 2^k, k from -330 to 330, the ridge is the same times 2^k, bit for bit", "[solvers][invariance]")
{
  const unsigned seed = test_seed(20261207);
  INFO("seed " << seed);
  const Mesh octahedron = make_subdivided_polyhedron(regular_octahedron_corners_and_faces(), 4, 0.25, seed).mesh;
  const Mesh bunny = load("bunny_1k.off");
  const std::vector<int> many = {-330, -164, -53, -1, 1, 7, 100, 330}, extremes = {-330, 330};
  check_power_of_two_scales(octahedron, "octahedron", Geodesic_ridge::Exact_solver(), many);
  check_power_of_two_scales(octahedron, "octahedron", Geodesic_ridge::Window_propagation_solver(), many);
  check_power_of_two_scales(octahedron, "octahedron", Geodesic_ridge::Fast_marching_solver(), many);
  check_power_of_two_scales(octahedron, "octahedron", Geodesic_ridge::Dijkstra_solver(), many);
  check_power_of_two_scales(bunny, "bunny_1k", Geodesic_ridge::Exact_solver(), extremes);
  check_power_of_two_scales(bunny, "bunny_1k", Geodesic_ridge::Window_propagation_solver(), extremes);
  check_power_of_two_scales(bunny, "bunny_1k", Geodesic_ridge::Fast_marching_solver(), extremes);
}

TEST_CASE("heat method: scaled by 2^-330 and 2^330, the same ridge bit for bit", "[solvers][invariance][heat]")
{
  const unsigned seed = test_seed(20261207);
  INFO("seed " << seed);
  const Mesh octahedron = make_subdivided_polyhedron(regular_octahedron_corners_and_faces(), 4, 0.25, seed).mesh;
  check_power_of_two_scales(octahedron, "octahedron", Geodesic_ridge::Heat_method_solver(), {-330, 330});
  check_power_of_two_scales(load("bunny_1k.off"), "bunny_1k", Geodesic_ridge::Heat_method_solver(), {-330, 330});
}

// Scales that are no power of two, and a far translation, round every
// coordinate of the input once. Measured (bunny_1k v0): fast marching and
// Dijkstra stay within 1e-9 of the diagonal; the exact solver's and window
// propagation's ridges are not continuous in such a perturbation (a branch of
// a few edges may take the neighbouring faces: 0.075 diagonals at a
// translation of 2e5 diagonals, 0.008 between scales 0.7 and 5), so for them
// only what must hold at any scale is asserted: a ridge, connected, without
// cycles (user manual, Known Limits).
TEST_CASE("scales 1e-300 and 1e300 and a translation by 1e6 diagonals give the ridge of scale 1",
          "[solvers][invariance]")
{
  namespace p = Geodesic_ridge::parameters;
  const Mesh bunny = load("bunny_1k.off");
  const double diagonal = bbox_diagonal(bunny);
  const Vector_3 far(1e6 * diagonal, -0.5e6 * diagonal, 0.25e6 * diagonal);
  const auto fmm = Geodesic_ridge::compute_ridge_curve(bunny, *bunny.vertices().begin(),
                                                       p::solver(Geodesic_ridge::Fast_marching_solver()));
  for(const auto& [scale, move] : {std::make_pair(1e-300, Vector_3(0, 0, 0)), std::make_pair(1e300, Vector_3(0, 0, 0)),
                                   std::make_pair(1.0, far)})
  {
    INFO("bunny_1k scaled by " << scale << ", moved by " << move);
    const Mesh m = transformed(bunny, scale, 0, move);
    const auto r = Geodesic_ridge::compute_ridge_curve(m, *m.vertices().begin(),
                                                       p::solver(Geodesic_ridge::Fast_marching_solver()));
    CHECK(ridge_distance(fmm.ridge_polylines(), r.ridge_polylines(), scale, move) <= 1e-8 * diagonal);
    for(double d : r.vertex_distances) REQUIRE(std::isfinite(d));
    const auto exact = Geodesic_ridge::compute_ridge_curve(m, *m.vertices().begin());
    CHECK(exact.statistics.ridge.components == 1);
    CHECK(exact.statistics.ridge.cycles == 0);
    CHECK(exact.ridge_polylines().size() > 10);
  }
}

// Fast marching, Dijkstra and the heat method read the mesh through its
// geometry only, so the ridge does not depend on the numbering nor on the
// orientation, and is continuous in the rounding of a rotation. Measured
// (bunny_1k, kitten_5k, sources v0 and v n/3, reversed and renumbered): fast
// marching and Dijkstra bit for bit; the heat method within 1e-14 on bunny_1k
// but 0.0015 diagonals on kitten_5k (E grown otherwise after a round-off
// difference, and the heat method's distances depend on E's border). Fast
// marching depended on the orientation until its margin pass ran from scratch
// (0.008 diagonals, 54 polylines against 58). The exact solver and window
// propagation give the same vertex distances (1e-16) but their cone ridges
// differ by 0.017 diagonals renumbered and 0.04 to 0.08 reversed (the cones'
// samples; user manual, Known Limits): not asserted here.
TEST_CASE("reversed, renumbered or rotated, the ridge is the same (fast marching, Dijkstra, heat)",
          "[solvers][invariance]")
{
  namespace p = Geodesic_ridge::parameters;
  const unsigned seed = test_seed(20261208);
  INFO("seed " << seed);
  const Mesh bunny = load("bunny_1k.off");
  const double diagonal = bbox_diagonal(bunny);
  auto check = [&](const auto& solver, bool reverse) {
    std::vector<vertex_descriptor> new_index;
    const Mesh m = renumbered(bunny, seed, reverse, new_index);
    for(const std::size_t source : {std::size_t(0), std::size_t(bunny.number_of_vertices() / 3)})
    {
      INFO("bunny_1k, solver " << solver.name() << (reverse ? ", reversed" : "") << ", renumbered, source v" << source);
      const auto a = Geodesic_ridge::compute_ridge_curve(bunny, vertex_descriptor(source), p::solver(solver));
      const auto b = Geodesic_ridge::compute_ridge_curve(m, new_index[source], p::solver(solver));
      double worst = 0;
      for(vertex_descriptor v : bunny.vertices())
        worst = (std::max)(worst, std::abs(a.vertex_distances[v] - b.vertex_distances[new_index[v]]));
      CHECK(worst <= 1e-9 * diagonal);
      CHECK(a.ridge_polylines().size() == b.ridge_polylines().size());
      CHECK(ridge_distance(a.ridge_polylines(), b.ridge_polylines(), 1.0, Vector_3(0, 0, 0)) <= 1e-9 * diagonal);
    }
  };
  for(bool reverse : {false, true})
  {
    check(Geodesic_ridge::Fast_marching_solver(), reverse);
    check(Geodesic_ridge::Dijkstra_solver(), reverse);
    check(Geodesic_ridge::Heat_method_solver(), reverse);
  }

  // a rotation about a random axis, through a random angle: every coordinate rounded once
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Vector_3 axis(uniform(random), uniform(random), uniform(random));
  axis = axis / std::sqrt(axis.squared_length());
  const double angle = 3.14159 * uniform(random);
  const CGAL::Aff_transformation_3<CGAL::Epick> rotation = rotation_about(axis, angle);
  const CGAL::Aff_transformation_3<CGAL::Epick> back = rotation.inverse();
  Mesh rotated = bunny;
  for(vertex_descriptor v : rotated.vertices()) rotated.point(v) = rotation.transform(bunny.point(v));
  for(const std::string solver : {"fmm", "dijkstra"})
  {
    INFO("bunny_1k rotated by " << angle << " about " << axis << ", solver " << solver);
    const auto a = solver == "fmm" ? Geodesic_ridge::compute_ridge_curve(bunny, vertex_descriptor(0),
                                                                         p::solver(Geodesic_ridge::Fast_marching_solver()))
                                   : Geodesic_ridge::compute_ridge_curve(bunny, vertex_descriptor(0),
                                                                         p::solver(Geodesic_ridge::Dijkstra_solver()));
    const auto b = solver == "fmm" ? Geodesic_ridge::compute_ridge_curve(rotated, vertex_descriptor(0),
                                                                         p::solver(Geodesic_ridge::Fast_marching_solver()))
                                   : Geodesic_ridge::compute_ridge_curve(rotated, vertex_descriptor(0),
                                                                         p::solver(Geodesic_ridge::Dijkstra_solver()));
    double worst = 0;
    for(vertex_descriptor v : bunny.vertices())
      worst = (std::max)(worst, std::abs(a.vertex_distances[v] - b.vertex_distances[v]));
    CHECK(worst <= 1e-9 * diagonal);
    CHECK(a.ridge_polylines().size() == b.ridge_polylines().size());
    CHECK(ridge_distance_mapped(a.ridge_polylines(), b.ridge_polylines(),
                                [&](const Point_3& q) { return back.transform(q); }) <= 1e-9 * diagonal);
  }
}
