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
#include <Geodesic_ridge/rough_cut_locus_result.h>
#include <Geodesic_ridge/internal/corner_angles.h>
#include <Geodesic_ridge/internal/graph_polylines.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/normalization.h>
#include <Geodesic_ridge/mesh_validation.h>
#include <Geodesic_ridge/parameters.h>
#include <Geodesic_ridge/source.h>
#include <Geodesic_ridge/timings.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

// The passes of stage 1, one group per header, as functions of the state they
// share (internal/rough_cut/state.h, which fills the result types of
// rough_cut_locus_result.h).
#include <Geodesic_ridge/internal/rough_cut/state.h>
#include <Geodesic_ridge/internal/rough_cut/shortest_path_tree.h>
#include <Geodesic_ridge/internal/rough_cut/dual_significance.h>
#include <Geodesic_ridge/internal/rough_cut/dual_pruning.h>
#include <Geodesic_ridge/internal/rough_cut/cut_graph.h>
#include <Geodesic_ridge/internal/rough_cut/corners.h>
#include <Geodesic_ridge/internal/rough_cut/checks.h>

namespace Geodesic_ridge {
namespace internal {

// Stage 1 as its named steps (the manual's order), over the state they share.
// `run()` calls them in order; each step reads what the steps before it left.
template <class TriangleMesh, class Maps>
class Rough_cut_locus_builder
{
  typedef rough_cut::State<TriangleMesh, Maps> State;

public:
  typedef typename State::Options Options;

  Rough_cut_locus_builder(const TriangleMesh& tm, const Geodesic_source<TriangleMesh>& src, const Maps& maps,
                          const Options& options)
    : s_(tm, src, maps, options)
  {}

  // `field`, if given, holds a geodesic distance per vertex (by vertex index):
  // the tree then follows it (`descend_field`) instead of Dijkstra's edge distances.
  Rough_cut_locus<TriangleMesh> run(const std::vector<double>* field = nullptr)
  {
    Timings& timings = s_.r.timings;
    timings.time("shortest_path_tree", [&] {          // rough_cut/shortest_path_tree.h
      rough_cut::count_elements(s_);                  // genus, border loops, elements by index
      rough_cut::shortest_path_tree(s_);              // Dijkstra along mesh edges
      if(field != nullptr) rough_cut::descend_field(s_, *field); // or down the given field
    });
    timings.time("significance", [&] {                // rough_cut/dual_significance.h
      rough_cut::classify_edges(s_);                  // in T, at the source, or crossed by T*
      rough_cut::measure_face_areas(s_);
      rough_cut::build_dual_adjacency(s_);
      rough_cut::share_curvature_among_faces(s_);     // per face, for the branch sums
      rough_cut::peel_significance(s_);               // area (and curvature) per dual edge
    });
    timings.time("cut_graph", [&] {
      rough_cut::prune_by_significance(s_);           // rough_cut/dual_pruning.h
      rough_cut::prune_false_branches(s_);            // no curvature enclosed
      if(!s_.st.fallback_single_rung && s_.options.leaf_curvature > 0)
        rough_cut::extend_leaves_by_curvature(s_);    // towards the tips of the ridge
      rough_cut::record_dual_roles(s_);
      rough_cut::span_rungs(s_);                      // rough_cut/cut_graph.h: Kruskal
      rough_cut::close_handle_cycles(s_);             // the 2g rungs back
      rough_cut::remove_teeth(s_);
      if(!s_.st.fallback_single_rung && s_.options.leaf_curvature > 0)
      {
        rough_cut::move_leaves_onto_corners(s_);      // rough_cut/corners.h
        rough_cut::remove_prongs_at_corner_forks(s_);
        rough_cut::join_corners(s_);
      }
      rough_cut::collect_cut_edges(s_);               // rough_cut/checks.h
    });
    timings.time("disk_check", [&] { rough_cut::check_disk(s_); });
    return std::move(s_.r);
  }

private:
  State s_;
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
