// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The measure of correctness (user manual, "How Accuracy Is Measured"), for
// tests and benchmarks:
//
//  * `reference_ridge()`: the EXACT ridge of a source, sampled, from CGAL's
//    Surface_mesh_shortest_path (SMSP). x is on the exact ridge iff the arrival
//    direction of exact shortest paths is discontinuous at x.
//  * `ridge_accuracy()`: precision (computed ridge -> reference) and recall
//    (major reference ridge -> computed ridge), in mean edge lengths.
//
// Method (see reference_ridge() for the details and the reasons):
//  1. Every face is split into n x n congruent sub-triangles (n per face, from
//     its longest edge and the target spacing, default 0.15 mean edge); one
//     sample at each sub-triangle's centroid. Neighbouring samples are those of
//     sub-triangles sharing a side, inside a face and across mesh edges.
//  2. At every sample x, one SMSP path query, stopped at the end of the path's
//     LAST STRAIGHT LEG (at the first vertex it passes through, i.e. a
//     pseudo-source, or at the source). That leg gives, exactly, the arrival
//     direction u(x), the straight-line length rho(x) of the leg, and the
//     distance sigma(x) at its start (the pseudo-source's exact distance, or 0).
//     In the plane of x's face the front that reaches x is the cone field
//     d(y) = sigma + |y - S|, S = x - rho u (the unfolded (pseudo-)source image).
//  3. For two neighbouring samples a, b (b unfolded into a's face plane across
//     the shared edge) a ridge lies between them iff each one's front reaches
//     the other one later than its own front does: d_a(b) > d(b) and
//     d_b(a) > d(a) (one of them may be an equality: a sample on the ridge). Samples of one front (one sheet) have the same S and sigma,
//     so both differences are 0 up to round-off; the shadow boundary of a
//     saddle vertex (where the direction turns fast but continuously) fails the
//     test because the straight front underestimates past the vertex.
//  4. The reference point is the exact crossing d_a = d_b on the segment ab
//     (bisection), and its jump angle is the angle between the two arrival
//     directions there, (x - S_a) and (x - S_b). Points below a minimum jump
//     (default 2 degrees) and within `source_exclusion` mean edges of the source
//     (Euclidean) are dropped.
//
// Meshes with boundary (any number of boundary loops) are supported: no pair is
// formed across a border edge (there is no face beyond it; `border_edges`
// counts them); a shortest path bending at a boundary vertex of inner angle > pi
// stops the last-leg walk there like a saddle vertex does (its exact distance is
// the offset sigma); the shadow line of such a vertex fails the two-front test
// for the same reason as a saddle's. Near the boundary the ridge is sampled up
// to the last row of samples, about spacing / 2 from the border edge. A source
// on the boundary works: a vertex as is, a point of an edge (border or not)
// moved into its face first (see `reference_ridge()` for a surface point).
//
// This uses SMSP's public interface only (`shortest_path_sequence_to_source_points`
// with a visitor). Finite differences of `shortest_distance_to_source_points`
// were rejected: next to the ridge a difference stencil straddles two fronts and
// returns a mixed gradient, so the jump is smeared over the stencil width and the
// position is known only to the spacing; it also costs three queries per sample.
#ifndef GEODESIC_RIDGE_TEST_SUPPORT_REFERENCE_RIDGE_H
#define GEODESIC_RIDGE_TEST_SUPPORT_REFERENCE_RIDGE_H

#include <Geodesic_ridge/ridge_curve.h>

#include <Geodesic_ridge/internal/smsp_source_coordinates.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/property_map.h>
#include <CGAL/version_macros.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <iterator>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace testing {

/// How the reference ridge is sampled.
struct Reference_ridge_options
{
  double spacing = 0.15;         ///< target distance between neighbouring samples, in mean edge lengths
  int subdivisions = 0;          ///< > 0: this many subdivisions per face edge everywhere (overrides spacing)
  int max_subdivisions = 16;     ///< cap per face (long thin faces)
  /// keep reference points whose direction jump is at least this. Every vertex of
  /// positive curvature casts a ridge branch (jump = about its angle deficit) that
  /// the tolerance may keep: measured, computed leaf branches follow 2-5 degree
  /// ridges (torus_1k), while below ~1 degree such lines cover the surface every
  /// 1-2 edges and any curve would look precise.
  double min_jump_degrees = 2;
  double source_exclusion = 1.0; ///< drop points closer than this (mean edges, Euclidean) to the source
};

