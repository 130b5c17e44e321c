// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The test meshes WITH BOUNDARY of test/support/analytic_meshes.h (issue 13),
// checked with CGAL only (no stage of the package runs here): each is a valid,
// manifold, connected triangle mesh without degenerate faces, with the stated
// boundary loops and genus; the flat ones have the stated exact geodesic
// distance (CGAL Surface_mesh_shortest_path, SMSP); on the flat annulus the
// analytic ridge is where SMSP's shortest paths come from both sides of the
// hole; and the exact reference ridge of test/support/reference_ridge.h
// works on meshes with boundary.
//
// `geodesic_ridge_tests "[.generate]"` rewrites data/boundary/*.off.
#include "support/analytic_meshes.h"
#include "support/reference_ridge.h"

#include <CGAL/IO/OFF.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/boost/graph/helpers.h>

#include <catch2/catch.hpp>

#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace GT = Geodesic_ridge::testing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef GT::Mesh Mesh;
typedef GT::Point_3 Point_3;
typedef std::array<double, 2> P2;
typedef GT::internal::SMSP_for<Mesh> SMSP;

constexpr double pi = 3.14159265358979323846;

double degrees(const P2& a, const P2& b)
{
  return std::atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]) * 180 / pi;
}

// The annulus of the ridge tests (radii 1 and 3, 24 sectors) and its source,
// the vertex nearest (2, 0) or, perturbed, (2, 0.6) (then off every symmetry axis).
std::pair<GT::Flat_annulus, Mesh::Vertex_index> annulus_and_source(double perturbation, unsigned seed)
{
  GT::Flat_annulus an = GT::make_flat_annulus(24, 1, 3, perturbation, seed);
  const Mesh::Vertex_index source = GT::nearest_vertex(an.mesh, Point_3(2, perturbation > 0 ? 0.6 : 0, 0));
  return {std::move(an), source};
}

// Every generator at a coarse and a finer, perturbed resolution.
std::vector<std::shared_ptr<GT::Surface_with_boundary> > all_boundary_meshes()
{
  std::vector<std::shared_ptr<GT::Surface_with_boundary> > out;
  for(double p : {0.0, 0.3})
  {
    const unsigned seed = GT::test_seed(20261301);
    out.push_back(std::make_shared<GT::Flat_square>(GT::make_flat_square(p > 0 ? 12 : 3, p, seed)));
    out.push_back(std::make_shared<GT::Flat_L_domain>(GT::make_flat_L_domain(p > 0 ? 6 : 1, p, seed)));
    out.push_back(std::make_shared<GT::Flat_annulus>(GT::make_flat_annulus(p > 0 ? 32 : 6, 1, 3, p, seed)));
    out.push_back(std::make_shared<GT::Half_cylinder>(GT::make_half_cylinder(p > 0 ? 12 : 2, 1, 2, p, seed)));
    out.push_back(std::make_shared<GT::Open_box>(GT::make_open_box(p > 0 ? 6 : 1, p, seed)));
    out.push_back(std::make_shared<GT::Torus_with_hole>(GT::make_torus_with_hole(p > 0 ? 24 : 10, 1, 0.4, p > 0 ? 2 : 1, p, seed)));
  }
  return out;
}

std::string describe(const GT::Surface_with_boundary& s)
{
  return s.name + " n " + std::to_string(s.n) + " perturbation " + std::to_string(s.perturbation) + " seed " +
         std::to_string(s.seed);
}

