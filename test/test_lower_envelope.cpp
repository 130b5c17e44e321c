// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 2c (lower envelope of the linear fields of a face's copies): exact
// answers for known configurations, the degenerate cases the design calls
// normal (coincident fields, three fields through a point or a line, nearly
// parallel fields, breakpoints on the triangle's edges and corners), and
// random envelopes checked against brute force. Every test runs with the
// exact number types (exact equalities) and with double (within 1e-12).
#include <Geodesic_ridge/lower_envelope.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Random.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <vector>

namespace {

namespace GR = Geodesic_ridge;
typedef CGAL::Exact_predicates_exact_constructions_kernel::FT Exact_FT;
typedef std::array<double, 3> Distances;

template <class FT>
using Bary = std::array<FT, 3>;

template <class FT>
constexpr bool exact() { return GR::internal::lower_envelope::is_exact<FT>(); }

template <class FT>
FT q(int num, int den = 1) { return FT(num) / FT(den); }

// Exact types: equal; double: within 1e-12.
template <class FT>
bool same(const FT& a, const FT& b)
{
  if constexpr(exact<FT>()) return a == b;
  else return std::abs(a - b) <= 1e-12;
}

template <class FT>
bool same_point(const Bary<FT>& a, const Bary<FT>& b)
{ return same(a[0], b[0]) && same(a[1], b[1]) && same(a[2], b[2]); }

template <class FT>
Bary<FT> bary(const FT& a, const FT& b, const FT& c) { return {{a, b, c}}; }

template <class FT>
FT field(const Distances& d, const Bary<FT>& l)
{ return FT(d[0]) * l[0] + FT(d[1]) * l[1] + FT(d[2]) * l[2]; }

template <class FT>
const GR::Envelope_cell<FT>* find_cell(const GR::Lower_envelope<FT>& env, std::size_t copy)
{
  for(const auto& c : env.cells) if(c.copy == copy) return &c;
  return nullptr;
}

template <class FT>
FT total_area(const GR::Lower_envelope<FT>& env)
{
  FT a(0);
  for(const auto& c : env.cells) a += GR::barycentric_area(c.polygon);
  return a;
}

template <class FT>
bool segment_is(const GR::Envelope_segment<FT>& s, const Bary<FT>& p, const Bary<FT>& r)
{
  return (same_point(s.endpoints[0], p) && same_point(s.endpoints[1], r)) ||
         (same_point(s.endpoints[0], r) && same_point(s.endpoints[1], p));
}

template <class FT>
GR::Triangle_feature feature_at(const GR::Envelope_segment<FT>& s, const Bary<FT>& p)
{ return same_point(s.endpoints[0], p) ? s.endpoint_feature[0] : s.endpoint_feature[1]; }

GR::Triangle_feature on_edge(int k) { return {GR::Triangle_feature_type::edge, k}; }
GR::Triangle_feature on_vertex(int k) { return {GR::Triangle_feature_type::vertex, k}; }
GR::Triangle_feature inside() { return {}; }

// (λ1, λ2)-plane orientation of (p, r, x): positive when x is left of p -> r.
template <class FT>
FT orient(const Bary<FT>& p, const Bary<FT>& r, const Bary<FT>& x)
{ return (r[1] - p[1]) * (x[2] - p[2]) - (r[2] - p[2]) * (x[1] - p[1]); }

// Invariants every envelope satisfies, for exact FT exactly and for double
// within tolerances: the cells are convex CCW polygons in the triangle whose
// areas sum to 1/2, labels agree with the geometry, each segment lies on its
// bisector and matches the edges of both its cells.
template <class FT>
void check_invariants(const std::vector<Distances>& d, const GR::Lower_envelope<FT>& env)
{
  REQUIRE(!env.cells.empty());
  CHECK(same(total_area(env), q<FT>(1, 2)));
  for(std::size_t c = 0; c < env.cells.size(); ++c) {
    const auto& cell = env.cells[c];
    if(c > 0) CHECK(env.cells[c - 1].copy < cell.copy);
    const std::size_t n = cell.polygon.size();
    REQUIRE(n >= 3);
    REQUIRE(cell.edge_label.size() == n);
    REQUIRE(cell.vertex_feature.size() == n);
    CHECK(GR::barycentric_area(cell.polygon) > FT(0));
    for(std::size_t i = 0; i < n; ++i) {
      const Bary<FT>& p = cell.polygon[i];
      const Bary<FT>& r = cell.polygon[(i + 1) % n];
      const Bary<FT>& s = cell.polygon[(i + 2) % n];
      CHECK(same(p[0] + p[1] + p[2], FT(1)));
      for(int k = 0; k < 3; ++k) CHECK(p[k] >= (exact<FT>() ? FT(0) : FT(-1e-12)));
      if constexpr(exact<FT>()) {
        CHECK(orient(p, r, s) > FT(0)); // strictly convex: every vertex a corner
        CHECK(cell.vertex_feature[i] == GR::internal::lower_envelope::feature_of(p));
        // the cell's field is the lowest at its corners
        for(std::size_t j = 0; j < d.size(); ++j) CHECK(field(d[cell.copy], p) <= field(d[j], p));
      }
      const std::size_t label = cell.edge_label[i];
      if(GR::is_triangle_edge_label(label)) {
        const int z = GR::zero_coordinate_of_triangle_edge(GR::triangle_edge_of_label(label));
        CHECK(p[z] == FT(0));
        CHECK(r[z] == FT(0));
      } else {
        REQUIRE(label < d.size());
        CHECK(label != cell.copy);
        CHECK(same(field(d[cell.copy], p), field(d[label], p)));
        CHECK(same(field(d[cell.copy], r), field(d[label], r)));
        if constexpr(exact<FT>()) {
          // the neighbour has the same edge, reversed, labelled with this copy
          const GR::Envelope_cell<FT>* other = find_cell(env, label);
          REQUIRE(other != nullptr);
          int matches = 0;
          const std::size_t m = other->polygon.size();
          for(std::size_t t = 0; t < m; ++t)
            if(other->polygon[t] == r && other->polygon[(t + 1) % m] == p) {
              ++matches;
              CHECK(other->edge_label[t] == cell.copy);
            }
          CHECK(matches == 1);
        }
      }
    }
  }
  // segments: one per labelled edge pair, copy_a < copy_b, on the bisector,
  // copy_a on the left
  std::size_t labelled_edges = 0;
  for(const auto& cell : env.cells)
    for(std::size_t l : cell.edge_label) labelled_edges += GR::is_triangle_edge_label(l) ? 0 : 1;
  if constexpr(exact<FT>()) CHECK(2 * env.segments.size() == labelled_edges);
  for(const auto& s : env.segments) {
    CHECK(s.copy_a < s.copy_b);
    REQUIRE(s.copy_b < d.size());
    for(int e = 0; e < 2; ++e) {
      const Bary<FT>& p = s.endpoints[e];
      CHECK(same(field(d[s.copy_a], p), field(d[s.copy_b], p)));
      CHECK(same(p[0] + p[1] + p[2], FT(1)));
      for(int k = 0; k < 3; ++k) CHECK(p[k] >= (exact<FT>() ? FT(0) : FT(-1e-12)));
      if constexpr(exact<FT>()) CHECK(s.endpoint_feature[e] == GR::internal::lower_envelope::feature_of(p));
    }
    // an edge of copy_a's cell; with double, when round-off made the two cells
    // disagree, possibly only an edge of copy_b's cell, reversed
    auto has_edge = [&](std::size_t copy, std::size_t other, int first) {
      const GR::Envelope_cell<FT>* c = find_cell(env, copy);
      if(c == nullptr) return false;
      const std::size_t n = c->polygon.size();
      for(std::size_t t = 0; t < n; ++t)
        if(c->edge_label[t] == other && same_point(c->polygon[t], s.endpoints[first]) &&
           same_point(c->polygon[(t + 1) % n], s.endpoints[1 - first]))
          return true;
      return false;
    };
    if constexpr(exact<FT>()) CHECK(has_edge(s.copy_a, s.copy_b, 0));
    else CHECK((has_edge(s.copy_a, s.copy_b, 0) || has_edge(s.copy_b, s.copy_a, 1)));
  }
}

template <class FT>
GR::Lower_envelope<FT> envelope(const std::vector<Distances>& d)
{
  GR::Lower_envelope<FT> env = GR::compute_lower_envelope<FT>(d);
  check_invariants(d, env);
  return env;
}

} // namespace

