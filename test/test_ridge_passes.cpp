// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3's passes one at a time (include/Geodesic_ridge/internal/ridge_curve/),
// on a few faces with copies and fields made by hand, or on a ridge graph
// whose nodes and segments are set directly: what each pass must do, without
// the pipeline around it. The whole stage on real meshes and analytic cases:
// test_ridge_curve.cpp; the copy splitters: test_ridge_curve.cpp ("a copy is
// split at a kink between its corners' fronts") and test_ridge_accuracy.cpp;
// the two joining passes (border loops, verified pieces) need a whole
// pipeline's cells: test_ridge_curve.cpp ("surfaces with several border
// loops: ...") and test_boundary_meshes.cpp.
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/internal/corner_angles.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/ridge_curve/assemble_ridge_curve.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef decltype(Geodesic_ridge::internal::mesh_maps(std::declval<const Mesh&>(),
                                                     CGAL::parameters::default_values())) Maps;
typedef Geodesic_ridge::internal::Ridge_graph<Mesh, Maps> Graph;
typedef Graph::Segment Segment;
using Geodesic_ridge::internal::Face_copies;
using Geodesic_ridge::internal::Ridge_pass;
using Geodesic_ridge::internal::Ridge_passes;
constexpr std::size_t none = Graph::none;

Mesh mesh_of(const std::vector<Point_3>& points, const std::vector<std::array<int, 3> >& faces)
{
  Mesh m;
  for(const Point_3& p : points) m.add_vertex(p);
  for(const auto& f : faces) REQUIRE(m.add_face(Mesh::Vertex_index(f[0]), Mesh::Vertex_index(f[1]), Mesh::Vertex_index(f[2])) != Mesh::null_face());
  return m;
}

// the unit square in z = 0, two faces glued along the diagonal from (0, 0) to (1, 1)
Mesh square() { return mesh_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{{0, 1, 2}}, {{0, 2, 3}}}); }

// Everything a Ridge_graph refers to, and the graph itself. E is M itself (one
// copy per face, glued as M's faces are) unless `E.mesh` is set otherwise
// before `graph()`.
struct Stage3
{
  Mesh m;
  Geodesic_ridge::Extended_surface<Point_3> E;
  std::vector<Face_copies> copies;
  std::vector<double> angle_sum;
  std::vector<std::vector<Geodesic_ridge::Ridge_region_cell> > regions;
  Geodesic_ridge::Ridge_curve_statistics statistics;
  Maps maps;
  std::unique_ptr<Graph> ridge;

  explicit Stage3(Mesh mesh) : m(std::move(mesh)), maps(Geodesic_ridge::internal::mesh_maps(m, CGAL::parameters::default_values()))
  {
    E.mesh = m;
    for(std::size_t f = 0; f < m.number_of_faces(); ++f) E.original_face.push_back(f);
    for(std::size_t v = 0; v < m.number_of_vertices(); ++v) E.original_vertex.push_back(v);
    E.source_is_vertex = false;
    E.source_location.first = Mesh::Face_index(1000); // (no face of these meshes holds the source)
    copies.resize(m.number_of_faces());
    // the angle sums, as the pipeline has them
    angle_sum = Geodesic_ridge::internal::corner_angles(m, maps.vpm, maps.vim, maps.fim).angle_sum;
  }

  // copy `copy` of E on face f, its field the distance from `apex` in the plane, plus `offset`
  void add_copy(std::size_t f, std::size_t copy, const Point_3& apex, double offset = 0)
  {
    std::array<double, 3> field;
    auto h = m.halfedge(Mesh::Face_index(static_cast<Mesh::size_type>(f)));
    for(int k = 0; k < 3; ++k, h = m.next(h))
      field[k] = std::sqrt(CGAL::to_double(CGAL::squared_distance(m.point(m.source(h)), apex))) + offset;
    copies[f].copies.push_back(copy);
    copies[f].fields.push_back(field);
  }

