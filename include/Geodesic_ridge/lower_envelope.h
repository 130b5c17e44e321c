// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 2c: the lower envelope of the linear distance fields of the copies of
// one face (user manual, "The Exact Lower Envelope").
//
// Every copy i of a face carries the field f_i(λ) = λ0 d0^i + λ1 d1^i + λ2 d2^i,
// linear in the barycentric coordinates λ. The cell of copy i is where f_i is
// the lowest field; the edges between cells are the pieces of the ridge inside
// the face.
//
// Method. CGAL `halfspace_intersection_3` over a prism (the paper's) or an
// equivalent exact half-plane clipping would do; we clip. f_i − f_j = (d^i − d^j)·λ is
// linear in λ, so each cell is the triangle {λ ≥ 0} clipped by the half-planes
// (d^i − d^j)·λ ≤ 0, computed in barycentric coordinates directly: no 2D layout
// of the triangle, no 3D construction, and points on the triangle's edges and
// corners come out with exact zero coordinates.
#ifndef GEODESIC_RIDGE_LOWER_ENVELOPE_H
#define GEODESIC_RIDGE_LOWER_ENVELOPE_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/tuning.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Mpzf.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

// ---------------------------------------------------------------------------
// Conventions (shared by every type of this header)
//
// * Corner k of a face f is CGAL's: corner 0 = source(halfedge(f)),
//   corner 1 = target(halfedge(f)), corner 2 = target(next(halfedge(f))), as in
//   `CGAL::Polygon_mesh_processing::Face_location`. λ_k is the weight of corner k.
// * Triangle edge k runs from corner k to corner (k+1) mod 3: it is the
//   halfedge next^k(halfedge(f)), and λ_{(k+2) mod 3} = 0 on it.
// * Polygons are counter-clockwise in the (λ1, λ2) plane. The corners 0, 1, 2
//   are (0,0), (1,0), (0,1) there, so this is the orientation of the face itself.
//   Areas are measured in that plane: the whole triangle has area 1/2 (the same
//   value in the (λ0, λ1) or (λ2, λ0) plane: the maps between them have
//   determinant ±1).
// ---------------------------------------------------------------------------

/// \ingroup PkgGeodesicRidgeRef
/// Which feature of the triangle a barycentric point lies on.
enum class Triangle_feature_type : unsigned char
{
  interior, ///< no coordinate is zero
  edge,     ///< one coordinate is zero: on triangle edge `index` (not at a corner)
  vertex    ///< two coordinates are zero: at corner `index`
};

/// \ingroup PkgGeodesicRidgeRef
/// The feature of the triangle a barycentric point lies on: triangle edge k
/// (halfedge next^k(halfedge(f))) or corner k, or the interior (`index` = -1).
/// Stage 3 joins segments of adjacent faces with it, combinatorially.
struct Triangle_feature
{
  /// interior, edge or corner
  Triangle_feature_type type = Triangle_feature_type::interior;
  /// the triangle edge or corner (0, 1 or 2), -1 for the interior
  int index = -1;

  friend bool operator==(const Triangle_feature& a, const Triangle_feature& b)
  { return a.type == b.type && a.index == b.index; }
  friend bool operator!=(const Triangle_feature& a, const Triangle_feature& b)
  { return !(a == b); }
};

/// \ingroup PkgGeodesicRidgeRef
/// The barycentric coordinate that vanishes on triangle edge `k`: (k+2) mod 3.
inline int zero_coordinate_of_triangle_edge(int k) { return (k + 2) % 3; }

/// \ingroup PkgGeodesicRidgeRef
/// \name Edge labels of an `Envelope_cell`
/// A label is either the index of the neighbouring copy (a value < the number
/// of copies) or one of the three largest `std::size_t` values, which stand for
/// the triangle edges 0, 1, 2. Use these functions rather than the values.
/// @{

