// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The ridge curve (stage 3, and the whole pipeline) against analytic oracles
// (user manual, "Analytic Cases"):
//  * doubly covered square: the cut locus of a source on the top sheet is the
//    Voronoi diagram of the source's four mirror images, on the bottom sheet;
//  * convex polyhedra (subdivided box, tetrahedron, octahedron; perturbed in
//    their flat faces): every corner but the source is a leaf of the cut locus;
//  * tori and higher genus: one component with 2g independent cycles;
//  * a sweep of tolerances: connected, 2g cycles, consistent surface locations;
//  * sources given as Face_locations inside a face and on an edge;
//  * every solver (fast marching, heat, Dijkstra, a wrapper of the exact one)
//    on the square, tori and a tolerance sweep.
// Connectivity and cycles are recomputed here from the output polylines, not
// read from the statistics.
#include "support/analytic_meshes.h"
#include "support/written_ridge_topology.h"

#include <Geodesic_ridge/IO/polylines.h>
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/internal/coincident_points.h>
#include <Geodesic_ridge/solvers/Dijkstra_solver.h>
#include <Geodesic_ridge/solvers/Heat_method_solver.h>
#include <Geodesic_ridge/solvers/Window_propagation_solver.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <unistd.h>

namespace {

using namespace Geodesic_ridge::testing;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index   face_descriptor;
typedef std::pair<face_descriptor, std::array<double, 3> > Face_location;
typedef decltype(Geodesic_ridge::compute_ridge_curve(std::declval<const Mesh&>(), vertex_descriptor(0)))
    Result;
typedef Geodesic_ridge::Ridge_point<Point_3> Ridge_point;

Mesh load(const std::string& name)
{
  Mesh m;
  Geodesic_ridge::IO::read_triangle_mesh(std::string(GEODESIC_RIDGE_DATA_DIR) + "/" + name, m);
  return m;
}

int genus(const Mesh& m)
{
  const long chi = static_cast<long>(m.number_of_vertices()) - static_cast<long>(m.number_of_edges()) +
                   static_cast<long>(m.number_of_faces());
  return static_cast<int>((2 - chi) / 2);
}

// Runs the pipeline; an Algorithm_error is reported as a failed check (with
// its message) and gives no result.
template <class Source>
std::optional<Result> run(const Mesh& m, const Source& s, double tol, const std::string& what)
{
  try
  {
    return Geodesic_ridge::compute_ridge_curve(m, s, Geodesic_ridge::parameters::tolerance(tol));
  }
  catch(const Geodesic_ridge::Algorithm_error& e)
  {
    FAIL_CHECK(what << " (tolerance " << tol << "): Algorithm_error: " << e.what());
  }
  return std::nullopt;
}

// The ridge graph as the polylines give it (a node shared by polylines is one
// Ridge_point, copied, so exact comparison identifies it).
struct Ridge_topology
{
  std::size_t nodes = 0, edges = 0, components = 0, cycles = 0, leaves = 0, junctions = 0;
};

Ridge_topology ridge_topology(const std::vector<std::vector<Ridge_point> >& polylines)
{
  // key: the surface location (face, barycentric) and the point, exactly; on
  // the doubly covered square the two sheets share 3D points, so the point
  // alone would not do
  std::map<std::tuple<std::size_t, double, double, double, double, double, double>, std::size_t> id;
  auto node = [&](const Ridge_point& p) {
    return id.emplace(std::make_tuple(p.face, p.barycentric[0], p.barycentric[1], p.barycentric[2], p.point.x(),
                                      p.point.y(), p.point.z()),
                      id.size()).first->second;
  };
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  for(const auto& pl : polylines)
    for(std::size_t i = 0; i + 1 < pl.size(); ++i)
    {
      const std::size_t a = node(pl[i]), b = node(pl[i + 1]);
      if(a != b) edges.emplace_back(a, b);
    }
  Ridge_topology t;
  t.nodes = id.size();
  t.edges = edges.size();
  std::vector<std::size_t> parent(t.nodes), degree(t.nodes, 0);
  for(std::size_t i = 0; i < t.nodes; ++i) parent[i] = i;
  std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
    return parent[x] == x ? x : parent[x] = find(parent[x]);
  };
  for(const auto& e : edges)
  {
    parent[find(e.first)] = find(e.second);
    ++degree[e.first];
    ++degree[e.second];
  }
  for(std::size_t i = 0; i < t.nodes; ++i)
  {
    t.components += find(i) == i;
    t.leaves += degree[i] == 1;
    t.junctions += degree[i] >= 3;
  }
  t.cycles = t.edges + t.components - t.nodes;
  return t;
}

// Largest distance between a ridge point's 3D point and the barycentric
// combination of its face's corners.
double max_location_error(const Mesh& m, const std::vector<std::vector<Ridge_point> >& polylines)
{
  double err = 0;
  for(const auto& pl : polylines)
    for(const auto& p : pl)
    {
      if(p.face >= m.number_of_faces()) return std::numeric_limits<double>::infinity();
      const auto h = m.halfedge(face_descriptor(static_cast<Mesh::size_type>(p.face)));
      const Point_3 a = m.point(m.source(h)), b = m.point(m.target(h)), c = m.point(m.target(m.next(h)));
      const auto& w = p.barycentric;
      if(!(w[0] >= -1e-12 && w[1] >= -1e-12 && w[2] >= -1e-12 && std::abs(w[0] + w[1] + w[2] - 1) <= 1e-9))
        return std::numeric_limits<double>::infinity();
      const Point_3 q(w[0] * a.x() + w[1] * b.x() + w[2] * c.x(), w[0] * a.y() + w[1] * b.y() + w[2] * c.y(),
                      w[0] * a.z() + w[1] * b.z() + w[2] * c.z());
      err = std::max(err, std::sqrt(CGAL::squared_distance(p.point, q)));
    }
  return err;
}

// The checks every ridge must pass: connected (as the polylines say), a tree
// with 2g cycles, and consistent surface locations; the linear field's ridge
// and the one reported (the cone ridge with the exact solver: the same graph).
void check_ridge_validity(const Mesh& m, const Result& rc, const std::string& what)
{
  INFO(what);
  const int g = genus(m);
  for(const auto* polylines : {&rc.polylines, &rc.ridge_polylines()})
  {
    INFO((polylines == &rc.polylines ? "the linear ridge" : "the ridge reported"));
    const Ridge_topology t = ridge_topology(*polylines);
    INFO("ridge: " << t.nodes << " nodes, " << t.edges << " edges, " << t.components << " components, "
                   << t.cycles << " cycles, " << t.leaves << " leaves, " << t.junctions << " junctions");
    CHECK(!polylines->empty());
    CHECK(t.components == 1);
    CHECK(t.cycles == static_cast<std::size_t>(2 * g));
    if(polylines == &rc.polylines) CHECK(rc.statistics.ridge.ridge_segments == t.edges);
    CHECK(max_location_error(m, *polylines) <= 1e-9 * bbox_diagonal(m));
  }
  CHECK(rc.statistics.ridge.components == 1);
  CHECK(rc.statistics.ridge.cycles == static_cast<std::size_t>(2 * g));
}

// Points along the ridge polylines, every `spacing` of length (as the
// accuracy benchmark samples: each part of the ridge weighs by its length,
// not by its number of points).
template <class F>
void for_each_ridge_sample_by_length(const std::vector<std::vector<Ridge_point> >& polylines, double spacing, F f)
{
  for(const auto& pl : polylines)
  {
    double carried = 0; // length since the last sample
    if(!pl.empty()) f(pl.front().point);
    for(std::size_t i = 0; i + 1 < pl.size(); ++i)
    {
      const Point_3& a = pl[i].point;
      const Point_3& b = pl[i + 1].point;
      const double length = std::sqrt(CGAL::squared_distance(a, b));
      double at = spacing - carried;
      for(; at <= length; at += spacing)
      {
        const double t = at / length;
        f(Point_3(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()), a.z() + t * (b.z() - a.z())));
      }
      carried = length - (at - spacing);
    }
  }
}

// Points along the ridge polylines: every vertex and `k` - 1 points inside
// every segment (a segment is straight inside one face).
template <class F>
void for_each_ridge_sample(const std::vector<std::vector<Ridge_point> >& polylines, int k, F f)
{
  for(const auto& pl : polylines)
    for(std::size_t i = 0; i < pl.size(); ++i)
    {
      f(pl[i].point, pl[i].face);
      if(i + 1 == pl.size()) continue;
      for(int j = 1; j < k; ++j)
      {
        const double t = double(j) / k;
        const Point_3& a = pl[i].point; const Point_3& b = pl[i + 1].point;
        // the segment lies in both endpoint faces' closure; pl[i].face or pl[i+1].face holds it
        f(Point_3(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()), a.z() + t * (b.z() - a.z())),
          pl[i + 1].face);
      }
    }
}

double distance_to_ridge(const Point_3& p, const std::vector<std::vector<Ridge_point> >& polylines)
{
  double d2 = std::numeric_limits<double>::infinity();
  for(const auto& pl : polylines)
  {
    if(pl.size() == 1) d2 = std::min(d2, CGAL::squared_distance(p, pl[0].point));
    for(std::size_t i = 0; i + 1 < pl.size(); ++i)
      d2 = std::min(d2, CGAL::squared_distance(p, K::Segment_3(pl[i].point, pl[i + 1].point)));
  }
  return std::sqrt(d2);
}

double percentile(std::vector<double> v, double q)
{
  if(v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5))];
}

// ---------------------------------------------------------------------------

struct Square_measure
{
  double max_error = 0, p95_error = 0;      // ridge -> analytic cut locus, in mean edges
  double max_miss = 0, p95_miss = 0;        // analytic cut locus -> ridge, in mean edges
  double max_miss_inner = 0;                // the same, farther than 2 mean edges from the square's corners
  double covered = 0;                       // fraction of analytic samples within the coverage radius
  double precise = 0;                       // fraction of ridge samples within the precision radius
  std::size_t top_points = 0;               // ridge samples strictly inside the top sheet
  std::array<double, 2> worst_error_at = {{0, 0}}, worst_miss_at = {{0, 0}};
};

