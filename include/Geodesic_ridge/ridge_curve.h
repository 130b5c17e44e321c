// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3: the ridge curve (user manual, "Stage 3: The Ridge Curve").
//
// Every point of M is labelled by the copy that wins the lower envelope there.
// Two labels are the same front when their copies are glued in the extended
// surface across the edge between them (or carry equal fields, or agree along
// an edge of a thin face, whose gradient is noise). The ridge is
// every boundary between different fronts: inside faces (envelope edges) and
// along mesh edges. It is then made connected with the topology of the cut
// locus: the regions of M minus the ridge are merged (weakest ridge segment
// first) until one region is left, and detached pieces are dropped.
#ifndef GEODESIC_RIDGE_RIDGE_CURVE_H
#define GEODESIC_RIDGE_RIDGE_CURVE_H

#include <Geodesic_ridge/extended_surface.h>
#include <Geodesic_ridge/internal/coincident_points.h>
#include <Geodesic_ridge/internal/corner_angles.h>
#include <Geodesic_ridge/internal/graph_polylines.h>
#include <Geodesic_ridge/internal/union_find.h>
#include <Geodesic_ridge/lower_envelope.h>
#include <Geodesic_ridge/internal/face_copies.h>
#include <Geodesic_ridge/internal/faces_by_index.h>
#include <Geodesic_ridge/internal/field_gradients.h>
#include <Geodesic_ridge/internal/tuning.h>
#include <Geodesic_ridge/solvers/Face_cone.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Gmpq.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <queue>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// A point of the ridge: its surface location in M (face index, barycentric
/// coordinates in CGAL's order), its 3D point, and the angle between the two
/// fronts that meet there.
template <class Point_3>
struct Ridge_point
{
  /// the face of M (its index)
  std::size_t face = 0;
  /// barycentric coordinates in the face, in CGAL's corner order
  std::array<double, 3> barycentric = {{0, 0, 0}};
  /// the 3D point
  Point_3 point;
  /// degrees: the largest angle between the arrival directions of the two
  /// fronts over the ridge segments at this point
  double angle = 0;
};

/// \ingroup PkgGeodesicRidgeRef
/// \brief writes the 3D points of every polyline of `polylines` (as
/// `Ridge_curve::polylines` holds them) to `out`, one `std::vector<Point_3>`
/// per polyline: what `IO::write_polylines()` and CGAL's polyline tools take.
template <class Point_3, class OutputIterator>
OutputIterator ridge_polyline_points(const std::vector<std::vector<Ridge_point<Point_3> > >& polylines,
                                     OutputIterator out)
{
  for(const auto& polyline : polylines)
  {
    std::vector<Point_3> points;
    points.reserve(polyline.size());
    for(const Ridge_point<Point_3>& p : polyline) points.push_back(p.point);
    *out++ = std::move(points);
  }
  return out;
}

/// \ingroup PkgGeodesicRidgeRef
/// The linear field of one copy over its cell of an original face.
struct Ridge_region_cell
{
  std::size_t copy = 0;                     ///< face of the extended surface
  std::array<double, 3> field = {{0, 0, 0}}; ///< distances at the face's corners
  std::vector<std::array<double, 3> > polygon; ///< the cell, barycentric (rounded from exact)
};

/// \ingroup PkgGeodesicRidgeRef
/// Counts of stage 3.
struct Ridge_curve_statistics
{
  /// faces of M with more than one undominated copy
  std::size_t faces_with_several_copies = 0;
  std::size_t surviving_copies = 0;       ///< copies not dominated, over all faces
  std::size_t split_copies = 0;           ///< copies split at a kink between their corners' fronts (cones)
  std::size_t envelope_segments = 0;      ///< inside faces, between different fronts
  std::size_t edge_segments = 0;          ///< along mesh edges, between different fronts
  /// edge pieces of thin faces whose two sides are one front by their values
  /// alone (their gradients disagree; a thin face has none to trust)
  std::size_t thin_face_pieces = 0;
  std::size_t regions_before_merge = 0;   ///< components of M minus the raw ridge
  std::size_t merged_segments = 0;        ///< segments removed to merge regions
  std::size_t rejoined_segments = 0;      ///< merged segments put back to join two pieces of the ridge
  /// cell boundaries made ridge to join the pieces that hang from different border loops
  std::size_t border_joining_segments = 0;
  std::size_t dropped_components = 0;     ///< detached pieces dropped
  /// cell boundaries made ridge to join to the main piece the detached pieces
  /// that hold a verified kink (two fronts of one split copy)
  std::size_t piece_joining_segments = 0;
  std::size_t recombined_copies = 0;      ///< copies split into the fronts of nearer copies they recombine
  std::size_t pruned_spur_segments = 0;   ///< free-end segments with a gradient jump below the minimum angle
  std::size_t pruned_flat_end_segments = 0; ///< free-end segments with no positive curvature near their end
  /// ridge points computed again (from another face, or a few units of
  /// rounding from a vertex or an edge) that are one node of the ridge
  std::size_t coincident_points = 0;
  /// \name The Ridge
  //@{
  /// The ridge's segments, junctions (points where three or more regions
  /// meet), free ends (not on the border), connected components and
  /// independent cycles of the ridge with the border of M: 1 and 2g + b (b
  /// border loops; 2g on a closed mesh).
  std::size_t ridge_segments = 0, junctions = 0, free_ends = 0, components = 0, cycles = 0;
  //@}
  /// the ridge's total length
  double total_length = 0;
};

namespace internal {

typedef CGAL::Gmpq Exact_number;


// One field of a split copy with distances d: that of the front `front` (the
// owner of the corners k with owner[k] == front): d at its corners, its own
// value there (`value_at(k)`, never below d) at the others. The split fields'
// envelope keeps the copy's corner distances.
template <class ValueAt>
std::array<double, 3> split_field(const std::array<double, 3>& d, const std::array<std::size_t, 3>& owner,
                                  std::size_t front, const ValueAt& value_at)
{
  std::array<double, 3> field;
  for(int k = 0; k < 3; ++k) field[k] = owner[k] == front ? d[k] : std::max(d[k], value_at(k));
  return field;
}

// A copy that recombines fronts that nearer sheets carry apart. Grown far
// enough, a sheet of E wraps around and is reached by two fronts that K keeps
// apart in the nearer rings, glued across the ridge between them. Where the
// fronts' exact paths cross a false branch of K far upstream (small
// tolerances: K keeps many), only that far sheet carries the exact distances
// at the faces along the ridge; its linear field interpolates both fronts,
// lies below each, dominates the nearer copies and hides the ridge (bunny_7k
// v1951 at tolerance 0.002: a ring-43 copy, a branch of 12 mean edges lost).
// The nearer copies tell its fronts apart, with any solver: each corner of a
// copy of ring r > 0 belongs to the copy of the face in a ring below r whose
// distance there is closest to the copy's, within `witness_tolerance`. A copy
// whose corners all have owners, two or more of them, no one of which is
// within the tolerance at all three corners, and two of whose linear fields'
// gradients are `split_angle` or more apart, becomes one copy per owner: the
// copy's distance at the corners that owner owns, the owner's (never below
// the copy's) at the others. The envelope of the split copies keeps the
// copy's corner distances and has its boundary where the owners meet.
template <class TriangleMesh, class VertexPointMap, class FaceIndexMap, class Point>
class Recombined_copy_splitter
{
  typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
  typedef std::array<std::size_t, 3> Owners;
  static constexpr std::size_t none = std::size_t(-1);

public:
  // `corners`: per copy of E, its corner distances
  Recombined_copy_splitter(const TriangleMesh& tm, VertexPointMap vpm, FaceIndexMap fim,
                           const Extended_surface<Point>& E, const std::vector<std::array<double, 3> >& corners,
                           double witness_tolerance, double split_angle)
    : faces_(tm, vpm, fim), E_(E), corners_(corners), witness_tolerance_(witness_tolerance),
      split_angle_(split_angle), first_(num_faces(tm) + 1, 0), copies_of_(corners.size())
  {
    // every copy of E, by face of M
    for(std::size_t c = 0; c < corners.size(); ++c) ++first_[E.original_face[c] + 1];
    for(std::size_t f = 0; f + 1 < first_.size(); ++f) first_[f + 1] += first_[f];
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for(std::size_t c = 0; c < corners.size(); ++c) copies_of_[next[E.original_face[c]]++] = c;
  }

  // splits the recombined copies among `face_copies` (in place); how many
  std::size_t operator()(std::vector<Face_copies>& face_copies) const
  {
    std::size_t split_count = 0;
    for(std::size_t f = 0; f < face_copies.size(); ++f)
    {
      Face_copies& fc = face_copies[f];
      const std::size_t undominated = fc.copies.size();
      std::vector<char> replaced(undominated, 0);
      for(std::size_t j = 0; j < undominated; ++j)
      {
        const std::size_t c = fc.copies[j];
        if(E_.ring[c] == 0 || (!fc.split.empty() && fc.split[j])) continue;
        const std::array<double, 3> d = fc.fields[j];
        Owners owner;
        if(!nearer_owners(f, c, d, owner) || !fronts_apart(f, owner)) continue;
        add_split_fields(c, d, owner, fc);
        replaced[j] = 1;
        ++split_count;
      }
      remove_replaced(replaced, fc);
    }
    return split_count;
  }

private:
  // each corner's owner among the copies of face f nearer than copy c (with
  // distances d); false unless every corner has one, they are not all one
  // copy, and no one copy is within the tolerance at all three corners
  bool nearer_owners(std::size_t f, std::size_t c, const std::array<double, 3>& d, Owners& owner) const
  {
    owner = {{none, none, none}};
    std::array<double, 3> off{};
    for(std::size_t i = first_[f]; i < first_[f + 1]; ++i)
    {
      const std::size_t w = copies_of_[i];
      if(E_.ring[w] >= E_.ring[c]) continue;
      int within = 0;
      for(int k = 0; k < 3; ++k)
      {
        const double e = std::abs(corners_[w][k] - d[k]);
        if(e <= witness_tolerance_) ++within;
        if(owner[k] == none ? e <= witness_tolerance_ : e < off[k]) { owner[k] = w; off[k] = e; }
      }
      if(within == 3) return false; // one front in a nearer sheet
    }
    return owner[0] != none && owner[1] != none && owner[2] != none &&
           !(owner[0] == owner[1] && owner[1] == owner[2]);
  }

  // two owners' linear fields' gradients are `split_angle` or more apart
  bool fronts_apart(std::size_t f, const Owners& owner) const
  {
    const auto p = faces_.corner_points(f);
    for(int k = 0; k < 3; ++k)
    {
      if(owner[k] == owner[(k + 1) % 3]) continue;
      const std::array<double, 3> a = field_gradient(p, corners_[owner[k]]);
      const std::array<double, 3> b = field_gradient(p, corners_[owner[(k + 1) % 3]]);
      const Vector u(a[0], a[1], a[2]), v(b[0], b[1], b[2]);
      if(u != CGAL::NULL_VECTOR && v != CGAL::NULL_VECTOR &&
         CGAL::to_double(CGAL::approximate_angle(u, v)) >= split_angle_)
        return true;
    }
    return false;
  }