#define ENVELOPE_TYPES Exact_FT, CGAL::Gmpq, double

TEMPLATE_TEST_CASE("lower envelope: one copy is the whole triangle", "[lower_envelope]", ENVELOPE_TYPES)
{
  typedef TestType FT;
  const auto env = envelope<FT>({{{1.5, -2.0, 7.25}}});
  REQUIRE(env.cells.size() == 1);
  CHECK(env.segments.empty());
  const auto& c = env.cells[0];
  CHECK(c.copy == 0);
  REQUIRE(c.polygon.size() == 3);
  CHECK(c.polygon[0] == bary<FT>(1, 0, 0));
  CHECK(c.polygon[1] == bary<FT>(0, 1, 0));
  CHECK(c.polygon[2] == bary<FT>(0, 0, 1));
  for(int k = 0; k < 3; ++k) {
    CHECK(c.edge_label[k] == GR::triangle_edge_label(k));
    CHECK(c.vertex_feature[k] == on_vertex(k));
  }
  CHECK(GR::barycentric_area(c.polygon) == q<FT>(1, 2));
}

TEMPLATE_TEST_CASE("lower envelope: two copies with a known bisector", "[lower_envelope]", ENVELOPE_TYPES)
{
  typedef TestType FT;
  // f0 - f1 = λ1 - λ0: copy 0 wins where λ0 ≥ λ1; the ridge is λ0 = λ1.
  const auto env = envelope<FT>({{{0, 1, 1}}, {{1, 0, 1}}});
  REQUIRE(env.cells.size() == 2);
  REQUIRE(env.segments.size() == 1);
  const auto& s = env.segments[0];
  CHECK(s.copy_a == 0);
  CHECK(s.copy_b == 1);
  const Bary<FT> top = bary<FT>(0, 0, 1), mid = bary<FT>(q<FT>(1, 2), q<FT>(1, 2), 0);
  CHECK(segment_is(s, top, mid));
  CHECK(feature_at(s, top) == on_vertex(2));
  CHECK(feature_at(s, mid) == on_edge(0));
  // copy_a's cell (corner 0 side, λ1 < λ0) is on the left of endpoints[0] -> endpoints[1]
  CHECK(orient(s.endpoints[0], s.endpoints[1], bary<FT>(1, 0, 0)) > FT(0));
  for(const auto& c : env.cells) CHECK(GR::barycentric_area(c.polygon) == q<FT>(1, 4));
}