/// the label of triangle edge `k`
inline constexpr std::size_t triangle_edge_label(int k)
{ return (std::numeric_limits<std::size_t>::max)() - 2 + static_cast<std::size_t>(k); }
/// whether `label` stands for a triangle edge (else it is a copy's index)
inline constexpr bool is_triangle_edge_label(std::size_t label)
{ return label >= (std::numeric_limits<std::size_t>::max)() - 2; }
/// the triangle edge that `label` stands for
/// \pre `is_triangle_edge_label(label)`
inline constexpr int triangle_edge_of_label(std::size_t label)
{ return static_cast<int>(label - ((std::numeric_limits<std::size_t>::max)() - 2)); }
/// @}

/// \ingroup PkgGeodesicRidgeRef
/// The cell of one copy: the closed convex region of the face where its field
/// is the lowest (ties: see `compute_lower_envelope()`). Only cells of positive
/// area are reported.
///
/// \tparam FT the number type of the coordinates.
template <class FT>
struct Envelope_cell
{
  /// Index of the copy in the input of `compute_lower_envelope()`.
  std::size_t copy = 0;
  /// The cell's corners in barycentric coordinates (λ0, λ1, λ2), with
  /// λ0 + λ1 + λ2 = 1 exactly for an exact `FT`, counter-clockwise in the
  /// (λ1, λ2) plane, at least three of them, every one a true corner (with an
  /// exact `FT`, no two consecutive edges are collinear).
  std::vector<std::array<FT, 3>> polygon;
  /// `edge_label[i]` describes the edge polygon[i] -> polygon[(i+1) % n]:
  /// the index of the copy whose cell lies across it, or
  /// `triangle_edge_label(k)` when the edge lies on triangle edge k (a
  /// triangle edge wins if it is also a bisector). Test it with
  /// `is_triangle_edge_label()`.
  std::vector<std::size_t> edge_label;
  /// `vertex_feature[i]`: the triangle feature polygon[i] lies on.
  std::vector<Triangle_feature> vertex_feature;
};

/// \ingroup PkgGeodesicRidgeRef
/// A piece of the ridge inside the face: the common edge of the cells of
/// `copy_a` and `copy_b`. Walking from `endpoints[0]` to `endpoints[1]`, the
/// cell of `copy_a` is on the left (counter-clockwise side in the (λ1, λ2)
/// plane, i.e. with respect to the face's orientation).
template <class FT>
struct Envelope_segment
{
  /// the copies on either side (copy_a < copy_b)
  std::size_t copy_a = 0, copy_b = 0; ///< copy_a < copy_b
  std::array<std::array<FT, 3>, 2> endpoints; ///< barycentric, exact with an exact `FT`
  /// Where each endpoint lies: a triangle corner, a triangle edge, or the
  /// interior. Decided by exact zero tests on the coordinates.
  std::array<Triangle_feature, 2> endpoint_feature;
};

/// \ingroup PkgGeodesicRidgeRef
/// The lower envelope of one face: cells ordered by copy index, and every
/// ridge segment once, ordered by (copy_a, copy_b).
template <class FT>
struct Lower_envelope
{
  /// the cells of positive area, by copy index
  std::vector<Envelope_cell<FT>> cells;
  /// the ridge segments inside the face, by (copy_a, copy_b)
  std::vector<Envelope_segment<FT>> segments;
};

