// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1: the rough cut locus (the manual's "Stage 1: The Rough Cut Locus", paper §3.1).
//
//   Dijkstra shortest-path tree T  ->  dual T* of the non-tree edges
//   -> significance of every dual edge  -> pruning by tolerance
//   -> primal cut graph K on mesh edges: cutting the mesh along K gives one
//      topological disk with the source strictly inside.
#ifndef GEODESIC_RIDGE_ROUGH_CUT_LOCUS_H
#define GEODESIC_RIDGE_ROUGH_CUT_LOCUS_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/corner_angles.h>
#include <Geodesic_ridge/internal/edge_graph_distances.h>
#include <Geodesic_ridge/internal/graph_polylines.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/normalization.h>
#include <Geodesic_ridge/internal/tuning.h>
#include <Geodesic_ridge/internal/union_find.h>
#include <Geodesic_ridge/mesh_validation.h>
#include <Geodesic_ridge/parameters.h>
#include <Geodesic_ridge/source.h>
#include <Geodesic_ridge/timings.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <queue>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// What a mesh edge is to the rough cut locus.
enum class Edge_role : unsigned char
{
  shortest_path_tree, ///< an edge of the shortest-path tree T
  source_face,        ///< an edge of a face holding the source (never crossed by T*)
  dual_pruned,        ///< crossed by an edge of T* whose significance is below the tolerance
  dual_kept,          ///< crossed by an edge of T* that survives the pruning
  dual_leaf_extension, ///< crossed by a pruned edge of T* kept for the curvature it holds (see
                       ///< `leaf_curvature`)
  dual_false_branch    ///< crossed by an edge of T* significant enough but on a branch that encloses no
                       ///< curvature: a false branch (see `branch_curvature`)
};

/// \ingroup PkgGeodesicRidgeRef
/// Counts of stage 1.
struct Rough_cut_locus_statistics
{
  int genus = 0;                          ///< the genus g of the mesh, from its Euler characteristic
  std::size_t number_of_boundary_loops = 0; ///< b: the loops of border edges (0 on a closed mesh)
  std::size_t number_of_vertices = 0;     ///< vertices of the mesh
  std::size_t number_of_edges = 0;        ///< edges of the mesh
  std::size_t number_of_faces = 0;        ///< faces of the mesh
  std::size_t number_of_dual_edges = 0;      ///< |T*| = F' - 1 + 2g (F' = faces not holding the source)
  std::size_t number_of_core_dual_edges = 0; ///< dual edges on the 2-core (significance = total area)
  std::size_t number_of_kept_dual_edges = 0; ///< dual edges that survive the pruning (the kept dual structure)
  std::size_t number_of_kept_dual_leaves = 0; ///< faces with exactly one kept dual edge
  std::size_t number_of_extended_dual_leaves = 0; ///< same, with the leaf extension edges (`leaf_curvature`) too
  std::size_t number_of_leaf_extension_edges = 0; ///< pruned dual edges kept for their curvature (`leaf_curvature`)
  std::size_t number_of_cut_edges = 0;        ///< |K|
  std::size_t number_of_cut_vertices = 0;    ///< vertices of K
  std::size_t number_of_cut_leaves = 0;       ///< vertices of degree 1 in K, not on the border
  std::size_t cut_cycle_rank = 0;             ///< of K ∪ ∂M (K on a closed mesh): equals 2g + b
  std::size_t number_of_closing_rungs = 0;    ///< rungs added back to close the 2g cycles
  std::size_t number_of_teeth_pruned = 0;     ///< one-edge leaves of K removed
  std::size_t number_of_curvature_pruned_dual_edges = 0; ///< kept dual edges of false branches (see `branch_curvature`)
  std::size_t number_of_corner_moves = 0;     ///< leaves of K moved back onto a corner (large curvature), corners where K forks rid of their one-edge prongs, and corners joined to K
  bool fallback_single_rung = false;          ///< no dual edge reached the tolerance: K is the best rung
};

/// \ingroup PkgGeodesicRidgeRef
/// The result of stage 1. Per-vertex vectors are indexed by the vertex index
/// map, per-edge vectors by the edge index map (for `CGAL::Surface_mesh`:
/// `v.idx()` and `e.idx()`).
template <class TriangleMesh>
struct Rough_cut_locus
{
  typedef boost::graph_traits<TriangleMesh>   GT;                ///< the graph traits of `TriangleMesh`
  typedef typename GT::vertex_descriptor     vertex_descriptor; ///< a vertex of the mesh
  typedef typename GT::edge_descriptor       edge_descriptor;   ///< an edge of the mesh
  typedef typename GT::face_descriptor       face_descriptor;   ///< a face of the mesh

  Geodesic_source<TriangleMesh> source; ///< the source, validated (`make_source()`)
  double tolerance = default_tolerance; ///< the significance tolerance used (a fraction of the total area)
  double total_area = 0;                ///< the total area of the mesh (the unit of the tolerance)

  /// the distance the tree follows (per vertex): Dijkstra's along mesh edges,
  /// or inside the pipeline the geodesic field it was given
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
  /// pruned ones kept for the curvature they hold (`leaf_curvature`), by increasing edge index
  std::vector<edge_descriptor> leaf_extension_edges;
  /// edges of K that are no rungs: paths that join a corner to K (the leaves
  /// at corners, \ref GeodesicRidgeSecStage1), by increasing edge index
  std::vector<edge_descriptor> corner_path_edges;
  /// the primal cut graph K, by increasing edge index
  std::vector<edge_descriptor> cut_edges;

  Rough_cut_locus_statistics statistics; ///< counts of stage 1
  /// seconds per step: `shortest_path_tree`, `significance` (the dual and the
  /// significance of its edges), `cut_graph` (the pruning and K), `disk_check`
  /// (K connected with cycle rank 2g, the cut surface a disk)
  Timings timings;
};

namespace internal {

// Stage 1 as its named steps (the manual's order), over the state they share.
// `run()` calls them in order; each step reads what the steps before it left.
template <class TriangleMesh, class Maps>
class Rough_cut_locus_builder
{
  typedef boost::graph_traits<TriangleMesh>  GT;
  typedef typename GT::vertex_descriptor    vertex_descriptor;
  typedef typename GT::halfedge_descriptor  halfedge_descriptor;
  typedef typename GT::edge_descriptor      edge_descriptor;
  typedef typename GT::face_descriptor      face_descriptor;
  typedef Geodesic_source<TriangleMesh>     Source;

public:
  // The curvature thresholds in radians.
  struct Options
  {
    double tolerance = default_tolerance, leaf_curvature = 0, branch_curvature = 0;
    // the mesh's corner angles, when a batch of sources computed them once
    const Corner_angles* corner_angles = nullptr;
  };

  Rough_cut_locus_builder(const TriangleMesh& tm, const Source& src, const Maps& maps, const Options& options)
    : tm_(tm), src_(src), maps_(maps), options_(options),
      nv_(num_vertices(tm)), ne_(num_edges(tm)), nf_(num_faces(tm)), st_(r_.statistics)
  {}

