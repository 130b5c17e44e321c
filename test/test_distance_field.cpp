// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the region-wise distance field (distance_field.h), the
// ridge-refined mesh (refined_mesh.h) and iso-lines (isolines.h):
//  * at a vertex the query equals the vertex distance;
//  * on the doubly covered square (exact distance: to the source on the top
//    sheet, to the nearest mirror image on the bottom one), the field's mean
//    error falls at second order under refinement, in the faces the ridge
//    crosses as elsewhere;
//  * across the ridge the field is continuous (exact solver: both sides agree
//    within 1e-9 of the diagonal at ridge points inside faces);
//  * the refined mesh is valid, closed, conforming, of the same area and Euler
//    characteristic, every face in one cell, every ridge segment on its edges;
//    it reads back through CGAL's PLY reader with its properties;
//  * iso-lines: every level present, closed curves, cusps where they cross
//    the ridge (and none with plain linear interpolation).
#include "support/analytic_meshes.h"
#include "support/extension_checks.h"

#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/connected_component.h>
#include <Geodesic_ridge/distance_field.h>
#include <Geodesic_ridge/isolines.h>
#include <Geodesic_ridge/refined_mesh.h>
#include <Geodesic_ridge/solvers/Window_propagation_solver.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/bounding_box.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace Geodesic_ridge::testing;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index face_descriptor;
typedef std::pair<face_descriptor, std::array<double, 3> > Location;
typedef Geodesic_ridge::Ridge_curve<Mesh, Point_3> Ridge;

Mesh read_data_mesh(const std::string& name)
{
  Mesh m;
  Geodesic_ridge::IO::read_triangle_mesh(std::string(GEODESIC_RIDGE_DATA_DIR) + "/" + name, m);
  return m;
}

double diagonal(const Mesh& m)
{
  const auto box = CGAL::bounding_box(m.points().begin(), m.points().end());
  return std::sqrt(CGAL::squared_distance(box.min(), box.max()));
}

Point_3 point_at(const Mesh& m, const Location& l)
{
  const auto h = m.halfedge(l.first);
  const Point_3 a = m.point(m.source(h)), b = m.point(m.target(h)), c = m.point(m.target(m.next(h)));
  const auto& w = l.second;
  return Point_3(w[0] * a.x() + w[1] * b.x() + w[2] * c.x(), w[0] * a.y() + w[1] * b.y() + w[2] * c.y(),
                 w[0] * a.z() + w[1] * b.z() + w[2] * c.z());
}

// Barycentric coordinates of p (on the plane of face f) in CGAL's corner order.
std::array<double, 3> barycentric_in(const Mesh& m, face_descriptor f, const Point_3& p)
{
  const auto h = m.halfedge(f);
  const Point_3 a = m.point(m.source(h)), b = m.point(m.target(h)), c = m.point(m.target(m.next(h)));
  const K::Vector_3 n = CGAL::cross_product(b - a, c - a);
  const double nn = n.squared_length();
  return {{CGAL::cross_product(c - b, p - b) * n / nn, CGAL::cross_product(a - c, p - c) * n / nn,
           CGAL::cross_product(b - a, p - a) * n / nn}};
}

struct Refined
{
  Mesh mesh;
  Mesh::Property_map<vertex_descriptor, double> distance;
  Mesh::Property_map<face_descriptor, std::int32_t> source_face;
  Mesh::Property_map<Mesh::Edge_index, bool> on_ridge;
  Geodesic_ridge::Refined_mesh_statistics statistics;
};

Refined refine(const Mesh& m, const Ridge& rc)
{
  Refined r;
  r.distance = r.mesh.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  r.source_face = r.mesh.add_property_map<face_descriptor, std::int32_t>("f:source_face", -1).first;
  r.on_ridge = r.mesh.add_property_map<Mesh::Edge_index, bool>("e:ridge", false).first;
  struct Visitor
  {
    Mesh::Property_map<face_descriptor, std::int32_t> map;
    void face_created(face_descriptor original, face_descriptor created) { map[created] = std::int32_t(original); }
  } visitor{r.source_face};
  r.statistics = Geodesic_ridge::refine_mesh_along_ridge(
      m, rc, r.mesh, CGAL::parameters::default_values(),
      Geodesic_ridge::parameters::vertex_distance_map(r.distance).edge_is_constrained_map(r.on_ridge).visitor(visitor));
  return r;
}

