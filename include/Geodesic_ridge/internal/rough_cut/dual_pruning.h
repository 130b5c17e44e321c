// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1, step 3a: which dual edges K follows. The pruning by significance,
// the false branches pruned back (no curvature enclosed), the pruned branches
// kept for the curvature they reach (the leaf extension), and the roles the
// result reports for them.
#ifndef GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_DUAL_PRUNING_H
#define GEODESIC_RIDGE_INTERNAL_ROUGH_CUT_DUAL_PRUNING_H

#include <Geodesic_ridge/internal/rough_cut/state.h>
#include <Geodesic_ridge/internal/tuning.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace Geodesic_ridge::internal::rough_cut {

// Step 3: keep the dual edges of significance at least tolerance × area.
template <class TriangleMesh, class Maps>
void prune_by_significance(State<TriangleMesh, Maps>& s)
{
  s.threshold = s.r.tolerance * s.r.total_area;
  s.kept.assign(s.nd, 0);
  s.extension.assign(s.nd, 0);
  for(std::size_t d = 0; d < s.nd; ++d)
    if(s.significance(d) >= s.threshold) { s.kept[d] = 1; ++s.nkept; }
  if(s.nkept == 0 && s.nd > 0 && !s.has_boundary())
  {
    // Genus 0 with a tolerance close to 1/2: keep the most significant dual
    // edge, so that K is one slit and the cut surface still a disk.
    std::size_t best = 0;
    for(std::size_t d = 1; d < s.nd; ++d)
      if(s.significance(d) > s.significance(best)) best = d;
    s.kept[best] = 1;
    s.nkept = 1;
    s.st.fallback_single_rung = true;
  }
  s.kept_degree.assign(s.nf + 1, 0);
  for(std::size_t d = 0; d < s.nd; ++d)
    if(s.kept[d])
    {
      ++s.kept_degree[s.dual_faces_of[d][0]];
      ++s.kept_degree[s.dual_faces_of[d][1]];
    }
}

// Branches that enclose no curvature are false (see parameters::branch_curvature):
// pruned back from their tips while the curvature beyond the tip's dual edge
// is below the minimum. The 2-core (genus) is never touched; one dual edge at
// least is kept.
template <class TriangleMesh, class Maps>
void prune_false_branches(State<TriangleMesh, Maps>& s)
{
  s.false_branch.assign(s.nd, 0);
  if(s.options.branch_curvature > 0 && !s.st.fallback_single_rung)
  {
    double total_curvature = 0, total_positive = 0;
    for(double c : s.curvature_share) total_curvature += c;
    for(double c : s.positive_share) total_positive += c;
    // the curvature, and its positive part, on the side of d that encloses the
    // two paths' meeting: the branch's side, or on genus 0 the side of less curvature
    auto enclosed = [&](std::size_t d) {
      const double c = s.subtree_curvature[d];
      if(s.st.genus == 0 && !s.has_boundary() && total_curvature - c < c)
        return std::make_pair(total_curvature - c, total_positive - s.subtree_positive[d]);
      return std::make_pair(c, s.subtree_positive[d]);
    };
    std::vector<std::size_t> tips;
    for(std::size_t f = 0; f < s.nf; ++f) if(s.kept_degree[f] == 1) tips.push_back(f);
    while(!tips.empty() && (s.nkept > 1 || s.has_boundary())) // (with a border, K may be empty)
    {
      const std::size_t f = tips.back();
      tips.pop_back();
      if(s.kept_degree[f] != 1) continue;
      std::size_t d = none;
      for(unsigned char k = 0; k < s.dual_degree[f]; ++k)
        if(s.kept[s.dual_of_face[f][k]]) d = s.dual_of_face[f][k];
      if(!s.peeled[d]) continue;
      // false: nearly no curvature enclosed, and no bump either (a bump with
      // its saddle-shaped foot encloses little in total but splits fronts)
      const auto [net, positive] = enclosed(d);
      if(net >= s.options.branch_curvature || positive >= 2 * s.options.branch_curvature) continue;
      s.kept[d] = 0;
      s.false_branch[d] = 1;
      --s.nkept;
      ++s.st.number_of_curvature_pruned_dual_edges;
      s.kept_degree[f] = 0;
      const std::size_t p = s.across(d, f);
      if(--s.kept_degree[p] == 1 && p != s.border_node()) tips.push_back(p);
    }
  }
  for(std::size_t f = 0; f < s.nf; ++f) s.st.number_of_kept_dual_leaves += (s.kept_degree[f] == 1);
}

