// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact geodesic distances by window propagation, triangle by triangle
// (Qin, Han, Yu, Yu and Zhang, "Fast and exact discrete geodesic computation
// based on triangle-oriented wavefront propagation", SIGGRAPH 2016: VTP).
//
// A window is an interval of an edge that the straight lines from one
// unfolded image of the source (or of a pseudo-source: a saddle or border
// vertex that paths bend around) reach directly. The windows waiting to enter
// a triangle through one of its edges are kept as one list on that half-edge
// and cross the triangle together; the half-edges are taken in the order of
// the smallest distance their windows can carry. A window's children on the
// two far edges are kept only if Xin and Wang's test (2009) cannot show that
// the distances already known at the triangle's three corners beat them.
// Nothing is approximated: the distances at the vertices are the shortest
// path lengths, up to floating-point rounding.
#ifndef GEODESIC_RIDGE_SOLVERS_WINDOW_PROPAGATION_SOLVER_H
#define GEODESIC_RIDGE_SOLVERS_WINDOW_PROPAGATION_SOLVER_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/face_cone_field.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/solver_from_source.h>
#include <Geodesic_ridge/internal/unfolded_mesh.h>
#include <Geodesic_ridge/source.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

/// Window propagation on the mesh's flat arrays (`Unfolded_mesh`): a window
/// on half-edge `3 f + i` enters face f.
class Window_propagation : public Unfolded_mesh
{
public:
  template <class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap>
  Window_propagation(const TriangleMesh& tm, const VertexPointMap& vpm, const VertexIndexMap& vim,
                     const FaceIndexMap& fim)
    : Unfolded_mesh(tm, vpm, vim, fim)
  {}
  /// Distances by vertex index from a source at vertex `v`.
  void from_vertex(std::size_t v, std::vector<double>& distance)
  {
    start();
    distance_[v] = 0.;
    arrival_[v] = std::numeric_limits<double>::quiet_NaN();
    emit(v, 0.);
    run(distance);
  }

  /// Distances by vertex index from point `p`, which lies in the closed
  /// triangles of faces `faces` (one face, or the two faces of its edge).
  template <class FaceRange>
  void from_point(const std::array<double, 3>& p, const FaceRange& face_indices, std::vector<double>& distance)
  {
    start();
    for(std::size_t f : face_indices)
      for(std::size_t h = 3 * f; h < 3 * f + 3; ++h)
      {
        const std::array<double, 3> u = minus(point_[corner_[next(h)]], point_[corner_[h]]);
        const std::array<double, 3> w = minus(p, point_[corner_[h]]);
        improve(corner_[h], norm(w), theta_[h] + std::atan2(norm(cross(u, w)), dot(u, w)));
        const Vec2 s = in_edge_frame(h, p);
        if(h % 3 == 0) record(Cone_record{h, false, 0., 0., s, 0.}); // the source, straight to every point of f
        if(s.y > 1e-12 * length_[h]) enter_across(h, s, 0., 0., length_[h]);
      }
    run(distance);
  }

  /// the number of windows that crossed a triangle in the last run
  std::size_t propagated_windows() const { return propagated_; }

  /// The faces (by index; none if null) whose cones the next runs keep: the
  /// windows that cross the face, its corners as pseudo-sources, the source
  /// point. `faces` must outlive the runs.
  void keep_cones(const std::vector<char>* faces) { keep_cones_ = faces; }