// The checks of the refined mesh that hold for any ridge.
void check_refined_mesh(const Mesh& m, const Ridge& rc, const Refined& r, const std::string& what, bool exact)
{
  INFO(what);
  const auto field = Geodesic_ridge::make_distance_field(m, rc);
  const double diag = diagonal(m);
  CHECK(CGAL::is_valid_polygon_mesh(r.mesh));
  CHECK(CGAL::is_triangle_mesh(r.mesh));
  CHECK(CGAL::is_closed(r.mesh)); // a T-junction would leave a border edge: closed means conforming
  const auto euler = [](const Mesh& x) {
    return long(x.number_of_vertices()) - long(x.number_of_edges()) + long(x.number_of_faces());
  };
  CHECK(euler(r.mesh) == euler(m));
  const double area_in = CGAL::Polygon_mesh_processing::area(m), area_out = CGAL::Polygon_mesh_processing::area(r.mesh);
  CHECK(std::abs(area_out - area_in) <= 1e-9 * area_in);
  CHECK(r.statistics.unmatched_ridge_segments == 0);
  CHECK(r.statistics.ridge_edges >= rc.statistics.ridge.ridge_segments);
  std::size_t constrained = 0;
  for(auto e : r.mesh.edges()) constrained += r.on_ridge[e];
  CHECK(constrained == r.statistics.ridge_edges);
  // With the exact solver the faces agree at every point, except where a
  // copy split at a kink inside one sheet meets a copy that is not split
  // (parameters::kink_angle): there the split copy follows the two cones and the
  // other the linear interpolation, below them (measured: up to 0.7 mean edges
  // on teddy_3k v0, 0.32 on bunny_1k; the mean field error, bench_distance_field,
  // is the same as without the split).
  if(exact && rc.statistics.ridge.split_copies == 0 && rc.statistics.ridge.recombined_copies == 0) CHECK(r.statistics.largest_disagreement <= 1e-9 * diag);
  if(exact) CHECK(r.statistics.largest_disagreement <= mean_edge_length(m));
  // every new face lies in one cell of its face: at its centroid and at the
  // midpoints of its corners and centroid, the interpolated vertex distances
  // equal the field (one linear piece), up to the disagreement rule's shift
  double worst = 0;
  std::size_t worst_face = 0;
  for(face_descriptor nf : r.mesh.faces())
  {
    REQUIRE(r.source_face[nf] >= 0);
    const face_descriptor f(static_cast<Mesh::size_type>(r.source_face[nf]));
    const auto h = r.mesh.halfedge(nf);
    const vertex_descriptor v[3] = {r.mesh.source(h), r.mesh.target(h), r.mesh.target(r.mesh.next(h))};
    const double w[4][3] = {{1. / 3, 1. / 3, 1. / 3}, {2. / 3, 1. / 6, 1. / 6}, {1. / 6, 2. / 3, 1. / 6}, {1. / 6, 1. / 6, 2. / 3}};
    for(const auto& wk : w)
    {
      double x = 0, y = 0, z = 0, d = 0;
      for(int k = 0; k < 3; ++k)
      {
        const Point_3& p = r.mesh.point(v[k]);
        x += wk[k] * p.x(); y += wk[k] * p.y(); z += wk[k] * p.z();
        d += wk[k] * r.distance[v[k]];
      }
      const double err = std::abs(d - field.distance(Location(f, barycentric_in(m, f, Point_3(x, y, z)))));
      if(err > worst) { worst = err; worst_face = std::size_t(nf); }
    }
  }
  INFO("largest gap between the refined mesh's interpolation and the field: " << worst / diag
       << " of the diagonal, at output face " << worst_face << "; largest disagreement "
       << r.statistics.largest_disagreement / diag);
  CHECK(worst <= 1e-9 * diag + r.statistics.largest_disagreement);
}

// The iso-lines of `distance` on `mesh` at n levels: every level present, every
// curve closed. Returns the largest turning angle (degrees) of an iso-line at
// a point within `near` of a ridge polyline of rc, measured over chords of
// length `scale` on either side, at points for which `counts`
// holds (on the doubly covered square: away from the border, where the
// surface folds back and every curve turns by 180 degrees in space).
template <class Counts>
double check_isolines(const Mesh& mesh, const std::vector<double>& distance, const Ridge& rc, std::size_t n,
                      double near, double scale, const std::string& what, const Counts& counts)
{
  INFO(what);
  double largest = 0;
  for(double d : distance) largest = std::max(largest, d);
  const auto levels = Geodesic_ridge::equally_spaced_levels(n, largest);
  std::vector<Geodesic_ridge::Isoline<Point_3> > lines;
  Geodesic_ridge::isolines(mesh, CGAL::make_property_map(distance), levels, std::back_inserter(lines));
  std::vector<int> per_level(levels.size(), 0);
  double sharpest = 0;
  for(const auto& l : lines)
  {
    CHECK(l.closed);
    CHECK(l.points.size() >= 4);
    const auto it = std::find(levels.begin(), levels.end(), l.level);
    REQUIRE(it != levels.end());
    ++per_level[it - levels.begin()];
    // the turn at point i over chords of at least `scale` on either side (a
    // curve through a vertex has tiny segments whose directions mean nothing)
    const std::size_t m = l.points.size();
    for(std::size_t i = 1; i + 1 < m; ++i)
    {
      if(!counts(l.points[i])) continue;
      bool on_ridge = false;
      for(const auto& pl : rc.polylines)
        for(std::size_t j = 0; j + 1 < pl.size() && !on_ridge; ++j)
          on_ridge = CGAL::squared_distance(l.points[i], K::Segment_3(pl[j].point, pl[j + 1].point)) <= near * near;
      if(!on_ridge) continue;
      std::size_t before = i, after = i;
      while(before > 0 && CGAL::squared_distance(l.points[before], l.points[i]) < scale * scale) --before;
      while(after + 1 < m && CGAL::squared_distance(l.points[after], l.points[i]) < scale * scale) ++after;
      const K::Vector_3 a = l.points[i] - l.points[before], b = l.points[after] - l.points[i];
      if(a.squared_length() < scale * scale || b.squared_length() < scale * scale) continue;
      const double c = a * b / std::sqrt(a.squared_length() * b.squared_length());
      const double turn = std::acos(std::max(-1.0, std::min(1.0, c))) * 180 / CGAL_PI;
      sharpest = std::max(sharpest, turn);
    }
  }
  for(std::size_t i = 0; i < levels.size(); ++i)
  {
    INFO("level " << levels[i]);
    CHECK(per_level[i] >= 1);
  }
  return sharpest;
}

} // namespace

TEST_CASE("distance field: at a vertex the query equals the vertex distance", "[distance_field]")
{
  for(const std::string name : {"bunny_1k.off", "eight.off", "knot_3k.off"})
    for(int solver = 0; solver < 2; ++solver)
    {
      const Mesh m = read_data_mesh(name);
      const vertex_descriptor s(17);
      namespace p = Geodesic_ridge::parameters;
      const Ridge rc = solver == 0 ? Geodesic_ridge::compute_ridge_curve(m, s)
                                   : Geodesic_ridge::compute_ridge_curve(m, s, p::solver(Geodesic_ridge::Fast_marching_solver()));
      const auto field = Geodesic_ridge::make_distance_field(m, rc);
      const double diag = diagonal(m);
      double worst = 0;
      for(face_descriptor f : m.faces())
      {
        auto h = m.halfedge(f);
        for(int k = 0; k < 3; ++k, h = m.next(h))
        {
          std::array<double, 3> b = {{0, 0, 0}};
          b[k] = 1;
          worst = std::max(worst, std::abs(field.distance(Location(f, b)) - field.distance(m.source(h))));
        }
      }
      INFO(name << (solver == 0 ? " exact" : " fmm") << " source vertex 17: largest difference " << worst / diag
                << " of the diagonal");
      CHECK(worst <= 1e-12 * diag);
      CHECK(field.distance(s) == 0);
    }
}