  Graph& graph(double minimum_angle = 15, double kink_angle = 60)
  {
    ridge = std::make_unique<Graph>(m, E, copies, 1.0, minimum_angle, kink_angle, maps, angle_sum, regions, statistics,
                                    nullptr);
    ridge->label_border_loops();
    return *ridge;
  }
};

// a ridge node inside face f at barycentric coordinates b (CGAL's corner order)
std::size_t add_node(Graph& g, std::size_t f, const std::array<double, 3>& b)
{
  Geodesic_ridge::Ridge_point<Point_3> p;
  p.face = f;
  p.barycentric = b;
  const auto corners = g.faces.corner_points(f);
  p.point = CGAL::barycenter(corners[0], b[0], corners[1], b[1], corners[2], b[2]);
  g.nodes.push_back(p);
  g.node_loop.push_back(none);
  return g.nodes.size() - 1;
}

void add_segment(Graph& g, std::size_t a, std::size_t b, double angle, double strength = 1)
{
  g.segments.push_back(Segment{a, b, 0, 0, strength, angle, true});
}

std::size_t ridge_segments(const Graph& g)
{
  std::size_t n = 0;
  for(const Segment& s : g.segments) n += s.ridge;
  return n;
}

} // namespace

TEST_CASE("envelope_cells and segments_inside_faces: two fronts crossing a face meet at one envelope edge",
          "[ridge_passes]")
{
  Stage3 s(square());
  // face 0: fronts from the left and from the right cross it; face 1: one copy
  s.add_copy(0, 0, Point_3(-1, 0.5, 0));
  s.add_copy(0, 2, Point_3(2, 0.5, 0));
  s.add_copy(1, 1, Point_3(-1, 0.5, 0));
  Graph& g = s.graph();
  Geodesic_ridge::internal::envelope_cells(g);
  CHECK(g.cells.size() == 3);
  CHECK(s.statistics.surviving_copies == 3);
  CHECK(s.statistics.faces_with_several_copies == 1);
  CHECK(s.regions[0].size() == 2);
  CHECK(s.regions[1].size() == 1);
  Geodesic_ridge::internal::segments_inside_faces(g);
  REQUIRE(s.statistics.envelope_segments == 1);
  REQUIRE(g.segments.size() == 1);
  // the fronts arrive from opposite sides: their linear fields' gradients are far apart
  CHECK(g.segments[0].angle > 90);
  CHECK(g.fronts.find(g.segments[0].left) != g.fronts.find(g.segments[0].right));
}

TEST_CASE("segments_inside_faces: fields equal within the solver's noise are one front", "[ridge_passes]")
{
  Stage3 s(square());
  s.add_copy(0, 0, Point_3(-1, 0.5, 0));
  s.copies[0].copies.push_back(2);
  std::array<double, 3> nearly = s.copies[0].fields[0];
  nearly[0] += 1e-9; // below `tuning::ridge::same_front` mean edges
  nearly[1] -= 1e-9;
  s.copies[0].fields.push_back(nearly);
  s.add_copy(1, 1, Point_3(-1, 0.5, 0));
  Graph& g = s.graph();
  Geodesic_ridge::internal::envelope_cells(g);
  REQUIRE(g.cells.size() == 3);
  Geodesic_ridge::internal::segments_inside_faces(g);
  CHECK(s.statistics.envelope_segments == 0);
  CHECK(g.segments.empty());
  CHECK(g.fronts.find(0) == g.fronts.find(1));
}

TEST_CASE("thin_faces: a needle is thin, a fair triangle is not", "[ridge_passes]")
{
  Stage3 s(mesh_of({{0, 0, 0}, {1, 0, 0}, {0.5, 1e-3, 0}, {0.5, -1, 0}}, {{{0, 1, 2}}, {{1, 0, 3}}}));
  s.add_copy(0, 0, Point_3(0, 0, 0));
  s.add_copy(1, 1, Point_3(0, 0, 0));
  Graph& g = s.graph();
  Geodesic_ridge::internal::thin_faces(g);
  REQUIRE(g.thin.size() == 2);
  CHECK(g.thin[0] == 1);
  CHECK(g.thin[1] == 0);
}