  // one field per owner (`split_field`)
  void add_split_fields(std::size_t c, const std::array<double, 3>& d, const Owners& owner, Face_copies& fc) const
  {
    if(fc.split.empty()) fc.split.assign(fc.copies.size(), 0);
    for(int k = 0; k < 3; ++k)
    {
      if((k > 0 && owner[k] == owner[0]) || (k > 1 && owner[k] == owner[1])) continue; // each owner once
      fc.copies.push_back(c);
      fc.fields.push_back(split_field(d, owner, owner[k], [&](int i) { return corners_[owner[k]][i]; }));
      fc.split.push_back(1);
    }
  }

  // drops the entries replaced by their split fields (the first replaced.size() of fc)
  static void remove_replaced(const std::vector<char>& replaced, Face_copies& fc)
  {
    if(std::find(replaced.begin(), replaced.end(), 1) == replaced.end()) return;
    keep_face_copies_if(fc, [&](std::size_t j) { return j >= replaced.size() || !replaced[j]; });
  }

  Faces_by_index<TriangleMesh, VertexPointMap> faces_;
  const Extended_surface<Point>& E_;
  const std::vector<std::array<double, 3> >& corners_;
  double witness_tolerance_, split_angle_;
  std::vector<std::size_t> first_, copies_of_; // the copies of face f: copies_of_[first_[f] .. first_[f + 1])
};

// A kink between the corners of one copy. Where the cut graph K lacks a
// branch of the cut locus, both fronts reach the faces along that branch
// inside one sheet of E: one copy carries the exact distance at all three
// corners, its corners reached by different fronts, and its linear field hides
// the ridge. The solver's cones tell the fronts apart (a front: the apex of its
// cone in the face's plane, and its offset):
//  1. the fronts of a copy are those of its samples' cones; each corner
//     belongs to the front whose cone there is nearest to the copy's distance,
//     and that cone must give the distance there (within round-off). Where no
//     sample's cone does (the kink passes between the corner and its sample),
//     with the corner fallback and the copy alone in its face, the corner's
//     fallback sample, nearer to it, gives its front; without an exact front
//     the copy stays whole. Only alone: where fronts of other sheets meet the
//     copy, a split raises its field (each split field is at least the copy's
//     linear one) and moves the ridge between the sheets; measured
//     (bench_ridge_accuracy, 168 pairs), the fallback in every face loses a
//     14-edge branch on kitten_5k v1250. With a guessed front at such corners,
//     the ridge refinement met envelope pieces it could not match. A fallback
//     front must meet the others at a ridge: no owner's cone lies below the
//     copy's distance at another corner (a cone below it is extended beyond
//     its window, in the shadow of a saddle vertex; without this test the
//     fallback in the default cone ridge gave teddy_3k v479 overall precision
//     p95 0.58 mean edges instead of 0.13, with it 0.40);
//  2. a copy whose corners belong to fronts that arrive at the face's centroid
//     `split_angle` or more apart becomes one copy per front, with the field of
//     its cone at the corners (never below the copy's distance there, and
//     exactly that distance at the corners the front owns): the lower envelope
//     of the split copies has the copy's distances at the corners and its
//     boundary near the kink;
//  3. the fronts of a split copy are unfolded across its edges into the copies
//     glued to it in E, which are tested again with them (step 1 with more
//     fronts), so that the kink goes on through faces none of whose samples
//     lies beyond it, until it ends or meets the ridge.
// `cones[S * copy + i]` is the cone of copy `copy` (a face of E) at sample i of
// `samples`; copies without cones (a source or apex at a sample) stay whole.
// With `corner_fallback` (`parameters::corner_fallback`), the last three
// samples are the fallbacks of corners 0, 1 and 2
// (`Cone_samples::corner_fallback_samples()`), the others those of step 1.
template <class TriangleMesh, class VertexPointMap, class FaceIndexMap, class Point>
class Kink_splitter
{
  typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
  struct Front { Point apex; double offset; };
  // a split copy: its fronts, and the front of each corner
  struct Split
  {
    std::vector<Front> fronts;
    std::array<std::size_t, 3> owner = {{0, 0, 0}};
    bool exact = true; // every owner's cone is exact at its corner
  };

public:
  Kink_splitter(const TriangleMesh& tm, VertexPointMap vpm, FaceIndexMap fim, const Extended_surface<Point>& E,
                const std::vector<Face_cone>& cones, const std::vector<std::array<double, 3> >& samples,
                double split_angle, double mean_edge, bool corner_fallback = false)
      : faces_(tm, vpm, fim), E_(E), cones_(cones), samples_(samples),
        first_fallback_(corner_fallback && samples.size() >= 3 ? samples.size() - 3 : samples.size()),
        split_angle_(split_angle), same_apex_(tuning::ridge::same_apex * mean_edge)
  {}

  // `front_cones`, if given, gets per split copy the cones of its fronts, one
  // per field it is split into, in the order of the fields (the cone ridge
  // moves the kink's points onto the curve where they agree).
  std::vector<Face_copies> operator()(const std::vector<Face_copies>& face_copies, std::size_t& split_count,
                                      std::map<std::size_t, std::vector<Face_cone> >* front_cones = nullptr) const
  {
    std::map<std::size_t, Split> split; // per split copy of E
    std::vector<std::size_t> queue;
    for(std::size_t f = 0; f < face_copies.size(); ++f)
      for(std::size_t j = 0; j < face_copies[f].copies.size(); ++j)
      {
        if(already_split(face_copies[f], j)) continue;
        Split x;
        const std::size_t c = face_copies[f].copies[j];
        const bool alone = face_copies[f].copies.size() == 1;
        if(!sample_fronts(f, c, x.fronts) || !kinked(f, c, face_copies[f].fields[j], alone, x)) continue;
        split.emplace(c, x);
        queue.push_back(c);
      }
    // step 3: the kinks go on into the glued copies
    while(!queue.empty())
    {
      const std::size_t c = queue.back();
      queue.pop_back();
      const std::size_t f = E_.original_face[c];
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t g = glued_across(c, k);
        if(g == std::size_t(-1) || split.count(g)) continue;
        const std::size_t n = E_.original_face[g];
        const auto& fc = face_copies[n];
        const auto it = std::find(fc.copies.begin(), fc.copies.end(), g);
        if(it == fc.copies.end() || already_split(fc, std::size_t(it - fc.copies.begin()))) continue; // dominated
        const std::array<double, 3>& d = fc.fields[std::size_t(it - fc.copies.begin())];
        const Split& from = split.at(c);
        Split x;
        for(const Front& y : from.fronts) x.fronts.push_back(unfolded(y, f, k, n));
        if(!sample_fronts(n, g, x.fronts) || !kinked(n, g, d, fc.copies.size() == 1, x)) continue;
        split.emplace(g, x);
        queue.push_back(g);
      }
    }
    std::vector<Face_copies> out(face_copies.size());
    split_count = split.size();
    for(std::size_t f = 0; f < face_copies.size(); ++f)
      for(std::size_t j = 0; j < face_copies[f].copies.size(); ++j)
      {
        const std::size_t c = face_copies[f].copies[j];
        const auto it = split.find(c);
        if(it == split.end() || already_split(face_copies[f], j))
        {
          out[f].copies.push_back(c);
          out[f].fields.push_back(face_copies[f].fields[j]);
          out[f].split.push_back(already_split(face_copies[f], j));
          continue;
        }
        for(const auto& field : split_fields(f, face_copies[f].fields[j], it->second))
        {
          out[f].copies.push_back(c);
          out[f].fields.push_back(field);
          out[f].split.push_back(1);
        }
        if(front_cones) (*front_cones)[c] = owner_cones(f, it->second);
      }
    return out;
  }

private:
  // entry j of fc: one front of a copy split before (`Recombined_copy_splitter`)
  static bool already_split(const Face_copies& fc, std::size_t j) { return !fc.split.empty() && fc.split[j]; }

  // the index of front x in `fronts`, where it is added unless it is there
  std::size_t add_front(const Front& x, std::vector<Front>& fronts) const
  {
    for(std::size_t i = 0; i < fronts.size(); ++i)
      if(std::sqrt(CGAL::to_double(CGAL::squared_distance(x.apex, fronts[i].apex))) <= same_apex_ &&
         std::abs(x.offset - fronts[i].offset) <= same_apex_)
        return i;
    fronts.push_back(x);
    return fronts.size() - 1;
  }

  // the front of copy c's sample i in face f; false without one (a source or
  // no path at the sample, or its cone not read: not near a kink)
  bool sample_front(std::size_t f, std::size_t c, std::size_t i, Front& x) const
  {
    const std::size_t S = samples_.size();
    if(S * (c + 1) > cones_.size()) return false;
    const Face_cone& cone = cones_[S * c + i];
    if(cone.apex == samples_[i] || std::abs(cone.apex[0] + cone.apex[1] + cone.apex[2] - 1) > 0.5) return false;
    const auto p = faces_.corner_points(f);
    x = Front{barycentric_to_point(cone.apex, p[0], p[1], p[2]), cone.offset};
    return true;
  }

  // step 1: the fronts of copy c's samples in face f (not the fallbacks);
  // false without cones
  bool sample_fronts(std::size_t f, std::size_t c, std::vector<Front>& fronts) const
  {
    for(std::size_t i = 0; i < first_fallback_; ++i)
    {
      Front x;
      if(!sample_front(f, c, i, x)) return false;
      add_front(x, fronts);
    }
    return true;
  }