TEST_CASE("several components: the ridge and field of the source's part are those of the part alone",
          "[distance_field][components]")
{
  // eight.off moved aside, then torus_1k.off: the source on the torus
  const Mesh torus = read_data_mesh("torus_1k.off");
  Mesh eight = read_data_mesh("eight.off");
  for(vertex_descriptor v : eight.vertices())
    eight.point(v) = Point_3(eight.point(v).x() + 10, eight.point(v).y(), eight.point(v).z());
  Mesh both;
  CGAL::copy_face_graph(eight, both);
  std::vector<std::pair<vertex_descriptor, vertex_descriptor> > v2v;
  CGAL::copy_face_graph(torus, both, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v)));
  std::vector<vertex_descriptor> in_both(torus.number_of_vertices());
  for(const auto& [from, to] : v2v) in_both[std::size_t(from)] = to;

  const vertex_descriptor s(17);
  Mesh part;
  const auto cc = Geodesic_ridge::extract_connected_component(both, *CGAL::faces_around_target(both.halfedge(in_both[17]), both).begin(), part);
  CHECK(cc.number_of_components() == 2);
  CHECK(cc.number_of_other_faces() == eight.number_of_faces());
  CHECK(part.number_of_faces() == torus.number_of_faces());
  const vertex_descriptor s_part = *cc.component_vertex(in_both[17]);
  CHECK_THROWS_AS(Geodesic_ridge::compute_ridge_curve(both, in_both[17]), Geodesic_ridge::Invalid_mesh_error);

  const Ridge alone = Geodesic_ridge::compute_ridge_curve(torus, s);
  const Ridge in_part = Geodesic_ridge::compute_ridge_curve(part, s_part);
  INFO("torus_1k source vertex 17: ridge length " << alone.statistics.ridge.total_length << " alone, "
       << in_part.statistics.ridge.total_length << " as a part");
  CHECK(in_part.statistics.ridge.cycles == 2);
  CHECK(in_part.statistics.ridge.components == 1);
  CHECK(std::abs(in_part.statistics.ridge.total_length - alone.statistics.ridge.total_length) <=
        1e-9 * alone.statistics.ridge.total_length);
  const auto field_alone = Geodesic_ridge::make_distance_field(torus, alone);
  const auto field_part = Geodesic_ridge::make_distance_field(part, in_part);
  double worst = 0;
  for(vertex_descriptor v : torus.vertices())
    worst = std::max(worst, std::abs(field_part.distance(*cc.component_vertex(in_both[std::size_t(v)])) -
                                     field_alone.distance(v)));
  CHECK(worst <= 1e-9 * diagonal(torus));
}

TEST_CASE("distance field: exact on the doubly covered square, second order under refinement", "[distance_field]")
{
  // source at grid point (n/4, n/3) of the top sheet, at the same place for
  // every n (n a multiple of 12); points uniform on the surface, outside the
  // source's one-ring (where the distance is a cone with its apex at a vertex)
  std::vector<double> mean_error, ridge_face_error;
  for(int n : {12, 24, 48})
  {
    const Doubly_covered_square sq = make_doubly_covered_square(n, 0, 0);
    const vertex_descriptor s = sq.top[n / 4 + (n + 1) * (n / 3)];
    const double a = sq.mesh.point(s).x(), b = sq.mesh.point(s).y();
    const Ridge rc = Geodesic_ridge::compute_ridge_curve(sq.mesh, s);
    const auto field = Geodesic_ridge::make_distance_field(sq.mesh, rc);
    const Doubly_covered_square_oracle oracle(a, b);
    const unsigned seed = test_seed(20261202);
    const auto sample = random_face_locations(sq.mesh, 20000, seed);
    double sum = 0, ridge_sum = 0;
    std::size_t count = 0, ridge_count = 0;
    for(const Location& l : sample)
    {
      const Point_3 p = point_at(sq.mesh, l);
      bool near_source = false;
      for(auto v : sq.mesh.vertices_around_face(sq.mesh.halfedge(l.first))) near_source = near_source || v == s;
      if(near_source) continue;
      double exact = std::hypot(p.x() - a, p.y() - b);
      if(sq.bottom_face[std::size_t(l.first)])
      {
        exact = std::numeric_limits<double>::infinity();
        for(const auto& im : oracle.images) exact = std::min(exact, std::hypot(p.x() - im[0], p.y() - im[1]));
      }
      const double err = std::abs(field.distance(l) - exact);
      sum += err;
      ++count;
      if(field.number_of_cells(l.first) > 1) { ridge_sum += err; ++ridge_count; }
    }
    mean_error.push_back(sum / count);
    ridge_face_error.push_back(ridge_sum / std::max<std::size_t>(ridge_count, 1));
    std::cout << "[distance_field] doubly covered square n=" << n << " seed " << seed << ": mean error "
              << mean_error.back() << ", in faces the ridge crosses " << ridge_face_error.back() << " ("
              << ridge_count << " points)\n";
  }
  for(std::size_t i = 1; i < mean_error.size(); ++i)
  {
    INFO("refinement " << i << ": mean error " << mean_error[i - 1] << " -> " << mean_error[i] << ", ridge faces "
                       << ridge_face_error[i - 1] << " -> " << ridge_face_error[i]);
    CHECK(mean_error[i] <= mean_error[i - 1] / 3);       // second order: / 4
    CHECK(ridge_face_error[i] <= ridge_face_error[i - 1] / 3);
  }
}