// The location of (x, y) on a flat mesh at z = 0, barycentric coordinates in CGAL's corner order.
std::pair<Mesh::Face_index, SMSP::Barycentric_coordinates> locate_flat(const Mesh& m, const P2& p)
{
  std::pair<Mesh::Face_index, SMSP::Barycentric_coordinates> best;
  double best_min = -std::numeric_limits<double>::infinity();
  for(auto f : m.faces())
  {
    const auto h = m.halfedge(f);
    const Point_3 a = m.point(m.source(h)), b = m.point(m.target(h)), c = m.point(m.target(m.next(h)));
    const double det = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    const double u = ((p[0] - a.x()) * (c.y() - a.y()) - (p[1] - a.y()) * (c.x() - a.x())) / det;
    const double v = ((b.x() - a.x()) * (p[1] - a.y()) - (b.y() - a.y()) * (p[0] - a.x())) / det;
    const double lowest = std::min({1 - u - v, u, v});
    if(lowest > best_min) { best_min = lowest; best = {f, {{1 - u - v, u, v}}}; }
  }
  REQUIRE(best_min > -1e-9);
  return best;
}

// SMSP at a point of a flat mesh: the distance and the unit arrival direction
// (the path's first straight piece, read backwards).
struct Exact_at
{
  double distance;
  P2 arrival;
};

Exact_at exact_at(SMSP& sp, const Mesh& m, const P2& p)
{
  const auto loc = locate_flat(m, p);
  std::vector<Point_3> path;
  const double d = CGAL::to_double(sp.shortest_path_points_to_source_points(loc.first, loc.second, std::back_inserter(path)).first);
  REQUIRE(path.size() >= 2);
  REQUIRE(std::hypot(path[0].x() - p[0], path[0].y() - p[1]) < 1e-9); // the path starts at the query
  std::size_t k = 1;
  while(k + 1 < path.size() && std::hypot(path[k].x() - p[0], path[k].y() - p[1]) < 1e-9) ++k;
  const double dx = p[0] - path[k].x(), dy = p[1] - path[k].y(), l = std::hypot(dx, dy);
  return {d, {{dx / l, dy / l}}};
}

// Largest |SMSP distance - analytic distance| over all vertices, from `source`.
double worst_vertex_distance_error(const Mesh& m, Mesh::Vertex_index source,
                                   const std::function<double(const Point_3&, const Point_3&)>& exact)
{
  SMSP sp(m);
  sp.add_source_point(source);
  sp.build_sequence_tree();
  double worst = 0;
  for(auto v : m.vertices())
    worst = std::max(worst, std::abs(CGAL::to_double(sp.shortest_distance_to_source_points(v).first) -
                                     exact(m.point(source), m.point(v))));
  return worst;
}

// Euclidean distance from p to the nearest border edge.
double distance_to_boundary(const Mesh& m, const Point_3& p)
{
  double d = std::numeric_limits<double>::infinity();
  for(auto h : m.halfedges())
    if(m.is_border(h))
      d = std::min(d, std::sqrt(CGAL::squared_distance(p, GT::K::Segment_3(m.point(m.source(h)), m.point(m.target(h))))));
  return d;
}

// The point at parameter t of halfedge h (from its source), as a location in h's face.
std::pair<Mesh::Face_index, std::array<double, 3> > edge_location(const Mesh& m, Mesh::Halfedge_index h, double t)
{
  const Mesh::Face_index f = m.face(h);
  int k = 0;
  for(auto g = m.halfedge(f); g != h; g = m.next(g)) ++k;
  std::array<double, 3> b = {{0, 0, 0}};
  b[k] = 1 - t;
  b[(k + 1) % 3] = t;
  return {f, b};
}

// The first halfedge h, inside a face, whose edge satisfies `wanted(h)`.
Mesh::Halfedge_index find_halfedge(const Mesh& m, const std::function<bool(Mesh::Halfedge_index)>& wanted)
{
  for(auto h : m.halfedges())
    if(!m.is_border(h) && wanted(h)) return h;
  FAIL("no such halfedge");
  return Mesh::Halfedge_index();
}

// Largest |distance of the two fronts - SMSP distance| at the reference points, in mean edges.
template <class Reference>
double worst_front_error(const Mesh& m, const Reference& ref, SMSP& sp)
{
  double worst = 0;
  for(std::size_t i = 0; i < ref.points.size(); ++i)
  {
    auto loc = PMP::locate_in_face(ref.points[i], Mesh::Face_index(Mesh::size_type(ref.faces[i])), m);
    double sum = 0;
    for(double& c : loc.second) { c = std::max(0.0, c); sum += c; }
    for(double& c : loc.second) c /= sum;
    const double d = CGAL::to_double(sp.shortest_distance_to_source_points(loc.first, loc.second).first);
    worst = std::max(worst, std::abs(ref.distances[i] - d) / ref.mean_edge);
  }
  return worst;
}

