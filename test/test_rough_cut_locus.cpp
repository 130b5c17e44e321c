// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1 (rough cut locus): significance against brute force and the paper's
// Algorithm 1, and the disk property over tolerance sweeps on meshes of genus
// 0 to 3, checked by actually cutting the mesh open.
#include <Geodesic_ridge/IO/polylines.h>
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/rough_cut_locus.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/subdivision_method_3.h>

#include "support/analytic_meshes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <deque>
#include <filesystem>
#include <iostream>
#include <array>
#include <map>
#include <sstream>
#include <set>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Mesh;
typedef Mesh::Vertex_index                                  vertex_descriptor;
typedef Mesh::Halfedge_index                                halfedge_descriptor;
typedef Mesh::Edge_index                                    edge_descriptor;
typedef Mesh::Face_index                                    face_descriptor;
typedef Geodesic_ridge::Rough_cut_locus<Mesh>               RCL;

Mesh load(const std::string& name)
{
  Mesh m;
  Geodesic_ridge::IO::read_triangle_mesh(std::string(GEODESIC_RIDGE_DATA_DIR) + "/" + name, m);
  return m;
}

std::vector<double> face_areas(const Mesh& m)
{
  std::vector<double> a(m.number_of_faces());
  for(face_descriptor f : m.faces()) a[f.idx()] = CGAL::Polygon_mesh_processing::face_area(f, m);
  return a;
}

// Significance by definition: remove the dual edge from T*, flood-fill one side.
std::vector<double> brute_force_significance(const Mesh& m, const RCL& r)
{
  const std::vector<double> area = face_areas(m);
  std::vector<char> is_source_face(m.number_of_faces(), 0);
  double node_total = r.total_area;
  for(face_descriptor f : r.source.faces) { is_source_face[f.idx()] = 1; node_total -= area[f.idx()]; }
  std::vector<char> is_dual(m.number_of_edges(), 0);
  for(edge_descriptor e : r.dual_edges) is_dual[e.idx()] = 1;
  std::vector<double> result(m.number_of_edges(), std::nan(""));
  std::vector<int> seen(m.number_of_faces(), -1);
  int stamp = 0;
  for(edge_descriptor removed : r.dual_edges)
  {
    ++stamp;
    const face_descriptor f1 = m.face(m.halfedge(removed)), f2 = m.face(m.opposite(m.halfedge(removed)));
    std::deque<face_descriptor> q{f1};
    seen[f1.idx()] = stamp;
    double side = 0;
    while(!q.empty())
    {
      const face_descriptor f = q.front();
      q.pop_front();
      side += area[f.idx()];
      for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m))
      {
        const edge_descriptor e = m.edge(h);
        if(!is_dual[e.idx()] || e == removed) continue;
        const face_descriptor g = m.face(m.opposite(h));
        if(seen[g.idx()] != stamp) { seen[g.idx()] = stamp; q.push_back(g); }
      }
    }
    // The 2-core (the 2g cycles and the paths joining them) is never pruned:
    // a dual edge whose removal leaves a cycle on both sides counts as the total.
    std::size_t side_nodes = 0, side_edge_ends = 0;
    for(std::size_t f = 0; f < seen.size(); ++f)
      if(seen[f] == stamp)
      {
        ++side_nodes;
        for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(face_descriptor(Mesh::size_type(f))), m))
          side_edge_ends += is_dual[m.edge(h).idx()] && m.edge(h) != removed;
      }
    const long nodes = static_cast<long>(m.number_of_faces() - r.source.faces.size());
    const long all_edges = static_cast<long>(r.dual_edges.size()) - 1;
    const long side_edges = static_cast<long>(side_edge_ends / 2);
    const bool cycle_on_this_side = side_edges >= static_cast<long>(side_nodes);
    const bool cycle_on_other_side = all_edges - side_edges >= nodes - static_cast<long>(side_nodes);
    if(seen[f2.idx()] == stamp || (cycle_on_this_side && cycle_on_other_side))
      result[removed.idx()] = r.total_area;
    else
      result[removed.idx()] = std::min(side, node_total - side);
  }
  return result;
}