namespace internal {
namespace lower_envelope {

template <class FT>
constexpr bool is_exact()
{
  return std::is_same<typename CGAL::Algebraic_structure_traits<FT>::Is_exact,
                      CGAL::Tag_true>::value;
}

// A corner of a polygon being clipped, in homogeneous barycentric coordinates:
// λ = w / (w0 + w1 + w2). Keeping w unnormalized saves every division in the
// clipping loop (w is a cross product of input differences, a dyadic rational);
// only the output is normalized. With an inexact FT, w is normalized at once
// (s_sign = 1) so that a near-degenerate construction can be checked and fixed.
template <class FT>
struct Vertex
{
  std::array<FT, 3> w;
  int s_sign; // sign of w0 + w1 + w2, never zero
};

template <class FT>
FT dot(const std::array<FT, 3>& a, const std::array<FT, 3>& w)
{ return a[0] * w[0] + a[1] * w[1] + a[2] * w[2]; }

// The point where line `a` (a·λ = 0, or triangle edge k when a is null) meets
// the bisector b·λ = 0: the cross product a × b, up to scale and sign.
template <class FT>
std::array<FT, 3> intersect(const std::array<FT, 3>* a, int triangle_edge, const std::array<FT, 3>& b)
{
  if(a == nullptr) {
    // λ_z = 0 and b·λ = 0; why special: exact zero in coordinate z for every FT
    const int z = zero_coordinate_of_triangle_edge(triangle_edge);
    std::array<FT, 3> w;
    w[z] = FT(0);
    w[(z + 1) % 3] = -b[(z + 2) % 3];
    w[(z + 2) % 3] = b[(z + 1) % 3];
    return w;
  }
  const std::array<FT, 3>& u = *a;
  return {{ u[1] * b[2] - u[2] * b[1],
            u[2] * b[0] - u[0] * b[2],
            u[0] * b[1] - u[1] * b[0] }};
}

template <class FT>
bool is_parallel(const std::array<FT, 3>& a, const std::array<FT, 3>& b)
{
  return a[0] * b[1] == a[1] * b[0] && a[1] * b[2] == a[2] * b[1] && a[0] * b[2] == a[2] * b[0];
}

// Builds the new corner on the edge P -> Q (g(P) and g(Q) of strictly opposite signs).
template <class FT>
Vertex<FT> make_vertex(std::array<FT, 3> w,
                       const Vertex<FT>& P, const Vertex<FT>& Q, const FT& gP, const FT& gQ)
{
  if constexpr(is_exact<FT>()) {
    (void)P; (void)Q; (void)gP; (void)gQ;
    const int s = static_cast<int>(CGAL::sign(FT(w[0] + w[1] + w[2])));
    if(s == 0) // two lines that cross between P and Q meet at a finite point
      throw Algorithm_error("compute_lower_envelope: parallel lines crossed while clipping (a bug)");
    return Vertex<FT>{w, s};
  } else {
    // Inexact: the sign tests may disagree with the lines (nearly parallel
    // ones); keep the new corner on the segment PQ whatever happens.
    const FT s = w[0] + w[1] + w[2];
    bool ok = (s != FT(0));
    if(ok) {
      for(int k = 0; k < 3; ++k) {
        w[k] = w[k] / s;
        const FT lo = (std::min)(P.w[k], Q.w[k]), hi = (std::max)(P.w[k], Q.w[k]);
        const FT slack = FT(tuning::envelope::barycentric_slack);
        if(!(w[k] >= lo - slack && w[k] <= hi + slack)) ok = false; // also catches NaN
      }
    }
    if(!ok) {
      const FT t = gP / (gP - gQ);
      for(int k = 0; k < 3; ++k) w[k] = P.w[k] + t * (Q.w[k] - P.w[k]);
    }
    return Vertex<FT>{w, 1};
  }
}

// One step of Sutherland-Hodgman: keeps {λ : b·λ ≤ 0} of the convex polygon
// (poly, label); the new edge on b·λ = 0 gets `new_label`. `line_of(l)` is the
// line vector of the edges labelled with copy l; triangle edges are handled apart.
template <class FT, class LineOf>
void clip(std::vector<Vertex<FT>>& poly, std::vector<std::size_t>& label,
          const std::array<FT, 3>& b, std::size_t new_label, const LineOf& line_of)
{
  const std::size_t n = poly.size();
  std::vector<FT> g(n);
  std::vector<int> sg(n);
  bool any_out = false, any_in = false;
  for(std::size_t i = 0; i < n; ++i) {
    g[i] = dot(b, poly[i].w);
    sg[i] = static_cast<int>(CGAL::sign(g[i])) * poly[i].s_sign;
    any_out = any_out || sg[i] > 0;
    any_in = any_in || sg[i] < 0;
  }
  if(!any_out) return; // all inside (or on the line): nothing to cut
  std::vector<Vertex<FT>> out;
  std::vector<std::size_t> out_label;
  if(!any_in) { poly.swap(out); label.swap(out_label); return; } // at most an edge remains
  out.reserve(n + 1);
  out_label.reserve(n + 1);
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t i1 = (i + 1 == n) ? 0 : i + 1;
    const int sp = sg[i], sq = sg[i1];
    if(sp <= 0) {
      if(sq <= 0) {
        out.push_back(poly[i]); out_label.push_back(label[i]);
      } else if(sp < 0) { // leaves the half-plane: keep P, add the crossing
        out.push_back(poly[i]); out_label.push_back(label[i]);
        const std::array<FT, 3>* a = is_triangle_edge_label(label[i]) ? nullptr : &line_of(label[i]);
        const int te = is_triangle_edge_label(label[i]) ? triangle_edge_of_label(label[i]) : -1;
        out.push_back(make_vertex(intersect(a, te, b), poly[i], poly[i1], g[i], g[i1]));
        out_label.push_back(new_label);
      } else { // P on the line, Q outside: the edge leaving P runs on the line
        out.push_back(poly[i]); out_label.push_back(new_label);
      }
    } else if(sq < 0) { // enters the half-plane: add the crossing
      const std::array<FT, 3>* a = is_triangle_edge_label(label[i]) ? nullptr : &line_of(label[i]);
      const int te = is_triangle_edge_label(label[i]) ? triangle_edge_of_label(label[i]) : -1;
      out.push_back(make_vertex(intersect(a, te, b), poly[i], poly[i1], g[i], g[i1]));
      out_label.push_back(label[i]);
    }
  }
  poly.swap(out);
  label.swap(out_label);
}

template <class FT>
Triangle_feature feature_of(const std::array<FT, 3>& w)
{
  int zeros = 0, zero = -1, nonzero = -1;
  for(int k = 0; k < 3; ++k) {
    if(CGAL::is_zero(w[k])) { ++zeros; zero = k; } else nonzero = k;
  }
  Triangle_feature f;
  if(zeros == 1) { f.type = Triangle_feature_type::edge; f.index = (zero + 1) % 3; }
  else if(zeros >= 2) { f.type = Triangle_feature_type::vertex; f.index = nonzero; }
  return f;
}

} // namespace lower_envelope
} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
/// Signed area of a polygon given in barycentric coordinates, measured in the
/// (λ1, λ2) plane: positive for a counter-clockwise polygon, 1/2 for the
/// whole triangle (so the fraction of the face covered is twice the area).
template <class FT>
FT barycentric_area(const std::vector<std::array<FT, 3>>& polygon)
{
  FT twice(0);
  const std::size_t n = polygon.size();
  for(std::size_t i = 0; i < n; ++i) {
    const std::array<FT, 3>& p = polygon[i];
    const std::array<FT, 3>& q = polygon[(i + 1) % n];
    twice += p[1] * q[2] - q[1] * p[2];
  }
  return twice / FT(2);
}