GT::Reference_ridge_options reference_options()
{
  GT::Reference_ridge_options opt;
#ifdef GEODESIC_RIDGE_SANITIZE
  opt.spacing = 0.25;
#endif
  return opt;
}

} // namespace

TEST_CASE("boundary meshes: valid, manifold, triangulated, with the stated boundary loops and genus", "[boundary_meshes]")
{
  for(const auto& sp : all_boundary_meshes())
  {
    const GT::Surface_with_boundary& s = *sp;
    const Mesh& m = s.mesh;
    INFO(describe(s));
    std::cout << "[boundary_meshes] " << describe(s) << ": " << m.number_of_vertices() << " vertices, "
              << m.number_of_faces() << " faces, b = " << s.boundary_loops << ", g = " << s.genus
              << ", rank of ridge + boundary " << s.cycle_rank() << "\n";
    CHECK(CGAL::is_valid_polygon_mesh(m));
    CHECK(CGAL::is_triangle_mesh(m));
    std::size_t non_manifold = 0, isolated = 0;
    for(auto v : m.vertices())
    {
      if(PMP::is_non_manifold_vertex(v, m)) ++non_manifold;
      if(m.is_isolated(v)) ++isolated;
    }
    CHECK(non_manifold == 0);
    CHECK(isolated == 0);
    std::vector<Mesh::Halfedge_index> cycles;
    PMP::extract_boundary_cycles(m, std::back_inserter(cycles));
    CHECK(int(cycles.size()) == s.boundary_loops);
    const long chi = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
    CHECK(chi == s.euler_characteristic());
    std::map<Mesh::Face_index, std::size_t> component;
    CHECK(PMP::connected_components(m, boost::make_assoc_property_map(component)) == 1);
    std::size_t degenerate = 0;
    for(auto f : m.faces()) if(PMP::is_degenerate_triangle_face(f, m)) ++degenerate;
    CHECK(degenerate == 0);
    CHECK(s.cycle_rank() == 2 * s.genus + s.boundary_loops);
  }
}

