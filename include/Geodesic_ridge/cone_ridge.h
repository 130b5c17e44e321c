// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cone field of a face, and the ridge of the cone field (beyond the paper,
// exact solver).
//
// Per face copy the exact solver gives S cones (one per sample point:
// `Cone_samples::cone_samples()` for the cone field,
// `Cone_samples::cone_ridge_fallback_samples()` for the default cone ridge,
// read on the faces near kinks only; a copy split at a kink gives one copy
// per front, whose every sample has the front's cone): a point of the face
// takes, per copy, the cone of the nearest sample point, the distance in the
// face's plane to the cone's apex plus its offset; the field is the lowest
// over the copies.
//
// The cone ridge is where the cones of two fronts agree: a straight bisector
// when their offsets are equal, a branch of a hyperbola otherwise. The ridge of
// the linear field has the topology of the cut locus and lies near it (the
// planes miss the cones at second order), so the cone ridge is traced from it:
//  1. every point of a polyline moves onto the curve where the lowest cones on
//     its two sides agree: along its mesh edge, or inside its face across the
//     polyline (bisection on the difference of the two cones, which changes
//     sign between the two sides);
//  2. every junction inside a face where three fronts meet moves to the point
//     where their three cones agree (Newton's method in the face's plane);
//  3. every piece between two points of one face is split at the curve until
//     the curve is within the tolerance of its chord's midpoint.
// Points at mesh vertices, free ends, junctions on edges and points where the
// two sides do not give two different lowest copies inside the face stay where
// the linear ridge put them (counted in the statistics).
#ifndef GEODESIC_RIDGE_CONE_RIDGE_H
#define GEODESIC_RIDGE_CONE_RIDGE_H

#include <Geodesic_ridge/internal/border_loops.h>
#include <Geodesic_ridge/internal/coincident_points.h>
#include <Geodesic_ridge/internal/cone_agreement.h>
#include <Geodesic_ridge/internal/face_cone_field.h>
#include <Geodesic_ridge/internal/faces_by_index.h>
#include <Geodesic_ridge/internal/union_find.h>
#include <Geodesic_ridge/lower_envelope.h>
#include <Geodesic_ridge/ridge_curve.h>
#include <Geodesic_ridge/solvers/Face_cone.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// Counts of the cone ridge (`Ridge_curve::cone_polylines`).
struct Cone_ridge_statistics
{
  double tolerance = 0;            ///< absolute: every chord's midpoint is within this of the curve
  std::size_t points_moved = 0;    ///< points of the linear ridge moved onto the cones' curve
  std::size_t junctions_moved = 0; ///< polyline ends (junctions) moved to where their cones agree
  std::size_t points_kept = 0;     ///< at vertices, free ends, or without two fronts in the face
  std::size_t points_added = 0;    ///< inserted so that the chords follow the curve
  double largest_move = 0;         ///< the largest distance a point moved, in mean edge lengths
  /// the traced curve's graph (with the border) had other components or
  /// cycles than the linear ridge's, so the cone ridge is the linear ridge
  bool kept_linear_ridge = false;
};

namespace internal {

/// Traces the ridge of the cone field from the ridge of the linear field (see
/// the top of this file). `cones`: per face, the cones of its copies
/// (`Ridge_curve::cones` with the cone field; empty where none were read);
/// `tolerance` absolute.
template <class TriangleMesh, class VertexPointMap, class FaceIndexMap, class Point>
class Cone_ridge_tracer
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef Face_plane::Point_2 Point_2;
  typedef Face_plane::Vector_2 Vector_2;
  typedef std::array<double, 3> Bary;
  // the largest barycentric coordinate read as 0 (a few units of rounding)
  static constexpr double rounded_zero = 1e-13;

public:
  Cone_ridge_tracer(const TriangleMesh& tm, VertexPointMap vpm, FaceIndexMap fim,
                    const std::vector<std::vector<Face_cone> >& cones,
                    const std::vector<std::array<double, 3> >& samples, double tolerance, double mean_edge)
      : tm_(tm), fim_(fim), faces_(tm, vpm, fim), cones_(cones), samples_(samples), tolerance_(tolerance),
        mean_edge_(mean_edge), agree_(mean_edge)
  {}

