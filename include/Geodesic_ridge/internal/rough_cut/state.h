// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1 (the rough cut locus): the state its passes share. Each pass of
// internal/rough_cut/ is a function of this state: it reads what the passes
// before it left and fills its own part; `Rough_cut_locus_builder::run()` in
// rough_cut_locus.h calls them in order. One struct instead of one class with
// every pass as a member keeps each header to one group of passes.
// The state fills the result types of rough_cut_locus_result.h.
#ifndef GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_STATE_H
#define GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_STATE_H

#include <Geodesic_ridge/internal/corner_angles.h>
#include <Geodesic_ridge/rough_cut_locus_result.h>
#include <Geodesic_ridge/parameters.h>
#include <Geodesic_ridge/source.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace Geodesic_ridge::internal::rough_cut {

/// no element (a dual edge or a face not found)
constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

// The input, the result filled step by step, and the per-element arrays of
// the passes (by element index; per dual edge by its position d in
// `r.dual_edges`), with the small queries every pass asks.
template <class TriangleMesh, class Maps>
struct State
{
  typedef boost::graph_traits<TriangleMesh>  GT;
  typedef typename GT::vertex_descriptor    vertex_descriptor;
  typedef typename GT::halfedge_descriptor  halfedge_descriptor;
  typedef typename GT::edge_descriptor      edge_descriptor;
  typedef typename GT::face_descriptor      face_descriptor;
  typedef Geodesic_source<TriangleMesh>     Source;

  // The curvature thresholds in radians.
  struct Options
  {
    double tolerance = default_tolerance, leaf_curvature = 0, branch_curvature = 0;
    // the mesh's corner angles, when a batch of sources computed them once
    const Corner_angles* corner_angles = nullptr;
  };

  State(const TriangleMesh& tm, const Source& src, const Maps& maps, const Options& options)
    : tm(tm), src(src), maps(maps), options(options),
      nv(num_vertices(tm)), ne(num_edges(tm)), nf(num_faces(tm)), st(r.statistics)
  {}

  std::size_t vi(vertex_descriptor v) const { return static_cast<std::size_t>(get(maps.vim, v)); }
  std::size_t ei(edge_descriptor e) const { return static_cast<std::size_t>(get(maps.eim, e)); }
  std::size_t fi(face_descriptor f) const { return static_cast<std::size_t>(get(maps.fim, f)); }
  double significance(std::size_t d) const { return r.significance[ei(r.dual_edges[d])]; }
  // the face of dual edge d other than f
  std::size_t across(std::size_t d, std::size_t f) const
  {
    return dual_faces_of[d][0] == f ? dual_faces_of[d][1] : dual_faces_of[d][0];
  }
  bool curvature_sums() const { return options.leaf_curvature > 0 || options.branch_curvature > 0; }

  bool has_boundary() const { return st.number_of_boundary_loops > 0; }
  bool on_boundary(vertex_descriptor v) const { return boundary_vertex[vi(v)] != 0; }
  // Gaussian curvature at v; 0 on the border, where the angle sum measures the
  // turning of the border, not curvature
  double curvature(vertex_descriptor v) const { return on_boundary(v) ? 0.0 : angles->curvature(vi(v)); }
  bool is_source_vertex(vertex_descriptor v) const
  {
    return is_seed[vi(v)] || (src.kind == Source::ON_VERTEX && v == src.vertex);
  }

  // the node of T* of the face of h: the face's index, or the border node
  std::size_t node_of(halfedge_descriptor h) const { return is_border(h, tm) ? border_node() : fi(face(h, tm)); }
  std::size_t border_node() const { return nf; }

  void add_cut(edge_descriptor e)
  {
    r.is_cut_edge[ei(e)] = 1;
    ++cut_degree[vi(source(e, tm))];
    ++cut_degree[vi(target(e, tm))];
  }
  void remove_cut(edge_descriptor e)
  {
    r.is_cut_edge[ei(e)] = 0;
    --cut_degree[vi(source(e, tm))];
    --cut_degree[vi(target(e, tm))];
  }
  // a free end of K: one cut edge, and not on the border (which K ∪ ∂M goes on along)
  bool is_leaf_of_cut(vertex_descriptor v) const { return cut_degree[vi(v)] == 1 && !on_boundary(v); }

  // a cut edge at v other than `not_this`, as a halfedge pointing into v
  halfedge_descriptor cut_halfedge_into(vertex_descriptor v, halfedge_descriptor not_this = GT::null_halfedge()) const
  {
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
      if(r.is_cut_edge[ei(edge(h, tm))] &&
         (not_this == GT::null_halfedge() || edge(h, tm) != edge(not_this, tm)))
        return h;
    return GT::null_halfedge();
  }

  // the input
  const TriangleMesh& tm;
  const Source src;
  const Maps maps;
  const Options options;
  const std::size_t nv, ne, nf;
  // the result, filled step by step
  Rough_cut_locus<TriangleMesh> r;
  Rough_cut_locus_statistics& st;
  // elements by index; per vertex: a seed of the source, on the border
  std::vector<edge_descriptor> edge_of;
  std::vector<face_descriptor> face_of;
  std::vector<char> is_seed, boundary_vertex;
  // step 1: edge lengths; step 2: areas, the dual graph (by position d in
  // r.dual_edges), curvature, and the peeling: per dual edge its child face
  // (the side peeled first) and the curvature beyond it
  std::vector<double> length, area;
  double node_total = 0;
  std::size_t nd = 0;
  std::vector<std::array<std::size_t, 2> > dual_faces_of;
  std::vector<std::array<std::size_t, 3> > dual_of_face;
  std::vector<unsigned char> dual_degree;
  Corner_angles own_angles;
  const Corner_angles* angles = nullptr;
  std::vector<double> curvature_share, positive_share, subtree_curvature, subtree_positive;
  std::vector<char> peeled;
  std::vector<std::size_t> child_face, peel_order;
  // step 3: the kept dual structure and its extensions; K and its vertex degrees
  double threshold = 0;
  std::vector<char> kept, false_branch, extension;
  std::size_t nkept = 0;
  std::vector<unsigned char> kept_degree;
  std::vector<std::size_t> rungs, cut_degree;
  std::vector<std::size_t> face_mark;
  std::size_t stamp = 0;
};

} // namespace Geodesic_ridge::internal::rough_cut

#endif