/// \ingroup PkgGeodesicRidgeRef
/// The 3D point at barycentric coordinates `lambda` of the triangle (p0, p1, p2)
/// (corners in CGAL's order, see the conventions above), computed in double.
/// A corner (1,0,0) gives p0 exactly.
/// \tparam Point_3 a point type with `x()`, `y()`, `z()` and a constructor from three doubles
/// (`CGAL::Epick::Point_3`, for example).
template <class Point_3, class FT>
Point_3 barycentric_to_point(const std::array<FT, 3>& lambda,
                             const Point_3& p0, const Point_3& p1, const Point_3& p2)
{
  const double l0 = CGAL::to_double(lambda[0]), l1 = CGAL::to_double(lambda[1]),
               l2 = CGAL::to_double(lambda[2]);
  return Point_3(l0 * CGAL::to_double(p0.x()) + l1 * CGAL::to_double(p1.x()) + l2 * CGAL::to_double(p2.x()),
                 l0 * CGAL::to_double(p0.y()) + l1 * CGAL::to_double(p1.y()) + l2 * CGAL::to_double(p2.y()),
                 l0 * CGAL::to_double(p0.z()) + l1 * CGAL::to_double(p1.z()) + l2 * CGAL::to_double(p2.z()));
}

namespace internal {
namespace lower_envelope {

// The number type the clipping runs in: the exact type under a lazy FT.
// Why: measured, clipping with Lazy_exact_nt directly took 2-2.6 times as long
// as in its exact type (every operation allocates a DAG node, and the output's zero
// tests need the exact values anyway); the result is converted at the end.
template <class FT> struct Computation_type { typedef FT type; };
template <class ET> struct Computation_type<CGAL::Lazy_exact_nt<ET>> { typedef ET type; };

// The ring the clipping runs in. Corners are kept in homogeneous coordinates
// (cross products of bisector vectors, which are differences of input
// doubles), so clipping only adds and multiplies; the one division per corner,
// the normalization, is done at the end in FT. CGAL::Mpzf (a binary float
// with a multi-limb mantissa, no gcd, no heap for small sizes) does that ring
// exactly and much faster than Gmpq, which normalizes every result.
template <class FT> struct Ring_type { typedef FT type; };
#ifdef CGAL_HAS_MPZF
template <> struct Ring_type<CGAL::Gmpq> { typedef CGAL::Mpzf type; };
#endif
template <class FT, class R> FT ring_to(const R& x) { return FT(x); }
#ifdef CGAL_HAS_MPZF
template <> inline CGAL::Gmpq ring_to<CGAL::Gmpq, CGAL::Mpzf>(const CGAL::Mpzf& x) { return static_cast<CGAL::Gmpq>(x); }
#endif

// λ = w / (w0 + w1 + w2) in FT. With an exact FT the last nonzero coordinate
// is 1 minus the others (so they sum to 1 exactly), and a triangle corner
// needs no arithmetic at all; an inexact w is already normalized (R is FT).
template <class FT, class R>
std::array<FT, 3> normalized(const Vertex<R>& v)
{
  if constexpr(is_exact<FT>()) {
    std::array<FT, 3> lambda = {{FT(0), FT(0), FT(0)}};
    int last = -1;
    for(int k = 0; k < 3; ++k) if(!CGAL::is_zero(v.w[k])) last = k;
    const FT s = ring_to<FT>(R(v.w[0] + v.w[1] + v.w[2]));
    FT rest(1);
    for(int k = 0; k < last; ++k)
      if(!CGAL::is_zero(v.w[k])) { lambda[k] = ring_to<FT>(v.w[k]) / s; rest -= lambda[k]; }
    lambda[last] = rest;
    return lambda;
  } else {
    return v.w;
  }
}

// The steps of `compute_lower_envelope()`: drop the dominated copies, form the
// bisector vectors, clip one cell per remaining copy, then read the segments
// off the cells. FT is the output number type, R the ring the clipping runs in.
template <class FT, class R>
class Envelope_builder
{
public:
  explicit Envelope_builder(const std::vector<std::array<double, 3>>& d) : d_(d), m_(d.size()) {}

