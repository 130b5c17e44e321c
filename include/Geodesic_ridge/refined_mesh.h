// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The ridge-refined mesh (user manual, "The Region-wise Distance Field"): M
// with every face that holds more
// than one cell of the envelope split along every cell boundary, so that each
// new face lies in one cell, where the field is linear, and linear
// interpolation of one distance per vertex is the region-wise field.
//
// Cells are recomputed exactly (the polygons of `Ridge_curve::regions` are
// rounded), so shared points are found by exact keys and a point of one cell
// on the side of another (on a mesh edge, from the face across it, or a
// T-junction inside a face) is found by exact tests and put into that side:
// the result is conforming.
#ifndef GEODESIC_RIDGE_REFINED_MESH_H
#define GEODESIC_RIDGE_REFINED_MESH_H

#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/distance_field.h>
#include <Geodesic_ridge/lower_envelope.h>
#include <Geodesic_ridge/internal/faces_by_index.h>
#include <Geodesic_ridge/parameters.h>

#include <CGAL/Gmpq.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

namespace internal_np {
struct vertex_distance_map_t {};
} // namespace internal_np

namespace parameters {
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Named parameter of `refine_mesh_along_ridge()`: a writable vertex property
/// map of the output mesh that receives the distance at each vertex.
template <class PropertyMap>
CGAL::Named_function_parameters<PropertyMap, internal_np::vertex_distance_map_t> vertex_distance_map(PropertyMap m)
{
  return CGAL::Named_function_parameters<PropertyMap, internal_np::vertex_distance_map_t>(m);
}
/// \ingroup PkgGeodesicRidgeNamedParameters
/// Same, added to the named parameters `np`.
template <class PropertyMap, class NamedParameters>
CGAL::Named_function_parameters<PropertyMap, internal_np::vertex_distance_map_t, NamedParameters>
vertex_distance_map(PropertyMap m, const NamedParameters& np)
{
  return CGAL::Named_function_parameters<PropertyMap, internal_np::vertex_distance_map_t, NamedParameters>(m, np);
}
} // namespace parameters

/// \ingroup PkgGeodesicRidgeRef
/// A visitor of `refine_mesh_along_ridge()` that does nothing. A visitor has
/// `void face_created(InputFace original, OutputFace created)`, called once
/// per face of the output with the face of the input it lies in (as CGAL's
/// corefinement visitor tells which face a new face came from).
struct Default_refinement_visitor
{
  /// called once per output face `created`, with the face `original` of the input it lies in
  template <class InputFace, class OutputFace>
  void face_created(InputFace, OutputFace) {}
};

/// \ingroup PkgGeodesicRidgeRef
/// Counts of the ridge-refined mesh.
struct Refined_mesh_statistics
{
  std::size_t split_faces = 0;          ///< faces of M with more than one cell, or with points of a neighbour's cells on an edge
  /// vertices and faces of the output
  std::size_t vertices = 0, faces = 0;  ///< of the output
  std::size_t centre_vertices = 0;      ///< added inside cells whose sides hold points of other cells
  std::size_t ridge_edges = 0;          ///< output edges marked as ridge
  std::size_t unmatched_ridge_segments = 0; ///< ridge segments not found as output edges (0 unless a bug)
  /// the largest difference between the values that the faces sharing a
  /// point give there (the output takes the smallest): a ridge along a mesh
  /// edge whose copies differ at its ends, or fast-marching noise
  double largest_disagreement = 0;
};