/// The sampled exact ridge.
template <class Point_3>
struct Reference_ridge
{
  std::vector<Point_3> points;      ///< points on the exact ridge
  std::vector<double> jump_degrees; ///< angle between the two arrival directions there
  std::vector<std::size_t> faces;   ///< face index holding each point
  std::vector<double> distances;    ///< geodesic distance there (both fronts agree), for self-checks
  Point_3 source;
  double mean_edge = 0;
  std::size_t samples = 0;          ///< SMSP queries
  std::size_t failed_samples = 0;   ///< queries with no path (disconnected) or a degenerate leg
  std::size_t pairs = 0;            ///< neighbouring sample pairs tested
  std::size_t crossings = 0;        ///< pairs with two fronts (before the jump / source filters)
  std::size_t border_edges = 0;     ///< edges with one face: no pair is formed across them
  double time_solve = 0, time_queries = 0, time_total = 0; ///< seconds
};

namespace internal {

typedef std::array<double, 3> V3;
inline V3 v_sub(const V3& a, const V3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline V3 v_add(const V3& a, const V3& b) { return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}}; }
inline V3 v_mul(const V3& a, double s) { return {{a[0] * s, a[1] * s, a[2] * s}}; }
inline double v_dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double v_norm(const V3& a) { return std::sqrt(v_dot(a, a)); }
inline V3 v_unit(const V3& a) { const double n = v_norm(a); return n > 0 ? v_mul(a, 1 / n) : a; }
inline double v_angle_degrees(const V3& a, const V3& b)
{
  const double na = v_norm(a), nb = v_norm(b);
  if(na == 0 || nb == 0) return 0;
  // atan2 of |a x b| and a.b: accurate for small and large angles
  const V3 c = {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
  return std::atan2(v_norm(c), v_dot(a, b)) * 180.0 / 3.14159265358979323846;
}
template <class P> V3 to_v3(const P& p) { return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}}; }

// Sub-triangle layout of a face split n x n: "up" sub-triangle (i, j) has lattice
// corners (i,j), (i+1,j), (i,j+1); "down" (i, j) has (i+1,j), (i,j+1), (i+1,j+1),
// where lattice point (i, j) has barycentric coordinates (1 - (i+j)/n, i/n, j/n)
// in CGAL's corner order. Samples are the sub-triangles' centroids.
struct Face_lattice
{
  int n = 0;
  std::vector<std::array<double, 2> > uv;   // centroid: weights of corners 1 and 2
  std::vector<std::array<int, 2> > pairs;   // neighbouring sub-triangles inside the face
  std::array<std::vector<int>, 3> boundary; // [k][m]: sub-triangle on side k at slot m
                                            // (side k runs from corner k to corner k+1,
                                            //  slot m centred at parameter (m + 0.5) / n)
  explicit Face_lattice(int n_) : n(n_)
  {
    std::vector<std::vector<int> > up(n, std::vector<int>(n, -1)), down(n, std::vector<int>(n, -1));
    for(int j = 0; j < n; ++j)
      for(int i = 0; i + j <= n - 1; ++i)
      {
        up[i][j] = int(uv.size());
        uv.push_back({{(3.0 * i + 1) / (3.0 * n), (3.0 * j + 1) / (3.0 * n)}});
      }
    for(int j = 0; j < n; ++j)
      for(int i = 0; i + j <= n - 2; ++i)
      {
        down[i][j] = int(uv.size());
        uv.push_back({{(3.0 * i + 2) / (3.0 * n), (3.0 * j + 2) / (3.0 * n)}});
        pairs.push_back({{down[i][j], up[i][j]}});
        pairs.push_back({{down[i][j], up[i + 1][j]}});
        pairs.push_back({{down[i][j], up[i][j + 1]}});
      }
    for(int m = 0; m < n; ++m)
    {
      boundary[0].push_back(up[m][0]);             // corner 0 -> 1 (j = 0)
      boundary[1].push_back(up[n - 1 - m][m]);     // corner 1 -> 2 (i + j = n - 1)
      boundary[2].push_back(up[0][n - 1 - m]);     // corner 2 -> 0 (i = 0)
    }
  }
};

// One sample: its point, the arrival direction (unit, in its face's plane),
// the length rho of the path's last straight leg and the distance sigma at
// the leg's start. Its front near it is d(y) = sigma + |y - (x - rho u)|.
struct Ridge_sample
{
  V3 x = {{0, 0, 0}}, u = {{0, 0, 0}};
  double rho = 0, sigma = 0;
  bool ok = false;
  V3 image() const { return v_sub(x, v_mul(u, rho)); }
  double distance() const { return sigma + rho; }
};