TEST_CASE("distance field: continuous across the ridge", "[distance_field]")
{
  for(const std::string name : {"bunny_1k.off", "eight.off", "torus_1k.off"})
  {
    const Mesh m = read_data_mesh(name);
    const Ridge rc = Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(0));
    const auto field = Geodesic_ridge::make_distance_field(m, rc);
    const double diag = diagonal(m);
    double worst = 0;
    std::size_t inside = 0;
    for(const auto& pl : rc.polylines)
      for(const auto& p : pl)
      {
        if(p.barycentric[0] == 0 || p.barycentric[1] == 0 || p.barycentric[2] == 0) continue;
        ++inside;
        // the two lowest cells at a ridge point inside a face agree there
        const face_descriptor f(static_cast<Mesh::size_type>(p.face));
        std::vector<double> values;
        for(std::size_t c = 0; c < field.number_of_cells(f); ++c)
        {
          const auto& d = field.cell_field(f, c);
          values.push_back(p.barycentric[0] * d[0] + p.barycentric[1] * d[1] + p.barycentric[2] * d[2]);
        }
        REQUIRE(values.size() >= 2);
        std::sort(values.begin(), values.end());
        worst = std::max(worst, values[1] - values[0]);
      }
    INFO(name << " source 0: " << inside << " ridge points inside faces, largest gap " << worst / diag
              << " of the diagonal");
    CHECK(inside > 0);
    CHECK(worst <= 1e-9 * diag);
  }
}

TEST_CASE("refined mesh: valid, closed, conforming, one cell per face, with both solvers", "[distance_field]")
{
  for(const std::string name : {"bunny_1k.off", "eight.off", "knot_3k.off", "teddy_3k.off"})
    for(int solver = 0; solver < 3; ++solver) // exact, fast marching, exact without the corner fallback
    {
      const Mesh m = read_data_mesh(name);
      namespace p = Geodesic_ridge::parameters;
      const vertex_descriptor s(5);
      // the corner fallback (default) splits more copies at kinks, whose
      // fields need not agree along their edges: bunny_1k had a ridge point
      // on an edge at two exact points that round to one
      const Ridge rc = solver == 0 ? Geodesic_ridge::compute_ridge_curve(m, s)
                     : solver == 1 ? Geodesic_ridge::compute_ridge_curve(m, s, p::solver(Geodesic_ridge::Fast_marching_solver()))
                                   : Geodesic_ridge::compute_ridge_curve(m, s, p::corner_fallback(false));
      const Refined r = refine(m, rc);
      std::ostringstream what;
      what << name << (solver == 0 ? " exact" : solver == 1 ? " fmm" : " exact, no corner fallback")
           << " source vertex 5: " << r.statistics.split_faces
           << " faces split, " << r.statistics.faces << " faces, " << r.statistics.centre_vertices
           << " centre vertices, " << r.statistics.ridge_edges << " ridge edges, disagreement "
           << r.statistics.largest_disagreement;
      std::cout << "[distance_field] " << what.str() << "\n";
      check_refined_mesh(m, rc, r, what.str(), solver != 1);
    }
  // a ridge along mesh edges (the unperturbed square's diagonals) and a source
  // inside a face
  const Doubly_covered_square sq = make_doubly_covered_square(12, 0, 0);
  const Ridge rc_vertex = Geodesic_ridge::compute_ridge_curve(sq.mesh, sq.top[6 + 13 * 6]);
  check_refined_mesh(sq.mesh, rc_vertex, refine(sq.mesh, rc_vertex), "square n=12, source at the centre", true);
  const Location inside(face_descriptor(7), {{0.2, 0.3, 0.5}});
  const Ridge rc_point = Geodesic_ridge::compute_ridge_curve(sq.mesh, inside);
  check_refined_mesh(sq.mesh, rc_point, refine(sq.mesh, rc_point), "square n=12, source inside face 7", true);
}

TEST_CASE("refined mesh: reads back through CGAL's PLY reader with its properties", "[distance_field]")
{
  const Mesh m = read_data_mesh("eight.off");
  const Ridge rc = Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(3));
  Refined r = refine(m, rc);
  r.mesh.remove_property_map(r.on_ridge);
  for(bool binary : {true, false})
  {
    INFO((binary ? "binary" : "ASCII") << " PLY");
    std::stringstream ss(binary ? std::ios::in | std::ios::out | std::ios::binary : std::ios::in | std::ios::out);
    if(binary) CGAL::IO::set_binary_mode(ss); else CGAL::IO::set_ascii_mode(ss);
    ss.precision(17);
    REQUIRE(CGAL::IO::write_PLY(ss, r.mesh));
    Mesh back;
    if(binary) CGAL::IO::set_binary_mode(ss); else CGAL::IO::set_ascii_mode(ss);
    REQUIRE(CGAL::IO::read_PLY(ss, back));
    REQUIRE(back.number_of_vertices() == r.mesh.number_of_vertices());
    REQUIRE(back.number_of_faces() == r.mesh.number_of_faces());
    const auto distance = back.property_map<vertex_descriptor, double>("v:distance");
    const auto source_face = back.property_map<face_descriptor, std::int32_t>("f:source_face");
    REQUIRE(distance.second);
    REQUIRE(source_face.second);
    double worst = 0;
    for(vertex_descriptor v : back.vertices())
      worst = std::max(worst, std::abs(distance.first[v] - r.distance[v]));
    CHECK(worst <= (binary ? 0 : 1e-12 * diagonal(m)));
    bool same_faces = true;
    for(face_descriptor f : back.faces()) same_faces = same_faces && source_face.first[f] == r.source_face[f];
    CHECK(same_faces);
  }
}

