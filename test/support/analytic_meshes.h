// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test support: meshes whose geodesic cut locus is known analytically (user
// manual, "Analytic Cases"), and the small geometric helpers the oracle tests
// need.
//
// * `make_doubly_covered_square()`: two flat sheets [0,1]^2 glued along their
//   border, both at z = 0 (coincident in 3D; the package's validation is
//   combinatorial plus an exact collinearity test per face, and the geodesic
//   geometry of a flat sheet is exact). For a source (a,b) on the top sheet the
//   cut locus lies on the bottom sheet: it is the Voronoi diagram, restricted to
//   the square, of the four mirror images of the source across the border lines
//   (`Doubly_covered_square_oracle`).
// * `make_subdivided_polyhedron()` with `box_corners_and_faces()`,
//   `regular_tetrahedron_corners_and_faces()`, `regular_octahedron_corners_and_faces()`:
//   convex polyhedra whose flat faces are finely triangulated; optionally the
//   subdivision points are moved at random inside their flat face (or along
//   their polyhedron edge), so that the polyhedron's corners stay the only
//   points of non-zero curvature. On a convex polyhedron every corner other
//   than the source is a leaf of the cut locus.
//
// Random perturbations are seeded; the seed is stored in the result and
// printed by the tests. The environment variable GEODESIC_RIDGE_TEST_SEED, if
// set, overrides every seed (to replay or to explore).
#ifndef GEODESIC_RIDGE_TEST_SUPPORT_ANALYTIC_MESHES_H
#define GEODESIC_RIDGE_TEST_SUPPORT_ANALYTIC_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace testing {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point_3;
typedef K::Vector_3                                         Vector_3;
typedef CGAL::Surface_mesh<Point_3>                         Mesh;

/// The seed to use: `seed`, unless GEODESIC_RIDGE_TEST_SEED is set.
inline unsigned test_seed(unsigned seed)
{
  if(const char* s = std::getenv("GEODESIC_RIDGE_TEST_SEED"))
    return static_cast<unsigned>(std::strtoul(s, nullptr, 10));
  return seed;
}

/// A mesh from a triangle soup, keeping the vertex and face order (the soup is
/// consistently oriented and manifold by construction; this is checked).
inline Mesh mesh_from_soup(const std::vector<Point_3>& points,
                           const std::vector<std::array<std::size_t, 3> >& triangles)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<std::vector<std::size_t> > polygons;
  for(const auto& t : triangles) polygons.push_back({t[0], t[1], t[2]});
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw std::logic_error("analytic mesh generator: the soup is not an oriented manifold polygon mesh");
  Mesh m;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, m);
  if(m.number_of_faces() != triangles.size() || m.number_of_vertices() != points.size())
    throw std::logic_error("analytic mesh generator: polygon_soup_to_polygon_mesh changed the sizes");
  return m;
}

inline double mean_edge_length(const Mesh& m)
{
  double s = 0;
  for(auto e : m.edges())
    s += std::sqrt(CGAL::squared_distance(m.point(m.source(m.halfedge(e))), m.point(m.target(m.halfedge(e)))));
  return s / static_cast<double>(m.number_of_edges());
}

// ---------------------------------------------------------------------------
// Doubly covered square

/// Two sheets [0,1]^2 x {0} glued along the border. Vertex (i, j) of the top
/// sheet (point (i/n, j/n) before perturbation) is `top[i + (n+1) j]`; the
/// border vertices are shared by both sheets. Top faces face +z, bottom faces
/// face -z; `bottom_face[f]` says which sheet face index f is on.
struct Doubly_covered_square
{
  Mesh mesh;
  int n = 0;
  double perturbation = 0; ///< maximal move of an interior vertex, per coordinate, in grid steps
  unsigned seed = 0;
  std::vector<Mesh::Vertex_index> top, bottom;
  std::vector<char> bottom_face;
};