TEST_CASE("segments_along_edges: an edge between sheets, or a kink inside one sheet, is ridge", "[ridge_passes]")
{
  const Point_3 left(-1, 0.5, 0), below(0.5, -3, 0);
  auto run = [&](bool glued, const Point_3& apex1, double kink_angle) {
    Stage3 s(square());
    if(!glued) // E: the two faces apart (two sheets)
      s.E.mesh = mesh_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{{0, 1, 2}}, {{3, 4, 5}}});
    s.add_copy(0, 0, left);
    s.add_copy(1, 1, apex1);
    Graph& g = s.graph(15, kink_angle);
    Geodesic_ridge::internal::envelope_cells(g);
    Geodesic_ridge::internal::segments_inside_faces(g);
    Geodesic_ridge::internal::thin_faces(g);
    Geodesic_ridge::internal::segments_along_edges(g);
    return std::make_pair(s.statistics.edge_segments, g.fronts.find(0) == g.fronts.find(1));
  };
  // one sheet, one front: no ridge, one front
  CHECK(run(true, left, 60) == std::make_pair(std::size_t(0), true));
  // two sheets, two fronts: the diagonal is a ridge segment
  CHECK(run(false, below, 60) == std::make_pair(std::size_t(1), false));
  // two sheets whose fields agree along the diagonal and jump not at all: one front
  CHECK(run(false, left, 60) == std::make_pair(std::size_t(0), true));
  // one sheet, but fronts from the left and from below: a kink well above 60
  // degrees across the diagonal, a ridge with the kink rule, none without it
  CHECK(run(true, below, 60).first == 1);
  CHECK(run(true, below, 0) == std::make_pair(std::size_t(0), true));
}

TEST_CASE("merge_into_one_region removes the weakest segment between two regions; rejoin_pieces puts back a link",
          "[ridge_passes]")
{
  {
    Stage3 s(square());
    Graph& g = s.graph();
    for(std::size_t c = 0; c < 2; ++c) // two regions (cells 0 and 1)
    {
      g.cells.push_back(Graph::Cell{c, {{0, 0, 0}}, {{0, 0, 0}}, false, 0});
      g.fronts.add();
    }
    const std::size_t a = add_node(g, 0, {{0.6, 0.2, 0.2}}), b = add_node(g, 0, {{0.2, 0.6, 0.2}}),
                      c = add_node(g, 0, {{0.2, 0.2, 0.6}});
    g.segments.push_back(Segment{a, b, 0, 1, 2.0, 30, true});
    g.segments.push_back(Segment{b, c, 0, 1, 0.5, 10, true}); // the weaker
    Geodesic_ridge::internal::merge_into_one_region(g);
    CHECK(s.statistics.regions_before_merge == 2);
    CHECK(s.statistics.merged_segments == 1);
    CHECK(g.segments[0].ridge);
    CHECK_FALSE(g.segments[1].ridge);
  }
  {
    // two pieces of ridge, a-b and c-d, and a merged segment b-c between them
    Stage3 s(square());
    Graph& g = s.graph();
    std::vector<std::size_t> n;
    for(double t : {0.1, 0.3, 0.5, 0.7}) n.push_back(add_node(g, 0, {{1 - t - 0.1, t, 0.1}}));
    add_segment(g, n[0], n[1], 30);
    g.segments.push_back(Segment{n[1], n[2], 0, 0, 1.0, 30, false});
    add_segment(g, n[2], n[3], 30);
    Geodesic_ridge::internal::rejoin_pieces(g);
    CHECK(s.statistics.rejoined_segments == 1);
    CHECK(ridge_segments(g) == 3);
  }
}

