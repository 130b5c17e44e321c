// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pipeline's tuning constants and numerical tolerances, one block per
// stage: what each decides, in which unit, and where it is used. The reason
// and the measurement that chose a value are at the place of use (and on the
// manual's companion page, GeodesicRidgeMeasurements); change one only with
// bench_ridge_accuracy and bench_geodesic_ridge before and after.
// (The named parameters, which users set, are in parameters.h.)
#ifndef GEODESIC_RIDGE_INTERNAL_TUNING_H
#define GEODESIC_RIDGE_INTERNAL_TUNING_H

namespace Geodesic_ridge {
namespace internal {
namespace tuning {

// Stage 1: the rough cut locus (rough_cut_locus.h, internal/rough_cut/). Angles in degrees.
namespace rough_cut {
/// A pruned branch is kept towards curvature (`extend_leaves_by_curvature`) through the
/// best child of a node on the way when its subtree holds this share of
/// `leaf_curvature`.
constexpr double extension_curvature_share = 0.25;
/// A leaf of K near a corner of at least this curvature is moved onto it
/// (`move_leaves_onto_corners`; 60 cut the ear tips of bunny_1k).
constexpr double corner_degrees = 60;
/// ... and near a sharp corner (a doubly covered square's corners: 180).
constexpr double sharp_corner_degrees = 100;
} // namespace rough_cut

// Stage 2: the growth of E, the solves, the lower envelope
// (internal/extension_growth.h, compute_geodesic_ridge.h, lower_envelope.h).
// Lengths in mean edges of M.
namespace extension {
/// A copy's border wins by more than this under fast marching (its error
/// is about a hundredth of an edge) before E grows there.
constexpr double fast_marching_slack = 0.02;
/// ... and under an exact solver (round-off).
constexpr double exact_slack = 1e-9;
/// A face closed as dominated is opened again when a solve brings it this
/// much below its cover.
constexpr double reopen_margin = 1e-9;
/// Cones are read only on copies whose linear field bends by this share of
/// the kink angle against a glued copy's (`grow_and_solve`).
constexpr double kink_filter_share = 0.25;
} // namespace extension

namespace envelope {
/// With an inexact number type, a new corner's barycentric coordinates may
/// leave the segment they lie on by this much before the exact type decides.
constexpr double barycentric_slack = 1e-9;
} // namespace envelope

// Stage 3: the ridge curve (ridge_curve.h, compute_geodesic_ridge.h).
// Lengths in mean edges of M, angles in degrees.
namespace ridge {
/// Two cones with apexes this close are one (round-off of the unfolding).
constexpr double same_apex = 1e-6;
/// Two fronts whose linear fields agree within this along an edge are one.
constexpr double same_front = 1e-6;
/// A jump weaker than this (a difference of gradients, unit-less) along an
/// edge is no ridge.
constexpr double weak_jump = 1e-6;
/// The arrival directions of a node's samples agree within this angle, or
/// the node's direction is not read from them (`arrival_direction`).
constexpr double consistent_arrival_degrees = 15;
/// Faces whose height is below this share of their longest edge are thin
/// (`thin_faces`: caps and needles).
constexpr double thin_face_ratio = 0.05;
/// A free end with less curvature than this share of `minimum_angle`
/// around it (within `curvature_radius`, summed with signs) is no ridge end
/// (`prune_spurs`).
constexpr double spur_curvature_share = 0.5;
/// A weak free end with at least this much curvature around it is kept
/// (`prune_spurs`: the cut locus ends at such vertices) ...
constexpr double spur_corner_degrees = 60;
/// ... unless its jump is below `minimum_angle` divided by this.
constexpr double spur_corner_end_divisor = 3;
/// The radius (mean edges) of a node's neighbourhood whose vertices'
/// curvature is summed (`Curvature_near`).
constexpr double curvature_radius = 2.5;
/// A vertex whose curvature is below this (radians) is flat.
constexpr double flat_vertex_curvature = 1e-9;
/// Copies that recombine nearer sheets' fronts: a corner's owner within this
/// (mean edges) of the copy's distance ...
constexpr double recombined_witness_tolerance = 0.1;
/// ... with owners this many degrees apart (`Recombined_copy_splitter`).
constexpr double recombined_split_degrees = 30;
} // namespace ridge

} // namespace tuning
} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_TUNING_H
