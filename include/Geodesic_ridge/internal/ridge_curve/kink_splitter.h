// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 pass (before the envelopes, with the solver's cones): copies split
// at a kink between the fronts of their corners.
// Test: test_ridge_curve.cpp, "a copy is split at a kink between its corners'
// fronts"; test_ridge_accuracy.cpp, "kinks inside one sheet: ...".
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_KINK_SPLITTER_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_KINK_SPLITTER_H

#include <Geodesic_ridge/extended_surface.h>
#include <Geodesic_ridge/internal/face_copies.h>
#include <Geodesic_ridge/internal/faces_by_index.h>
#include <Geodesic_ridge/internal/tuning.h>
#include <Geodesic_ridge/internal/ridge_curve/split_field.h>
#include <Geodesic_ridge/solvers/Face_cone.h>

#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

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

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_KINK_SPLITTER_H
