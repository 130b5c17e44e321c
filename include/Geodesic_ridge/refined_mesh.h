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
#include <Geodesic_ridge/internal/coincident_points.h>
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

// The ridge-refined mesh as its named steps: the exact cells of the faces
// with several cells, then the output faces (a face copied, or split into its
// cells, each triangulated), one distance per output vertex, and the ridge's
// edges marked.
template <class TriangleMesh, class Point, class MutableFaceGraph, class Field, class Maps, class OutputPointMap,
          class DistanceMap, class ConstrainedMap, class Visitor>
class Ridge_refiner
{
  typedef boost::graph_traits<MutableFaceGraph> OGT;
  typedef typename OGT::vertex_descriptor out_vertex;
  typedef typename OGT::face_descriptor out_face;
  typedef CGAL::Gmpq Q;

public:
  Ridge_refiner(const TriangleMesh& tm, const Ridge_curve<TriangleMesh, Point>& ridge, MutableFaceGraph& out,
                const Field& field, const Maps& maps, OutputPointMap vpm_out, DistanceMap distance_out,
                ConstrainedMap constrained_out, Visitor visitor)
    : tm_(tm), maps_(maps), ridge_(ridge), out_(out), field_(field), vpm_out_(vpm_out), distance_out_(distance_out),
      constrained_out_(constrained_out), visitor_(visitor), faces_(tm, maps.vpm, maps.fim), nf_(num_faces(tm)),
      vertex_of_mesh_vertex_(num_vertices(tm), OGT::null_vertex()), near_(coincident_tolerance(tm, maps.vpm))
  {}

  Refined_mesh_statistics run()
  {
    collect_exact_cells();
    for(std::size_t f = 0; f < nf_; ++f)
      if(is_split(f)) split_face(f);
      else add_triangle(f, vertex_at(f, corner(0)), vertex_at(f, corner(1)), vertex_at(f, corner(2)));
    assign_distances();
    mark_ridge_edges();
    st_.vertices = num_vertices(out_);
    st_.faces = num_faces(out_);
    return st_;
  }

private:
  static Exact_barycentric corner(int k)
  {
    Exact_barycentric l = {{Q(0), Q(0), Q(0)}};
    l[k] = Q(1);
    return l;
  }

  // edge k of a face runs from corner k to corner k+1; its parameter t runs
  // from the endpoint of smaller vertex index
  template <class Barycentric>
  auto edge_parameter(std::size_t f, int k, const Barycentric& lambda) const
  {
    const auto h = faces_.corner_halfedges(f);
    const bool forward = get(maps_.vim, source(h[k], tm_)) < get(maps_.vim, target(h[k], tm_));
    return forward ? lambda[(k + 1) % 3] : lambda[k];
  }
  std::size_t edge_index(std::size_t f, int k) const
  {
    return get(maps_.eim, edge(faces_.corner_halfedges(f)[k], tm_));
  }

  // the feature of a barycentric point: -1 interior, else the triangle edge k
  // it lies on (one zero) or 3 + the corner (two zeros)
  template <class Barycentric>
  static int feature_of(const Barycentric& lambda)
  {
    int zeros = 0, nz = -1, z = -1;
    for(int k = 0; k < 3; ++k) { if(lambda[k] == 0) { ++zeros; z = k; } else nz = k; }
    if(zeros >= 2) return 3 + nz;
    if(zeros == 1) return (z + 1) % 3; // coordinate (k+2)%3 vanishes on edge k
    return -1;
  }

  // Exact cells of the faces with several cells, and the exact parameters of
  // their corners inside mesh edges.
  void collect_exact_cells()
  {
    polygons_.resize(nf_);
    edge_points_.resize(num_edges(tm_));
    for(std::size_t f = 0; f < nf_; ++f)
    {
      if(ridge_.regions[f].size() < 2) continue;
      polygons_[f] = exact_cells(ridge_.regions[f]);
      for(const auto& polygon : polygons_[f])
        for(const auto& p : polygon)
        {
          const int feature = feature_of(p);
          if(feature >= 0 && feature < 3) edge_points_[edge_index(f, feature)].push_back(edge_parameter(f, feature, p));
        }
    }
    for(auto& points : edge_points_)
    {
      std::sort(points.begin(), points.end());
      points.erase(std::unique(points.begin(), points.end()), points.end());
    }
  }