// SMSP visitor: records the query point, then walks the path back until the
// first vertex (a pseudo-source, or the source vertex) or the source point, and
// stops there by throwing (the rest of the path is not needed).
template <class SMSP, class Graph>
struct Last_leg_visitor
{
  typedef typename boost::graph_traits<Graph>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Graph>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<Graph>::face_descriptor face_descriptor;
  struct Stop {};

  const SMSP& sp;
  const std::vector<double>& vertex_distance; // by vertex index
  const Graph& g;
  int events = 0;
  V3 query = {{0, 0, 0}}, first = {{0, 0, 0}}, last = {{0, 0, 0}};
  double length = 0, sigma = 0;
  bool finished = false;

  Last_leg_visitor(const SMSP& s, const std::vector<double>& vd, const Graph& gr)
    : sp(s), vertex_distance(vd), g(gr) {}

  void step(const V3& p)
  {
    if(events == 1) first = p;
    length += v_norm(v_sub(p, last));
    last = p;
    ++events;
  }
  void operator()(halfedge_descriptor h, typename SMSP::FT t) { step(to_v3(sp.point(h, t))); }
  void operator()(vertex_descriptor v)
  {
    step(to_v3(sp.point(v)));
    sigma = vertex_distance[static_cast<std::size_t>(get(CGAL::vertex_index, g, v))];
    finished = true;
    throw Stop();
  }
  void operator()(face_descriptor f, const typename SMSP::Barycentric_coordinates& b)
  {
    if(events == 0) { query = last = to_v3(sp.point(f, b)); ++events; return; }
    step(to_v3(sp.point(f, b))); // the source point: the end of the path
    sigma = 0;
    finished = true;
  }
};

template <class Graph>
struct Face_frame_helper
{
  typedef boost::graph_traits<Graph> GT;
  static std::array<typename GT::halfedge_descriptor, 3> halfedges(typename GT::face_descriptor f, const Graph& g)
  {
    const auto h0 = halfedge(f, g);
    return {{h0, next(h0, g), next(next(h0, g), g)}};
  }
};

template <class SMSP, class TriangleMesh>
Reference_ridge<typename boost::property_traits<typename boost::property_map<
    TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>