TEST_CASE("boundary meshes: the flat ones have the stated exact distance (SMSP), from inside and from the boundary",
          "[boundary_meshes]")
{
  const unsigned seed = GT::test_seed(20261302);
  std::cout << "[boundary_meshes] exact distances, seed " << seed << "\n";
  const GT::Flat_square sq = GT::make_flat_square(8, 0.3, seed);
  const GT::Flat_L_domain L = GT::make_flat_L_domain(4, 0.3, seed);
  const GT::Half_cylinder hc = GT::make_half_cylinder(8, 1, 2, 0.3, seed);
  const GT::Flat_annulus an = GT::make_flat_annulus(16, 1, 3, 0.3, seed);
  // sources: an inside vertex, a boundary vertex that is no corner, a corner
  struct Case { const GT::Surface_with_boundary* s; std::vector<Mesh::Vertex_index> sources;
                std::function<double(const Point_3&, const Point_3&)> exact; };
  const int w = 2 * L.n + 1;
  const std::vector<Case> cases = {
    {&sq, {sq.grid[3 + 9 * 5], sq.grid[4], sq.grid[0]}, &GT::Flat_square::geodesic_distance},
    {&L, {L.grid[std::size_t(6 + w * 2)], L.grid[std::size_t(2 + w * 8)], L.reflex_corner}, &GT::Flat_L_domain::geodesic_distance},
    {&hc, {hc.grid[std::size_t(3 + 9 * 2)], hc.grid[std::size_t(9 * 3)], hc.grid[5]},
     [&](const Point_3& a, const Point_3& b) { return hc.geodesic_distance(a, b); }},
    {&an, {an.grid[std::size_t(5 + 16 * 1)], an.grid[2], an.grid[std::size_t(9 + 16 * an.rings)]},
     [&](const Point_3& a, const Point_3& b) { return an.geodesic_distance(a, b); }}};
  for(const Case& c : cases)
    for(Mesh::Vertex_index s : c.sources)
    {
      INFO(describe(*c.s) << " source " << std::size_t(s) << (c.s->mesh.is_border(s) ? " (boundary)" : " (inside)"));
      const double err = worst_vertex_distance_error(c.s->mesh, s, c.exact);
      std::cout << "  " << c.s->name << " source " << std::size_t(s) << (c.s->mesh.is_border(s) ? " (boundary)" : "")
                << ": max |SMSP - exact| over the vertices " << err << "\n";
      CHECK(err < 1e-9);
    }
  // the annulus's oracle from every vertex of a small perturbed one
  const GT::Flat_annulus small = GT::make_flat_annulus(12, 1, 3, 0.3, seed);
  double worst_annulus = 0;
  for(auto s : small.mesh.vertices())
    worst_annulus = std::max(worst_annulus, worst_vertex_distance_error(small.mesh, s, [&](const Point_3& a, const Point_3& b) {
      return small.geodesic_distance(a, b);
    }));
  std::cout << "  " << describe(small) << ", every vertex a source: max |SMSP - exact| " << worst_annulus << "\n";
  CHECK(worst_annulus < 1e-9);
  // the L's paths do bend at the reflex corner: some vertex pairs are not Euclidean
  const Mesh::Vertex_index s = L.grid[std::size_t(6 + w * 2)];
  std::size_t bent = 0;
  for(auto v : L.mesh.vertices())
    bent += GT::Flat_L_domain::segment_leaves(L.mesh.point(s), L.mesh.point(v)) ? 1 : 0;
  CHECK(bent > 5);
}

// The oracle's ridge is where SMSP's shortest paths arrive from the two sides
// of the hole: at a ridge point SMSP's distance equals both ways' lengths, and
// just off it, on either side, SMSP's distance and arrival direction are those
// of the way that the oracle says is shorter there, the two directions apart.
TEST_CASE("flat annulus: at the analytic ridge, SMSP's shortest paths come around both sides of the hole", "[boundary_meshes]")
{
  const unsigned seed = GT::test_seed(20261303);
  for(double perturbation : {0.0, 0.3})
  {
    const auto [an, source] = annulus_and_source(perturbation, seed);
    const Point_3 sp3 = an.mesh.point(source);
    INFO(describe(an) << " source " << std::size_t(source) << " at " << sp3);
    const GT::Flat_annulus_ridge ridge = an.ridge(sp3);
    const auto& pl = ridge.polyline();
    REQUIRE(pl.size() == 201);
    if(perturbation == 0) // the source is on the x axis: the ridge is the far side of the axis, from the hole to R
    {
      for(const P2& q : pl) CHECK(std::abs(q[1]) < 1e-9);
      CHECK(std::abs(pl.front()[0] + 1) < 1e-9);
      CHECK(std::abs(pl.back()[0] + 3) < 1e-9);
    }
    const double L = GT::mean_edge_length(an.mesh), delta = 0.02 * L;
    SMSP sp(an.mesh);
    sp.add_source_point(source);
    sp.build_sequence_tree();
    double worst_distance = 0, worst_direction = 0, smallest_jump = 180;
    for(std::size_t i = 10; i + 10 < pl.size(); i += 10)
    {
      const P2 q = pl[i];
      const double ccw = ridge.path(q, 1).length, cw = ridge.path(q, -1).length;
      worst_distance = std::max({worst_distance, std::abs(ccw - cw), std::abs(exact_at(sp, an.mesh, q).distance - ccw)});
      const double tx = pl[i + 1][0] - pl[i - 1][0], ty = pl[i + 1][1] - pl[i - 1][1], tl = std::hypot(tx, ty);
      std::array<int, 2> winner;
      std::array<P2, 2> smsp_arrival;
      for(int k = 0; k < 2; ++k)
      {
        const double sign = k == 0 ? 1 : -1;
        const P2 x = {{q[0] - sign * delta * ty / tl, q[1] + sign * delta * tx / tl}};
        winner[k] = ridge.gap(x) < 0 ? 1 : -1;
        const Exact_at e = exact_at(sp, an.mesh, x);
        smsp_arrival[k] = e.arrival;
        worst_distance = std::max(worst_distance, std::abs(e.distance - ridge.distance(x)));
        worst_direction = std::max(worst_direction, std::abs(degrees(e.arrival, ridge.arrival(x, winner[k]))));
      }
      CHECK(winner[0] != winner[1]);
      smallest_jump = std::min(smallest_jump, std::abs(degrees(smsp_arrival[0], smsp_arrival[1])));
    }
    // how far the ridge is from the line through the source and the centre (0 on a symmetry axis)
    double off_line = 0;
    const double sl = std::hypot(sp3.x(), sp3.y());
    for(const P2& q : pl) off_line = std::max(off_line, std::abs(q[0] * sp3.y() - q[1] * sp3.x()) / sl);
    std::cout << "[boundary_meshes] annulus ridge vs SMSP, " << describe(an) << ", source at angle "
              << std::atan2(sp3.y(), sp3.x()) * 180 / pi << " deg: ridge at most " << off_line / L
              << " mean edges from the line through the source and the centre; max distance error " << worst_distance
              << ", max arrival direction error " << worst_direction << " deg, smallest jump across the ridge "
              << smallest_jump << " deg\n";
    CHECK(worst_distance < 1e-9);
    CHECK(worst_direction < 1e-4);
    CHECK(smallest_jump > 20);
  }
}