/// The n x n grid of the unit square (n >= 3), every cell split by the diagonal
/// that points to the square's centre (so that no triangle has three border
/// vertices and the two sheets never share a triangle). Interior vertices of
/// both sheets are then moved by up to `perturbation` grid steps in x and in y
/// (uniformly, seeded; redrawn if a triangle would flip or become thinner
/// than 1/20 of a grid triangle), within the plane z = 0.
inline Doubly_covered_square make_doubly_covered_square(int n, double perturbation = 0, unsigned seed = 1)
{
  if(n < 3) throw std::invalid_argument("make_doubly_covered_square: n >= 3");
  if(perturbation < 0 || perturbation > 0.4)
    throw std::invalid_argument("make_doubly_covered_square: perturbation in [0, 0.4]");
  Doubly_covered_square s;
  s.n = n;
  s.perturbation = perturbation;
  s.seed = seed;
  const double h = 1.0 / n;
  const std::size_t nn = static_cast<std::size_t>(n + 1) * (n + 1);
  std::vector<std::size_t> top(nn), bottom(nn);
  std::vector<std::array<double, 2> > xy;
  auto border = [n](int i, int j) { return i == 0 || j == 0 || i == n || j == n; };
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      top[i + (n + 1) * j] = xy.size();
      xy.push_back({{i * h, j * h}});
    }
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      if(border(i, j)) bottom[i + (n + 1) * j] = top[i + (n + 1) * j];
      else
      {
        bottom[i + (n + 1) * j] = xy.size();
        xy.push_back({{i * h, j * h}});
      }
  // triangles: top counter-clockwise seen from +z, bottom clockwise
  std::vector<std::array<std::size_t, 3> > tris;
  std::vector<char> is_bottom;
  for(int sheet = 0; sheet < 2; ++sheet)
  {
    const std::vector<std::size_t>& id = sheet == 0 ? top : bottom;
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
      {
        const std::size_t a = id[i + (n + 1) * j], b = id[i + 1 + (n + 1) * j],
                          c = id[i + 1 + (n + 1) * (j + 1)], d = id[i + (n + 1) * (j + 1)];
        const bool main_diagonal = (2 * i + 1 < n) == (2 * j + 1 < n); // towards the centre
        std::array<std::array<std::size_t, 3>, 2> t;
        if(main_diagonal) t = {{{{a, b, c}}, {{a, c, d}}}};
        else t = {{{{a, b, d}}, {{b, c, d}}}};
        for(auto tri : t)
        {
          if(sheet == 1) std::swap(tri[1], tri[2]);
          tris.push_back(tri);
          is_bottom.push_back(static_cast<char>(sheet));
        }
      }
  }
  // perturbation of interior vertices (both sheets), seeded, in the plane
  if(perturbation > 0)
  {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-perturbation * h, perturbation * h);
    const std::vector<std::array<double, 2> > grid = xy;
    auto signed_area = [&](const std::array<std::size_t, 3>& t, bool bot) {
      const auto& p = xy[t[0]]; const auto& q = xy[t[1]]; const auto& r = xy[t[2]];
      const double a = 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
      return bot ? -a : a;
    };
    for(int attempt = 0;; ++attempt)
    {
      if(attempt == 1000) throw std::logic_error("make_doubly_covered_square: no valid perturbation");
      for(std::size_t v = 0; v < xy.size(); ++v)
      {
        const bool on_border = grid[v][0] == 0 || grid[v][1] == 0 || grid[v][0] == 1 || grid[v][1] == 1;
        xy[v] = grid[v];
        if(!on_border) { xy[v][0] += u(rng); xy[v][1] += u(rng); }
      }
      bool ok = true;
      for(std::size_t f = 0; f < tris.size() && ok; ++f) ok = signed_area(tris[f], is_bottom[f]) > 0.05 * 0.5 * h * h;
      if(ok) break;
    }
  }
  std::vector<Point_3> points;
  for(const auto& p : xy) points.emplace_back(p[0], p[1], 0.0);
  s.mesh = mesh_from_soup(points, tris);
  s.bottom_face = is_bottom;
  for(std::size_t v : top) s.top.push_back(Mesh::Vertex_index(static_cast<Mesh::size_type>(v)));
  for(std::size_t v : bottom) s.bottom.push_back(Mesh::Vertex_index(static_cast<Mesh::size_type>(v)));
  return s;
}

/// A planar segment.
struct Segment_2d
{
  std::array<double, 2> a, b;
  double length() const { return std::hypot(b[0] - a[0], b[1] - a[1]); }
};

inline double point_segment_distance_2d(const std::array<double, 2>& p, const Segment_2d& s)
{
  const double dx = s.b[0] - s.a[0], dy = s.b[1] - s.a[1];
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p[0] - s.a[0]) * dx + (p[1] - s.a[1]) * dy) / l2 : 0;
  t = std::max(0.0, std::min(1.0, t));
  return std::hypot(p[0] - (s.a[0] + t * dx), p[1] - (s.a[1] + t * dy));
}