  Lower_envelope<FT> run()
  {
    check_input();
    find_undominated_copies();
    compute_bisectors();
    std::vector<std::size_t> cell_order(alive_);
    std::sort(cell_order.begin(), cell_order.end());
    for(std::size_t i : cell_order)
      add_cell(i);
    add_segments();
    return std::move(result_);
  }

private:
  void check_input() const
  {
    if(m_ == 0)
      throw Invalid_parameter_error("compute_lower_envelope: no copy of the face (at least one is needed)");
    for(std::size_t i = 0; i < m_; ++i)
      for(int k = 0; k < 3; ++k)
        if(!std::isfinite(d_[i][k]))
          throw Invalid_parameter_error("compute_lower_envelope: distance " + std::to_string(k) +
                                        " of copy " + std::to_string(i) + " is not finite");
  }

  // Decided on the input doubles (exact): i never has a 2D cell if j is ≤ it
  // at the three corners (and j < i when they are equal).
  bool dominates(std::size_t j, std::size_t i) const
  {
    bool equal = true;
    for(int k = 0; k < 3; ++k) {
      if(d_[j][k] > d_[i][k]) return false;
      if(d_[j][k] != d_[i][k]) equal = false;
    }
    return !equal || j < i;
  }

  // The undominated copies (they dominate all others), lowest on average
  // first: clipping by them first shrinks the cells sooner.
  void find_undominated_copies()
  {
    for(std::size_t i = 0; i < m_; ++i) {
      bool dominated = false;
      for(std::size_t j = 0; j < m_ && !dominated; ++j) dominated = (j != i && dominates(j, i));
      if(!dominated) alive_.push_back(i);
    }
    std::sort(alive_.begin(), alive_.end(), [&](std::size_t a, std::size_t b) {
      const double sa = d_[a][0] + d_[a][1] + d_[a][2], sb = d_[b][0] + d_[b][1] + d_[b][2];
      return sa < sb || (sa == sb && a < b);
    });
  }