// A junction inside the flat square (no curvature anywhere: its vertices are
// on the border) with three branches: a weak one (5 degrees), a moderate one
// (30 degrees, below three times the minimum angle of 15) and a strong one
// (80 degrees).
TEST_CASE("prune_spurs: each rule prunes what it names, and only when it is on", "[ridge_passes]")
{
  auto run = [](unsigned disabled) {
    Stage3 s(square());
    Graph& g = s.graph();
    const std::size_t junction = add_node(g, 0, {{0.4, 0.3, 0.3}});
    add_segment(g, junction, add_node(g, 0, {{0.6, 0.2, 0.2}}), 5);
    add_segment(g, junction, add_node(g, 0, {{0.2, 0.6, 0.2}}), 30);
    add_segment(g, junction, add_node(g, 0, {{0.2, 0.2, 0.6}}), 80);
    Geodesic_ridge::internal::prune_spurs(g, Ridge_passes{disabled});
    return std::make_pair(ridge_segments(g), s.statistics);
  };
  {
    const auto [left, st] = run(0);
    // the weak branch away from any corner and the flat end go; the strong
    // branch stays, and with it the junction's last segment
    CHECK(left == 1);
    CHECK(st.spurs_away_from_corners == 1);
    CHECK(st.pruned_flat_end_segments == 1);
    CHECK(st.pruned_spur_segments == 1);
    CHECK(st.spurs_at_impossible_ends + st.spurs_too_weak_for_corners == 0);
  }
  {
    const auto [left, st] = run(unsigned(Ridge_pass::spur_away_from_corner));
    // the weak branch is not pruned as weak; it is a flat end (5 < 45 degrees)
    CHECK(left == 1);
    CHECK(st.spurs_away_from_corners == 0);
    CHECK(st.pruned_flat_end_segments == 2);
  }
  {
    const auto [left, st] = run(unsigned(Ridge_pass::spur_away_from_corner) | unsigned(Ridge_pass::spur_flat_end));
    CHECK(left == 3);
    CHECK(st.pruned_spur_segments + st.pruned_flat_end_segments == 0);
  }
}

TEST_CASE("prune_spurs: a weak end at a flat inner vertex goes with the weak chain behind it", "[ridge_passes]")
{
  // the square with its centre (vertex 4) inside: angle sum 2 pi, no curvature
  auto run = [](unsigned disabled) {
    Stage3 s(mesh_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}},
                     {{{0, 1, 4}}, {{1, 2, 4}}, {{2, 3, 4}}, {{3, 0, 4}}}));
    Graph& g = s.graph();
    // the centre is corner k of face 0 where that corner's barycentric coordinate is 1
    const auto corners = g.faces.corner_points(0);
    std::array<double, 3> at_centre = {{0, 0, 0}};
    for(int k = 0; k < 3; ++k) if(corners[k] == Point_3(0.5, 0.5, 0)) at_centre[k] = 1;
    const std::size_t centre = add_node(g, 0, at_centre), middle = add_node(g, 0, {{0.3, 0.3, 0.4}}),
                      junction = add_node(g, 0, {{0.4, 0.4, 0.2}});
    add_segment(g, centre, middle, 10);
    add_segment(g, middle, junction, 10);
    add_segment(g, junction, add_node(g, 1, {{0.3, 0.3, 0.4}}), 80);
    add_segment(g, junction, add_node(g, 2, {{0.3, 0.3, 0.4}}), 80);
    Geodesic_ridge::internal::prune_spurs(g, Ridge_passes{disabled});
    return s.statistics;
  };
  const auto st = run(0);
  CHECK(st.spurs_at_impossible_ends == 2); // the end at the centre, and the segment behind it
  CHECK(st.spurs_away_from_corners == 0);
  // without the rule, the same two go as weak ends away from a corner
  const auto without = run(unsigned(Ridge_pass::spur_at_impossible_end));
  CHECK(without.spurs_at_impossible_ends == 0);
  CHECK(without.spurs_away_from_corners == 2);
}