/// The exact cut locus of a source (a, b) of the top sheet, on the bottom sheet:
/// the points of [0,1]^2 where the two smallest of the distances to the four
/// mirror images (-a,b), (2-a,b), (a,-b), (a,2-b) are equal. Computed as the
/// Voronoi edges of the images clipped to the square: for every pair (i, j),
/// the bisector line clipped by the square and by d_i <= d_k for every k
/// (half-planes, since the images are fixed points).
struct Doubly_covered_square_oracle
{
  std::array<std::array<double, 2>, 4> images;
  std::vector<Segment_2d> edges;

  Doubly_covered_square_oracle(double a, double b)
  {
    images = {{{{-a, b}}, {{2 - a, b}}, {{a, -b}}, {{a, 2 - b}}}};
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
      {
        // bisector: points m + t * dir
        const auto& p = images[i]; const auto& q = images[j];
        const std::array<double, 2> m = {{0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])}};
        const std::array<double, 2> dir = {{-(q[1] - p[1]), q[0] - p[0]}};
        double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
        // clip by the half-plane  n . x <= c  (x = m + t dir)
        auto clip = [&](const std::array<double, 2>& nrm, double c) {
          const double base = nrm[0] * m[0] + nrm[1] * m[1], slope = nrm[0] * dir[0] + nrm[1] * dir[1];
          if(slope == 0) { if(base > c) { lo = 1; hi = 0; } return; }
          const double t = (c - base) / slope;
          if(slope > 0) hi = std::min(hi, t); else lo = std::max(lo, t);
        };
        clip({{-1, 0}}, 0); clip({{1, 0}}, 1); clip({{0, -1}}, 0); clip({{0, 1}}, 1);
        for(int k = 0; k < 4; ++k)
        {
          if(k == i || k == j) continue;
          // |x - p|^2 <= |x - r|^2  <=>  2 (r - p) . x <= |r|^2 - |p|^2
          const auto& r = images[k];
          clip({{2 * (r[0] - p[0]), 2 * (r[1] - p[1])}}, r[0] * r[0] + r[1] * r[1] - p[0] * p[0] - p[1] * p[1]);
        }
        if(lo < hi - 1e-12)
          edges.push_back(Segment_2d{{{m[0] + lo * dir[0], m[1] + lo * dir[1]}},
                                     {{m[0] + hi * dir[0], m[1] + hi * dir[1]}}});
      }
  }

  /// distance from (x, y) in the square to the analytic cut locus
  double distance_to_cut_locus(const std::array<double, 2>& p) const
  {
    double d = std::numeric_limits<double>::infinity();
    for(const auto& e : edges) d = std::min(d, point_segment_distance_2d(p, e));
    return d;
  }

  /// geodesic distance from the source to (x, y) on the bottom sheet
  double bottom_distance(const std::array<double, 2>& p) const
  {
    double d = std::numeric_limits<double>::infinity();
    for(const auto& q : images) d = std::min(d, std::hypot(p[0] - q[0], p[1] - q[1]));
    return d;
  }

  double total_length() const
  {
    double l = 0;
    for(const auto& e : edges) l += e.length();
    return l;
  }
};

// ---------------------------------------------------------------------------
// Subdivided convex polyhedra

/// A convex polyhedron: corners and flat faces (triangles or planar convex
/// quadrilaterals), every face counter-clockwise seen from outside.
struct Polyhedron_description
{
  std::vector<Point_3> corners;
  std::vector<std::vector<std::size_t> > faces;
};

/// The box [0,dx] x [0,dy] x [0,dz] (the unit cube by default).
inline Polyhedron_description box_corners_and_faces(double dx = 1, double dy = 1, double dz = 1)
{
  Polyhedron_description p;
  for(int k = 0; k < 8; ++k) p.corners.emplace_back((k & 1) ? dx : 0, (k & 2) ? dy : 0, (k & 4) ? dz : 0);
  p.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return p;
}

/// The regular tetrahedron with edge length sqrt(8) (corners of a cube [-1,1]^3).
inline Polyhedron_description regular_tetrahedron_corners_and_faces()
{
  Polyhedron_description p;
  p.corners = {Point_3(1, 1, 1), Point_3(1, -1, -1), Point_3(-1, 1, -1), Point_3(-1, -1, 1)};
  p.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return p;
}

