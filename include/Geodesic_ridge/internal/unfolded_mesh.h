// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh as window propagation reads it (`Window_propagation`): flat
// arrays, half-edge `3 f + i` face f's edge from its corner i to corner i+1
// (corners in CGAL's order from `halfedge(f)`), each half-edge's frame (its
// first corner at the origin, the edge along x, its face above), and around
// every vertex the angles of its half-edges and what kind of vertex it is.
// Built once per mesh; the propagation's runs only read it.
#ifndef GEODESIC_RIDGE_INTERNAL_UNFOLDED_MESH_H
#define GEODESIC_RIDGE_INTERNAL_UNFOLDED_MESH_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/face_cone_field.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

class Unfolded_mesh
{
public:
  struct Vec2
  {
    double x, y;
  };


  template <class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap>
  Unfolded_mesh(const TriangleMesh& tm, const VertexPointMap& vpm, const VertexIndexMap& vim,
                const FaceIndexMap& fim)
  {
    const std::size_t nv = num_vertices(tm), nf = num_faces(tm);
    point_.resize(nv);
    for(auto v : vertices(tm))
    {
      const auto& p = get(vpm, v);
      point_[get(vim, v)] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    }
    corner_.resize(3 * nf);
    twin_.assign(3 * nf, none);
    for(auto f : faces(tm))
    {
      const std::size_t fi = get(fim, f);
      int i = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      {
        corner_[3 * fi + i] = static_cast<std::uint32_t>(get(vim, source(h, tm)));
        ++i;
      }
      // unfolding needs triangles of positive area (decided exactly)
      typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 P;
      auto at = [&](int k) { const auto& q = point_[corner_[3 * fi + k]]; return P(q[0], q[1], q[2]); };
      if(CGAL::collinear(at(0), at(1), at(2)))
        throw Invalid_mesh_error("face " + std::to_string(fi) +
                                 " is degenerate (its corners are collinear): window propagation needs "
                                 "triangles of positive area");
    }
    for(auto f : faces(tm))
    {
      const std::size_t fi = get(fim, f);
      int i = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      {
        const auto o = opposite(h, tm);
        if(!is_border(o, tm))
        {
          const std::size_t gi = get(fim, face(o, tm));
          int j = 0;
          for(auto g : CGAL::halfedges_around_face(halfedge(face(o, tm), tm), tm))
          {
            if(g == o) twin_[3 * fi + i] = 3 * gi + j;
            ++j;
          }
        }
        ++i;
      }
    }
    // edge lengths, the far corner of each half-edge's face in its frame, the
    // corner angles, the vertices' borders, the faces around each vertex
    length_.resize(3 * nf);
    apex_.resize(3 * nf);
    corner_angle_.resize(3 * nf);
    star_begin_.assign(nv + 1, 0);
    for(std::size_t h = 0; h < 3 * nf; ++h)
    {
      const auto& a = point_[corner_[h]];
      const auto& b = point_[corner_[next(h)]];
      const auto& c = point_[corner_[prev(h)]];
      const std::array<double, 3> u = minus(b, a), w = minus(c, a);
      length_[h] = norm(u);
      const double x = dot(u, w) / length_[h];
      const std::array<double, 3> cr = cross(u, w);
      apex_[h] = {x, norm(cr) / length_[h]};
      corner_angle_[h] = std::atan2(norm(cr), dot(u, w));
      ++star_begin_[corner_[h] + 1];
    }
    for(std::size_t v = 0; v < nv; ++v) star_begin_[v + 1] += star_begin_[v];
    star_.resize(3 * nf);
    std::vector<std::size_t> fill(star_begin_.begin(), star_begin_.end() - 1);
    for(std::size_t h = 0; h < 3 * nf; ++h) star_[fill[corner_[h]]++] = h;
    order_stars();
  }

  /// face f in its plane (corner 0 at the origin, corner 1 on the x axis)
  Face_plane plane(std::size_t f) const { return Face_plane(length_[3 * f], apex_[3 * f].x, apex_[3 * f].y); }

protected:
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

  static std::size_t next(std::size_t h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static std::size_t prev(std::size_t h) { return h % 3 == 0 ? h + 2 : h - 1; }
  static std::array<double, 3> minus(const std::array<double, 3>& a, const std::array<double, 3>& b)
  {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  }
  static double dot(const std::array<double, 3>& a, const std::array<double, 3>& b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
  static std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b)
  {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  static double norm(const std::array<double, 3>& a) { return std::sqrt(dot(a, a)); }
  static double distance2(Vec2 a, Vec2 b) { return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)); }
  static double cross2(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

  // point p of face(h)'s closed triangle in the frame of half-edge h (y >= 0)
  Vec2 in_edge_frame(std::size_t h, const std::array<double, 3>& p) const
  {
    const std::array<double, 3> u = minus(point_[corner_[next(h)]], point_[corner_[h]]);
    const std::array<double, 3> w = minus(p, point_[corner_[h]]);
    return {dot(u, w) / length_[h], norm(cross(u, w)) / length_[h]};
  }

  // Around each vertex, the directions of its half-edges as angles turning
  // counterclockwise from the first (after the border, if any), its total
  // angle, and whether it is a pseudo-source: a saddle (total angle above
  // 2 pi) or a border vertex, where shortest paths may bend.
  void order_stars()
  {
    const std::size_t nv = point_.size();
    theta_.assign(corner_.size(), 0.);
    total_angle_.assign(nv, 0.);
    kind_.assign(nv, Vertex_kind::plain);
    const double two_pi = 2 * std::acos(-1.);
    for(std::size_t v = 0; v < nv; ++v)
    {
      const std::size_t count = star_begin_[v + 1] - star_begin_[v];
      if(count == 0) continue;
      std::size_t first = star_[star_begin_[v]];
      bool border = false;
      for(std::size_t k = star_begin_[v]; k < star_begin_[v + 1]; ++k)
        if(twin_[star_[k]] == none) { first = star_[k]; border = true; }
      // counterclockwise around v: the next half-edge from v is the twin of
      // the current face's edge into v
      double theta = 0.;
      std::size_t seen = 0;
      for(std::size_t h = first; h != none && seen <= count;)
      {
        theta_[h] = theta;
        theta += corner_angle_[h];
        ++seen;
        h = twin_[prev(h)];
        if(h == first) break;
      }
      total_angle_[v] = theta;
      if(seen != count) kind_[v] = Vertex_kind::unordered; // not one fan or disk: emit everywhere
      else if(border) kind_[v] = Vertex_kind::border;
      else if(theta > two_pi * (1 + 1e-12)) kind_[v] = Vertex_kind::saddle;
    }
  }


  std::vector<std::array<double, 3> > point_;
  std::vector<std::uint32_t> corner_;
  std::vector<std::size_t> twin_;
  std::vector<double> length_;
  std::vector<Vec2> apex_;
  std::vector<double> corner_angle_, theta_, total_angle_;
  enum class Vertex_kind : char { plain, saddle, border, unordered };
  std::vector<Vertex_kind> kind_;
  std::vector<std::size_t> star_begin_, star_;

};

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_UNFOLDED_MESH_H
