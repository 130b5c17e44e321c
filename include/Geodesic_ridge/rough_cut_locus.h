// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1: the rough cut locus (DESIGN.md §2, paper §3.1).
//
//   Dijkstra shortest-path tree T  ->  dual T* of the non-tree edges
//   -> significance of every dual edge  -> pruning by tolerance
//   -> primal cut graph K on mesh edges: cutting the mesh along K gives one
//      topological disk with the source strictly inside.
#ifndef GEODESIC_RIDGE_ROUGH_CUT_LOCUS_H
#define GEODESIC_RIDGE_ROUGH_CUT_LOCUS_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/corner_angles.h>
#include <Geodesic_ridge/internal/graph_polylines.h>
#include <Geodesic_ridge/internal/union_find.h>
#include <Geodesic_ridge/mesh_validation.h>
#include <Geodesic_ridge/parameters.h>
#include <Geodesic_ridge/source.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// What a mesh edge is to the rough cut locus.
enum class Edge_role : unsigned char
{
  shortest_path_tree, ///< an edge of the Dijkstra shortest-path tree T
  source_face,        ///< an edge of a face holding the source (never crossed by T*)
  dual_pruned,        ///< crossed by an edge of T* whose significance is below the tolerance
  dual_kept,          ///< crossed by an edge of T* that survives the pruning
  dual_leaf_extension, ///< crossed by a pruned edge of T* that extends a kept leaf (see `leaf_extension`,
                       ///< `leaf_curvature`)
  dual_false_branch    ///< crossed by an edge of T* significant enough but on a branch that encloses no
                       ///< curvature: a false branch (see `branch_curvature`)
};

/// \ingroup PkgGeodesicRidgeRef
/// Counts and timings of stage 1 (seconds).
struct Rough_cut_locus_statistics
{
  int genus = 0;
  std::size_t number_of_vertices = 0, number_of_edges = 0, number_of_faces = 0;
  std::size_t number_of_dual_edges = 0;      ///< |T*| = F' - 1 + 2g (F' = faces not holding the source)
  std::size_t number_of_core_dual_edges = 0; ///< dual edges on the 2-core (significance = total area)
  std::size_t number_of_kept_dual_edges = 0;
  std::size_t number_of_kept_dual_leaves = 0; ///< faces with exactly one kept dual edge
  std::size_t number_of_extended_dual_leaves = 0; ///< same, with the leaf extension edges too
  std::size_t number_of_leaf_extension_edges = 0; ///< pruned dual edges added to extend kept leaves
  std::size_t number_of_cut_edges = 0;        ///< |K|
  std::size_t number_of_cut_vertices = 0;
  std::size_t number_of_cut_leaves = 0;       ///< vertices of degree 1 in K
  std::size_t cut_cycle_rank = 0;             ///< |K| - |V(K)| + 1; equals 2g
  std::size_t number_of_closing_rungs = 0;    ///< rungs added back to close the 2g cycles
  std::size_t number_of_teeth_pruned = 0;     ///< one-edge leaves of K removed
  std::size_t number_of_curvature_pruned_dual_edges = 0; ///< kept dual edges of false branches (see `branch_curvature`)
  std::size_t number_of_corner_moves = 0;     ///< leaves of K moved back onto a corner (large curvature), and corners joined to K
  bool fallback_single_rung = false;          ///< no dual edge reached the tolerance: K is the best rung
  double time_shortest_path_tree = 0, time_significance = 0, time_cut_graph = 0,
         time_disk_check = 0, time_total = 0;
};

/// \ingroup PkgGeodesicRidgeRef
/// The result of stage 1. Per-vertex vectors are indexed by the vertex index
/// map, per-edge vectors by the edge index map (for `CGAL::Surface_mesh`:
/// `v.idx()` and `e.idx()`).
template <class TriangleMesh>
struct Rough_cut_locus
{
  typedef boost::graph_traits<TriangleMesh>   GT;
  typedef typename GT::vertex_descriptor     vertex_descriptor;
  typedef typename GT::edge_descriptor       edge_descriptor;
  typedef typename GT::face_descriptor       face_descriptor;

  Geodesic_source<TriangleMesh> source;
  double tolerance = default_tolerance;
  double total_area = 0;

  /// Dijkstra distance along mesh edges (per vertex)
  std::vector<double> distance;
  /// predecessor in the shortest-path tree T (per vertex; a root is its own parent)
  std::vector<vertex_descriptor> parent;

  /// role of every edge (per edge)
  std::vector<Edge_role> edge_role;
  /// significance I(e) of the dual edge crossing e (per edge; NaN if e is not crossed by T*)
  std::vector<double> significance;
  /// 1 if e is in the primal cut graph K (per edge)
  std::vector<char> is_cut_edge;

  /// the mesh edges crossed by T*, by increasing edge index
  std::vector<edge_descriptor> dual_edges;
  /// those that survive the pruning (the kept dual structure), by increasing edge index
  std::vector<edge_descriptor> kept_dual_edges;
  /// pruned ones that extend leaves of the kept dual structure, by increasing edge index
  std::vector<edge_descriptor> leaf_extension_edges;
  /// edges of K that are no rungs: paths that join a corner to K (see the leaves
  /// at corners in rough_cut_locus.h), by increasing edge index
  std::vector<edge_descriptor> corner_path_edges;
  /// the primal cut graph K, by increasing edge index
  std::vector<edge_descriptor> cut_edges;

  Rough_cut_locus_statistics statistics;
};

