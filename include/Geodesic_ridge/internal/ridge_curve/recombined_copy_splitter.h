// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 pass (before the envelopes): copies that recombine the fronts of
// nearer copies split into those fronts (the class's comment says how).
// Its thresholds: a corner's owner within a tenth of a mean edge of the
// copy's distance (`tuning::ridge::recombined_witness_tolerance`; 0.05 missed
// teddy_3k v383 and bunny_1k v80 at tolerance 0.002, 0.25 placed teddy_3k
// v383's ridge worse), owners 30 degrees apart (the fronts meet where the
// precision is measured). With the cone field too: the cone ridge is traced
// from the linear one and keeps its branches. Measured (bunny_7k v1951 and
// f6223, bunny_1k v80 at tolerance 0.002): recall p95 2.52, 2.34 and 0.61 mean
// edges without the split, 0.23, 0.21 and 0.10 with it; `bench_ridge_accuracy
// --without recombined-copy-split` measures it again. Test: test_ridge_accuracy.cpp,
// "copies that recombine nearer sheets' fronts: the major ridge at a small tolerance".
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_RECOMBINED_COPY_SPLITTER_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_RECOMBINED_COPY_SPLITTER_H

#include <Geodesic_ridge/extended_surface.h>
#include <Geodesic_ridge/internal/face_copies.h>
#include <Geodesic_ridge/internal/faces_by_index.h>
#include <Geodesic_ridge/internal/field_gradients.h>
#include <Geodesic_ridge/internal/ridge_curve/split_field.h>

#include <CGAL/Kernel_traits.h>

#include <array>
#include <cmath>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

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

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_RECOMBINED_COPY_SPLITTER_H
