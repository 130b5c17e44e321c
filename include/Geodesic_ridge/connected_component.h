// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One connected component of a mesh copied into a mesh of its own, with the
// map between the two: the algorithm runs on one component (a geodesic from
// the source never reaches the others), and the others are unreachable.
#ifndef GEODESIC_RIDGE_CONNECTED_COMPONENT_H
#define GEODESIC_RIDGE_CONNECTED_COMPONENT_H

#include <Geodesic_ridge/exceptions.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <iterator>
#include <optional>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
///
/// \brief The map between a mesh and the copy of one of its connected
/// components that `extract_connected_component()` made: vertices, faces and
/// surface points, both ways, and what the other components hold.
///
/// Elements of the other components have no counterpart in the component:
/// the functions from the mesh to the component answer "none" for them, and
/// a geodesic distance there is infinite (unreachable from a source in the
/// component).
///
/// The map refers to the elements of both meshes through their initialized
/// vertex and face index maps: neither mesh may be changed while it is used.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
template <class TriangleMesh>
class Connected_component_map
{
public:
  /// the graph traits of `TriangleMesh`
  typedef boost::graph_traits<TriangleMesh> GT;
  /// a vertex, of the mesh or of the component
  typedef typename GT::vertex_descriptor vertex_descriptor;
  /// a face, of the mesh or of the component
  typedef typename GT::face_descriptor face_descriptor;
  /// a surface point: \cgal's `Polygon_mesh_processing::Face_location`, a face
  /// and barycentric coordinates in the order `source(halfedge(f))`,
  /// `target(halfedge(f))`, `target(next(halfedge(f)))`
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;

  /// the number of connected components of the mesh (edge-connected, as
  /// `CGAL::Polygon_mesh_processing::connected_components()` counts them)
  std::size_t number_of_components() const { return number_of_components_; }
  /// the number of faces of the mesh outside the component
  std::size_t number_of_other_faces() const { return other_faces_; }
  /// the number of vertices of the mesh outside the component
  std::size_t number_of_other_vertices() const { return other_vertices_; }

  /// the mesh vertex that component vertex `v` copies
  vertex_descriptor mesh_vertex(vertex_descriptor v) const { return mesh_vertex_[index(component_vim_, v)]; }
  /// the mesh face that component face `f` copies
  face_descriptor mesh_face(face_descriptor f) const { return mesh_face_[index(component_fim_, f)]; }

  /// the copy of mesh vertex `v`; none if `v` is in another component
  std::optional<vertex_descriptor> component_vertex(vertex_descriptor v) const
  {
    const std::size_t i = index(mesh_vim_, v);
    if(i >= component_vertex_.size() || component_vertex_[i] == GT::null_vertex())
      return std::nullopt;
    return component_vertex_[i];
  }

  /// the copy of mesh face `f`; none if `f` is in another component
  std::optional<face_descriptor> component_face(face_descriptor f) const
  {
    const std::size_t i = index(mesh_fim_, f);
    if(i >= component_face_.size() || component_face_[i] == GT::null_face())
      return std::nullopt;
    return component_face_[i];
  }

  /// the same point as `loc` (a point of the mesh) in the component, its
  /// coordinates only reordered; none if it is in another component
  std::optional<Face_location> component_location(const Face_location& loc) const
  {
    const std::optional<face_descriptor> f = component_face(loc.first);
    if(!f)
      return std::nullopt;
    return Face_location(*f, reordered(loc.second, corner_in_component_[index(mesh_fim_, loc.first)]));
  }

  /// the same point as `loc` (a point of the component) in the mesh, its
  /// coordinates only reordered
  Face_location mesh_location(const Face_location& loc) const
  {
    const face_descriptor f = mesh_face(loc.first);
    const std::array<int, 3>& k = corner_in_component_[index(mesh_fim_, f)];
    std::array<double, 3> b{};
    for(int i = 0; i < 3; ++i)
      b[i] = loc.second[k[i]];
    return Face_location(f, b);
  }

private:
  template <class Mesh, class NamedParameters>
  friend Connected_component_map<Mesh>
  extract_connected_component(const Mesh&, typename boost::graph_traits<Mesh>::face_descriptor, Mesh&,
                              const NamedParameters&);

  typedef typename CGAL::GetInitializedVertexIndexMap<TriangleMesh>::const_type Vertex_index_map;
  typedef typename CGAL::GetInitializedFaceIndexMap<TriangleMesh>::const_type Face_index_map;

  Connected_component_map(const TriangleMesh& tm, const TriangleMesh& component)
    : mesh_vim_(CGAL::get_initialized_vertex_index_map(tm)), mesh_fim_(CGAL::get_initialized_face_index_map(tm)),
      component_vim_(CGAL::get_initialized_vertex_index_map(component)),
      component_fim_(CGAL::get_initialized_face_index_map(component))
  {}

  template <class Map, class Key>
  static std::size_t index(const Map& map, const Key& k) { return static_cast<std::size_t>(get(map, k)); }