TEST_CASE("reference ridge on the flat annulus: the analytic arc, nothing on the near side", "[boundary_meshes][ridge_accuracy]")
{
  const unsigned seed = GT::test_seed(20261304);
  for(double perturbation : {0.0, 0.3})
  {
    const auto [an, source] = annulus_and_source(perturbation, seed);
    INFO(describe(an) << " source " << std::size_t(source));
    const GT::Flat_annulus_ridge ridge = an.ridge(an.mesh.point(source));
    const auto ref = GT::reference_ridge(an.mesh, source, reference_options());
    const double L = ref.mean_edge;
    double worst = 0, min_jump = 180;
    for(std::size_t i = 0; i < ref.points.size(); ++i)
    {
      worst = std::max(worst, ridge.distance_to_ridge({{ref.points[i].x(), ref.points[i].y()}}) / L);
      min_jump = std::min(min_jump, ref.jump_degrees[i]);
    }
    // recall: every point of the arc has a reference point near it
    double gap = 0;
    for(const P2& q : ridge.polyline())
    {
      double d = std::numeric_limits<double>::infinity();
      for(const auto& p : ref.points) d = std::min(d, std::hypot(p.x() - q[0], p.y() - q[1]));
      gap = std::max(gap, d / L);
    }
    std::cout << "[boundary_meshes] reference ridge on the " << describe(an) << ": " << ref.points.size()
              << " points from " << ref.samples << " samples (" << ref.failed_samples << " failed), max distance to the arc "
              << worst << " mean edges, min jump " << min_jump << " deg, largest gap along the arc " << gap
              << " mean edges\n";
    CHECK(ref.failed_samples == 0);
    CHECK(ref.points.size() > 12); // (17-22 points, by build type)
    CHECK(worst < 1.0);
    CHECK(gap < 1.0);
  }
}