  bool is_split(std::size_t f) const
  {
    if(polygons_[f].size() > 1) return true;
    for(int k = 0; k < 3; ++k)
      if(!edge_points_[edge_index(f, k)].empty()) return true;
    return false;
  }

  out_vertex new_vertex(const Point& p)
  {
    const out_vertex v = add_vertex(out_);
    put(vpm_out_, v, p);
    near_.insert(out_vertices_.size(), xyz(p));
    out_vertices_.push_back(v);
    value_range_.emplace(v, std::make_pair(std::numeric_limits<double>::infinity(),
                                           -std::numeric_limits<double>::infinity()));
    return v;
  }

  // the output vertex at exact point `lambda` of face f, found by its exact
  // key; it records the value face f gives there
  out_vertex vertex_at(std::size_t f, const Exact_barycentric& lambda)
  {
    const auto h = faces_.corner_halfedges(f);
    const int feature = feature_of(lambda);
    out_vertex v;
    if(feature >= 3)
    {
      const auto mv = source(h[feature - 3], tm_);
      out_vertex& mapped = vertex_of_mesh_vertex_[get(maps_.vim, mv)];
      if(mapped == OGT::null_vertex()) mapped = new_vertex(get(maps_.vpm, mv));
      v = mapped;
    }
    else
    {
      Exact_point_key key;
      Rounded_point_key rkey;
      if(feature >= 0)
      {
        const std::size_t e = edge_index(f, feature);
        const Q t = edge_parameter(f, feature, lambda);
        key = Exact_point_key(1, e, t, Q(0));
        rkey = Rounded_point_key(1, e, CGAL::to_double(t), 0.);
      }
      else
      {
        key = Exact_point_key(2, f, lambda[1], lambda[2]);
        rkey = Rounded_point_key(2, f, CGAL::to_double(lambda[1]), CGAL::to_double(lambda[2]));
      }
      auto it = vertex_of_point_.find(key);
      if(it == vertex_of_point_.end())
      {
        const auto cp = faces_.corner_points(f);
        it = vertex_of_point_.emplace(key, new_vertex(barycentric_to_point(lambda, cp[0], cp[1], cp[2]))).first;
        vertex_of_rounded_.emplace(rkey, it->second);
      }
      v = it->second;
    }
    const std::array<double, 3> rounded = {{CGAL::to_double(lambda[0]), CGAL::to_double(lambda[1]),
                                            CGAL::to_double(lambda[2])}};
    const double d = field_.distance(std::make_pair(faces_.face(f), rounded));
    auto& r = value_range_[v];
    r.first = (std::min)(r.first, d);
    r.second = (std::max)(r.second, d);
    return v;
  }

  void add_triangle(std::size_t f, out_vertex a, out_vertex b, out_vertex c)
  {
    const out_face created = CGAL::Euler::add_face(std::array<out_vertex, 3>{{a, b, c}}, out_);
    if(created == OGT::null_face())
      throw Algorithm_error("the refined mesh could not be assembled at face " + std::to_string(f));
    visitor_.face_created(faces_.face(f), created);
  }

  // every point of face f that a side may hold: cell corners and the points of
  // both faces' cells on its edges
  std::vector<Exact_barycentric> points_of_face(std::size_t f) const
  {
    std::vector<Exact_barycentric> points;
    for(const auto& polygon : polygons_[f]) points.insert(points.end(), polygon.begin(), polygon.end());
    const auto h = faces_.corner_halfedges(f);
    for(int k = 0; k < 3; ++k)
    {
      const bool forward = get(maps_.vim, source(h[k], tm_)) < get(maps_.vim, target(h[k], tm_));
      for(const Q& t : edge_points_[edge_index(f, k)])
      {
        Exact_barycentric l = {{Q(0), Q(0), Q(0)}};
        l[(k + 1) % 3] = forward ? t : Q(1) - t;
        l[k] = Q(1) - l[(k + 1) % 3];
        points.push_back(l);
      }
    }
    return points;
  }