reference_ridge_impl(const TriangleMesh& tm, SMSP& sp, const std::array<double, 3>& source_point,
                     const Reference_ridge_options& opt, double time_start_offset)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<typename boost::property_map<
      TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type Point_3;
  const auto vpm = get(CGAL::vertex_point, tm);
  auto seconds_since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };

  Reference_ridge<Point_3> R;
  R.source = Point_3(source_point[0], source_point[1], source_point[2]);
  R.time_solve = time_start_offset;
  const auto t_start = std::chrono::steady_clock::now();

  double L = 0;
  for(auto e : edges(tm)) L += v_norm(v_sub(to_v3(get(vpm, source(e, tm))), to_v3(get(vpm, target(e, tm)))));
  L /= std::max<double>(1, double(num_edges(tm)));
  R.mean_edge = L;

  auto t0 = std::chrono::steady_clock::now();
  sp.build_sequence_tree();
  std::vector<double> vertex_distance(num_vertices(tm), 0);
  for(auto v : vertices(tm))
    vertex_distance[static_cast<std::size_t>(get(CGAL::vertex_index, tm, v))] =
        CGAL::to_double(sp.shortest_distance_to_source_points(v).first);
  R.time_solve += seconds_since(t0);

  // ---- sampling layout
  const std::size_t nf = num_faces(tm);
  std::vector<face_descriptor> face_of(nf);
  for(face_descriptor f : faces(tm)) face_of[static_cast<std::size_t>(get(CGAL::face_index, tm, f))] = f;
  std::vector<int> sub(nf);
  std::vector<std::size_t> first_sample(nf + 1, 0);
  std::map<int, Face_lattice> lattices;
  for(std::size_t fi = 0; fi < nf; ++fi)
  {
    int n = opt.subdivisions;
    if(n <= 0)
    {
      double longest = 0;
      for(auto h : Face_frame_helper<TriangleMesh>::halfedges(face_of[fi], tm))
        longest = std::max(longest, v_norm(v_sub(to_v3(get(vpm, source(h, tm))), to_v3(get(vpm, target(h, tm))))));
      // centroids of neighbouring sub-triangles of an equilateral face of side s are s / (n sqrt 3) apart
      n = int(std::ceil(longest / (std::sqrt(3.0) * opt.spacing * L)));
    }
    n = std::max(1, std::min(n, std::max(1, opt.max_subdivisions)));
    sub[fi] = n;
    if(!lattices.count(n)) lattices.emplace(n, Face_lattice(n));
    first_sample[fi + 1] = first_sample[fi] + std::size_t(n) * std::size_t(n);
  }

  // ---- one SMSP query per sample
  t0 = std::chrono::steady_clock::now();
  std::vector<Ridge_sample> S(first_sample[nf]);
  R.samples = S.size();
  for(std::size_t fi = 0; fi < nf; ++fi)
  {
    const Face_lattice& lat = lattices.at(sub[fi]);
    for(std::size_t k = 0; k < lat.uv.size(); ++k)
    {
      const double u = lat.uv[k][0], v = lat.uv[k][1];
      const typename SMSP::Barycentric_coordinates b = {{1 - u - v, u, v}};
      Last_leg_visitor<SMSP, TriangleMesh> vis(sp, vertex_distance, tm);
      try { sp.shortest_path_sequence_to_source_points(face_of[fi], b, vis); }
      catch(const typename Last_leg_visitor<SMSP, TriangleMesh>::Stop&) {}
      Ridge_sample& s = S[first_sample[fi] + k];
      s.x = vis.query;
      if(vis.finished && vis.events >= 2)
      {
        const V3 d = v_sub(vis.query, vis.first);
        if(v_norm(d) > 1e-12 * L)
        {
          s.u = v_unit(d);
          s.rho = vis.length;
          s.sigma = vis.sigma;
          s.ok = true;
        }
      }
      if(!s.ok) ++R.failed_samples;
    }
  }
  R.time_queries = seconds_since(t0);

  // ---- the two-front test on a pair, b given in a's face plane (b_x, b_u, b_image unfolded)
  const double eps = 1e-9 * L;
  auto test_pair = [&](const Ridge_sample& a, const V3& bx, const V3& bS, double b_sigma, double b_dist,
                       V3& x_out, double& jump_out, double& dist_out) {
    const V3 aS = a.image();
    const double a_at_b = a.sigma + v_norm(v_sub(bx, aS)); // a's front at b
    const double b_at_a = b_sigma + v_norm(v_sub(a.x, bS)); // b's front at a
    // strictly later on at least one side, not earlier on either: a sample lying
    // exactly on the ridge (symmetric meshes put whole rows of samples there) has
    // both fronts at once, and is found from its neighbours on the other side
    const double gap_b = a_at_b - b_dist, gap_a = b_at_a - a.distance();
    if(!(gap_a >= -eps && gap_b >= -eps && std::max(gap_a, gap_b) > eps)) return false;
    // crossing of the two fronts on [a, b]: f(0) < 0 < f(1)
    auto f = [&](double t) {
      const V3 y = v_add(a.x, v_mul(v_sub(bx, a.x), t));
      return (a.sigma + v_norm(v_sub(y, aS))) - (b_sigma + v_norm(v_sub(y, bS)));
    };
    double lo = 0, hi = 1;
    for(int it = 0; it < 48; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      (f(mid) < 0 ? lo : hi) = mid;
    }
    x_out = v_add(a.x, v_mul(v_sub(bx, a.x), 0.5 * (lo + hi)));
    jump_out = v_angle_degrees(v_sub(x_out, aS), v_sub(x_out, bS));
    dist_out = a.sigma + v_norm(v_sub(x_out, aS));
    return true;
  };
  const V3 src = source_point;
  auto record = [&](const V3& x, double jump, double dist, std::size_t face) {
    ++R.crossings;
    if(jump < opt.min_jump_degrees) return;
    if(v_norm(v_sub(x, src)) < opt.source_exclusion * L) return;
    R.points.push_back(Point_3(x[0], x[1], x[2]));
    R.jump_degrees.push_back(jump);
    R.faces.push_back(face);
    R.distances.push_back(dist);
  };

  // pairs inside faces
  for(std::size_t fi = 0; fi < nf; ++fi)
  {
    const Face_lattice& lat = lattices.at(sub[fi]);
    for(const auto& p : lat.pairs)
    {
      const Ridge_sample& a = S[first_sample[fi] + std::size_t(p[0])];
      const Ridge_sample& b = S[first_sample[fi] + std::size_t(p[1])];
      if(!a.ok || !b.ok) continue;
      ++R.pairs;
      V3 x; double jump, dist;
      if(test_pair(a, b.x, b.image(), b.sigma, b.distance(), x, jump, dist)) record(x, jump, dist, fi);
    }
  }

  // pairs across edges: b (in face g) is unfolded into the plane of a's face f
  // by the rotation about the shared edge
  for(auto e : edges(tm))
  {
    const halfedge_descriptor h = halfedge(e, tm), ho = opposite(h, tm);
    if(is_border(h, tm) || is_border(ho, tm)) { ++R.border_edges; continue; }
    const std::size_t fi = static_cast<std::size_t>(get(CGAL::face_index, tm, face(h, tm)));
    const std::size_t gi = static_cast<std::size_t>(get(CGAL::face_index, tm, face(ho, tm)));
    auto side_of = [&](std::size_t fidx, halfedge_descriptor hh) {
      const auto hs = Face_frame_helper<TriangleMesh>::halfedges(face_of[fidx], tm);
      for(int k = 0; k < 3; ++k) if(hs[k] == hh) return k;
      return -1;
    };
    const int kf = side_of(fi, h), kg = side_of(gi, ho);
    if(kf < 0 || kg < 0) continue;
    const V3 P = to_v3(get(vpm, source(h, tm))), Q = to_v3(get(vpm, target(h, tm)));
    const V3 cf = to_v3(get(vpm, target(next(h, tm), tm))), cg = to_v3(get(vpm, target(next(ho, tm), tm)));
    const V3 E = v_unit(v_sub(Q, P));
    const V3 nf_in = v_unit(v_sub(v_sub(cf, P), v_mul(E, v_dot(v_sub(cf, P), E))));
    const V3 ng_in = v_unit(v_sub(v_sub(cg, P), v_mul(E, v_dot(v_sub(cg, P), E))));
    // g's plane -> f's plane (points relative to P, and vectors)
    auto unfold_vec = [&](const V3& w) { return v_sub(v_mul(E, v_dot(w, E)), v_mul(nf_in, v_dot(w, ng_in))); };
    auto unfold_pt = [&](const V3& y) { return v_add(P, unfold_vec(v_sub(y, P))); };
    // f's plane -> the surface: points past the edge fold back into g
    auto fold_pt = [&](const V3& y, std::size_t& face_out) {
      const V3 w = v_sub(y, P);
      const double beta = v_dot(w, nf_in);
      face_out = fi;
      if(beta >= 0) return y;
      face_out = gi;
      return v_add(P, v_add(v_mul(E, v_dot(w, E)), v_mul(ng_in, -beta)));
    };
    const int n_f = sub[fi], n_g = sub[gi];
    const Face_lattice& lf = lattices.at(n_f);
    const Face_lattice& lg = lattices.at(n_g);
    // slot m of side kf is centred at t = (m + 0.5) / n_f from P; on g's side (from Q) at 1 - t
    std::vector<std::pair<int, int> > slot_pairs;
    for(int m = 0; m < n_f; ++m)
      slot_pairs.emplace_back(m, std::min(n_g - 1, int((1.0 - (m + 0.5) / n_f) * n_g)));
    for(int m = 0; m < n_g; ++m)
      slot_pairs.emplace_back(std::min(n_f - 1, int((1.0 - (m + 0.5) / n_g) * n_f)), m);
    std::sort(slot_pairs.begin(), slot_pairs.end());
    slot_pairs.erase(std::unique(slot_pairs.begin(), slot_pairs.end()), slot_pairs.end());
    for(const auto& sp_ : slot_pairs)
    {
      const Ridge_sample& a = S[first_sample[fi] + std::size_t(lf.boundary[kf][sp_.first])];
      const Ridge_sample& b = S[first_sample[gi] + std::size_t(lg.boundary[kg][sp_.second])];
      if(!a.ok || !b.ok) continue;
      ++R.pairs;
      const V3 bx = unfold_pt(b.x);
      const V3 bS = v_sub(bx, v_mul(unfold_vec(b.u), b.rho));
      V3 x; double jump, dist;
      if(test_pair(a, bx, bS, b.sigma, b.distance(), x, jump, dist))
      {
        std::size_t face_out;
        const V3 y = fold_pt(x, face_out);
        record(y, jump, dist, face_out);
      }
    }
  }
  R.time_total = time_start_offset + seconds_since(t_start);
  return R;
}