// On flat simply connected domains shortest paths are unique: the reference
// marks nothing (the shadow line of the L's reflex corner included).
TEST_CASE("reference ridge on flat simply connected domains: empty", "[boundary_meshes][ridge_accuracy]")
{
  const unsigned seed = GT::test_seed(20261305);
  const GT::Flat_square sq = GT::make_flat_square(10, 0.3, seed);
  const GT::Flat_L_domain L = GT::make_flat_L_domain(5, 0.3, seed);
  const GT::Half_cylinder hc = GT::make_half_cylinder(10, 1, 2, 0.3, seed);
  const int w = 2 * L.n + 1;
  const std::vector<std::pair<const GT::Surface_with_boundary*, std::vector<Mesh::Vertex_index> > > cases = {
    {&sq, {sq.grid[3 + 11 * 4], sq.grid[5]}},
    {&L, {L.grid[std::size_t(8 + w * 2)], L.grid[std::size_t(2 + w * 8)], L.grid[std::size_t(w * 3)]}},
    {&hc, {hc.grid[std::size_t(4 + 11 * 2)], hc.grid[std::size_t(11 * 3)]}}};
  for(const auto& c : cases)
    for(Mesh::Vertex_index s : c.second)
    {
      INFO(describe(*c.first) << " source " << std::size_t(s));
      const auto ref = GT::reference_ridge(c.first->mesh, s, reference_options());
      double max_jump = 0;
      for(double j : ref.jump_degrees) max_jump = std::max(max_jump, j);
      std::cout << "[boundary_meshes] reference ridge on the " << describe(*c.first) << ", source " << std::size_t(s)
                << (c.first->mesh.is_border(s) ? " (boundary)" : "") << ": " << ref.points.size() << " points ("
                << ref.crossings << " two-front pairs before the filters, max jump " << max_jump << " deg), "
                << ref.failed_samples << " failed samples of " << ref.samples << "\n";
      CHECK(ref.failed_samples == 0);
      CHECK(ref.points.empty());
    }
}

// A source on an edge, border or not (reference_ridge.h moves it into its face
// with CGAL < 5.6, whose SMSP expands edge sources wrongly): SMSP with the
// moved point has the annulus's exact distances, and the reference ridge is
// the analytic arc.
TEST_CASE("reference ridge on the flat annulus from a point of an edge, border or not", "[boundary_meshes][ridge_accuracy]")
{
  const unsigned seed = GT::test_seed(20261306);
  const GT::Flat_annulus an = GT::make_flat_annulus(24, 1, 3, 0.3, seed);
  const Mesh& m = an.mesh;
  auto radius = [&](Mesh::Vertex_index v) { return std::hypot(m.point(v).x(), m.point(v).y()); };
  const std::vector<std::pair<std::string, Mesh::Halfedge_index> > edges = {
    {"edge of the outer boundary", find_halfedge(m, [&](Mesh::Halfedge_index h) { return m.is_border(m.opposite(h)) && radius(m.source(h)) > 2; })},
    {"edge of the hole", find_halfedge(m, [&](Mesh::Halfedge_index h) { return m.is_border(m.opposite(h)) && radius(m.source(h)) < 2; })},
    {"inner edge (not a border)", find_halfedge(m, [&](Mesh::Halfedge_index h) { return !m.is_border(m.edge(h)) && radius(m.source(h)) > 1.5; })}};
  for(const auto& e : edges)
  {
    const auto loc = edge_location(m, e.second, 0.37);
    const std::array<double, 3> w = Geodesic_ridge::internal::smsp_source_coordinates(loc.second);
    SMSP sp(m);
    sp.add_source_point(loc.first, {{w[0], w[1], w[2]}});
    sp.build_sequence_tree();
    const Point_3 source = sp.point(loc.first, {{loc.second[0], loc.second[1], loc.second[2]}});
    INFO(describe(an) << ", source on the " << e.first << " at " << source);
    const GT::Flat_annulus_ridge ridge = an.ridge(source);
    double worst_distance = 0;
    for(auto v : m.vertices())
      worst_distance = std::max(worst_distance, std::abs(CGAL::to_double(sp.shortest_distance_to_source_points(v).first) -
                                                         ridge.distance({{m.point(v).x(), m.point(v).y()}})));
    // as given (no move): informative only, it depends on the CGAL version
    SMSP raw(m);
    raw.add_source_point(loc.first, {{loc.second[0], loc.second[1], loc.second[2]}});
    raw.build_sequence_tree();
    double raw_worst = 0;
    for(auto v : m.vertices())
      raw_worst = std::max(raw_worst, std::abs(CGAL::to_double(raw.shortest_distance_to_source_points(v).first) -
                                               ridge.distance({{m.point(v).x(), m.point(v).y()}})));
    const auto ref = GT::reference_ridge(m, loc, reference_options());
    double worst = 0;
    for(const auto& p : ref.points) worst = std::max(worst, ridge.distance_to_ridge({{p.x(), p.y()}}) / ref.mean_edge);
    std::cout << "[boundary_meshes] annulus, source on the " << e.first << ": max vertex distance error " << worst_distance
              << " (SMSP with the point as given, CGAL " << CGAL_VERSION_STR << ": " << raw_worst << "), reference "
              << ref.points.size() << " points, max distance to the arc " << worst << " mean edges\n";
    CHECK(worst_distance < 1e-9);
    CHECK(ref.failed_samples == 0);
    CHECK(ref.points.size() > 12); // (17-22 points, by build type)
    CHECK(worst < 0.01);
  }
}