namespace internal {

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// `field`, if given, holds a geodesic distance per vertex (by vertex index):
// the tree then follows it (see below) instead of Dijkstra's edge distances.
template <class TriangleMesh, class NamedParameters>
Rough_cut_locus<TriangleMesh>
rough_cut_locus_impl(const TriangleMesh& tm, Geodesic_source<TriangleMesh> src,
                     const NamedParameters& np, const std::vector<double>* field = nullptr)
{
  typedef boost::graph_traits<TriangleMesh>  GT;
  typedef typename GT::vertex_descriptor    vertex_descriptor;
  typedef typename GT::halfedge_descriptor  halfedge_descriptor;
  typedef typename GT::edge_descriptor      edge_descriptor;
  typedef typename GT::face_descriptor      face_descriptor;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const auto t_start = std::chrono::steady_clock::now();
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto eim = CGAL::get_initialized_edge_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);

  const std::size_t nv = num_vertices(tm), ne = num_edges(tm), nf = num_faces(tm);
  auto vi = [&](vertex_descriptor v) { return static_cast<std::size_t>(get(vim, v)); };
  auto ei = [&](edge_descriptor e) { return static_cast<std::size_t>(get(eim, e)); };
  auto fi = [&](face_descriptor f) { return static_cast<std::size_t>(get(fim, f)); };

  Rough_cut_locus<TriangleMesh> r;
  r.source = src;
  r.tolerance = get_tolerance(np);
  Rough_cut_locus_statistics& st = r.statistics;
  st.number_of_vertices = nv;
  st.number_of_edges = ne;
  st.number_of_faces = nf;
  const long chi = static_cast<long>(nv) - static_cast<long>(ne) + static_cast<long>(nf);
  st.genus = static_cast<int>((2 - chi) / 2);

  std::vector<edge_descriptor> edge_of(ne);
  for(edge_descriptor e : edges(tm))
  {
    if(ei(e) >= ne)
      throw Invalid_mesh_error("mesh has removed elements (call collect_garbage() first)");
    edge_of[ei(e)] = e;
  }
  std::vector<face_descriptor> face_of(nf);
  for(face_descriptor f : faces(tm))
  {
    if(fi(f) >= nf)
      throw Invalid_mesh_error("mesh has removed elements (call collect_garbage() first)");
    face_of[fi(f)] = f;
  }

  // ---------------------------------------------------------------------------
  // 1. Shortest-path tree T (Boost Dijkstra, several seeds for a surface point).
  auto t0 = std::chrono::steady_clock::now();
  std::vector<double> length(ne);
  for(edge_descriptor e : edges(tm))
    length[ei(e)] = distance_between(vpm, source(e, tm), target(e, tm));

  const double inf = std::numeric_limits<double>::infinity();
  r.distance.assign(nv, inf);
  r.parent.resize(nv);
  for(vertex_descriptor v : vertices(tm)) r.parent[vi(v)] = v;
  std::vector<vertex_descriptor> seed_vertices;
  for(const auto& s : src.seeds)
  {
    r.distance[vi(s.first)] = s.second;
    seed_vertices.push_back(s.first);
  }
  boost::dijkstra_shortest_paths_no_init(
      tm, seed_vertices.begin(), seed_vertices.end(),
      boost::make_iterator_property_map(r.parent.begin(), vim),
      boost::make_iterator_property_map(r.distance.begin(), vim),
      boost::make_iterator_property_map(length.begin(), eim), vim,
      std::less<double>(), boost::closed_plus<double>(inf), 0.0,
      boost::default_dijkstra_visitor());
  // A straight segment from the source is a geodesic (no edge path in R^3 is
  // shorter), so seeds stay roots and a vertex source's neighbours hang from it,
  // whatever ties the floating-point sums produced: the cut never touches the source.
  for(const auto& s : src.seeds)
  {
    r.distance[vi(s.first)] = s.second;
    r.parent[vi(s.first)] = s.first;
  }
  if(src.kind == Geodesic_source<TriangleMesh>::ON_VERTEX)
    for(halfedge_descriptor h : CGAL::halfedges_around_target(src.vertex, tm))
    {
      const vertex_descriptor u = source(h, tm);
      r.parent[vi(u)] = src.vertex;
      r.distance[vi(u)] = length[ei(edge(h, tm))];
    }
  for(vertex_descriptor v : vertices(tm))
    if(!(r.distance[vi(v)] < inf))
      throw Invalid_mesh_error("vertex " + std::to_string(vi(v)) +
                               " cannot be reached from the source");

  // With a geodesic field, every vertex hangs from the neighbour u of smaller
  // field value that minimizes field(u) + |uv|: the tree descends the true
  // distance instead of Dijkstra's staircase paths, whose anisotropy on regular
  // meshes makes significant dual branches far from the real ridge. Strictly
  // decreasing values make it a tree; where a vertex has no lower neighbour it
  // keeps its Dijkstra parent, and if that mix ever closed a cycle, the whole
  // Dijkstra tree is kept.
  if(field != nullptr)
  {
    std::vector<vertex_descriptor> dijkstra_parent = r.parent;
    std::vector<char> is_root(nv, 0);
    for(const auto& sd : src.seeds) is_root[vi(sd.first)] = 1;
    for(vertex_descriptor v : vertices(tm))
    {
      if(is_root[vi(v)]) continue;
      if(src.kind == Geodesic_source<TriangleMesh>::ON_VERTEX && r.parent[vi(v)] == src.vertex &&
         v != src.vertex)
        continue; // the source's neighbours stay its children
      double best = inf;
      for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
      {
        const vertex_descriptor u = source(h, tm);
        if(!((*field)[vi(u)] < (*field)[vi(v)])) continue;
        const double value = (*field)[vi(u)] + length[ei(edge(h, tm))];
        if(value < best) { best = value; r.parent[vi(v)] = u; }
      }
    }
    // a tree iff every vertex reaches a root
    std::vector<char> state(nv, 0); // 0 unknown, 1 in progress, 2 reaches a root
    bool tree = true;
    for(vertex_descriptor v : vertices(tm))
    {
      std::vector<std::size_t> path;
      std::size_t x = vi(v);
      while(state[x] == 0 && !is_root[x])
      {
        state[x] = 1;
        path.push_back(x);
        x = vi(r.parent[x]);
      }
      if(state[x] == 1) { tree = false; break; }
      for(std::size_t y : path) state[y] = 2;
      state[x] = 2;
    }
    if(!tree) r.parent = dijkstra_parent;
    else
      for(vertex_descriptor v : vertices(tm)) r.distance[vi(v)] = (*field)[vi(v)];
  }
  st.time_shortest_path_tree = seconds_since(t0);