// The paper's Algorithm 1 (appendix), for a tree T*: walk from every leaf along
// degree-2 nodes accumulating areas; a degree-3 node waits for two branches,
// then the walk goes on through its third edge. Edge significance is
// min(phi, total - phi) of the side walked from.
std::map<std::size_t, double> paper_algorithm_1(const Mesh& m, const RCL& r)
{
  const std::vector<double> area = face_areas(m);
  const double total = r.total_area;
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > adj(m.number_of_faces()); // (face, edge)
  for(edge_descriptor e : r.dual_edges)
  {
    const std::size_t f1 = m.face(m.halfedge(e)).idx(), f2 = m.face(m.opposite(m.halfedge(e))).idx();
    adj[f1].emplace_back(f2, e.idx());
    adj[f2].emplace_back(f1, e.idx());
  }
  std::map<std::size_t, double> significance;
  std::map<std::size_t, std::pair<double, std::size_t> > waiting; // degree-3 node -> (phi, edge it came by)
  for(std::size_t leaf = 0; leaf < adj.size(); ++leaf)
  {
    if(adj[leaf].size() != 1) continue;
    double phi = area[leaf];
    std::size_t last = leaf, via = adj[leaf][0].second, next = adj[leaf][0].first;
    for(;;)
    {
      if(significance.count(via)) break; // the walk from the other side got here
      significance[via] = std::min(phi, total - phi);
      if(adj[next].size() == 2)
      {
        phi += area[next];
        const auto& other = adj[next][0].second == via ? adj[next][1] : adj[next][0];
        last = next;
        via = other.second;
        next = other.first;
      }
      else if(adj[next].size() == 3)
      {
        auto it = waiting.find(next);
        if(it == waiting.end()) { waiting[next] = {phi, via}; break; }
        phi = it->second.first + phi + area[next];
        std::size_t third = 0;
        for(std::size_t k = 0; k < 3; ++k)
          if(adj[next][k].second != via && adj[next][k].second != it->second.second) third = k;
        last = next;
        via = adj[next][third].second;
        next = adj[next][third].first;
      }
      else break; // the other leaf of a path
    }
    (void)last;
  }
  return significance;
}

struct Cut_surface
{
  Mesh mesh;
  std::vector<std::size_t> copy_of_halfedge_target; // per halfedge of M: vertex of the cut mesh
};

// Cuts M open along K for real: every vertex is split into one copy per sector
// between consecutive cut edges around it; faces keep their corners' copies.
Cut_surface cut_open(const Mesh& m, const RCL& r)
{
  Cut_surface c;
  c.copy_of_halfedge_target.assign(m.number_of_halfedges(), 0);
  std::vector<Point_3> points;
  for(vertex_descriptor v : m.vertices())
  {
    halfedge_descriptor start = m.halfedge(v);
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, m))
      if(r.is_cut_edge[m.edge(h).idx()]) { start = h; break; }
    std::size_t id = points.size();
    points.push_back(m.point(v));
    halfedge_descriptor h = start;
    do
    {
      if(h != start && r.is_cut_edge[m.edge(h).idx()]) { id = points.size(); points.push_back(m.point(v)); }
      c.copy_of_halfedge_target[h.idx()] = id;
      h = m.opposite(m.next(h));
    } while(h != start);
  }
  std::vector<std::vector<std::size_t> > polygons;
  for(face_descriptor f : m.faces())
  {
    std::vector<std::size_t> poly;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m))
      poly.push_back(c.copy_of_halfedge_target[h.idx()]);
    polygons.push_back(poly);
  }
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, c.mesh);
  return c;
}