template <class TriangleMesh>
using SMSP_for = CGAL::Surface_mesh_shortest_path<CGAL::Surface_mesh_shortest_path_traits<
    typename CGAL::Kernel_traits<typename boost::property_traits<typename boost::property_map<
        TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel,
    TriangleMesh> >;

} // namespace internal

/// The exact reference ridge of a source at vertex `s` (see the file comment).
/// `TriangleMesh` must have internal vertex_point, vertex_index and face_index
/// maps (e.g. `CGAL::Surface_mesh`).
template <class TriangleMesh>
auto reference_ridge(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::vertex_descriptor s,
                     const Reference_ridge_options& opt = Reference_ridge_options())
{
  const auto t0 = std::chrono::steady_clock::now();
  internal::SMSP_for<TriangleMesh> sp(tm);
  sp.add_source_point(s);
  const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return internal::reference_ridge_impl(tm, sp, internal::to_v3(get(CGAL::vertex_point, tm, s)), opt, setup);
}

/// The exact reference ridge of a source at a surface point (face, barycentric
/// coordinates in CGAL's order). A point of an edge, border or not, is moved
/// into the face by 2^-40 of the barycentric range with CGAL < 5.6
/// (`Geodesic_ridge::internal::smsp_source_coordinates()`).
template <class TriangleMesh, class FT>
auto reference_ridge(const TriangleMesh& tm,
                     const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor, std::array<FT, 3> >& loc,
                     const Reference_ridge_options& opt = Reference_ridge_options())
{
  const auto t0 = std::chrono::steady_clock::now();
  internal::SMSP_for<TriangleMesh> sp(tm);
  const std::array<FT, 3> w = Geodesic_ridge::internal::smsp_source_coordinates(loc.second);
  typename internal::SMSP_for<TriangleMesh>::Barycentric_coordinates b = {{w[0], w[1], w[2]}};
  sp.add_source_point(loc.first, b);
  const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  typename internal::SMSP_for<TriangleMesh>::Barycentric_coordinates given = {{loc.second[0], loc.second[1], loc.second[2]}};
  return internal::reference_ridge_impl(tm, sp, internal::to_v3(sp.point(loc.first, given)), opt, setup);
}

