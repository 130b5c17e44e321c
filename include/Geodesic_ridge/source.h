// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The geodesic source: a mesh vertex or a surface point (`Face_location`),
// validated and turned into what the stages need (Dijkstra seeds, the faces
// that hold the source).
#ifndef GEODESIC_RIDGE_SOURCE_H
#define GEODESIC_RIDGE_SOURCE_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/normalization.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// Where the source lies, after validation. A `Face_location` whose
/// barycentric coordinates put it on a vertex or an edge is classified as such,
/// because the cut must avoid exactly that vertex or edge.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
template <class TriangleMesh>
struct Geodesic_source
{
  /// the graph traits of `TriangleMesh`
  typedef boost::graph_traits<TriangleMesh>                 GT;
  /// a vertex of the mesh
  typedef typename GT::vertex_descriptor                   vertex_descriptor;
  /// a face of the mesh
  typedef typename GT::face_descriptor                     face_descriptor;
  /// a halfedge of the mesh
  typedef typename GT::halfedge_descriptor                 halfedge_descriptor;

  /// where the source lies
  enum Kind { ON_VERTEX, ON_EDGE, IN_FACE };
  /// \var Geodesic_source::ON_VERTEX
  /// at a vertex of the mesh
  /// \var Geodesic_source::ON_EDGE
  /// in the interior of an edge
  /// \var Geodesic_source::IN_FACE
  /// in the interior of a face

  /// where the source lies
  Kind kind = ON_VERTEX;
  /// the source vertex (`ON_VERTEX` only)
  vertex_descriptor vertex;
  /// the halfedge the source lies on (`ON_EDGE` only)
  halfedge_descriptor edge_halfedge;
  /// the faces whose interior or interior edge holds the source (none for `ON_VERTEX`)
  std::vector<face_descriptor> faces;
  /// Dijkstra seeds: vertices with their exact straight-line distance to the source
  /// (a straight segment inside one face or across the source's edge is a geodesic)
  std::vector<std::pair<vertex_descriptor, double> > seeds;
  /// the source as a face location (barycentric coordinates in CGAL's order)
  std::pair<face_descriptor, std::array<double, 3> > location;
};

/// \ingroup PkgGeodesicRidgeRef
/// Makes a source at vertex `v`.
/// \param tm the mesh
/// \param v the source vertex
/// \param vim the vertex index map of `tm`
/// \pre `v` is a vertex of `tm` (`Invalid_source_error` otherwise).
template <class TriangleMesh, class VertexIndexMap>
Geodesic_source<TriangleMesh>
make_vertex_source(const TriangleMesh& tm,
                   typename boost::graph_traits<TriangleMesh>::vertex_descriptor v,
                   const VertexIndexMap& vim)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  const std::size_t n = num_vertices(tm);
  bool found = false;
  if(v != GT::null_vertex())
  {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    found = (i < n);
  }
  if(!found || halfedge(v, tm) == GT::null_halfedge())
    throw Invalid_source_error("source vertex is not a vertex of the mesh (the mesh has " +
                               std::to_string(n) + " vertices)");
  Geodesic_source<TriangleMesh> s;
  s.kind = Geodesic_source<TriangleMesh>::ON_VERTEX;
  s.vertex = v;
  s.seeds.emplace_back(v, 0.0);
  // the location: in the face of halfedge(v), v is the target of that halfedge
  typename GT::halfedge_descriptor h = halfedge(v, tm);
  if(face(h, tm) == GT::null_face()) h = opposite(h, tm);
  const typename GT::face_descriptor f = face(h, tm);
  s.location.first = f;
  s.location.second = {0., 0., 0.};
  int k = 0;
  for(typename GT::halfedge_descriptor g : CGAL::halfedges_around_face(halfedge(f, tm), tm))
  {
    if(source(g, tm) == v) s.location.second[k] = 1.;
    ++k;
  }
  return s;
}