// From the bottom centre of the open box the ridge is the four vertical edges
// (Open_box); the reference finds them up to the rim.
TEST_CASE("reference ridge on the open box from the bottom centre: the four vertical edges", "[boundary_meshes][ridge_accuracy]")
{
  const GT::Open_box box = GT::make_open_box(6);
  const Mesh::Vertex_index source = GT::nearest_vertex(box.mesh, Point_3(0.5, 0.5, 0));
  REQUIRE(box.mesh.point(source) == Point_3(0.5, 0.5, 0));
  const auto ref = GT::reference_ridge(box.mesh, source, reference_options());
  const double L = ref.mean_edge;
  double worst = 0, top = 0, bottom = 1;
  for(const auto& p : ref.points)
  {
    worst = std::max(worst, GT::Open_box::distance_to_bottom_centre_ridge(p) / L);
    top = std::max(top, p.z());
    bottom = std::min(bottom, p.z());
  }
  std::cout << "[boundary_meshes] reference ridge on the open box from the bottom centre: " << ref.points.size()
            << " points, max distance to the vertical edges " << worst << " mean edges, z from " << bottom << " to "
            << top << " (mean edge " << L << ", " << ref.border_edges << " border edges)\n";
  CHECK(ref.failed_samples == 0);
  CHECK(ref.points.size() > 40);
  CHECK(worst < 0.01);
  CHECK(1 - top < 0.25 * L); // kept up to the rim
  CHECK(bottom < 0.25 * L);  // and down to the bottom corners (leaves)
}