  // ---------------------------------------------------------------------------
  // 2. Edge roles and the dual T*; significance by peeling leaves of T* (O(F)).
  t0 = std::chrono::steady_clock::now();
  std::vector<char> is_source_face(nf, 0);
  for(face_descriptor f : src.faces) is_source_face[fi(f)] = 1;
  r.edge_role.assign(ne, Edge_role::dual_pruned);
  r.significance.assign(ne, std::numeric_limits<double>::quiet_NaN());
  for(edge_descriptor e : edges(tm))
  {
    const halfedge_descriptor h = halfedge(e, tm);
    const vertex_descriptor a = source(h, tm), b = target(h, tm);
    const bool in_tree = (r.parent[vi(a)] == b && a != b) || (r.parent[vi(b)] == a && a != b);
    if(in_tree)
      r.edge_role[ei(e)] = Edge_role::shortest_path_tree;
    else if(is_source_face[fi(face(h, tm))] || is_source_face[fi(face(opposite(h, tm), tm))])
      r.edge_role[ei(e)] = Edge_role::source_face;
    else
      r.dual_edges.push_back(e);
  }
  st.number_of_dual_edges = r.dual_edges.size();
  const std::size_t dual_faces = nf - src.faces.size();
  if(static_cast<long>(r.dual_edges.size()) != static_cast<long>(dual_faces) - 1 + 2 * st.genus)
    throw Algorithm_error("the dual of the shortest-path tree has " +
                          std::to_string(r.dual_edges.size()) + " edges, expected " +
                          std::to_string(static_cast<long>(dual_faces) - 1 + 2 * st.genus));

  std::vector<double> area(nf);
  r.total_area = 0;
  for(face_descriptor f : faces(tm))
  {
    area[fi(f)] = CGAL::Polygon_mesh_processing::face_area(f, tm, CGAL::parameters::vertex_point_map(vpm));
    r.total_area += area[fi(f)];
  }
  const double total = r.total_area;
  // The faces holding a surface-point source are no nodes of T*: the two sides
  // of a dual edge share the rest of the area.
  double node_total = total;
  for(face_descriptor f : src.faces) node_total -= area[fi(f)];

  // dual adjacency, by position in dual_edges
  const std::size_t nd = r.dual_edges.size();
  std::vector<std::array<std::size_t, 2> > dual_faces_of(nd);
  std::vector<std::array<std::size_t, 3> > dual_of_face(nf);
  std::vector<unsigned char> dual_degree(nf, 0);
  for(std::size_t d = 0; d < nd; ++d)
  {
    const halfedge_descriptor h = halfedge(r.dual_edges[d], tm);
    const std::size_t f1 = fi(face(h, tm)), f2 = fi(face(opposite(h, tm), tm));
    dual_faces_of[d] = {f1, f2};
    dual_of_face[f1][dual_degree[f1]++] = d;
    dual_of_face[f2][dual_degree[f2]++] = d;
  }
  // the face of dual edge d other than f
  auto across = [&](std::size_t d, std::size_t f) {
    return dual_faces_of[d][0] == f ? dual_faces_of[d][1] : dual_faces_of[d][0];
  };
  // Peel leaves: when a face becomes a leaf, its one remaining dual edge
  // separates the faces accumulated in it from the rest. What is never peeled
  // is the 2-core (the non-contractible cycles and the paths joining them).
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  // Gaussian curvature (2π − angle sum) of every vertex, shared among its
  // faces by angle, accumulated per branch of T* like the area (with its
  // positive part): the false branches and the leaf curvature extension
  // (below) follow it.
  const double leaf_curvature = get_leaf_curvature(np) * 3.14159265358979323846 / 180.0;
  const double branch_curvature_min = get_branch_curvature(np) * 3.14159265358979323846 / 180.0;
  const bool curvature_sums = leaf_curvature > 0 || branch_curvature_min > 0;
  std::vector<double> curvature_share, positive_share;
  // (the corner angles serve the leaves at corners, step 3d, too)
  const Corner_angles angles = curvature_sums ? corner_angles(tm, vpm, vim, fim) : Corner_angles();
  if(curvature_sums)
  {
    curvature_share.assign(nf, 0.0);
    positive_share.assign(nf, 0.0);
    for(face_descriptor f : faces(tm))
    {
      halfedge_descriptor h = halfedge(f, tm);
      for(int k = 0; k < 3; ++k, h = next(h, tm))
      {
        const std::size_t v = vi(source(h, tm));
        // the source is no leaf of its own cut locus
        if(src.kind == Geodesic_source<TriangleMesh>::ON_VERTEX && source(h, tm) == src.vertex) continue;
        curvature_share[fi(f)] += angles.curvature(v) * angles.angle[fi(f)][k] / angles.angle_sum[v];
        positive_share[fi(f)] += std::max(0.0, angles.curvature(v)) * angles.angle[fi(f)][k] / angles.angle_sum[v];
      }
    }
  }
  std::vector<double> branch_curvature(curvature_share), subtree_curvature(curvature_sums ? nd : 0, 0.0);
  std::vector<double> branch_positive(positive_share), subtree_positive(curvature_sums ? nd : 0, 0.0);
  std::vector<double> accumulated(area);
  std::vector<unsigned char> degree(dual_degree);
  std::vector<char> peeled(nd, 0);
  std::vector<std::size_t> child_face(nd, none), peel_order;
  peel_order.reserve(nd);
  std::vector<std::size_t> queue;
  for(std::size_t f = 0; f < nf; ++f)
    if(degree[f] == 1) queue.push_back(f);
  for(std::size_t qi = 0; qi < queue.size(); ++qi)
  {
    const std::size_t f = queue[qi];
    if(degree[f] != 1) continue;
    std::size_t d = none;
    for(unsigned char k = 0; k < dual_degree[f]; ++k)
      if(!peeled[dual_of_face[f][k]]) d = dual_of_face[f][k];
    peeled[d] = 1;
    child_face[d] = f;
    peel_order.push_back(d);
    const double side = accumulated[f];
    r.significance[ei(r.dual_edges[d])] = (std::min)(side, node_total - side);
    const std::size_t p = across(d, f);
    accumulated[p] += side;
    if(curvature_sums)
    {
      subtree_curvature[d] = branch_curvature[f];
      branch_curvature[p] += branch_curvature[f];
      subtree_positive[d] = branch_positive[f];
      branch_positive[p] += branch_positive[f];
    }
    degree[f] = 0;
    if(--degree[p] == 1) queue.push_back(p);
  }
  for(std::size_t d = 0; d < nd; ++d)
    if(!peeled[d])
    {
      r.significance[ei(r.dual_edges[d])] = total;
      ++st.number_of_core_dual_edges;
    }
  st.time_significance = seconds_since(t0);

