// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1, step 2: the dual T* of the edges not in T, and the significance of
// each of its edges (the area it cuts off, paper section 3.1): edge roles, face
// areas, the dual adjacency, the Gaussian curvature shared among the faces, and
// the peeling of T*'s leaves that accumulates area and curvature per branch.
#ifndef GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_DUAL_SIGNIFICANCE_H
#define GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_DUAL_SIGNIFICANCE_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/corner_angles.h>
#include <Geodesic_ridge/internal/rough_cut/state.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace Geodesic_ridge::internal::rough_cut {

// whether h lies on a face holding the source
template <class TriangleMesh, class Maps>
bool touches_source_face(const State<TriangleMesh, Maps>& s,
                         typename State<TriangleMesh, Maps>::halfedge_descriptor h,
                         const std::vector<char>& is_source_face)
{
  return !is_border(h, s.tm) && is_source_face[s.fi(face(h, s.tm))];
}

// Step 2: every edge is in T, on a face holding the source, or crossed by T*.
template <class TriangleMesh, class Maps>
void classify_edges(State<TriangleMesh, Maps>& s)
{
  std::vector<char> is_source_face(s.nf, 0);
  for(auto f : s.src.faces) is_source_face[s.fi(f)] = 1;
  s.r.edge_role.assign(s.ne, Edge_role::dual_pruned);
  s.r.significance.assign(s.ne, std::numeric_limits<double>::quiet_NaN());
  for(auto e : edges(s.tm))
  {
    const auto h = halfedge(e, s.tm);
    const auto a = source(h, s.tm), b = target(h, s.tm);
    const bool in_tree = (s.r.parent[s.vi(a)] == b && a != b) || (s.r.parent[s.vi(b)] == a && a != b);
    if(in_tree)
      s.r.edge_role[s.ei(e)] = Edge_role::shortest_path_tree;
    else if(touches_source_face(s, h, is_source_face) || touches_source_face(s, opposite(h, s.tm), is_source_face))
      s.r.edge_role[s.ei(e)] = Edge_role::source_face;
    else
      s.r.dual_edges.push_back(e);
  }
  s.st.number_of_dual_edges = s.r.dual_edges.size();
  // T* has a node per face not holding the source, and one for the border
  // (all its loops): a spanning tree plus 2g + b - 1 independent cycles
  const long nodes = static_cast<long>(s.nf - s.src.faces.size()) + (s.has_boundary() ? 1 : 0);
  const long expected = nodes - 1 + 2 * s.st.genus + (s.has_boundary() ? static_cast<long>(s.st.number_of_boundary_loops) - 1 : 0);
  if(static_cast<long>(s.r.dual_edges.size()) != expected)
    throw Algorithm_error("the dual of the shortest-path tree has " + std::to_string(s.r.dual_edges.size()) +
                          " edges, expected " + std::to_string(expected));
}

// the area of every face, the total, and the part of it the nodes of T* share
template <class TriangleMesh, class Maps>
void measure_face_areas(State<TriangleMesh, Maps>& s)
{
  s.area.assign(s.nf + 1, 0.0); // (the border node has none)
  s.r.total_area = 0;
  for(auto f : faces(s.tm))
  {
    s.area[s.fi(f)] = CGAL::Polygon_mesh_processing::face_area(f, s.tm, CGAL::parameters::vertex_point_map(s.maps.vpm));
    s.r.total_area += s.area[s.fi(f)];
  }
  // The faces holding a surface-point source are no nodes of T*: the two sides
  // of a dual edge share the rest of the area.
  s.node_total = s.r.total_area;
  for(auto f : s.src.faces) s.node_total -= s.area[s.fi(f)];
}

// the faces of every dual edge, and the dual edges of every face (by position in dual_edges)
template <class TriangleMesh, class Maps>
void build_dual_adjacency(State<TriangleMesh, Maps>& s)
{
  s.nd = s.r.dual_edges.size();
  s.dual_faces_of.resize(s.nd);
  s.dual_of_face.resize(s.nf);
  s.dual_degree.assign(s.nf + 1, 0); // the border node's is never read
  for(std::size_t d = 0; d < s.nd; ++d)
  {
    const auto h = halfedge(s.r.dual_edges[d], s.tm);
    const std::size_t f1 = s.node_of(h), f2 = s.node_of(opposite(h, s.tm));
    s.dual_faces_of[d] = {f1, f2};
    for(std::size_t f : {f1, f2})
      if(f != s.border_node()) s.dual_of_face[f][s.dual_degree[f]++] = d;
  }
}