  std::vector<std::vector<Ridge_point<Point> > > trace(std::vector<std::vector<Ridge_point<Point> > > linear,
                                                      Cone_ridge_statistics& st)
  {
    round_near_zero(linear);
    st.tolerance = tolerance_;
    // one point of the ridge, rounded in two faces, comes twice this close
    const double same_point = 1e-9 * mean_edge_;
    // A point is moved once (junctions end several polylines), and the ridge
    // keeps the linear ridge's graph: its points are told apart as there, by
    // face, coordinates and point. A point on an edge may come twice in a row,
    // once per face, rounded differently: the second follows the first.
    typedef std::tuple<std::size_t, double, double, double, double, double, double> Identity;
    auto identity = [](const Ridge_point<Point>& p) {
      return Identity(p.face, p.barycentric[0], p.barycentric[1], p.barycentric[2], CGAL::to_double(p.point.x()),
                      CGAL::to_double(p.point.y()), CGAL::to_double(p.point.z()));
    };
    std::map<Identity, Ridge_point<Point> > moved_of;
    std::map<std::array<double, 3>, Ridge_point<Point> > moved_on_edges; // by the point before the move
    // where each point moved to, and from where: two points of the linear
    // ridge must not move onto one (a mesh edge that the linear ridge crosses
    // twice, along which the face's lowest cone changes once: both would move
    // to that change, closing a cycle; the cube's ridge from a point of a face)
    std::map<std::array<double, 3>, std::array<double, 3> > moved_from;
    std::vector<std::vector<Ridge_point<Point> > > result;
    for(const auto& pl : linear)
    {
      std::vector<Ridge_point<Point> > moved(pl.size());
      for(std::size_t i = 0; i < pl.size(); ++i)
      {
        const std::array<double, 3> key = {{CGAL::to_double(pl[i].point.x()), CGAL::to_double(pl[i].point.y()),
                                            CGAL::to_double(pl[i].point.z())}};
        const Identity id = identity(pl[i]);
        if(const auto it = moved_of.find(id); it != moved_of.end())
        {
          moved[i] = it->second;
          continue;
        }
        const bool on_edge = zeros(pl[i].barycentric) == 1;
        if(const Ridge_point<Point>* twin = on_edge ? find_near(moved_on_edges, key, same_point) : nullptr)
        {
          moved[i] = in_face_of(*twin, pl[i]);
          moved_of.emplace(id, moved[i]);
          continue;
        }
        // the nearest other points before and after it
        auto same = [&](std::size_t j) { return CGAL::squared_distance(pl[j].point, pl[i].point) <= same_point * same_point; };
        std::size_t before = i, after = i;
        while(before > 0 && same(before)) --before;
        while(after + 1 < pl.size() && same(after)) ++after;
        const bool has_before = !same(before), has_after = !same(after);
        const bool end = i == 0 || i + 1 == pl.size();
        const Cone_ridge_statistics counts = st;
        if(!has_before && !has_after) moved[i] = pl[i];
        else if(end || !has_before || !has_after)
          moved[i] = move_end(pl[i], pl[has_before ? before : after].point, st);
        else
          moved[i] = move_interior(pl[i], pl[before].point, pl[after].point, st);
        const std::array<double, 3> to = {{CGAL::to_double(moved[i].point.x()), CGAL::to_double(moved[i].point.y()),
                                           CGAL::to_double(moved[i].point.z())}};
        if(find_near(moved_from, to, same_point))
        { // another point moved here first: this one stays
          moved[i] = pl[i];
          st = counts;
          ++st.points_kept;
        }
        else
          moved_from.emplace(to, key);
        moved_of.emplace(id, moved[i]);
        if(on_edge) moved_on_edges.emplace(key, moved[i]);
      }
      result.emplace_back();
      std::vector<Ridge_point<Point> >& out = result.back();
      for(std::size_t i = 0; i < moved.size(); ++i)
      {
        if(i > 0) refine(pl[i - 1], pl[i], moved[i - 1], moved[i], out, st);
        out.push_back(moved[i]);
      }
    }
    return result;
  }