// Everything stage 1 promises, checked independently of the stage's own check.
void check_rough_cut_locus(const Mesh& m, const RCL& r, double tolerance, int genus)
{
  const auto& st = r.statistics;
  INFO("tolerance " << tolerance);
  REQUIRE(st.genus == genus);
  REQUIRE(r.dual_edges.size() == m.number_of_faces() - r.source.faces.size() - 1 + 2 * genus);

  // pruning by significance
  // (a false branch is significant, but pruned for the curvature it encloses)
  std::size_t kept = 0, false_branch = 0, wrongly_kept = 0, wrongly_pruned = 0;
  for(edge_descriptor e : r.dual_edges)
  {
    const double I = r.significance[e.idx()];
    if(r.edge_role[e.idx()] == Geodesic_ridge::Edge_role::dual_kept)
    {
      ++kept;
      wrongly_kept += !st.fallback_single_rung && !(I >= tolerance * r.total_area);
    }
    else if(r.edge_role[e.idx()] == Geodesic_ridge::Edge_role::dual_false_branch)
    {
      ++false_branch;
      wrongly_pruned += !(I >= tolerance * r.total_area);
    }
    else
      wrongly_pruned += !(I < tolerance * r.total_area);
  }
  REQUIRE(wrongly_kept == 0);
  REQUIRE(wrongly_pruned == 0);
  REQUIRE(kept == r.kept_dual_edges.size());
  REQUIRE(false_branch == st.number_of_curvature_pruned_dual_edges);
  if(tolerance == 0) REQUIRE(r.kept_dual_edges.size() + false_branch == r.dual_edges.size());
  if(genus > 0) REQUIRE_FALSE(st.fallback_single_rung);

  // the kept dual structure is connected
  {
    Geodesic_ridge::internal::Union_find uf(m.number_of_faces());
    std::set<std::size_t> nodes;
    for(edge_descriptor e : r.kept_dual_edges)
    {
      const std::size_t f1 = m.face(m.halfedge(e)).idx(), f2 = m.face(m.opposite(m.halfedge(e))).idx();
      uf.unite(f1, f2);
      nodes.insert(f1);
      nodes.insert(f2);
    }
    std::set<std::size_t> roots;
    for(std::size_t f : nodes) roots.insert(uf.find(f));
    REQUIRE(roots.size() == 1);
  }

  // K is made of rungs of kept dual edges, connected, with cycle rank 2g
  std::set<std::size_t> kv;
  Geodesic_ridge::internal::Union_find kuf(m.number_of_vertices());
  std::size_t cut_but_not_kept = 0;
  const std::set<edge_descriptor> corner_paths(r.corner_path_edges.begin(), r.corner_path_edges.end());
  for(edge_descriptor e : r.cut_edges)
  {
    cut_but_not_kept += r.edge_role[e.idx()] != Geodesic_ridge::Edge_role::dual_kept &&
                        r.edge_role[e.idx()] != Geodesic_ridge::Edge_role::dual_leaf_extension &&
                        !corner_paths.count(e);
    kv.insert(m.source(m.halfedge(e)).idx());
    kv.insert(m.target(m.halfedge(e)).idx());
    kuf.unite(m.source(m.halfedge(e)).idx(), m.target(m.halfedge(e)).idx());
  }
  REQUIRE(cut_but_not_kept == 0);
  std::set<std::size_t> kroots;
  for(std::size_t v : kv) kroots.insert(kuf.find(v));
  REQUIRE(kroots.size() == 1);
  REQUIRE(r.cut_edges.size() + 1 - kv.size() == static_cast<std::size_t>(2 * genus));
  REQUIRE(st.cut_cycle_rank == static_cast<std::size_t>(2 * genus));

  // cutting along K gives one topological disk ...
  if(r.cut_edges.size() == 1)
  {
    // one slit: both its ends stay single vertices, which a polygon soup
    // cannot express (two edges between the same two vertices); V - (E+1) + F = 1.
    REQUIRE(genus == 0);
    const halfedge_descriptor h = m.halfedge(r.cut_edges[0]);
    if(r.source.kind == Geodesic_ridge::Geodesic_source<Mesh>::ON_VERTEX)
      REQUIRE((m.source(h) != r.source.vertex && m.target(h) != r.source.vertex));
    return;
  }
  Cut_surface c = cut_open(m, r);
  REQUIRE(CGAL::is_valid_polygon_mesh(c.mesh));
  REQUIRE(c.mesh.number_of_faces() == m.number_of_faces());
  std::vector<std::size_t> fcc(c.mesh.number_of_faces());
  REQUIRE(CGAL::Polygon_mesh_processing::connected_components(
              c.mesh, CGAL::make_property_map(fcc)) == 1);
  const long chi = static_cast<long>(c.mesh.number_of_vertices()) -
                   static_cast<long>(c.mesh.number_of_edges()) +
                   static_cast<long>(c.mesh.number_of_faces());
  REQUIRE(chi == 1);
  std::vector<halfedge_descriptor> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(c.mesh, std::back_inserter(cycles));
  REQUIRE(cycles.size() == 1);
  REQUIRE(c.mesh.number_of_edges() == m.number_of_edges() + r.cut_edges.size());

  // ... with the source strictly inside
  typedef Geodesic_ridge::Geodesic_source<Mesh> Source;
  if(r.source.kind == Source::ON_VERTEX)
  {
    const halfedge_descriptor h = m.halfedge(r.source.vertex);
    const vertex_descriptor copy(static_cast<Mesh::size_type>(c.copy_of_halfedge_target[h.idx()]));
    const bool on_border = bool(CGAL::is_border(copy, c.mesh));
    REQUIRE_FALSE(on_border);
  }
  else if(r.source.kind == Source::ON_EDGE)
    REQUIRE_FALSE(r.is_cut_edge[m.edge(r.source.edge_halfedge).idx()]);

  // no teeth: about one leaf of K per leaf of the kept dual structure (with
  // its leaf extensions), and one per corner joined to K
  REQUIRE(st.number_of_cut_leaves <= st.number_of_extended_dual_leaves + st.number_of_corner_moves + 2);
}

} // namespace