  // ---------------------------------------------------------------------------
  // 3. Pruning, then the primal cut graph K.
  t0 = std::chrono::steady_clock::now();
  const double threshold = r.tolerance * total;
  std::vector<char> kept(nd, 0);
  std::size_t nkept = 0;
  for(std::size_t d = 0; d < nd; ++d)
    if(r.significance[ei(r.dual_edges[d])] >= threshold) { kept[d] = 1; ++nkept; }
  if(nkept == 0 && nd > 0)
  {
    // Genus 0 with a tolerance close to 1/2: keep the most significant dual
    // edge, so that K is one slit and the cut surface still a disk.
    std::size_t best = 0;
    for(std::size_t d = 1; d < nd; ++d)
      if(r.significance[ei(r.dual_edges[d])] > r.significance[ei(r.dual_edges[best])]) best = d;
    kept[best] = 1;
    nkept = 1;
    st.fallback_single_rung = true;
  }
  std::vector<unsigned char> kept_degree(nf, 0);
  for(std::size_t d = 0; d < nd; ++d)
    if(kept[d])
    {
      ++kept_degree[dual_faces_of[d][0]];
      ++kept_degree[dual_faces_of[d][1]];
    }
  // 3+. Branches that enclose no curvature are false (see
  //     parameters::branch_curvature): pruned back from their tips while the
  //     curvature beyond the tip's dual edge is below the minimum. The 2-core
  //     (genus) is never touched; one dual edge at least is kept.
  std::vector<char> false_branch(nd, 0);
  if(branch_curvature_min > 0 && !st.fallback_single_rung)
  {
    double total_curvature = 0;
    for(double c : curvature_share) total_curvature += c;
    double total_positive = 0;
    for(double c : positive_share) total_positive += c;
    // the curvature, and its positive part, on the side of d that encloses the
    // two paths' meeting: the branch's side, or on genus 0 the side of less
    // curvature
    auto enclosed = [&](std::size_t d) {
      const double c = subtree_curvature[d];
      if(st.genus == 0 && total_curvature - c < c)
        return std::make_pair(total_curvature - c, total_positive - subtree_positive[d]);
      return std::make_pair(c, subtree_positive[d]);
    };
    std::vector<std::size_t> tips;
    for(std::size_t f = 0; f < nf; ++f) if(kept_degree[f] == 1) tips.push_back(f);
    while(!tips.empty() && nkept > 1)
    {
      const std::size_t f = tips.back();
      tips.pop_back();
      if(kept_degree[f] != 1) continue;
      std::size_t d = none;
      for(unsigned char k = 0; k < dual_degree[f]; ++k)
        if(kept[dual_of_face[f][k]]) d = dual_of_face[f][k];
      // false: nearly no curvature enclosed, and no bump either (a bump with
      // its saddle-shaped foot encloses little in total but splits fronts)
      if(!peeled[d]) continue;
      const auto [net, positive] = enclosed(d);
      if(net >= branch_curvature_min || positive >= 2 * branch_curvature_min) continue;
      kept[d] = 0;
      false_branch[d] = 1;
      --nkept;
      ++st.number_of_curvature_pruned_dual_edges;
      kept_degree[f] = 0;
      const std::size_t p = across(d, f);
      if(--kept_degree[p] == 1) tips.push_back(p);
    }
  }
  for(std::size_t f = 0; f < nf; ++f) st.number_of_kept_dual_leaves += (kept_degree[f] == 1);