// Gaussian curvature (2π − angle sum) of every vertex, shared among its
// faces by angle (and its positive part): the peeling accumulates it per
// branch of T* like the area, for the false branches and the leaf curvature
// extension. The corner angles serve the leaves at corners too.
template <class TriangleMesh, class Maps>
void share_curvature_among_faces(State<TriangleMesh, Maps>& s)
{
  typedef Geodesic_source<TriangleMesh> Source;
  if(!s.curvature_sums()) return;
  if(s.options.corner_angles) s.angles = s.options.corner_angles;
  else
  {
    s.own_angles = corner_angles(s.tm, s.maps.vpm, s.maps.vim, s.maps.fim);
    s.angles = &s.own_angles;
  }
  s.curvature_share.assign(s.nf + 1, 0.0);
  s.positive_share.assign(s.nf + 1, 0.0);
  for(auto f : faces(s.tm))
  {
    auto h = halfedge(f, s.tm);
    for(int k = 0; k < 3; ++k, h = next(h, s.tm))
    {
      const std::size_t v = s.vi(source(h, s.tm));
      // the source is no leaf of its own cut locus
      if(s.src.kind == Source::ON_VERTEX && source(h, s.tm) == s.src.vertex) continue;
      const double share = s.angles->angle[s.fi(f)][k] / s.angles->angle_sum[v];
      s.curvature_share[s.fi(f)] += s.curvature(source(h, s.tm)) * share;
      s.positive_share[s.fi(f)] += std::max(0.0, s.curvature(source(h, s.tm))) * share;
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
template <class TriangleMesh, class Maps>
void peel_significance(State<TriangleMesh, Maps>& s)
{
  std::vector<double> branch_curvature(s.curvature_share), branch_positive(s.positive_share);
  branch_curvature.resize(s.nf + 1, 0.0);
  branch_positive.resize(s.nf + 1, 0.0);
  s.subtree_curvature.assign(s.curvature_sums() ? s.nd : 0, 0.0);
  s.subtree_positive.assign(s.curvature_sums() ? s.nd : 0, 0.0);
  std::vector<double> accumulated(s.area);
  std::vector<unsigned char> degree(s.dual_degree);
  s.peeled.assign(s.nd, 0);
  s.child_face.assign(s.nd, none);
  s.peel_order.reserve(s.nd);
  std::vector<std::size_t> queue;
  for(std::size_t f = 0; f < s.nf; ++f)
    if(degree[f] == 1) queue.push_back(f);
  for(std::size_t qi = 0; qi < queue.size(); ++qi)
  {
    const std::size_t f = queue[qi];
    if(degree[f] != 1) continue;
    std::size_t d = none;
    for(unsigned char k = 0; k < s.dual_degree[f]; ++k)
      if(!s.peeled[s.dual_of_face[f][k]]) d = s.dual_of_face[f][k];
    s.peeled[d] = 1;
    s.child_face[d] = f;
    s.peel_order.push_back(d);
    const double side = accumulated[f];
    s.r.significance[s.ei(s.r.dual_edges[d])] = s.has_boundary() ? side : (std::min)(side, s.node_total - side);
    const std::size_t p = s.across(d, f);
    accumulated[p] += side;
    if(s.curvature_sums())
    {
      s.subtree_curvature[d] = branch_curvature[f];
      branch_curvature[p] += branch_curvature[f];
      s.subtree_positive[d] = branch_positive[f];
      branch_positive[p] += branch_positive[f];
    }
    degree[f] = 0;
    if(--degree[p] == 1 && p != s.border_node()) queue.push_back(p);
  }
  for(std::size_t d = 0; d < s.nd; ++d)
    if(!s.peeled[d])
    {
      s.r.significance[s.ei(s.r.dual_edges[d])] = s.r.total_area;
      ++s.st.number_of_core_dual_edges;
    }
}

} // namespace Geodesic_ridge::internal::rough_cut

#endif
