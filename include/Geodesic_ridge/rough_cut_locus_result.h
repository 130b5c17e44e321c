// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1's result: the rough cut locus (`Rough_cut_locus`), its statistics
// and the role of every edge. rough_cut_locus.h computes it; the passes of
// internal/rough_cut/ fill it.
#ifndef GEODESIC_RIDGE_ROUGH_CUT_LOCUS_RESULT_H
#define GEODESIC_RIDGE_ROUGH_CUT_LOCUS_RESULT_H

#include <Geodesic_ridge/parameters.h>
#include <Geodesic_ridge/source.h>
#include <Geodesic_ridge/timings.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
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

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_ROUGH_CUT_LOCUS_RESULT_H