  // f into its cells (a face with one cell but points on its edges is one cell)
  void split_face(std::size_t f)
  {
    ++st_.split_faces;
    if(polygons_[f].empty()) polygons_[f].push_back({corner(0), corner(1), corner(2)});
    const std::vector<Exact_barycentric> points = points_of_face(f);
    for(const auto& polygon : polygons_[f]) triangulate_cell(f, polygon, points);
  }

  // a cell's boundary with the points inside its sides, triangulated
  void triangulate_cell(std::size_t f, const std::vector<Exact_barycentric>& polygon,
                        const std::vector<Exact_barycentric>& points)
  {
    std::vector<out_vertex> loop;
    for(std::size_t i = 0; i < polygon.size(); ++i)
    {
      const Exact_barycentric& a = polygon[i];
      const Exact_barycentric& b = polygon[(i + 1) % polygon.size()];
      const auto inside = points_inside_side(a, b, points);
      loop.push_back(vertex_at(f, a));
      if(inside.empty()) continue;
      // the side's chain, kept so the ridge can be found along it
      std::vector<out_vertex> chain{loop.back()};
      for(const Exact_barycentric* p : inside)
      {
        loop.push_back(vertex_at(f, *p));
        chain.push_back(loop.back());
      }
      chain.push_back(vertex_at(f, b));
      if(chain.front() > chain.back()) std::reverse(chain.begin(), chain.end());
      chain_of_side_[std::make_pair(chain.front(), chain.back())] = chain;
    }
    const std::size_t n = loop.size();
    if(n == polygon.size())
    {
      // a convex polygon with true corners only: a fan
      for(std::size_t i = 1; i + 1 < n; ++i) add_triangle(f, loop[0], loop[i], loop[i + 1]);
      return;
    }
    // points inside sides: a star from the centre, so no triangle is flat
    const out_vertex c = vertex_at(f, centroid(polygon));
    ++st_.centre_vertices;
    for(std::size_t i = 0; i < n; ++i) add_triangle(f, c, loop[i], loop[(i + 1) % n]);
  }

  // one distance per vertex: the smallest of the faces' values
  void assign_distances()
  {
    for(out_vertex v : vertices(out_))
    {
      const auto& r = value_range_[v];
      put(distance_out_, v, r.first);
      st_.largest_disagreement = (std::max)(st_.largest_disagreement, r.second - r.first);
    }
  }

  static std::array<double, 3> xyz(const Point& p)
  {
    return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  }

  // the output vertices at a ridge point: those at its rounded coordinates
  // (one, or several where the two faces of an edge put exact points on it
  // that differ below the rounding: the fields of copies split at a kink need
  // not agree along their edges), and those within the coincidence tolerance
  // of it (one ridge node stands for the exact points of the cells it joins
  // that are one surface point: internal/coincident_points.h)
  std::vector<out_vertex> rounded_vertices(const Ridge_point<Point>& p) const
  {
    std::vector<out_vertex> out = vertices_at(p);
    near_.for_each_near(xyz(p.point), [&](std::size_t i) {
      if(std::find(out.begin(), out.end(), out_vertices_[i]) == out.end()) out.push_back(out_vertices_[i]);
      return false;
    });
    return out;
  }
  std::vector<out_vertex> vertices_at(const Ridge_point<Point>& p) const
  {
    const auto& l = p.barycentric;
    const int feature = feature_of(l);
    const auto h = faces_.corner_halfedges(p.face);
    std::vector<out_vertex> out;
    if(feature >= 3)
    {
      const out_vertex v = vertex_of_mesh_vertex_[get(maps_.vim, source(h[feature - 3], tm_))];
      if(v != OGT::null_vertex()) out.push_back(v);
      return out;
    }
    const Rounded_point_key key = feature >= 0
        ? Rounded_point_key(1, edge_index(p.face, feature), edge_parameter(p.face, feature, l), 0.)
        : Rounded_point_key(2, p.face, l[1], l[2]);
    const auto range = vertex_of_rounded_.equal_range(key);
    for(auto it = range.first; it != range.second; ++it) out.push_back(it->second);
    return out;
  }