  /// After a run with `keep_cones`: the cones of face f, each a window
  /// (`Face_cone::entry` set: the straight way through its part of the entry
  /// edge) or a cone straight to every point of the face (a corner that
  /// paths bend around, the source), with barycentric apexes in the order of
  /// the face's corners. The lowest of their paths at a point of the face is
  /// its distance.
  template <class Output>
  void cones_of_faces(const Output& out) const
  {
    const std::size_t nf = corner_.size() / 3;
    std::vector<std::size_t> first(nf + 1, 0), order(records_.size());
    for(const Cone_record& r : records_) ++first[r.frame / 3 + 1];
    for(std::size_t f = 0; f < nf; ++f) first[f + 1] += first[f];
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(std::size_t i = 0; i < records_.size(); ++i) order[fill[records_[i].frame / 3]++] = i;
    std::vector<Face_cone> cones;
    for(std::size_t f = 0; f < nf; ++f)
    {
      cones.clear();
      for(std::size_t i = first[f]; i < first[f + 1]; ++i)
        if(consistent(records_[order[i]])) cones.push_back(face_cone(records_[order[i]]));
      out(f, cones);
    }
  }

private:

  // A window on a half-edge: the interval [b0, b1] of the edge (distance from
  // the half-edge's first corner), the unfolded image of its (pseudo-)source
  // in the half-edge's frame (first corner at the origin, edge along x, the
  // face it enters above: the image is at y <= 0), and the distance sigma
  // already travelled to that (pseudo-)source.
  struct Window
  {
    double b0, b1;
    Vec2 image;
    double sigma;
  };

  // A cone that reaches into face `frame / 3`: the image of its
  // (pseudo-)source in the frame of half-edge `frame` and its distance sigma;
  // a window enters through that half-edge in [b0, b1].
  struct Cone_record
  {
    std::size_t frame;
    bool window;
    double b0, b1;
    Vec2 image;
    double sigma;
  };

  void record(const Cone_record& r)
  {
    if(keep_cones_ && (*keep_cones_)[r.frame / 3]) records_.push_back(r);
  }

  // Whether a window agrees with the distances at its face's corners: the
  // distance is 1-Lipschitz, so at an end e of the window d(e) >= d(c) -
  // |e - c| for every corner c. A window that passed a saddle vertex on the
  // wrong side by round-off carries an unfolding into the vertex's shadow,
  // too short there (bunny_7k from vertex 1742: a window 1e-12 of an edge
  // wide at a corner of face 4148, 6e-7 below that corner's distance, whose
  // way around its end made the cone field 5e-6 too short inside the face).
  bool consistent(const Cone_record& r) const
  {
    if(!r.window) return true;
    const std::size_t h = r.frame;
    const Vec2 corner[3] = {Vec2{0., 0.}, Vec2{length_[h], 0.}, apex_[h]};
    const std::size_t index[3] = {corner_[h], corner_[next(h)], corner_[prev(h)]};
    for(double t : {r.b0, r.b1})
    {
      const Vec2 e{t, 0.};
      const double at_e = r.sigma + distance2(r.image, e);
      for(int k = 0; k < 3; ++k)
      {
        const double bound = distance_[index[k]] - distance2(e, corner[k]);
        if(at_e < bound - 1e-12 * (distance_[index[k]] + length_[h])) return false;
      }
    }
    return true;
  }

  // a record as a Face_cone of its face (barycentric in corner order)
  Face_cone face_cone(const Cone_record& r) const
  {
    const std::size_t h = r.frame;
    const int k = int(h % 3);
    Face_cone cone;
    cone.apex[(k + 2) % 3] = r.image.y / apex_[h].y;
    cone.apex[(k + 1) % 3] = (r.image.x - cone.apex[(k + 2) % 3] * apex_[h].x) / length_[h];
    cone.apex[k] = 1 - cone.apex[(k + 1) % 3] - cone.apex[(k + 2) % 3];
    cone.offset = r.sigma;
    if(r.window && r.b1 - r.b0 <= 1e-8 * length_[h])
    {
      // A window narrower than round-off allows, at a vertex: which side of
      // the vertex its straight ways pass is noise (teddy_3k from vertex 159:
      // one 2e-12 of an edge wide at a convex corner of face 2231 reached
      // points beyond the corner's ray 3e-6 too short). Its paths around its
      // middle instead: as long to within the square of its width.
      const double t = 0.5 * (r.b0 + r.b1);
      cone.apex = {{0., 0., 0.}};
      cone.apex[k] = 1 - t / length_[h];
      cone.apex[(k + 1) % 3] = t / length_[h];
      cone.offset = r.sigma + distance2(r.image, Vec2{t, 0.});
      return cone;
    }
    if(r.window)
    {
      cone.entry = static_cast<std::int8_t>(k);
      cone.through = {{r.b0 / length_[h], r.b1 / length_[h]}};
    }
    return cone;
  }