TEST_CASE("prune_spurs: a weak end near a corner stays, unless its jump is too small for a corner", "[ridge_passes]")
{
  // a pyramid without its base: the apex's angle deficit is about 128 degrees
  const Mesh pyramid = mesh_of({{0, 0, 1.5}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}},
                               {{{0, 1, 2}}, {{0, 2, 3}}, {{0, 3, 4}}, {{0, 4, 1}}});
  auto run = [&](double weak_angle) {
    Stage3 s(pyramid);
    Graph& g = s.graph();
    const std::size_t junction = add_node(g, 0, {{0.5, 0.25, 0.25}});
    add_segment(g, junction, add_node(g, 1, {{0.6, 0.2, 0.2}}), weak_angle);
    add_segment(g, junction, add_node(g, 2, {{0.6, 0.2, 0.2}}), 80);
    add_segment(g, junction, add_node(g, 3, {{0.6, 0.2, 0.2}}), 80);
    Geodesic_ridge::internal::prune_spurs(g, Ridge_passes{});
    return std::make_pair(ridge_segments(g), s.statistics);
  };
  const auto [kept, st] = run(10); // weak (below 15), but at a corner with a corner's jump
  CHECK(kept == 3);
  CHECK(st.pruned_spur_segments == 0);
  const auto [left, st2] = run(1); // below 15 / 3 degrees: no corner's end
  CHECK(left == 2);
  CHECK(st2.spurs_too_weak_for_corners == 1);
}

TEST_CASE("keep_main_component, count_topology and chains_as_polylines on a closed surface", "[ridge_passes]")
{
  Stage3 s(mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{0, 3, 2}}}));
  Graph& g = s.graph();
  REQUIRE(g.number_of_loops == 0);
  // a long chain of three segments with a branch at its second node, and a short piece apart
  const std::size_t a = add_node(g, 0, {{0.8, 0.1, 0.1}}), b = add_node(g, 0, {{0.1, 0.8, 0.1}}),
                    c = add_node(g, 0, {{0.1, 0.1, 0.8}}), d = add_node(g, 1, {{0.1, 0.1, 0.8}}),
                    e = add_node(g, 2, {{0.1, 0.8, 0.1}});
  add_segment(g, a, b, 40);
  add_segment(g, b, c, 50);
  add_segment(g, c, d, 60);
  add_segment(g, b, e, 70);
  const std::size_t p = add_node(g, 3, {{0.3, 0.3, 0.4}}), q = add_node(g, 3, {{0.3, 0.35, 0.35}});
  add_segment(g, p, q, 20);
  const auto kept = Geodesic_ridge::internal::keep_main_component(g);
  CHECK(kept.size() == 4);
  CHECK(s.statistics.dropped_components == 1);
  CHECK(g.nodes[b].angle == 70); // the largest jump over its segments
  Geodesic_ridge::internal::count_topology(g, kept);
  CHECK(s.statistics.ridge_segments == 4);
  CHECK(s.statistics.junctions == 1);
  CHECK(s.statistics.free_ends == 3);
  CHECK(s.statistics.components == 1);
  CHECK(s.statistics.cycles == 0);
  std::vector<std::vector<Geodesic_ridge::Ridge_point<Point_3> > > polylines;
  Geodesic_ridge::internal::chains_as_polylines(g, kept, polylines);
  CHECK(polylines.size() == 3); // the three chains from the junction
  std::size_t points = 0;
  for(const auto& pl : polylines) points += pl.size();
  CHECK(points == 7); // 4 segments: each chain has its ends
}

// Every switch of `Ridge_passes` can be turned off alone: the pipeline then
// gives a ridge or a typed error, never a crash (with the thin-faces pass off,
// stage 3 once read the thin-face flags it had not made).
TEST_CASE("every pass switch off alone: a ridge or a typed error", "[ridge_passes]")
{
  // a tetrahedron with one vertex pulled out: faces of several shapes, one closed surface
  const Mesh m = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.3, 2}}, {{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{0, 3, 2}}});
  for(const auto& [name, pass] : Geodesic_ridge::internal::ridge_pass_names())
  {
    INFO("switched off: " << name);
    try
    {
      const auto rc = Geodesic_ridge::compute_ridge_curve(
          m, Mesh::Vertex_index(0), Geodesic_ridge::parameters::disabled_ridge_passes(static_cast<unsigned>(pass)));
      CHECK(rc.statistics.ridge.components == 1);
    }
    catch(const Geodesic_ridge::Algorithm_error&)
    {
      SUCCEED("a typed error");
    }
  }
}