TEMPLATE_TEST_CASE("lower envelope: coincident fields", "[lower_envelope]", ENVELOPE_TYPES)
{
  typedef TestType FT;
  SECTION("two identical copies: the lower index takes the whole face")
  {
    const auto env = envelope<FT>({{{3, 1, 2}}, {{3, 1, 2}}});
    REQUIRE(env.cells.size() == 1);
    CHECK(env.cells[0].copy == 0);
    CHECK(env.segments.empty());
  }
  SECTION("three identical copies")
  {
    const auto env = envelope<FT>({{{0.1, 0.7, 0.3}}, {{0.1, 0.7, 0.3}}, {{0.1, 0.7, 0.3}}});
    REQUIRE(env.cells.size() == 1);
    CHECK(env.cells[0].copy == 0);
    CHECK(env.segments.empty());
  }
  SECTION("identical up to a constant: the lower field wins everywhere")
  {
    const auto env = envelope<FT>({{{3, 1, 2}}, {{2.5, 0.5, 1.5}}, {{4, 2, 3}}});
    REQUIRE(env.cells.size() == 1);
    CHECK(env.cells[0].copy == 1);
    CHECK(env.segments.empty());
  }
  SECTION("an identical pair and a third copy")
  {
    const Distances a = {{0, 1, 1}}, b = {{1, 0, 1}};
    for(int order = 0; order < 3; ++order) {
      std::vector<Distances> d = order == 0 ? std::vector<Distances>{a, a, b}
                               : order == 1 ? std::vector<Distances>{b, a, a}
                                            : std::vector<Distances>{a, b, a};
      const auto env = envelope<FT>(d);
      REQUIRE(env.cells.size() == 2);
      REQUIRE(env.segments.size() == 1);
      const std::size_t a_index = order == 1 ? 1 : 0, b_index = order == 0 ? 2 : order == 1 ? 0 : 1;
      CHECK(find_cell(env, a_index) != nullptr);
      CHECK(find_cell(env, b_index) != nullptr);
      CHECK(segment_is(env.segments[0], bary<FT>(0, 0, 1), bary<FT>(q<FT>(1, 2), q<FT>(1, 2), 0)));
    }
  }
  SECTION("three fields through one line: the edge is labelled with the copy across it")
  {
    // f1 - f0 = λ0 - λ1, f2 - f0 = 2(λ0 - λ1): copy 1 is never lowest on an open set.
    const auto env = envelope<FT>({{{5, 5, 5}}, {{6, 4, 5}}, {{7, 3, 5}}});
    REQUIRE(env.cells.size() == 2);
    CHECK(find_cell(env, 0) != nullptr);
    CHECK(find_cell(env, 2) != nullptr);
    REQUIRE(env.segments.size() == 1);
    CHECK(env.segments[0].copy_a == 0);
    CHECK(env.segments[0].copy_b == 2);
    CHECK(segment_is(env.segments[0], bary<FT>(0, 0, 1), bary<FT>(q<FT>(1, 2), q<FT>(1, 2), 0)));
  }
}