  // Bisector vectors e(i,j) = d^i − d^j: f_i − f_j = e(i,j)·λ, exact.
  void compute_bisectors()
  {
    n_alive_ = alive_.size();
    slot_.assign(m_, m_);
    for(std::size_t s = 0; s < n_alive_; ++s) slot_[alive_[s]] = s;
    std::vector<std::array<R, 3>> D(n_alive_);
    for(std::size_t s = 0; s < n_alive_; ++s)
      for(int k = 0; k < 3; ++k) D[s][k] = R(d_[alive_[s]][k]);
    E_.resize(n_alive_ * n_alive_);
    for(std::size_t a = 0; a < n_alive_; ++a)
      for(std::size_t b = a + 1; b < n_alive_; ++b)
        for(int k = 0; k < 3; ++k) {
          E_[a * n_alive_ + b][k] = D[a][k] - D[b][k];
          E_[b * n_alive_ + a][k] = -E_[a * n_alive_ + b][k];
        }
  }

  // e(i,j) for the copy i of slot si
  const std::array<R, 3>& bisector(std::size_t si, std::size_t j) const { return E_[si * n_alive_ + slot_[j]]; }

  // The cell of copy i, unless it has zero area (round-off slivers too with an
  // inexact FT).
  void add_cell(std::size_t i)
  {
    std::vector<Vertex<R>> poly;
    std::vector<std::size_t> label;
    clip_cell(i, poly, label);
    if(poly.size() < 3) return; // empty, a point or a segment
    relabel_shared_lines(i, label);
    Envelope_cell<FT> cell;
    cell.copy = i;
    cell.edge_label = label;
    cell.polygon.reserve(poly.size());
    cell.vertex_feature.reserve(poly.size());
    for(const Vertex<R>& v : poly) {
      cell.vertex_feature.push_back(feature_of(v.w));
      cell.polygon.push_back(normalized<FT>(v));
    }
    if constexpr(!is_exact<FT>()) {
      if(!(barycentric_area(cell.polygon) > FT(0))) return;
    }
    result_.cells.push_back(std::move(cell));
  }

  // The triangle clipped by the half-planes where f_i ≤ f_j, stopping once
  // less than a polygon remains.
  void clip_cell(std::size_t i, std::vector<Vertex<R>>& poly, std::vector<std::size_t>& label) const
  {
    const std::size_t si = slot_[i];
    auto line_of = [&](std::size_t j) -> const std::array<R, 3>& { return bisector(si, j); };
    poly.resize(3);
    for(int k = 0; k < 3; ++k) {
      poly[k].w = {{R(0), R(0), R(0)}};
      poly[k].w[k] = R(1);
      poly[k].s_sign = 1;
    }
    label = {triangle_edge_label(0), triangle_edge_label(1), triangle_edge_label(2)};
    for(std::size_t j : alive_) {
      if(j == i) continue;
      clip(poly, label, line_of(j), j, line_of);
      if(poly.size() < 3) break;
    }
  }