TEST_CASE("significance equals the brute-force definition and the paper's Algorithm 1", "[rough_cut_locus]")
{
  for(const std::string name : {"bunny_1k.off", "torus_1k.off", "eight.off", "armadillo_2k.off"})
  {
    const Mesh m = load(name);
    for(std::size_t s : {std::size_t(0), std::size_t(m.number_of_vertices() / 2)})
    {
      INFO(name << " source vertex " << s);
      const RCL r = Geodesic_ridge::compute_rough_cut_locus(m, vertex_descriptor(Mesh::size_type(s)));
      const std::vector<double> brute = brute_force_significance(m, r);
      for(edge_descriptor e : r.dual_edges)
        REQUIRE(r.significance[e.idx()] == Approx(brute[e.idx()]).epsilon(1e-9));
      if(r.statistics.genus == 0)
      {
        const auto paper = paper_algorithm_1(m, r);
        REQUIRE(paper.size() == r.dual_edges.size());
        for(const auto& [e, I] : paper) REQUIRE(r.significance[e] == Approx(I).epsilon(1e-9));
      }
    }
    // a surface-point source: the faces holding it are no nodes of T*
    const face_descriptor f(Mesh::size_type(m.number_of_faces() / 3));
    const std::pair<face_descriptor, std::array<double, 3> > loc(f, {0.2, 0.3, 0.5});
    const RCL r = Geodesic_ridge::compute_rough_cut_locus(m, loc);
    const std::vector<double> brute = brute_force_significance(m, r);
    for(edge_descriptor e : r.dual_edges)
      REQUIRE(r.significance[e.idx()] == Approx(brute[e.idx()]).epsilon(1e-9));
  }
}

TEST_CASE("the shortest-path tree is a Dijkstra tree rooted at the source", "[rough_cut_locus]")
{
  const Mesh m = load("bunny_1k.off");
  const vertex_descriptor s(7);
  const RCL r = Geodesic_ridge::compute_rough_cut_locus(m, s);
  REQUIRE(r.distance[s.idx()] == 0);
  std::size_t tree_edges = 0;
  for(edge_descriptor e : m.edges())
    tree_edges += r.edge_role[e.idx()] == Geodesic_ridge::Edge_role::shortest_path_tree;
  REQUIRE(tree_edges == m.number_of_vertices() - 1);
  for(vertex_descriptor v : m.vertices())
  {
    if(v == s) { REQUIRE(r.parent[v.idx()] == s); continue; }
    const vertex_descriptor p = r.parent[v.idx()];
    REQUIRE(p != v);
    const double len = std::sqrt(CGAL::squared_distance(m.point(v), m.point(p)));
    REQUIRE(r.distance[v.idx()] == Approx(r.distance[p.idx()] + len).epsilon(1e-12));
    // optimality: no edge relaxes any further
    for(vertex_descriptor u : CGAL::vertices_around_target(v, m))
      REQUIRE(r.distance[v.idx()] <=
              r.distance[u.idx()] + std::sqrt(CGAL::squared_distance(m.point(v), m.point(u))) + 1e-12);
  }
}