  // `field`, if given, holds a geodesic distance per vertex (by vertex index):
  // the tree then follows it (`descend_field`) instead of Dijkstra's edge distances.
  Rough_cut_locus<TriangleMesh> run(const std::vector<double>* field = nullptr)
  {
    Timings& timings = r_.timings;
    timings.time("shortest_path_tree", [&] {
      count_elements();
      shortest_path_tree();
      if(field != nullptr) descend_field(*field);
    });
    timings.time("significance", [&] {
      classify_edges();
      measure_face_areas();
      build_dual_adjacency();
      share_curvature_among_faces();
      peel_significance();
    });
    timings.time("cut_graph", [&] {
      prune_by_significance();
      prune_false_branches();
      if(!st_.fallback_single_rung && options_.leaf_curvature > 0) extend_leaves_by_curvature();
      record_dual_roles();
      span_rungs();
      close_handle_cycles();
      remove_teeth();
      if(!st_.fallback_single_rung && options_.leaf_curvature > 0)
      {
        move_leaves_onto_corners();
        remove_prongs_at_corner_forks();
        join_corners();
      }
      collect_cut_edges();
    });
    timings.time("disk_check", [&] { check_disk(); });
    return std::move(r_);
  }

private:
  std::size_t vi(vertex_descriptor v) const { return static_cast<std::size_t>(get(maps_.vim, v)); }
  std::size_t ei(edge_descriptor e) const { return static_cast<std::size_t>(get(maps_.eim, e)); }
  std::size_t fi(face_descriptor f) const { return static_cast<std::size_t>(get(maps_.fim, f)); }
  double significance(std::size_t d) const { return r_.significance[ei(r_.dual_edges[d])]; }
  // the face of dual edge d other than f
  std::size_t across(std::size_t d, std::size_t f) const
  {
    return dual_faces_of_[d][0] == f ? dual_faces_of_[d][1] : dual_faces_of_[d][0];
  }
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  bool curvature_sums() const { return options_.leaf_curvature > 0 || options_.branch_curvature > 0; }

  void count_elements()
  {
    r_.source = src_;
    r_.tolerance = options_.tolerance;
    st_.number_of_vertices = nv_;
    st_.number_of_edges = ne_;
    st_.number_of_faces = nf_;
    st_.number_of_boundary_loops = boundary_loops();
    const long chi = static_cast<long>(nv_) - static_cast<long>(ne_) + static_cast<long>(nf_);
    st_.genus = static_cast<int>((2 - chi - static_cast<long>(st_.number_of_boundary_loops)) / 2);
    edge_of_.resize(ne_);
    for(edge_descriptor e : edges(tm_))
    {
      if(ei(e) >= ne_)
        throw Invalid_mesh_error("mesh has removed elements (call collect_garbage() first)");
      edge_of_[ei(e)] = e;
    }
    face_of_.resize(nf_);
    for(face_descriptor f : faces(tm_))
    {
      if(fi(f) >= nf_)
        throw Invalid_mesh_error("mesh has removed elements (call collect_garbage() first)");
      face_of_[fi(f)] = f;
    }
    is_seed_.assign(nv_, 0);
    for(const auto& s : src_.seeds) is_seed_[vi(s.first)] = 1;
  }

  // The number of loops of border edges; marks the border vertices.
  std::size_t boundary_loops()
  {
    Union_find loops(nv_);
    boundary_vertex_.assign(nv_, 0);
    for(halfedge_descriptor h : halfedges(tm_))
      if(is_border(h, tm_))
      {
        boundary_vertex_[vi(source(h, tm_))] = boundary_vertex_[vi(target(h, tm_))] = 1;
        loops.unite(vi(source(h, tm_)), vi(target(h, tm_)));
      }
    std::size_t inside = 0;
    for(std::size_t v = 0; v < nv_; ++v) inside += !boundary_vertex_[v];
    return loops.number_of_sets() - inside;
  }
  bool has_boundary() const { return st_.number_of_boundary_loops > 0; }
  bool on_boundary(vertex_descriptor v) const { return boundary_vertex_[vi(v)] != 0; }
  // Gaussian curvature at v; 0 on the border, where the angle sum measures the
  // turning of the border, not curvature
  double curvature(vertex_descriptor v) const { return on_boundary(v) ? 0.0 : angles_->curvature(vi(v)); }

  // Step 1: Boost's Dijkstra on the mesh graph, several seeds for a surface point.
  void shortest_path_tree()
  {
    const double inf = std::numeric_limits<double>::infinity();
    edge_graph_distances(tm_, maps_, src_.seeds, length_, r_.distance, r_.parent);
    // A straight segment from the source is a geodesic (no edge path in R^3 is
    // shorter), so seeds stay roots and a vertex source's neighbours hang from it,
    // whatever ties the floating-point sums produced: the cut never touches the source.
    for(const auto& s : src_.seeds)
    {
      r_.distance[vi(s.first)] = s.second;
      r_.parent[vi(s.first)] = s.first;
    }
    if(src_.kind == Source::ON_VERTEX)
      for(halfedge_descriptor h : CGAL::halfedges_around_target(src_.vertex, tm_))
      {
        const vertex_descriptor u = source(h, tm_);
        r_.parent[vi(u)] = src_.vertex;
        r_.distance[vi(u)] = length_[ei(edge(h, tm_))];
      }
    for(vertex_descriptor v : vertices(tm_))
      if(!(r_.distance[vi(v)] < inf))
        throw Invalid_mesh_error("vertex " + std::to_string(vi(v)) + " cannot be reached from the source");
  }