  // b with corner i of the mesh face moved to position k[i] of the component face
  static std::array<double, 3> reordered(const std::array<double, 3>& b, const std::array<int, 3>& k)
  {
    std::array<double, 3> r{};
    for(int i = 0; i < 3; ++i)
      r[k[i]] = b[i];
    return r;
  }

  Vertex_index_map mesh_vim_;
  Face_index_map mesh_fim_;
  Vertex_index_map component_vim_;
  Face_index_map component_fim_;
  std::size_t number_of_components_ = 0, other_faces_ = 0, other_vertices_ = 0;
  std::vector<vertex_descriptor> mesh_vertex_, component_vertex_;
  std::vector<face_descriptor> mesh_face_, component_face_;
  // per mesh face of the component: where each of its corners is in the copy
  std::vector<std::array<int, 3>> corner_in_component_;
};

/// \ingroup PkgGeodesicRidgeRef
///
/// \brief copies the connected component of `tm` that holds face `f` into
/// `component`, and returns the map between them.
///
/// The algorithm (`compute_geodesic_ridge()` and the stages) takes a
/// connected mesh: on a mesh of several parts (a model made of pieces, a
/// scan with stray fragments), the ridge of a source is the ridge of the
/// source's component, and the other components are unreachable. This
/// function makes that component a mesh of its own: run the algorithm on it,
/// and translate with the returned map (`Connected_component_map`). The
/// components are edge-connected, as
/// `CGAL::Polygon_mesh_processing::connected_components()` finds them; the
/// copy is made with `CGAL::copy_face_graph()` from a
/// `CGAL::Face_filtered_graph`, so vertex points and orientation are kept.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `MutableFaceGraph`
///         with an internal `CGAL::vertex_point` property map
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param f a face of `tm`: its component is copied
/// \param component an empty mesh, filled with the copy
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in `[0, num_faces(tm))`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
///                    as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_parameter_error if `component` is not empty
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Connected_component_map<TriangleMesh>
extract_connected_component(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                            TriangleMesh& component,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(num_vertices(component) != 0 || num_faces(component) != 0)
    throw Invalid_parameter_error("extract_connected_component: the output mesh must be empty");

  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  std::vector<std::size_t> component_id(num_faces(tm));
  const std::size_t n = PMP::connected_components(tm, boost::make_iterator_property_map(component_id.begin(), fim),
                                                  CGAL::parameters::face_index_map(fim));
  auto face_id = [&](face_descriptor g) { return static_cast<std::size_t>(get(fim, g)); };

  const std::size_t id = component_id[face_id(f)];
  std::vector<face_descriptor> selected;
  for(face_descriptor g : faces(tm))
    if(component_id[face_id(g)] == id)
      selected.push_back(g);
  const CGAL::Face_filtered_graph<TriangleMesh> part(tm, selected, CGAL::parameters::face_index_map(fim));
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> v2v;
  std::vector<std::pair<face_descriptor, face_descriptor>> f2f;
  CGAL::copy_face_graph(part, component,
                        CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v))
                          .face_to_face_output_iterator(std::back_inserter(f2f)));

  Connected_component_map<TriangleMesh> map(tm, component);
  typedef Connected_component_map<TriangleMesh> Map;
  map.number_of_components_ = n;
  map.other_faces_ = num_faces(tm) - num_faces(component);
  map.other_vertices_ = num_vertices(tm) - num_vertices(component);
  map.component_vertex_.assign(num_vertices(tm), GT::null_vertex());
  map.component_face_.assign(num_faces(tm), GT::null_face());
  map.corner_in_component_.assign(num_faces(tm), {{0, 1, 2}});
  map.mesh_vertex_.assign(num_vertices(component), GT::null_vertex());
  map.mesh_face_.assign(num_faces(component), GT::null_face());
  for(const auto& [mv, cv] : v2v)
  {
    map.component_vertex_[Map::index(map.mesh_vim_, mv)] = cv;
    map.mesh_vertex_[Map::index(map.component_vim_, cv)] = mv;
  }
  for(const auto& [mf, cf] : f2f)
  {
    map.component_face_[Map::index(map.mesh_fim_, mf)] = cf;
    map.mesh_face_[Map::index(map.component_fim_, cf)] = mf;
    // corner i of the mesh face, as a copy, is corner k[i] of the component face
    const halfedge_descriptor hm = halfedge(mf, tm), hc = halfedge(cf, component);
    const std::array<vertex_descriptor, 3> mc = {{source(hm, tm), target(hm, tm), target(next(hm, tm), tm)}};
    const std::array<vertex_descriptor, 3> cc = {
      {source(hc, component), target(hc, component), target(next(hc, component), component)}};
    std::array<int, 3>& k = map.corner_in_component_[Map::index(map.mesh_fim_, mf)];
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
        if(map.component_vertex_[Map::index(map.mesh_vim_, mc[i])] == cc[j])
          k[i] = j;
  }
  return map;
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_CONNECTED_COMPONENT_H