TEST_CASE("iso-lines: every level, closed, with cusps at the ridge", "[distance_field]")
{
  const Doubly_covered_square sq = make_doubly_covered_square(24, 0.25, test_seed(20261203));
  const vertex_descriptor s = sq.top[6 + 25 * 8];
  const Ridge rc = Geodesic_ridge::compute_ridge_curve(sq.mesh, s);
  const Refined r = refine(sq.mesh, rc);
  std::vector<double> refined_distance(r.mesh.number_of_vertices());
  for(auto v : r.mesh.vertices()) refined_distance[std::size_t(v)] = r.distance[v];
  const double near = 1e-9;
  const double margin = 0.15; // away from the border and the corners, where the surface folds
  auto inside = [&](const Point_3& p) {
    return std::min({p.x(), p.y(), 1 - p.x(), 1 - p.y()}) > margin;
  };
  const double sharp = check_isolines(r.mesh, refined_distance, rc, 15, near, 0.3 / 24,
                                      "refined square, seed " + std::to_string(sq.seed), inside);
  // plain linear interpolation of the vertex distances: no cusp on the ridge
  // (the ridge runs inside faces, so its points are not on the iso-lines'
  // edges either; measure near it instead)
  const double near_linear = 0.5 * mean_edge_length(sq.mesh);
  const double smooth = check_isolines(sq.mesh, rc.vertex_distances, rc, 15, near_linear, 0.3 / 24,
                                       "vertex distances on the square, seed " + std::to_string(sq.seed), inside);
  std::cout << "[distance_field] iso-lines on the square: sharpest turn on the ridge, region-wise " << sharp
            << " degrees, linear interpolation " << smooth << " degrees (chords of 0.3 grid steps)\n";
  // the cusps: where an iso-line of the refined mesh meets the ridge inside
  // the square, it turns by the angle between the two fronts there (the
  // directions from the two nearest mirror images), up to the chords' error
  {
    const Doubly_covered_square_oracle oracle(sq.mesh.point(s).x(), sq.mesh.point(s).y());
    double largest = 0;
    for(double d : refined_distance) largest = std::max(largest, d);
    std::vector<Geodesic_ridge::Isoline<Point_3> > lines;
    Geodesic_ridge::isolines(r.mesh, CGAL::make_property_map(refined_distance),
                             Geodesic_ridge::equally_spaced_levels(60, largest), std::back_inserter(lines));
    std::vector<double> errors;
    const double min_segment = 0.1 / 24;
    for(const auto& l : lines)
      for(std::size_t i = 1; i + 1 < l.points.size(); ++i)
      {
        const Point_3& p = l.points[i];
        if(!inside(p)) continue;
        // the bottom sheet's field: its two nearest images
        std::vector<std::pair<double, int> > d;
        for(int k = 0; k < 4; ++k) d.emplace_back(std::hypot(p.x() - oracle.images[k][0], p.y() - oracle.images[k][1]), k);
        std::sort(d.begin(), d.end());
        bool on_ridge = false; // the computed ridge, on the bottom sheet
        for(const auto& pl : rc.polylines)
          for(std::size_t j = 0; j + 1 < pl.size() && !on_ridge; ++j)
            on_ridge = CGAL::squared_distance(p, K::Segment_3(pl[j].point, pl[j + 1].point)) <= 1e-18;
        if(!on_ridge) continue;
        const K::Vector_3 a = p - l.points[i - 1], b = l.points[i + 1] - p;
        if(a.squared_length() < min_segment * min_segment || b.squared_length() < min_segment * min_segment) continue;
        const auto& g0 = oracle.images[d[0].second];
        const auto& g1 = oracle.images[d[1].second];
        const double u0x = p.x() - g0[0], u0y = p.y() - g0[1], u1x = p.x() - g1[0], u1y = p.y() - g1[1];
        const double fronts = std::acos(std::max(-1.0, std::min(1.0, (u0x * u1x + u0y * u1y) / (d[0].first * d[1].first)))) * 180 / CGAL_PI;
        const double turn = std::acos(std::max(-1.0, std::min(1.0, a * b / std::sqrt(a.squared_length() * b.squared_length())))) * 180 / CGAL_PI;
        errors.push_back(std::abs(turn - fronts));
      }
    std::sort(errors.begin(), errors.end());
    INFO(errors.size() << " iso-line points on the ridge; turn minus front angle: median "
                       << (errors.empty() ? -1 : errors[errors.size() / 2]) << ", largest "
                       << (errors.empty() ? -1 : errors.back()) << " degrees");
    std::cout << "[distance_field] " << errors.size() << " cusps checked, median error "
              << (errors.empty() ? -1 : errors[errors.size() / 2]) << " degrees\n";
    REQUIRE(errors.size() >= 5);
    CHECK(errors[errors.size() / 2] <= 5);
    CHECK(errors.back() <= 20);
  }
  // the same on a real mesh with both solvers: every level, closed
  const Mesh m = read_data_mesh("bunny_1k.off");
  for(int solver = 0; solver < 2; ++solver)
  {
    namespace p = Geodesic_ridge::parameters;
    const Ridge rcb = solver == 0 ? Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(0))
                                  : Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(0), p::solver(Geodesic_ridge::Fast_marching_solver()));
    const Refined rb = refine(m, rcb);
    std::vector<double> d(rb.mesh.number_of_vertices());
    for(auto v : rb.mesh.vertices()) d[std::size_t(v)] = rb.distance[v];
    check_isolines(rb.mesh, d, rcb, 10, 1e-9 * diagonal(m), 0.3 * mean_edge_length(m), std::string("bunny_1k ") + (solver == 0 ? "exact" : "fmm"),
                   [](const Point_3&) { return true; });
  }
}

TEST_CASE("distance field: bad input is refused", "[distance_field]")
{
  const Mesh m = read_data_mesh("bunny_1k.off");
  const Ridge rc = Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(0));
  const Mesh other = read_data_mesh("eight.off");
  CHECK_THROWS_AS(Geodesic_ridge::make_distance_field(other, rc), Geodesic_ridge::Invalid_parameter_error);
  Mesh out;
  CHECK_THROWS_AS(Geodesic_ridge::refine_mesh_along_ridge(other, rc, out), Geodesic_ridge::Invalid_parameter_error);
  Mesh not_empty = m;
  CHECK_THROWS_AS(Geodesic_ridge::refine_mesh_along_ridge(m, rc, not_empty), Geodesic_ridge::Invalid_parameter_error);
  std::vector<Geodesic_ridge::Isoline<Point_3> > lines;
  std::vector<double> d(m.number_of_vertices(), 1.0);
  CHECK_THROWS_AS(Geodesic_ridge::isolines(m, CGAL::make_property_map(d), {std::nan("")}, std::back_inserter(lines)),
                  Geodesic_ridge::Invalid_parameter_error);
}