  // Step 1, with a geodesic field: every vertex hangs from the neighbour u of
  // smaller field value that minimizes field(u) + |uv|, so the tree descends the
  // true distance instead of Dijkstra's staircase paths, whose anisotropy on
  // regular meshes makes significant dual branches far from the real ridge.
  // Strictly decreasing values make it a tree; where a vertex has no lower
  // neighbour it keeps its Dijkstra parent, and if that mix ever closed a
  // cycle, the whole Dijkstra tree is kept.
  void descend_field(const std::vector<double>& field)
  {
    std::vector<vertex_descriptor> dijkstra_parent = r_.parent;
    for(vertex_descriptor v : vertices(tm_))
    {
      if(is_seed_[vi(v)]) continue;
      if(src_.kind == Source::ON_VERTEX && r_.parent[vi(v)] == src_.vertex && v != src_.vertex)
        continue; // the source's neighbours stay its children
      double best = std::numeric_limits<double>::infinity();
      for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm_))
      {
        const vertex_descriptor u = source(h, tm_);
        if(!(field[vi(u)] < field[vi(v)])) continue;
        const double value = field[vi(u)] + length_[ei(edge(h, tm_))];
        if(value < best) { best = value; r_.parent[vi(v)] = u; }
      }
    }
    if(!parents_form_a_tree()) r_.parent = dijkstra_parent;
    else
      for(vertex_descriptor v : vertices(tm_)) r_.distance[vi(v)] = field[vi(v)];
  }

  // A tree iff every vertex reaches a root (a seed) through its parents.
  bool parents_form_a_tree() const
  {
    std::vector<char> state(nv_, 0); // 0 unknown, 1 in progress, 2 reaches a root
    std::vector<std::size_t> path;   // (reused: no heap block per vertex)
    for(vertex_descriptor v : vertices(tm_))
    {
      path.clear();
      std::size_t x = vi(v);
      while(state[x] == 0 && !is_seed_[x])
      {
        state[x] = 1;
        path.push_back(x);
        x = vi(r_.parent[x]);
      }
      if(state[x] == 1) return false;
      for(std::size_t y : path) state[y] = 2;
      state[x] = 2;
    }
    return true;
  }

  // Step 2: every edge is in T, on a face holding the source, or crossed by T*.
  void classify_edges()
  {
    std::vector<char> is_source_face(nf_, 0);
    for(face_descriptor f : src_.faces) is_source_face[fi(f)] = 1;
    r_.edge_role.assign(ne_, Edge_role::dual_pruned);
    r_.significance.assign(ne_, std::numeric_limits<double>::quiet_NaN());
    for(edge_descriptor e : edges(tm_))
    {
      const halfedge_descriptor h = halfedge(e, tm_);
      const vertex_descriptor a = source(h, tm_), b = target(h, tm_);
      const bool in_tree = (r_.parent[vi(a)] == b && a != b) || (r_.parent[vi(b)] == a && a != b);
      if(in_tree)
        r_.edge_role[ei(e)] = Edge_role::shortest_path_tree;
      else if(touches_source_face(h, is_source_face) || touches_source_face(opposite(h, tm_), is_source_face))
        r_.edge_role[ei(e)] = Edge_role::source_face;
      else
        r_.dual_edges.push_back(e);
    }
    st_.number_of_dual_edges = r_.dual_edges.size();
    // T* has a node per face not holding the source, and one for the border
    // (all its loops): a spanning tree plus 2g + b - 1 independent cycles
    const long nodes = static_cast<long>(nf_ - src_.faces.size()) + (has_boundary() ? 1 : 0);
    const long expected = nodes - 1 + 2 * st_.genus + (has_boundary() ? static_cast<long>(st_.number_of_boundary_loops) - 1 : 0);
    if(static_cast<long>(r_.dual_edges.size()) != expected)
      throw Algorithm_error("the dual of the shortest-path tree has " + std::to_string(r_.dual_edges.size()) +
                            " edges, expected " + std::to_string(expected));
  }

  bool touches_source_face(halfedge_descriptor h, const std::vector<char>& is_source_face) const
  {
    return !is_border(h, tm_) && is_source_face[fi(face(h, tm_))];
  }
  // the node of T* of the face of h: the face's index, or the border node
  std::size_t node_of(halfedge_descriptor h) const { return is_border(h, tm_) ? border_node() : fi(face(h, tm_)); }
  std::size_t border_node() const { return nf_; }

  void measure_face_areas()
  {
    area_.assign(nf_ + 1, 0.0); // (the border node has none)
    r_.total_area = 0;
    for(face_descriptor f : faces(tm_))
    {
      area_[fi(f)] = CGAL::Polygon_mesh_processing::face_area(f, tm_, CGAL::parameters::vertex_point_map(maps_.vpm));
      r_.total_area += area_[fi(f)];
    }
    // The faces holding a surface-point source are no nodes of T*: the two sides
    // of a dual edge share the rest of the area.
    node_total_ = r_.total_area;
    for(face_descriptor f : src_.faces) node_total_ -= area_[fi(f)];
  }

  // the faces of every dual edge, and the dual edges of every face (by position in dual_edges)
  void build_dual_adjacency()
  {
    nd_ = r_.dual_edges.size();
    dual_faces_of_.resize(nd_);
    dual_of_face_.resize(nf_);
    dual_degree_.assign(nf_ + 1, 0); // the border node's is never read
    for(std::size_t d = 0; d < nd_; ++d)
    {
      const halfedge_descriptor h = halfedge(r_.dual_edges[d], tm_);
      const std::size_t f1 = node_of(h), f2 = node_of(opposite(h, tm_));
      dual_faces_of_[d] = {f1, f2};
      for(std::size_t f : {f1, f2})
        if(f != border_node()) dual_of_face_[f][dual_degree_[f]++] = d;
    }
  }

  // Gaussian curvature (2π − angle sum) of every vertex, shared among its
  // faces by angle (and its positive part): the peeling accumulates it per
  // branch of T* like the area, for the false branches and the leaf curvature
  // extension. The corner angles serve the leaves at corners too.
  void share_curvature_among_faces()
  {
    if(!curvature_sums()) return;
    if(options_.corner_angles) angles_ = options_.corner_angles;
    else
    {
      own_angles_ = corner_angles(tm_, maps_.vpm, maps_.vim, maps_.fim);
      angles_ = &own_angles_;
    }
    curvature_share_.assign(nf_ + 1, 0.0);
    positive_share_.assign(nf_ + 1, 0.0);
    for(face_descriptor f : faces(tm_))
    {
      halfedge_descriptor h = halfedge(f, tm_);
      for(int k = 0; k < 3; ++k, h = next(h, tm_))
      {
        const std::size_t v = vi(source(h, tm_));
        // the source is no leaf of its own cut locus
        if(src_.kind == Source::ON_VERTEX && source(h, tm_) == src_.vertex) continue;
        const double share = angles_->angle[fi(f)][k] / angles_->angle_sum[v];
        curvature_share_[fi(f)] += curvature(source(h, tm_)) * share;
        positive_share_[fi(f)] += std::max(0.0, curvature(source(h, tm_))) * share;
      }
    }
  }

  // Peel leaves of T* (O(F)): when a face becomes a leaf, its one remaining dual
  // edge separates the faces accumulated in it from the rest. What is never
  // peeled is the 2-core (the non-contractible cycles and the paths joining
  // them); its edges get the total area. The border node is never peeled: with
  // a border, T* is rooted there, and an edge's significance is the area of
  // its side away from the border (the other side reaches the border, and a
  // branch is no less significant for reaching it).
  void peel_significance()
  {
    std::vector<double> branch_curvature(curvature_share_), branch_positive(positive_share_);
    branch_curvature.resize(nf_ + 1, 0.0);
    branch_positive.resize(nf_ + 1, 0.0);
    subtree_curvature_.assign(curvature_sums() ? nd_ : 0, 0.0);
    subtree_positive_.assign(curvature_sums() ? nd_ : 0, 0.0);
    std::vector<double> accumulated(area_);
    std::vector<unsigned char> degree(dual_degree_);
    peeled_.assign(nd_, 0);
    child_face_.assign(nd_, none);
    peel_order_.reserve(nd_);
    std::vector<std::size_t> queue;
    for(std::size_t f = 0; f < nf_; ++f)
      if(degree[f] == 1) queue.push_back(f);
    for(std::size_t qi = 0; qi < queue.size(); ++qi)
    {
      const std::size_t f = queue[qi];
      if(degree[f] != 1) continue;
      std::size_t d = none;
      for(unsigned char k = 0; k < dual_degree_[f]; ++k)
        if(!peeled_[dual_of_face_[f][k]]) d = dual_of_face_[f][k];
      peeled_[d] = 1;
      child_face_[d] = f;
      peel_order_.push_back(d);
      const double side = accumulated[f];
      r_.significance[ei(r_.dual_edges[d])] = has_boundary() ? side : (std::min)(side, node_total_ - side);
      const std::size_t p = across(d, f);
      accumulated[p] += side;
      if(curvature_sums())
      {
        subtree_curvature_[d] = branch_curvature[f];
        branch_curvature[p] += branch_curvature[f];
        subtree_positive_[d] = branch_positive[f];
        branch_positive[p] += branch_positive[f];
      }
      degree[f] = 0;
      if(--degree[p] == 1 && p != border_node()) queue.push_back(p);
    }
    for(std::size_t d = 0; d < nd_; ++d)
      if(!peeled_[d])
      {
        r_.significance[ei(r_.dual_edges[d])] = r_.total_area;
        ++st_.number_of_core_dual_edges;
      }
  }

  // Step 3: keep the dual edges of significance at least tolerance × area.
  void prune_by_significance()
  {
    threshold_ = r_.tolerance * r_.total_area;
    kept_.assign(nd_, 0);
    extension_.assign(nd_, 0);
    for(std::size_t d = 0; d < nd_; ++d)
      if(significance(d) >= threshold_) { kept_[d] = 1; ++nkept_; }
    if(nkept_ == 0 && nd_ > 0 && !has_boundary())
    {
      // Genus 0 with a tolerance close to 1/2: keep the most significant dual
      // edge, so that K is one slit and the cut surface still a disk.
      std::size_t best = 0;
      for(std::size_t d = 1; d < nd_; ++d)
        if(significance(d) > significance(best)) best = d;
      kept_[best] = 1;
      nkept_ = 1;
      st_.fallback_single_rung = true;
    }
    kept_degree_.assign(nf_ + 1, 0);
    for(std::size_t d = 0; d < nd_; ++d)
      if(kept_[d])
      {
        ++kept_degree_[dual_faces_of_[d][0]];
        ++kept_degree_[dual_faces_of_[d][1]];
      }
  }

  // Branches that enclose no curvature are false (see parameters::branch_curvature):
  // pruned back from their tips while the curvature beyond the tip's dual edge
  // is below the minimum. The 2-core (genus) is never touched; one dual edge at
  // least is kept.
  void prune_false_branches()
  {
    false_branch_.assign(nd_, 0);
    if(options_.branch_curvature > 0 && !st_.fallback_single_rung)
    {
      double total_curvature = 0, total_positive = 0;
      for(double c : curvature_share_) total_curvature += c;
      for(double c : positive_share_) total_positive += c;
      // the curvature, and its positive part, on the side of d that encloses the
      // two paths' meeting: the branch's side, or on genus 0 the side of less curvature
      auto enclosed = [&](std::size_t d) {
        const double c = subtree_curvature_[d];
        if(st_.genus == 0 && !has_boundary() && total_curvature - c < c)
          return std::make_pair(total_curvature - c, total_positive - subtree_positive_[d]);
        return std::make_pair(c, subtree_positive_[d]);
      };
      std::vector<std::size_t> tips;
      for(std::size_t f = 0; f < nf_; ++f) if(kept_degree_[f] == 1) tips.push_back(f);
      while(!tips.empty() && (nkept_ > 1 || has_boundary())) // (with a border, K may be empty)
      {
        const std::size_t f = tips.back();
        tips.pop_back();
        if(kept_degree_[f] != 1) continue;
        std::size_t d = none;
        for(unsigned char k = 0; k < dual_degree_[f]; ++k)
          if(kept_[dual_of_face_[f][k]]) d = dual_of_face_[f][k];
        if(!peeled_[d]) continue;
        // false: nearly no curvature enclosed, and no bump either (a bump with
        // its saddle-shaped foot encloses little in total but splits fronts)
        const auto [net, positive] = enclosed(d);
        if(net >= options_.branch_curvature || positive >= 2 * options_.branch_curvature) continue;
        kept_[d] = 0;
        false_branch_[d] = 1;
        --nkept_;
        ++st_.number_of_curvature_pruned_dual_edges;
        kept_degree_[f] = 0;
        const std::size_t p = across(d, f);
        if(--kept_degree_[p] == 1 && p != border_node()) tips.push_back(p);
      }
    }
    for(std::size_t f = 0; f < nf_; ++f) st_.number_of_kept_dual_leaves += (kept_degree_[f] == 1);
  }

  // Extensions of the kept structure into pruned branches. The ridge shows only
  // where K cuts: beyond K's end, the disk's copy of a face carries the smaller
  // of the two fronts at its corners and dominates every other copy. The leaves
  // of the cut locus of a polyhedral surface are vertices of positive curvature,
  // so every pruned branch that holds at least `leaf_curvature` of Gaussian
  // curvature is kept, outwards from the kept structure (paths to the curvature,
  // branching only where two branches both hold enough). From the core outwards
  // (reverse peeling order), so a branch's parent is decided first; with
  // hysteresis: an added branch goes on into its child branch of most curvature
  // while that holds a quarter of it, so that it reaches the vertex whose
  // curvature its last faces share.
  void extend_leaves_by_curvature()
  {
    auto parent_of = [&](std::size_t d) { return across(d, child_face_[d]); };
    std::vector<std::size_t> best_child(nf_ + 1, none);
    for(std::size_t d : peel_order_)
    {
      const std::size_t p = parent_of(d);
      if(best_child[p] == none || subtree_curvature_[d] > subtree_curvature_[best_child[p]]) best_child[p] = d;
    }
    std::vector<char> inside(nf_ + 1, 0); // 1 kept (the border always), 2 reached by an extension
    for(std::size_t f = 0; f < nf_; ++f) inside[f] = kept_degree_[f] > 0 ? 1 : 0;
    inside[border_node()] = has_boundary() ? 1 : 0;
    for(auto it = peel_order_.rbegin(); it != peel_order_.rend(); ++it)
    {
      const std::size_t d = *it;
      const std::size_t p = parent_of(d);
      if(kept_[d] || false_branch_[d] || !inside[p]) continue;
      const bool goes_on =
          inside[p] == 2 && best_child[p] == d && subtree_curvature_[d] >= tuning::rough_cut::extension_curvature_share * options_.leaf_curvature;
      if(!goes_on && subtree_curvature_[d] < options_.leaf_curvature) continue;
      extension_[d] = 1;
      inside[child_face_[d]] = 2;
    }
  }

  void record_dual_roles()
  {
    std::vector<unsigned char> degree_with_extension(kept_degree_);
    degree_with_extension[border_node()] = 0; // (not a face: never a leaf)
    for(std::size_t d = 0; d < nd_; ++d)
      if(extension_[d])
      {
        ++degree_with_extension[dual_faces_of_[d][0]];
        ++degree_with_extension[dual_faces_of_[d][1]];
      }
    for(std::size_t f = 0; f < nf_; ++f) st_.number_of_extended_dual_leaves += (degree_with_extension[f] == 1);
    for(std::size_t d = 0; d < nd_; ++d)
      if(false_branch_[d]) r_.edge_role[ei(r_.dual_edges[d])] = Edge_role::dual_false_branch;
    for(std::size_t d = 0; d < nd_; ++d)
      if(extension_[d])
      {
        r_.edge_role[ei(r_.dual_edges[d])] = Edge_role::dual_leaf_extension;
        r_.leaf_extension_edges.push_back(r_.dual_edges[d]);
        ++st_.number_of_leaf_extension_edges;
      }
    for(std::size_t d = 0; d < nd_; ++d)
      if(kept_[d])
      {
        r_.edge_role[ei(r_.dual_edges[d])] = Edge_role::dual_kept;
        r_.kept_dual_edges.push_back(r_.dual_edges[d]);
      }
    st_.number_of_kept_dual_edges = nkept_;
  }

  void add_cut(edge_descriptor e)
  {
    r_.is_cut_edge[ei(e)] = 1;
    ++cut_degree_[vi(source(e, tm_))];
    ++cut_degree_[vi(target(e, tm_))];
  }
  void remove_cut(edge_descriptor e)
  {
    r_.is_cut_edge[ei(e)] = 0;
    --cut_degree_[vi(source(e, tm_))];
    --cut_degree_[vi(target(e, tm_))];
  }

  // The rungs (mesh edges crossed by kept dual edges) reduced to a
  // maximum-significance spanning tree (Kruskal).
  void span_rungs()
  {
    for(std::size_t d = 0; d < nd_; ++d)
      if((kept_[d] || extension_[d]) && !is_border(r_.dual_edges[d], tm_)) rungs_.push_back(d);
    std::stable_sort(rungs_.begin(), rungs_.end(),
                     [&](std::size_t a, std::size_t b) { return significance(a) > significance(b); });
    r_.is_cut_edge.assign(ne_, 0);
    cut_degree_.assign(nv_, 0);
    // each border loop is one piece of K ∪ ∂M already: a rung path that joins
    // two loops is no cycle, one that returns to its loop is
    Union_find uf(nv_);
    for(halfedge_descriptor h : halfedges(tm_))
      if(is_border(h, tm_)) uf.unite(vi(source(h, tm_)), vi(target(h, tm_)));
    for(std::size_t d : rungs_)
    {
      const edge_descriptor e = r_.dual_edges[d];
      if(uf.unite(vi(source(e, tm_)), vi(target(e, tm_)))) add_cut(e);
    }
  }

  // Genus g: add back the 2g rungs that close the non-contractible cycles. A
  // rung may be added iff the faces stay connected across non-cut edges (its
  // dual edge is no bridge), i.e. it closes no contractible cycle. The
  // candidates that qualify form a cographic matroid, so greedy is optimal, and
  // a connected cut surface with Euler characteristic 1 is a disk.
  void close_handle_cycles()
  {
    if(st_.genus == 0) return;
    const std::size_t wanted = static_cast<std::size_t>(2 * st_.genus);
    face_mark_.assign(nf_, 0);
    for(std::size_t d : rungs_)
    {
      if(st_.number_of_closing_rungs == wanted) break;
      const edge_descriptor e = r_.dual_edges[d];
      if(r_.is_cut_edge[ei(e)] || !faces_stay_connected_without(d)) continue;
      add_cut(e);
      ++st_.number_of_closing_rungs;
    }
    if(st_.number_of_closing_rungs != wanted)
      throw Algorithm_error("found " + std::to_string(st_.number_of_closing_rungs) + " of the " +
                            std::to_string(wanted) + " rungs closing the non-contractible cycles");
  }

  // Whether the two faces of dual edge d stay connected when K and d's edge are
  // cut: an alternating BFS from both faces stops after O(smaller side) steps
  // when the edge is a bridge.
  bool faces_stay_connected_without(std::size_t d)
  {
    const edge_descriptor e = r_.dual_edges[d];
    const std::size_t ma = ++stamp_, mb = ++stamp_;
    std::deque<std::size_t> qa{dual_faces_of_[d][0]}, qb{dual_faces_of_[d][1]};
    face_mark_[qa.front()] = ma;
    face_mark_[qb.front()] = mb;
    bool joined = false;
    auto step = [&](std::deque<std::size_t>& q, std::size_t mine, std::size_t other) {
      const std::size_t f = q.front();
      q.pop_front();
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(face_of_[f], tm_), tm_))
      {
        const edge_descriptor eh = edge(h, tm_);
        if(r_.is_cut_edge[ei(eh)] || eh == e || is_border(opposite(h, tm_), tm_)) continue;
        const std::size_t g = fi(face(opposite(h, tm_), tm_));
        if(face_mark_[g] == other) { joined = true; return; }
        if(face_mark_[g] != mine) { face_mark_[g] = mine; q.push_back(g); }
      }
    };
    while(!joined && !qa.empty() && !qb.empty())
    {
      step(qa, ma, mb);
      if(!joined && !qb.empty()) step(qb, mb, ma);
    }
    return joined;
  }

  // No teeth: a spanning tree of the rungs keeps every zigzag tooth of the strip
  // as a one-edge leaf. A leaf of K is a tooth unless its dual edge is the
  // outermost cut rung of its branch of T* (nothing cut further out). Removing a
  // leaf of K keeps K connected and the cut surface a disk.
  void remove_teeth()
  {
    const std::vector<char> cut_beyond = cut_further_out();
    std::vector<std::size_t> dual_index_of_edge(ne_, none);
    for(std::size_t d = 0; d < nd_; ++d) dual_index_of_edge[ei(r_.dual_edges[d])] = d;
    std::size_t cut_size = 0;
    for(std::size_t i = 0; i < ne_; ++i) cut_size += r_.is_cut_edge[i];
    std::vector<vertex_descriptor> leaves;
    for(vertex_descriptor v : vertices(tm_))
      if(is_leaf_of_cut(v)) leaves.push_back(v);
    while(!leaves.empty() && (cut_size > 1 || has_boundary()))
    {
      const vertex_descriptor w = leaves.back();
      leaves.pop_back();
      if(!is_leaf_of_cut(w)) continue;
      const halfedge_descriptor hw = cut_halfedge_into(w, GT::null_halfedge());
      if(!cut_beyond[dual_index_of_edge[ei(edge(hw, tm_))]]) continue; // the end of a branch: keep it
      remove_cut(edge(hw, tm_));
      --cut_size;
      const vertex_descriptor u = source(hw, tm_);
      if(is_leaf_of_cut(u)) leaves.push_back(u);
      ++st_.number_of_teeth_pruned;
    }
  }

  // per dual edge: whether K cuts further out on its branch of T* (always on the 2-core)
  std::vector<char> cut_further_out() const
  {
    std::vector<char> cut_beyond(nd_, 0), face_has_cut_beyond(nf_ + 1, 0);
    for(std::size_t d : peel_order_)
    {
      const std::size_t c = child_face_[d];
      cut_beyond[d] = face_has_cut_beyond[c];
      if(cut_beyond[d] || r_.is_cut_edge[ei(r_.dual_edges[d])]) face_has_cut_beyond[across(d, c)] = 1;
    }
    for(std::size_t d = 0; d < nd_; ++d)
      if(!peeled_[d]) cut_beyond[d] = 1; // a cycle of the 2-core never ends
    return cut_beyond;
  }

  // a free end of K: one cut edge, and not on the border (which K ∪ ∂M goes on along)
  bool is_leaf_of_cut(vertex_descriptor v) const { return cut_degree_[vi(v)] == 1 && !on_boundary(v); }

  // a cut edge at v other than `not_this`, as a halfedge pointing into v
  halfedge_descriptor cut_halfedge_into(vertex_descriptor v, halfedge_descriptor not_this) const
  {
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm_))
      if(r_.is_cut_edge[ei(edge(h, tm_))] &&
         (not_this == GT::null_halfedge() || edge(h, tm_) != edge(not_this, tm_)))
        return h;
    return GT::null_halfedge();
  }

  // Leaves at corners. The cut locus ends at vertices of positive curvature
  // (generically every such vertex is a leaf: one shortest path reaches it). A
  // leaf of K one or two edges past a sharp corner, or a corner left off K (see
  // `join_corners`), puts the slit's end beside the ridge's end; the fronts on
  // both sides of the corner then come out wrong. So the leaf is moved back
  // onto the corner. Measured (bench_ridge_accuracy): trimming at corners of 60
  // degrees cut real branches through the 77-90 degree ear tips of bunny_1k
  // (recall p95 at tolerance 0.001 0.27 -> 4.5 mean edges), hence the sharper
  // threshold here.
  static double corner_curvature() { return radians(tuning::rough_cut::corner_degrees); }
  // (a doubly covered square's corners have 180 degrees)
  static double sharp_corner_curvature() { return radians(tuning::rough_cut::sharp_corner_degrees); }

  void move_leaves_onto_corners()
  {
    std::vector<vertex_descriptor> leaves;
    for(vertex_descriptor v : vertices(tm_))
      if(is_leaf_of_cut(v) && curvature(v) < corner_curvature()) leaves.push_back(v);
    for(vertex_descriptor w : leaves)
    {
      // past a sharp corner: walk in through at most two vertices of degree 2
      std::vector<halfedge_descriptor> path;
      halfedge_descriptor h = cut_halfedge_into(w, GT::null_halfedge());
      for(int step = 0; step < 2 && h != GT::null_halfedge(); ++step)
      {
        path.push_back(h);
        const vertex_descriptor u = source(h, tm_);
        // (u keeps a cut edge, so K never becomes empty)
        if(curvature(u) >= sharp_corner_curvature() && !is_source_vertex(u) && cut_degree_[vi(u)] >= 2)
        {
          for(halfedge_descriptor p : path) remove_cut(edge(p, tm_));
          ++st_.number_of_corner_moves;
          break;
        }
        if(cut_degree_[vi(u)] != 2) break;
        h = cut_halfedge_into(u, h); // the other cut edge at u, again pointing outwards
      }
    }
  }

  // Prongs at a corner where K forks. The dual edges kept around a corner for
  // its curvature cross several of its spokes, and the rungs make K fork at
  // the corner into one-edge prongs that end at flat vertices beside it (the
  // open box's bottom corners: two prongs along the bottom edges). A front that
  // crosses such a prong's edge is split between two sheets, and the faces at
  // the corner get no copy that carries it at all three corners: the ridge
  // forks beside the corner. The cut locus ends at vertices of positive
  // curvature, never at a flat vertex one edge from a corner, so at a corner
  // (60 degrees or more) where K has three or more edges, every such prong is
  // removed while one other edge stays. A corner where K does not fork (a
  // branch through it and one edge on, as at bunny_1k's ear tips) is left to
  // `move_leaves_onto_corners()`.
  void remove_prongs_at_corner_forks()
  {
    for(vertex_descriptor u : vertices(tm_))
    {
      if(cut_degree_[vi(u)] < 3 || curvature(u) < corner_curvature() || is_source_vertex(u)) continue;
      std::vector<edge_descriptor> prongs;
      for(halfedge_descriptor h : CGAL::halfedges_around_target(u, tm_))
      {
        const vertex_descriptor w = source(h, tm_);
        if(r_.is_cut_edge[ei(edge(h, tm_))] && is_leaf_of_cut(w) && curvature(w) < corner_curvature() &&
           !is_source_vertex(w))
          prongs.push_back(edge(h, tm_));
      }
      if(prongs.empty()) continue;
      if(prongs.size() == cut_degree_[vi(u)]) prongs.pop_back(); // (K keeps an edge at u)
      for(edge_descriptor e : prongs) remove_cut(e);
      ++st_.number_of_corner_moves;
    }
  }

  bool is_source_vertex(vertex_descriptor v) const
  {
    return is_seed_[vi(v)] || (src_.kind == Source::ON_VERTEX && v == src_.vertex);
  }

  // A corner (60 degrees or more of curvature) off K is joined to K by the
  // shortest path of at most three edges through vertices off K (a pendant
  // path: K stays a tree plus its 2g rungs); corners of most curvature first.
  void join_corners()
  {
    std::vector<vertex_descriptor> corners;
    for(vertex_descriptor v : vertices(tm_))
      if(cut_degree_[vi(v)] == 0 && !is_source_vertex(v) && curvature(v) >= corner_curvature())
        corners.push_back(v);
    std::stable_sort(corners.begin(), corners.end(), [&](vertex_descriptor a, vertex_descriptor b) {
      return curvature(a) > curvature(b);
    });
    Short_path_search search(*this);
    for(vertex_descriptor c : corners)
    {
      if(cut_degree_[vi(c)] != 0) continue;
      const std::vector<halfedge_descriptor> path = search(c);
      if(path.empty()) continue;
      for(halfedge_descriptor h : path)
      {
        add_cut(edge(h, tm_));
        r_.corner_path_edges.push_back(edge(h, tm_));
      }
      ++st_.number_of_corner_moves;
    }
  }

  // Dijkstra from a corner over at most `maximum_hops` edges, avoiding the
  // source, to the nearest vertex of K; the path as halfedges from K back
  // towards the corner (empty if K is farther). Its tables are reset per search
  // only where a search touched them.
  struct Short_path_search
  {
    static constexpr int maximum_hops = 3;
    const Rough_cut_locus_builder& b;
    std::vector<vertex_descriptor> vertex_of;
    std::vector<double> reach;
    std::vector<int> hops;
    std::vector<halfedge_descriptor> reached_by;
    std::vector<std::size_t> touched;

    explicit Short_path_search(const Rough_cut_locus_builder& builder)
      : b(builder), vertex_of(builder.nv_), reach(builder.nv_, std::numeric_limits<double>::infinity()),
        hops(builder.nv_, 0), reached_by(builder.nv_, GT::null_halfedge())
    {
      for(vertex_descriptor v : vertices(b.tm_)) vertex_of[b.vi(v)] = v;
    }

    std::vector<halfedge_descriptor> operator()(vertex_descriptor c)
    {
      for(std::size_t t : touched) { reach[t] = std::numeric_limits<double>::infinity(); reached_by[t] = GT::null_halfedge(); }
      touched.clear();
      typedef std::pair<double, std::size_t> Entry;
      std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
      reach[b.vi(c)] = 0; hops[b.vi(c)] = 0; touched.push_back(b.vi(c));
      queue.emplace(0.0, b.vi(c));
      vertex_descriptor found = GT::null_vertex();
      while(!queue.empty() && found == GT::null_vertex())
      {
        const double d = queue.top().first;
        const vertex_descriptor u = vertex_of[queue.top().second];
        queue.pop();
        if(d > reach[b.vi(u)]) continue;
        if(b.cut_degree_[b.vi(u)] > 0 || b.on_boundary(u)) { found = u; break; }
        if(hops[b.vi(u)] == maximum_hops) continue;
        for(halfedge_descriptor h : CGAL::halfedges_around_target(u, b.tm_))
        {
          const vertex_descriptor w = source(h, b.tm_);
          if(b.is_seed_[b.vi(w)]) continue;
          const double dw = d + distance_between(b.maps_.vpm, u, w);
          if(dw >= reach[b.vi(w)]) continue;
          if(reach[b.vi(w)] == std::numeric_limits<double>::infinity()) touched.push_back(b.vi(w));
          reach[b.vi(w)] = dw; hops[b.vi(w)] = hops[b.vi(u)] + 1; reached_by[b.vi(w)] = h;
          queue.emplace(dw, b.vi(w));
        }
      }
      std::vector<halfedge_descriptor> path;
      if(found == GT::null_vertex()) return path;
      for(vertex_descriptor u = found; u != c; u = target(path.back(), b.tm_))
        path.push_back(reached_by[b.vi(u)]); // from u back towards c
      return path;
    }
  };

  void collect_cut_edges()
  {
    for(std::size_t i = 0; i < ne_; ++i)
      if(r_.is_cut_edge[i]) r_.cut_edges.push_back(edge_of_[i]);
    auto by_index = [&](edge_descriptor a, edge_descriptor b) { return ei(a) < ei(b); };
    std::sort(r_.dual_edges.begin(), r_.dual_edges.end(), by_index);
    std::sort(r_.kept_dual_edges.begin(), r_.kept_dual_edges.end(), by_index);
    std::sort(r_.leaf_extension_edges.begin(), r_.leaf_extension_edges.end(), by_index);
    std::sort(r_.corner_path_edges.begin(), r_.corner_path_edges.end(), by_index);
    st_.number_of_cut_edges = r_.cut_edges.size();
  }

  // Step 4, always: K ∪ ∂M (K on a closed mesh) is connected with cycle rank
  // 2g + b, the cut surface is connected with Euler characteristic 1 (so a
  // disk), the source is off K.
  void check_disk()
  {
    std::size_t split_vertices = 0; // vertex copies in the cut surface beyond one per vertex
    std::size_t graph_vertices = 0, graph_edges = st_.number_of_cut_edges;
    for(vertex_descriptor v : vertices(tm_))
    {
      const std::size_t k = cut_degree_[vi(v)];
      if(k > 0) ++st_.number_of_cut_vertices;
      if(is_leaf_of_cut(v)) ++st_.number_of_cut_leaves;
      // k cut edges split an inner vertex into k sectors, a border vertex into k + 1
      split_vertices += on_boundary(v) ? k : (k > 0 ? k - 1 : 0);
      graph_vertices += (k > 0 || on_boundary(v));
    }
    Union_find kuf(nv_);
    for(edge_descriptor e : r_.cut_edges) kuf.unite(vi(source(e, tm_)), vi(target(e, tm_)));
    for(halfedge_descriptor h : halfedges(tm_))
      if(is_border(h, tm_)) { kuf.unite(vi(source(h, tm_)), vi(target(h, tm_))); ++graph_edges; }
    const std::size_t k_components = kuf.number_of_sets() - (nv_ - graph_vertices);
    st_.cut_cycle_rank = graph_edges + k_components - graph_vertices;
    Union_find fuf(nf_);
    for(edge_descriptor e : edges(tm_))
      if(!r_.is_cut_edge[ei(e)] && !is_border(e, tm_))
      {
        const halfedge_descriptor h = halfedge(e, tm_);
        fuf.unite(fi(face(h, tm_)), fi(face(opposite(h, tm_), tm_)));
      }
    const long cut_chi = static_cast<long>(nv_ + split_vertices) -
                         static_cast<long>(ne_ + st_.number_of_cut_edges) + static_cast<long>(nf_);
    const std::size_t rank = static_cast<std::size_t>(2 * st_.genus) + st_.number_of_boundary_loops;
    const std::string graph = has_boundary() ? "K with the border" : "the cut graph";
    std::string why;
    if(graph_edges == 0) why = "the cut graph is empty";
    else if(k_components != 1) why = graph + " has " + std::to_string(k_components) + " components";
    else if(st_.cut_cycle_rank != rank)
      why = graph + " has cycle rank " + std::to_string(st_.cut_cycle_rank) + ", not 2g + b = " + std::to_string(rank);
    else if(fuf.number_of_sets() != 1)
      why = "cutting along K splits the surface into " + std::to_string(fuf.number_of_sets()) + " parts";
    else if(cut_chi != 1)
      why = "the cut surface has Euler characteristic " + std::to_string(cut_chi) + ", not 1";
    else if(source_on_cut())
      why = "the source lies on the cut";
    if(!why.empty()) throw Algorithm_error("rough cut locus: cutting along K does not give a disk: " + why);
  }

  bool source_on_cut() const
  {
    if(src_.kind == Source::ON_VERTEX) return cut_degree_[vi(src_.vertex)] > 0;
    if(src_.kind == Source::ON_EDGE) return r_.is_cut_edge[ei(edge(src_.edge_halfedge, tm_))] != 0;
    return false;
  }

  // the input
  const TriangleMesh& tm_;
  const Source src_;
  const Maps maps_;
  const Options options_;
  const std::size_t nv_, ne_, nf_;
  // the result, filled step by step
  Rough_cut_locus<TriangleMesh> r_;
  Rough_cut_locus_statistics& st_;
  // elements by index; per vertex: a seed of the source, on the border
  std::vector<edge_descriptor> edge_of_;
  std::vector<face_descriptor> face_of_;
  std::vector<char> is_seed_, boundary_vertex_;
  // step 1: edge lengths; step 2: areas, the dual graph (by position d in
  // r_.dual_edges), curvature, and the peeling: per dual edge its child face
  // (the side peeled first) and the curvature beyond it
  std::vector<double> length_, area_;
  double node_total_ = 0;
  std::size_t nd_ = 0;
  std::vector<std::array<std::size_t, 2> > dual_faces_of_;
  std::vector<std::array<std::size_t, 3> > dual_of_face_;
  std::vector<unsigned char> dual_degree_;
  Corner_angles own_angles_;
  const Corner_angles* angles_ = nullptr;
  std::vector<double> curvature_share_, positive_share_, subtree_curvature_, subtree_positive_;
  std::vector<char> peeled_;
  std::vector<std::size_t> child_face_, peel_order_;
  // step 3: the kept dual structure and its extensions; K and its vertex degrees
  double threshold_ = 0;
  std::vector<char> kept_, false_branch_, extension_;
  std::size_t nkept_ = 0;
  std::vector<unsigned char> kept_degree_;
  std::vector<std::size_t> rungs_, cut_degree_;
  std::vector<std::size_t> face_mark_;
  std::size_t stamp_ = 0;
};