// Curved meshes with boundary (no closed form): the reference runs (no failed
// sample), its two fronts agree with SMSP's distance at every point, and the
// ridge reaches the boundary (ridge + boundary is connected), from a source
// inside, at a boundary vertex and on a border edge.
TEST_CASE("reference ridge on the open box and the torus with a hole: consistent with SMSP, reaching the boundary",
          "[boundary_meshes][ridge_accuracy]")
{
  const unsigned seed = GT::test_seed(20261307);
  const GT::Open_box box = GT::make_open_box(6, 0.3, seed);
  const GT::Torus_with_hole torus = GT::make_torus_with_hole(24, 1, 0.4, 2, 0.3, seed);
  for(const GT::Surface_with_boundary* s : {static_cast<const GT::Surface_with_boundary*>(&box),
                                            static_cast<const GT::Surface_with_boundary*>(&torus)})
  {
    const Mesh& m = s->mesh;
    const Mesh::Vertex_index inside = GT::nearest_vertex(m, s == &box ? Point_3(0.3, 0.6, 0) : Point_3(-1.4, 0, 0));
    const Mesh::Vertex_index rim = GT::border_vertices(m)[3];
    const Mesh::Halfedge_index border = find_halfedge(m, [&](Mesh::Halfedge_index h) { return m.is_border(m.opposite(h)); });
    for(int k = 0; k < 3; ++k)
    {
      const auto loc = k == 2 ? edge_location(m, border, 0.37) : std::pair<Mesh::Face_index, std::array<double, 3> >();
      const auto ref = k == 2 ? GT::reference_ridge(m, loc, reference_options())
                              : GT::reference_ridge(m, k == 0 ? inside : rim, reference_options());
      SMSP sp(m);
      if(k == 2)
      {
        const std::array<double, 3> w = Geodesic_ridge::internal::smsp_source_coordinates(loc.second);
        sp.add_source_point(loc.first, {{w[0], w[1], w[2]}});
      }
      else sp.add_source_point(k == 0 ? inside : rim);
      sp.build_sequence_tree();
      const double front_error = worst_front_error(m, ref, sp);
      double nearest_boundary = std::numeric_limits<double>::infinity();
      for(const auto& p : ref.points) nearest_boundary = std::min(nearest_boundary, distance_to_boundary(m, p) / ref.mean_edge);
      const char* where[3] = {"inside", "a boundary vertex", "a border edge"};
      INFO(describe(*s) << ", source " << where[k]);
      std::cout << "[boundary_meshes] reference ridge on the " << describe(*s) << ", source " << where[k] << ": "
                << ref.points.size() << " points, " << ref.failed_samples << " failed samples, fronts vs SMSP max "
                << front_error << " mean edges, nearest point to the boundary " << nearest_boundary << " mean edges\n";
      CHECK(ref.failed_samples == 0);
      CHECK(ref.points.size() > 40);
      CHECK(front_error < 0.05);
      CHECK(nearest_boundary < 0.25);
    }
  }
}

// ---------------------------------------------------------------------------
// data/boundary/: small meshes with boundary for the command-line tests

namespace {

struct Data_mesh
{
  std::string file;
  std::function<GT::Surface_with_boundary()> make;
};

const std::vector<Data_mesh>& data_meshes()
{
  static const std::vector<Data_mesh> list = {
    {"flat_annulus.off", [] { return GT::Surface_with_boundary(GT::make_flat_annulus(24, 1, 3, 0.25, 20261313)); }},
    {"open_box.off", [] { return GT::Surface_with_boundary(GT::make_open_box(6, 0.25, 20261314)); }}};
  return list;
}

std::string data_path(const std::string& file) { return std::string(GEODESIC_RIDGE_DATA_DIR) + "/boundary/" + file; }

} // namespace

TEST_CASE("write data/boundary/*.off", "[.generate]")
{
  for(const Data_mesh& d : data_meshes())
  {
    const GT::Surface_with_boundary s = d.make();
    REQUIRE(CGAL::IO::write_OFF(data_path(d.file), s.mesh, CGAL::parameters::stream_precision(17)));
    std::cout << "wrote " << data_path(d.file) << " (" << describe(s) << ")\n";
  }
}

TEST_CASE("data/boundary/*.off are the generators' meshes", "[boundary_meshes][data]")
{
  for(const Data_mesh& d : data_meshes())
  {
    INFO(data_path(d.file));
    const GT::Surface_with_boundary s = d.make();
    Mesh m;
    REQUIRE(CGAL::IO::read_OFF(data_path(d.file), m));
    REQUIRE(m.number_of_vertices() == s.mesh.number_of_vertices());
    REQUIRE(m.number_of_faces() == s.mesh.number_of_faces());
    double worst = 0;
    for(auto v : m.vertices()) worst = std::max(worst, std::sqrt(CGAL::squared_distance(m.point(v), s.mesh.point(v))));
    CHECK(worst == 0);
    std::vector<Mesh::Halfedge_index> cycles;
    PMP::extract_boundary_cycles(m, std::back_inserter(cycles));
    CHECK(int(cycles.size()) == s.boundary_loops);
  }
}