  void start()
  {
    distance_.assign(point_.size(), std::numeric_limits<double>::infinity());
    emitted_.assign(point_.size(), std::numeric_limits<double>::infinity());
    arrival_.assign(point_.size(), 0.);
    pending_.assign(corner_.size(), std::vector<Window>());
    key_.assign(corner_.size(), std::numeric_limits<double>::infinity());
    queue_ = Queue();
    propagated_ = 0;
    records_.clear();
  }

  // a path of length d reaches vertex v from the direction at angle `back`
  // around v
  void improve(std::size_t v, double d, double back)
  {
    if(!(d < distance_[v])) return;
    distance_[v] = d;
    arrival_[v] = back;
    if(kind_[v] != Vertex_kind::plain) queue_.push(Event{d, none - 1 - v});
  }

  // A window of face(h) on its half-edge h, image s in h's frame (y > 0,
  // inside face(h)): it crosses into the twin face, in whose frame the edge
  // runs the other way.
  void enter_across(std::size_t h, Vec2 s, double sigma, double t0, double t1)
  {
    const std::size_t t = twin_[h];
    if(t == none) return;
    const double L = length_[h];
    add(t, Window{L - t1, L - t0, Vec2{L - s.x, -s.y}, sigma});
  }

  void add(std::size_t h, const Window& w)
  {
    // the smallest distance the window carries
    double nearest;
    if(w.image.x < w.b0) nearest = distance2(w.image, Vec2{w.b0, 0.});
    else if(w.image.x > w.b1) nearest = distance2(w.image, Vec2{w.b1, 0.});
    else nearest = -w.image.y;
    const double key = w.sigma + nearest;
    pending_[h].push_back(w);
    if(key < key_[h])
    {
      key_[h] = key;
      queue_.push(Event{key, h});
    }
  }

  // Vertex v, reached at distance d, as a pseudo-source: a window across the
  // far edge of each face around it, limited to the directions in which a
  // path bending at v can leave. Such a path is shortest only if it turns by
  // at least pi on each side (on the surface's side at a border vertex); the
  // other directions are reached by the windows that pass v.
  void emit(std::size_t v, double d)
  {
    emitted_[v] = d;
    const double pi = std::acos(-1.), slack = 1e-9;
    const double back = arrival_[v], total = total_angle_[v];
    const bool everywhere = std::isnan(back) || kind_[v] == Vertex_kind::unordered;
    for(std::size_t k = star_begin_[v]; k < star_begin_[v + 1]; ++k)
    {
      const std::size_t h = star_[k];        // from v
      // v's cone, straight to every point of the face (in h's frame v is the origin)
      record(Cone_record{h, false, 0., 0., Vec2{0., 0.}, d});
      const double alpha = corner_angle_[h];
      // the directions to leave by, as angles from the edge h: [lo, hi]
      double lo = 0., hi = alpha;
      if(!everywhere && kind_[v] == Vertex_kind::border)
      {
        if(theta_[h] + alpha >= back + pi - slack) lo = (std::max)(0., back + pi - slack - theta_[h]);
        else if(theta_[h] <= back - pi + slack) hi = (std::min)(alpha, back - pi + slack - theta_[h]);
        else continue;
      }
      else if(!everywhere)
      {
        // turning counterclockwise from `back`, the directions in [pi, total - pi]
        const double range = total - 2 * pi + 2 * slack;
        double from = std::fmod(theta_[h] - back - pi + slack, total);
        if(from < 0) from += total;
        if(from <= range) hi = (std::min)(alpha, range - from);
        else if(from + alpha >= total) { lo = total - from; hi = (std::min)(alpha, total + range - from); }
        else continue;
      }
      const std::size_t far = next(h);       // the edge opposite v, from b to c
      improve(corner_[far], d + length_[h], theta_[far] + corner_angle_[far]);
      improve(corner_[next(far)], d + length_[prev(h)], theta_[prev(h)]);
      // where the rays from v at angles lo and hi meet the far edge (h's frame:
      // v at the origin, b on the x axis)
      const Vec2 b{length_[h], 0.}, c = apex_[h];
      const Vec2 u{(c.x - b.x) / length_[far], (c.y - b.y) / length_[far]};
      auto meet = [&](double angle) {
        const Vec2 r{std::cos(angle), std::sin(angle)};
        const double den = cross2(r, u);
        const double t = den != 0 ? -cross2(r, b) / den : 0.;
        return (std::min)((std::max)(t, 0.), length_[far]);
      };
      const double t0 = lo <= 0 ? 0. : meet(lo), t1 = hi >= alpha ? length_[far] : meet(hi);
      if(t1 > t0) enter_across(far, in_edge_frame(far, point_[v]), d, t0, t1);
    }
  }