// What every entry point does first: the parameters of stage 1 checked (a bad
// one is reported before any work), the mesh validated, the source (a vertex or
// a `Face_location`) made.
template <class TriangleMesh, class SourceLocation, class NamedParameters>
Geodesic_source<TriangleMesh> checked_source(const TriangleMesh& tm, const SourceLocation& source,
                                             const NamedParameters& np)
{
  get_tolerance(np);
  validate_triangle_mesh(tm, np);
  return make_source(tm, source, np);
}

template <class TriangleMesh, class NamedParameters>
Rough_cut_locus<TriangleMesh>
rough_cut_locus_impl(const TriangleMesh& tm, Geodesic_source<TriangleMesh> src,
                     const NamedParameters& np, const std::vector<double>* field = nullptr,
                     const Corner_angles* angles = nullptr)
{
  typedef Rough_cut_locus_builder<TriangleMesh, Mesh_maps_of<TriangleMesh, NamedParameters> > Builder;
  typename Builder::Options options;
  options.tolerance = get_tolerance(np);
  options.leaf_curvature = radians(get_leaf_curvature(np));
  options.branch_curvature = radians(get_branch_curvature(np));
  options.corner_angles = angles;
  return Builder(tm, src, mesh_maps(tm, np), options).run(field);
}

// Stage 1's lengths and areas, computed on the unit mesh, in the input's units.
template <class TriangleMesh>
void map_from_unit(Rough_cut_locus<TriangleMesh>& r, const Normalization& n)
{
  if(n.identity()) return;
  r.total_area = n.area_from_unit(r.total_area);
  for(double& s : r.significance) s = n.area_from_unit(s);
  for(double& d : r.distance) d = n.length_from_unit(d);
  for(auto& seed : r.source.seeds) seed.second = n.length_from_unit(seed.second);
}