  // The ridge's barycentric coordinates are rounded from exact ones: a point
  // on an edge may come with a coordinate of the order of the rounding.
  static void round_near_zero(std::vector<std::vector<Ridge_point<Point> > >& polylines)
  {
    for(auto& pl : polylines)
      for(auto& p : pl)
        for(double& b : p.barycentric)
          if(std::abs(b) <= rounded_zero) b = 0;
  }

private:
  // the entry of `points` within `distance` of `key` in every coordinate, if any
  template <class Value>
  static const Value* find_near(const std::map<std::array<double, 3>, Value>& points, const std::array<double, 3>& key,
                                double distance)
  {
    for(auto it = points.lower_bound({{key[0] - distance, -HUGE_VAL, -HUGE_VAL}});
        it != points.end() && it->first[0] <= key[0] + distance; ++it)
      if(std::abs(it->first[1] - key[1]) <= distance && std::abs(it->first[2] - key[2]) <= distance) return &it->second;
    return nullptr;
  }

  // The moved point `done` of p's twin (the same point in the face across
  // p's edge; at a vertex p stays), in p's face: the ridge's graph
  // keeps the twins apart, as the linear ridge does (the ridge along a mesh
  // edge may run on both sides of it).
  Ridge_point<Point> in_face_of(const Ridge_point<Point>& done, const Ridge_point<Point>& p) const
  {
    if(done.face == p.face) return done;
    if(zeros(p.barycentric) != 1 || zeros(done.barycentric) != 1) return p; // at a vertex: not moved
    int k = 0;
    while(p.barycentric[k] != 0) ++k;
    const auto c = faces_.corner_points(p.face);
    const auto& a = c[(k + 1) % 3];
    const auto& b = c[(k + 2) % 3];
    const double t = CGAL::to_double((done.point - a) * (b - a)) / CGAL::to_double((b - a).squared_length());
    Bary along = {{0, 0, 0}};
    along[(k + 1) % 3] = 1 - (std::min)(1.0, (std::max)(0.0, t));
    along[(k + 2) % 3] = (std::min)(1.0, (std::max)(0.0, t));
    return make_point(p, p.face, along);
  }

  Face_plane plane_of(std::size_t f) const { return Face_plane(faces_.corner_points(f)); }

  Face_cone_field field_of(std::size_t f) const
  {
    return Face_cone_field(plane_of(f), cones_[f].data(), cones_[f].size(), samples_);
  }

  // the plane vector, in face f, of a 3D vector given in 3D (projected)
  Vector_2 direction_in_face(std::size_t f, const Point& from, const Point& to) const
  {
    typedef CGAL::Epick::Vector_3 Vector;
    const auto p = faces_.corner_points(f);
    auto vec = [](const Point& a, const Point& b) {
      return Vector(CGAL::to_double(b.x() - a.x()), CGAL::to_double(b.y() - a.y()), CGAL::to_double(b.z() - a.z()));
    };
    const Vector e1 = vec(p[0], p[1]), e2 = vec(p[0], p[2]), t = vec(from, to);
    const Vector ex = e1 / std::sqrt(e1.squared_length());
    Vector ey = e2 - (e2 * ex) * ex;
    ey = ey / std::sqrt(ey.squared_length());
    return Vector_2(t * ex, t * ey);
  }

  Ridge_point<Point> make_point(const Ridge_point<Point>& like, std::size_t f, const Bary& b) const
  {
    Ridge_point<Point> p = like;
    p.face = f;
    p.barycentric = b;
    const auto c = faces_.corner_points(f);
    p.point = barycentric_to_point(b, c[0], c[1], c[2]);
    return p;
  }

  void count_move(const Ridge_point<Point>& from, const Ridge_point<Point>& to, Cone_ridge_statistics& st) const
  {
    st.largest_move = (std::max)(st.largest_move, std::sqrt(CGAL::to_double(CGAL::squared_distance(from.point, to.point))) / mean_edge_);
  }

  // the number of zero barycentric coordinates (1: on an edge, 2: at a vertex)
  static int zeros(const Bary& b) { return int(b[0] == 0) + int(b[1] == 0) + int(b[2] == 0); }