  // 3-. Extensions of the kept structure into pruned branches. The ridge
  //     shows only where K cuts: beyond K's end, the disk's copy of a face
  //     carries the smaller of the two fronts at its corners and dominates
  //     every other copy. The leaves of the cut locus of a polyhedral surface
  //     are vertices of positive curvature:
  //     * leaf_curvature: every pruned branch that holds at least that much
  //       Gaussian curvature is kept, outwards from the kept structure (paths
  //       to the curvature, branching only where two branches both hold enough);
  //     * else leaf_extension: from every leaf face of the kept structure, go
  //       on into its most significant pruned child branch while that is
  //       significant enough (one path per leaf).
  std::vector<char> extension(nd, 0);
  const double leaf_extension = get_leaf_extension(np);
  const double extension_threshold = leaf_extension * threshold;
  if(!st.fallback_single_rung && leaf_curvature > 0)
  {
    // every pruned branch hanging from the kept structure (or from a branch
    // added here) that holds at least `leaf_curvature` of curvature: from the
    // core outwards (reverse peeling order), so a branch's parent is decided first
    // (with hysteresis: an added branch goes on into its child branch of most
    // curvature while that holds a quarter of it, so that it reaches the
    // vertex whose curvature its last faces share)
    auto parent_of = [&](std::size_t d) {
      return across(d, child_face[d]);
    };
    std::vector<std::size_t> best_child(nf, none);
    for(std::size_t d : peel_order)
    {
      const std::size_t p = parent_of(d);
      if(best_child[p] == none || subtree_curvature[d] > subtree_curvature[best_child[p]]) best_child[p] = d;
    }
    std::vector<char> inside(nf, 0); // 1 kept, 2 reached by an extension
    for(std::size_t f = 0; f < nf; ++f) inside[f] = kept_degree[f] > 0 ? 1 : 0;
    for(auto it = peel_order.rbegin(); it != peel_order.rend(); ++it)
    {
      const std::size_t d = *it;
      const std::size_t p = parent_of(d);
      if(kept[d] || false_branch[d] || !inside[p]) continue;
      const bool goes_on = inside[p] == 2 && best_child[p] == d && subtree_curvature[d] >= 0.25 * leaf_curvature;
      if(!goes_on && subtree_curvature[d] < leaf_curvature) continue;
      extension[d] = 1;
      inside[child_face[d]] = 2;
    }
  }
  else if(!st.fallback_single_rung && leaf_extension < 1)
    for(std::size_t f = 0; f < nf; ++f)
    {
      if(kept_degree[f] != 1) continue;
      for(std::size_t cur = f;;)
      {
        std::size_t best = none;
        for(unsigned char k = 0; k < dual_degree[cur]; ++k)
        {
          const std::size_t d = dual_of_face[cur][k];
          if(kept[d] || extension[d] || false_branch[d] || !peeled[d] || child_face[d] == cur) continue;
          const double I = r.significance[ei(r.dual_edges[d])];
          if(I >= extension_threshold && (best == none || I > r.significance[ei(r.dual_edges[best])])) best = d;
        }
        if(best == none) break;
        extension[best] = 1;
        cur = child_face[best];
      }
    }
  {
    std::vector<unsigned char> degree_with_extension(kept_degree);
    for(std::size_t d = 0; d < nd; ++d)
      if(extension[d])
      {
        ++degree_with_extension[dual_faces_of[d][0]];
        ++degree_with_extension[dual_faces_of[d][1]];
      }
    for(std::size_t f = 0; f < nf; ++f) st.number_of_extended_dual_leaves += (degree_with_extension[f] == 1);
  }
  for(std::size_t d = 0; d < nd; ++d)
    if(false_branch[d]) r.edge_role[ei(r.dual_edges[d])] = Edge_role::dual_false_branch;
  for(std::size_t d = 0; d < nd; ++d)
    if(extension[d])
    {
      r.edge_role[ei(r.dual_edges[d])] = Edge_role::dual_leaf_extension;
      r.leaf_extension_edges.push_back(r.dual_edges[d]);
      ++st.number_of_leaf_extension_edges;
    }
  for(std::size_t d = 0; d < nd; ++d)
    if(kept[d])
    {
      r.edge_role[ei(r.dual_edges[d])] = Edge_role::dual_kept;
      r.kept_dual_edges.push_back(r.dual_edges[d]);
    }
  st.number_of_kept_dual_edges = nkept;

  // 3a. The rungs (mesh edges crossed by kept dual edges) reduced to a
  //     maximum-significance spanning tree (Kruskal).
  std::vector<std::size_t> rungs;
  for(std::size_t d = 0; d < nd; ++d) if(kept[d] || extension[d]) rungs.push_back(d);
  std::stable_sort(rungs.begin(), rungs.end(), [&](std::size_t a, std::size_t b) {
    return r.significance[ei(r.dual_edges[a])] > r.significance[ei(r.dual_edges[b])];
  });
  r.is_cut_edge.assign(ne, 0);
  std::vector<std::size_t> cut_degree(nv, 0);
  auto add_cut = [&](std::size_t d) {
    const edge_descriptor e = r.dual_edges[d];
    r.is_cut_edge[ei(e)] = 1;
    ++cut_degree[vi(source(e, tm))];
    ++cut_degree[vi(target(e, tm))];
  };
  {
    Union_find uf(nv);
    for(std::size_t d : rungs)
    {
      const edge_descriptor e = r.dual_edges[d];
      if(uf.unite(vi(source(e, tm)), vi(target(e, tm)))) add_cut(d);
    }
  }