// The public entry: stage 1 on the unit mesh (internal/normalization.h).
template <class TriangleMesh, class SourceLocation, class NamedParameters>
Rough_cut_locus<TriangleMesh> rough_cut_locus_of(const TriangleMesh& tm, const SourceLocation& source,
                                                 const NamedParameters& np)
{
  Normalization n;
  const auto unit_np = unit_parameters(tm, np, n);
  Rough_cut_locus<TriangleMesh> r = rough_cut_locus_impl(tm, checked_source(tm, source, unit_np), unit_np);
  map_from_unit(r, n);
  return r;
}

} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
/// Computes the rough cut locus of `source` on the triangle mesh `tm` (closed or with a border):
/// the shortest-path tree, the significance of the edges of its dual, the
/// pruning by `tolerance`, and the cut graph K (\ref GeodesicRidgeSecStage1).
///
/// \tparam TriangleMesh a model of `FaceListGraph` (`CGAL::Surface_mesh`, for example)
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param source a vertex of `tm`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \pre `tm` is a connected, manifold (closed or with a border), consistently oriented triangle
///      mesh with finite coordinates, no isolated vertex, no duplicate face and
///      no zero-area face (checked first by `validate_triangle_mesh()`:
///      `Invalid_mesh_error` otherwise).
/// \pre `source` is a vertex of `tm` (`Invalid_source_error` otherwise).
/// \pre Every named parameter is in its range (`Invalid_parameter_error`
///      otherwise, thrown before any work).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{tolerance}
///     \cgalParamDescription{the dual edges whose significance is at least this fraction of the total area are kept}
///     \cgalParamType{`double`, in [0, 0.5)}
///     \cgalParamDefault{`default_tolerance` (0.025)}
///   \cgalParamNEnd
///   \cgalParamNBegin{branch_curvature}
///     \cgalParamDescription{degrees: kept branches of the dual tree that enclose less Gaussian curvature are false and pruned back; 0 is the paper's pruning}
///     \cgalParamType{`double`, in [0, 720]}
///     \cgalParamDefault{`default_branch_curvature` (15)}
///   \cgalParamNEnd
///   \cgalParamNBegin{leaf_curvature}
///     \cgalParamDescription{degrees: pruned branches that hold this much Gaussian curvature are kept, so that the cut graph reaches the tips of the ridge, and its leaves are moved onto corners; 0 turns both off}
///     \cgalParamType{`double`, in [0, 720]}
///     \cgalParamDefault{`default_leaf_curvature` (45)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a 3D point as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and `num_vertices(tm) - 1`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index between `0` and `num_edges(tm) - 1`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index between `0` and `num_faces(tm) - 1`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \post cutting `tm` along `cut_edges` gives one topological disk with the
///       source strictly inside; `Algorithm_error` is thrown if it ever does not.
template <class TriangleMesh,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Rough_cut_locus<TriangleMesh>
compute_rough_cut_locus(const TriangleMesh& tm,
                        typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::rough_cut_locus_of(tm, source, np);
}