// Ridge of a source on the top sheet against the oracle.
Square_measure measure_square(const Doubly_covered_square& sq, const Result& rc, double a, double b,
                              double precision_radius, double coverage_radius)
{
  const double h = mean_edge_length(sq.mesh);
  const Doubly_covered_square_oracle oracle(a, b);
  Square_measure r;
  std::vector<double> err;
  for_each_ridge_sample(rc.ridge_polylines(), 4, [&](const Point_3& p, std::size_t f) {
    const std::array<double, 2> xy = {{p.x(), p.y()}};
    double d = oracle.distance_to_cut_locus(xy);
    const double to_border = std::min(std::min(p.x(), 1 - p.x()), std::min(p.y(), 1 - p.y()));
    if(!sq.bottom_face[f] && to_border > 1e-9)
    {
      // on the top sheet: at least as far (intrinsically) as the border is
      ++r.top_points;
      d = std::max(d, to_border);
    }
    if(err.empty() || d / h > *std::max_element(err.begin(), err.end())) r.worst_error_at = xy;
    err.push_back(d / h);
  });
  r.max_error = err.empty() ? 0 : *std::max_element(err.begin(), err.end());
  r.p95_error = percentile(err, 0.95);
  std::size_t close = 0;
  for(double d : err) close += d <= precision_radius;
  r.precise = err.empty() ? 1 : double(close) / err.size();
  std::vector<double> miss;
  for(const auto& e : oracle.edges)
  {
    const int k = std::max(2, static_cast<int>(std::ceil(e.length() / (0.1 * h))));
    for(int j = 0; j <= k; ++j)
    {
      const double t = double(j) / k;
      const Point_3 p(e.a[0] + t * (e.b[0] - e.a[0]), e.a[1] + t * (e.b[1] - e.a[1]), 0);
      const double d = distance_to_ridge(p, rc.ridge_polylines()) / h;
      if(miss.empty() || d > *std::max_element(miss.begin(), miss.end())) r.worst_miss_at = {{p.x(), p.y()}};
      const double to_corner = std::min(std::min(std::hypot(p.x(), p.y()), std::hypot(1 - p.x(), p.y())),
                                        std::min(std::hypot(p.x(), 1 - p.y()), std::hypot(1 - p.x(), 1 - p.y())));
      if(to_corner > 2 * h) r.max_miss_inner = std::max(r.max_miss_inner, d);
      miss.push_back(d);
    }
  }
  r.max_miss = miss.empty() ? 0 : *std::max_element(miss.begin(), miss.end());
  r.p95_miss = percentile(miss, 0.95);
  std::size_t in = 0;
  for(double d : miss) in += d <= coverage_radius;
  r.covered = miss.empty() ? 1 : double(in) / miss.size();
  return r;
}

} // namespace

// Doubly covered square, source at interior vertices of the top sheet (away
// from the symmetric positions x = 1/2, y = 1/2, where the two junctions of
// the Voronoi diagram merge). Precision: every ridge sample (polyline points
// and 3 points inside each segment) within 0.25 mean edges of the analytic
// cut locus (a sample inside the top sheet counts with at least its distance
// to the border). Coverage: the analytic Voronoi edges sampled every 0.1 mean
// edges, each sample within 0.5 mean edges of the computed ridge (3D distance
// to its segments; both sheets lie in z = 0, and top-sheet segments are
// already charged by the precision check).
// Measured (2026-12-01, with the branch curvature and the leaves at corners of
// stage 1): ridge -> analytic max 0.01-0.02 mean edges over the 32 cases,
// analytic -> ridge max 0.00-0.02; before them 0.8-3.1 and 0.5-2.5.
TEST_CASE("doubly covered square: the ridge is the Voronoi diagram of the mirror images", "[ridge_curve]")
{
  struct Case { int n; double perturbation; unsigned seed; };
#ifdef GEODESIC_RIDGE_SANITIZE
  const std::vector<Case> cases = {{12, 0, 0}, {12, 0.25, 20260101}};
  const std::vector<double> tolerances = {0.025};
#else
  const std::vector<Case> cases = {{10, 0, 0}, {16, 0, 0}, {12, 0.25, 20260101}, {16, 0.25, 20260102}};
  const std::vector<double> tolerances = {0.01, 0.025};
#endif
  const double precision_radius = 0.25, coverage_radius = 0.5; // in mean edge lengths
  for(const Case& c : cases)
  {
    const unsigned seed = test_seed(c.seed);
    const Doubly_covered_square sq = make_doubly_covered_square(c.n, c.perturbation, seed);
    const int n = c.n;
    const std::vector<std::array<int, 2> > grid_sources = {
        {{n / 4, n / 3}}, {{n / 2 + 1, n / 4}}, {{n / 3, 2 * n / 3 + 1}}, {{3 * n / 4, 3 * n / 4 - 1}}};
    for(double tol : tolerances)
      for(const auto& gs : grid_sources)
      {
        const vertex_descriptor s = sq.top[gs[0] + (n + 1) * gs[1]];
        const double a = sq.mesh.point(s).x(), b = sq.mesh.point(s).y();
        std::ostringstream what;
        what << "doubly covered square n=" << n << " perturbation=" << c.perturbation << " seed=" << seed
             << " tolerance=" << tol << " source vertex " << s << " (" << a << ", " << b << ")";
        INFO(what.str());
        const auto rc = run(sq.mesh, s, tol, what.str());
        if(!rc) continue;
        check_ridge_validity(sq.mesh, *rc, what.str());
        const Square_measure r = measure_square(sq, *rc, a, b, precision_radius, coverage_radius);
        const auto& st = rc->statistics.ridge;
        std::ostringstream measured;
        measured << "ridge->analytic max " << r.max_error << " at (" << r.worst_error_at[0] << ", "
                 << r.worst_error_at[1] << ") p95 " << r.p95_error << " within " << precision_radius << ": "
                 << r.precise << " | analytic->ridge max " << r.max_miss << " at (" << r.worst_miss_at[0] << ", "
                 << r.worst_miss_at[1] << "), " << r.max_miss_inner << " away from the corners, p95 "
                 << r.p95_miss << " within " << coverage_radius << ": " << r.covered << " | top-sheet samples "
                 << r.top_points << " | junctions " << st.junctions << " free ends " << st.free_ends
                 << " regions " << st.regions_before_merge << " dropped " << st.dropped_components;
        INFO(measured.str());
        std::cout << "[ridge_curve] " << what.str() << ": " << measured.str() << "\n";
        CHECK(r.top_points == 0);
        CHECK(r.max_error <= precision_radius);
        CHECK(r.max_miss <= coverage_radius);
      }
  }
}

// Convex polyhedra: every corner other than the source is a leaf of the cut
// locus, so the ridge must come near it: within 1.25 of the corner's longest
// edge (3D distance from the corner to the ridge segments; the box's faces are
// not square), at a small and at the default tolerance. The ridge is a tree.
// Measured (2026-12-01): farthest corner 0-1.0 of its longest edge over the 36
// runs (before the branch curvature and the leaves at corners: up to 5.9 mean
// edges).
TEST_CASE("convex polyhedra: the ridge reaches every corner", "[ridge_curve]")
{
  struct Case { std::string name; Polyhedron_description p; int n; double perturbation; unsigned seed; };
#ifdef GEODESIC_RIDGE_SANITIZE
  // (the cube as in the optimised build: with n = 6 the sanitizer's build,
  // whose rounding differs, ended the ridge from vertex 146 at the default
  // tolerance one diagonal (1.41 edges) short of corner (0, 1, 1) since weak
  // ends at flat vertices are pruned; the optimised build reaches it, 2026-12-06)
  const std::vector<Case> cases = {{"cube", box_corners_and_faces(), 8, 0, 0},
                                   {"tetrahedron", regular_tetrahedron_corners_and_faces(), 8, 0.25, 20260201}};
#else
  const std::vector<Case> cases = {
      {"cube", box_corners_and_faces(), 8, 0, 0},
      {"cube (perturbed)", box_corners_and_faces(), 8, 0.25, 20260201},
      {"box 2x1x0.7 (perturbed)", box_corners_and_faces(2, 1, 0.7), 8, 0.25, 20260202},
      {"tetrahedron", regular_tetrahedron_corners_and_faces(), 12, 0, 0},
      {"tetrahedron (perturbed)", regular_tetrahedron_corners_and_faces(), 12, 0.25, 20260203},
      {"octahedron (perturbed)", regular_octahedron_corners_and_faces(), 8, 0.25, 20260204}};
#endif
  const std::vector<double> tolerances = {0.005, Geodesic_ridge::default_tolerance};
  const double corner_radius = 1.25; // of the corner's longest edge
  for(const Case& c : cases)
  {
    const unsigned seed = test_seed(c.seed);
    const Subdivided_polyhedron poly = make_subdivided_polyhedron(c.p, c.n, c.perturbation, seed);
    const Mesh& m = poly.mesh;
    const double h = mean_edge_length(m);
    // sources: a corner, and two vertices inside faces
    const std::size_t nv = m.number_of_vertices();
    std::vector<vertex_descriptor> sources = {poly.corner_vertices[0]};
    for(std::size_t k : {nv / 3, (2 * nv) / 3 + 1})
    {
      vertex_descriptor v(static_cast<Mesh::size_type>(k));
      while(std::find(poly.corner_vertices.begin(), poly.corner_vertices.end(), v) != poly.corner_vertices.end())
        v = vertex_descriptor(static_cast<Mesh::size_type>((std::size_t(v) + 1) % nv));
      sources.push_back(v);
    }
    for(double tol : tolerances)
    for(vertex_descriptor s : sources)
    {
      std::ostringstream what;
      what << c.name << " n=" << c.n << " (" << m.number_of_faces() << " faces) perturbation=" << c.perturbation
           << " seed=" << seed << " tolerance=" << tol << " source vertex " << s << " (" << m.point(s) << ")";
      INFO(what.str());
      const auto rc = run(m, s, tol, what.str());
      if(!rc) continue;
      check_ridge_validity(m, *rc, what.str());
      double worst = 0;
      for(vertex_descriptor corner : poly.corner_vertices)
      {
        if(corner == s) continue;
        // in the corner's own edge length (the box's faces are not square)
        double local = 0;
        for(auto hc : CGAL::halfedges_around_target(corner, m))
          local = std::max(local, std::sqrt(CGAL::squared_distance(m.point(m.source(hc)), m.point(corner))));
        const double d = distance_to_ridge(m.point(corner), rc->ridge_polylines()) / local;
        worst = std::max(worst, d);
        INFO("corner " << corner << " (" << m.point(corner) << "): distance to the ridge " << d
                       << " of its longest edge (" << d * local / h << " mean edges)");
        CHECK(d <= corner_radius);
      }
      const auto& st = rc->statistics.ridge;
      std::cout << "[ridge_curve] " << what.str() << ": farthest corner " << worst << " (of the corner's longest edge); free ends "
                << st.free_ends << " (corners " << poly.corner_vertices.size() << ") junctions " << st.junctions
                << " regions " << st.regions_before_merge << " dropped " << st.dropped_components << "\n";
    }
  }
}