  // 3b. Genus g: add back the 2g rungs that close the non-contractible cycles.
  //     A rung may be added iff the faces stay connected across non-cut edges
  //     (its dual edge is no bridge), i.e. it closes no contractible cycle. The
  //     candidates that qualify form a cographic matroid, so greedy is optimal,
  //     and a connected cut surface with Euler characteristic 1 is a disk.
  if(st.genus > 0)
  {
    std::vector<std::size_t> mark(nf, 0);
    std::size_t stamp = 0;
    for(std::size_t d : rungs)
    {
      if(st.number_of_closing_rungs == static_cast<std::size_t>(2 * st.genus)) break;
      const edge_descriptor e = r.dual_edges[d];
      if(r.is_cut_edge[ei(e)]) continue;
      // Alternating BFS from both faces of e, never crossing K or e: it stops
      // after O(smaller side) steps when e is a bridge.
      const std::size_t ma = ++stamp, mb = ++stamp;
      std::deque<std::size_t> qa{dual_faces_of[d][0]}, qb{dual_faces_of[d][1]};
      mark[qa.front()] = ma;
      mark[qb.front()] = mb;
      bool joined = false;
      auto step = [&](std::deque<std::size_t>& q, std::size_t mine, std::size_t other) {
        const std::size_t f = q.front();
        q.pop_front();
        for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of[f], tm), tm))
        {
          const edge_descriptor eh = edge(h, tm);
          if(r.is_cut_edge[ei(eh)] || eh == e) continue;
          const std::size_t g = fi(face(opposite(h, tm), tm));
          if(mark[g] == other) { joined = true; return; }
          if(mark[g] != mine) { mark[g] = mine; q.push_back(g); }
        }
      };
      while(!joined && !qa.empty() && !qb.empty())
      {
        step(qa, ma, mb);
        if(!joined && !qb.empty()) step(qb, mb, ma);
      }
      if(joined)
      {
        add_cut(d);
        ++st.number_of_closing_rungs;
      }
    }
    if(st.number_of_closing_rungs != static_cast<std::size_t>(2 * st.genus))
      throw Algorithm_error("found " + std::to_string(st.number_of_closing_rungs) +
                            " of the " + std::to_string(2 * st.genus) +
                            " rungs closing the non-contractible cycles");
  }

  // 3c. No teeth: a spanning tree of the rungs keeps every zigzag tooth of the
  //     strip as a one-edge leaf. A leaf of K is a tooth unless its dual edge is
  //     the outermost cut rung of its branch of T* (nothing cut further out).
  //     Removing a leaf of K keeps K connected and the cut surface a disk.
  {
    std::vector<char> cut_beyond(nd, 0);
    std::vector<char> face_has_cut_beyond(nf, 0);
    for(std::size_t d : peel_order)
    {
      const std::size_t c = child_face[d];
      const std::size_t p = across(d, c);
      cut_beyond[d] = face_has_cut_beyond[c];
      if(cut_beyond[d] || r.is_cut_edge[ei(r.dual_edges[d])]) face_has_cut_beyond[p] = 1;
    }
    for(std::size_t d = 0; d < nd; ++d)
      if(!peeled[d]) cut_beyond[d] = 1; // a cycle of the 2-core never ends
    std::vector<std::size_t> dual_index_of_edge(ne, none);
    for(std::size_t d = 0; d < nd; ++d) dual_index_of_edge[ei(r.dual_edges[d])] = d;

    std::size_t cut_size = 0;
    for(std::size_t i = 0; i < ne; ++i) cut_size += r.is_cut_edge[i];
    std::vector<vertex_descriptor> leaves;
    for(vertex_descriptor v : vertices(tm))
      if(cut_degree[vi(v)] == 1) leaves.push_back(v);
    while(!leaves.empty() && cut_size > 1)
    {
      const vertex_descriptor w = leaves.back();
      leaves.pop_back();
      if(cut_degree[vi(w)] != 1) continue;
      halfedge_descriptor hw = GT::null_halfedge();
      for(halfedge_descriptor h : CGAL::halfedges_around_target(w, tm))
        if(r.is_cut_edge[ei(edge(h, tm))]) { hw = h; break; }
      const std::size_t d = dual_index_of_edge[ei(edge(hw, tm))];
      if(!cut_beyond[d]) continue; // the end of a branch: keep it
      r.is_cut_edge[ei(edge(hw, tm))] = 0;
      --cut_size;
      --cut_degree[vi(w)];
      const vertex_descriptor u = source(hw, tm);
      if(--cut_degree[vi(u)] == 1) leaves.push_back(u);
      ++st.number_of_teeth_pruned;
    }
  }

  // 3d. Leaves at corners. The cut locus ends at vertices of positive
  //     curvature (generically every such vertex is a leaf: one shortest path
  //     reaches it). A leaf of K one or two edges past a sharp corner (more
  //     than 100 degrees, a doubly covered square's has 180), or a corner
  //     (60 degrees or more) left off K, puts the slit's end beside the
  //     ridge's end; the fronts on both sides of the corner then come out
  //     wrong. So the leaf is moved back onto the corner, and a corner off K
  //     joined to it. Measured (bench_ridge_accuracy): trimming at corners of
  //     60 degrees cut real branches through the 77-90 degree ear tips of
  //     bunny_1k (recall p95 at tolerance 0.001 0.27 -> 4.5 mean edges).
  if(!st.fallback_single_rung && leaf_curvature > 0)
  {
    const double degree_to_radian = 3.14159265358979323846 / 180.0;
    const double corner = 60 * degree_to_radian, sharp_corner = 100 * degree_to_radian;
    std::vector<char> is_seed(nv, 0);
    for(const auto& sd : src.seeds) is_seed[vi(sd.first)] = 1;
    if(src.kind == Geodesic_source<TriangleMesh>::ON_VERTEX) is_seed[vi(src.vertex)] = 1;
    // a cut edge at v other than `not_this`, as a halfedge pointing into v
    auto cut_halfedge_into = [&](vertex_descriptor v, halfedge_descriptor not_this) {
      for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
        if(r.is_cut_edge[ei(edge(h, tm))] && (not_this == GT::null_halfedge() || edge(h, tm) != edge(not_this, tm)))
          return h;
      return GT::null_halfedge();
    };
    std::vector<vertex_descriptor> leaves;
    for(vertex_descriptor v : vertices(tm))
      if(cut_degree[vi(v)] == 1 && angles.curvature(vi(v)) < corner) leaves.push_back(v);
    for(vertex_descriptor w : leaves)
    {
      // past a sharp corner: walk in through at most two vertices of degree 2
      std::vector<halfedge_descriptor> path;
      halfedge_descriptor h = cut_halfedge_into(w, GT::null_halfedge());
      for(int step = 0; step < 2 && h != GT::null_halfedge(); ++step)
      {
        path.push_back(h);
        const vertex_descriptor u = source(h, tm);
        // (u keeps a cut edge, so K never becomes empty)
        if(angles.curvature(vi(u)) >= sharp_corner && !is_seed[vi(u)] && cut_degree[vi(u)] >= 2)
        {
          for(halfedge_descriptor p : path)
          {
            r.is_cut_edge[ei(edge(p, tm))] = 0;
            --cut_degree[vi(source(p, tm))];
            --cut_degree[vi(target(p, tm))];
          }
          ++st.number_of_corner_moves;
          break;
        }
        if(cut_degree[vi(u)] != 2) break;
        h = cut_halfedge_into(u, h); // the other cut edge at u, again pointing outwards
      }
    }
    // a corner off K: joined to K by the shortest path of at most three edges
    // through vertices off K (a pendant path: K stays a tree plus its 2g rungs)
    std::vector<vertex_descriptor> corners;
    for(vertex_descriptor v : vertices(tm))
      if(cut_degree[vi(v)] == 0 && !is_seed[vi(v)] && angles.curvature(vi(v)) >= corner) corners.push_back(v);
    std::stable_sort(corners.begin(), corners.end(), [&](vertex_descriptor a, vertex_descriptor b) {
      return angles.curvature(vi(a)) > angles.curvature(vi(b));
    });
    const int maximum_hops = 3;
    std::vector<vertex_descriptor> vertex_of(nv);
    for(vertex_descriptor v : vertices(tm)) vertex_of[vi(v)] = v;
    std::vector<double> reach(nv, std::numeric_limits<double>::infinity());
    std::vector<int> hops(nv, 0);
    std::vector<halfedge_descriptor> reached_by(nv, GT::null_halfedge());
    std::vector<std::size_t> touched;
    for(vertex_descriptor c : corners)
    {
      if(cut_degree[vi(c)] != 0) continue;
      for(std::size_t t : touched) { reach[t] = std::numeric_limits<double>::infinity(); reached_by[t] = GT::null_halfedge(); }
      touched.clear();
      typedef std::pair<double, std::size_t> Entry;
      std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
      reach[vi(c)] = 0; hops[vi(c)] = 0; touched.push_back(vi(c));
      queue.emplace(0.0, vi(c));
      vertex_descriptor found = GT::null_vertex();
      while(!queue.empty())
      {
        const double d = queue.top().first;
        const vertex_descriptor u = vertex_of[queue.top().second];
        queue.pop();
        if(d > reach[vi(u)]) continue;
        if(cut_degree[vi(u)] > 0) { found = u; break; }
        if(hops[vi(u)] == maximum_hops) continue;
        for(halfedge_descriptor h : CGAL::halfedges_around_target(u, tm))
        {
          const vertex_descriptor w = source(h, tm);
          if(is_seed[vi(w)]) continue;
          const double dw = d + std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, u), get(vpm, w))));
          if(dw >= reach[vi(w)]) continue;
          if(reach[vi(w)] == std::numeric_limits<double>::infinity()) touched.push_back(vi(w));
          reach[vi(w)] = dw; hops[vi(w)] = hops[vi(u)] + 1; reached_by[vi(w)] = h;
          queue.emplace(dw, vi(w));
        }
      }
      if(found == GT::null_vertex()) continue;
      for(vertex_descriptor u = found; u != c;)
      {
        const halfedge_descriptor h = reached_by[vi(u)]; // from u back towards c
        r.is_cut_edge[ei(edge(h, tm))] = 1;
        r.corner_path_edges.push_back(edge(h, tm));
        ++cut_degree[vi(source(h, tm))];
        ++cut_degree[vi(target(h, tm))];
        u = target(h, tm);
      }
      ++st.number_of_corner_moves;
    }
  }
  for(std::size_t i = 0; i < ne; ++i)
    if(r.is_cut_edge[i]) r.cut_edges.push_back(edge_of[i]);
  std::sort(r.dual_edges.begin(), r.dual_edges.end(),
            [&](edge_descriptor a, edge_descriptor b) { return ei(a) < ei(b); });
  std::sort(r.kept_dual_edges.begin(), r.kept_dual_edges.end(),
            [&](edge_descriptor a, edge_descriptor b) { return ei(a) < ei(b); });
  std::sort(r.leaf_extension_edges.begin(), r.leaf_extension_edges.end(),
            [&](edge_descriptor a, edge_descriptor b) { return ei(a) < ei(b); });
  std::sort(r.corner_path_edges.begin(), r.corner_path_edges.end(),
            [&](edge_descriptor a, edge_descriptor b) { return ei(a) < ei(b); });
  st.time_cut_graph = seconds_since(t0);

  // ---------------------------------------------------------------------------
  // 4. Check, always: K is connected with cycle rank 2g, the cut surface is
  //    connected with Euler characteristic 1 (so a disk), the source is off K.
  t0 = std::chrono::steady_clock::now();
  {
    st.number_of_cut_edges = r.cut_edges.size();
    Union_find kuf(nv);
    std::size_t split_vertices = 0;
    for(vertex_descriptor v : vertices(tm))
    {
      const std::size_t k = cut_degree[vi(v)];
      if(k > 0) ++st.number_of_cut_vertices;
      if(k == 1) ++st.number_of_cut_leaves;
      if(k > 1) split_vertices += k - 1;
    }
    for(edge_descriptor e : r.cut_edges) kuf.unite(vi(source(e, tm)), vi(target(e, tm)));
    const std::size_t k_components = kuf.number_of_sets() - (nv - st.number_of_cut_vertices);
    st.cut_cycle_rank = st.number_of_cut_edges + k_components - st.number_of_cut_vertices;

    Union_find fuf(nf);
    for(edge_descriptor e : edges(tm))
      if(!r.is_cut_edge[ei(e)])
      {
        const halfedge_descriptor h = halfedge(e, tm);
        fuf.unite(fi(face(h, tm)), fi(face(opposite(h, tm), tm)));
      }
    const long cut_chi = static_cast<long>(nv + split_vertices) -
                         static_cast<long>(ne + st.number_of_cut_edges) + static_cast<long>(nf);
    bool source_on_cut = false;
    if(src.kind == Geodesic_source<TriangleMesh>::ON_VERTEX)
      source_on_cut = cut_degree[vi(src.vertex)] > 0;
    else if(src.kind == Geodesic_source<TriangleMesh>::ON_EDGE)
      source_on_cut = r.is_cut_edge[ei(edge(src.edge_halfedge, tm))] != 0;
    std::string why;
    if(r.cut_edges.empty()) why = "the cut graph is empty";
    else if(k_components != 1) why = "the cut graph has " + std::to_string(k_components) + " components";
    else if(st.cut_cycle_rank != static_cast<std::size_t>(2 * st.genus))
      why = "the cut graph has cycle rank " + std::to_string(st.cut_cycle_rank) + ", not 2g = " +
            std::to_string(2 * st.genus);
    else if(fuf.number_of_sets() != 1)
      why = "cutting along K splits the surface into " + std::to_string(fuf.number_of_sets()) + " parts";
    else if(cut_chi != 1)
      why = "the cut surface has Euler characteristic " + std::to_string(cut_chi) + ", not 1";
    else if(source_on_cut)
      why = "the source lies on the cut";
    if(!why.empty())
      throw Algorithm_error("rough cut locus: cutting along K does not give a disk: " + why);
  }
  st.time_disk_check = seconds_since(t0);
  st.time_total = seconds_since(t_start);
  return r;
}

} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
/// Computes the rough cut locus of `source` on the closed triangle mesh `tm`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph`-free
///         `HalfedgeListGraph` (e.g. `CGAL::Surface_mesh`), closed, connected, manifold.
/// \param tm the mesh; it is validated first (`Invalid_mesh_error` if not supported)
/// \param source a vertex of `tm` (`Invalid_source_error` otherwise)
/// \param np an optional sequence of named parameters:
///   `Geodesic_ridge::parameters::tolerance(t)` (default 0.025, in [0, 0.5),
///   else `Invalid_parameter_error`), and CGAL's `vertex_point_map`,
///   `vertex_index_map`, `edge_index_map`, `face_index_map`.
/// \post cutting `tm` along `cut_edges` gives one topological disk with the
///       source strictly inside; `Algorithm_error` is thrown if it ever does not.
template <class TriangleMesh,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Rough_cut_locus<TriangleMesh>
compute_rough_cut_locus(const TriangleMesh& tm,
                        typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::get_tolerance(np); // a bad parameter is reported before any work
  validate_triangle_mesh(tm, np);
  return internal::rough_cut_locus_impl(tm, make_source(tm, source, np), np);
}