  Ridge_point<Point> move_interior(const Ridge_point<Point>& p, const Point& prev, const Point& next,
                                   Cone_ridge_statistics& st) const
  {
    const int z = zeros(p.barycentric);
    if(z >= 2) { ++st.points_kept; return p; }
    const Face_cone_field field = field_of(p.face);
    const Face_plane& plane = field.plane();
    const Point_2 x0 = plane.point(p.barycentric);
    const double reach = 0.5 * (std::min)(std::sqrt(CGAL::to_double(CGAL::squared_distance(p.point, prev))),
                                          std::sqrt(CGAL::to_double(CGAL::squared_distance(p.point, next))));
    Vector_2 d;
    if(z == 1)
    {
      // along the edge the point lies on
      int k = 0;
      while(p.barycentric[k] != 0) ++k;
      d = plane.corner((k + 2) % 3) - plane.corner((k + 1) % 3);
    }
    else
      d = direction_in_face(p.face, prev, next).perpendicular(CGAL::COUNTERCLOCKWISE);
    const double n = std::sqrt(d.squared_length());
    if(!(n > 0)) { ++st.points_kept; return p; }
    d = d / n;
    Bary w = plane.barycentric(d);
    for(int k = 0; k < 3; ++k)
      if(p.barycentric[k] == 0) w[k] = 0; // along its edge
    const Bary minus_w = {{-w[0], -w[1], -w[2]}};
    const double hi = (std::min)(reach, Cone_agreement::room(p.barycentric, w, 0.999)),
                 lo = -(std::min)(reach, Cone_agreement::room(p.barycentric, minus_w, 0.999));
    Point_2 root;
    bool found = hi > 0 && lo < 0 && agree_.bisect(field, x0, d, lo, hi, root);
    if(!found)
    {
      // the cones' curve lies farther than the linear ridge's neighbours: look
      // up to half an edge away
      const double far = 0.5 * mean_edge_;
      found = agree_.bisect(field, x0, d, -(std::min)(far, Cone_agreement::room(p.barycentric, minus_w, 0.999)),
                     (std::min)(far, Cone_agreement::room(p.barycentric, w, 0.999)), root);
    }
    if(!found) { ++st.points_kept; return p; }
    Bary b = plane.barycentric(root);
    if(z == 1)
    {
      // exactly on the edge
      int k = 0;
      while(p.barycentric[k] != 0) ++k;
      const double t = b[(k + 2) % 3] / (b[(k + 1) % 3] + b[(k + 2) % 3]);
      b[k] = 0;
      b[(k + 1) % 3] = 1 - t;
      b[(k + 2) % 3] = t;
    }
    const Ridge_point<Point> q = make_point(p, p.face, b);
    count_move(p, q, st);
    ++st.points_moved;
    return q;
  }

  // A junction inside a face where exactly three copies are lowest around it
  // moves to where their three cones agree; every other end stays.
  Ridge_point<Point> move_end(const Ridge_point<Point>& p, const Point& neighbour, Cone_ridge_statistics& st) const
  {
    // on an edge: where the lowest copy of the face changes along the edge
    // (there the ridge that runs into the face meets the one along the edge)
    if(zeros(p.barycentric) == 1)
    {
      const std::size_t moved = st.points_moved;
      const Ridge_point<Point> q = move_interior(p, neighbour, neighbour, st);
      if(st.points_moved > moved) { --st.points_moved; ++st.junctions_moved; }
      return q;
    }
    if(zeros(p.barycentric) != 0) { ++st.points_kept; return p; }
    const Face_cone_field field = field_of(p.face);
    const Face_plane& plane = field.plane();
    const Point_2 start = plane.point(p.barycentric);
    const double r = 0.25 * std::sqrt(CGAL::to_double(CGAL::squared_distance(p.point, neighbour)));
    const std::set<std::size_t> around = Cone_agreement::copies_around(field, start, r);
    if(around.size() != 3) { ++st.points_kept; return p; }
    const std::vector<std::size_t> c(around.begin(), around.end());
    Point_2 x = start;
    const bool converged = agree_.where_three_cones_agree(field, c, x);
    const Bary b = plane.barycentric(x);
    const bool inside = b[0] > 0 && b[1] > 0 && b[2] > 0;
    const double moved = std::sqrt(CGAL::squared_distance(x, start));
    const auto best = field.lowest(x);
    const double va = field.value(c[0], x);
    if(!converged || !inside || moved > 2 * r ||
       !(best.first == c[0] || best.first == c[1] || best.first == c[2] || best.second >= va - 1e-12 * (va + mean_edge_)))
    {
      ++st.points_kept;
      return p;
    }
    const Ridge_point<Point> q = make_point(p, p.face, b);
    count_move(p, q, st);
    ++st.junctions_moved;
    return q;
  }