TEST_CASE("cutting along K gives one disk with the source inside, for every tolerance and genus 0 to 3",
          "[slow][rough_cut_locus][sweep]")
{
  const std::vector<std::pair<std::string, int> > meshes = {
      {"bunny_1k.off", 0}, {"armadillo_2k.off", 0}, {"torus_1k.off", 1},
      {"knot_3k.off", 1},  {"eight.off", 2},        {"3holes_7k.off", 3}};
  std::vector<double> tolerances;
  for(int i = 0; i < 25; ++i) tolerances.push_back(0.49 * i / 24.0); // 0 .. 0.49
  tolerances.push_back(0.4999999);
  const unsigned int seed = CGAL::get_default_random().get_seed();
  std::cout << "[rough_cut_locus sweep] random seed " << seed << std::endl;
  CGAL::Random rnd(seed);
  for(const auto& [name, genus] : meshes)
  {
    const Mesh m = load(name);
    // sources: two vertices, a point inside a face, a point on an edge
    std::vector<std::pair<face_descriptor, std::array<double, 3> > > points;
    {
      const face_descriptor f(Mesh::size_type(rnd.get_int(0, int(m.number_of_faces()))));
      double a = rnd.get_double(0.05, 0.9), b = rnd.get_double(0.05, 0.95 - a);
      points.push_back({f, {a, b, 1 - a - b}});
      const face_descriptor g(Mesh::size_type(rnd.get_int(0, int(m.number_of_faces()))));
      a = rnd.get_double(0.1, 0.9);
      points.push_back({g, {a, 0., 1 - a}});
    }
    const std::vector<std::size_t> vsources = {0, std::size_t(rnd.get_int(0, int(m.number_of_vertices())))};
    for(double t : tolerances)
    {
      for(std::size_t s : vsources)
      {
        INFO(name << " source vertex " << s << " seed " << seed);
        const RCL r = Geodesic_ridge::compute_rough_cut_locus(
            m, vertex_descriptor(Mesh::size_type(s)), Geodesic_ridge::parameters::tolerance(t));
        check_rough_cut_locus(m, r, t, genus);
      }
      for(const auto& loc : points)
      {
        INFO(name << " source face " << loc.first.idx() << " (" << loc.second[0] << ", "
                  << loc.second[1] << ", " << loc.second[2] << ") seed " << seed);
        const RCL r = Geodesic_ridge::compute_rough_cut_locus(m, loc, Geodesic_ridge::parameters::tolerance(t));
        check_rough_cut_locus(m, r, t, genus);
      }
    }
  }
}

TEST_CASE("leaf curvature: the cut graph's leaves go on to the corners of convex polyhedra", "[rough_cut_locus]")
{
  namespace p = Geodesic_ridge::parameters;
  namespace T = Geodesic_ridge::testing;
  struct Case { std::string name; T::Polyhedron_description d; int n; double perturbation; };
  const std::vector<Case> cases = {{"cube", T::box_corners_and_faces(), 8, 0.0},
                                   {"cube (perturbed)", T::box_corners_and_faces(), 8, 0.25},
                                   {"tetrahedron", T::regular_tetrahedron_corners_and_faces(), 10, 0.0}};
  for(const Case& c : cases)
  {
    const unsigned seed = T::test_seed(20261201);
    const T::Subdivided_polyhedron poly = T::make_subdivided_polyhedron(c.d, c.n, c.perturbation, seed);
    const Mesh& m = poly.mesh;
    const double h = T::mean_edge_length(m);
    const vertex_descriptor s(static_cast<Mesh::size_type>(m.number_of_vertices() / 3));
    for(double t : {0.025, 0.1})
    {
      INFO(c.name << " n " << c.n << " perturbation " << c.perturbation << " seed " << seed << " source " << s
                  << " tolerance " << t);
      const RCL plain = Geodesic_ridge::compute_rough_cut_locus(m, s, p::tolerance(t, p::leaf_curvature(0)));
      const RCL r = Geodesic_ridge::compute_rough_cut_locus(m, s, p::tolerance(t, p::leaf_curvature(45)));
      check_rough_cut_locus(m, r, t, 0);
      REQUIRE(plain.leaf_extension_edges.empty());
      REQUIRE(r.kept_dual_edges == plain.kept_dual_edges);
      REQUIRE(r.statistics.number_of_leaf_extension_edges == r.leaf_extension_edges.size());
      for(edge_descriptor e : r.leaf_extension_edges)
      {
        REQUIRE(r.edge_role[e.idx()] == Geodesic_ridge::Edge_role::dual_leaf_extension);
        REQUIRE(r.significance[e.idx()] < t * r.total_area); // pruned edges only
      }
      // how far each corner is from K
      auto corner_distances = [&](const RCL& x) {
        std::vector<double> out;
        for(vertex_descriptor corner : poly.corner_vertices)
        {
          if(corner == s) continue;
          double best = 1e300;
          for(edge_descriptor e : x.cut_edges)
            for(vertex_descriptor v : {m.source(m.halfedge(e)), m.target(m.halfedge(e))})
              best = std::min(best, std::sqrt(CGAL::squared_distance(m.point(v), m.point(corner))) / h);
          out.push_back(best);
        }
        return out;
      };
      const std::vector<double> before = corner_distances(plain), after = corner_distances(r);
      std::size_t reached_before = 0, reached_after = 0;
      double worst_after = 0;
      for(std::size_t i = 0; i < after.size(); ++i)
      {
        reached_before += before[i] <= 1.0;
        reached_after += after[i] <= 1.0;
        worst_after = std::max(worst_after, after[i]);
      }
      std::cout << "[rough_cut_locus] " << c.name << " tolerance " << t << ": corners within one edge of K "
                << reached_before << " -> " << reached_after << " of " << after.size() << ", farthest "
                << worst_after << " mean edges, " << r.leaf_extension_edges.size() << " extension edges\n";
      CHECK(reached_after >= reached_before);
      CHECK(reached_after + 1 >= after.size()); // all corners but at most one
    }
  }
}