  // An edge on a line where several fields meet f_i (f_j, f_k − f_i ∝ the
  // same linear function) was labelled by whichever clipped last. Across it,
  // the winner among those copies is the lowest at a triangle corner on the
  // far side (their differences all vanish on the line), ties to the lower index.
  void relabel_shared_lines(std::size_t i, std::vector<std::size_t>& label) const
  {
    const std::size_t si = slot_[i];
    for(std::size_t t = 0; t < label.size(); ++t) {
      if(is_triangle_edge_label(label[t])) continue;
      const std::size_t j = label[t];
      const std::array<R, 3>& eij = bisector(si, j);
      int c = -1;
      for(int k = 0; k < 3 && c < 0; ++k)
        if(CGAL::is_positive(eij[k])) c = k; // f_i > f_j at corner k: the far side
      if(c < 0) continue; // cannot happen for an edge inside the triangle
      std::size_t best = j;
      for(std::size_t k : alive_) {
        if(k == i || k == j || !is_parallel(bisector(si, k), eij)) continue;
        if(d_[k][c] < d_[best][c] || (d_[k][c] == d_[best][c] && k < best)) best = k;
      }
      label[t] = best;
    }
  }

  // Edge t of `cell` as a segment, reported from its lower copy (`from_lower`)
  // or, reversed, from its higher one: copy_a is on the left.
  void add_segment(const Envelope_cell<FT>& cell, std::size_t t, bool from_lower,
                   std::set<std::pair<std::size_t, std::size_t>>& reported)
  {
    const std::size_t n = cell.polygon.size(), t1 = (t + 1) % n;
    Envelope_segment<FT> s;
    s.copy_a = from_lower ? cell.copy : cell.edge_label[t];
    s.copy_b = from_lower ? cell.edge_label[t] : cell.copy;
    const std::size_t p = from_lower ? t : t1, q = from_lower ? t1 : t;
    s.endpoints = {{ cell.polygon[p], cell.polygon[q] }};
    s.endpoint_feature = {{ cell.vertex_feature[p], cell.vertex_feature[q] }};
    reported.insert(std::make_pair(s.copy_a, s.copy_b));
    result_.segments.push_back(std::move(s));
  }

  // The edge of cell i labelled j, reported from the lower copy. With an
  // exact FT both cells have this edge, with the same endpoints; with an
  // inexact one the higher copy reports it when the lower one does not.
  void add_segments()
  {
    std::set<std::pair<std::size_t, std::size_t>> reported;
    for(const Envelope_cell<FT>& cell : result_.cells)
      for(std::size_t t = 0; t < cell.edge_label.size(); ++t)
        if(!is_triangle_edge_label(cell.edge_label[t]) && cell.copy < cell.edge_label[t])
          add_segment(cell, t, true, reported);
    if constexpr(!is_exact<FT>()) {
      for(const Envelope_cell<FT>& cell : result_.cells)
        for(std::size_t t = 0; t < cell.edge_label.size(); ++t) {
          const std::size_t j = cell.edge_label[t];
          if(!is_triangle_edge_label(j) && j < cell.copy && !reported.count(std::make_pair(j, cell.copy)))
            add_segment(cell, t, false, reported);
        }
    }
    std::stable_sort(result_.segments.begin(), result_.segments.end(),
                     [](const Envelope_segment<FT>& a, const Envelope_segment<FT>& b) {
                       return a.copy_a < b.copy_a || (a.copy_a == b.copy_a && a.copy_b < b.copy_b);
                     });
  }

