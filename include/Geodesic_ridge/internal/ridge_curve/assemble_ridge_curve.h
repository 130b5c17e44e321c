// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 (user manual, "Stage 3: The Ridge Curve"): the driver, which runs
// the passes in order over the state they share (`Ridge_graph`).
//
// Every point of M is labelled by the copy that wins the lower envelope there.
// Two labels are the same front when their copies are glued in the extended
// surface across the edge between them (or carry equal fields, or agree along
// an edge of a thin face, whose gradient is noise, unless that costs the
// ridge a cycle of the topology). The ridge is every
// boundary between different fronts: inside faces (envelope edges) and along
// mesh edges. It is then made connected with the topology of the cut locus:
// the regions of M minus the ridge are merged (weakest ridge segment first)
// until one region is left, and detached pieces are dropped.
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_ASSEMBLE_RIDGE_CURVE_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_ASSEMBLE_RIDGE_CURVE_H

#include <Geodesic_ridge/internal/ridge_curve/envelope_cells.h>
#include <Geodesic_ridge/internal/ridge_curve/join_border_components.h>
#include <Geodesic_ridge/internal/ridge_curve/kink_splitter.h>
#include <Geodesic_ridge/internal/ridge_curve/join_verified_pieces.h>
#include <Geodesic_ridge/internal/ridge_curve/main_component.h>
#include <Geodesic_ridge/internal/ridge_curve/merge_into_one_region.h>
#include <Geodesic_ridge/internal/ridge_curve/prune_spurs.h>
#include <Geodesic_ridge/internal/ridge_curve/recombined_copy_splitter.h>
#include <Geodesic_ridge/internal/ridge_curve/rejoin_pieces.h>
#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>
#include <Geodesic_ridge/internal/ridge_curve/ridge_passes.h>
#include <Geodesic_ridge/internal/ridge_curve/segments_along_edges.h>
#include <Geodesic_ridge/internal/ridge_curve/segments_inside_faces.h>
#include <Geodesic_ridge/internal/ridge_curve/thin_faces.h>

#include <array>
#include <map>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// What stage 3 reads besides the mesh and E: the copies, what the splitters
// read (the copies' corner distances; the solver's cones at the samples),
// the parameters and which passes run.
struct Ridge_curve_input
{
  std::vector<Face_copies>& face_copies;        // per face of M: its undominated copies (split in place)
  std::vector<std::array<double, 3> >& copy_corners; // per copy of E: its corner distances (freed once read)
  const std::vector<Face_cone>& copy_cones;     // S per copy of E at the S samples (empty: none read)
  const std::vector<std::array<double, 3> >& samples;
  const std::vector<double>& angle_sum;         // per vertex of M: the sum of its corner angles
  double mean_edge, minimum_angle, kink_angle;
  bool split_at_kinks, corner_fallback;
  bool fronts_as_copies; // the cone ridge sees a split copy's fronts as copies (their cones in `front_cones`)
  Ridge_passes passes;
  std::size_t cycles; // 2g + b: the independent cycles of the ridge with the border of M
};

// From the fronts of the copies on: the envelopes, the ridge between
// different fronts, one region, the main component and its polylines.
template <class TriangleMesh, class Point, class Maps>
void ridge_between_fronts(const TriangleMesh& tm, const Extended_surface<Point>& E, const Maps& maps,
                          const Ridge_curve_input& in, const std::vector<Face_copies>& fronts,
                          const Copy_cones* cones, Ridge_passes passes,
                          std::vector<std::vector<Ridge_point<Point> > >& polylines,
                          std::vector<std::vector<Ridge_region_cell> >& regions, Ridge_curve_statistics& st)
{
  Ridge_graph<TriangleMesh, Maps> ridge(tm, E, fronts, in.mean_edge, in.minimum_angle, in.kink_angle, maps,
                                        in.angle_sum, regions, st, cones);
  ridge.label_border_loops();                           // the border's loops, each one node of the graph
  envelope_cells(ridge);                                // per face the exact envelope of its copies; a front per cell
  segments_inside_faces(ridge);                         // envelope edges between different fronts
  if(passes.on(Ridge_pass::thin_faces)) thin_faces(ridge); // faces whose gradient is noise (else none)
  segments_along_edges(ridge);                          // pieces of mesh edges between different fronts
  merge_into_one_region(ridge);                         // weakest segments out until M minus the ridge is one region
  if(passes.on(Ridge_pass::rejoin_pieces)) rejoin_pieces(ridge); // merged segments back where a branch was cut off
  if(in.minimum_angle > 0) prune_spurs(ridge, passes);  // free ends that end no cut locus, rule by rule
  if(passes.on(Ridge_pass::join_border_components)) join_border_components(ridge); // pieces on different loops
  if(passes.on(Ridge_pass::join_verified_pieces)) join_verified_pieces(ridge); // detached pieces with a kink
  const auto kept = keep_main_component(ridge);         // the main component's segments
  count_topology(ridge, kept);                          // junctions, free ends, components, cycles
  chains_as_polylines(ridge, kept, polylines);          // its chains as polylines
}