// Branch curvature (parameters::branch_curvature). The doubly covered square is
// flat but for its four corners (180 degrees each), so a branch of the dual
// tree that encloses no corner encloses no curvature at all: it is a false
// branch. Every leaf of the cut locus is a corner, and after the false
// branches are pruned (and leaves moved onto corners) K's leaves are exactly
// the four corners, at every tolerance, regular or perturbed. Without the
// pruning (branch_curvature(0), the paper's cut) K has false leaves.
TEST_CASE("branch curvature: on the doubly covered square K's leaves are the four corners", "[rough_cut_locus]")
{
  namespace p = Geodesic_ridge::parameters;
  namespace T = Geodesic_ridge::testing;
  struct Case { int n; double perturbation; unsigned seed; };
  for(const Case& c : {Case{10, 0, 0}, Case{16, 0, 0}, Case{12, 0.25, 20260101}, Case{16, 0.25, 20260102}})
  {
    const unsigned seed = T::test_seed(c.seed);
    const T::Doubly_covered_square sq = T::make_doubly_covered_square(c.n, c.perturbation, seed);
    const Mesh& m = sq.mesh;
    const int n = c.n;
    const std::set<vertex_descriptor> corners = {sq.top[0], sq.top[n], sq.top[(n + 1) * n], sq.top[(n + 1) * n + n]};
    std::size_t false_leaves_without = 0;
    for(const auto& g : std::vector<std::array<int, 2> >{{{n / 4, n / 3}}, {{n / 2 + 1, n / 4}}, {{3 * n / 4, 3 * n / 4 - 1}}})
      for(double t : {0.0, 0.005, 0.01, 0.025, 0.1})
      {
        const vertex_descriptor s = sq.top[g[0] + (n + 1) * g[1]];
        INFO("doubly covered square n " << n << " perturbation " << c.perturbation << " seed " << seed << " source "
                                        << s << " tolerance " << t);
        const RCL r = Geodesic_ridge::compute_rough_cut_locus(m, s, p::tolerance(t));
        check_rough_cut_locus(m, r, t, 0);
        std::map<vertex_descriptor, int> degree;
        for(edge_descriptor e : r.cut_edges) { ++degree[m.source(m.halfedge(e))]; ++degree[m.target(m.halfedge(e))]; }
        std::set<vertex_descriptor> leaves;
        for(const auto& [v, k] : degree) if(k == 1) leaves.insert(v);
        CHECK(leaves == corners);
        if(t <= 0.01) CHECK(r.statistics.number_of_curvature_pruned_dual_edges > 0);
        const RCL plain = Geodesic_ridge::compute_rough_cut_locus(m, s, p::tolerance(t, p::branch_curvature(0)));
        REQUIRE(plain.statistics.number_of_curvature_pruned_dual_edges == 0);
        false_leaves_without += plain.statistics.number_of_cut_leaves - 4;
      }
    std::cout << "[rough_cut_locus] doubly covered square n " << n << " perturbation " << c.perturbation
              << ": false leaves of K over 15 runs without the branch curvature " << false_leaves_without
              << ", with it 0\n";
    CHECK(false_leaves_without > 0);
  }
}