  // Xin and Wang's test: a child window on an edge from v1 (a corner of the
  // edge it entered by) to the apex v2, with end B nearer v1 and end A nearer
  // v2, is useless if a known corner distance plus the straight way from that
  // corner beats the window at the end far from the corner: at A for v1, at B
  // for v2 (along the edge, the window loses least there), or at B for v3,
  // the other corner of the entry edge. The margin keeps a window against its
  // own rounding.
  bool useless(const Window& w, Vec2 B, Vec2 A, std::size_t v1, Vec2 p1, std::size_t v2, Vec2 p2, std::size_t v3,
               Vec2 p3) const
  {
    const double at_b = w.sigma + distance2(w.image, B), at_a = w.sigma + distance2(w.image, A);
    const double margin = 1e-12;
    return at_a > (distance_[v1] + distance2(p1, A)) * (1 + margin) ||
           at_b > (distance_[v2] + distance2(p2, B)) * (1 + margin) ||
           at_b > (distance_[v3] + distance2(p3, B)) * (1 + margin);
  }

  // The part of the edge from a to b (length len, in h's entry frame) that
  // the lines from the image through [b0, b1] reach: [lo, hi] from a.
  static bool reached(const Window& w, Vec2 a, Vec2 b, double len, double& lo, double& hi)
  {
    const Vec2 u{(b.x - a.x) / len, (b.y - a.y) / len};
    const Vec2 d0{w.b0 - w.image.x, -w.image.y}, d1{w.b1 - w.image.x, -w.image.y};
    const Vec2 as{a.x - w.image.x, a.y - w.image.y};
    lo = 0;
    hi = len;
    // right of the ray through b0: cross(d0, X - s) <= 0; left of the ray through b1: >= 0
    auto clip = [&](double alpha, double beta) { // keep alpha + beta t <= 0
      if(beta > 0) hi = (std::min)(hi, -alpha / beta);
      else if(beta < 0) lo = (std::max)(lo, -alpha / beta);
      else if(alpha > 0) hi = -1;
    };
    clip(cross2(d0, as), cross2(d0, u));
    clip(-cross2(d1, as), -cross2(d1, u));
    return hi - lo > 1e-12 * len;
  }