/// \ingroup PkgGeodesicRidgeRef
/// Makes a source at a surface point given by a face and barycentric
/// coordinates ordered as `source(halfedge(f))`, `target(halfedge(f))`,
/// `target(next(halfedge(f)))` (CGAL's `Face_location`). A location with two
/// zero coordinates is a vertex source, one with one zero coordinate lies on
/// an edge.
/// \param tm the mesh
/// \param loc the surface point
/// \param vpm, fim, vim the vertex point map, the face index map and the
///        vertex index map of `tm`
/// \pre the face of `loc` is a face of `tm`, and its coordinates are finite,
///      non-negative and sum to 1 within 1e-9 (`Invalid_source_error`
///      otherwise).
template <class TriangleMesh, class FT, class VertexPointMap, class FaceIndexMap, class VertexIndexMap>
Geodesic_source<TriangleMesh>
make_face_source(const TriangleMesh& tm,
                 const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                 std::array<FT, 3> >& loc,
                 const VertexPointMap& vpm, const FaceIndexMap& fim, const VertexIndexMap& vim)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  const std::size_t nf = num_faces(tm);
  const typename GT::face_descriptor f = loc.first;
  if(f == GT::null_face() || static_cast<std::size_t>(get(fim, f)) >= nf)
    throw Invalid_source_error("source face is not a face of the mesh (the mesh has " +
                               std::to_string(nf) + " faces)");
  std::array<double, 3> w;
  double sum = 0;
  for(int i = 0; i < 3; ++i)
  {
    w[i] = CGAL::to_double(loc.second[i]);
    if(!std::isfinite(w[i]) || w[i] < 0)
      throw Invalid_source_error("source barycentric coordinates must be finite and non-negative");
    sum += w[i];
  }
  if(!(std::abs(sum - 1.0) <= 1e-9))
    throw Invalid_source_error("source barycentric coordinates must sum to 1");

  const halfedge_descriptor h0 = halfedge(f, tm);
  const std::array<halfedge_descriptor, 3> hs = {h0, next(h0, tm), next(next(h0, tm), tm)};
  // corner i is source(hs[i]); the edge opposite corner i is hs[(i+1)%3]
  std::array<vertex_descriptor, 3> c = {source(hs[0], tm), source(hs[1], tm), source(hs[2], tm)};
  int zeros = 0;
  for(int i = 0; i < 3; ++i) zeros += (w[i] == 0.);
  if(zeros == 2)
  {
    for(int i = 0; i < 3; ++i)
      if(w[i] != 0.) return make_vertex_source(tm, c[i], vim);
  }

  Geodesic_source<TriangleMesh> s;
  s.location.first = f;
  s.location.second = w;
  const auto o = CGAL::ORIGIN;
  const auto p = o + ((get(vpm, c[0]) - o) * w[0] + (get(vpm, c[1]) - o) * w[1] + (get(vpm, c[2]) - o) * w[2]);
  auto dist_to = [&](vertex_descriptor v) { return internal::length_at_any_scale(get(vpm, v) - p); };
  s.faces.push_back(f);
  for(int i = 0; i < 3; ++i) s.seeds.emplace_back(c[i], dist_to(c[i]));
  if(zeros == 0)
  {
    s.kind = Geodesic_source<TriangleMesh>::IN_FACE;
    return s;
  }
  // On the edge opposite the corner with zero weight: the face across it holds the
  // source too, and its far corner is reached by a straight segment in that face.
  int zi = 0;
  for(int i = 0; i < 3; ++i) if(w[i] == 0.) zi = i;
  const halfedge_descriptor he = hs[(zi + 1) % 3];
  s.kind = Geodesic_source<TriangleMesh>::ON_EDGE;
  s.edge_halfedge = he;
  const halfedge_descriptor ho = opposite(he, tm);
  if(is_border(ho, tm)) return s; // a point of the border
  s.faces.push_back(face(ho, tm));
  s.seeds.emplace_back(target(next(ho, tm), tm), dist_to(target(next(ho, tm), tm)));
  return s;
}

/// \ingroup PkgGeodesicRidgeRef
/// \brief makes a source at the vertex `v`, reading the maps it needs from the
/// named parameters: what every entry point of the package calls.
///
/// \param tm the mesh
/// \param v the source vertex
/// \param np a sequence of named parameters among the ones listed below
/// \pre `v` is a vertex of `tm` (`Invalid_source_error` otherwise).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in [0, `num_vertices(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class TriangleMesh, class NamedParameters>
Geodesic_source<TriangleMesh>
make_source(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::vertex_descriptor v,
            const NamedParameters& np)
{
  return make_vertex_source(tm, v, internal::mesh_maps(tm, np).vim);
}

/// \ingroup PkgGeodesicRidgeRef
/// \brief makes a source at the surface point `loc` (a `Face_location`),
/// reading the maps it needs from the named parameters (see `make_face_source()`).
///
/// \param tm the mesh
/// \param loc the surface point
/// \param np a sequence of named parameters among the ones listed below
/// \pre the face of `loc` is a face of `tm`, and its coordinates are finite,
///      non-negative and sum to 1 within 1e-9 (`Invalid_source_error`
///      otherwise).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in [0, `num_vertices(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in [0, `num_faces(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
///                    as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class TriangleMesh, class FT, class NamedParameters>
Geodesic_source<TriangleMesh>
make_source(const TriangleMesh& tm,
            const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor, std::array<FT, 3> >& loc,
            const NamedParameters& np)
{
  const auto maps = internal::mesh_maps(tm, np);
  return make_face_source(tm, loc, maps.vpm, maps.fim, maps.vim);
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_SOURCE_H