TEST_CASE("leaf and branch curvatures out of range are errors", "[rough_cut_locus]")
{
  namespace p = Geodesic_ridge::parameters;
  const Mesh m = load("torus_1k.off");
  const vertex_descriptor s(0);
  for(double bad : {-1.0, 721.0, std::nan("")})
  {
    INFO("curvature " << bad);
    REQUIRE_THROWS_AS(Geodesic_ridge::compute_rough_cut_locus(m, s, p::leaf_curvature(bad)),
                      Geodesic_ridge::Invalid_parameter_error);
    REQUIRE_THROWS_AS(Geodesic_ridge::compute_rough_cut_locus(m, s, p::branch_curvature(bad)),
                      Geodesic_ridge::Invalid_parameter_error);
  }
  REQUIRE_NOTHROW(Geodesic_ridge::compute_rough_cut_locus(m, s, p::leaf_curvature(0)));
  REQUIRE_NOTHROW(Geodesic_ridge::compute_rough_cut_locus(m, s, p::branch_curvature(0)));
}

TEST_CASE("convex polyhedra and generated meshes", "[rough_cut_locus]")
{
  // A subdivided icosahedron (sphere) and a subdivided, perturbed cube.
  Mesh ico;
  CGAL::make_icosahedron(ico, Point_3(0, 0, 0), 1.0);
  CGAL::Subdivision_method_3::Loop_subdivision(ico, CGAL::parameters::number_of_iterations(3));
  Mesh cube;
  CGAL::make_hexahedron(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0),
                        Point_3(0, 1, 1), Point_3(0, 0, 1), Point_3(1, 0, 1), Point_3(1, 1, 1), cube);
  CGAL::Polygon_mesh_processing::triangulate_faces(cube);
  CGAL::Subdivision_method_3::Loop_subdivision(cube, CGAL::parameters::number_of_iterations(3));
  for(Mesh* m : {&ico, &cube})
    for(double t : {0.0, 0.01, 0.025, 0.1, 0.3, 0.49})
    {
      const RCL r = Geodesic_ridge::compute_rough_cut_locus(*m, vertex_descriptor(0),
                                                            Geodesic_ridge::parameters::tolerance(t));
      check_rough_cut_locus(*m, r, t, 0);
    }
}

TEST_CASE("stage 1 rejects bad parameters and sources with typed exceptions", "[rough_cut_locus][validation]")
{
  const Mesh m = load("torus_1k.off");
  const vertex_descriptor v0(0);
  using Geodesic_ridge::parameters::tolerance;
  for(double t : {-0.1, 0.5, 0.7, std::nan(""), HUGE_VAL})
    REQUIRE_THROWS_AS(Geodesic_ridge::compute_rough_cut_locus(m, v0, tolerance(t)),
                      Geodesic_ridge::Invalid_parameter_error);
  REQUIRE_THROWS_WITH(Geodesic_ridge::compute_rough_cut_locus(m, v0, tolerance(0.5)),
                      Catch::Contains("tolerance") && Catch::Contains("[0, 0.5)"));
  REQUIRE_THROWS_AS(Geodesic_ridge::compute_rough_cut_locus(m, vertex_descriptor(Mesh::size_type(m.number_of_vertices()))),
                    Geodesic_ridge::Invalid_source_error);
  REQUIRE_THROWS_AS(Geodesic_ridge::compute_rough_cut_locus(m, Mesh::null_vertex()),
                    Geodesic_ridge::Invalid_source_error);
  typedef std::pair<face_descriptor, std::array<double, 3> > Loc;
  const face_descriptor f0(0);
  for(const Loc& bad : {Loc(f0, {-0.1, 0.6, 0.5}), Loc(f0, {0.2, 0.2, 0.2}), Loc(f0, {std::nan(""), 0.5, 0.5}),
                        Loc(face_descriptor(Mesh::size_type(m.number_of_faces())), {0.2, 0.3, 0.5}),
                        Loc(Mesh::null_face(), {0.2, 0.3, 0.5})})
    REQUIRE_THROWS_AS(Geodesic_ridge::compute_rough_cut_locus(m, bad), Geodesic_ridge::Invalid_source_error);
  // the parameters chain with CGAL's own
  const RCL r = Geodesic_ridge::compute_rough_cut_locus(
      m, v0, tolerance(0.1).vertex_point_map(get(CGAL::vertex_point, m)));
  REQUIRE(r.tolerance == 0.1);
  // a location on a vertex is a vertex source
  const RCL rv = Geodesic_ridge::compute_rough_cut_locus(m, Loc(f0, {0., 1., 0.}));
  REQUIRE(rv.source.kind == Geodesic_ridge::Geodesic_source<Mesh>::ON_VERTEX);
  REQUIRE(rv.source.vertex == m.target(m.halfedge(f0)));
}