// ----------------------------------------------------------------------------
// Accuracy of a computed ridge against the reference

/// How the computed ridge is compared with the reference.
struct Ridge_accuracy_options
{
  double sample_spacing = 0.1;     ///< spacing of samples along the computed polylines (mean edges)
  double major_jump_degrees = 30;  ///< precision is reported apart for reference points below this
  double recall_jump_degrees = 60; ///< recall is measured from reference points at least this
  double outlier_distance = 0.5;   ///< computed samples farther than this (mean edges) are listed
  double near_feature = 1.0;       ///< an outlier is "near" a leaf / junction / the source within this (mean edges)
};

/// A computed ridge sample far from the reference ridge, with what lies near it.
template <class Point_3>
struct Ridge_outlier
{
  Point_3 point;
  double distance = 0;          ///< to the reference ridge (mean edges)
  double nearest_jump = 0;      ///< jump of the nearest reference point (degrees)
  double to_leaf = 0, to_junction = 0, to_source = 0; ///< Euclidean, mean edges (inf if none)
  std::size_t polyline = 0;
};

/// Precision and recall of a computed ridge, all distances in mean edge lengths.
///
/// Precision: every sample of the computed polylines (spacing `sample_spacing`,
/// ignoring those within `source_exclusion` of the source) is matched with the
/// nearest reference point (jump >= the reference's minimum). It belongs to the
/// major part if that reference point's jump is >= `major_jump_degrees`, to the
/// minor (ill-conditioned) part otherwise. Its distance is to the reference
/// ridge, approximated locally by the segment joining its two nearest reference
/// points when they are closer than 0.5 mean edge (else the nearest point):
/// this removes most of the sampling floor of a point set.
/// Recall: every reference point with jump >= `recall_jump_degrees` is matched
/// with the computed polylines (exact point-to-segment distance near the
/// nearest computed sample).
template <class Point_3>
struct Ridge_accuracy
{
  std::size_t computed_samples = 0;
  std::size_t major_samples = 0, minor_samples = 0;
  double precision_median = 0, precision_p95 = 0, precision_max = 0;             ///< major part (jump >= 30)
  double precision_minor_median = 0, precision_minor_p95 = 0, precision_minor_max = 0; ///< minor part
  double precision_all_p95 = 0;                                                  ///< both parts together
  std::size_t recall_points = 0;
  double recall_median = 0, recall_p95 = 0, recall_max = 0;                      ///< reference jump >= 60
  double ridge_length = 0;                ///< total length of the computed polylines (mean edges)
  std::size_t leaves = 0, junctions = 0;  ///< of the computed polylines
  std::vector<Ridge_outlier<Point_3> > outliers; ///< computed samples farther than outlier_distance
  std::vector<std::pair<std::size_t, double> > missed; ///< reference points (index, distance) of the recall set farther than outlier_distance
};