// The free ends of the ridge: the polylines' end points that end one polyline
// only (a node shared by polylines is one Ridge_point, copied, so its 3D point
// identifies it exactly).
std::vector<const Ridge_point*> free_ends(const std::vector<std::vector<Ridge_point> >& polylines)
{
  std::vector<const Ridge_point*> end_points, result;
  for(const auto& pl : polylines)
    if(!pl.empty()) { end_points.push_back(&pl.front()); end_points.push_back(&pl.back()); }
  std::map<std::array<double, 3>, int> ends;
  for(const Ridge_point* p : end_points) ++ends[{{p->point.x(), p->point.y(), p->point.z()}}];
  for(const Ridge_point* p : end_points)
    if(ends[{{p->point.x(), p->point.y(), p->point.z()}}] == 1) result.push_back(p);
  return result;
}

// A free end of the cut locus of a convex polyhedron is a corner, and the two
// fronts meet there at about its angle deficit (90 degrees on a box). A weak
// end near a corner is kept by the spur pruning (the corner rule) only with a
// jump of at least a third of the spur angle: the box's faces (flat, a CAD
// model's kind) made spurs near its corners with jumps of 0.6-4.6 degrees from
// these three sources, all kept before that floor (2026-12-06; fandisk's
// corners likewise).
TEST_CASE("convex polyhedra: no weak spur near a corner", "[ridge_curve]")
{
  const unsigned seed = test_seed(20260202);
  const Subdivided_polyhedron poly = make_subdivided_polyhedron(box_corners_and_faces(2, 1, 0.7), 8, 0.25, seed);
  const Mesh& m = poly.mesh;
  const double h = mean_edge_length(m);
  const double floor_angle = Geodesic_ridge::default_minimum_spur_angle / 3;
  for(std::size_t k : {128, 192, 256})
  {
    const vertex_descriptor s(static_cast<Mesh::size_type>(k));
    std::ostringstream what;
    what << "box 2x1x0.7 n=8 (" << m.number_of_faces() << " faces) perturbation=0.25 seed=" << seed
         << " source vertex " << s;
    INFO(what.str());
    const auto rc = run(m, s, Geodesic_ridge::default_tolerance, what.str());
    if(!rc) continue;
    const std::vector<const Ridge_point*> ends = free_ends(rc->ridge_polylines());
    std::size_t weak_off_corner = 0;
    for(const Ridge_point* p : ends)
    {
      double to_corner = std::numeric_limits<double>::infinity();
      for(vertex_descriptor c : poly.corner_vertices)
        to_corner = std::min(to_corner, std::sqrt(CGAL::squared_distance(p->point, m.point(c))) / h);
      INFO("free end " << p->point << " in face " << p->face << ": jump " << p->angle << " degrees, "
                       << to_corner << " mean edges from the nearest corner");
      if(to_corner > 0.5 && p->angle < floor_angle) ++weak_off_corner;
      CHECK(!(to_corner > 0.5 && p->angle < floor_angle));
    }
    std::cout << "[ridge_curve] " << what.str() << ": free ends " << ends.size() << " (corners 8), weak ends off the corners "
              << weak_off_corner << "\n";
  }
}

// The cut locus ends only at vertices of positive curvature. A weak free end
// (jump below the spur angle) exactly at an inner vertex whose curvature is
// not positive (a saddle, or a flat vertex of a CAD face) is a false branch
// or one that ran past its end: the spur pruning removes it and the weak
// chain behind it, even near a corner. The code of 2026-12-06 (before this
// rule) left 1-3 such ends from each of these sources of the box of fans and
// 1-5 from bunny_1k's.
TEST_CASE("spurs: no weak free end at a vertex without positive curvature", "[ridge_curve]")
{
  const Subdivided_polyhedron fans = make_fan_box(2, 1, 0.7, 4);
  const std::vector<std::pair<std::string, Mesh> > meshes = {{"box of fans 2x1x0.7 n=4", fans.mesh},
                                                            {"bunny_1k.off", load("bunny_1k.off")}};
  for(const auto& [name, m] : meshes)
  {
    // the curvature of the vertices, from the pipeline's own angle sums
    const auto angles = Geodesic_ridge::internal::corner_angles(m, m.points(), get(CGAL::vertex_index, m),
                                                                get(CGAL::face_index, m));
    const std::size_t nv = m.number_of_vertices();
    for(std::size_t k : {std::size_t(0), nv / 4, nv / 2, (3 * nv) / 4})
    {
      const vertex_descriptor s(static_cast<Mesh::size_type>(k));
      std::ostringstream what;
      what << name << " (" << m.number_of_faces() << " faces) source vertex " << s;
      INFO(what.str());
      const auto rc = run(m, s, Geodesic_ridge::default_tolerance, what.str());
      if(!rc) continue;
      const std::vector<const Ridge_point*> ends = free_ends(rc->ridge_polylines());
      std::size_t at_vertices = 0;
      for(const Ridge_point* p : ends)
      {
        Mesh::Halfedge_index h = m.halfedge(face_descriptor(static_cast<Mesh::size_type>(p->face)));
        for(int i = 0; i < 3; ++i, h = m.next(h))
          if(p->barycentric[i] == 1.0)
          {
            ++at_vertices;
            const vertex_descriptor v = m.source(h);
            if(m.is_border(v)) continue; // (a border vertex ends the ridge on the border)
            const double curvature = angles.curvature(std::size_t(v));
            INFO("free end at vertex " << v << " (" << p->point << "): jump " << p->angle << " degrees, curvature "
                                       << curvature * 180 / CGAL_PI << " degrees");
            CHECK(!(p->angle < Geodesic_ridge::default_minimum_spur_angle && curvature <= 1e-9));
          }
      }
      std::cout << "[ridge_curve] " << what.str() << ": free ends " << ends.size() << ", at vertices " << at_vertices << "\n";
    }
  }
}

// Genus g: one component and 2g independent cycles, from several sources.
TEST_CASE("tori and higher genus: one component with 2g cycles", "[ridge_curve]")
{
#ifdef GEODESIC_RIDGE_SANITIZE
  const std::vector<std::string> names = {"torus_1k.off", "eight.off"};
#else
  const std::vector<std::string> names = {"torus_1k.off", "knot_3k.off", "eight.off", "3holes_7k.off"};
#endif
  for(const std::string& name : names)
  {
    const Mesh m = load(name);
    const std::size_t nv = m.number_of_vertices();
    const int g = genus(m);
    std::vector<std::size_t> sources = {0, nv / 2};
    if(name != "3holes_7k.off") sources.push_back((3 * nv) / 4 + 1);
    for(std::size_t s : sources)
    {
      std::ostringstream what;
      what << name << " (genus " << g << ") source vertex " << s;
      INFO(what.str());
      const auto t0 = std::chrono::steady_clock::now();
      const auto rc = run(m, vertex_descriptor(static_cast<Mesh::size_type>(s)), Geodesic_ridge::default_tolerance,
                          what.str());
      if(!rc) continue;
      check_ridge_validity(m, *rc, what.str());
      std::cout << "[ridge_curve] " << what.str() << ": " << rc->statistics.ridge.cycles << " cycles, "
                << rc->statistics.ridge.junctions << " junctions, "
                << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
    }
  }
}

// Tolerance sweep: connected, 2g cycles, and surface locations that reproduce
// the 3D points, at every tolerance.
TEST_CASE("tolerance sweep: connected ridge with 2g cycles", "[ridge_curve]")
{
#ifdef GEODESIC_RIDGE_SANITIZE
  const std::vector<std::string> names = {"bunny_1k.off", "torus_1k.off"};
  const std::vector<double> tolerances = {0.005, 0.05, 0.2};
#else
  const std::vector<std::string> names = {"bunny_1k.off", "torus_1k.off", "eight.off", "3holes_7k.off"};
  const std::vector<double> tolerances = {0.005, 0.01, 0.025, 0.05, 0.1, 0.2};
#endif
  for(const std::string& name : names)
  {
    const Mesh m = load(name);
    const vertex_descriptor s(static_cast<Mesh::size_type>(m.number_of_vertices() / 3));
    for(double tol : tolerances)
    {
      std::ostringstream what;
      what << name << " source vertex " << s << " tolerance " << tol;
      INFO(what.str());
      const auto t0 = std::chrono::steady_clock::now();
      const auto rc = run(m, s, tol, what.str());
      if(!rc) continue;
      check_ridge_validity(m, *rc, what.str());
      std::cout << "[ridge_curve] " << what.str() << ": " << rc->statistics.ridge.ridge_segments << " segments, "
                << rc->statistics.ridge.cycles << " cycles, "
                << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
    }
  }
}