namespace {

// Largest distance from the ridge (its points and 8 samples per chord) to the
// analytic cut locus of the doubly covered square (a point on the top sheet
// counts at least its distance to the border).
double square_ridge_error(const Doubly_covered_square& sq, const Doubly_covered_square_oracle& oracle,
                          const std::vector<std::vector<Geodesic_ridge::Ridge_point<Point_3> > >& polylines)
{
  double worst = 0;
  for(const auto& pl : polylines)
    for(std::size_t i = 0; i < pl.size(); ++i)
      for(int j = 0; j < (i + 1 < pl.size() ? 8 : 1); ++j)
      {
        const double t = j / 8.0;
        const Point_3& a = pl[i].point;
        const Point_3& b = i + 1 < pl.size() ? pl[i + 1].point : a;
        const double x = a.x() + t * (b.x() - a.x()), y = a.y() + t * (b.y() - a.y());
        double d = oracle.distance_to_cut_locus({{x, y}});
        if(!sq.bottom_face[pl[i].face])
          d = std::max(d, std::min(std::min(x, 1 - x), std::min(y, 1 - y)));
        worst = std::max(worst, d);
      }
  return worst;
}

} // namespace

TEST_CASE("cone field and ridge: exact on the doubly covered square, far better than linear on real meshes", "[distance_field]")
{
  namespace p = Geodesic_ridge::parameters;
  const auto cone = p::field(Geodesic_ridge::Field::cone);
  // flat sheets: every window's apex is the source or one of its mirror
  // images, so the cones are exact everywhere, the source's one-ring included
  for(const double perturbation : {0.0, 0.25})
  {
    const unsigned seed = test_seed(20261204);
    const Doubly_covered_square sq = make_doubly_covered_square(16, perturbation, seed);
    const vertex_descriptor s = sq.top[4 + 17 * 5];
    const double a = sq.mesh.point(s).x(), b = sq.mesh.point(s).y();
    const Ridge rc = Geodesic_ridge::compute_ridge_curve(sq.mesh, s, cone);
    const auto field = Geodesic_ridge::make_distance_field(sq.mesh, rc, cone);
    CHECK(field.field() == Geodesic_ridge::Field::cone);
    const Doubly_covered_square_oracle oracle(a, b);
    double worst = 0;
    for(const Location& l : random_face_locations(sq.mesh, 20000, seed))
    {
      const Point_3 q = point_at(sq.mesh, l);
      double exact = std::hypot(q.x() - a, q.y() - b);
      if(sq.bottom_face[std::size_t(l.first)])
      {
        exact = std::numeric_limits<double>::infinity();
        for(const auto& im : oracle.images) exact = std::min(exact, std::hypot(q.x() - im[0], q.y() - im[1]));
      }
      worst = std::max(worst, std::abs(field.distance(l) - exact));
    }
    INFO("doubly covered square n=16 perturbation " << perturbation << " seed " << seed << ": largest error " << worst);
    std::cout << "[distance_field] cone field on the square, perturbation " << perturbation << ": largest error "
              << worst << "\n";
    CHECK(worst <= 1e-12);
    // and so is their ridge (straight bisectors of mirror images, junctions
    // where three of them meet), but near a junction where the linear
    // envelope's fronts are not the cones' (see the test below)
    const double cones = square_ridge_error(sq, oracle, rc.cone_polylines);
    const double linear = square_ridge_error(sq, oracle, rc.polylines);
    const auto& st = rc.statistics.cone_ridge;
    INFO("doubly covered square n=16 perturbation " << perturbation << " seed " << seed << ": largest distance to "
         << "the cut locus, linear ridge " << linear << ", cone ridge " << cones << "; moved " << st.points_moved
         << ", junctions " << st.junctions_moved << ", kept " << st.points_kept << ", added " << st.points_added);
    std::cout << "[distance_field] cone ridge on the square, perturbation " << perturbation << ": largest distance "
              << "to the cut locus " << cones << " (linear ridge " << linear << "), moved " << st.points_moved
              << ", junctions " << st.junctions_moved << ", kept " << st.points_kept << "\n";
    CHECK(rc.cone_polylines.size() == rc.polylines.size());
    CHECK(cones <= (perturbation == 0 ? 1e-9 : 0.5 * linear));
    CHECK(st.junctions_moved >= 1);
  }
  // real meshes: against SMSP on M at random points
  for(const std::string name : {"bunny_1k.off", "teddy_3k.off"})
  {
    const Mesh m = read_data_mesh(name);
    const vertex_descriptor s(100);
    const Ridge rc = Geodesic_ridge::compute_ridge_curve(m, s, cone);
    const auto linear = Geodesic_ridge::make_distance_field(m, rc);
    const auto cones = Geodesic_ridge::make_distance_field(m, rc, cone);
    typedef CGAL::Surface_mesh_shortest_path_traits<K, Mesh> Traits;
    CGAL::Surface_mesh_shortest_path<Traits> sp(m);
    sp.add_source_point(s);
    sp.build_sequence_tree();
    double linear_error = 0, cone_error = 0;
    const unsigned seed = test_seed(20261205);
    for(const Location& l : random_face_locations(m, 5000, seed))
    {
      const double exact = sp.shortest_distance_to_source_points(l.first, {{l.second[0], l.second[1], l.second[2]}}).first;
      linear_error += std::abs(linear.distance(l) - exact);
      cone_error += std::abs(cones.distance(l) - exact);
    }
    INFO(name << " source 100 seed " << seed << ": mean error linear " << linear_error / 5000 << ", cone "
              << cone_error / 5000);
    std::cout << "[distance_field] " << name << ": mean error linear " << linear_error / 5000 << ", cone "
              << cone_error / 5000 << "\n";
    CHECK(cone_error <= 0.1 * linear_error);
  }
  // the cone field needs cones, and the exact solver
  const Mesh m = read_data_mesh("bunny_1k.off");
  const Ridge plain = Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(0));
  CHECK_THROWS_AS(Geodesic_ridge::make_distance_field(m, plain, cone), Geodesic_ridge::Invalid_parameter_error);
  CHECK_THROWS_AS(Geodesic_ridge::compute_ridge_curve(
                      m, vertex_descriptor(0), p::field(Geodesic_ridge::Field::cone, p::solver(Geodesic_ridge::Fast_marching_solver()))),
                  Geodesic_ridge::Invalid_parameter_error);
}