  // The faces that hold a point: its face, the face across its edge, or the
  // faces around its vertex.
  std::vector<std::size_t> faces_holding(const Ridge_point<Point>& p) const
  {
    const auto h = faces_.corner_halfedges(p.face);
    const int z = zeros(p.barycentric);
    std::vector<std::size_t> result{p.face};
    if(z == 1)
    {
      int k = 0;
      while(p.barycentric[k] != 0) ++k;
      const auto g = face(opposite(h[(k + 1) % 3], tm_), tm_);
      if(g != GT::null_face()) result.push_back(static_cast<std::size_t>(get(fim_, g)));
    }
    else if(z == 2)
    {
      int k = 0;
      while(p.barycentric[k] == 0) ++k;
      result.clear();
      for(face_descriptor g : CGAL::faces_around_target(h[(k + 2) % 3], tm_))
        if(g != GT::null_face()) result.push_back(static_cast<std::size_t>(get(fim_, g)));
    }
    return result;
  }

  // the barycentric coordinates of p in face g, which holds it
  Bary barycentric_in(const Ridge_point<Point>& p, std::size_t g) const
  {
    if(g == p.face) return p.barycentric;
    const auto hp = faces_.corner_halfedges(p.face), hg = faces_.corner_halfedges(g);
    Bary b = {{0, 0, 0}};
    for(int k = 0; k < 3; ++k)
      if(p.barycentric[k] != 0)
        for(int j = 0; j < 3; ++j)
          if(source(hg[j], tm_) == source(hp[k], tm_)) b[j] = p.barycentric[k];
    return b;
  }

  // Splits the piece from a to b (moved from la, lb) at the curve until the
  // curve is within the tolerance of every chord's midpoint; appends the
  // points strictly between a and b.
  void refine(const Ridge_point<Point>& la, const Ridge_point<Point>& lb, const Ridge_point<Point>& a,
              const Ridge_point<Point>& b, std::vector<Ridge_point<Point> >& out, Cone_ridge_statistics& st) const
  {
    const std::vector<std::size_t> fa = faces_holding(la), fb = faces_holding(lb);
    std::vector<std::size_t> common;
    for(std::size_t f : fa)
      if(std::find(fb.begin(), fb.end(), f) != fb.end()) common.push_back(f);
    if(common.size() != 1) return; // along a mesh edge, or not in one face
    const std::size_t f = common[0];
    const Face_cone_field field = field_of(f);
    split(field, f, a, barycentric_in(a, f), barycentric_in(b, f), out, st, 0);
  }

  void split(const Face_cone_field& field, std::size_t f, const Ridge_point<Point>& like, const Bary& ba,
             const Bary& bb, std::vector<Ridge_point<Point> >& out, Cone_ridge_statistics& st, int depth) const
  {
    const Face_plane& plane = field.plane();
    const Point_2 xa = plane.point(ba), xb = plane.point(bb);
    const double len = std::sqrt(CGAL::squared_distance(xa, xb));
    if(depth >= 12 || !(len > 2 * tolerance_)) return;
    const Point_2 m = CGAL::midpoint(xa, xb);
    const Vector_2 d = (xb - xa).perpendicular(CGAL::COUNTERCLOCKWISE) / len;
    const Bary bm = {{0.5 * (ba[0] + bb[0]), 0.5 * (ba[1] + bb[1]), 0.5 * (ba[2] + bb[2])}};
    const Bary w = plane.barycentric(d);
    const Bary minus_w = {{-w[0], -w[1], -w[2]}};
    const double hi = (std::min)(0.5 * len, Cone_agreement::room(bm, w, 0.999)), lo = -(std::min)(0.5 * len, Cone_agreement::room(bm, minus_w, 0.999));
    Point_2 root;
    if(!(hi > 0 && lo < 0)) return;
    if(!agree_.bisect(field, m, d, lo, hi, root)) return;
    if(CGAL::squared_distance(root, m) <= tolerance_ * tolerance_) return;
    const Bary br = plane.barycentric(root);
    split(field, f, like, ba, br, out, st, depth + 1);
    Ridge_point<Point> r = make_point(like, f, br);
    out.push_back(r);
    ++st.points_added;
    split(field, f, like, br, bb, out, st, depth + 1);
  }