TEMPLATE_TEST_CASE("lower envelope: three fields through one point", "[lower_envelope]", ENVELOPE_TYPES)
{
  typedef TestType FT;
  SECTION("symmetric: the junction is the centroid")
  {
    const auto env = envelope<FT>({{{0, 1, 1}}, {{1, 0, 1}}, {{1, 1, 0}}});
    REQUIRE(env.cells.size() == 3);
    REQUIRE(env.segments.size() == 3);
    const Bary<FT> centroid = bary<FT>(q<FT>(1, 3), q<FT>(1, 3), q<FT>(1, 3));
    for(const auto& s : env.segments) {
      CHECK((same_point(s.endpoints[0], centroid) || same_point(s.endpoints[1], centroid)));
      CHECK(feature_at(s, centroid) == inside());
    }
    for(const auto& c : env.cells) CHECK(same(GR::barycentric_area(c.polygon), q<FT>(1, 6)));
  }
  SECTION("generic: the junction is the exact solution of f0 = f1 = f2")
  {
    const std::vector<Distances> d = {{{0.1, 1.3, 0.9}}, {{1.7, 0.2, 1.1}}, {{1.2, 1.4, 0.05}}};
    const auto env = envelope<FT>(d);
    REQUIRE(env.cells.size() == 3);
    REQUIRE(env.segments.size() == 3);
    // Cramer on the rows (d0 - d1), (d1 - d2), (1, 1, 1): λ = (a × b) / Σ(a × b).
    std::array<FT, 3> a, b;
    for(int k = 0; k < 3; ++k) {
      a[k] = FT(d[0][k]) - FT(d[1][k]);
      b[k] = FT(d[1][k]) - FT(d[2][k]);
    }
    std::array<FT, 3> x = {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
    const FT s = x[0] + x[1] + x[2];
    for(FT& v : x) v /= s;
    for(int k = 0; k < 3; ++k) REQUIRE(x[k] > FT(0)); // the junction is inside
    // Exactly one shared endpoint, the junction, and the same numbers in all three segments.
    for(const auto& seg : env.segments) {
      const int e = same_point(seg.endpoints[0], x) ? 0 : 1;
      CHECK(same_point(seg.endpoints[e], x));
      CHECK(!same_point(seg.endpoints[1 - e], x));
      CHECK(seg.endpoint_feature[e] == inside());
      if constexpr(exact<FT>()) CHECK(seg.endpoints[e] == x);
    }
  }
}

TEMPLATE_TEST_CASE("lower envelope: nearly parallel fields", "[lower_envelope]", ENVELOPE_TYPES)
{
  typedef TestType FT;
  const double eps = 1e-15;
  SECTION("differences of 1e-15 relative still give an exact partition")
  {
    const Distances base = {{1.0, 2.0, 3.0}};
    std::vector<Distances> d = {
      base,
      {{base[0] * (1 + eps), base[1] * (1 - eps), base[2]}},
      {{base[0], base[1] * (1 + 2 * eps), base[2] * (1 - eps)}},
      {{base[0] * (1 - eps), base[1] * (1 + eps), base[2] * (1 + eps)}}};
    const auto env = envelope<FT>(d);
    CHECK(env.cells.size() >= 2);
    if constexpr(exact<FT>()) CHECK(total_area(env) == q<FT>(1, 2));
  }
  SECTION("a field lower by a tiny constant plus a tinier slope")
  {
    // f1 - f0 = -e + (e/2) λ2 < 0 on the whole face (e ≈ 1e-15): copy 1 wins everywhere.
    const double e = 1 - (1 - eps);
    const auto env = envelope<FT>({{{1, 1, 1}}, {{1 - e, 1 - e, 1 - e / 2}}});
    if constexpr(exact<FT>()) {
      REQUIRE(env.cells.size() == 1);
      CHECK(env.cells[0].copy == 1);
      CHECK(env.segments.empty());
    }
  }
  SECTION("planes that differ by 1e-15 at the corners cross where the exact result says")
  {
    // f0 - f1 = eps·(λ1 - λ0) (up to the rounding of 1 + eps): the ridge is λ0 = λ1.
    const double one_plus = 1 + eps, d_eps = one_plus - 1;
    const auto env = envelope<FT>({{{1, one_plus, 1}}, {{one_plus, 1, 1}}});
    REQUIRE(d_eps > 0);
    REQUIRE(env.segments.size() == 1);
    CHECK(segment_is(env.segments[0], bary<FT>(0, 0, 1), bary<FT>(q<FT>(1, 2), q<FT>(1, 2), 0)));
  }
}

TEMPLATE_TEST_CASE("lower envelope: breakpoints on triangle corners and edges", "[lower_envelope]", ENVELOPE_TYPES)
{
  typedef TestType FT;
  SECTION("a bisector from corner 0 to edge 1")
  {
    const auto env = envelope<FT>({{{5, 1, 3}}, {{5, 3, 1}}});
    REQUIRE(env.segments.size() == 1);
    const auto& s = env.segments[0];
    const Bary<FT> c0 = bary<FT>(1, 0, 0), e1 = bary<FT>(0, q<FT>(1, 2), q<FT>(1, 2));
    CHECK(segment_is(s, c0, e1));
    CHECK(feature_at(s, c0) == on_vertex(0));
    CHECK(feature_at(s, e1) == on_edge(1));
  }
  SECTION("three cells meeting at a point of edge 0")
  {
    // All three fields equal at (1/2, 1/2, 0); cells 0 and 1 touch only there.
    const auto env = envelope<FT>({{{0, 2, 1}}, {{2, 0, 1}}, {{1, 1, 0}}});
    REQUIRE(env.cells.size() == 3);
    REQUIRE(env.segments.size() == 2);
    const Bary<FT> junction = bary<FT>(q<FT>(1, 2), q<FT>(1, 2), 0);
    CHECK(env.segments[0].copy_a == 0);
    CHECK(env.segments[0].copy_b == 2);
    CHECK(segment_is(env.segments[0], junction, bary<FT>(q<FT>(1, 2), 0, q<FT>(1, 2))));
    CHECK(env.segments[1].copy_a == 1);
    CHECK(env.segments[1].copy_b == 2);
    CHECK(segment_is(env.segments[1], junction, bary<FT>(0, q<FT>(1, 2), q<FT>(1, 2))));
    for(const auto& s : env.segments) CHECK(feature_at(s, junction) == on_edge(0));
    CHECK(GR::barycentric_area(find_cell(env, 0)->polygon) == q<FT>(1, 8));
    CHECK(GR::barycentric_area(find_cell(env, 1)->polygon) == q<FT>(1, 8));
    CHECK(GR::barycentric_area(find_cell(env, 2)->polygon) == q<FT>(1, 4));
  }
  SECTION("three cells meeting at corner 2")
  {
    const auto env = envelope<FT>({{{0, 3, 5}}, {{3, 0, 5}}, {{1, 1, 5}}});
    REQUIRE(env.cells.size() == 3);
    REQUIRE(env.segments.size() == 2);
    const Bary<FT> c2 = bary<FT>(0, 0, 1);
    CHECK(segment_is(env.segments[0], c2, bary<FT>(q<FT>(2, 3), q<FT>(1, 3), 0)));
    CHECK(segment_is(env.segments[1], c2, bary<FT>(q<FT>(1, 3), q<FT>(2, 3), 0)));
    for(const auto& s : env.segments) {
      CHECK(feature_at(s, c2) == on_vertex(2));
      const Bary<FT>& other = same_point(s.endpoints[0], c2) ? s.endpoints[1] : s.endpoints[0];
      CHECK(feature_at(s, other) == on_edge(0));
    }
  }
}

TEMPLATE_TEST_CASE("lower envelope: dominated copies drop out", "[lower_envelope]", ENVELOPE_TYPES)
{
  typedef TestType FT;
  SECTION("dominated at the three corners, strictly or with equal corners")
  {
    // copy 1: higher everywhere; copy 2: equal at corner 0 only (a point);
    // copy 3: equal on edge 0 (a segment); copy 4: identical to copy 0.
    const auto env = envelope<FT>({{{1, 1, 1}}, {{2, 1.5, 3}}, {{1, 2, 2}}, {{1, 1, 2}}, {{1, 1, 1}}});
    REQUIRE(env.cells.size() == 1);
    CHECK(env.cells[0].copy == 0);
    CHECK(env.segments.empty());
  }
  SECTION("beaten by the envelope of two others, not by either alone")
  {
    const auto env = envelope<FT>({{{0, 4, 4}}, {{4, 0, 4}}, {{3, 3, 10}}});
    REQUIRE(env.cells.size() == 2);
    CHECK(find_cell(env, 2) == nullptr);
    REQUIRE(env.segments.size() == 1);
    CHECK(segment_is(env.segments[0], bary<FT>(0, 0, 1), bary<FT>(q<FT>(1, 2), q<FT>(1, 2), 0)));
  }
}

TEMPLATE_TEST_CASE("lower envelope: random envelopes are lowest and partition the face", "[lower_envelope]",
                   ENVELOPE_TYPES)
{
  typedef TestType FT;
  const int trials = 40, samples = 200;
  const unsigned base_seed = 20260;
  std::cout << "lower_envelope random test: seeds " << base_seed << ".." << base_seed + trials - 1 << "\n";
  for(int trial = 0; trial < trials; ++trial) {
    CGAL::Random rng(base_seed + trial);
    INFO("CGAL::Random seed " << rng.get_seed());
    const int m = rng.get_int(2, 9);
    // Half of the trials on small integers: coincidences, three fields
    // through a point, on an edge or a corner, happen all the time there.
    const bool small_integers = (trial % 2 == 0);
    std::vector<Distances> d(m);
    for(auto& row : d)
      for(double& v : row) v = small_integers ? rng.get_int(0, 4) : rng.get_double(0, 10);
    const GR::Lower_envelope<FT> env = envelope<FT>(d);

    // (b) at random points, the copy whose cell holds the point is lowest there
    for(int k = 0; k < samples; ++k) {
      double u = rng.get_double(), v = rng.get_double();
      if(u + v > 1) { u = 1 - u; v = 1 - v; }
      if(k % 10 == 0) v = 0; // on edge 0 every tenth time
      const Bary<FT> x = bary<FT>(FT(1) - FT(u) - FT(v), FT(u), FT(v));
      FT lowest = field(d[0], x);
      std::size_t winner = 0;
      for(std::size_t j = 1; j < d.size(); ++j)
        if(field(d[j], x) < lowest) { lowest = field(d[j], x); winner = j; }
      int holders = 0;
      for(const auto& cell : env.cells) {
        const std::size_t n = cell.polygon.size();
        bool in = true, strictly_in = true;
        for(std::size_t i = 0; i < n; ++i) {
          const FT o = orient(cell.polygon[i], cell.polygon[(i + 1) % n], x);
          if(o < (exact<FT>() ? FT(0) : FT(-1e-12))) in = false;
          if(!(o > FT(0))) strictly_in = false;
        }
        if(!in) continue;
        ++holders;
        if constexpr(exact<FT>()) {
          CHECK(field(d[cell.copy], x) == lowest);
          if(strictly_in) CHECK(cell.copy == winner); // ties go to the lower index
        } else {
          CHECK(field(d[cell.copy], x) <= lowest + 1e-9);
        }
      }
      CHECK(holders >= 1);
    }

    // the double result agrees with the exact one, cell by cell
    if constexpr(!exact<FT>()) {
      const auto ref = GR::compute_lower_envelope<Exact_FT>(d);
      std::map<std::size_t, double> area;
      for(const auto& c : env.cells) area[c.copy] += GR::barycentric_area(c.polygon);
      for(const auto& c : ref.cells) area[c.copy] -= CGAL::to_double(GR::barycentric_area(c.polygon));
      for(const auto& a : area) CHECK(std::abs(a.second) <= 1e-9);
    }
  }
}

TEST_CASE("lower envelope: clipping in CGAL::Mpzf gives the same result as in CGAL::Gmpq", "[lower_envelope]")
{
#ifdef CGAL_HAS_MPZF
  namespace LE = GR::internal::lower_envelope;
  const int trials = 200;
  const unsigned base_seed = 31337;
  std::cout << "lower_envelope Mpzf test: seeds " << base_seed << ".." << base_seed + trials - 1 << "\n";
  for(int trial = 0; trial < trials; ++trial) {
    CGAL::Random rng(base_seed + trial);
    INFO("CGAL::Random seed " << rng.get_seed());
    const int m = rng.get_int(2, 9);
    std::vector<Distances> d(m);
    for(auto& row : d)
      for(double& v : row) {
        switch(trial % 3) {
          case 0: v = rng.get_int(0, 4); break;                                 // coincidences
          case 1: v = rng.get_double(0, 10); break;                             // generic
          default: v = 100 + rng.get_double(0, 1e-9) * rng.get_int(0, 3); break; // nearly parallel
        }
      }
    const auto a = LE::compute<CGAL::Gmpq, CGAL::Mpzf>(d);
    const auto b = LE::compute<CGAL::Gmpq, CGAL::Gmpq>(d);
    REQUIRE(a.cells.size() == b.cells.size());
    for(std::size_t c = 0; c < a.cells.size(); ++c) {
      CHECK(a.cells[c].copy == b.cells[c].copy);
      CHECK(a.cells[c].edge_label == b.cells[c].edge_label);
      CHECK(a.cells[c].polygon == b.cells[c].polygon);
      CHECK(a.cells[c].vertex_feature == b.cells[c].vertex_feature);
    }
    REQUIRE(a.segments.size() == b.segments.size());
    for(std::size_t i = 0; i < a.segments.size(); ++i) {
      CHECK(a.segments[i].copy_a == b.segments[i].copy_a);
      CHECK(a.segments[i].copy_b == b.segments[i].copy_b);
      CHECK(a.segments[i].endpoints == b.segments[i].endpoints);
    }
  }
#else
  WARN("CGAL::Mpzf is not available here: the clipping runs in the output type");
#endif
}

TEST_CASE("lower envelope: bad input is an error", "[lower_envelope]")
{
  CHECK_THROWS_AS(GR::compute_lower_envelope(std::vector<Distances>{}), GR::Invalid_parameter_error);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(GR::compute_lower_envelope({{{0, 1, 2}}, {{0, nan, 2}}}), GR::Invalid_parameter_error);
  CHECK_THROWS_AS(GR::compute_lower_envelope({{{inf, 1, 2}}}), GR::Invalid_parameter_error);
}

TEST_CASE("lower envelope: barycentric points to 3D", "[lower_envelope]")
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point_3;
  const Point_3 p0(1, 2, 3), p1(4, -1, 0.5), p2(-2, 0, 7);
  const auto env = GR::compute_lower_envelope({{{0, 1, 1}}, {{1, 0, 1}}});
  REQUIRE(env.segments.size() == 1);
  for(const auto& e : env.segments[0].endpoints) {
    const Point_3 p = GR::barycentric_to_point(e, p0, p1, p2);
    if(e[2] == 1) CHECK(p == p2); // a corner is the corner, exactly
    else CHECK(p == Point_3(2.5, 0.5, 1.75));
  }
}