/// \ingroup PkgGeodesicRidgeRef
/// Same, from a surface point given as a `Face_location` (face + barycentric
/// coordinates in CGAL's order). A location on an edge or a vertex is handled
/// as such.
///
/// \pre the face is a face of `tm` and the coordinates are finite,
///      non-negative and sum to 1 within 1e-9 (`Invalid_source_error` otherwise).
///
/// The other preconditions and the named parameters are those of the first overload.
template <class TriangleMesh, class FT,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Rough_cut_locus<TriangleMesh>
compute_rough_cut_locus(const TriangleMesh& tm,
                        const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                        std::array<FT, 3> >& source,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::rough_cut_locus_of(tm, source, np);
}

/// \ingroup PkgGeodesicRidgeRef
/// Writes the cut graph K as polylines (`std::vector<Point_3>`) to `out`, one
/// per chain between vertices of K whose degree is not 2 (closed chains repeat
/// their first point).
///
/// \tparam OutputIterator an output iterator accepting `std::vector<Point_3>`
/// \param tm the mesh
/// \param rcl the rough cut locus of a source on `tm`
/// \param out where the polylines go
/// \param np an optional sequence of named parameters among the ones listed below
/// \returns `out` past the last polyline
/// \pre `rcl` was computed on `tm` with the same vertex index map.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and a 3D point as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and `num_vertices(tm) - 1`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class TriangleMesh, class OutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator cut_graph_polylines(const TriangleMesh& tm, const Rough_cut_locus<TriangleMesh>& rcl,
                                   OutputIterator out,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const auto maps = internal::mesh_maps(tm, np);
  const auto& vpm = maps.vpm;
  const auto& vim = maps.vim;
  std::vector<vertex_descriptor> vertex_of(num_vertices(tm));
  for(vertex_descriptor v : vertices(tm)) vertex_of[get(vim, v)] = v;
  std::vector<std::pair<std::size_t, std::size_t> > graph;
  for(const auto& e : rcl.cut_edges)
    graph.emplace_back(get(vim, source(e, tm)), get(vim, target(e, tm)));
  typedef typename decltype(maps)::Point Point;
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