// The ridge as the surface sees it (issue 38): written as a user writes it
// (`IO::write_polylines`, a file), read back with no code of the pipeline
// (test/support/written_ridge_topology.h: points within 1e-12 of the
// diagonal are one, border points joined to their loop), it is connected with
// cycle rank 2g + b, for both ridges and the solvers exact, vtp and fmm. Before
// one node per surface point (internal/coincident_points.h), 13 of 96 runs
// of these meshes (sources i V / 8) had 1 to 3 cycles read back that the
// library's graph did not have: one point computed from two faces, or an
// envelope edge ending 1e-12 from a vertex, written twice with different
// rounding (armadillo_2k v216, v324, v540; teddy_3k v599, v1198 below).
TEST_CASE("the written ridge, read back as geometry, is connected with 2g + b cycles", "[ridge_curve][topology]")
{
  namespace p = Geodesic_ridge::parameters;
  namespace fs = std::filesystem;
#ifdef GEODESIC_RIDGE_SANITIZE
  const std::vector<std::string> names = {"armadillo_2k.off", "torus_1k.off", "boundary/open_box.off"};
  const std::vector<std::size_t> eighths = {2, 5};
#else
  const std::vector<std::string> names = {"bunny_1k.off",  "armadillo_2k.off", "teddy_3k.off",
                                          "torus_1k.off",  "eight.off",        "knot_3k.off",
                                          "3holes_7k.off", "boundary/open_box.off", "boundary/flat_annulus.off"};
  const std::vector<std::size_t> eighths = {2, 3, 5, 6};
#endif
  const fs::path file = fs::temp_directory_path() / ("geodesic_ridge_topology_" + std::to_string(::getpid()) + ".txt");
  std::size_t runs = 0, merged = 0;
  for(const std::string& name : names)
  {
    const Mesh m = load(name);
    for(std::size_t i : eighths)
    {
      const vertex_descriptor s(static_cast<Mesh::size_type>(i * m.number_of_vertices() / 8));
      auto check = [&](const std::vector<std::vector<Ridge_point> >& ridge, const std::string& what) {
        INFO(name << " source vertex " << std::size_t(s) << ", " << what);
        std::vector<std::vector<Point_3> > points;
        Geodesic_ridge::ridge_polyline_points(ridge, std::back_inserter(points));
        Geodesic_ridge::IO::write_polylines(file.string(), points);
        const Written_ridge_topology t = written_ridge_topology(m, file.string());
        INFO(t.points << " points (" << t.merged_points << " merged), " << t.segments << " segments, "
                      << t.components << " components, " << t.cycles << " cycles, genus " << t.genus << ", "
                      << t.border_loops << " border loops");
        CHECK(t.components == 1);
        CHECK(t.cycles == t.expected_cycles());
        ++runs;
        merged += t.merged_points;
      };
      const Result exact = Geodesic_ridge::compute_ridge_curve(m, s);
      check(exact.polylines, "exact, linear ridge");
      check(exact.ridge_polylines(), "exact, cone ridge");
      check(Geodesic_ridge::compute_ridge_curve(m, s, p::solver(Geodesic_ridge::Window_propagation_solver())).ridge_polylines(),
            "vtp");
      check(Geodesic_ridge::compute_ridge_curve(m, s, p::solver(Geodesic_ridge::Fast_marching_solver())).ridge_polylines(),
            "fmm");
    }
  }
  fs::remove(file);
  std::cout << "[ridge_curve] written ridges read back: " << runs << " runs, " << merged
            << " written points merged with another (a point that ends two polylines is written twice)\n";
}

// One surface point, one node, at the rounding stage 3 meets: a junction at a
// vertex of high valence, where fronts meet at small angles, came back as
// three points 1.6e-10 to 4.1e-10 of the diagonal apart (the teapot's pole,
// 40 faces, with caps from v160: a cycle of the ridge that the topology has
// not, `bench_ridge_accuracy --repair --caps 0.2`); points a hundredth of a
// mean edge apart on the finest mesh measured (mean edge 1e-4 diagonals) stay
// two. The teapot's three points, around its pole at the origin:
TEST_CASE("coincident points: a junction computed three times near a vertex is one node", "[ridge_curve][topology]")
{
  using Geodesic_ridge::internal::Coincident_points;
  const CGAL::Bbox_3 box(-2.0, 0.0, -2.0, 2.0, 2.498438, 2.0); // the teapot's box (diagonal 6.18)
  Coincident_points points(Geodesic_ridge::internal::coincident_tolerance(box));
  const std::array<std::array<double, 3>, 3> junction = {{{{0.0, 0.0, 0.0}},
                                                           {{-1.741623300336791e-09, 1.4024602243928447e-11, -1.8083291391363459e-09}},
                                                           {{-1.2559422745318416e-09, 8.693426156286319e-12, -9.217190093536783e-10}}}};
  points.insert(0, junction[0]);
  CHECK(points.find(junction[1]) == 0);
  CHECK(points.find(junction[2]) == 0);
  const double diagonal = std::sqrt(box.x_span() * box.x_span() + box.y_span() * box.y_span() + box.z_span() * box.z_span());
  CHECK(points.find({{1e-6 * diagonal, 0.0, 0.0}}) == Coincident_points::none);
}

// Sources given as Face_locations: inside a face and on an edge. On the doubly
// covered square the oracle applies to any top-sheet point, so the ridge is
// also compared with the analytic cut locus (same radii as above).
// Measured (2026-12-01): max 0.01-0.02 mean edges either way. Sources on an
// edge were 0.7 off before the exact solver worked around CGAL 5.5's edge
// sources (see solvers/Exact_solver.h).
TEST_CASE("Face_location sources inside a face and on an edge", "[ridge_curve]")
{
  const std::vector<std::array<double, 3> > barycentrics = {{{0.2, 0.3, 0.5}}, {{0.35, 0.65, 0.0}}};
  {
    const Mesh m = load("torus_1k.off");
    for(std::size_t f : {std::size_t(17), std::size_t(600)})
      for(const auto& w : barycentrics)
      {
        const Face_location loc(face_descriptor(static_cast<Mesh::size_type>(f)), w);
        std::ostringstream what;
        what << "torus_1k.off source face " << f << " barycentric (" << w[0] << ", " << w[1] << ", " << w[2] << ")";
        INFO(what.str());
        const auto rc = run(m, loc, Geodesic_ridge::default_tolerance, what.str());
        if(rc) check_ridge_validity(m, *rc, what.str());
      }
  }
  {
    const Doubly_covered_square sq = make_doubly_covered_square(12, 0.25, test_seed(20260301));
    for(std::size_t f : {std::size_t(40), std::size_t(150)})
      for(const auto& w : barycentrics)
      {
        REQUIRE(!sq.bottom_face[f]);
        const face_descriptor fd(static_cast<Mesh::size_type>(f));
        const auto h = sq.mesh.halfedge(fd);
        const Point_3 p0 = sq.mesh.point(sq.mesh.source(h)), p1 = sq.mesh.point(sq.mesh.target(h)),
                      p2 = sq.mesh.point(sq.mesh.target(sq.mesh.next(h)));
        const double a = w[0] * p0.x() + w[1] * p1.x() + w[2] * p2.x(), b = w[0] * p0.y() + w[1] * p1.y() + w[2] * p2.y();
        std::ostringstream what;
        what << "doubly covered square n=12 perturbation=0.25 seed=" << sq.seed << " source face " << f
             << " barycentric (" << w[0] << ", " << w[1] << ", " << w[2] << ") = (" << a << ", " << b << ")";
        INFO(what.str());
        const auto rc = run(sq.mesh, Face_location(fd, w), Geodesic_ridge::default_tolerance, what.str());
        if(!rc) continue;
        check_ridge_validity(sq.mesh, *rc, what.str());
        const Square_measure r = measure_square(sq, *rc, a, b, 0.25, 0.5);
        std::cout << "[ridge_curve] " << what.str() << ": ridge->analytic max " << r.max_error << " p95 "
                  << r.p95_error << " | analytic->ridge max " << r.max_miss << " p95 " << r.p95_miss
                  << " within 0.5: " << r.covered << " | top-sheet samples " << r.top_points << "\n";
        CHECK(r.max_error <= 0.25);
        CHECK(r.max_miss <= 0.5);
      }
  }
}

// A ridge that runs exactly along mesh edges: the doubly covered square's grid
// has its cells split along x + y = 1 in the top-left quadrant, and a source on
// that line puts one Voronoi edge of the mirror images (-a, b) and (a, 2 - b)
// on those edges. Both fronts agree on every such edge (it is the ridge), so
// only their gradients tell them apart; an earlier version compared values
// along the edge and lost the whole branch (10.8 mean edges off).
TEST_CASE("a ridge along mesh edges is found", "[ridge_curve]")
{
  const int n = 16;
  const Doubly_covered_square sq = make_doubly_covered_square(n, 0, 0);
  const vertex_descriptor s = sq.top[5 + (n + 1) * 11]; // (0.3125, 0.6875): a + b = 1
  const double a = sq.mesh.point(s).x(), b = sq.mesh.point(s).y();
  REQUIRE(a + b == 1.0);
  const auto rc = run(sq.mesh, s, Geodesic_ridge::default_tolerance, "square n=16, source on x + y = 1");
  REQUIRE(rc);
  check_ridge_validity(sq.mesh, *rc, "square n=16, source on x + y = 1");
  const double h = mean_edge_length(sq.mesh);
  // the analytic branches on x + y = 1, from the Voronoi junctions towards the
  // corners (0, 1) and (1, 0), but for their last 4 mean edges (the tolerance
  // prunes K there)
  const Doubly_covered_square_oracle oracle(a, b);
  double worst = 0;
  std::size_t samples = 0;
  for(const auto& e : oracle.edges)
  {
    if(std::abs(e.a[0] + e.a[1] - 1) > 1e-9 || std::abs(e.b[0] + e.b[1] - 1) > 1e-9) continue;
    const int k = static_cast<int>(std::ceil(e.length() / (0.1 * h)));
    for(int j = 0; j <= k; ++j)
    {
      const double t = double(j) / k;
      const Point_3 p(e.a[0] + t * (e.b[0] - e.a[0]), e.a[1] + t * (e.b[1] - e.a[1]), 0);
      if(std::hypot(p.x(), 1 - p.y()) < 4 * h || std::hypot(1 - p.x(), p.y()) < 4 * h) continue;
      worst = std::max(worst, distance_to_ridge(p, rc->ridge_polylines()) / h);
      ++samples;
    }
  }
  INFO("samples " << samples << ", farthest from the ridge " << worst << " mean edges");
  std::cout << "[ridge_curve] ridge along mesh edges: " << samples << " samples of x + y = 1, farthest "
            << worst << " mean edges from the ridge\n";
  REQUIRE(samples > 50);
  CHECK(worst <= 0.5);
}