  const std::vector<std::array<double, 3>>& d_; // the input: corner distances of every copy
  const std::size_t m_;                         // number of copies
  std::vector<std::size_t> alive_;              // undominated copies, in clipping order
  std::size_t n_alive_ = 0;
  std::vector<std::size_t> slot_;               // copy -> its index in alive_ (m_ if dominated)
  std::vector<std::array<R, 3>> E_;             // e(alive_[a], alive_[b]) at a * n_alive_ + b
  Lower_envelope<FT> result_;
};

template <class FT, class R = typename Ring_type<FT>::type>
Lower_envelope<FT> compute(const std::vector<std::array<double, 3>>& d)
{
  return Envelope_builder<FT, R>(d).run();
}

} // namespace lower_envelope
} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
/// Computes the lower envelope, over one face, of the linear distance fields of
/// the face's copies.
///
/// Copy i has the field f_i(λ) = λ0 d[i][0] + λ1 d[i][1] + λ2 d[i][2], where
/// d[i][k] is its distance at corner k. The cell of copy i is the closure of
/// the set where i wins, and copy i wins at λ when f_i(λ) < f_j(λ) for every
/// j < i and f_i(λ) ≤ f_j(λ) for every j > i: **ties go to the lower index**.
/// Hence coincident fields (the normal case, not an exception) give one cell,
/// to the lowest of the copies; a field lower by a constant wins everywhere; a
/// copy dominated at the three corners (d[i][k] ≥ d[j][k] for all k, for some
/// j, with the tie rule when they are equal) has no cell. Cells of zero area
/// are dropped, so the reported cells have disjoint interiors and cover the
/// triangle: their areas sum to 1/2 exactly with an exact `FT`.
///
/// Every cell edge between cells i and j gives one `Envelope_segment`. Where
/// three or more cells meet, the segments' endpoints are equal numbers with an
/// exact `FT` (the same point, computed from the same two lines, normalized).
///
/// Method: each cell is the triangle clipped by the half-planes
/// (d^i − d^j)·λ ≤ 0 of the undominated copies j (Sutherland-Hodgman, O(m²)
/// clippings of polygons of at most m + 2 corners). New corners are the cross
/// products of the two lines that meet there, so a corner is computed the same
/// way in every cell and a corner on triangle edge k has an exact zero
/// coordinate. An edge on a line shared by several bisectors (three fields
/// through one line) is labelled with the copy that really lies across it.
///
/// \tparam FT the number type of the result. Use an exact one: the default
///         `CGAL::Exact_predicates_exact_constructions_kernel::FT` (the clipping
///         then runs in its exact type, and the result is converted),
///         `CGAL::Gmpq` (the clipping then runs in `CGAL::Mpzf`, the
///         normalization in `Gmpq`; the fastest of those measured, and the pipeline's), or
///         `boost::multiprecision::mpq_rational`. Timings per number type:
///         \ref GeodesicRidgeSecPerformance. `double` works, for comparison
///         only: the result is then approximate, may miss or add tiny cells
///         when fields nearly coincide, and features are decided by the exact
///         zeros that the construction gives (corners and clipped triangle edges).
/// \param d the three corner distances of every copy (doubles from a solver,
///        converted exactly to `FT`).
/// \pre `d` is not empty and holds finite values; otherwise
///      `Invalid_parameter_error` is thrown.
template <class FT = CGAL::Exact_predicates_exact_constructions_kernel::FT>
Lower_envelope<FT> compute_lower_envelope(const std::vector<std::array<double, 3>>& d)
{
  typedef typename internal::lower_envelope::Computation_type<FT>::type NT;
  if constexpr(std::is_same<NT, FT>::value) {
    return internal::lower_envelope::compute<FT>(d);
  } else {
    const Lower_envelope<NT> exact = internal::lower_envelope::compute<NT>(d);
    auto convert = [](const std::array<NT, 3>& p) { return std::array<FT, 3>{{FT(p[0]), FT(p[1]), FT(p[2])}}; };
    Lower_envelope<FT> result;
    result.cells.resize(exact.cells.size());
    for(std::size_t c = 0; c < exact.cells.size(); ++c) {
      result.cells[c].copy = exact.cells[c].copy;
      result.cells[c].edge_label = exact.cells[c].edge_label;
      result.cells[c].vertex_feature = exact.cells[c].vertex_feature;
      for(const std::array<NT, 3>& p : exact.cells[c].polygon) result.cells[c].polygon.push_back(convert(p));
    }
    result.segments.resize(exact.segments.size());
    for(std::size_t i = 0; i < exact.segments.size(); ++i) {
      const Envelope_segment<NT>& e = exact.segments[i];
      Envelope_segment<FT>& r = result.segments[i];
      r.copy_a = e.copy_a;
      r.copy_b = e.copy_b;
      r.endpoints = {{convert(e.endpoints[0]), convert(e.endpoints[1])}};
      r.endpoint_feature = e.endpoint_feature;
    }
    return result;
  }
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_LOWER_ENVELOPE_H