namespace internal {

inline double quantile(std::vector<double> v, double q)
{
  if(v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t i = std::min(v.size() - 1, std::size_t(std::ceil(q * double(v.size()))) - (q > 0 ? 1 : 0));
  return v[i];
}

inline double point_segment_distance(const V3& p, const V3& a, const V3& b)
{
  const V3 ab = v_sub(b, a);
  const double l2 = v_dot(ab, ab);
  double t = l2 > 0 ? v_dot(v_sub(p, a), ab) / l2 : 0;
  t = std::max(0.0, std::min(1.0, t));
  return v_norm(v_sub(p, v_add(a, v_mul(ab, t))));
}

// k nearest neighbours among a set of points, by index
template <class Point_3>
class Nearest_points
{
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel K;
  typedef CGAL::Search_traits_3<K> Base;
  typedef typename CGAL::Pointer_property_map<Point_3>::const_type Map;
  typedef CGAL::Search_traits_adapter<std::size_t, Map, Base> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef typename Search::Tree Tree;
  typedef typename Search::Distance Distance;

  const std::vector<Point_3>& pts_;
  Map map_;
  Tree tree_;

public:
  explicit Nearest_points(const std::vector<Point_3>& pts)
    : pts_(pts), map_(CGAL::make_property_map(pts.data())), // (no element of an empty vector is bound)
      tree_(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(pts.size()),
            typename Tree::Splitter(), Traits(map_))
  {
    if(!pts.empty()) tree_.build(); // (CGAL's Kd_tree builds from one point at least)
  }
  bool empty() const { return pts_.empty(); }
  // indices of the k nearest points, nearest first
  std::vector<std::size_t> query(const Point_3& q, unsigned int k) const
  {
    std::vector<std::size_t> out;
    if(pts_.empty()) return out;
    Distance dist(map_);
    Search search(tree_, q, k, 0, true, dist);
    for(auto it = search.begin(); it != search.end(); ++it) out.push_back(it->first);
    return out;
  }
};

} // namespace internal

/// Accuracy of computed polylines of 3D points (see `Ridge_accuracy`).
template <class Point_3>
Ridge_accuracy<Point_3> ridge_accuracy(const Reference_ridge<Point_3>& ref,
                                       const std::vector<std::vector<Point_3> >& polylines,
                                       const Reference_ridge_options& ref_opt = Reference_ridge_options(),
                                       const Ridge_accuracy_options& opt = Ridge_accuracy_options())
{
  using namespace internal;
  Ridge_accuracy<Point_3> A;
  const double L = ref.mean_edge;
  const V3 src = to_v3(ref.source);

  // samples along the computed polylines, with the segment they lie on
  struct Where { std::size_t polyline, segment; };
  std::vector<Point_3> samples;
  std::vector<Where> where;
  std::vector<Point_3> ends;
  for(std::size_t pi = 0; pi < polylines.size(); ++pi)
  {
    const auto& pl = polylines[pi];
    if(pl.empty()) continue;
    ends.push_back(pl.front());
    ends.push_back(pl.back());
    for(std::size_t k = 0; k + 1 < pl.size(); ++k)
    {
      const V3 a = to_v3(pl[k]), b = to_v3(pl[k + 1]);
      const double len = v_norm(v_sub(b, a));
      A.ridge_length += len / L;
      const int m = std::max(1, int(std::ceil(len / (opt.sample_spacing * L))));
      for(int i = 0; i < m; ++i)
      {
        const V3 p = v_add(a, v_mul(v_sub(b, a), double(i) / m));
        samples.push_back(Point_3(p[0], p[1], p[2]));
        where.push_back({pi, k});
      }
    }
    samples.push_back(pl.back());
    where.push_back({pi, pl.size() >= 2 ? pl.size() - 2 : 0});
  }
  // leaves and junctions: polyline ends, by how many ends meet at a point
  std::vector<Point_3> leaves, junctions;
  {
    std::map<std::array<double, 3>, int> degree;
    for(const auto& p : ends) ++degree[to_v3(p)];
    for(const auto& d : degree)
    {
      const Point_3 p(d.first[0], d.first[1], d.first[2]);
      if(d.second == 1) leaves.push_back(p);
      else if(d.second >= 3) junctions.push_back(p);
    }
  }
  A.leaves = leaves.size();
  A.junctions = junctions.size();
  const Nearest_points<Point_3> leaf_search(leaves), junction_search(junctions);
  auto nearest_distance = [&](const Nearest_points<Point_3>& s, const std::vector<Point_3>& pts, const Point_3& q) {
    const auto idx = s.query(q, 1);
    return idx.empty() ? std::numeric_limits<double>::infinity() : v_norm(v_sub(to_v3(pts[idx[0]]), to_v3(q))) / L;
  };

  // ---- precision
  const Nearest_points<Point_3> ref_search(ref.points);
  std::vector<double> major, minor;
  for(std::size_t i = 0; i < samples.size(); ++i)
  {
    const V3 q = to_v3(samples[i]);
    if(v_norm(v_sub(q, src)) < ref_opt.source_exclusion * L) continue;
    ++A.computed_samples;
    const auto nn = ref_search.query(samples[i], 2);
    if(nn.empty()) continue;
    const V3 p1 = to_v3(ref.points[nn[0]]);
    double d = v_norm(v_sub(q, p1));
    if(nn.size() == 2)
    {
      const V3 p2 = to_v3(ref.points[nn[1]]);
      if(v_norm(v_sub(p1, p2)) < 0.5 * L) d = std::min(d, point_segment_distance(q, p1, p2));
    }
    d /= L;
    const double jump = ref.jump_degrees[nn[0]];
    (jump >= opt.major_jump_degrees ? major : minor).push_back(d);
    if(d > opt.outlier_distance)
    {
      Ridge_outlier<Point_3> o;
      o.point = samples[i];
      o.distance = d;
      o.nearest_jump = jump;
      o.polyline = where[i].polyline;
      o.to_leaf = nearest_distance(leaf_search, leaves, samples[i]);
      o.to_junction = nearest_distance(junction_search, junctions, samples[i]);
      o.to_source = v_norm(v_sub(q, src)) / L;
      A.outliers.push_back(o);
    }
  }
  A.major_samples = major.size();
  A.minor_samples = minor.size();
  A.precision_median = quantile(major, 0.5);
  A.precision_p95 = quantile(major, 0.95);
  A.precision_max = major.empty() ? 0 : *std::max_element(major.begin(), major.end());
  A.precision_minor_median = quantile(minor, 0.5);
  A.precision_minor_p95 = quantile(minor, 0.95);
  A.precision_minor_max = minor.empty() ? 0 : *std::max_element(minor.begin(), minor.end());
  {
    std::vector<double> all = major;
    all.insert(all.end(), minor.begin(), minor.end());
    A.precision_all_p95 = quantile(all, 0.95);
  }

  // ---- recall
  const Nearest_points<Point_3> sample_search(samples);
  std::vector<double> recall;
  for(std::size_t i = 0; i < ref.points.size(); ++i)
  {
    if(ref.jump_degrees[i] < opt.recall_jump_degrees) continue;
    const V3 q = to_v3(ref.points[i]);
    double d = std::numeric_limits<double>::infinity();
    for(std::size_t j : sample_search.query(ref.points[i], 1))
    {
      const auto& pl = polylines[where[j].polyline];
      const std::size_t s = where[j].segment;
      d = v_norm(v_sub(q, to_v3(samples[j])));
      for(std::size_t k = (s > 0 ? s - 1 : 0); k <= s + 1 && k + 1 < pl.size(); ++k)
        d = std::min(d, point_segment_distance(q, to_v3(pl[k]), to_v3(pl[k + 1])));
    }
    recall.push_back(d / L);
    if(d / L > opt.outlier_distance) A.missed.emplace_back(i, d / L);
  }
  A.recall_points = recall.size();
  A.recall_median = quantile(recall, 0.5);
  A.recall_p95 = quantile(recall, 0.95);
  A.recall_max = recall.empty() ? 0 : *std::max_element(recall.begin(), recall.end());
  return A;
}

/// Same, for the polylines of `compute_ridge_curve()` (`Ridge_point`s).
template <class Point_3>
Ridge_accuracy<Point_3> ridge_accuracy(const Reference_ridge<Point_3>& ref,
                                       const std::vector<std::vector<Ridge_point<Point_3> > >& polylines,
                                       const Reference_ridge_options& ref_opt = Reference_ridge_options(),
                                       const Ridge_accuracy_options& opt = Ridge_accuracy_options())
{
  std::vector<std::vector<Point_3> > pls;
  Geodesic_ridge::ridge_polyline_points(polylines, std::back_inserter(pls));
  return ridge_accuracy(ref, pls, ref_opt, opt);
}

} // namespace testing
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_TEST_SUPPORT_REFERENCE_RIDGE_H
