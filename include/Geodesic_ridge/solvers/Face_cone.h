// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact distance near a point of a face as a cone (`Face_cone`), and the
// points of a face whose shortest paths give the cones (`Cone_samples`). A
// header of their own: stage 3 and the cone field read them without the
// exact solver's (CGAL's Surface_mesh_shortest_path) header.
#ifndef GEODESIC_RIDGE_SOLVERS_FACE_CONE_H
#define GEODESIC_RIDGE_SOLVERS_FACE_CONE_H

#include <array>
#include <cstdint>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeSolvers
/// The exact distance near a point of a face, as a cone: the distance in the
/// face's plane to `apex` (the source, or the saddle vertex where the shortest
/// path first bends, unfolded into the face) plus `offset` (the distance at
/// that apex). Exact wherever the shortest paths run through the same apex
/// (one window of the exact solver).
struct Face_cone
{
  std::array<double, 3> apex = {{0, 0, 0}}; ///< barycentric in the face (CGAL's corner order; may lie outside it)
  /// the distance at the apex
  double offset = 0;
  /// the part of edge `entry` a window passes (fractions from its first corner)
  std::array<double, 2> through = {{0, 1}};
  /// Of a window: the index of its copy among the copies of the face (the
  /// cone field `Ridge_curve::cones` of a solver with windows, where a copy
  /// is the lower envelope of its windows); `no_copy` for the sampled cones
  /// of `Exact_solver`, S per copy.
  std::uint32_t copy = no_copy;
  /// A window (`Window_propagation_solver`): the straight way from the apex
  /// enters the face through edge `entry` (from corner `entry` to corner
  /// `entry + 1`, mod 3) between the fractions `through[0]` and `through[1]`
  /// of it (from corner `entry`); a point that the straight way reaches
  /// elsewhere is reached around the nearer end of that part. -1: the
  /// straight way everywhere (a sampled cone, a corner, the source).
  std::int8_t entry = -1;
  /// the `copy` of a sampled cone
  static constexpr std::uint32_t no_copy = 0xffffffffu;
};

/// \ingroup PkgGeodesicRidgeSolvers
/// The sample sets of the cones: points of a face (barycentric, CGAL's corner
/// order) whose shortest paths give the face's `Face_cone`s, read by the
/// exact solvers (`Exact_solver`, whose members of the same names return
/// these) and by stage 3.
struct Cone_samples
{
  /// The points of a face (barycentric) whose shortest paths give its cones:
  /// the centroid, three points near the corners (barycentric 0.95) and three
  /// near the edge midpoints. The cone field evaluates, per copy, the cone of
  /// the sample nearest to the query: one sample (the centroid) leaves a
  /// larger mean error, and the minimum over the samples' cones is worse still
  /// (a cone evaluated beyond its window, in the shadow of a saddle vertex, is
  /// too short); measured in the user manual, \ref GeodesicRidgeSecAccuracyField.
  /// The samples near the corners give the kink split of the cone field each
  /// corner's own front where a kink passes near the corner (at 0.8, the
  /// ridge of bunny_7k from vertex 697 missed a branch: recall p95 at
  /// tolerance 0.002 3.00 mean edges; at 0.95 0.05, and every pair of
  /// `bench_ridge_accuracy` within 0.5).
  static const std::vector<std::array<double, 3> >& cone_samples()
  {
    static const std::vector<std::array<double, 3> > samples = {
        {{1. / 3, 1. / 3, 1. / 3}}, {{0.95, 0.025, 0.025}}, {{0.025, 0.95, 0.025}}, {{0.025, 0.025, 0.95}},
        {{0.45, 0.45, 0.1}}, {{0.1, 0.45, 0.45}}, {{0.45, 0.1, 0.45}}};
    return samples;
  }

  /// The samples of the cone ridge (`parameters::cone_ridge`) without the
  /// cone field: those of `cone_samples()`, but near the corners at
  /// barycentric 0.8, as `corner_samples()`. Nearer to the corners (0.95) the
  /// kink split also finds the branches that pass between a corner and its
  /// sample (bunny_7k from vertex 697: recall p95 at tolerance 0.002 0.05
  /// instead of 2.8 mean edges), but it finds false ones near convex corners
  /// too: on an open box from the centre of its bottom, 10 copies split and
  /// 4 more ridge polylines, prongs to the rim beside the bottom corners;
  /// fandisk, a CAD model, is placed worse (user manual,
  /// \ref GeodesicRidgeSecCone).
  static const std::vector<std::array<double, 3> >& cone_ridge_samples()
  {
    static const std::vector<std::array<double, 3> > samples = {
        {{1. / 3, 1. / 3, 1. / 3}}, {{0.8, 0.1, 0.1}}, {{0.1, 0.8, 0.1}}, {{0.1, 0.1, 0.8}},
        {{0.45, 0.45, 0.1}}, {{0.1, 0.45, 0.45}}, {{0.45, 0.1, 0.45}}};
    return samples;
  }

  /// Three samples near the corners (barycentric 0.8), one front per corner,
  /// enough to tell the fronts of a face's corners apart (the kink split of
  /// the linear field, `parameters::kink_angle`). Nearer to the corners
  /// (0.95), the linear field's split finds more branches but places them
  /// less well: precision p95 within 0.25 mean edge on 151 of the 168 pairs
  /// of `bench_ridge_accuracy` instead of 161.
  static const std::vector<std::array<double, 3> >& corner_samples()
  {
    static const std::vector<std::array<double, 3> > samples = {
        {{0.8, 0.1, 0.1}}, {{0.1, 0.8, 0.1}}, {{0.1, 0.1, 0.8}}};
    return samples;
  }

  /// `corner_samples()`, then one sample much nearer to each corner
  /// (barycentric 0.98), in corner order: the corner's front where a kink
  /// passes between the corner and its first sample
  /// (`parameters::corner_fallback` with the linear ridge; bunny_7k from
  /// vertex 697: recall p95 at tolerance 0.002 2.82 mean edges without them,
  /// 0.13 with them).
  static const std::vector<std::array<double, 3> >& corner_fallback_samples()
  {
    static const std::vector<std::array<double, 3> > samples = {
        corner_samples()[0], corner_samples()[1], corner_samples()[2],
        {{0.98, 0.01, 0.01}}, {{0.01, 0.98, 0.01}}, {{0.01, 0.01, 0.98}}};
    return samples;
  }

  /// `cone_ridge_samples()`, then the three samples at barycentric 0.98 of
  /// the corners, in corner order: the samples of the default cone ridge
  /// (`parameters::corner_fallback` with the cone ridge).
  static const std::vector<std::array<double, 3> >& cone_ridge_fallback_samples()
  {
    static const std::vector<std::array<double, 3> > samples = [] {
      std::vector<std::array<double, 3> > s = cone_ridge_samples();
      s.insert(s.end(), corner_fallback_samples().end() - 3, corner_fallback_samples().end());
      return s;
    }();
    return samples;
  }

};

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_SOLVERS_FACE_CONE_H