TEST_CASE("the rough cut polylines are K, with the mesh's exact coordinates", "[rough_cut_locus][io]")
{
  for(const std::string name : {"bunny_1k.off", "eight.off"})
  {
    const Mesh m = load(name);
    const RCL r = Geodesic_ridge::compute_rough_cut_locus(m, vertex_descriptor(3));
    std::vector<std::vector<Point_3> > polylines;
    Geodesic_ridge::cut_graph_polylines(m, r, std::back_inserter(polylines));
    std::ostringstream os;
    Geodesic_ridge::IO::write_polylines(os, polylines);

    std::map<Point_3, std::size_t> vertex_at;
    for(vertex_descriptor v : m.vertices()) vertex_at[m.point(v)] = v.idx();
    std::set<std::pair<std::size_t, std::size_t> > cut, written;
    for(edge_descriptor e : r.cut_edges)
      cut.insert(std::minmax(m.source(m.halfedge(e)).idx(), m.target(m.halfedge(e)).idx()));
    std::istringstream is(os.str());
    std::string line;
    std::size_t lines = 0, segments = 0;
    while(std::getline(is, line))
    {
      ++lines;
      std::istringstream ls(line);
      std::size_t n = 0;
      ls >> n;
      REQUIRE(n >= 2);
      std::vector<std::size_t> ids;
      for(std::size_t i = 0; i < n; ++i)
      {
        double x, y, z;
        REQUIRE(bool(ls >> x >> y >> z));
        const auto it = vertex_at.find(Point_3(x, y, z)); // exact equality, no tolerance
        REQUIRE(it != vertex_at.end());
        ids.push_back(it->second);
      }
      for(std::size_t i = 0; i + 1 < n; ++i)
      {
        written.insert(std::minmax(ids[i], ids[i + 1]));
        ++segments;
      }
    }
    REQUIRE(lines == polylines.size());
    REQUIRE(segments == r.cut_edges.size()); // every edge of K once
    REQUIRE(written == cut);
  }
}

TEST_CASE("every closed mesh of ../shared/data gives a disk cut from several sources", "[slow][rough_cut_locus][shared]")
{
  namespace fs = std::filesystem;
  const fs::path dir = GEODESIC_RIDGE_SHARED_DATA_DIR;
  if(!fs::is_directory(dir))
  {
    WARN("no " << dir << ": skipped (the repository's own meshes are tested above)");
    return;
  }
#ifdef GEODESIC_RIDGE_SANITIZE
  const std::size_t max_faces = 20000; // sanitizers are ~10x slower
#else
  const std::size_t max_faces = 250000;
#endif
  const unsigned int seed = CGAL::get_default_random().get_seed();
  std::cout << "[rough_cut_locus shared] random seed " << seed << std::endl;
  CGAL::Random rnd(seed);
  std::size_t meshes = 0;
  for(const auto& entry : fs::directory_iterator(dir))
  {
    if(entry.path().extension() != ".off") continue;
    Mesh m;
    Geodesic_ridge::IO::read_triangle_mesh(entry.path().string(), m);
    if(m.number_of_faces() > max_faces) continue;
    ++meshes;
    const long chi = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
    const int genus = int((2 - chi) / 2);
    const bool large = m.number_of_faces() > 50000;
    const std::vector<double> tolerances = large ? std::vector<double>{0.025}
                                                 : std::vector<double>{0.005, 0.025, 0.2};
    for(double t : tolerances)
    {
      for(int k = 0; k < (large ? 1 : 3); ++k)
      {
        const std::size_t s = std::size_t(rnd.get_int(0, int(m.number_of_vertices())));
        INFO(entry.path().filename() << " source vertex " << s << " seed " << seed);
        check_rough_cut_locus(m, Geodesic_ridge::compute_rough_cut_locus(
                                     m, vertex_descriptor(Mesh::size_type(s)), Geodesic_ridge::parameters::tolerance(t)),
                              t, genus);
      }
      const face_descriptor f(Mesh::size_type(rnd.get_int(0, int(m.number_of_faces()))));
      const std::pair<face_descriptor, std::array<double, 3> > loc(f, {0.25, 0.25, 0.5});
      INFO(entry.path().filename() << " source face " << f.idx() << " seed " << seed);
      check_rough_cut_locus(m, Geodesic_ridge::compute_rough_cut_locus(m, loc, Geodesic_ridge::parameters::tolerance(t)),
                            t, genus);
    }
  }
  std::cout << "[rough_cut_locus shared] " << meshes << " meshes checked" << std::endl;
  REQUIRE(meshes > 0);
}