// The optional schedules (the tree from the solver's distances, every pass a
// solve) keep every guarantee (valid E, no refused gluing, connected ridge
// with 2g cycles); bad values are typed errors.
TEST_CASE("the optional schedules keep the ridge's guarantees", "[ridge_curve]")
{
  namespace p = Geodesic_ridge::parameters;
  for(const std::string name : {"bunny_1k.off", "torus_1k.off", "eight.off"})
  {
    const Mesh m = load(name);
    for(double tol : {0.01, Geodesic_ridge::default_tolerance})
      for(int variant = 0; variant < 2; ++variant)
      {
        const vertex_descriptor s(static_cast<Mesh::size_type>(m.number_of_vertices() / 2));
        std::ostringstream what;
        what << name << " source " << s << " tolerance " << tol << " variant " << variant
             << " (0 tree from solver, 1 every pass a solve)";
        INFO(what.str());
        std::optional<Result> rc;
        try
        {
          rc = Geodesic_ridge::compute_ridge_curve(
              m, s, p::tolerance(tol, p::tree_from_solver(variant == 0, p::predicted_extension(variant != 1))));
        }
        catch(const Geodesic_ridge::Algorithm_error& e)
        {
          FAIL_CHECK(what.str() << ": Algorithm_error: " << e.what());
        }
        if(!rc) continue;
        check_ridge_validity(m, *rc, what.str());
        const auto& es = rc->statistics.extended_surface;
        CHECK(es.refused_gluings + es.refused_faces == 0);
        CHECK(!rc->statistics.ring_cap_hit);
        std::cout << "[ridge_curve] " << what.str() << ": E/F " << double(es.number_of_faces) / m.number_of_faces()
                  << ", rings " << es.rings << ", solves " << rc->statistics.solves << "\n";
      }
  }
  const Mesh m = load("torus_1k.off");
  REQUIRE_THROWS_AS(Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(0), p::maximum_solves(0)),
                    Geodesic_ridge::Invalid_parameter_error);
  for(double bad : {-0.1, 721.0, std::nan("")})
    REQUIRE_THROWS_AS(Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(0), p::leaf_curvature(bad)),
                      Geodesic_ridge::Invalid_parameter_error);
}

// The ridge reported (`Ridge_curve::ridge_polylines()`, the output of
// `compute_geodesic_ridge()`): with the exact solver the cone ridge, traced
// from the linear field's ridge with its topology; the linear field's with
// `cone_ridge(false)` and with a solver without cones; the corner fallback
// (default) works with either. Asking for the cone ridge without cones is an
// error before any work.
TEST_CASE("the ridge reported: the cone ridge with the exact solver, else the linear field's", "[ridge_curve]")
{
  namespace p = Geodesic_ridge::parameters;
  for(const std::string name : {"bunny_1k.off", "torus_1k.off"})
  {
    const Mesh m = load(name);
    const vertex_descriptor s(0);
    INFO(name << " source 0");
    const Result cone = Geodesic_ridge::compute_ridge_curve(m, s);
    REQUIRE(cone.statistics.cone_ridge_traced);
    CHECK_FALSE(cone.statistics.cone_ridge.kept_linear_ridge);
    CHECK(&cone.ridge_polylines() == &cone.cone_polylines);
    CHECK(cone.cone_polylines.size() == cone.polylines.size()); // same topology
    // bunny_1k from vertex 0 has kinks inside one sheet, the torus none (there
    // the cones are not read and the cone ridge is the linear one)
    if(name == "bunny_1k.off") CHECK(cone.statistics.cone_ridge.points_moved > 0);
    CHECK(cone.cones.empty()); // kept for the cone field only
    check_ridge_validity(m, cone, name + " (cone ridge)");
    std::vector<std::vector<Point_3> > out;
    Geodesic_ridge::compute_geodesic_ridge(m, s, std::back_inserter(out));
    REQUIRE(out.size() == cone.cone_polylines.size());
    for(std::size_t i = 0; i < out.size(); ++i)
    {
      REQUIRE(out[i].size() == cone.cone_polylines[i].size());
      for(std::size_t j = 0; j < out[i].size(); ++j) CHECK(out[i][j] == cone.cone_polylines[i][j].point);
    }
    auto check_linear = [&](const Result& rc, const std::string& what) {
      INFO(what);
      CHECK_FALSE(rc.statistics.cone_ridge_traced);
      CHECK(&rc.ridge_polylines() == &rc.polylines);
      CHECK(rc.cone_polylines.empty());
      CHECK(rc.statistics.ridge.components == 1);
    };
    check_linear(Geodesic_ridge::compute_ridge_curve(m, s, p::cone_ridge(false)), "cone_ridge(false)");
    check_linear(Geodesic_ridge::compute_ridge_curve(m, s, p::cone_ridge(false, p::corner_fallback(true))),
                 "cone_ridge(false), corner_fallback(true)");
    const Result without_fallback = Geodesic_ridge::compute_ridge_curve(m, s, p::corner_fallback(false));
    CHECK(without_fallback.statistics.cone_ridge_traced);
    check_ridge_validity(m, without_fallback, name + " (cone ridge, no corner fallback)");
    check_linear(Geodesic_ridge::compute_ridge_curve(m, s, p::solver(Geodesic_ridge::Fast_marching_solver())),
                 "fast marching");
  }
  const Mesh m = load("torus_1k.off");
  CHECK_THROWS_AS(Geodesic_ridge::compute_ridge_curve(
                      m, vertex_descriptor(0), p::cone_ridge(true, p::solver(Geodesic_ridge::Fast_marching_solver()))),
                  Geodesic_ridge::Invalid_parameter_error);
  CHECK_THROWS_AS(Geodesic_ridge::compute_ridge_curve(
                      m, vertex_descriptor(0), p::cone_ridge(false, p::field(Geodesic_ridge::Field::cone))),
                  Geodesic_ridge::Invalid_parameter_error);
}

// A copy whose corners are reached by different fronts inside one sheet (a
// branch the cut graph lacks) is split into one copy per front by the cones of
// its samples (Kink_splitter); the split copies keep the copy's distances at
// the corners. The kinks' effect on real meshes (recall) is measured by the
// accuracy tests (test_ridge_accuracy.cpp).
TEST_CASE("a copy is split at a kink between its corners' fronts", "[ridge_curve]")
{
  Mesh m;
  const auto v0 = m.add_vertex(Point_3(0, 0, 0)), v1 = m.add_vertex(Point_3(1, 0, 0)), v2 = m.add_vertex(Point_3(0, 1, 0));
  m.add_face(v0, v1, v2);
  std::array<Point_3, 3> corner;
  {
    auto h = m.halfedge(*m.faces().begin());
    for(int k = 0; k < 3; ++k, h = m.next(h)) corner[k] = m.point(m.source(h));
  }
  // barycentric coordinates of a point of the plane z = 0 (signed areas)
  auto barycentric = [&](double x, double y) {
    typedef K::Point_2 P2;
    auto flat = [](const Point_3& p) { return P2(p.x(), p.y()); };
    const P2 q(x, y), a = flat(corner[0]), b = flat(corner[1]), c = flat(corner[2]);
    const double whole = CGAL::area(a, b, c);
    return std::array<double, 3>{{CGAL::area(q, b, c) / whole, CGAL::area(a, q, c) / whole, CGAL::area(a, b, q) / whole}};
  };
  auto distance_to = [&](int k, double x, double y) {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(corner[k], Point_3(x, y, 0))));
  };
  const auto& samples = Geodesic_ridge::Exact_solver::corner_fallback_samples();
  // fronts from the left (apex (-2, 0)) and from above (apex (0, 3)): they
  // arrive at the centroid 91 degrees apart; a third front from (-2, 0.3) is
  // the first one's neighbour (5 degrees)
  struct Front { double x, y; };
  // front_of_sample[k]: the front of the first sample of corner k (sample k);
  // the fallback sample of corner k (sample 3 + k) has the corner's own front
  auto run = [&](const std::array<Front, 3>& front_of_corner, std::array<Front, 3> front_of_sample) {
    REQUIRE(samples.size() == 6);
    std::vector<Geodesic_ridge::internal::Face_copies> copies(1);
    std::vector<Geodesic_ridge::Face_cone> cones(samples.size());
    std::array<double, 3> d;
    for(int k = 0; k < 3; ++k)
    {
      d[k] = distance_to(k, front_of_corner[k].x, front_of_corner[k].y);
      cones[k].apex = barycentric(front_of_sample[k].x, front_of_sample[k].y);
      cones[k].offset = 0;
      cones[3 + k].apex = barycentric(front_of_corner[k].x, front_of_corner[k].y);
      cones[3 + k].offset = 0;
    }
    copies[0].copies = {0};
    copies[0].fields = {d};
    std::size_t split = 0;
    // E: the triangle itself, one copy
    Geodesic_ridge::Extended_surface<Point_3> E;
    E.mesh = m;
    E.original_face = {0};
    E.original_vertex = {0, 1, 2};
    const Geodesic_ridge::internal::Kink_splitter<Mesh, decltype(get(CGAL::vertex_point, m)),
                                                  decltype(get(CGAL::face_index, m)), Point_3>
        splitter(m, get(CGAL::vertex_point, m), get(CGAL::face_index, m), E, cones, samples, 60.0, 1.0, true);
    const auto out = splitter(copies, split);
    REQUIRE(out.size() == 1);
    REQUIRE(out[0].copies.size() == out[0].fields.size());
    REQUIRE(out[0].split.size() == out[0].fields.size());
    for(char x : out[0].split) CHECK(bool(x) == (split > 0));
    for(std::size_t c : out[0].copies) CHECK(c == 0);
    // the split copies keep the copy's distances at the corners
    for(int k = 0; k < 3; ++k)
    {
      double lowest = std::numeric_limits<double>::infinity();
      for(const auto& f : out[0].fields) { CHECK(f[k] >= d[k]); lowest = std::min(lowest, f[k]); }
      CHECK(lowest == d[k]);
    }
    return std::make_pair(out[0], split);
  };
  const Front left{-2, 0}, above{0, 3}, left_too{-2, 0.3};
  {
    // the corner (0, 1) is reached from above, the two others from the left
    std::array<Front, 3> fronts;
    int top = 0;
    for(int k = 0; k < 3; ++k)
    {
      fronts[k] = corner[k].y() == 1 ? above : left;
      if(corner[k].y() == 1) top = k;
    }
    // each front's field is its cone at the corners it does not reach
    auto check_fields = [&](const Geodesic_ridge::internal::Face_copies& out) {
      REQUIRE(out.fields.size() == 2);
      const std::size_t from_left = out.fields[0][top] > out.fields[1][top] ? 0 : 1;
      for(int k = 0; k < 3; ++k)
      {
        CHECK(out.fields[from_left][k] == Approx(distance_to(k, left.x, left.y)));
        CHECK(out.fields[1 - from_left][k] == Approx(distance_to(k, above.x, above.y)));
      }
    };
    {
      const auto [out, split] = run(fronts, fronts);
      CHECK(split == 1);
      check_fields(out);
    }
    {
      // the kink passes between the top corner and its first sample: that
      // sample has the front from the left, which is not exact at the corner;
      // the corner's fallback sample gives its front
      const auto [out, split] = run(fronts, {{left, left, left}});
      CHECK(split == 1);
      check_fields(out);
    }
    {
      // a fallback front whose cone lies below the copy's distance at another
      // corner (3 from the left at (1, 0), 2.06 from (0.5, 2)) is extended
      // beyond its window there: no ridge, no split (they arrive 104 degrees
      // apart at the centroid)
      const Front near_top{0.5, 2};
      std::array<Front, 3> shadowed = fronts;
      shadowed[top] = near_top;
      const auto [out, split] = run(shadowed, {{left, left, left}});
      CHECK(split == 0);
      CHECK(out.fields.size() == 1);
    }
  }
  {
    const auto [out, split] = run({{left, left, left}}, {{left, left, left}}); // one front
    CHECK(split == 0);
    CHECK(out.fields.size() == 1);
  }
  {
    // two fronts, 5 degrees apart: no kink
    const auto [out, split] = run({{left, left_too, left}}, {{left, left_too, left}});
    CHECK(split == 0);
    CHECK(out.fields.size() == 1);
  }
}