/// The regular octahedron with corners (+-1,0,0), (0,+-1,0), (0,0,+-1).
inline Polyhedron_description regular_octahedron_corners_and_faces()
{
  Polyhedron_description p;
  p.corners = {Point_3(1, 0, 0), Point_3(-1, 0, 0), Point_3(0, 1, 0),
               Point_3(0, -1, 0), Point_3(0, 0, 1), Point_3(0, 0, -1)};
  p.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return p;
}

struct Subdivided_polyhedron
{
  Mesh mesh;
  Polyhedron_description description;
  std::vector<Mesh::Vertex_index> corner_vertices; ///< the mesh vertex at each corner
  double perturbation = 0;
  unsigned seed = 0;
};

/// Every face of `p` subdivided: a triangle into n^2 triangles (the standard
/// triangular grid), a quadrilateral into an n x n grid of cells split along
/// alternating diagonals. Points are integer combinations of the corners (so
/// shared polyhedron edges get identical vertices). With `perturbation` > 0
/// (in grid steps, <= 0.3), points inside a flat face move at random within
/// that face's plane and points on a polyhedron edge move along the edge;
/// corners stay. A draw that flips a triangle or makes it thinner than 1/20
/// of its grid triangle is redrawn.
inline Subdivided_polyhedron make_subdivided_polyhedron(const Polyhedron_description& p, int n,
                                                        double perturbation = 0, unsigned seed = 1)
{
  if(n < 1) throw std::invalid_argument("make_subdivided_polyhedron: n >= 1");
  if(perturbation < 0 || perturbation > 0.3)
    throw std::invalid_argument("make_subdivided_polyhedron: perturbation in [0, 0.3]");
  const std::size_t nc = p.corners.size();
  Subdivided_polyhedron out;
  out.description = p;
  out.perturbation = perturbation;
  out.seed = seed;
  typedef std::vector<long> Weights; // per corner; sum = denominator of the face kind
  std::map<Weights, std::size_t> index_of;
  std::vector<Weights> weights;
  std::vector<long> denominators;
  std::vector<std::vector<std::size_t> > faces_of_point; // polyhedron faces holding the point
  auto point_id = [&](const Weights& w, long denominator, std::size_t face) {
    // normalise: triangles use n, quads n^2; scale triangle weights to a common n^2
    Weights key = w;
    if(denominator == n) for(long& x : key) x *= n;
    auto it = index_of.find(key);
    std::size_t id;
    if(it == index_of.end())
    {
      id = weights.size();
      index_of.emplace(key, id);
      weights.push_back(key);
      denominators.push_back(static_cast<long>(n) * n);
      faces_of_point.emplace_back();
    }
    else id = it->second;
    if(std::find(faces_of_point[id].begin(), faces_of_point[id].end(), face) == faces_of_point[id].end())
      faces_of_point[id].push_back(face);
    return id;
  };
  std::vector<std::array<std::size_t, 3> > tris;
  std::vector<std::size_t> tri_face;
  for(std::size_t f = 0; f < p.faces.size(); ++f)
  {
    const auto& c = p.faces[f];
    if(c.size() == 3)
    {
      auto id = [&](int i, int j) {
        Weights w(nc, 0);
        w[c[0]] += n - i - j; w[c[1]] += i; w[c[2]] += j;
        return point_id(w, n, f);
      };
      for(int j = 0; j < n; ++j)
        for(int i = 0; i + j < n; ++i)
        {
          tris.push_back({{id(i, j), id(i + 1, j), id(i, j + 1)}});
          tri_face.push_back(f);
          if(i + j + 1 < n)
          {
            tris.push_back({{id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}});
            tri_face.push_back(f);
          }
        }
    }
    else if(c.size() == 4)
    {
      auto id = [&](int i, int j) {
        Weights w(nc, 0);
        w[c[0]] += static_cast<long>(n - i) * (n - j); w[c[1]] += static_cast<long>(i) * (n - j);
        w[c[2]] += static_cast<long>(i) * j;           w[c[3]] += static_cast<long>(n - i) * j;
        return point_id(w, static_cast<long>(n) * n, f);
      };
      for(int j = 0; j < n; ++j)
        for(int i = 0; i < n; ++i)
        {
          const std::size_t a = id(i, j), b = id(i + 1, j), cc = id(i + 1, j + 1), d = id(i, j + 1);
          if((i + j) % 2 == 0) { tris.push_back({{a, b, cc}}); tris.push_back({{a, cc, d}}); }
          else { tris.push_back({{a, b, d}}); tris.push_back({{b, cc, d}}); }
          tri_face.push_back(f); tri_face.push_back(f);
        }
    }
    else throw std::invalid_argument("make_subdivided_polyhedron: faces must be triangles or quadrilaterals");
  }
  std::vector<Point_3> base(weights.size());
  for(std::size_t v = 0; v < weights.size(); ++v)
  {
    double x = 0, y = 0, z = 0;
    for(std::size_t k = 0; k < nc; ++k)
      if(weights[v][k] != 0)
      {
        x += weights[v][k] * p.corners[k].x(); y += weights[v][k] * p.corners[k].y(); z += weights[v][k] * p.corners[k].z();
      }
    const double d = static_cast<double>(denominators[v]);
    base[v] = Point_3(x / d, y / d, z / d);
  }
  // corners
  out.corner_vertices.assign(nc, Mesh::Vertex_index());
  for(std::size_t v = 0; v < weights.size(); ++v)
    for(std::size_t k = 0; k < nc; ++k)
      if(weights[v][k] == denominators[v]) out.corner_vertices[k] = Mesh::Vertex_index(static_cast<Mesh::size_type>(v));

  std::vector<Point_3> points = base;
  if(perturbation > 0)
  {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    // per vertex: the directions it may move in (0, 1 or 2 unit vectors) and the grid step
    std::vector<std::vector<Vector_3> > dirs(points.size());
    std::vector<double> step(points.size(), 0);
    for(std::size_t v = 0; v < points.size(); ++v)
    {
      std::vector<std::size_t> nz;
      for(std::size_t k = 0; k < nc; ++k) if(weights[v][k] != 0) nz.push_back(k);
      if(faces_of_point[v].size() >= 3 || nz.size() == 1) continue; // a corner
      const auto& fc = p.faces[faces_of_point[v][0]];
      const Point_3& A = p.corners[fc[0]];
      Vector_3 e1 = p.corners[fc[1]] - A, e2 = p.corners[fc.back()] - A;
      step[v] = std::sqrt(std::min(e1.squared_length(), e2.squared_length())) / n;
      if(faces_of_point[v].size() == 2)
      {
        // on a polyhedron edge: along the edge between the two corners it depends on
        if(nz.size() != 2) continue;
        Vector_3 d = p.corners[nz[1]] - p.corners[nz[0]];
        d = d / std::sqrt(d.squared_length());
        dirs[v].push_back(d);
      }
      else
      {
        e1 = e1 / std::sqrt(e1.squared_length());
        Vector_3 nrm = CGAL::cross_product(e1, e2);
        Vector_3 e2o = CGAL::cross_product(nrm, e1);
        e2o = e2o / std::sqrt(e2o.squared_length());
        dirs[v].push_back(e1);
        dirs[v].push_back(e2o);
      }
    }
    auto area_vector = [](const Point_3& a, const Point_3& b, const Point_3& c) {
      return CGAL::cross_product(b - a, c - a);
    };
    for(int attempt = 0;; ++attempt)
    {
      if(attempt == 1000) throw std::logic_error("make_subdivided_polyhedron: no valid perturbation");
      for(std::size_t v = 0; v < points.size(); ++v)
      {
        Vector_3 m(0, 0, 0);
        for(const auto& d : dirs[v]) m = m + (u(rng) * perturbation * step[v]) * d;
        points[v] = base[v] + m;
      }
      bool ok = true;
      for(std::size_t t = 0; t < tris.size() && ok; ++t)
      {
        const Vector_3 a0 = area_vector(base[tris[t][0]], base[tris[t][1]], base[tris[t][2]]);
        const Vector_3 a1 = area_vector(points[tris[t][0]], points[tris[t][1]], points[tris[t][2]]);
        ok = a1 * a0 > 0.05 * a0.squared_length();
      }
      if(ok) break;
    }
  }
  out.mesh = mesh_from_soup(points, tris);
  return out;
}

} // namespace testing
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_TEST_SUPPORT_ANALYTIC_MESHES_H