  // The windows waiting on h cross face(h).
  void cross_face(std::size_t h)
  {
    std::vector<Window> windows;
    windows.swap(pending_[h]);
    key_[h] = std::numeric_limits<double>::infinity();
    const std::size_t h1 = next(h), h2 = prev(h);
    const std::size_t v0 = corner_[h], v1 = corner_[h1], v2 = corner_[h2];
    const Vec2 p0{0., 0.}, p1{length_[h], 0.}, p2 = apex_[h];
    for(const Window& w : windows)
    {
      ++propagated_;
      record(Cone_record{h, true, w.b0, w.b1, w.image, w.sigma});
      // the apex
      const Vec2 d0{w.b0 - w.image.x, -w.image.y}, d1{w.b1 - w.image.x, -w.image.y};
      const Vec2 sp{p2.x - w.image.x, p2.y - w.image.y};
      // (within rounding: a vertex on a boundary ray, e.g. on the line of an
      // edge from the source, is reached by the windows on both sides)
      const double round_off = 1e-10 * (std::abs(sp.x) + std::abs(sp.y));
      if(cross2(d0, sp) <= round_off * (std::abs(d0.x) + std::abs(d0.y)) &&
         cross2(d1, sp) >= -round_off * (std::abs(d1.x) + std::abs(d1.y)))
      {
        const double d = w.sigma + distance2(w.image, p2);
        if(d < distance_[v2])
        {
          // the way back, turning counterclockwise from the edge to v0
          const Vec2 e{p0.x - p2.x, p0.y - p2.y}, back{-sp.x, -sp.y};
          const double turn = std::atan2(cross2(e, back), e.x * back.x + e.y * back.y);
          improve(v2, d, theta_[h2] + (std::min)((std::max)(turn, 0.), corner_angle_[h2]));
        }
      }
      cross_to(w, h1, v1, p1, v2, p2, false, v0, p0); // across the edge from v1 to the apex
      cross_to(w, h2, v2, p2, v0, p0, true, v1, p1);  // across the edge from the apex to v0
    }
  }

  // The child of window w on edge e of its face, from corner a to corner b
  // (at pa, pb in the entry frame), one of which is the apex; `other` is the
  // entry edge's corner not on e.
  void cross_to(const Window& w, std::size_t e, std::size_t a, Vec2 pa, std::size_t b, Vec2 pb, bool apex_first,
                std::size_t other, Vec2 po)
  {
    double lo, hi;
    if(!reached(w, pa, pb, length_[e], lo, hi)) return;
    const Vec2 u{(pb.x - pa.x) / length_[e], (pb.y - pa.y) / length_[e]};
    const Vec2 at_lo{pa.x + lo * u.x, pa.y + lo * u.y}, at_hi{pa.x + hi * u.x, pa.y + hi * u.y};
    // the test takes the end near the entry corner, then the end near the apex
    const bool dropped = apex_first ? useless(w, at_hi, at_lo, b, pb, a, pa, other, po)
                                    : useless(w, at_lo, at_hi, a, pa, b, pb, other, po);
    if(dropped) return;
    const Vec2 image{(w.image.x - pa.x) * u.x + (w.image.y - pa.y) * u.y,
                     u.x * (w.image.y - pa.y) - u.y * (w.image.x - pa.x)};
    enter_across(e, image, w.sigma, lo, hi);
  }

  void run(std::vector<double>& distance)
  {
    while(!queue_.empty())
    {
      const Event e = queue_.top();
      queue_.pop();
      if(e.what >= corner_.size() && e.what != none)
      {
        const std::size_t v = none - 1 - e.what;
        if(e.key == distance_[v] && distance_[v] < emitted_[v]) emit(v, distance_[v]);
      }
      else if(e.key == key_[e.what])
        cross_face(e.what);
    }
    distance = distance_;
  }

  // a half-edge whose windows may cross its face, or (what >= 3 F) a vertex
  // to emit as a pseudo-source, by the smallest distance it carries
  struct Event
  {
    double key;
    std::size_t what;
    bool operator>(const Event& o) const { return key > o.key; }
  };
  typedef std::priority_queue<Event, std::vector<Event>, std::greater<Event> > Queue;