// ---------------------------------------------------------------------------
// Surfaces with a border (user manual, "Surfaces with a Border").

// `name` with the faces within `radius` (times the bounding box diagonal) of
// the vertices `centres` removed: one more border loop per centre (where the
// holes stay apart).
Mesh with_holes(const std::string& name, const std::vector<std::size_t>& centres, double radius)
{
  Mesh m = load(name);
  std::vector<Point_3> c;
  for(std::size_t v : centres) c.push_back(m.point(vertex_descriptor(static_cast<Mesh::size_type>(v))));
  const double r = radius * bbox_diagonal(m);
  std::vector<face_descriptor> doomed;
  for(face_descriptor f : m.faces())
  {
    double nearest = std::numeric_limits<double>::infinity();
    for(vertex_descriptor v : CGAL::vertices_around_face(m.halfedge(f), m))
      for(const Point_3& q : c) nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(m.point(v), q)));
    if(nearest <= r) doomed.push_back(f);
  }
  for(face_descriptor f : doomed) CGAL::Euler::remove_face(m.halfedge(f), m);
  m.collect_garbage();
  return m;
}

// The ridge with the border, from the polylines alone: each border loop one
// node, joined to the ridge nodes that lie on it (by their Face_location);
// components and cycle rank, the loops counted as the cycles they are.
std::pair<std::size_t, std::size_t> ridge_with_border_topology(const Mesh& m,
                                                                const std::vector<std::vector<Ridge_point> >& polylines)
{
  std::vector<std::size_t> parent(m.number_of_vertices());
  for(std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  std::function<std::size_t(std::size_t)> find = [&](std::size_t x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
  std::vector<char> on_border(m.number_of_vertices(), 0);
  for(auto h : m.halfedges())
    if(m.is_border(h))
    {
      on_border[m.source(h)] = on_border[m.target(h)] = 1;
      parent[find(m.source(h))] = find(m.target(h));
    }
  std::map<std::size_t, std::size_t> loop; // root vertex -> loop index
  for(std::size_t v = 0; v < on_border.size(); ++v) if(on_border[v]) loop.emplace(find(v), loop.size());
  // the loop a ridge point lies on, or none
  auto loop_of = [&](const Ridge_point& p) -> std::size_t {
    auto h = m.halfedge(face_descriptor(static_cast<Mesh::size_type>(p.face)));
    std::array<Mesh::Halfedge_index, 3> hs = {{h, m.next(h), m.next(m.next(h))}};
    for(int k = 0; k < 3; ++k)
    {
      const bool at_vertex = p.barycentric[k] == 1;
      const bool on_edge = p.barycentric[(k + 2) % 3] == 0 && m.is_border(m.opposite(hs[k]));
      if((at_vertex && on_border[m.source(hs[k])]) || on_edge) return loop.at(find(m.source(hs[k])));
    }
    return std::size_t(-1);
  };
  // nodes: the loops, then the ridge points (keyed as in `ridge_topology`)
  std::map<std::tuple<std::size_t, double, double, double, double, double, double>, std::size_t> id;
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  auto node = [&](const Ridge_point& p) {
    const auto [it, added] = id.emplace(std::make_tuple(p.face, p.barycentric[0], p.barycentric[1], p.barycentric[2],
                                                        p.point.x(), p.point.y(), p.point.z()),
                                        loop.size() + id.size());
    if(added && loop_of(p) != std::size_t(-1)) edges.emplace_back(it->second, loop_of(p));
    return it->second;
  };
  for(const auto& pl : polylines)
    for(std::size_t i = 0; i + 1 < pl.size(); ++i)
    {
      const std::size_t a = node(pl[i]), b = node(pl[i + 1]);
      if(a != b) edges.emplace_back(a, b);
    }
  const std::size_t nodes = loop.size() + id.size();
  std::vector<std::size_t> up(nodes);
  for(std::size_t i = 0; i < nodes; ++i) up[i] = i;
  std::function<std::size_t(std::size_t)> root = [&](std::size_t x) { return up[x] == x ? x : up[x] = root(up[x]); };
  std::size_t joins = 0;
  for(const auto& [a, b] : edges) if(root(a) != root(b)) { up[root(a)] = root(b); ++joins; }
  const std::size_t components = nodes - joins;
  return {components, edges.size() + components - nodes + loop.size()};
}

TEST_CASE("surfaces with a border: the ridge with the border is connected, with cycle rank 2g + b", "[ridge_curve][border]")
{
  namespace p = Geodesic_ridge::parameters;
  struct Case { std::string name; std::size_t centre; double radius; int genus; };
  for(const Case& c : {Case{"bunny_1k.off", 300, 0.02, 0}, Case{"torus_1k.off", 10, 0.08, 1}, Case{"eight.off", 100, 0.05, 2}})
  {
    const Mesh m = with_holes(c.name, {c.centre}, c.radius);
    REQUIRE(CGAL::is_valid_polygon_mesh(m));
    // sources: an inner vertex, a border vertex, the middle of a border edge
    Mesh::Halfedge_index border;
    for(auto h : m.halfedges()) if(m.is_border(h)) { border = m.opposite(h); break; }
    const face_descriptor bf = m.face(border);
    std::array<double, 3> mid = {{0, 0, 0}};
    int k = 0;
    for(auto h = m.halfedge(bf); h != border; h = m.next(h)) ++k;
    mid[k] = mid[(k + 1) % 3] = 0.5;
    for(const std::string solver : {"exact", "fmm"})
      for(int s = 0; s < 3; ++s)
      {
        const std::string what = c.name + " with a hole, " + solver + ", source " +
                                 (s == 0 ? "vertex 0" : s == 1 ? "a border vertex" : "a border edge's middle");
        INFO(what);
        auto run = [&](const auto& solver_model) {
          const auto np = p::solver(solver_model);
          if(s == 0) return Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(0), np);
          if(s == 1) return Geodesic_ridge::compute_ridge_curve(m, m.source(border), np);
          return Geodesic_ridge::compute_ridge_curve(m, Face_location(bf, mid), np);
        };
        const Result rc = solver == "exact" ? run(Geodesic_ridge::Exact_solver()) : run(Geodesic_ridge::Fast_marching_solver());
        const auto& rs = rc.rough_cut_locus.statistics;
        CHECK(rs.genus == c.genus);
        CHECK(rs.number_of_boundary_loops == 1);
        CHECK(rs.cut_cycle_rank == static_cast<std::size_t>(2 * c.genus + 1));
        const auto [components, cycles] = ridge_with_border_topology(m, rc.ridge_polylines());
        CHECK(components == 1);
        CHECK(cycles == static_cast<std::size_t>(2 * c.genus + 1));
        CHECK(rc.statistics.ridge.components == 1);
        CHECK(rc.statistics.ridge.cycles == static_cast<std::size_t>(2 * c.genus + 1));
        CHECK(rc.statistics.extended_surface.refused_faces + rc.statistics.extended_surface.refused_gluings == 0);
        CHECK(max_location_error(m, rc.ridge_polylines()) <= 1e-9 * bbox_diagonal(m));
        std::cout << "[ridge_curve] " << what << ": " << rc.statistics.ridge.ridge_segments << " segments, E/F "
                  << double(rc.statistics.extended_surface.number_of_faces) / m.number_of_faces() << "\n";
      }
  }
}

// Several border loops: where two fronts meet at a small angle, or where a
// front of a copy split at a kink continues a glued copy (their fields differ
// by round-off, so the two faces' envelopes cross their common edge at points
// a hair apart), stage 3 unites them as one front and draws no segment; the
// ridge then hung from each loop in a piece of its own (M minus the ridge and
// the border an annulus). armadillo_2k with two holes (radius 0.04 of the
// diagonal around vertices 300 and 800): 4 of 171 sources (every fifth
// vertex) failed the topology check before the pieces were joined
// (join_border_components); bench_ridge_accuracy measured joined ridges at
// precision p95 0.19-0.26 mean edges, as the others'. Since one node per
// surface point (issue 38: those points a hair apart are one node, and an
// edge piece between them joins no regions) none of these sources needs the
// join any more (0 of 7, 2026-12-06); the pass stays for the cases it was
// not measured on, and this test for the topology.
TEST_CASE("surfaces with several border loops: the pieces hanging from different loops are joined", "[slow][ridge_curve][border]")
{
  const Mesh m = with_holes("armadillo_2k.off", {300, 800}, 0.04);
  REQUIRE(CGAL::is_valid_polygon_mesh(m));
  std::size_t joined_sources = 0, sources = 0;
  // 15, 125, 310 and 545 failed; 0, 100 and 400 did not (the linear ridge:
  // with the cone ridge's splits, none of these needs the join)
  for(std::size_t v : {0, 15, 100, 125, 310, 400, 545})
    for(const bool cone_ridge : {false, true})
    {
      INFO("armadillo_2k with two holes, source vertex " << v << (cone_ridge ? ", cone ridge" : ", linear ridge"));
      const Result rc = Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(static_cast<Mesh::size_type>(v)),
                                                            Geodesic_ridge::parameters::cone_ridge(cone_ridge));
      REQUIRE(rc.rough_cut_locus.statistics.number_of_boundary_loops == 2);
      const auto [components, cycles] = ridge_with_border_topology(m, rc.ridge_polylines());
      CHECK(components == 1);
      CHECK(cycles == 2);
      CHECK(max_location_error(m, rc.ridge_polylines()) <= 1e-9 * bbox_diagonal(m));
      if(cone_ridge) continue;
      joined_sources += rc.statistics.ridge.border_joining_segments > 0;
      ++sources;
    }
  std::cout << "[ridge_curve] armadillo_2k with two holes: " << joined_sources << " of " << sources
            << " sources needed their pieces joined\n";
}