TEST_CASE("cone field with window propagation: the windows' lower envelope is the exact distance", "[distance_field][vtp]")
{
  // every window is the length of a real path, and the shortest path to any
  // point runs through one of them: against SMSP on M, within round-off at
  // random points, on genus 0 and 1, with a border, from a vertex and from a
  // point inside a face; and the cone ridge is traced from them
  namespace p = Geodesic_ridge::parameters;
  const auto vtp_cone = p::field(Geodesic_ridge::Field::cone, p::solver(Geodesic_ridge::Window_propagation_solver()));
  const unsigned seed = test_seed(20261206);
  for(const std::string name : {"bunny_1k.off", "armadillo_2k.off", "torus_1k.off", "eight.off", "boundary/open_box.off"})
  {
    const Mesh m = read_data_mesh(name);
    typedef CGAL::Surface_mesh_shortest_path_traits<K, Mesh> Traits;
    for(int k = 0; k < 3; ++k)
    {
      CGAL::Surface_mesh_shortest_path<Traits> sp(m);
      Ridge rc;
      std::string from;
      if(k < 2)
      {
        const vertex_descriptor s(static_cast<Mesh::size_type>((k * 2 + 1) * m.number_of_vertices() / 4));
        sp.add_source_point(s);
        rc = Geodesic_ridge::compute_ridge_curve(m, s, vtp_cone);
        from = "vertex " + std::to_string(std::size_t(s));
      }
      else
      {
        const Location src(face_descriptor(static_cast<Mesh::size_type>(m.number_of_faces() / 3)), {{0.2, 0.3, 0.5}});
        sp.add_source_point(src.first, {{0.2, 0.3, 0.5}});
        rc = Geodesic_ridge::compute_ridge_curve(m, src, vtp_cone);
        from = "a point of face " + std::to_string(std::size_t(src.first));
      }
      sp.build_sequence_tree();
      const auto field = Geodesic_ridge::make_distance_field(m, rc, p::field(Geodesic_ridge::Field::cone));
      double worst = 0;
      for(const Location& l : random_face_locations(m, 3000, seed + k))
      {
        const double exact =
            sp.shortest_distance_to_source_points(l.first, {{l.second[0], l.second[1], l.second[2]}}).first;
        if(exact > 0) worst = std::max(worst, std::abs(field.distance(l) - exact) / exact);
      }
      INFO(name << " from " << from << " seed " << seed + k << ": largest relative error " << worst);
      std::cout << "[distance_field] vtp cone field, " << name << " from " << from << ": largest relative error "
                << worst << "\n";
      CHECK(worst <= 1e-9);
      CHECK(rc.statistics.cone_ridge_traced);
      CHECK(!rc.cone_polylines.empty());
    }
  }
}

TEST_CASE("refined mesh: points of a neighbour's cells on a side make a conforming star", "[distance_field]")
{
  // A tetrahedron whose face 0 holds two copies that cross inside it (and on
  // two of its edges); the other faces hold one copy each, so the crossing
  // points on face 0's edges lie inside their neighbours' sides.
  const std::vector<Point_3> points = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0, 0, 1)};
  const std::vector<std::array<std::size_t, 3> > triangles = {{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{0, 3, 2}}};
  const Mesh m = mesh_from_soup(points, triangles);
  Ridge rc;
  rc.regions.resize(m.number_of_faces());
  rc.vertex_distances.assign(m.number_of_vertices(), 1.0);
  for(face_descriptor f : m.faces())
  {
    Geodesic_ridge::Ridge_region_cell cell;
    cell.copy = std::size_t(f);
    cell.field = {{1.0, 1.0, 1.0}};
    rc.regions[std::size_t(f)].push_back(cell);
  }
  // face 0: fields (0.6, 1.4, 1.0) and (1.4, 0.6, 1.0) cross on the line λ0 = λ1
  rc.regions[0][0].field = {{0.6, 1.4, 1.0}};
  Geodesic_ridge::Ridge_region_cell other = rc.regions[0][0];
  other.copy = 99;
  other.field = {{1.4, 0.6, 1.0}};
  rc.regions[0].push_back(other);
  const Refined r = refine(m, rc);
  INFO("split faces " << r.statistics.split_faces << ", centre vertices " << r.statistics.centre_vertices
                      << ", faces " << r.statistics.faces);
  CHECK(r.statistics.split_faces >= 2);
  CHECK(r.statistics.centre_vertices >= 1);
  check_refined_mesh(m, rc, r, "tetrahedron with two crossing copies on face 0", false);
}


