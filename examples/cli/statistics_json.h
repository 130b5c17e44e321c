// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The statistics of a ridge as JSON: what geodesic_ridge writes with --stats
// and what the Python module returns as `Ridge.statistics`. One key per
// member, named as the member (the reference manual documents each).
#ifndef GEODESIC_RIDGE_CLI_STATISTICS_JSON_H
#define GEODESIC_RIDGE_CLI_STATISTICS_JSON_H

#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/refined_mesh.h>
#include <Geodesic_ridge/repair.h>

#include <nlohmann/json.hpp>

#include <string>

// through nlohmann-json's field macros
#define GEODESIC_RIDGE_JSON_FIELDS(Type, ...)                                                           \
  inline void to_json(nlohmann::ordered_json& nlohmann_json_j, const Type& nlohmann_json_t)             \
  {                                                                                                     \
    NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(NLOHMANN_JSON_TO, __VA_ARGS__))                            \
  }

// (found by argument-dependent lookup: in the statistics' namespace)
namespace Geodesic_ridge {
GEODESIC_RIDGE_JSON_FIELDS(Rough_cut_locus_statistics, genus, number_of_boundary_loops, number_of_vertices, number_of_edges, number_of_faces,
                           number_of_dual_edges, number_of_core_dual_edges, number_of_kept_dual_edges,
                           number_of_kept_dual_leaves, number_of_extended_dual_leaves, number_of_leaf_extension_edges,
                           number_of_cut_edges, number_of_cut_vertices, number_of_cut_leaves, cut_cycle_rank,
                           number_of_closing_rungs, number_of_teeth_pruned, number_of_curvature_pruned_dual_edges,
                           number_of_corner_moves, fallback_single_rung)
GEODESIC_RIDGE_JSON_FIELDS(Extended_surface_statistics, rings, number_of_faces, number_of_vertices, faces_per_ring,
                           number_of_closures, winding_bound_hits, refused_faces, refused_gluings, open_fans,
                           number_of_leaf_vertices)
GEODESIC_RIDGE_JSON_FIELDS(Ridge_curve_statistics, ridge_segments, junctions, free_ends, components, cycles,
                           total_length, faces_with_several_copies, surviving_copies, split_copies, recombined_copies,
                           envelope_segments,
                           edge_segments, thin_face_pieces, thin_face_pieces_undone, regions_before_merge, merged_segments, rejoined_segments,
                           border_joining_segments,
                           dropped_components, piece_joining_segments,
                           pruned_spur_segments, spurs_at_impossible_ends, spurs_away_from_corners,
                           spurs_too_weak_for_corners, pruned_flat_end_segments, coincident_points)
GEODESIC_RIDGE_JSON_FIELDS(Cone_ridge_statistics, tolerance, points_moved, junctions_moved, points_kept, points_added,
                           kept_linear_ridge,
                           largest_move)
GEODESIC_RIDGE_JSON_FIELDS(Geodesic_ridge_statistics, solver, tolerance, tree_from_solver, solves, predicted_passes,
                           outer_copies_winning, ring_cap_hit, margin_rings, rough_cut_locus, extended_surface, ridge,
                           cone_ridge_traced, cone_ridge)
GEODESIC_RIDGE_JSON_FIELDS(Refined_mesh_statistics, vertices, faces, split_faces, centre_vertices, ridge_edges,
                           unmatched_ridge_segments, largest_disagreement)
GEODESIC_RIDGE_JSON_FIELDS(Repair_statistics, triangulated_polygons, non_planar_polygons, triangles_from_polygons,
                           repaired, merged_vertices, removed_invalid_faces, removed_duplicate_faces,
                           split_non_manifold_edges, split_non_manifold_vertices, added_vertex_copies,
                           removed_degenerate_faces, reoriented_faces, removed_isolated_vertices)
} // namespace Geodesic_ridge
namespace geodesic_ridge_cli {

/// every step the pipeline timed, stage 1's split into its own steps, and the
/// seconds it took to read and validate the mesh before
template <class RidgeCurve>
nlohmann::ordered_json timings_json(const RidgeCurve& rc, double read_seconds)
{
  nlohmann::ordered_json timings = {{"read_and_validate", read_seconds}};
  for(const auto& [step, seconds] : rc.timings.steps()) timings[step] = seconds;
  for(const auto& [step, seconds] : rc.rough_cut_locus.timings.steps()) timings["rough_cut_locus." + step] = seconds;
  timings["total"] = read_seconds + rc.timings.total();
  return timings;
}

/// the mesh as the pipeline saw it, the ridge's size and every stage's counts
template <class RidgeCurve>
nlohmann::ordered_json ridge_json(const RidgeCurve& rc)
{
  const auto& r = rc.rough_cut_locus;
  const auto& s = r.statistics;
  return {{"mesh", {{"vertices", s.number_of_vertices}, {"edges", s.number_of_edges},
                    {"faces", s.number_of_faces}, {"genus", s.genus}, {"total_area", r.total_area}}},
          {"ridge", {{"polylines", rc.polylines.size()}, {"cone_polylines", rc.cone_polylines.size()}}},
          {"statistics", rc.statistics}};
}

} // namespace geodesic_ridge_cli

#endif // GEODESIC_RIDGE_CLI_STATISTICS_JSON_H