// The analytic cases with a border (test/support/analytic_meshes.h): flat
// simply connected domains have no ridge; the flat annulus's ridge is the arc
// behind the hole; the open box's, from the bottom centre, its four vertical
// edges; every case has the ridge with the border connected, of rank 2g + b.
TEST_CASE("surfaces with a border: analytic cases", "[ridge_curve][border]")
{
  namespace p = Geodesic_ridge::parameters;
  const unsigned seed = test_seed(20261202);
  auto compute = [](const Mesh& m, vertex_descriptor s, bool exact) {
    return exact ? Geodesic_ridge::compute_ridge_curve(m, s)
                 : Geodesic_ridge::compute_ridge_curve(m, s, p::solver(Geodesic_ridge::Fast_marching_solver()));
  };
  auto check_topology = [](const Surface_with_boundary& c, const Result& rc) {
    CHECK(rc.rough_cut_locus.statistics.number_of_boundary_loops == std::size_t(c.boundary_loops));
    CHECK(rc.rough_cut_locus.statistics.genus == c.genus);
    CHECK(rc.statistics.ridge.components == 1);
    CHECK(rc.statistics.ridge.cycles == std::size_t(c.cycle_rank()));
    if(rc.ridge_polylines().empty()) return; // flat and simply connected: no ridge
    const auto [components, cycles] = ridge_with_border_topology(c.mesh, rc.ridge_polylines());
    CHECK(components == 1);
    CHECK(cycles == std::size_t(c.cycle_rank()));
  };
  const Flat_square square = make_flat_square(10, 0.2, seed);
  const Flat_L_domain ell = make_flat_L_domain(8, 0.2, seed);
  const Half_cylinder half = make_half_cylinder(12, 1, 2, 0.2, seed);
  for(const Surface_with_boundary* c : {static_cast<const Surface_with_boundary*>(&square),
                                        static_cast<const Surface_with_boundary*>(&ell),
                                        static_cast<const Surface_with_boundary*>(&half)})
    for(vertex_descriptor s : {vertex_descriptor(static_cast<Mesh::size_type>(c->mesh.number_of_vertices() / 2)),
                               border_vertices(c->mesh).front()})
      for(bool exact : {true, false})
      {
        INFO(c->name << " seed " << seed << " source " << s << (exact ? " exact" : " fmm"));
        const Result rc = compute(c->mesh, s, exact);
        check_topology(*c, rc);
        CHECK(rc.rough_cut_locus.cut_edges.empty());
        double length = 0;
        for(const auto& pl : rc.ridge_polylines())
          for(std::size_t i = 0; i + 1 < pl.size(); ++i) length += std::sqrt(CGAL::squared_distance(pl[i].point, pl[i + 1].point));
        std::cout << "[ridge_curve] " << c->name << " source " << s << (exact ? " exact" : " fmm") << ": ridge length "
                  << length / mean_edge_length(c->mesh) << " mean edges (the exact ridge is empty)\n";
        if(exact) CHECK(rc.ridge_polylines().empty());
      }

  // A slit in the border (issue 38): paths bend around its end, whose linear
  // fields jump by 66 degrees across the edges there; that was a one-edge
  // ridge from 9 of 60 sources. The exact ridge is empty from every source.
  {
    const Flat_slit_square slit = make_flat_slit_square(16, 0.002);
#ifdef GEODESIC_RIDGE_SANITIZE
    const std::size_t step = 23;
#else
    const std::size_t step = 5;
#endif
    std::size_t nonempty = 0, runs = 0;
    for(std::size_t v = 0; v < slit.mesh.number_of_vertices(); v += step)
      for(const std::string solver : {"exact", "vtp"})
      {
        INFO(slit.name << " source " << v << " " << solver);
        const vertex_descriptor s(static_cast<Mesh::size_type>(v));
        const Result rc = solver == "exact" ? Geodesic_ridge::compute_ridge_curve(slit.mesh, s)
                                            : Geodesic_ridge::compute_ridge_curve(
                                                  slit.mesh, s, p::solver(Geodesic_ridge::Window_propagation_solver()));
        check_topology(slit, rc);
        CHECK(rc.ridge_polylines().empty());
        nonempty += !rc.ridge_polylines().empty();
        ++runs;
      }
    std::cout << "[ridge_curve] flat square with a slit: " << nonempty << " of " << runs << " ridges not empty\n";
  }

  const Flat_annulus annulus = make_flat_annulus(24, 1, 3, 0.2, seed);
  const double h = mean_edge_length(annulus.mesh);
  for(vertex_descriptor s : {annulus.grid[3 + 24 * 1], annulus.grid[7 + 24 * annulus.rings]})
  {
    INFO("flat annulus seed " << seed << " source " << s);
    const Result rc = compute(annulus.mesh, s, true);
    check_topology(annulus, rc);
    const auto arc = annulus.ridge(annulus.mesh.point(s));
    double precision = 0, recall = 0;
    for_each_ridge_sample(rc.ridge_polylines(), 8, [&](const Point_3& q, std::size_t) {
      precision = std::max(precision, arc.distance_to_ridge({{q.x(), q.y()}}) / h);
    });
    for(const auto& a : arc.polyline())
      recall = std::max(recall, distance_to_ridge(Point_3(a[0], a[1], 0), rc.ridge_polylines()) / h);
    std::cout << "[ridge_curve] flat annulus source " << s << ": farthest ridge point " << precision
              << " mean edges from the arc, farthest arc point " << recall << " from the ridge\n";
    CHECK(precision <= 0.5);
    CHECK(recall <= 0.5);
  }

  const Open_box box = make_open_box(12, 0, seed);
  {
    const vertex_descriptor s = nearest_vertex(box.mesh, Point_3(0.5, 0.5, 0));
    const double hb = mean_edge_length(box.mesh);
    for(bool exact : {true, false})
    {
      INFO("open box, bottom centre " << s << (exact ? " exact" : " fmm"));
      const Result rc = compute(box.mesh, s, exact);
      check_topology(box, rc);
      // precision as the accuracy benchmark measures it, p95 of samples every
      // 0.1 mean edge, of the linear field's ridge
      // Before prongs at corner forks were removed from K (stage 1), the ridge
      // forked one edge above each bottom corner into two short branches that
      // ended on the bottom edges: p95 0.67, max 0.88 mean edges (n = 12).
      double recall = 0;
      auto precision_of = [&](const auto& polylines) {
        std::vector<double> off;
        for_each_ridge_sample_by_length(polylines, 0.1 * hb, [&](const Point_3& q) {
          off.push_back(Open_box::distance_to_bottom_centre_ridge(q) / hb);
        });
        std::sort(off.begin(), off.end());
        return off.empty() ? 0 : off[std::size_t(0.95 * double(off.size() - 1))];
      };
      // Beside two of the bottom corners the ridge drew a short false prong
      // (2.1 mean edges, from the vertical edge two edges up to the bottom
      // edge one edge from the corner; p95 0.24 for the cone ridge, 0.15 for
      // the linear one, 2026-12-05). Its end lies on a flat vertex of the
      // bottom edge and its jumps are weak (0.5-11 degrees), so the exact
      // pipeline now prunes it (no weak end at a vertex without positive
      // curvature): p95 1e-14. What the prong stood in for is missing: the
      // two lowest edges of those vertical edges, a branch inside one sheet
      // of E (K reaches the corner along a wall's diagonal; the manual's
      // Known Limits), so the farthest edge point is 0.70 mean edges from the
      // ridge (0.5 before, reached by the prong). Fast marching keeps it.
      const double precision = precision_of(rc.polylines), reported = precision_of(rc.ridge_polylines());
      if(exact) CHECK(reported <= 0.05);
      for(double x : {0.0, 1.0})
        for(double y : {0.0, 1.0})
          for(double z = 0.1; z < 0.95; z += 0.1)
            recall = std::max(recall, distance_to_ridge(Point_3(x, y, z), rc.ridge_polylines()) / hb);
      std::cout << "[ridge_curve] open box" << (exact ? " exact" : " fmm") << ": ridge points p95 " << precision
                << " (the ridge reported: " << reported << ") mean edges from the vertical edges, farthest edge point "
                << recall << " from the ridge\n";
      CHECK(recall <= (exact ? 0.8 : 0.5));
      if(exact) CHECK(precision <= 0.25);
    }
  }

  const Torus_with_hole torus = make_torus_with_hole(16, 1, 0.4, 2, 0.2, seed);
  for(bool exact : {true, false})
  {
    INFO("torus with a hole seed " << seed << (exact ? " exact" : " fmm"));
    check_topology(torus, compute(torus.mesh, vertex_descriptor(0), exact));
  }
}