  double cone_at(const Front& x, const Point& q) const
  {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(q, x.apex))) + x.offset;
  }

  // the front of each corner of face f, for a copy with distances d
  std::array<std::size_t, 3> owners(std::size_t f, const std::array<double, 3>& d, const std::vector<Front>& fronts) const
  {
    const auto p = faces_.corner_points(f);
    std::array<std::size_t, 3> owner = {{0, 0, 0}};
    for(int k = 0; k < 3; ++k)
      for(std::size_t x = 1; x < fronts.size(); ++x)
        if(std::abs(cone_at(fronts[x], p[k]) - d[k]) < std::abs(cone_at(fronts[owner[k]], p[k]) - d[k])) owner[k] = x;
    return owner;
  }

  // step 2's test: the corners' fronts (each exact at its corner; for a copy
  // c alone in face f, from the corner's fallback sample where no front is)
  // arrive split_angle apart; sets x.owner
  bool kinked(std::size_t f, std::size_t c, const std::array<double, 3>& d, bool alone, Split& x) const
  {
    const auto p = faces_.corner_points(f);
    x.owner = owners(f, d, x.fronts);
    bool fallback_used = false;
    for(int k = 0; k < 3; ++k)
    {
      auto exact = [&](std::size_t i) { return std::abs(cone_at(x.fronts[i], p[k]) - d[k]) <= same_apex_; };
      if(exact(x.owner[k])) continue;
      Front y;
      if(!alone || first_fallback_ == samples_.size() || !sample_front(f, c, first_fallback_ + k, y)) return false;
      x.owner[k] = add_front(y, x.fronts);
      if(!exact(x.owner[k])) return false;
      fallback_used = true;
    }
    if(x.fronts.size() < 2) return false;
    // a front taken from a fallback sample must meet the others at a ridge:
    // no owner's cone lies below the copy's distance at another corner
    // (there it would be extended beyond its window)
    if(fallback_used)
      for(int k = 0; k < 3; ++k)
        for(int j = 0; j < 3; ++j)
          if(cone_at(x.fronts[x.owner[j]], p[k]) < d[k] - same_apex_) return false;
    const Point centroid = CGAL::centroid(p[0], p[1], p[2]);
    for(int k = 0; k < 3; ++k)
    {
      const Vector u = centroid - x.fronts[x.owner[k]].apex, v = centroid - x.fronts[x.owner[(k + 1) % 3]].apex;
      if(u == CGAL::NULL_VECTOR || v == CGAL::NULL_VECTOR) continue;
      if(CGAL::to_double(CGAL::approximate_angle(u, v)) >= split_angle_) return true;
    }
    return false;
  }

  // whether front i of x owns a corner (it becomes a split copy)
  static bool owns_corner(const Split& x, std::size_t i)
  {
    return x.owner[0] == i || x.owner[1] == i || x.owner[2] == i;
  }

  // step 2: one field per front that owns a corner
  std::vector<std::array<double, 3> > split_fields(std::size_t f, const std::array<double, 3>& d, const Split& x) const
  {
    const auto p = faces_.corner_points(f);
    std::vector<std::array<double, 3> > out;
    for(std::size_t i = 0; i < x.fronts.size(); ++i)
    {
      if(!owns_corner(x, i)) continue;
      out.push_back(split_field(d, x.owner, i, [&](int k) { return cone_at(x.fronts[i], p[k]); }));
    }
    return out;
  }

  // the cones of the fronts that own a corner of face f, in the order of
  // `split_fields`, their apexes barycentric in f
  std::vector<Face_cone> owner_cones(std::size_t f, const Split& x) const
  {
    const auto p = faces_.corner_points(f);
    const Vector e1 = p[1] - p[0], e2 = p[2] - p[0];
    const double a = CGAL::to_double(e1 * e1), b = CGAL::to_double(e1 * e2), c = CGAL::to_double(e2 * e2);
    const double det = a * c - b * b;
    std::vector<Face_cone> out;
    for(std::size_t i = 0; i < x.fronts.size(); ++i)
    {
      if(!owns_corner(x, i)) continue;
      const Vector w = x.fronts[i].apex - p[0];
      const double u = CGAL::to_double(w * e1), v = CGAL::to_double(w * e2);
      const double b1 = (c * u - b * v) / det, b2 = (a * v - b * u) / det;
      out.push_back(Face_cone{{{1 - b1 - b2, b1, b2}}, x.fronts[i].offset});
    }
    return out;
  }

  // the copy glued to copy c across its edge k in E (corner k to k + 1), if any
  std::size_t glued_across(std::size_t c, int k) const
  {
    typedef typename Extended_surface<Point>::Mesh Mesh;
    auto h = E_.mesh.halfedge(typename Mesh::Face_index(static_cast<typename Mesh::size_type>(c)));
    for(int j = 0; j < k; ++j) h = E_.mesh.next(h);
    const auto o = E_.mesh.opposite(h);
    return E_.mesh.is_border(o) ? std::size_t(-1) : std::size_t(E_.mesh.face(o));
  }

  // front x of face f unfolded across f's edge k into face n, the face beyond it
  Front unfolded(const Front& x, std::size_t f, int k, std::size_t n) const
  {
    const auto p = faces_.corner_points(f), q = faces_.corner_points(n);
    const Point& a = p[k];
    const Point& b = p[(k + 1) % 3];
    int third = 0;
    while(q[third] == a || q[third] == b) ++third;
    const Vector t = (b - a) / std::sqrt(CGAL::to_double((b - a).squared_length()));
    auto inward = [&](const Point& r) { // in the plane of a, b, r: unit, normal to the edge, towards r
      Vector w = r - a;
      w = w - (w * t) * t;
      return w / std::sqrt(CGAL::to_double(w.squared_length()));
    };
    const Vector w = x.apex - a;
    return Front{a + (w * t) * t - (w * inward(p[(k + 2) % 3])) * inward(q[third]), x.offset};
  }

  Faces_by_index<TriangleMesh, VertexPointMap> faces_;
  const Extended_surface<Point>& E_;
  const std::vector<Face_cone>& cones_;
  const std::vector<std::array<double, 3> >& samples_;
  std::size_t first_fallback_; // samples from here on: one per corner
  double split_angle_, same_apex_;
};


// The solver's cones: S per copy of E at the S `samples` (a copy whose cones
// were not read has no apex), and per copy split at a kink the cones of its
// fronts in the order of its fields (`Kink_splitter`).
struct Copy_cones
{
  const std::vector<Face_cone>* per_copy;
  const std::map<std::size_t, std::vector<Face_cone> >* split_fronts;
  const std::vector<std::array<double, 3> >* samples;
};

// Stage 3 as its named steps (the manual's order), over the state they share:
// the envelope of every face and its cells (one per surviving copy), the ridge
// nodes (exact keys) and segments, and the fronts (cells that are one front).
template <class TriangleMesh, class Maps>
class Ridge_curve_assembler
{
  typedef typename Maps::Point Point;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef Exact_number Q;
  static constexpr std::size_t none = std::size_t(-1);

public:
  Ridge_curve_assembler(const TriangleMesh& tm, const Extended_surface<Point>& E,
                        const std::vector<Face_copies>& face_copies, double mean_edge, double minimum_angle,
                        double kink_angle, const Maps& maps, const std::vector<double>& angle_sum,
                        std::vector<std::vector<Ridge_region_cell> >& regions, Ridge_curve_statistics& st,
                        const Copy_cones* cones = nullptr)
    : tm_(tm), maps_(maps), E_(E), face_copies_(face_copies), mean_edge_(mean_edge), minimum_angle_(minimum_angle),
      kink_angle_(kink_angle), angle_sum_(angle_sum), regions_(regions), st_(st), faces_(tm, maps.vpm, maps.fim),
      nf_(num_faces(tm)), same_front_tolerance_(tuning::ridge::same_front * mean_edge), cones_(cones),
      coincident_(coincident_tolerance(tm, maps.vpm))
  {}

  void run(std::vector<std::vector<Ridge_point<Point> > >& polylines)
  {
    label_border_loops();
    compute_envelopes();
    for(std::size_t c = 0; c < cells_.size(); ++c) fronts_.add();
    segments_inside_faces();
    segments_along_edges();
    merge_into_one_region();
    rejoin_pieces();
    if(minimum_angle_ > 0) prune_spurs();
    join_border_components();
    join_verified_pieces();
    keep_main_component(polylines);
  }

private:
  // a cell: its copy, its linear field and the field's gradient (in the face's plane)
  // (entry: its index among the face's copies, as in `Face_copies`)
  struct Cell { std::size_t copy; std::array<double, 3> field, gradient; bool split; std::size_t entry; };
  struct Segment { std::size_t a, b, left, right; double strength; double angle; bool ridge; };
  // an interval of an edge (t along it) and the cell that wins there on one side
  struct Interval { Q lo, hi; std::size_t cell; };
  // nodes, keyed exactly: (0, vertex) | (1, edge, t along the edge) | (2, face, λ1, λ2)
  typedef std::tuple<int, std::size_t, Q, Q> Key;

  // equal fields within the tolerance are one front (solver noise)
  bool same_field(const std::array<double, 3>& a, const std::array<double, 3>& b) const
  {
    return std::abs(a[0] - b[0]) <= same_front_tolerance_ && std::abs(a[1] - b[1]) <= same_front_tolerance_ &&
           std::abs(a[2] - b[2]) <= same_front_tolerance_;
  }

  // One copy: its cell is the whole triangle (most faces; no clipping needed),
  // made once and shared.
  static Lower_envelope<Q> whole_triangle()
  {
    Lower_envelope<Q> envelope;
    Envelope_cell<Q> cell;
    cell.copy = 0;
    cell.polygon = {{{Q(1), Q(0), Q(0)}}, {{Q(0), Q(1), Q(0)}}, {{Q(0), Q(0), Q(1)}}};
    cell.edge_label = {triangle_edge_label(0), triangle_edge_label(1), triangle_edge_label(2)};
    envelope.cells.assign(1, cell);
    return envelope;
  }

  // The lower envelope of every face's copies, its cells, and the regions.
  // The cells of face f are cells_[first_cell_[f]] to cells_[first_cell_[f + 1] - 1],
  // in the order of its envelope's cells; every array is sized before it is
  // filled (one block each, and one per region: most faces have one cell).
  void compute_envelopes()
  {
    envelope_of_.assign(nf_, nullptr);
    whole_triangle_ = whole_triangle();
    first_cell_.assign(nf_ + 1, 0);
    for(std::size_t f = 0; f < nf_; ++f)
    {
      const Face_copies& fc = face_copies_[f];
      if(fc.fields.size() == 1) envelope_of_[f] = &whole_triangle_;
      else
      {
        computed_.push_back(compute_lower_envelope<Q>(fc.fields));
        envelope_of_[f] = &computed_.back();
      }
      if(fc.copies.size() > 1) ++st_.faces_with_several_copies;
      first_cell_[f + 1] = first_cell_[f] + envelope_of_[f]->cells.size();
    }
    st_.surviving_copies = first_cell_[nf_];
    const std::vector<std::array<double, 3> > whole_polygon = polygon_to_double(whole_triangle_.cells[0].polygon);
    cells_.reserve(first_cell_[nf_]);
    regions_.assign(nf_, {});
    for(std::size_t f = 0; f < nf_; ++f)
    {
      const Face_copies& fc = face_copies_[f];
      const auto cp = faces_.corner_points(f);
      regions_[f].reserve(envelope_of_[f]->cells.size());
      for(const auto& c : envelope_of_[f]->cells)
      {
        const std::array<double, 3>& field = fc.fields[c.copy];
        cells_.push_back(
            Cell{fc.copies[c.copy], field, field_gradient(cp, field), !fc.split.empty() && fc.split[c.copy], c.copy});
        Ridge_region_cell rc;
        rc.copy = fc.copies[c.copy];
        rc.field = field;
        rc.polygon = envelope_of_[f] == &whole_triangle_ ? whole_polygon : polygon_to_double(c.polygon);
        regions_[f].push_back(std::move(rc));
      }
    }
  }