  std::vector<double> distance_, emitted_, key_;
  // the direction back along the best path found to each vertex, as an angle
  // around it (NaN: from everywhere, at the source)
  std::vector<double> arrival_;
  std::vector<std::vector<Window> > pending_;
  Queue queue_;
  std::size_t propagated_ = 0;
  const std::vector<char>* keep_cones_ = nullptr;
  std::deque<Cone_record> records_; // no copies as it grows: it is the peak of memory with the cone field
};

} // namespace internal

/// \ingroup PkgGeodesicRidgeSolvers
/// Model of `GeodesicSolver`: exact distances by window propagation across
/// whole triangles (VTP, Qin et al. 2016), written for this package. Exact in
/// the sense of `Exact_solver` (CGAL's `Surface_mesh_shortest_path`): the
/// shortest path lengths on the mesh, up to floating-point rounding (within
/// 1e-9 relative of it on the test meshes). Its memory holds the wavefront
/// only, not a tree of all windows, and it is much faster on large meshes.
///
/// It offers the cone query of `Exact_solver` (the cones at sample points of
/// the faces, for the kink split and the cone ridge) and, beyond it, the
/// windows of every face (`has_windows`): with them the cone field
/// (`field(Field::cone)`) is the exact lower envelope of the windows' cones,
/// nothing sampled. Sources on a vertex, on an edge or inside a face; border
/// edges are respected (paths bend around border vertices).
struct Window_propagation_solver : internal::Solver_from_source<Window_propagation_solver>
{
  /// "vtp"
  static const char* name() { return "vtp"; }
  /// `true`: exact distances (`Geodesic_solver_traits`)
  static constexpr bool is_exact = true;
  /// `true`: the cone query of `Exact_solver` (`Geodesic_solver_traits`)
  static constexpr bool has_cones = true;
  /// `true`: the windows of the faces (`Geodesic_solver_traits`)
  static constexpr bool has_windows = true;

  using internal::Solver_from_source<Window_propagation_solver>::operator();

  /// The cone query of `Exact_solver` (on the mesh's own points): the distances, and
  /// `cones[S * i + j]`, the cone of the face of index i at its sample point
  /// j (`Cone_samples::cone_samples()`, S of them), for every face for which
  /// `wanted(i)` is true (called once the distances are written). A sample's
  /// cone is that of the window lowest there: exact at the sample.
  template <class TriangleMesh, class Source, class VertexDistanceMap, class Wanted>
  void operator()(const TriangleMesh& tm, const Source& s, VertexDistanceMap distance, std::vector<Face_cone>& cones,
                  const Wanted& wanted) const
  {
    (*this)(tm, s, distance, cones, wanted, Cone_samples::cone_samples());
  }

  /// Same, at the given sample points.
  template <class TriangleMesh, class Source, class VertexDistanceMap, class Wanted>
  void operator()(const TriangleMesh& tm, const Source& s, VertexDistanceMap distance, std::vector<Face_cone>& cones,
                  const Wanted& wanted, const std::vector<std::array<double, 3> >& samples) const
  {
    (*this)(tm, s, distance, cones, wanted, samples, nullptr);
  }