// Stage 3: every pass in order, one line each. `front_cones`: the cones of
// the fronts of the copies split at a kink (with `fronts_as_copies`).
template <class TriangleMesh, class Point, class Maps>
void assemble_ridge_curve(const TriangleMesh& tm, const Extended_surface<Point>& E, const Maps& maps,
                          const Ridge_curve_input& in, std::vector<std::vector<Ridge_point<Point> > >& polylines,
                          std::vector<std::vector<Ridge_region_cell> >& regions, Ridge_curve_statistics& st,
                          std::map<std::size_t, std::vector<Face_cone> >& front_cones)
{
  typedef typename Maps::Vertex_point_map VPM;
  typedef typename Maps::Face_index_map FIM;
  const Ridge_passes passes = in.passes;
  // before the envelopes: copies split into the fronts they carry
  if(passes.on(Ridge_pass::recombined_copy_split))      // copies that recombine nearer copies' fronts
    st.recombined_copies = Recombined_copy_splitter<TriangleMesh, VPM, FIM, Point>(
        tm, maps.vpm, maps.fim, E, in.copy_corners, tuning::ridge::recombined_witness_tolerance * in.mean_edge,
        tuning::ridge::recombined_split_degrees)(in.face_copies);
  std::vector<std::array<double, 3> >().swap(in.copy_corners);
  const bool split_at_kinks = in.split_at_kinks && passes.on(Ridge_pass::kink_split);
  std::vector<Face_copies> split_fronts; // (without a split, the copies as they are: no copy of them)
  if(split_at_kinks)                                    // copies whose corners' fronts meet at a kink
    split_fronts = Kink_splitter<TriangleMesh, VPM, FIM, Point>(
        tm, maps.vpm, maps.fim, E, in.copy_cones, in.samples, in.kink_angle, in.mean_edge,
        in.corner_fallback)(in.face_copies, st.split_copies, in.fronts_as_copies ? &front_cones : nullptr);
  // the cones (the copies' and the split fronts') give the fronts' arrival
  // directions at the ridge segments
  const Copy_cones cones{&in.copy_cones, &front_cones, &in.samples};
  const std::vector<Face_copies>& fronts = split_at_kinks ? split_fronts : in.face_copies;
  const Copy_cones* front_cones_read = in.fronts_as_copies ? &cones : nullptr;
  const Ridge_curve_statistics copies_statistics = st;
  ridge_between_fronts(tm, E, maps, in, fronts, front_cones_read, passes, polylines, regions, st);
  // The thin-face rule unites two fronts by their values alone, and where a
  // cycle of the cut locus crosses thin faces that can open the cycle: the
  // ridge then lacks a cycle of the topology (fertility_9k with caps from
  // v2696: 7 of 8, `bench_ridge_accuracy --caps 0.2`). Such a ridge is
  // assembled again without the rule (which keeps it wherever the topology
  // holds: it moves the ridge off the caps).
  if(st.thin_face_pieces > 0 && (st.components != 1 || st.cycles != in.cycles))
  {
    const std::size_t thin_face_pieces = st.thin_face_pieces;
    st = copies_statistics;
    polylines.clear();
    Ridge_passes without_thin = passes;
    without_thin.disabled |= static_cast<unsigned>(Ridge_pass::thin_faces);
    ridge_between_fronts(tm, E, maps, in, fronts, front_cones_read, without_thin, polylines, regions, st);
    st.thin_face_pieces_undone = thin_face_pieces;
  }
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_ASSEMBLE_RIDGE_CURVE_H