  bool mark(out_vertex a, out_vertex b)
  {
    const auto hb = halfedge(a, b, out_);
    if(!hb.second) return false;
    if(!get(constrained_out_, edge(hb.first, out_))) ++st_.ridge_edges;
    put(constrained_out_, edge(hb.first, out_), true);
    return true;
  }

  // The reported ridge as constrained edges: each segment is an output edge,
  // or a side's chain of them.
  void mark_ridge_edges()
  {
    for(auto e : edges(out_)) put(constrained_out_, e, false);
    for(const auto& polyline : ridge_.polylines)
      for(std::size_t i = 0; i + 1 < polyline.size(); ++i)
      {
        const std::vector<out_vertex> as = rounded_vertices(polyline[i]), bs = rounded_vertices(polyline[i + 1]);
        bool found = false, same = false;
        for(const out_vertex a : as)
          for(const out_vertex b : bs)
          {
            same = same || a == b;
            if(!found && a != b) found = mark_segment(a, b);
          }
        // else a segment shorter than the rounding: nothing to mark
        if(!found && !same) ++st_.unmatched_ridge_segments;
      }
  }

  // the ridge segment between output vertices a != b, if it is an edge or a
  // side's chain
  bool mark_segment(out_vertex a, out_vertex b)
  {
    if(mark(a, b)) return true;
    const auto it = chain_of_side_.find(a < b ? std::make_pair(a, b) : std::make_pair(b, a));
    if(it == chain_of_side_.end()) return false;
    bool found = true;
    for(std::size_t j = 0; j + 1 < it->second.size(); ++j) found = mark(it->second[j], it->second[j + 1]) && found;
    return found;
  }

  const TriangleMesh& tm_;
  const Maps maps_;
  const Ridge_curve<TriangleMesh, Point>& ridge_;
  MutableFaceGraph& out_;
  const Field& field_;
  OutputPointMap vpm_out_;
  DistanceMap distance_out_;
  ConstrainedMap constrained_out_;
  Visitor visitor_;
  const Faces_by_index<TriangleMesh, typename Maps::Vertex_point_map> faces_;
  const std::size_t nf_;
  Refined_mesh_statistics st_;
  std::vector<std::vector<std::vector<Exact_barycentric> > > polygons_; // per face with several cells
  std::vector<std::vector<Q> > edge_points_; // per edge: exact t of cell corners inside it
  std::vector<out_vertex> vertex_of_mesh_vertex_;
  std::map<Exact_point_key, out_vertex> vertex_of_point_;
  std::multimap<Rounded_point_key, out_vertex> vertex_of_rounded_; // to find the ridge's points
  Coincident_points near_;                 // the output vertices' points (by creation order),
  std::vector<out_vertex> out_vertices_;   // to find those that one ridge node stands for
  std::map<out_vertex, std::pair<double, double> > value_range_; // smallest and largest value given
  std::map<std::pair<out_vertex, out_vertex>, std::vector<out_vertex> > chain_of_side_; // sides that got points
};

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
  const auto vpm_out = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                                        get_property_map(CGAL::vertex_point, out));
  const auto distance_out = choose_parameter(get_parameter(np_out, internal_np::vertex_distance_map_t()),
                                             CGAL::Constant_property_map<typename OGT::vertex_descriptor, double>(0));
  const auto constrained_out = choose_parameter(get_parameter(np_out, CGAL::internal_np::edge_is_constrained),
                                                CGAL::Constant_property_map<typename OGT::edge_descriptor, bool>(false));
  const auto visitor = choose_parameter(get_parameter(np_out, CGAL::internal_np::visitor), Default_refinement_visitor());

  if(ridge.regions.size() != num_faces(tm) || ridge.vertex_distances.size() != num_vertices(tm))
    throw Invalid_parameter_error("the ridge curve was not computed on this mesh");
  if(num_vertices(out) != 0 || num_faces(out) != 0) throw Invalid_parameter_error("the output mesh must be empty");
  const auto field = make_distance_field(tm, ridge, np_in);
  return internal::Ridge_refiner(tm, ridge, out, field, internal::mesh_maps(tm, np_in), vpm_out, distance_out,
                                 constrained_out, visitor)
      .run();
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_REFINED_MESH_H