/// \ingroup PkgGeodesicRidgeRef
/// Same, from a surface point given as a `Face_location` (face + barycentric
/// coordinates in CGAL's order). A location on an edge or a vertex is handled
/// as such.
template <class TriangleMesh, class FT,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Rough_cut_locus<TriangleMesh>
compute_rough_cut_locus(const TriangleMesh& tm,
                        const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                        std::array<FT, 3> >& source,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::get_tolerance(np);
  validate_triangle_mesh(tm, np);
  return internal::rough_cut_locus_impl(tm, make_source(tm, source, np), np);
}

/// \ingroup PkgGeodesicRidgeRef
/// Writes the cut graph K as polylines (`std::vector<Point_3>`) to `out`, one
/// per chain between vertices of K whose degree is not 2 (closed chains repeat
/// their first point).
template <class TriangleMesh, class OutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator cut_graph_polylines(const TriangleMesh& tm, const Rough_cut_locus<TriangleMesh>& rcl,
                                   OutputIterator out,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  std::vector<vertex_descriptor> vertex_of(num_vertices(tm));
  for(vertex_descriptor v : vertices(tm)) vertex_of[get(vim, v)] = v;
  std::vector<std::pair<std::size_t, std::size_t> > graph;
  for(const auto& e : rcl.cut_edges)
    graph.emplace_back(get(vim, source(e, tm)), get(vim, target(e, tm)));
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  for(const auto& chain : internal::graph_to_chains(num_vertices(tm), graph))
  {
    std::vector<Point> polyline;
    for(std::size_t v : chain) polyline.push_back(get(vpm, vertex_of[v]));
    *out++ = polyline;
  }
  return out;
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_ROUGH_CUT_LOCUS_H