  const TriangleMesh& tm_;
  FaceIndexMap fim_;
  Faces_by_index<TriangleMesh, VertexPointMap> faces_;
  const std::vector<std::vector<Face_cone> >& cones_;
  const std::vector<std::array<double, 3> >& samples_;
  double tolerance_, mean_edge_;
  Cone_agreement agree_;
};

// The components and independent cycles of the graph of `polylines` with the
// border loops of `tm` as nodes (a point on a border edge or at a border
// vertex is joined to its loop); points within `coincident_tolerance` of one
// another are one node, as a reader of the written polylines sees them.
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap, class Point>
std::pair<std::size_t, std::size_t> ridge_graph_with_border(const TriangleMesh& tm, VertexPointMap vpm,
                                                            VertexIndexMap vim, FaceIndexMap fim,
                                                            const std::vector<std::vector<Ridge_point<Point> > >& polylines)
{
  const Faces_by_index<TriangleMesh, VertexPointMap> faces(tm, vpm, fim);
  const Border_loops loops = border_loops(tm, vim);
  // nodes: the loops (their numbers), then the ridge points
  Coincident_points id(coincident_tolerance(tm, vpm));
  std::size_t points = 0;
  const std::size_t first_point = num_vertices(tm);
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  std::set<std::pair<std::size_t, std::size_t> > border_links; // (a point seen twice is linked once)
  auto node = [&](const Ridge_point<Point>& p) {
    const std::array<double, 3> xyz = {{CGAL::to_double(p.point.x()), CGAL::to_double(p.point.y()),
                                        CGAL::to_double(p.point.z())}};
    const std::size_t same = id.find(xyz);
    const std::size_t n = same != Coincident_points::none ? same : first_point + points++;
    if(same == Coincident_points::none) id.insert(n, xyz);
    const auto h = faces.corner_halfedges(p.face);
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t v = get(vim, source(h[k], tm));
      if((p.barycentric[k] == 1 && loops.on_border(v)) ||
         (p.barycentric[(k + 2) % 3] == 0 && is_border(opposite(h[k], tm), tm)))
      {
        border_links.emplace(n, loops.loop_of_vertex[v]);
        break;
      }
    }
    return n;
  };
  for(const auto& pl : polylines)
    for(std::size_t i = 0; i + 1 < pl.size(); ++i)
    {
      const std::size_t a = node(pl[i]), b = node(pl[i + 1]);
      if(a != b) edges.emplace_back(a, b);
    }
  edges.insert(edges.end(), border_links.begin(), border_links.end());
  Union_find graph(first_point + points);
  std::set<std::size_t> nodes;
  for(std::size_t i = 0; i < points; ++i) nodes.insert(first_point + i);
  for(const auto& e : edges)
  {
    nodes.insert(e.second);
    graph.unite(e.first, e.second);
  }
  std::set<std::size_t> roots;
  for(std::size_t n : nodes) roots.insert(graph.find(n));
  return {roots.size(), edges.size() + roots.size() - nodes.size()};
}

/// The cone ridge traced from the linear ridge `linear`.
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap, class Point>
std::vector<std::vector<Ridge_point<Point> > >
trace_cone_ridge(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim, FaceIndexMap fim,
                 const std::vector<std::vector<Ridge_point<Point> > >& linear,
                 const std::vector<std::vector<Face_cone> >& cones,
                 const std::vector<std::array<double, 3> >& samples, double tolerance, double mean_edge,
                 Cone_ridge_statistics& st)
{
  Cone_ridge_tracer<TriangleMesh, VertexPointMap, FaceIndexMap, Point> tracer(tm, vpm, fim, cones, samples, tolerance,
                                                                              mean_edge);
  auto traced = tracer.trace(linear, st);
  // the cone ridge keeps the linear ridge's graph, or it is the linear ridge
  // (compared with the linear ridge as it is reported: a point rounded onto
  // a border edge that the comparison counts there makes the linear ridge
  // reported, never a wrong graph)
  if(ridge_graph_with_border(tm, vpm, vim, fim, traced) != ridge_graph_with_border(tm, vpm, vim, fim, linear))
  {
    st = Cone_ridge_statistics();
    st.tolerance = tolerance;
    st.kept_linear_ridge = true;
    return linear;
  }
  return traced;
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_CONE_RIDGE_H
