// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The property maps of the input mesh that every stage reads, taken once from
// the named parameters.
#ifndef GEODESIC_RIDGE_INTERNAL_MESH_MAPS_H
#define GEODESIC_RIDGE_INTERNAL_MESH_MAPS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <type_traits>

namespace Geodesic_ridge {
namespace internal {

// the length of the segment between the points of `a` and `b` (the sum of
// squares in the order of CGAL::squared_distance(), without its header)
template <class VPM, class Key>
double distance_between(const VPM& vpm, const Key& a, const Key& b)
{
  return std::sqrt(CGAL::to_double((get(vpm, a) - get(vpm, b)).squared_length()));
}

/// The input mesh's point and index maps: the user's `vertex_point_map` and
/// index maps, or the mesh's own (CGAL initializes index maps a mesh lacks).
/// Every internal class of a stage takes one of these.
template <class VertexPointMap, class VertexIndexMap, class FaceIndexMap, class EdgeIndexMap>
struct Mesh_maps
{
  typedef VertexPointMap Vertex_point_map;
  typedef VertexIndexMap Vertex_index_map;
  typedef FaceIndexMap Face_index_map;
  typedef EdgeIndexMap Edge_index_map;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

  VertexPointMap vpm;
  VertexIndexMap vim;
  FaceIndexMap fim;
  EdgeIndexMap eim;
};

/// The maps of `tm` from the named parameters `np` (`vertex_point_map`,
/// `vertex_index_map`, `face_index_map`, `edge_index_map`).
template <class TriangleMesh, class NamedParameters>
auto mesh_maps(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, tm));
  auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  auto fim = CGAL::get_initialized_face_index_map(tm, np);
  auto eim = CGAL::get_initialized_edge_index_map(tm, np);
  return Mesh_maps<decltype(vpm), decltype(vim), decltype(fim), decltype(eim)>{vpm, vim, fim, eim};
}

/// The type `mesh_maps(tm, np)` returns.
template <class TriangleMesh, class NamedParameters>
using Mesh_maps_of =
    decltype(mesh_maps(std::declval<const TriangleMesh&>(), std::declval<const NamedParameters&>()));

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_MESH_MAPS_H