// Extensions of the kept structure into pruned branches. The ridge shows only
// where K cuts: beyond K's end, the disk's copy of a face carries the smaller
// of the two fronts at its corners and dominates every other copy. The leaves
// of the cut locus of a polyhedral surface are vertices of positive curvature,
// so every pruned branch that holds at least `leaf_curvature` of Gaussian
// curvature is kept, outwards from the kept structure (paths to the curvature,
// branching only where two branches both hold enough). From the core outwards
// (reverse peeling order), so a branch's parent is decided first; with
// hysteresis: an added branch goes on into its child branch of most curvature
// while that holds a quarter of it, so that it reaches the vertex whose
// curvature its last faces share.
template <class TriangleMesh, class Maps>
void extend_leaves_by_curvature(State<TriangleMesh, Maps>& s)
{
  auto parent_of = [&](std::size_t d) { return s.across(d, s.child_face[d]); };
  std::vector<std::size_t> best_child(s.nf + 1, none);
  for(std::size_t d : s.peel_order)
  {
    const std::size_t p = parent_of(d);
    if(best_child[p] == none || s.subtree_curvature[d] > s.subtree_curvature[best_child[p]]) best_child[p] = d;
  }
  std::vector<char> inside(s.nf + 1, 0); // 1 kept (the border always), 2 reached by an extension
  for(std::size_t f = 0; f < s.nf; ++f) inside[f] = s.kept_degree[f] > 0 ? 1 : 0;
  inside[s.border_node()] = s.has_boundary() ? 1 : 0;
  for(auto it = s.peel_order.rbegin(); it != s.peel_order.rend(); ++it)
  {
    const std::size_t d = *it;
    const std::size_t p = parent_of(d);
    if(s.kept[d] || s.false_branch[d] || !inside[p]) continue;
    const bool goes_on =
        inside[p] == 2 && best_child[p] == d && s.subtree_curvature[d] >= tuning::rough_cut::extension_curvature_share * s.options.leaf_curvature;
    if(!goes_on && s.subtree_curvature[d] < s.options.leaf_curvature) continue;
    s.extension[d] = 1;
    inside[s.child_face[d]] = 2;
  }
}

// the roles and lists of the result for the dual edges (false branches, leaf
// extensions, kept), and the counts of leaves
template <class TriangleMesh, class Maps>
void record_dual_roles(State<TriangleMesh, Maps>& s)
{
  std::vector<unsigned char> degree_with_extension(s.kept_degree);
  degree_with_extension[s.border_node()] = 0; // (not a face: never a leaf)
  for(std::size_t d = 0; d < s.nd; ++d)
    if(s.extension[d])
    {
      ++degree_with_extension[s.dual_faces_of[d][0]];
      ++degree_with_extension[s.dual_faces_of[d][1]];
    }
  for(std::size_t f = 0; f < s.nf; ++f) s.st.number_of_extended_dual_leaves += (degree_with_extension[f] == 1);
  for(std::size_t d = 0; d < s.nd; ++d)
    if(s.false_branch[d]) s.r.edge_role[s.ei(s.r.dual_edges[d])] = Edge_role::dual_false_branch;
  for(std::size_t d = 0; d < s.nd; ++d)
    if(s.extension[d])
    {
      s.r.edge_role[s.ei(s.r.dual_edges[d])] = Edge_role::dual_leaf_extension;
      s.r.leaf_extension_edges.push_back(s.r.dual_edges[d]);
      ++s.st.number_of_leaf_extension_edges;
    }
  for(std::size_t d = 0; d < s.nd; ++d)
    if(s.kept[d])
    {
      s.r.edge_role[s.ei(s.r.dual_edges[d])] = Edge_role::dual_kept;
      s.r.kept_dual_edges.push_back(s.r.dual_edges[d]);
    }
  s.st.number_of_kept_dual_edges = s.nkept;
}

} // namespace Geodesic_ridge::internal::rough_cut

#endif