  /// Same, and with `windows` (if not null), `(*windows)[i]` the windows of
  /// every wanted face i (`Face_cone::entry` set; corners that paths bend
  /// around and the source as cones straight to every point of the face):
  /// the lowest of their paths at a point of the face is its distance. The
  /// named parameters `vertex_point_map`, `vertex_index_map` and
  /// `face_index_map` give the geometry and the indices.
  template <class TriangleMesh, class Source, class VertexDistanceMap, class Wanted,
            class NamedParameters = CGAL::parameters::Default_named_parameters>
  void operator()(const TriangleMesh& tm, const Source& s, VertexDistanceMap distance, std::vector<Face_cone>& cones,
                  const Wanted& wanted, const std::vector<std::array<double, 3> >& samples,
                  std::vector<std::vector<Face_cone> >* windows,
                  const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    const auto maps = internal::mesh_maps(tm, np);
    const auto src = make_source(tm, s, np);
    internal::Window_propagation propagation(tm, maps.vpm, maps.vim, maps.fim);
    const std::size_t S = samples.size(), nf = num_faces(tm);
    std::vector<char> want(nf, 1);
    // The windows of the cone field: every face's, in one run (its `wanted`
    // is all faces). The cones of the kink split: a first run for the
    // distances that tell the wanted faces, then a second that keeps their
    // windows only (some 60 windows cross each face of a 100k-face mesh:
    // keeping every face's costs 4 times the propagation's memory, for the
    // kink split's few faces).
    if(windows) propagation.keep_cones(&want);
    propagate(tm, src, distance, maps, propagation);
    cones.assign(S * nf, Face_cone());
    if(windows) windows->assign(nf, {});
    for(std::size_t i = 0; i < nf; ++i) want[i] = wanted(i);
    if(std::find(want.begin(), want.end(), 1) == want.end()) return;
    if(!windows)
    {
      propagation.keep_cones(&want);
      propagate(tm, src, distance, maps, propagation);
    }
    propagation.keep_cones(nullptr);
    propagation.cones_of_faces([&](std::size_t f, const std::vector<Face_cone>& face_windows) {
      if(!want[f]) return;
      const internal::Face_plane plane = propagation.plane(f);

      for(std::size_t j = 0; j < S; ++j) cones[S * f + j] = sampled_cone(plane, face_windows, samples[j]);
      if(windows) (*windows)[f] = face_windows;
    });
  }

private:
  friend struct internal::Solver_from_source<Window_propagation_solver>;
  template <class TriangleMesh, class VertexDistanceMap, class NamedParameters>
  static void run(const TriangleMesh& tm, const Geodesic_source<TriangleMesh>& src, VertexDistanceMap distance,
                  const NamedParameters& np)
  {
    const auto maps = internal::mesh_maps(tm, np);
    internal::Window_propagation propagation(tm, maps.vpm, maps.vim, maps.fim);
    propagate(tm, src, distance, maps, propagation);
  }

  template <class TriangleMesh, class VertexDistanceMap, class Maps>
  static void propagate(const TriangleMesh& tm, const Geodesic_source<TriangleMesh>& src, VertexDistanceMap distance,
                        const Maps& maps, internal::Window_propagation& propagation)
  {
    std::vector<double> d;
    if(src.kind == Geodesic_source<TriangleMesh>::ON_VERTEX)
      propagation.from_vertex(get(maps.vim, src.vertex), d);
    else
    {
      const auto q = CGAL::Polygon_mesh_processing::construct_point(src.location, tm,
                                                                    CGAL::parameters::vertex_point_map(maps.vpm));
      const std::array<double, 3> p = {CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())};
      std::vector<std::size_t> face_indices;
      for(auto g : src.faces) face_indices.push_back(get(maps.fim, g));
      propagation.from_point(p, face_indices, d);
    }
    for(auto v : vertices(tm)) put(distance, v, d[get(maps.vim, v)]);
  }

  // The cone at a sample: that of the window lowest there (its apex, or the
  // end of its part of the entry edge that the way to the sample goes around).
  static Face_cone sampled_cone(const internal::Face_plane& plane, const std::vector<Face_cone>& windows,
                                const std::array<double, 3>& sample)
  {
    const auto x = plane.point(sample);
    Face_cone best;
    best.apex = sample; // no cone reaches the face: unreachable
    best.offset = std::numeric_limits<double>::infinity();
    double lowest = std::numeric_limits<double>::infinity();
    for(const Face_cone& w : windows)
    {
      const auto path = internal::cone_path(plane, w, x);
      if(!(path.second < lowest)) continue;
      lowest = path.second;
      best.apex = plane.barycentric(path.first);
      best.offset = path.second - std::sqrt(CGAL::squared_distance(x, path.first));
    }
    return best;
  }
};

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_SOLVERS_WINDOW_PROPAGATION_SOLVER_H