// ---------------------------------------------------------------------------
// Every solver drives the pipeline (issue 14). The approximate ones have no
// analytic bound: the square's bounds below are the worst measured over these
// cases (2026-12-03) with a margin, so that a regression shows.

namespace {

template <class Solver, class Source>
std::optional<Result> run_with(const Mesh& m, const Source& s, double tol, const Solver& solver,
                               const std::string& what)
{
  namespace p = Geodesic_ridge::parameters;
  try
  {
    return Geodesic_ridge::compute_ridge_curve(m, s, p::tolerance(tol, p::solver(solver)));
  }
  catch(const Geodesic_ridge::Algorithm_error& e)
  {
    FAIL_CHECK(what << " (" << solver.name() << ", tolerance " << tol << "): Algorithm_error: " << e.what());
  }
  return std::nullopt;
}

// A user's wrapper of the exact solver: it declares `is_exact` and forwards
// every call, the cone query included, so it must get the exact treatment.
struct Wrapped_exact_solver
{
  static const char* name() { return "wrapped-exact"; }
  static constexpr bool is_exact = true;
  template <class... Args>
  void operator()(Args&&... args) const
  {
    Geodesic_ridge::Exact_solver()(std::forward<Args>(args)...);
  }
};

struct Solver_bounds
{
  double square_error, square_miss; // ridge -> analytic and analytic -> ridge, max, mean edges
};

template <class Solver>
void check_solver_drives_the_pipeline(const Solver& solver, const Solver_bounds& bounds)
{
  const std::string name = solver.name();
  // the doubly covered square
  for(double perturbation : {0.0, 0.25})
  {
    const int n = 16;
    const unsigned seed = test_seed(20261203);
    const Doubly_covered_square sq = make_doubly_covered_square(n, perturbation, seed);
    for(const auto& gs : std::vector<std::array<int, 2> >{{{n / 4, n / 3}}, {{n / 2 + 1, n / 4}}, {{3 * n / 4, 3 * n / 4 - 1}}})
    {
      const vertex_descriptor s = sq.top[gs[0] + (n + 1) * gs[1]];
      const double a = sq.mesh.point(s).x(), b = sq.mesh.point(s).y();
      std::ostringstream what;
      what << name << ": doubly covered square n=" << n << " perturbation=" << perturbation << " seed=" << seed
           << " source (" << a << ", " << b << ")";
      INFO(what.str());
      const auto rc = run_with(sq.mesh, s, Geodesic_ridge::default_tolerance, solver, what.str());
      if(!rc) continue;
      check_ridge_validity(sq.mesh, *rc, what.str());
      CHECK(rc->statistics.solver == name);
      const Square_measure r = measure_square(sq, *rc, a, b, 0.25, 0.5);
      std::cout << "[solvers] " << what.str() << ": ridge->analytic max " << r.max_error << " p95 " << r.p95_error
                << " | analytic->ridge max " << r.max_miss << " (" << r.max_miss_inner
                << " away from the corners) p95 " << r.p95_miss << "\n";
      CHECK(r.max_error <= bounds.square_error);
      CHECK(r.max_miss_inner <= bounds.square_miss);
    }
  }
  // tori and a tolerance sweep: one component, 2g cycles
  struct Run { std::string mesh; double tolerance; };
  for(const Run& run : std::vector<Run>{{"torus_1k.off", 0.025}, {"eight.off", 0.025}, {"knot_3k.off", 0.025},
                                        {"bunny_1k.off", 0.005}, {"bunny_1k.off", 0.1}, {"torus_1k.off", 0.005},
                                        {"torus_1k.off", 0.2}})
  {
    const Mesh m = load(run.mesh);
    for(std::size_t s : {std::size_t(0), std::size_t(m.number_of_vertices() / 2)})
    {
      std::ostringstream what;
      what << name << ": " << run.mesh << " source vertex " << s << " tolerance " << run.tolerance;
      INFO(what.str());
      const auto rc = run_with(m, vertex_descriptor(static_cast<Mesh::size_type>(s)), run.tolerance, solver, what.str());
      if(rc) check_ridge_validity(m, *rc, what.str());
    }
  }
}

} // namespace

// Measured on the square (max either way, mean edges): fmm 0.008 unperturbed,
// 0.16 perturbed; heat 0.34; heat-idt 0.33 unperturbed (the same mesh), 0.22
// perturbed; Dijkstra 1.9 (its metric is not the plane's: on the grid its
// unit circle is an octagon, and so its bisectors are not the Voronoi edges).
TEST_CASE("every solver drives the pipeline: the square, tori, a tolerance sweep", "[ridge_curve][solvers]")
{
  SECTION("fast marching") { check_solver_drives_the_pipeline(Geodesic_ridge::Fast_marching_solver(), {0.3, 0.3}); }
  SECTION("window propagation") { check_solver_drives_the_pipeline(Geodesic_ridge::Window_propagation_solver(), {0.3, 0.3}); }
  SECTION("heat") { check_solver_drives_the_pipeline(Geodesic_ridge::Heat_method_solver<>(), {0.5, 0.5}); }
  SECTION("heat-idt") { check_solver_drives_the_pipeline(Geodesic_ridge::Heat_method_idt_solver(), {0.5, 0.5}); }
  SECTION("dijkstra") { check_solver_drives_the_pipeline(Geodesic_ridge::Dijkstra_solver(), {2.5, 2.5}); }
}

TEST_CASE("a user's wrapper of the exact solver gets the exact treatment", "[ridge_curve][solvers]")
{
  STATIC_REQUIRE(Geodesic_ridge::Geodesic_solver_traits<Wrapped_exact_solver>::is_exact);
  STATIC_REQUIRE(Geodesic_ridge::Geodesic_solver_traits<Geodesic_ridge::Exact_solver>::is_exact);
  STATIC_REQUIRE(!Geodesic_ridge::Geodesic_solver_traits<Geodesic_ridge::Fast_marching_solver>::is_exact);
  namespace p = Geodesic_ridge::parameters;
  for(const std::string name : {"bunny_1k.off", "torus_1k.off"})
  {
    const Mesh m = load(name);
    const vertex_descriptor s(7);
    INFO(name << " source vertex 7");
    const Result exact = Geodesic_ridge::compute_ridge_curve(m, s);
    const Result wrapped = Geodesic_ridge::compute_ridge_curve(m, s, p::solver(Wrapped_exact_solver()));
    CHECK(wrapped.statistics.solver == std::string("wrapped-exact"));
    CHECK(wrapped.statistics.solves == exact.statistics.solves);
    CHECK(wrapped.statistics.extended_surface.number_of_faces == exact.statistics.extended_surface.number_of_faces);
    REQUIRE(wrapped.polylines.size() == exact.polylines.size());
    for(std::size_t i = 0; i < exact.polylines.size(); ++i)
    {
      REQUIRE(wrapped.polylines[i].size() == exact.polylines[i].size());
      for(std::size_t j = 0; j < exact.polylines[i].size(); ++j)
        CHECK(wrapped.polylines[i][j].point == exact.polylines[i][j].point);
    }
    // the cone field needs an exact solver: the wrapper is one
    CHECK_NOTHROW(Geodesic_ridge::compute_ridge_curve(m, s, p::solver(Wrapped_exact_solver(), p::field(Geodesic_ridge::Field::cone))));
  }
}

TEST_CASE("the heat method refuses a point source with a typed error, takes a point at a vertex", "[ridge_curve][solvers]")
{
  namespace p = Geodesic_ridge::parameters;
  const Mesh m = load("bunny_1k.off");
  const face_descriptor f(10);
  CHECK_THROWS_AS(Geodesic_ridge::compute_ridge_curve(m, Face_location(f, {{0.2, 0.3, 0.5}}),
                                                      p::solver(Geodesic_ridge::Heat_method_solver<>())),
                  Geodesic_ridge::Invalid_source_error);
  const auto at_corner = Geodesic_ridge::compute_ridge_curve(m, Face_location(f, {{0.0, 1.0, 0.0}}),
                                                             p::solver(Geodesic_ridge::Heat_method_solver<>()));
  const auto at_vertex = Geodesic_ridge::compute_ridge_curve(m, m.target(m.halfedge(f)),
                                                             p::solver(Geodesic_ridge::Heat_method_solver<>()));
  CHECK(at_corner.statistics.ridge.ridge_segments == at_vertex.statistics.ridge.ridge_segments);
}
