// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 pass: free ends that are no ends of a cut locus pruned, repeatedly.
// Test: test_ridge_passes.cpp, the three "prune_spurs: ..." cases (each rule,
// on and off).
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_PRUNE_SPURS_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_PRUNE_SPURS_H

#include <Geodesic_ridge/internal/corner_angles.h>
#include <Geodesic_ridge/internal/ridge_curve/ridge_graph.h>
#include <Geodesic_ridge/internal/ridge_curve/ridge_passes.h>

#include <CGAL/boost/graph/iterator.h>

#include <cmath>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// Stage 3 pass: spurs pruned, each by a named rule with a counter of its own.
template <class Ridge>
class Spur_pruning
{
  typedef typename Ridge::Point Point;
  typedef typename Ridge::vertex_descriptor vertex_descriptor;
  static constexpr std::size_t none = Ridge::none;

public:
  Spur_pruning(Ridge& ridge, Ridge_passes passes) : ridge(ridge), passes(passes) {}

  // Free ends of the ridge that end no cut locus (the rules below) are
  // pruned, repeatedly: each pruned segment may make its other end free.
  // Cycles and segments between junctions are never touched.
  void run()
  {
    std::vector<char> on_impossible_chain(ridge.nodes.size(), 0);
    Curvature_near curvature_near(*this);
    std::vector<std::vector<std::size_t> > at(ridge.nodes.size());
    std::vector<std::size_t> live(ridge.nodes.size(), 0);
    for(std::size_t i = 0; i < ridge.segments.size(); ++i)
      if(ridge.segments[i].ridge && ridge.segments[i].a != ridge.segments[i].b)
      {
        at[ridge.segments[i].a].push_back(i); at[ridge.segments[i].b].push_back(i);
        ++live[ridge.segments[i].a]; ++live[ridge.segments[i].b];
      }
    std::vector<std::size_t> leaves;
    // (a node on the border is no free end: the ridge goes on along the border)
    for(std::size_t v = 0; v < ridge.nodes.size(); ++v) if(live[v] == 1 && ridge.node_loop[v] == none) leaves.push_back(v);
    while(!leaves.empty())
    {
      const std::size_t v = leaves.back();
      leaves.pop_back();
      if(live[v] != 1) continue;
      std::size_t seg = none;
      for(std::size_t i : at[v]) if(ridge.segments[i].ridge) { seg = i; break; }
      if(seg == none) continue;
      const double angle = ridge.segments[seg].angle, curvature_here = curvature_near(v);
      const bool impossible_end = on_impossible_chain[v] || at_vertex_without_curvature(v);
      const Rule rule = rule_for(angle, curvature_here, impossible_end);
      if(rule == Rule::none) continue;
      ridge.segments[seg].ridge = false;
      ++counter(rule);
      if(rule != Rule::flat_end) ++ridge.statistics.pruned_spur_segments; // (the weak rules' sum)
      --live[v];
      const std::size_t w = ridge.segments[seg].a == v ? ridge.segments[seg].b : ridge.segments[seg].a;
      if(rule != Rule::flat_end && impossible_end && passes.on(Ridge_pass::spur_at_impossible_end))
        on_impossible_chain[w] = 1;
      if(--live[w] == 1 && ridge.node_loop[w] == none) leaves.push_back(w);
    }
  }

private:
  // The rules, asked in this order; the first that holds prunes the end's
  // segment and is counted. A weak end (its segment's jump below the minimum
  // angle) is pruned at an impossible end, away from a corner, or at a corner
  // with too small a jump; an end no weak rule prunes is pruned when flat.
  enum class Rule { none, impossible_end, away_from_corner, too_weak_for_corner, flat_end };
  Rule rule_for(double angle, double curvature_here, bool impossible_end) const
  {
    if(weak(angle))
    {
      if(passes.on(Ridge_pass::spur_at_impossible_end) && impossible_end) return Rule::impossible_end;
      if(passes.on(Ridge_pass::spur_away_from_corner) && !at_corner(curvature_here)) return Rule::away_from_corner;
      if(passes.on(Ridge_pass::spur_too_weak_for_corner) && too_weak_for_a_corner(angle))
        return Rule::too_weak_for_corner;
    }
    if(passes.on(Ridge_pass::spur_flat_end) && flat_end(angle, curvature_here)) return Rule::flat_end;
    return Rule::none;
  }
  std::size_t& counter(Rule rule) const
  {
    Ridge_curve_statistics& st = ridge.statistics;
    switch(rule)
    {
    case Rule::impossible_end: return st.spurs_at_impossible_ends;
    case Rule::away_from_corner: return st.spurs_away_from_corners;
    case Rule::too_weak_for_corner: return st.spurs_too_weak_for_corners;
    default: return st.pruned_flat_end_segments;
    }
  }

  // A free end whose segment's gradient jump is below `minimum_angle` cannot
  // be located (two fronts meeting at a small angle).
  bool weak(double angle) const { return angle < ridge.minimum_angle; }

  // A weak free end with at least this much curvature around it (a cube's
  // corner has 90 degrees) ends where the cut locus must: at a vertex of
  // positive curvature. It is kept: its position is ill-conditioned, but the
  // branch is real. Measured (bench_ridge_accuracy): bunny_1k v0 recall p95
  // 2.38 -> 0.75 mean edges, precision p95 0.27 -> 0.44; the convex test
  // polyhedra reach 8 more corners.
  bool at_corner(double curvature_here) const
  {
    return curvature_here >= radians(tuning::ridge::spur_corner_degrees);
  }