  static std::vector<std::array<double, 3> > polygon_to_double(const std::vector<std::array<Q, 3> >& polygon)
  {
    std::vector<std::array<double, 3> > out;
    out.reserve(polygon.size());
    for(const auto& p : polygon) out.push_back({{CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2])}});
    return out;
  }

  // are the copies of cells c1 and c2 glued in E across edge k1 of c1's face (one sheet)?
  bool glued_across(std::size_t c1, int k1, std::size_t c2) const
  {
    typedef typename Extended_surface<Point>::Mesh Mesh;
    const Mesh& em = E_.mesh;
    auto eh = em.halfedge(typename Mesh::Face_index(static_cast<typename Mesh::size_type>(cells_[c1].copy)));
    for(int j = 0; j < k1; ++j) eh = em.next(eh);
    const auto eo = em.opposite(eh);
    return !em.is_border(eo) && std::size_t(em.face(eo)) == cells_[c2].copy;
  }

  std::size_t cell_of(std::size_t f, std::size_t local_copy) const
  {
    for(std::size_t i = 0; i < envelope_of_[f]->cells.size(); ++i)
      if(envelope_of_[f]->cells[i].copy == local_copy) return first_cell_[f] + i;
    return none;
  }

  // The node of a point: one per surface point. A point within the
  // coincidence tolerance of a node (the same point computed from another
  // face, or an envelope edge that ends 1e-12 from a vertex) is that node; the
  // node then takes the point's location if it is on a lower feature (a
  // vertex, then an edge), so that nodes at vertices are exactly there.
  std::size_t add_node(const Key& key, std::size_t f, const std::array<Q, 3>& lambda, std::size_t loop = none)
  {
    auto it = node_of_.find(key);
    if(it != node_of_.end()) return it->second;
    Ridge_point<Point> p;
    p.face = f;
    p.barycentric = {{CGAL::to_double(lambda[0]), CGAL::to_double(lambda[1]), CGAL::to_double(lambda[2])}};
    const auto cp = faces_.corner_points(f);
    p.point = barycentric_to_point(lambda, cp[0], cp[1], cp[2]);
    const std::array<double, 3> xyz = {{CGAL::to_double(p.point.x()), CGAL::to_double(p.point.y()),
                                        CGAL::to_double(p.point.z())}};
    // (a key's kind is the dimension of the feature it lies on: 0 vertex, 1 edge, 2 face)
    const int feature = std::get<0>(key);
    const std::size_t same = coincident_.find(xyz, [&](std::size_t n) { return faces_share_a_vertex(nodes_[n].face, f); });
    if(same != Coincident_points::none)
    {
      if(feature < node_feature_[same])
      {
        nodes_[same] = p;
        node_feature_[same] = feature;
        coincident_.insert(same, xyz);
      }
      if(node_loop_[same] == none) node_loop_[same] = loop;
      ++st_.coincident_points;
      node_of_.emplace(key, same);
      return same;
    }
    node_loop_.push_back(loop);
    node_feature_.push_back(feature);
    nodes_.push_back(p);
    coincident_.insert(nodes_.size() - 1, xyz);
    node_of_.emplace(key, nodes_.size() - 1);
    return nodes_.size() - 1;
  }
  // (points of two sheets of a surface that touches itself may coincide in space)
  bool faces_share_a_vertex(std::size_t f, std::size_t g) const
  {
    if(f == g) return true;
    const auto hf = faces_.corner_halfedges(f), hg = faces_.corner_halfedges(g);
    for(const auto& a : hf)
      for(const auto& b : hg)
        if(source(a, tm_) == source(b, tm_)) return true;
    return false;
  }

  // The loops of the border of M (b of them): per vertex its loop, or none
  // inside. K ∪ ∂M, and so the ridge with the border, is one connected graph;
  // each loop counts as one node of it (`loop_node`), joined to the ridge
  // nodes on it.
  void label_border_loops()
  {
    const std::size_t nv = num_vertices(tm_);
    Union_find loops(nv);
    std::vector<char> on_border(nv, 0);
    for(halfedge_descriptor h : halfedges(tm_))
      if(is_border(h, tm_))
      {
        const std::size_t a = get(maps_.vim, source(h, tm_)), b = get(maps_.vim, target(h, tm_));
        on_border[a] = on_border[b] = 1;
        loops.unite(a, b);
      }
    loop_of_vertex_.assign(nv, none);
    std::map<std::size_t, std::size_t> label;
    for(std::size_t v = 0; v < nv; ++v)
      if(on_border[v]) loop_of_vertex_[v] = label.emplace(loops.find(v), label.size()).first->second;
    number_of_loops_ = label.size();
  }
  std::size_t loop_node(std::size_t loop) const { return nodes_.size() + loop; }
  // `uf`, over the ridge nodes and then the loops: the nodes on a loop joined to it
  void join_border_nodes(Union_find& uf) const
  {
    for(std::size_t v = 0; v < nodes_.size(); ++v)
      if(node_loop_[v] != none) uf.unite(v, loop_node(node_loop_[v]));
  }

  // a point of face f given by exact barycentric coordinates: normalized to its feature
  std::size_t node_at(std::size_t f, const std::array<Q, 3>& lambda)
  {
    const auto h = faces_.corner_halfedges(f);
    int zeros = 0, nz = -1;
    for(int k = 0; k < 3; ++k) { if(CGAL::is_zero(lambda[k])) ++zeros; else nz = k; }
    if(zeros == 2)
    {
      const std::size_t v = get(maps_.vim, source(h[nz], tm_));
      return add_node(Key(0, v, Q(0), Q(0)), f, lambda, loop_of_vertex_[v]);
    }
    for(int k = 0; k < 3; ++k)
      if(CGAL::is_zero(lambda[(k + 2) % 3])) // on edge k, from corner k to corner k+1
      {
        // t runs from the endpoint of smaller vertex index (an edge descriptor may
        // remember the halfedge it was made from, so halfedge(e) is no orientation)
        const bool forward = get(maps_.vim, source(h[k], tm_)) < get(maps_.vim, target(h[k], tm_));
        const Q t = forward ? lambda[(k + 1) % 3] : lambda[k];
        const std::size_t loop =
            is_border(edge(h[k], tm_), tm_) ? loop_of_vertex_[get(maps_.vim, source(h[k], tm_))] : none;
        return add_node(Key(1, get(maps_.eim, edge(h[k], tm_)), t, Q(0)), f, lambda, loop);
      }
    return add_node(Key(2, f, lambda[1], lambda[2]), f, lambda);
  }

  // Inside faces: the envelope's edges between different fronts.
  void segments_inside_faces()
  {
    for(std::size_t f = 0; f < nf_; ++f)
    {
      for(const auto& s : envelope_of_[f]->segments)
      {
        const std::size_t ca = cell_of(f, s.copy_a), cb = cell_of(f, s.copy_b);
        const std::size_t a = node_at(f, s.endpoints[0]), b = node_at(f, s.endpoints[1]);
        // (a boundary of length 0, one surface point, joins no regions and is no ridge)
        if(a == b) continue;
        if(same_field(cells_[ca].field, cells_[cb].field)) { fronts_.unite(ca, cb); continue; }
        const Gradient_jump j = front_jump_in_face(f, ca, cb, s.endpoints);
        segments_.push_back(Segment{a, b, ca, cb, j.strength, j.angle, true});
        ++st_.envelope_segments;
      }
    }
  }

  // the jump between the linear fields of two cells of one face
  static Gradient_jump gradient_jump_in_face(const Cell& a, const Cell& b)
  {
    return jump_between(a.gradient, b.gradient);
  }

  // The jump of a ridge segment: between the arrival directions of its two
  // fronts, read from the solver's cones, where both cells give one; else
  // between their linear fields. A linear field is exact at its copy's
  // corners only: a copy inexact at one corner (a sheet of E that reaches it
  // around a vertex of the cut K, a little longer) has a gradient that points
  // anywhere. Two sheets of one front then met at an envelope edge (or a mesh
  // edge) whose linear jump was 30-90 degrees, drawn as a strong ridge where
  // none is: on CAD models, whose K follows the grid lines of flat faces
  // (`bench_ridge_accuracy --boxes`, box_fans from v0: a ridge line along a
  // grid line, precision p95 1.1 mean edges; the cones' jump there 1-5
  // degrees). Measured in `segments_inside_faces` and `segments_on_edge`.
  Gradient_jump front_jump_in_face(std::size_t f, std::size_t ca, std::size_t cb,
                                   const std::array<std::array<Q, 3>, 2>& ends) const
  {
    std::array<double, 3> mid;
    for(int k = 0; k < 3; ++k) mid[k] = CGAL::to_double((ends[0][k] + ends[1][k]) / 2);
    std::array<double, 3> da, db;
    if(arrival_direction(f, ca, mid, da) && arrival_direction(f, cb, mid, db)) return jump_between(da, db);
    return gradient_jump_in_face(cells_[ca], cells_[cb]);
  }

  // The arrival direction (unit) of cell c's front at the point `at`
  // (barycentric) of its face f: from the apex of the cone of the sample
  // nearest to it, if the solver read the copy's cones and those of all its
  // samples point within `consistent_angle` of it there. A copy whose
  // samples' cones point apart straddles a kink (the sample nearest to the
  // segment may lie beyond it); the cones of one front's windows around a
  // vertex of K point a few degrees apart. Measured (`bench_ridge_accuracy`,
  // exact solver; precision p95 (>= 30 degrees) <= 0.25 / <= 0.5; pairs whose
  // recall at the default tolerance is above a mean edge): any cone, 168
  // pairs 167 / 168 and 4 (bunny_7k v3136 lost a branch of 90-degree jumps:
  // the nearest samples of unsplit copies lay beyond a kink), real models 60
  // / 68; within 5 degrees 165 / 168 and 1, real 56 / 67; within 15 degrees
  // 166 / 168 and 2, real 59 / 70.
  bool arrival_direction(std::size_t f, std::size_t c, const std::array<double, 3>& at,
                         std::array<double, 3>& direction) const
  {
    typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
    const double consistent_angle = tuning::ridge::consistent_arrival_degrees;
    if(!cones_) return false;
    const std::size_t S = cones_->samples->size();
    const Cell& cell = cells_[c];
    const Face_cone* split_front = nullptr; // a front of a copy split at a kink: its cone everywhere
    if(cell.split)
    {
      const auto it = cones_->split_fronts->find(cell.copy);
      if(it == cones_->split_fronts->end()) return false; // (split into nearer copies' fronts)
      const std::vector<std::size_t>& entries = face_copies_[f].copies;
      const std::size_t front = std::size_t(std::count(entries.begin(), entries.begin() + cell.entry, cell.copy));
      if(front >= it->second.size()) return false;
      split_front = &it->second[front];
    }
    else if(S * (cell.copy + 1) > cones_->per_copy->size()) return false;
    auto cone_at_sample = [&](std::size_t i) -> const Face_cone& {
      return split_front ? *split_front : (*cones_->per_copy)[S * cell.copy + i];
    };
    std::size_t nearest = 0;
    double nearest_d2 = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < S; ++i)
    {
      const std::array<double, 3>& q = (*cones_->samples)[i];
      double d2 = 0;
      for(int k = 0; k < 3; ++k) d2 += (q[k] - at[k]) * (q[k] - at[k]);
      if(d2 < nearest_d2) { nearest_d2 = d2; nearest = i; }
    }
    const auto p = faces_.corner_points(f);
    const Point x = barycentric_to_point(at, p[0], p[1], p[2]);
    auto from_apex = [&](std::size_t i, Vector& v) {
      const Face_cone& cone = cone_at_sample(i);
      // not read, or the source (or an apex) at the sample
      if(std::abs(cone.apex[0] + cone.apex[1] + cone.apex[2] - 1) > 0.5 ||
         (!split_front && cone.apex == (*cones_->samples)[i]))
        return false;
      v = x - barycentric_to_point(cone.apex, p[0], p[1], p[2]);
      return v != CGAL::NULL_VECTOR;
    };
    Vector v;
    if(!from_apex(nearest, v)) return false;
    for(std::size_t i = 0; i < S; ++i)
    {
      Vector w;
      if(!from_apex(i, w) || CGAL::to_double(CGAL::approximate_angle(v, w)) > consistent_angle) return false;
    }
    const double length = std::sqrt(CGAL::to_double(v.squared_length()));
    direction = {{CGAL::to_double(v.x()) / length, CGAL::to_double(v.y()) / length, CGAL::to_double(v.z()) / length}};
    return true;
  }

  // the jump between two gradients of one face
  static Gradient_jump jump_between(const std::array<double, 3>& ga, const std::array<double, 3>& gb)
  {
    typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
    const Vector va(ga[0], ga[1], ga[2]), vb(gb[0], gb[1], gb[2]);
    const double strength = std::sqrt(CGAL::to_double((va - vb).squared_length()));
    const double angle =
        (va == CGAL::NULL_VECTOR || vb == CGAL::NULL_VECTOR) ? 0.0 : CGAL::to_double(CGAL::approximate_angle(va, vb));
    return Gradient_jump{strength, angle};
  }

  // the jump of the gradient across edge k1 of face f1 (edge k2 of f2) between
  // cells c1 and c2
  // None at the source: the distance is a cone there, and the kinks of its
  // linear interpolation across the edges at the source vertex, or of the
  // source's face, are no fronts meeting.
  Gradient_jump edge_jump(std::size_t f1, int k1, std::size_t c1, std::size_t f2, int k2, std::size_t c2) const
  {
    if(at_source(f1, k1) || at_source(f2, k2)) return Gradient_jump{0, 0};
    const auto cp1 = faces_.corner_points(f1), cp2 = faces_.corner_points(f2);
    return gradient_jump_across_edge(cp1[k1], cp1[(k1 + 1) % 3], cp1[(k1 + 2) % 3], cp2[(k2 + 2) % 3],
                                     cells_[c1].gradient, cells_[c2].gradient);
  }

  // edge k of face f: an edge of the source's face, or at the source vertex
  bool at_source(std::size_t f, int k) const
  {
    if(!E_.source_is_vertex) return f == std::size_t(E_.source_location.first);
    const std::size_t s = E_.original_vertex[E_.source_vertex];
    const auto h = faces_.corner_halfedges(f);
    return std::size_t(get(maps_.vim, source(h[k], tm_))) == s || std::size_t(get(maps_.vim, target(h[k], tm_))) == s;
  }

  // A kink inside one sheet: glued copies whose gradients jump by at least
  // `kink_angle`. Where the cut graph K lacks a branch of the cut locus, both
  // fronts reach the faces along that branch inside one sheet of E, and only
  // the kink shows the ridge there.
  bool kinked(const Gradient_jump& j) const { return kink_angle_ > 0 && j.angle >= kink_angle_; }

  // A kink along edge k of face f, inside one sheet: none at a reflex vertex
  // of the border (angle sum above pi). Shortest paths bend around it, and
  // in its shadow the distance is a cone with its apex there, which the
  // linear fields of the faces at it interpolate as badly as the source's
  // cone: a flat square with a slit in its border (simply connected and flat,
  // so no cut locus) got a one-edge ridge at the slit's end, a linear jump of
  // 66 degrees (issue 38). A generic cut locus meets the border away from its
  // reflex vertices.
  bool kinked_along(std::size_t f, int k, const Gradient_jump& j) const
  {
    if(!kinked(j)) return false;
    const auto h = faces_.corner_halfedges(f);
    for(const auto v : {source(h[k], tm_), target(h[k], tm_)})
    {
      const std::size_t i = get(maps_.vim, v);
      if(loop_of_vertex_[i] != none && angle_sum_[i] > CGAL_PI) return false;
    }
    return true;
  }

  // Thin faces: height over the longest edge below `thin_face_ratio` of that
  // edge (caps, three corners nearly on a line, and needles). A linear field
  // interpolates the distance along the long edge from its two ends only, and
  // the corner across it lies a small height h away: the gradient across the
  // face is their difference divided by h, so the interpolation's error
  // (which grows with the square of the length) becomes a gradient that may
  // point anywhere. Two cells on either side of such a face's edge that agree
  // along it were then a ridge along the edge (the gradients disagree) that
  // is no ridge: on bunny_1k and teddy_3k with caps added (their surfaces
  // unchanged, `bench_ridge_accuracy --caps 0.2`), 80-90 % of the ridge samples
  // more than half a mean edge off lay on caps, and the beetle's needles
  // likewise (user manual, \ref GeodesicRidgeSecThinFaces).
  void thin_faces()
  {
    const double thin_face_ratio = tuning::ridge::thin_face_ratio;
    thin_.assign(nf_, 0);
    for(std::size_t f = 0; f < nf_; ++f)
    {
      const auto p = faces_.corner_points(f);
      double longest2 = 0;
      for(int k = 0; k < 3; ++k)
        longest2 = (std::max)(longest2, CGAL::to_double(CGAL::squared_distance(p[k], p[(k + 1) % 3])));
      // twice the area is the longest edge times the height over it
      const double twice_area = std::sqrt(CGAL::to_double(CGAL::squared_area(p[0], p[1], p[2]))) * 2;
      thin_[f] = twice_area < thin_face_ratio * longest2;
    }
  }

  // Along mesh edges: every edge split by both sides' cell boundaries.
  void segments_along_edges()
  {
    thin_faces();
    std::vector<char> edge_done(num_edges(tm_), 0);
    for(std::size_t f1 = 0; f1 < nf_; ++f1)
    {
      const auto h1s = faces_.corner_halfedges(f1);
      for(int k1 = 0; k1 < 3; ++k1)
      {
        const std::size_t e = get(maps_.eim, edge(h1s[k1], tm_));
        if(edge_done[e]) continue;
        edge_done[e] = 1;
        const halfedge_descriptor h2 = opposite(h1s[k1], tm_);
        if(is_border(h2, tm_)) continue; // the border of M: one side only
        const std::size_t f2 = get(maps_.fim, face(h2, tm_));
        const auto h2s = faces_.corner_halfedges(f2);
        int k2 = 0;
        while(h2s[k2] != h2) ++k2;
        if(!one_sheet_across(f1, k1, f2, k2)) segments_on_edge(f1, k1, f2, k2);
      }
    }
  }

  // Most edges: one cell on either side, glued in E across this edge (one
  // sheet), so one front and no exact arithmetic.
  bool one_sheet_across(std::size_t f1, int k1, std::size_t f2, int k2)
  {
    if(envelope_of_[f1]->cells.size() != 1 || envelope_of_[f2]->cells.size() != 1) return false;
    const std::size_t c1 = first_cell_[f1], c2 = first_cell_[f2];
    if(!glued_across(c1, k1, c2) || cells_[c1].split || cells_[c2].split ||
       kinked_along(f1, k1, edge_jump(f1, k1, c1, f2, k2, c2)))
      return false;
    fronts_.unite(c1, c2);
    return true;
  }

  // the intervals of edge k of face f (t from corner k to k + 1, or back if
  // `reversed`) and the cell that wins on each, by increasing t
  std::vector<Interval> edge_intervals(std::size_t f, int k, bool reversed) const
  {
    std::vector<Interval> out;
    for(std::size_t i = 0; i < envelope_of_[f]->cells.size(); ++i)
    {
      const auto& c = envelope_of_[f]->cells[i];
      const std::size_t n = c.polygon.size();
      for(std::size_t j = 0; j < n; ++j)
        if(is_triangle_edge_label(c.edge_label[j]) && triangle_edge_of_label(c.edge_label[j]) == k)
        {
          Q ta = c.polygon[j][(k + 1) % 3], tb = c.polygon[(j + 1) % n][(k + 1) % 3];
          if(reversed) { ta = Q(1) - ta; tb = Q(1) - tb; }
          if(tb < ta) std::swap(ta, tb);
          if(ta < tb) out.push_back(Interval{ta, tb, first_cell_[f] + i});
        }
    }
    std::sort(out.begin(), out.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
    return out;
  }

  static std::size_t cell_at(const std::vector<Interval>& side, const Q& t)
  {
    for(const auto& iv : side) if(iv.lo <= t && t <= iv.hi) return iv.cell;
    return none;
  }

  // A piece [ta, tb] of edge k1 of f1 (t from corner k1 to k1 + 1) between the
  // cell boundaries of both sides, with the cells on either side.
  struct Edge_piece { Q ta, tb; std::size_t c1, c2; Gradient_jump jump; };

  // The pieces of edge k1 of f1 (k2 of f2).
  std::vector<Edge_piece> edge_pieces(std::size_t f1, int k1, std::size_t f2, int k2) const
  {
    const std::vector<Interval> side1 = edge_intervals(f1, k1, false), side2 = edge_intervals(f2, k2, true);
    std::vector<Q> cuts;
    for(const auto* side : {&side1, &side2})
      for(const auto& i : *side) { cuts.push_back(i.lo); cuts.push_back(i.hi); }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    std::vector<Edge_piece> out;
    for(std::size_t i = 0; i + 1 < cuts.size(); ++i)
    {
      const Q mid = (cuts[i] + cuts[i + 1]) / 2;
      const std::size_t c1 = cell_at(side1, mid), c2 = cell_at(side2, mid);
      if(c1 != none && c2 != none)
        out.push_back(Edge_piece{cuts[i], cuts[i + 1], c1, c2, edge_jump(f1, k1, c1, f2, k2, c2)});
    }
    return out;
  }

  // the nodes at the ends of piece p of edge k1 of f1
  std::pair<std::size_t, std::size_t> piece_nodes(std::size_t f1, int k1, const Edge_piece& p)
  {
    std::array<Q, 3> la = {{Q(0), Q(0), Q(0)}}, lb = la;
    la[k1] = Q(1) - p.ta; la[(k1 + 1) % 3] = p.ta;
    lb[k1] = Q(1) - p.tb; lb[(k1 + 1) % 3] = p.tb;
    return {node_at(f1, la), node_at(f1, lb)};
  }

  // A ridge segment on each piece where the cells on the two sides are different fronts.
  void segments_on_edge(std::size_t f1, int k1, std::size_t f2, int k2)
  {
    for(const Edge_piece& p : edge_pieces(f1, k1, f2, k2))
    {
      const auto [a, b] = piece_nodes(f1, k1, p);
      if(a == b) continue; // (one surface point: joins no regions, no ridge)
      // a front of a split copy is one front with a glued copy only where their fields agree
      const bool glued =
          glued_across(p.c1, k1, p.c2) && !kinked_along(f1, k1, p.jump) && !cells_[p.c1].split && !cells_[p.c2].split;
      const bool thin = thin_[f1] || thin_[f2];
      if(glued || one_front_along(p.c1, k1, p.c2, k2, p.ta, p.tb, p.jump, thin))
      {
        if(!glued && thin && !one_front_along(p.c1, k1, p.c2, k2, p.ta, p.tb, p.jump, false))
          ++st_.thin_face_pieces;
        fronts_.unite(p.c1, p.c2);
        continue;
      }
      const Gradient_jump j = front_jump_across(f1, k1, f2, k2, p);
      segments_.push_back(Segment{a, b, p.c1, p.c2, j.strength, j.angle, true});
      ++st_.edge_segments;
    }
  }

  // One front across the edge piece [ta, tb]: equal values along it and no
  // real gradient jump (below the spur angle: copies of one front, one slightly
  // inexact off the edge). Equal values alone are no test: where the ridge runs
  // along the edge, both fronts agree on it. Except on an edge of a thin face
  // (`thin`, see thin_faces()), whose gradient is no test either.
  bool one_front_along(std::size_t c1, int k1, std::size_t c2, int k2, const Q& ta, const Q& tb,
                       const Gradient_jump& jump, bool thin) const
  {
    auto value = [&](const Cell& c, int k, const Q& tq) { // tq along corner k -> k+1
      const double tt = CGAL::to_double(tq);
      return (1 - tt) * c.field[k] + tt * c.field[(k + 1) % 3];
    };
    auto agree = [&](const Q& t) {
      return std::abs(value(cells_[c1], k1, t) - value(cells_[c2], k2, Q(1) - t)) <= same_front_tolerance_;
    };
    return agree(ta) && agree(tb) && (thin || jump.strength <= tuning::ridge::weak_jump || jump.angle < minimum_angle_);
  }

  // the jump across the piece p of edge k1 of f1 (edge k2 of f2), at its
  // middle, as `front_jump_in_face`
  Gradient_jump front_jump_across(std::size_t f1, int k1, std::size_t f2, int k2, const Edge_piece& p) const
  {
    const double t = CGAL::to_double((p.ta + p.tb) / 2);
    std::array<double, 3> at1 = {{0, 0, 0}}, at2 = at1; // the middle, barycentric in f1 and in f2
    at1[k1] = 1 - t;
    at1[(k1 + 1) % 3] = t;
    at2[k2] = t;
    at2[(k2 + 1) % 3] = 1 - t;
    std::array<double, 3> d1, d2;
    if(at_source(f1, k1) || at_source(f2, k2) || !arrival_direction(f1, p.c1, at1, d1) ||
       !arrival_direction(f2, p.c2, at2, d2))
      return p.jump;
    const auto cp1 = faces_.corner_points(f1), cp2 = faces_.corner_points(f2);
    return gradient_jump_across_edge(cp1[k1], cp1[(k1 + 1) % 3], cp1[(k1 + 2) % 3], cp2[(k2 + 2) % 3], d1, d2);
  }

  // One region: merge the regions of M minus the ridge, weakest segment first.
  void merge_into_one_region()
  {
    std::set<std::size_t> roots;
    for(std::size_t c = 0; c < cells_.size(); ++c) roots.insert(fronts_.find(c));
    st_.regions_before_merge = roots.size();
    std::vector<std::size_t> order(segments_.size());
    for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return segments_[a].strength < segments_[b].strength; });
    for(std::size_t i : order)
      if(fronts_.unite(segments_[i].left, segments_[i].right))
      {
        segments_[i].ridge = false;
        ++st_.merged_segments;
      }
  }

  // A merge may have cut a branch off the tree: re-add, strongest first, merged
  // segments that join two pieces of the ridge. Joining two pieces closes no
  // cycle, so no region is split again.
  void rejoin_pieces()
  {
    Union_find pieces(nodes_.size() + number_of_loops_);
    join_border_nodes(pieces); // (a piece on the border is joined to it)
    for(const Segment& sg : segments_) if(sg.ridge) pieces.unite(sg.a, sg.b);
    std::vector<std::size_t> merged;
    for(std::size_t i = 0; i < segments_.size(); ++i)
      if(!segments_[i].ridge && segments_[i].a != segments_[i].b) merged.push_back(i);
    std::stable_sort(merged.begin(), merged.end(),
                     [&](std::size_t a, std::size_t b) { return segments_[a].strength > segments_[b].strength; });
    std::vector<char> on_ridge(nodes_.size(), 0);
    for(const Segment& sg : segments_) if(sg.ridge) on_ridge[sg.a] = on_ridge[sg.b] = 1;
    for(std::size_t i : merged)
    {
      const std::size_t ra = pieces.find(segments_[i].a), rb = pieces.find(segments_[i].b);
      // only segments that touch the ridge at both ends reconnect something
      if(ra == rb || !on_ridge[segments_[i].a] || !on_ridge[segments_[i].b]) continue;
      segments_[i].ridge = true;
      pieces.unite(ra, rb);
      ++st_.rejoined_segments;
    }
  }

  // With a border, the ridge with the border is one connected graph (so is
  // K ∪ ∂M). Where two fronts meet at a small angle, or where a split copy's
  // front continues a glued one, the assembly may have united them as one front
  // and drawn no segment: the ridge then hangs from the loops in pieces and
  // M minus the pieces is no disk. Each other piece is joined to the main one
  // by the path along the boundaries between cells (envelope edges inside
  // faces, pieces of mesh edges) that is shortest in length over the gradient
  // jump (the fronts meet where the jump is large). Joining two pieces closes
  // no cycle, so the cycle rank is kept.
  void join_border_components()
  {
    if(number_of_loops_ < 2) return;
    auto unite_pieces = [&](Union_find& uf) {
      join_border_nodes(uf);
      for(const Segment& sg : segments_) if(sg.ridge && sg.a != sg.b) uf.unite(sg.a, sg.b);
    };
    {
      Union_find uf(nodes_.size() + number_of_loops_);
      unite_pieces(uf);
      std::set<std::size_t> roots;
      for(std::size_t loop = 0; loop < number_of_loops_; ++loop) roots.insert(uf.find(loop_node(loop)));
      if(roots.size() < 2) return;
    }
    const Link_graph& g = link_graph(); // (node ids as in unite_pieces: nodes_ is complete now)
    const std::size_t n = g.at.size();
    for(;;)
    {
      Union_find uf(n);
      unite_pieces(uf);
      const std::size_t main = uf.find(loop_node(0));
      std::set<std::size_t> other_loops;
      for(std::size_t loop = 1; loop < number_of_loops_; ++loop)
        if(uf.find(loop_node(loop)) != main) other_loops.insert(uf.find(loop_node(loop)));
      if(other_loops.empty()) return;
      // from the main piece to the nearest node of a piece with a loop
      std::vector<std::size_t> sources;
      for(std::size_t v = 0; v < n; ++v) if(uf.find(v) == main) sources.push_back(v);
      double path_length = 0;
      const std::vector<std::size_t> path = shortest_link_path(
          g, sources, [&](std::size_t v) { return other_loops.count(uf.find(v)) > 0; },
          [](std::size_t) { return false; }, std::numeric_limits<double>::infinity(), path_length);
      if(path.empty()) return; // (the check of the topology reports it)
      add_ridge_links(g, path);
      st_.border_joining_segments += path.size();
    }
  }

  // A piece of the ridge detached from the main one (the longest, or the
  // loops' piece) is dropped, unless it holds a verified kink: a segment
  // between two fronts of one split copy (split at a kink by the solver's
  // cones, `Kink_splitter`, or into the nearer copies' fronts it recombines,
  // `Recombined_copy_splitter`). Such a piece is a real branch whose link to
  // the rest was missed where its fronts meet at a smaller angle than a split
  // needs, or where no cone gave a corner's front (teddy_3k v894 at tolerance
  // 0.002: a branch of 13 mean edges, 3.5 from the main piece, its link 40
  // degrees). It is joined to the main piece, longest first, by the path along
  // the boundaries between cells that is shortest in length over the gradient
  // jump, through no node of another piece: two trees joined by a path close
  // no cycle. A piece with a cycle of its own stays detached (joining it would
  // add one), and so does a piece farther from the main one than its own
  // length: that is a fragment of a branch the tolerance pruned from K
  // (trim_star_10k v1038 at the default tolerance: pieces of 3 mean edges, 18
  // of path along mesh edges each, precision p95 0.07 -> 0.20 when joined).
  void join_verified_pieces()
  {
    // a node of each piece not joined (too far in space, no path, a path too
    // long); tried again after a join, which brings the main piece nearer
    std::vector<std::size_t> skipped;
    for(;;)
    {
      Pieces pieces = ridge_pieces();
      std::set<std::size_t> skip;
      for(std::size_t v : skipped) skip.insert(pieces.uf.find(v));
      std::size_t from = none;
      for(const auto& [r, p] : pieces.piece)
        if(r != pieces.main && p.verified && !p.border && p.segments + 1 == p.nodes && !skip.count(r) &&
           (from == none || p.length > pieces.piece.at(from).length))
          from = r;
      if(from == none) return;
      const double piece_length = pieces.piece.at(from).length;
      std::vector<std::size_t> from_nodes;
      for(std::size_t v = 0; v < pieces.in_piece.size(); ++v)
        if(pieces.in_piece[v] && pieces.uf.find(v) == from) from_nodes.push_back(v);
      // (a path is no shorter than the gap in space; with a border, nodes on it
      // come with the links, so the gap is not known before)
      if(number_of_loops_ == 0 && !links_ && gap_in_space(pieces, from_nodes) > piece_length)
      {
        skipped.push_back(from_nodes.front());
        continue;
      }
      // Without the whole link graph (built by the border join), the links
      // near the piece only: a joining path is no longer than the piece, so
      // it stays within that distance of it in space, and the path taken is
      // the lightest of those near the piece. (The whole graph took 0.2 s on
      // kitten_80k, source 0, fast marching: 40 % of the process. A lighter
      // path through the whole graph that is longer than the piece would have
      // left it detached: on none of bench_ridge_accuracy's 168 pairs.)
      Link_graph near;
      const Link_graph* g = links_ ? &*links_ : nullptr;
      if(!g)
      {
        const std::size_t nodes_before = nodes_.size();
        near = links_within(from_nodes, piece_length);
        g = &near;
        if(nodes_.size() != nodes_before) pieces = ridge_pieces(); // (the loops' node ids moved)
        from = pieces.uf.find(from_nodes.front());
      }
      auto piece_of = [&](std::size_t v) { return pieces.in_piece[v] ? pieces.uf.find(v) : none; };
      double path_length = 0;
      const std::vector<std::size_t> path = shortest_link_path(
          *g, from_nodes, [&](std::size_t v) { return piece_of(v) == pieces.main; },
          [&](std::size_t v) { return piece_of(v) != none && piece_of(v) != from; }, piece_length, path_length);
      if(path.empty() || path_length > piece_length)
      {
        skipped.push_back(from_nodes.front());
        continue;
      }
      add_ridge_links(*g, path);
      st_.piece_joining_segments += path.size();
      skipped.clear();
    }
  }

  // The boundaries between cells (`cell_boundary_links()`) as a graph: per
  // node, the links at it. The whole graph is built once (it completes nodes_).
  struct Link_graph { std::vector<Segment> links; std::vector<std::vector<std::size_t> > at; };
  Link_graph make_link_graph(std::vector<Segment> links) const
  {
    Link_graph g;
    g.links = std::move(links);
    g.at.assign(nodes_.size() + number_of_loops_, {});
    for(std::size_t i = 0; i < g.links.size(); ++i) { g.at[g.links[i].a].push_back(i); g.at[g.links[i].b].push_back(i); }
    return g;
  }
  const Link_graph& link_graph()
  {
    if(!links_) links_ = make_link_graph(cell_boundary_links([](std::size_t) { return true; }));
    return *links_;
  }

  // The link graph of the faces that come within `reach` of a node of
  // `around` (their bounding boxes overlap).
  Link_graph links_within(const std::vector<std::size_t>& around, double reach)
  {
    CGAL::Bbox_3 box;
    for(std::size_t v : around) box += nodes_[v].point.bbox();
    box = CGAL::Bbox_3(box.xmin() - reach, box.ymin() - reach, box.zmin() - reach, box.xmax() + reach,
                       box.ymax() + reach, box.zmax() + reach);
    std::vector<char> in(nf_, 0);
    for(std::size_t f = 0; f < nf_; ++f)
    {
      const auto p = faces_.corner_points(f);
      in[f] = CGAL::do_overlap(box, p[0].bbox() + p[1].bbox() + p[2].bbox());
    }
    return make_link_graph(cell_boundary_links([&](std::size_t f) { return in[f] != 0; }));
  }

  // The links from a node of `sources` to the first node with is_goal() that
  // are shortest in length over the gradient jump (the fronts meet where the
  // jump is large), through no node with blocked(), as long as that sum stays
  // within max_weight (it is at most the path's length); and their length.
  // Empty if there is none.
  template <class IsGoal, class IsBlocked>
  std::vector<std::size_t> shortest_link_path(const Link_graph& g, const std::vector<std::size_t>& sources,
                                              const IsGoal& is_goal, const IsBlocked& blocked, double max_weight,
                                              double& path_length) const
  {
    const std::size_t n = g.at.size();
    std::vector<double> dist(n, std::numeric_limits<double>::infinity());
    std::vector<std::size_t> via(n, none);
    typedef std::pair<double, std::size_t> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
    for(std::size_t v : sources) { dist[v] = 0; queue.emplace(0.0, v); }
    std::size_t reached = none;
    while(!queue.empty() && reached == none)
    {
      const auto [d, v] = queue.top();
      queue.pop();
      if(d > dist[v]) continue;
      if(d > max_weight) break;
      if(is_goal(v)) { reached = v; continue; }
      if(via[v] != none && blocked(v)) continue; // (a source is never blocked)
      for(std::size_t i : g.at[v])
      {
        const Segment& link = g.links[i];
        const std::size_t w = link.a == v ? link.b : link.a;
        const double dw = d + length(link) / std::max(link.angle, 1.0);
        if(dw < dist[w]) { dist[w] = dw; via[w] = i; queue.emplace(dw, w); }
      }
    }
    std::vector<std::size_t> path;
    path_length = 0;
    for(std::size_t v = reached; v != none && via[v] != none;)
    {
      const Segment& link = g.links[via[v]];
      path.push_back(via[v]);
      path_length += length(link);
      v = link.a == v ? link.b : link.a;
    }
    return path;
  }

  // The links of `path` (indices into the link graph g) made ridge segments.
  void add_ridge_links(const Link_graph& g, const std::vector<std::size_t>& path)
  {
    for(std::size_t i : path)
    {
      segments_.push_back(g.links[i]);
      segments_.back().ridge = true;
    }
  }

  // The pieces of the ridge: nodes joined by ridge segments, the loops and
  // the nodes on them; per piece its length, segments and nodes (a tree has
  // one node more), whether it holds a verified kink (two fronts of one split
  // copy) or the border; the main piece (the loops', or the longest).
  struct Piece { double length = 0; std::size_t segments = 0, nodes = 0; bool verified = false, border = false; };
  struct Pieces
  {
    Union_find uf;
    std::vector<char> in_piece; // per node
    std::map<std::size_t, Piece> piece;
    std::size_t main = none;
  };
  Pieces ridge_pieces() const
  {
    const std::size_t n = nodes_.size() + number_of_loops_;
    Pieces x{Union_find(n), std::vector<char>(n, 0), {}, none};
    join_border_nodes(x.uf);
    for(std::size_t v = 0; v < n; ++v) x.in_piece[v] = v >= nodes_.size() || node_loop_[v] != none;
    for(const Segment& sg : segments_)
      if(sg.ridge && sg.a != sg.b) { x.uf.unite(sg.a, sg.b); x.in_piece[sg.a] = x.in_piece[sg.b] = 1; }
    for(const Segment& sg : segments_)
      if(sg.ridge && sg.a != sg.b)
      {
        Piece& p = x.piece[x.uf.find(sg.a)];
        p.length += length(sg);
        ++p.segments;
        p.verified = p.verified || (cells_[sg.left].split && cells_[sg.right].split &&
                                    cells_[sg.left].copy == cells_[sg.right].copy);
      }
    for(std::size_t v = 0; v < n; ++v)
      if(x.in_piece[v])
      {
        Piece& p = x.piece[x.uf.find(v)];
        ++p.nodes;
        p.border = p.border || v >= nodes_.size() || node_loop_[v] != none;
      }
    if(number_of_loops_ > 0) x.main = x.uf.find(loop_node(0));
    else
      for(const auto& [r, p] : x.piece) if(x.main == none || p.length > x.piece.at(x.main).length) x.main = r;
    return x;
  }

  // The distance in space from the nodes `from_nodes` to the main piece's
  // (no path along the surface is shorter).
  double gap_in_space(const Pieces& pieces, const std::vector<std::size_t>& from_nodes) const
  {
    double gap = std::numeric_limits<double>::infinity();
    for(std::size_t b = 0; b < nodes_.size(); ++b)
      if(pieces.in_piece[b] && pieces.uf.find(b) == pieces.main)
        for(std::size_t a : from_nodes)
          gap = std::min(gap, CGAL::to_double(CGAL::squared_distance(nodes_[a].point, nodes_[b].point)));
    return std::sqrt(gap);
  }

  // Every boundary between two cells as a segment: the envelope's edges inside
  // faces, and the pieces of the mesh's inner edges between the cell boundaries
  // of both sides (whole edges where one copy covers each side).
  template <class InFace>
  std::vector<Segment> cell_boundary_links(const InFace& in_face)
  {
    std::vector<Segment> links;
    for(std::size_t f = 0; f < nf_; ++f)
    {
      if(!in_face(f)) continue;
      for(const auto& s : envelope_of_[f]->segments)
      {
        const std::size_t ca = cell_of(f, s.copy_a), cb = cell_of(f, s.copy_b);
        const std::size_t a = node_at(f, s.endpoints[0]), b = node_at(f, s.endpoints[1]);
        if(a == b) continue;
        const Gradient_jump j = gradient_jump_in_face(cells_[ca], cells_[cb]);
        links.push_back(Segment{a, b, ca, cb, j.strength, j.angle, false});
      }
    }
    std::vector<char> edge_done(num_edges(tm_), 0);
    for(std::size_t f1 = 0; f1 < nf_; ++f1)
    {
      const auto h1s = faces_.corner_halfedges(f1);
      for(int k1 = 0; k1 < 3; ++k1)
      {
        const std::size_t e = get(maps_.eim, edge(h1s[k1], tm_));
        const halfedge_descriptor h2 = opposite(h1s[k1], tm_);
        if(edge_done[e] || is_border(h2, tm_)) continue;
        edge_done[e] = 1;
        const std::size_t f2 = get(maps_.fim, face(h2, tm_));
        if(!in_face(f1) && !in_face(f2)) continue;
        const auto h2s = faces_.corner_halfedges(f2);
        int k2 = 0;
        while(h2s[k2] != h2) ++k2;
        for(const Edge_piece& p : edge_pieces(f1, k1, f2, k2))
        {
          const auto [a, b] = piece_nodes(f1, k1, p);
          if(a != b) links.push_back(Segment{a, b, p.c1, p.c2, p.jump.strength, p.jump.angle, false});
        }
      }
    }
    return links;
  }

  // Prune spurs. A free end of the cut locus of a polyhedral surface is a
  // vertex of positive curvature (angle sum < 2π): a free end with no such
  // curvature around it (within 2.5 mean edges, summed with signs) is no ridge
  // end, typically the crease along the shadow line of the tip of a false
  // branch of K, where two copies that are both slightly inexact meet at a
  // moderate angle (below 3 x `minimum_angle`; a branch that stops short of its
  // true end has a large one). A free end whose segment's gradient jump is
  // below `minimum_angle` cannot be located either (two fronts meeting at a
  // small angle). Both are removed, repeatedly; cycles and segments between
  // junctions are never touched.
  void prune_spurs()
  {
    const double minimum_curvature = radians(tuning::ridge::spur_curvature_share * minimum_angle_);
    // A weak free end with at least this much curvature around it (a cube's
    // corner has 90 degrees) ends where the cut locus must: at a vertex of
    // positive curvature. It is kept: its position is ill-conditioned, but the
    // branch is real. Measured (bench_ridge_accuracy): bunny_1k v0 recall p95
    // 2.38 -> 0.75 mean edges, precision p95 0.27 -> 0.44; the convex test
    // polyhedra reach 8 more corners.
    const double corner_curvature = radians(tuning::ridge::spur_corner_degrees);
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
    const double corner_end_angle = minimum_angle_ / tuning::ridge::spur_corner_end_divisor;
    // But a weak end exactly at a vertex of M without positive curvature (a
    // saddle, or a flat vertex of a CAD model's face) ends where the cut locus
    // cannot, whatever the curvature around it: the ridge drawn there is a
    // false branch (or one that ran past its true end), and the whole chain
    // of weak segments behind it goes, corner or not. Measured
    // (bench_ridge_accuracy, exact): real models' precision p95 <= 0.5 on 70
    // -> 72 of 72 pairs (fandisk v3237 0.34 -> 0.16, suzanne v0 0.58 -> 0.39),
    // the CAD boxes 10 -> 16 of 24; a floor of 5 degrees of curvature instead
    // of 0 lost a real branch of bunny_7k (recall 0.03 -> 5.9 mean edges).
    std::vector<char> on_impossible_chain(nodes_.size(), 0);
    Curvature_near curvature_near(*this);
    std::vector<std::vector<std::size_t> > at(nodes_.size());
    std::vector<std::size_t> live(nodes_.size(), 0);
    for(std::size_t i = 0; i < segments_.size(); ++i)
      if(segments_[i].ridge && segments_[i].a != segments_[i].b)
      {
        at[segments_[i].a].push_back(i); at[segments_[i].b].push_back(i);
        ++live[segments_[i].a]; ++live[segments_[i].b];
      }
    std::vector<std::size_t> leaves;
    // (a node on the border is no free end: the ridge goes on along the border)
    for(std::size_t v = 0; v < nodes_.size(); ++v) if(live[v] == 1 && node_loop_[v] == none) leaves.push_back(v);
    while(!leaves.empty())
    {
      const std::size_t v = leaves.back();
      leaves.pop_back();
      if(live[v] != 1) continue;
      std::size_t seg = none;
      for(std::size_t i : at[v]) if(segments_[i].ridge) { seg = i; break; }
      if(seg == none) continue;
      const double curvature_here = curvature_near(v);
      const bool impossible_end = on_impossible_chain[v] || at_vertex_without_curvature(v);
      // a weak end at a corner (curvature like that of a cube's) is a real
      // leaf, unless its jump is too small for any corner's or it lies where
      // no cut locus ends
      const bool weak = segments_[seg].angle < minimum_angle_ &&
                        (impossible_end || curvature_here < corner_curvature || segments_[seg].angle < corner_end_angle);
      const bool flat = !weak && curvature_here < minimum_curvature;
      const bool flat_end = flat && segments_[seg].angle < 3 * minimum_angle_;
      if(!weak && !flat_end) continue;
      segments_[seg].ridge = false;
      ++(weak ? st_.pruned_spur_segments : st_.pruned_flat_end_segments);
      --live[v];
      const std::size_t w = segments_[seg].a == v ? segments_[seg].b : segments_[seg].a;
      if(weak && impossible_end) on_impossible_chain[w] = 1;
      if(--live[w] == 1 && node_loop_[w] == none) leaves.push_back(w);
    }
  }

  // Gaussian curvature of a vertex (by index) as `Corner_angles::curvature`;
  // none on the border (its angle sum measures the border's turning)
  double vertex_curvature(std::size_t v) const { return loop_of_vertex_[v] == none ? 2 * CGAL_PI - angle_sum_[v] : 0.0; }

  // Whether a node lies exactly on an inner vertex of M whose curvature is not
  // positive: a saddle, or a flat vertex (below 1e-9 radians: the rounding of
  // a flat vertex's angle sum).
  bool at_vertex_without_curvature(std::size_t node) const
  {
    const Ridge_point<Point>& p = nodes_[node];
    const auto h = faces_.corner_halfedges(p.face);
    for(int i = 0; i < 3; ++i)
      if(p.barycentric[i] == 1.0) // (exact: a node at a vertex has λ = 1 there)
      {
        const std::size_t v = get(maps_.vim, source(h[i], tm_));
        return loop_of_vertex_[v] == none && vertex_curvature(v) <= tuning::ridge::flat_vertex_curvature;
      }
    return false;
  }

  // The total curvature of the vertices within 2.5 mean edges of a node (grown
  // from its face's corners).
  struct Curvature_near
  {
    const Ridge_curve_assembler& a;
    std::vector<vertex_descriptor> vertex_of;
    std::vector<std::size_t> seen_at;

    explicit Curvature_near(const Ridge_curve_assembler& assembler)
      : a(assembler), vertex_of(num_vertices(a.tm_)), seen_at(num_vertices(a.tm_), none)
    {
      for(vertex_descriptor v : vertices(a.tm_)) vertex_of[get(a.maps_.vim, v)] = v;
    }

    double operator()(std::size_t node)
    {
      const double radius = tuning::ridge::curvature_radius * a.mean_edge_;
      const Point& p = a.nodes_[node].point;
      std::vector<std::size_t> stack;
      double total = 0;
      for(const auto h : a.faces_.corner_halfedges(a.nodes_[node].face))
      {
        const std::size_t v = get(a.maps_.vim, source(h, a.tm_));
        if(seen_at[v] != node) { seen_at[v] = node; stack.push_back(v); total += a.vertex_curvature(v); }
      }
      while(!stack.empty())
      {
        const std::size_t v = stack.back();
        stack.pop_back();
        for(auto h : CGAL::halfedges_around_target(halfedge(vertex_of[v], a.tm_), a.tm_))
        {
          const std::size_t w = get(a.maps_.vim, source(h, a.tm_));
          if(seen_at[w] == node) continue;
          seen_at[w] = node;
          if(std::sqrt(CGAL::to_double(CGAL::squared_distance(get(a.maps_.vpm, vertex_of[w]), p))) > radius) continue;
          total += a.vertex_curvature(w);
          stack.push_back(w);
        }
      }
      return total;
    }
  };

  double length(const Segment& s) const
  {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(nodes_[s.a].point, nodes_[s.b].point)));
  }

  // Keep the main component as polylines: on a closed mesh the longest one,
  // with a border every piece joined to the border (K ∪ ∂M is connected, and
  // so is the ridge with the border); drop degenerate segments.
  void keep_main_component(std::vector<std::vector<Ridge_point<Point> > >& polylines)
  {
    Union_find comp(nodes_.size() + number_of_loops_);
    join_border_nodes(comp); // (a piece on the border is joined to it)
    for(const Segment& s : segments_) if(s.ridge && s.a != s.b) comp.unite(s.a, s.b);
    std::map<std::size_t, double> comp_length;
    for(const Segment& s : segments_) if(s.ridge && s.a != s.b) comp_length[comp.find(s.a)] += length(s);
    std::set<std::size_t> main;
    for(std::size_t loop = 0; loop < number_of_loops_; ++loop) main.insert(comp.find(loop_node(loop)));
    double best = -1;
    if(number_of_loops_ == 0)
      for(const auto& [r, l] : comp_length) if(l > best) { best = l; main = {r}; }
    st_.dropped_components = 0;
    for(const auto& rl : comp_length) st_.dropped_components += main.count(rl.first) == 0;

    std::vector<std::pair<std::size_t, std::size_t> > graph;
    std::vector<std::size_t> degree(nodes_.size(), 0);
    for(const Segment& s : segments_)
      if(s.ridge && s.a != s.b && main.count(comp.find(s.a)))
      {
        graph.emplace_back(s.a, s.b);
        ++degree[s.a]; ++degree[s.b];
        nodes_[s.a].angle = std::max(nodes_[s.a].angle, s.angle);
        nodes_[s.b].angle = std::max(nodes_[s.b].angle, s.angle);
        st_.total_length += length(s);
      }
    count_topology(graph, degree);
    polylines.clear();
    for(const auto& chain : graph_to_chains(nodes_.size(), graph))
    {
      std::vector<Ridge_point<Point> > pl;
      for(std::size_t v : chain) pl.push_back(nodes_[v]);
      polylines.push_back(std::move(pl));
    }
  }

  // Junctions, free ends, and the components and cycle rank of the ridge with
  // the border: each loop collapsed to a node, joined to the ridge nodes on it,
  // and counted again as the cycle it is.
  void count_topology(const std::vector<std::pair<std::size_t, std::size_t> >& graph,
                      const std::vector<std::size_t>& degree)
  {
    st_.ridge_segments = graph.size();
    Union_find uf(nodes_.size() + number_of_loops_);
    join_border_nodes(uf); // (a piece on the border is joined to it)
    std::size_t used_nodes = 0, border_links = 0;
    for(std::size_t v = 0; v < nodes_.size(); ++v)
    {
      if(degree[v] == 0) continue;
      ++used_nodes;
      border_links += node_loop_[v] != none;
      st_.junctions += degree[v] >= 3;
      st_.free_ends += degree[v] == 1 && node_loop_[v] == none;
    }
    for(const auto& [a, b] : graph) uf.unite(a, b);
    std::set<std::size_t> components;
    for(std::size_t v = 0; v < nodes_.size(); ++v) if(degree[v] > 0) components.insert(uf.find(v));
    for(std::size_t loop = 0; loop < number_of_loops_; ++loop) components.insert(uf.find(loop_node(loop)));
    st_.components = components.size();
    // rank = edges - vertices + components, of the graph with the loop nodes, plus the b loops
    if(st_.components > 0) st_.cycles = graph.size() + border_links + st_.components - used_nodes;
  }

  const TriangleMesh& tm_;
  const Maps maps_;
  const Extended_surface<Point>& E_;
  const std::vector<Face_copies>& face_copies_;
  const double mean_edge_, minimum_angle_, kink_angle_;
  const std::vector<double>& angle_sum_; // per vertex of M (by index): the sum of its corner angles
  std::vector<std::vector<Ridge_region_cell> >& regions_;
  Ridge_curve_statistics& st_;
  const Faces_by_index<TriangleMesh, typename Maps::Vertex_point_map> faces_;
  const std::size_t nf_;
  const double same_front_tolerance_;
  const Copy_cones* cones_; // the solver's cones, if read (else the linear fields' jumps)
  std::vector<char> thin_; // per face of M: thin (see thin_faces())
  // per face: its envelope, either the shared whole-triangle one or one of
  // `computed_` (a deque: pointers into it stay valid as it grows)
  Lower_envelope<Q> whole_triangle_;
  std::deque<Lower_envelope<Q> > computed_;
  std::vector<const Lower_envelope<Q>*> envelope_of_;
  std::vector<Cell> cells_;
  std::vector<std::size_t> first_cell_; // per face, then the number of cells
  std::map<Key, std::size_t> node_of_;
  std::vector<Ridge_point<Point> > nodes_;
  std::vector<Segment> segments_;
  std::optional<Link_graph> links_; // the boundaries between cells, once needed
  Union_find fronts_; // cells that are one front
  // the border: per vertex of M its loop (or none), per node its loop (or none)
  std::vector<std::size_t> loop_of_vertex_, node_loop_;
  std::size_t number_of_loops_ = 0;
  // one node per surface point: the nodes' points, and per node the
  // dimension of the feature its location is on (0 vertex, 1 edge, 2 face)
  Coincident_points coincident_;
  std::vector<int> node_feature_;
};

template <class TriangleMesh, class Point, class Maps>
void assemble_ridge_curve(const TriangleMesh& tm, const Extended_surface<Point>& E,
                          const std::vector<Face_copies>& face_copies, double mean_edge,
                          double minimum_angle, double kink_angle, const Maps& maps,
                          const std::vector<double>& angle_sum,
                          std::vector<std::vector<Ridge_point<Point> > >& polylines,
                          std::vector<std::vector<Ridge_region_cell> >& regions,
                          Ridge_curve_statistics& st, const Copy_cones* cones = nullptr)
{
  Ridge_curve_assembler<TriangleMesh, Maps>(tm, E, face_copies, mean_edge, minimum_angle, kink_angle, maps, angle_sum,
                                            regions, st, cones)
      .run(polylines);
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_RIDGE_CURVE_H