namespace internal {

// An exact point of M: (0, vertex) | (1, edge, t from the endpoint of smaller
// index) | (2, face, λ1, λ2), as stage 3 keys its nodes.
typedef std::tuple<int, std::size_t, CGAL::Gmpq, CGAL::Gmpq> Exact_point_key;
typedef std::tuple<int, std::size_t, double, double> Rounded_point_key;
typedef std::array<CGAL::Gmpq, 3> Exact_barycentric;

// The cells of a face's envelope as exact polygons (the polygons of
// `Ridge_curve::regions` are rounded), recomputed from the cells' fields.
inline std::vector<std::vector<Exact_barycentric> > exact_cells(const std::vector<Ridge_region_cell>& cells)
{
  std::vector<std::array<double, 3> > fields;
  for(const auto& c : cells) fields.push_back(c.field);
  std::vector<std::vector<Exact_barycentric> > polygons;
  Lower_envelope<CGAL::Gmpq> envelope = compute_lower_envelope<CGAL::Gmpq>(fields);
  for(auto& cell : envelope.cells) polygons.push_back(std::move(cell.polygon));
  return polygons;
}

// The points of `points` strictly inside the segment ab, in order from a,
// each once (exact tests).
inline std::vector<const Exact_barycentric*> points_inside_side(const Exact_barycentric& a, const Exact_barycentric& b,
                                                               const std::vector<Exact_barycentric>& points)
{
  typedef CGAL::Gmpq Q;
  std::vector<std::pair<Q, const Exact_barycentric*> > inside;
  const Q d1 = b[1] - a[1], d2 = b[2] - a[2];
  for(const Exact_barycentric& p : points)
  {
    // p = a + s (b - a) with 0 < s < 1
    if((p[1] - a[1]) * d2 - (p[2] - a[2]) * d1 != 0) continue;
    const Q s = d1 != 0 ? (p[1] - a[1]) / d1 : (p[2] - a[2]) / d2;
    if(s > 0 && s < 1) inside.emplace_back(s, &p);
  }
  std::sort(inside.begin(), inside.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<const Exact_barycentric*> out;
  for(std::size_t i = 0; i < inside.size(); ++i)
    if(i == 0 || inside[i].first != inside[i - 1].first) out.push_back(inside[i].second);
  return out;
}

inline Exact_barycentric centroid(const std::vector<Exact_barycentric>& polygon)
{
  Exact_barycentric c = {{CGAL::Gmpq(0), CGAL::Gmpq(0), CGAL::Gmpq(0)}};
  for(const auto& p : polygon)
    for(int k = 0; k < 3; ++k) c[k] += p[k];
  for(int k = 0; k < 3; ++k) c[k] /= CGAL::Gmpq(static_cast<int>(polygon.size()));
  return c;
}

} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
/// Writes into `out` the ridge-refined mesh of `tm`: every face that holds more
/// than one cell of the envelope of `ridge` is split along every cell
/// boundary (the ridge, and the boundaries between fronts that the tolerance
/// pruned from it), conformingly, and every other face is copied. Each output
/// face lies in one cell; each output vertex carries one distance, and linear
/// interpolation of them is the region-wise field.
///
/// Where the faces that share a point disagree on its distance (a ridge along
/// a mesh edge whose copies differ at its ends; always a little with fast
/// marching), the vertex takes the smallest of their values (the envelope
/// over both sides); `Refined_mesh_statistics::largest_disagreement` reports
/// the largest difference.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam MutableFaceGraph a model of `MutableFaceGraph`
///
/// \param tm the mesh
/// \param ridge its ridge curve (`compute_ridge_curve()`)
/// \param out the output mesh
/// \param np_in an optional sequence of named parameters of `tm` among the
///        ones listed below: those the ridge was computed with
/// \param np_out an optional sequence of named parameters of `out` among the
///        ones listed below
///
/// \pre `out` is empty, and `ridge` was computed on `tm`
///      (`Invalid_parameter_error` otherwise).
///
/// \returns the counts of the refinement
///
/// \cgalNamedParamsBegin{Named Parameters of the Input (np_in)}
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in [0, `num_vertices(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
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
///   \cgalParamNBegin{field}
///     \cgalParamDescription{the field whose values the output vertices take; the faces are split along the cells of the linear field either way}
///     \cgalParamType{`Field`}
///     \cgalParamDefault{`Field::linear`}
///     \cgalParamExtra{`Field::cone` needs a ridge computed with `field(Field::cone)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \cgalNamedParamsBegin{Named Parameters of the Output (np_out)}
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `out`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<MutableFaceGraph>::%vertex_descriptor` as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, out)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_distance_map}
///     \cgalParamDescription{receives the distance at every output vertex (`Geodesic_ridge::parameters::vertex_distance_map()`)}
///     \cgalParamType{a class model of `WritablePropertyMap` with `boost::graph_traits<MutableFaceGraph>::%vertex_descriptor` as key type and `double` as value type}
///     \cgalParamDefault{none: the distances are not written}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map}
///     \cgalParamDescription{set to `true` on the output edges of the reported ridge, `false` elsewhere}
///     \cgalParamType{a class model of `WritablePropertyMap` with `boost::graph_traits<MutableFaceGraph>::%edge_descriptor` as key type and `bool` as value type}
///     \cgalParamDefault{none: the ridge edges are not marked}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{called once per output face with the face of the input it lies in (see `Default_refinement_visitor`)}
///     \cgalParamType{a class with `void face_created(boost::graph_traits<TriangleMesh>::%face_descriptor original, boost::graph_traits<MutableFaceGraph>::%face_descriptor created)`}
///     \cgalParamDefault{`Default_refinement_visitor()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class TriangleMesh, class Point, class MutableFaceGraph,
          class NamedParametersIn = CGAL::parameters::Default_named_parameters,
          class NamedParametersOut = CGAL::parameters::Default_named_parameters>
Refined_mesh_statistics refine_mesh_along_ridge(const TriangleMesh& tm, const Ridge_curve<TriangleMesh, Point>& ridge,
                                                MutableFaceGraph& out,
                                                const NamedParametersIn& np_in = CGAL::parameters::default_values(),
                                                const NamedParametersOut& np_out = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<MutableFaceGraph> OGT;
  typedef typename OGT::vertex_descriptor out_vertex;
  typedef typename OGT::face_descriptor out_face;
  typedef CGAL::Gmpq Q;
  typedef internal::Exact_barycentric Exact_barycentric;

  const auto vpm = CGAL::get_const_property_map(CGAL::vertex_point, tm);
  const auto vpm_in = choose_parameter(get_parameter(np_in, CGAL::internal_np::vertex_point), vpm);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np_in);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np_in);
  const auto eim = CGAL::get_initialized_edge_index_map(tm, np_in);
  const auto vpm_out = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                                        get_property_map(CGAL::vertex_point, out));
  auto distance_out = choose_parameter(get_parameter(np_out, internal_np::vertex_distance_map_t()),
                                       CGAL::Constant_property_map<out_vertex, double>(0));
  auto constrained_out = choose_parameter(get_parameter(np_out, CGAL::internal_np::edge_is_constrained),
                                          CGAL::Constant_property_map<typename OGT::edge_descriptor, bool>(false));
  auto visitor = choose_parameter(get_parameter(np_out, CGAL::internal_np::visitor), Default_refinement_visitor());

  const std::size_t nf = num_faces(tm), nv = num_vertices(tm), ne = num_edges(tm);
  if(ridge.regions.size() != nf || ridge.vertex_distances.size() != nv)
    throw Invalid_parameter_error("the ridge curve was not computed on this mesh");
  if(num_vertices(out) != 0 || num_faces(out) != 0) throw Invalid_parameter_error("the output mesh must be empty");
  const auto field = make_distance_field(tm, ridge, np_in);
  Refined_mesh_statistics st;

  const internal::Faces_by_index<TriangleMesh, std::decay_t<decltype(vpm_in)> > faces_by_index(tm, vpm_in, fim);
  auto face_of = [&](std::size_t f) { return faces_by_index.face(f); };
  auto corner_halfedges = [&](std::size_t f) { return faces_by_index.corner_halfedges(f); };
  auto corner_points = [&](std::size_t f) { return faces_by_index.corner_points(f); };
  // edge k of a face runs from corner k to corner k+1; its parameter t runs
  // from the endpoint of smaller vertex index
  auto edge_parameter = [&](std::size_t f, int k, const auto& lambda) {
    const auto h = corner_halfedges(f);
    const bool forward = get(vim, source(h[k], tm)) < get(vim, target(h[k], tm));
    return forward ? lambda[(k + 1) % 3] : lambda[k];
  };
  // the feature of a barycentric point: -1 interior, else the triangle edge k
  // it lies on (one zero) or 3 + the corner (two zeros)
  auto feature_of = [](const auto& lambda) {
    int zeros = 0, nz = -1, z = -1;
    for(int k = 0; k < 3; ++k) { if(lambda[k] == 0) { ++zeros; z = k; } else nz = k; }
    if(zeros >= 2) return 3 + nz;
    if(zeros == 1) return (z + 1) % 3; // coordinate (k+2)%3 vanishes on edge k
    return -1;
  };

  // ---- exact cells of the faces with several cells
  std::vector<std::vector<std::vector<Exact_barycentric> > > polygons(nf);
  std::vector<std::vector<Q> > edge_points(ne); // exact t of cell corners inside mesh edges
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& cells = ridge.regions[f];
    if(cells.size() < 2) continue;
    polygons[f] = internal::exact_cells(cells);
    const auto h = corner_halfedges(f);
    for(const auto& polygon : polygons[f])
    {
      for(const auto& p : polygon)
      {
        const int feature = feature_of(p);
        if(feature >= 0 && feature < 3)
          edge_points[get(eim, edge(h[feature], tm))].push_back(edge_parameter(f, feature, p));
      }
    }
  }
  for(auto& points : edge_points)
  {
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
  }

  // ---- output vertices, found by their exact key; values from every face
  //      that holds them (the smallest wins)
  std::vector<out_vertex> vertex_of_mesh_vertex(nv, OGT::null_vertex());
  std::map<internal::Exact_point_key, out_vertex> vertex_of_point;
  std::map<internal::Rounded_point_key, out_vertex> vertex_of_rounded; // to find the ridge's points
  std::map<out_vertex, std::pair<double, double> > value_range; // smallest and largest value given
  auto new_vertex = [&](const Point& p) {
    const out_vertex v = add_vertex(out);
    put(vpm_out, v, p);
    value_range.emplace(v, std::make_pair(std::numeric_limits<double>::infinity(),
                                          -std::numeric_limits<double>::infinity()));
    return v;
  };
  auto record_value = [&](out_vertex v, std::size_t f, const std::array<double, 3>& lambda) {
    const double d = field.distance(std::make_pair(face_of(f), lambda));
    auto& r = value_range[v];
    r.first = (std::min)(r.first, d);
    r.second = (std::max)(r.second, d);
  };
  auto rounded = [](const Exact_barycentric& l) {
    return std::array<double, 3>{{CGAL::to_double(l[0]), CGAL::to_double(l[1]), CGAL::to_double(l[2])}};
  };
  // the output vertex at exact point `lambda` of face f
  auto vertex_at = [&](std::size_t f, const Exact_barycentric& lambda) {
    const auto h = corner_halfedges(f);
    const int feature = feature_of(lambda);
    out_vertex v;
    if(feature >= 3)
    {
      const auto mv = source(h[feature - 3], tm);
      const std::size_t i = get(vim, mv);
      if(vertex_of_mesh_vertex[i] == OGT::null_vertex()) vertex_of_mesh_vertex[i] = new_vertex(get(vpm_in, mv));
      v = vertex_of_mesh_vertex[i];
    }
    else
    {
      internal::Exact_point_key key;
      internal::Rounded_point_key rkey;
      if(feature >= 0)
      {
        const std::size_t e = get(eim, edge(h[feature], tm));
        const Q t = edge_parameter(f, feature, lambda);
        key = internal::Exact_point_key(1, e, t, Q(0));
        rkey = internal::Rounded_point_key(1, e, CGAL::to_double(t), 0.);
      }
      else
      {
        key = internal::Exact_point_key(2, f, lambda[1], lambda[2]);
        rkey = internal::Rounded_point_key(2, f, CGAL::to_double(lambda[1]), CGAL::to_double(lambda[2]));
      }
      auto it = vertex_of_point.find(key);
      if(it == vertex_of_point.end())
      {
        const auto cp = corner_points(f);
        it = vertex_of_point.emplace(key, new_vertex(barycentric_to_point(lambda, cp[0], cp[1], cp[2]))).first;
        vertex_of_rounded.emplace(rkey, it->second);
      }
      v = it->second;
    }
    record_value(v, f, rounded(lambda));
    return v;
  };

  // ---- faces
  std::map<std::pair<out_vertex, out_vertex>, std::vector<out_vertex> > chain_of_side; // sides that got points
  auto add_triangle = [&](std::size_t f, out_vertex a, out_vertex b, out_vertex c) {
    const out_face nfce = CGAL::Euler::add_face(std::array<out_vertex, 3>{{a, b, c}}, out);
    if(nfce == OGT::null_face())
      throw Algorithm_error("the refined mesh could not be assembled at face " + std::to_string(f));
    visitor.face_created(face_of(f), nfce);
  };
  const Exact_barycentric corner[3] = {{{Q(1), Q(0), Q(0)}}, {{Q(0), Q(1), Q(0)}}, {{Q(0), Q(0), Q(1)}}};
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto h = corner_halfedges(f);
    bool split = polygons[f].size() > 1;
    for(int k = 0; k < 3 && !split; ++k) split = !edge_points[get(eim, edge(h[k], tm))].empty();
    if(!split)
    {
      add_triangle(f, vertex_at(f, corner[0]), vertex_at(f, corner[1]), vertex_at(f, corner[2]));
      continue;
    }
    ++st.split_faces;
    if(polygons[f].empty()) polygons[f].push_back({corner[0], corner[1], corner[2]});
    // every point of the face that a side may hold: cell corners and the
    // points of both faces' cells on its edges
    std::vector<Exact_barycentric> points;
    for(const auto& polygon : polygons[f]) points.insert(points.end(), polygon.begin(), polygon.end());
    for(int k = 0; k < 3; ++k)
    {
      const bool forward = get(vim, source(h[k], tm)) < get(vim, target(h[k], tm));
      for(const Q& t : edge_points[get(eim, edge(h[k], tm))])
      {
        Exact_barycentric l = {{Q(0), Q(0), Q(0)}};
        l[(k + 1) % 3] = forward ? t : Q(1) - t;
        l[k] = Q(1) - l[(k + 1) % 3];
        points.push_back(l);
      }
    }
    for(const auto& polygon : polygons[f])
    {
      // the cell's boundary with the points inside its sides
      std::vector<out_vertex> loop_vertices;
      for(std::size_t i = 0; i < polygon.size(); ++i)
      {
        const Exact_barycentric& a = polygon[i];
        const Exact_barycentric& b = polygon[(i + 1) % polygon.size()];
        const auto inside = internal::points_inside_side(a, b, points);
        loop_vertices.push_back(vertex_at(f, a));
        if(!inside.empty())
        {
          std::vector<out_vertex> chain{loop_vertices.back()};
          for(const Exact_barycentric* p : inside)
          {
            loop_vertices.push_back(vertex_at(f, *p));
            chain.push_back(loop_vertices.back());
          }
          const out_vertex vb = vertex_at(f, b);
          chain.push_back(vb);
          if(chain.front() > vb) std::reverse(chain.begin(), chain.end());
          chain_of_side[std::make_pair(chain.front(), chain.back())] = chain;
        }
      }
      const std::size_t n = loop_vertices.size();
      if(n == polygon.size())
      {
        // a convex polygon with true corners only: a fan
        for(std::size_t i = 1; i + 1 < n; ++i) add_triangle(f, loop_vertices[0], loop_vertices[i], loop_vertices[i + 1]);
      }
      else
      {
        // points inside sides: a star from the centre, so no triangle is flat
        const out_vertex c = vertex_at(f, internal::centroid(polygon));
        ++st.centre_vertices;
        for(std::size_t i = 0; i < n; ++i) add_triangle(f, c, loop_vertices[i], loop_vertices[(i + 1) % n]);
      }
    }
  }

  // ---- one distance per vertex: the smallest of the faces' values
  for(out_vertex v : vertices(out))
  {
    const auto& r = value_range[v];
    put(distance_out, v, r.first);
    st.largest_disagreement = (std::max)(st.largest_disagreement, r.second - r.first);
  }

  // ---- the reported ridge as constrained edges
  for(auto e : edges(out)) put(constrained_out, e, false);
  auto rounded_vertex = [&](const Ridge_point<Point>& p) -> out_vertex {
    const auto& l = p.barycentric;
    const int feature = feature_of(l);
    const auto h = corner_halfedges(p.face);
    if(feature >= 3) return vertex_of_mesh_vertex[get(vim, source(h[feature - 3], tm))];
    internal::Rounded_point_key key =
        feature >= 0 ? internal::Rounded_point_key(1, get(eim, edge(h[feature], tm)),
                                                    edge_parameter(p.face, feature, l), 0.)
                     : internal::Rounded_point_key(2, p.face, l[1], l[2]);
    const auto it = vertex_of_rounded.find(key);
    return it == vertex_of_rounded.end() ? OGT::null_vertex() : it->second;
  };
  auto mark = [&](out_vertex a, out_vertex b) {
    const auto hb = halfedge(a, b, out);
    if(!hb.second) return false;
    if(!get(constrained_out, edge(hb.first, out))) ++st.ridge_edges;
    put(constrained_out, edge(hb.first, out), true);
    return true;
  };
  for(const auto& polyline : ridge.polylines)
    for(std::size_t i = 0; i + 1 < polyline.size(); ++i)
    {
      const out_vertex a = rounded_vertex(polyline[i]), b = rounded_vertex(polyline[i + 1]);
      bool found = a != OGT::null_vertex() && b != OGT::null_vertex();
      if(found && a == b) continue; // a segment shorter than the rounding: nothing to mark
      if(found && !mark(a, b))
      {
        const auto it = chain_of_side.find(a < b ? std::make_pair(a, b) : std::make_pair(b, a));
        found = it != chain_of_side.end();
        if(found)
          for(std::size_t j = 0; j + 1 < it->second.size(); ++j) found = mark(it->second[j], it->second[j + 1]) && found;
      }
      if(!found) ++st.unmatched_ridge_segments;
    }
  st.vertices = num_vertices(out);
  st.faces = num_faces(out);
  return st;
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_REFINED_MESH_H