  // But not every weak end there: the cut locus ends at a vertex of positive
  // curvature with a jump about that vertex's angle deficit (the two fronts
  // come around it on either side), so an end whose jump is a small part of
  // the minimum angle ends at no corner. Near a CAD model's box corners
  // (about 90 degrees in one vertex, a fan of long faces) the assembly
  // leaves spurs that the corner rule kept: fandisk from v5827 has 69
  // leaves, 38 of them with jumps of 0.0001-4.5 degrees within 2.5 mean
  // edges of one of eight corners of 79-91 degrees (spurs of 0.1-1.9 mean
  // edges). Measured (bench_ridge_accuracy, exact): real models' precision
  // p95 <= 0.25 on 47 -> 50 of 72 pairs, fandisk's median 0.44 -> 0.31.
  bool too_weak_for_a_corner(double angle) const
  {
    return angle < ridge.minimum_angle / tuning::ridge::spur_corner_end_divisor;
  }

  // But a weak end exactly at a vertex of M without positive curvature (a
  // saddle, or a flat vertex of a CAD model's face) ends where the cut locus
  // cannot, whatever the curvature around it: the ridge drawn there is a
  // false branch (or one that ran past its true end), and the whole chain
  // of weak segments behind it goes, corner or not (`on_impossible_chain`).
  // Measured (bench_ridge_accuracy, exact): real models' precision p95 <= 0.5
  // on 70 -> 72 of 72 pairs (fandisk v3237 0.34 -> 0.16, suzanne v0 0.58 ->
  // 0.39), the CAD boxes 10 -> 16 of 24; a floor of 5 degrees of curvature
  // instead of 0 lost a real branch of bunny_7k (recall 0.03 -> 5.9 mean edges).
  // (The test itself: `at_vertex_without_curvature`.)

  // A free end of the cut locus of a polyhedral surface is a vertex of
  // positive curvature (angle sum < 2π): a free end with no such curvature
  // around it (within 2.5 mean edges, summed with signs) is no ridge end,
  // typically the crease along the shadow line of the tip of a false branch
  // of K, where two copies that are both slightly inexact meet at a moderate
  // angle (below 3 x `minimum_angle`; a branch that stops short of its true
  // end has a large one).
  bool flat_end(double angle, double curvature_here) const
  {
    return curvature_here < radians(tuning::ridge::spur_curvature_share * ridge.minimum_angle) &&
           angle < 3 * ridge.minimum_angle;
  }

  // Gaussian curvature of a vertex (by index) as `Corner_angles::curvature`;
  // none on the border (its angle sum measures the border's turning)
  double vertex_curvature(std::size_t v) const { return ridge.loop_of_vertex[v] == none ? 2 * CGAL_PI - ridge.angle_sum[v] : 0.0; }

  // Whether a node lies exactly on an inner vertex of M whose curvature is not
  // positive: a saddle, or a flat vertex (below 1e-9 radians: the rounding of
  // a flat vertex's angle sum).
  bool at_vertex_without_curvature(std::size_t node) const
  {
    const Ridge_point<Point>& p = ridge.nodes[node];
    const auto h = ridge.faces.corner_halfedges(p.face);
    for(int i = 0; i < 3; ++i)
      if(p.barycentric[i] == 1.0) // (exact: a node at a vertex has λ = 1 there)
      {
        const std::size_t v = get(ridge.maps.vim, source(h[i], ridge.tm));
        return ridge.loop_of_vertex[v] == none && vertex_curvature(v) <= tuning::ridge::flat_vertex_curvature;
      }
    return false;
  }

  // The total curvature of the vertices within 2.5 mean edges of a node (grown
  // from its face's corners).
  struct Curvature_near
  {
    const Spur_pruning& a;
    std::vector<vertex_descriptor> vertex_of;
    std::vector<std::size_t> seen_at;

    explicit Curvature_near(const Spur_pruning& assembler)
      : a(assembler), vertex_of(num_vertices(a.ridge.tm)), seen_at(num_vertices(a.ridge.tm), none)
    {
      for(vertex_descriptor v : vertices(a.ridge.tm)) vertex_of[get(a.ridge.maps.vim, v)] = v;
    }

    double operator()(std::size_t node)
    {
      const double radius = tuning::ridge::curvature_radius * a.ridge.mean_edge;
      const Point& p = a.ridge.nodes[node].point;
      std::vector<std::size_t> stack;
      double total = 0;
      for(const auto h : a.ridge.faces.corner_halfedges(a.ridge.nodes[node].face))
      {
        const std::size_t v = get(a.ridge.maps.vim, source(h, a.ridge.tm));
        if(seen_at[v] != node) { seen_at[v] = node; stack.push_back(v); total += a.vertex_curvature(v); }
      }
      while(!stack.empty())
      {
        const std::size_t v = stack.back();
        stack.pop_back();
        for(auto h : CGAL::halfedges_around_target(halfedge(vertex_of[v], a.ridge.tm), a.ridge.tm))
        {
          const std::size_t w = get(a.ridge.maps.vim, source(h, a.ridge.tm));
          if(seen_at[w] == node) continue;
          seen_at[w] = node;
          if(std::sqrt(CGAL::to_double(CGAL::squared_distance(get(a.ridge.maps.vpm, vertex_of[w]), p))) > radius) continue;
          total += a.vertex_curvature(w);
          stack.push_back(w);
        }
      }
      return total;
    }
  };

  Ridge& ridge;
  const Ridge_passes passes;
};

template <class Ridge>
void prune_spurs(Ridge& ridge, Ridge_passes passes)
{
  Spur_pruning<Ridge>(ridge, passes).run();
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_PRUNE_SPURS_H
