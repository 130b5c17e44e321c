// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Iso-lines of a field that is linear on every face of a triangle mesh, by
// marching triangles. On the ridge-refined mesh (refined_mesh.h) this is the
// region-wise field, whose iso-lines turn sharply where they cross the ridge;
// on M with the vertex distances it is plain linear interpolation, for
// comparison.
#ifndef GEODESIC_RIDGE_ISOLINES_H
#define GEODESIC_RIDGE_ISOLINES_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/mesh_maps.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// One iso-line: a polyline at distance `level`. A closed one repeats its
/// first point at the end.
template <class Point_3>
struct Isoline
{
  /// the distance of the iso-line
  double level = 0;
  /// its points, on the edges of the mesh
  std::vector<Point_3> points;
  /// whether it is a closed curve (else it ends on the border)
  bool closed = false;
};

/// \ingroup PkgGeodesicRidgeRef
/// `n` levels equally spaced strictly between 0 and `largest`:
/// `largest * i / (n + 1)`, i = 1..n (for example with `largest` the
/// `Geodesic_distance_field::maximum_distance()`).
inline std::vector<double> equally_spaced_levels(std::size_t n, double largest)
{
  std::vector<double> levels;
  for(std::size_t i = 1; i <= n; ++i) levels.push_back(largest * double(i) / double(n + 1));
  return levels;
}

/// \ingroup PkgGeodesicRidgeRef
/// Writes to `out` (an output iterator of `Isoline<Point>`) the iso-lines of
/// the field that interpolates `distance_map` (a vertex property map of
/// doubles) linearly on every face of the triangle mesh `tm`, at each of
/// `levels`.
///
/// A vertex exactly at a level counts as above it (a symbolic perturbation),
/// so every face holds at most one segment per level and the segments chain
/// through the edges into closed curves, or curves that end on the border.
/// On the ridge-refined mesh (`refine_mesh_along_ridge()`) these are the
/// iso-lines of the region-wise field, sharp where they cross the ridge.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam DistanceMap a model of `ReadablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type
///         and `double` as value type
/// \tparam OutputIterator an output iterator accepting `Isoline<Point_3>`,
///         `Point_3` the value type of the vertex point map
///
/// \param tm the mesh
/// \param distance_map the distance at every vertex
/// \param levels the distances of the iso-lines
/// \param out the output iterator
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \pre every level is finite (`Invalid_parameter_error` otherwise).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in [0, `num_faces(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in [0, `num_edges(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `out` past the last iso-line
template <class TriangleMesh, class DistanceMap, class OutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator isolines(const TriangleMesh& tm, DistanceMap distance_map, const std::vector<double>& levels,
                        OutputIterator out, const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  const auto maps = internal::mesh_maps(tm, np);
  typedef typename decltype(maps)::Point Point;
  const auto& vpm = maps.vpm;
  const auto& eim = maps.eim;
  const auto& fim = maps.fim;
  const std::size_t ne = num_edges(tm), nf = num_faces(tm);
  for(double level : levels)
    if(!std::isfinite(level)) throw Invalid_parameter_error("an iso-line level is not a finite number");

  std::vector<halfedge_descriptor> halfedge_of_edge(ne);
  for(auto e : edges(tm)) halfedge_of_edge[get(eim, e)] = halfedge(e, tm);
  std::vector<face_descriptor> face_of(nf);
  for(face_descriptor f : faces(tm)) face_of[get(fim, f)] = f;

  for(double level : levels)
  {
    auto above = [&](halfedge_descriptor h, bool at_target) {
      return get(distance_map, at_target ? target(h, tm) : source(h, tm)) >= level;
    };
    auto crossed = [&](halfedge_descriptor h) { return above(h, false) != above(h, true); };
    auto crossing_point = [&](std::size_t e) {
      const halfedge_descriptor h = halfedge_of_edge[e];
      const double da = get(distance_map, source(h, tm)), db = get(distance_map, target(h, tm));
      const double t = (level - da) / (db - da);
      const Point& a = get(vpm, source(h, tm));
      const Point& b = get(vpm, target(h, tm));
      return Point(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()), a.z() + t * (b.z() - a.z()));
    };
    // per crossed face: its two crossed edges
    std::vector<std::array<std::size_t, 2> > crossed_edges(nf, {{ne, ne}});
    std::vector<std::array<std::size_t, 2> > faces_at_edge(ne, {{nf, nf}});
    std::vector<char> crossed_edge(ne, 0);
    for(std::size_t f = 0; f < nf; ++f)
    {
      int n = 0;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(face_of[f], tm), tm))
        if(crossed(h))
        {
          const std::size_t e = get(eim, edge(h, tm));
          if(n < 2) crossed_edges[f][n] = e;
          ++n;
          crossed_edge[e] = 1;
          faces_at_edge[e][faces_at_edge[e][0] == nf ? 0 : 1] = f;
        }
      if(n != 0 && n != 2) throw Invalid_parameter_error("the iso-lines need a triangle mesh");
    }
    std::vector<char> face_done(nf, 0), edge_done(ne, 0);
    // walks from edge e into the faces across it, until the curve ends or closes
    auto walk = [&](std::size_t e) {
      Isoline<Point> line;
      line.level = level;
      const std::size_t first = e;
      line.points.push_back(crossing_point(e));
      edge_done[e] = 1;
      for(;;)
      {
        std::size_t f = nf;
        for(std::size_t g : faces_at_edge[e])
          if(g != nf && !face_done[g]) { f = g; break; }
        if(f == nf) break;
        face_done[f] = 1;
        e = crossed_edges[f][0] == e ? crossed_edges[f][1] : crossed_edges[f][0];
        line.points.push_back(crossing_point(e));
        if(e == first) { line.closed = true; break; }
        edge_done[e] = 1;
      }
      return line;
    };
    // curves that end on the border first, then the closed ones
    for(std::size_t e = 0; e < ne; ++e)
      if(crossed_edge[e] && !edge_done[e] && (faces_at_edge[e][0] == nf || faces_at_edge[e][1] == nf))
        *out++ = walk(e);
    for(std::size_t e = 0; e < ne; ++e)
      if(crossed_edge[e] && !edge_done[e]) *out++ = walk(e);
  }
  return out;
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_ISOLINES_H