TEST_CASE("cone ridge: the cones agree on it on real meshes", "[distance_field]")
{
  namespace p = Geodesic_ridge::parameters;
  const auto cone = p::field(Geodesic_ridge::Field::cone);
  // real meshes: the two lowest cones agree at every moved point; the ends
  // are those of the linear ridge but for junctions inside faces
  for(const std::string name : {"bunny_1k.off", "eight.off", "torus_1k.off"})
  {
    const Mesh m = read_data_mesh(name);
    // The tracer moves points between the cones of different copies. The
    // kinks inside one sheet (copies split by their cones, parameters::kink_angle)
    // run between the fronts of one copy, and their points stay where the
    // linear ridge put them: with them, bunny_1k keeps 292 of 765 points.
    // The tracer is tested here without them; with them, it moves nothing far.
    {
      const Ridge with_kinks = Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(100), cone);
      CHECK(with_kinks.cone_polylines.size() == with_kinks.polylines.size());
      CHECK(with_kinks.statistics.cone_ridge.largest_move < 1);
    }
    const Ridge rc = Geodesic_ridge::compute_ridge_curve(m, vertex_descriptor(100), p::kink_angle(0, cone));
    const double h = mean_edge_length(m);
    const auto& st = rc.statistics.cone_ridge;
    REQUIRE(rc.cone_polylines.size() == rc.polylines.size());
    std::size_t on_curve = 0, interior = 0, continuous = 0;
    auto kept = [&](const Geodesic_ridge::Ridge_point<Point_3>& q) {
      for(const auto& pl : rc.polylines)
        for(const auto& p : pl)
          if(p.point == q.point) return true;
      return false;
    };
    double largest_gap = 0;
    for(std::size_t i = 0; i < rc.polylines.size(); ++i)
    {
      const auto& lin = rc.polylines[i];
      const auto& con = rc.cone_polylines[i];
      REQUIRE(con.size() >= lin.size());
      CHECK(CGAL::squared_distance(lin.front().point, con.front().point) <= 4 * h * h);
      CHECK(CGAL::squared_distance(lin.back().point, con.back().point) <= 4 * h * h);
      for(std::size_t j = 1; j + 1 < con.size(); ++j)
      {
        const auto& q = con[j];
        const auto corners = Geodesic_ridge::internal::Faces_by_index<Mesh, decltype(m.points())>(
                                 m, m.points(), get(CGAL::face_index, m)).corner_points(q.face);
        const Geodesic_ridge::internal::Face_plane plane(corners);
        const auto& cs = rc.cones[q.face];
        const Geodesic_ridge::internal::Face_cone_field field(plane, cs.data(), cs.size());
        ++interior;
        if(kept(q)) continue; // where the linear ridge put it
        const auto x = plane.point(q.barycentric);
        std::vector<std::pair<double, std::size_t> > values;
        for(std::size_t c = 0; c < field.number_of_copies(); ++c) values.push_back({field.value(c, x), c});
        std::sort(values.begin(), values.end());
        if(values.size() < 2) continue;
        // where the two lowest copies keep their cones on a small disc around
        // the point (no change of window), they must agree at it
        bool same_cones = true;
        for(int k = 0; k < 8 && same_cones; ++k)
        {
          const double phi = k * CGAL_PI / 4, eps = 1e-6 * h;
          const auto y = x + eps * Geodesic_ridge::internal::Face_plane::Vector_2(std::cos(phi), std::sin(phi));
          for(int j = 0; j < 2; ++j)
            same_cones = same_cones && field.apex(values[j].second, x) == field.apex(values[j].second, y);
        }
        if(!same_cones) continue;
        ++continuous;
        const double gap = values[1].first - values[0].first;
        if(gap <= 1e-9 * h) ++on_curve;
        largest_gap = std::max(largest_gap, gap / h);
      }
    }
    const std::string summary = name + " source 100: of " + std::to_string(interior) + " inner points, " +
                                std::to_string(continuous) + " moved or added where the two lowest cones stay the same nearby, two cones agree at " +
                                std::to_string(on_curve) + " (largest gap " + std::to_string(largest_gap) +
                                " mean edges); moved " + std::to_string(st.points_moved) + ", kept " +
                                std::to_string(st.points_kept) + ", added " + std::to_string(st.points_added) +
                                ", junctions " + std::to_string(st.junctions_moved) + ", largest move " +
                                std::to_string(st.largest_move) + " mean edges";
    INFO(summary);
    std::cout << "[distance_field] cone ridge " << summary << "\n";
    CHECK(on_curve == continuous);
    CHECK(continuous >= 0.5 * interior);
    CHECK(st.points_kept <= 0.35 * (st.points_kept + st.points_moved));
    CHECK(st.largest_move < 1);
  }
  CHECK_THROWS_AS(Geodesic_ridge::compute_ridge_curve(read_data_mesh("bunny_1k.off"), vertex_descriptor(0),
                                                      p::cone_ridge_tolerance(0, cone)),
                  Geodesic_ridge::Invalid_parameter_error);
}


TEST_CASE("cone ridge: exact on the doubly covered square but near some junctions", "[slow][distance_field]")
{
  // Every point and chord of the cone ridge lies on the analytic cut locus
  // (within 1e-9), except where the linear ridge has a junction of three
  // fronts of which the face's cones hold only two (the cones' junction lies
  // in a neighbouring face): that junction stays, and so do the chords to it.
  // Measured on 24 perturbed squares: 21 exact to 4e-15, 3 within 6e-5 to
  // 4e-4 (the linear ridge: 4e-4 to 1e-3).
  namespace p = Geodesic_ridge::parameters;
  std::size_t exact = 0, runs = 0;
  for(int n : {16, 24})
    for(unsigned k = 1; k <= 12; ++k)
    {
      const unsigned seed = test_seed(k);
      const Doubly_covered_square sq = make_doubly_covered_square(n, 0.25, seed);
      const vertex_descriptor s = sq.top[n / 4 + (n + 1) * (n / 3)];
      const Ridge rc = Geodesic_ridge::compute_ridge_curve(sq.mesh, s, p::field(Geodesic_ridge::Field::cone));
      const Doubly_covered_square_oracle oracle(sq.mesh.point(s).x(), sq.mesh.point(s).y());
      const double cones = square_ridge_error(sq, oracle, rc.cone_polylines),
                   linear = square_ridge_error(sq, oracle, rc.polylines);
      INFO("n " << n << " perturbation 0.25 seed " << seed << ": cone ridge " << cones << ", linear ridge " << linear);
      CHECK(cones <= 0.5 * linear);
      exact += cones <= 1e-9;
      ++runs;
    }
  std::cout << "[distance_field] cone ridge exact on " << exact << " of " << runs << " perturbed squares\n";
  CHECK(exact >= 0.8 * runs);
}
