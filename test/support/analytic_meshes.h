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
// * Surfaces WITH BOUNDARY (issue 13; all derive from `Surface_with_boundary`,
//   which holds the boundary loop count b, the genus g and the cycle rank
//   2g + b of ridge + boundary):
//   `make_flat_square()`, `make_flat_L_domain()`, `make_flat_slit_square()`, `make_half_cylinder()`
//   (flat and simply connected: the ridge is empty for every source, boundary
//   sources included), `make_flat_annulus()` (the ridge is one arc from the
//   hole to the outer boundary, given exactly by `Flat_annulus_ridge`),
//   `make_open_box()` (from the bottom centre the ridge is the four vertical
//   edges; otherwise no closed form) and `make_torus_with_hole()` (no analytic
//   ridge: compare with the exact solver). Their perturbation moves vertices only where the
//   surface stays the same (`perturb_keeping_surface()`), except the torus's,
//   which moves them on the smooth torus.
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
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

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

inline double bbox_diagonal(const Mesh& m)
{
  CGAL::Bbox_3 b;
  for(auto v : m.vertices()) b += m.point(v).bbox();
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

inline double mean_edge_length(const Mesh& m)
{
  double s = 0;
  for(auto e : m.edges())
    s += std::sqrt(CGAL::squared_distance(m.point(m.source(m.halfedge(e))), m.point(m.target(m.halfedge(e)))));
  return s / static_cast<double>(m.number_of_edges());
}

/// Caps on the same surface: in a share `share` of the faces (drawn with
/// std::mt19937(seed)), a vertex inside the face at 1 % of its longest edge
/// from that edge's midpoint, joined to the three corners. The face between
/// it and the longest edge is a cap (three nearly collinear corners, like the
/// needles of scanned and CAD models); the surface is unchanged and the
/// vertices keep their indices. Returns the number of caps.
inline std::size_t add_caps(Mesh& mesh, double share, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::vector<Mesh::Face_index> chosen;
  for(auto f : mesh.faces())
    if(uniform(random) < share) chosen.push_back(f);
  for(auto f : chosen)
  {
    auto h = mesh.halfedge(f), longest = h; // the longest edge's halfedge in f
    double longest_l2 = 0;
    for(int k = 0; k < 3; ++k, h = mesh.next(h))
    {
      const double l2 = CGAL::squared_distance(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)));
      if(l2 > longest_l2) { longest_l2 = l2; longest = h; }
    }
    const Point_3 a = mesh.point(mesh.source(longest)), b = mesh.point(mesh.target(longest)),
                  c = mesh.point(mesh.target(mesh.next(longest)));
    const Point_3 m = CGAL::midpoint(a, b);
    const double height = std::sqrt(CGAL::squared_distance(c, K::Line_3(a, b)));
    const double t = 0.01 * std::sqrt(longest_l2) / height;
    const auto v = mesh.target(CGAL::Euler::add_center_vertex(longest, mesh));
    mesh.point(v) = m + t * (c - m);
  }
  return chosen.size();
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

/// The box [0,dx] x [0,dy] x [0,dz] as CAD models triangulate flat faces:
/// each side a fan of 4n long faces from one inner point (at 0.37 and 0.58 of
/// the side's two axes), n points per side edge. The corners are
/// `corner_vertices` (the box's eight, in `box_corners_and_faces()` order).
inline Subdivided_polyhedron make_fan_box(double dx, double dy, double dz, int n)
{
  if(n < 1) throw std::invalid_argument("make_fan_box: n >= 1");
  Subdivided_polyhedron out;
  out.description = box_corners_and_faces(dx, dy, dz);
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::map<std::array<long, 3>, std::size_t> id; // points on shared edges, by rounded coordinates
  auto vertex = [&](const Point_3& p) {
    const std::array<long, 3> key = {{std::lround(p.x() * 1e9), std::lround(p.y() * 1e9), std::lround(p.z() * 1e9)}};
    const auto it = id.find(key);
    if(it != id.end()) return it->second;
    points.push_back(p);
    return id[key] = points.size() - 1;
  };
  for(const auto& face : out.description.faces) // quadrilaterals, outward
  {
    std::vector<Point_3> ring;
    for(std::size_t c = 0; c < 4; ++c)
    {
      const Point_3& a = out.description.corners[face[c]];
      const Point_3& b = out.description.corners[face[(c + 1) % 4]];
      for(int i = 0; i < n; ++i) ring.push_back(a + (double(i) / n) * (b - a));
    }
    const Point_3& o = out.description.corners[face[0]];
    const Vector_3 u = out.description.corners[face[1]] - o, w = out.description.corners[face[3]] - o;
    const std::size_t centre = vertex(o + 0.37 * u + 0.58 * w);
    for(std::size_t i = 0; i < ring.size(); ++i) triangles.push_back({centre, vertex(ring[i]), vertex(ring[(i + 1) % ring.size()])});
  }
  out.mesh = mesh_from_soup(points, triangles);
  for(const Point_3& c : out.description.corners)
    out.corner_vertices.push_back(Mesh::Vertex_index(static_cast<Mesh::size_type>(vertex(c))));
  return out;
}

// ---------------------------------------------------------------------------
// Surfaces with boundary

/// A generated surface with boundary, and what the tests need of it.
struct Surface_with_boundary
{
  Mesh mesh;
  std::string name;
  int n = 0;                ///< the resolution parameter it was made with
  double perturbation = 0;  ///< see the generator
  unsigned seed = 0;
  int boundary_loops = 0;   ///< b
  int genus = 0;            ///< g
  bool empty_ridge = false; ///< the exact ridge is empty for every source (flat and simply connected)
  /// Cycle rank (first Betti number) of the graph ridge + boundary: cutting the
  /// surface along both leaves one disk around the source, so it is 2g + b.
  int cycle_rank() const { return 2 * genus + boundary_loops; }
  /// V - E + F of the mesh
  int euler_characteristic() const { return 2 - 2 * genus - boundary_loops; }
};

/// The vertex nearest to p (Euclidean).
inline Mesh::Vertex_index nearest_vertex(const Mesh& m, const Point_3& p)
{
  Mesh::Vertex_index best;
  double d = std::numeric_limits<double>::infinity();
  for(auto v : m.vertices())
    if(CGAL::squared_distance(m.point(v), p) < d) { d = CGAL::squared_distance(m.point(v), p); best = v; }
  return best;
}

/// The vertices on the boundary, in index order.
inline std::vector<Mesh::Vertex_index> border_vertices(const Mesh& m)
{
  std::vector<Mesh::Vertex_index> out;
  for(auto v : m.vertices()) if(m.is_border(v)) out.push_back(v);
  return out;
}

namespace boundary_internal {

typedef std::array<std::size_t, 3> Triangle;

inline Vector_3 unit(const Vector_3& v) { return v / std::sqrt(v.squared_length()); }

/// The fields every surface with a border has; checks the perturbation.
template <class S>
void set_common(S& s, const char* name, int n, double perturbation, unsigned seed, int b, int g, bool empty_ridge)
{
  if(perturbation < 0 || perturbation > 0.3)
    throw std::invalid_argument(std::string(name) + ": perturbation in [0, 0.3]");
  s.name = name; s.n = n; s.perturbation = perturbation; s.seed = seed;
  s.boundary_loops = b; s.genus = g; s.empty_ridge = empty_ridge;
}

/// The n_i x n_j cells of a grid of points `id(i, j)` (i in [0, n_i], j in
/// [0, n_j]; `id` may wrap around), the cells with `keep(i, j)`, each split
/// counter-clockwise in the (i, j) plane along the diagonal (i,j)-(i+1,j+1) if
/// `main_diagonal(i, j)`, else along (i+1,j)-(i,j+1).
template <class Id, class Diagonal, class Keep>
std::vector<Triangle> grid_triangles(int ni, int nj, Id id, Diagonal main_diagonal, Keep keep)
{
  std::vector<Triangle> tris;
  for(int j = 0; j < nj; ++j)
    for(int i = 0; i < ni; ++i)
    {
      if(!keep(i, j)) continue;
      const std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if(main_diagonal(i, j)) { tris.push_back({{a, b, c}}); tris.push_back({{a, c, d}}); }
      else { tris.push_back({{a, b, d}}); tris.push_back({{b, c, d}}); }
    }
  return tris;
}

/// Diagonal rule of a planar grid domain: a cell holding a convex corner of the
/// domain is split along the diagonal through it (no triangle has two boundary
/// edges there); the other cells alternate.
template <class Corner>
auto corner_diagonal(Corner is_corner)
{
  return [is_corner](int i, int j) {
    if(is_corner(i, j) || is_corner(i + 1, j + 1)) return true;
    if(is_corner(i + 1, j) || is_corner(i, j + 1)) return false;
    return (i + j) % 2 == 0;
  };
}

/// Drops the points that no triangle uses (the others keep their order).
inline void drop_unused_points(std::vector<Point_3>& points, std::vector<Triangle>& tris)
{
  const std::size_t unused = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> new_index(points.size(), unused);
  for(const auto& t : tris) for(std::size_t v : t) new_index[v] = 0;
  std::vector<Point_3> kept;
  for(std::size_t v = 0; v < points.size(); ++v)
    if(new_index[v] != unused) { new_index[v] = kept.size(); kept.push_back(points[v]); }
  for(auto& t : tris) for(std::size_t& v : t) v = new_index[v];
  points.swap(kept);
}

/// Moves every vertex to `draw(v, rng)`, then redraws the vertices of every
/// face that flipped or became thinner than 1/20 of its area (area vectors
/// compared with the unperturbed ones), until there is none.
template <class Draw>
void perturb_vertices(Mesh& m, Draw draw, unsigned seed, const char* who)
{
  std::mt19937 rng(seed);
  std::vector<Point_3> base(m.number_of_vertices());
  for(auto v : m.vertices()) base[std::size_t(v)] = m.point(v);
  auto area = [&](Mesh::Face_index f, bool before) {
    const Mesh::Halfedge_index h = m.halfedge(f);
    auto at = [&](Mesh::Vertex_index v) { return before ? base[std::size_t(v)] : m.point(v); };
    const Point_3 a = at(m.source(h)), b = at(m.target(h)), c = at(m.target(m.next(h)));
    return CGAL::cross_product(b - a, c - a);
  };
  std::vector<Mesh::Vertex_index> todo(m.vertices().begin(), m.vertices().end());
  for(int round = 0; !todo.empty(); ++round)
  {
    if(round == 1000) throw std::logic_error(std::string(who) + ": no valid perturbation");
    for(auto v : todo) m.point(v) = draw(v, rng);
    todo.clear();
    for(auto f : m.faces())
    {
      const Vector_3 a0 = area(f, true);
      if(area(f, false) * a0 > 0.05 * a0.squared_length()) continue;
      for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) todo.push_back(v);
    }
    std::sort(todo.begin(), todo.end());
    todo.erase(std::unique(todo.begin(), todo.end()), todo.end());
  }
}

/// The distinct planes (unit normals) of the faces around v.
inline std::vector<Vector_3> incident_planes(const Mesh& m, Mesh::Vertex_index v)
{
  std::vector<Vector_3> planes;
  for(auto f : CGAL::faces_around_target(m.halfedge(v), m))
  {
    if(f == Mesh::null_face()) continue;
    const Mesh::Halfedge_index h = m.halfedge(f);
    const Point_3 &a = m.point(m.source(h)), &b = m.point(m.target(h)), &c = m.point(m.target(m.next(h)));
    const Vector_3 nrm = unit(CGAL::cross_product(b - a, c - a));
    bool known = false;
    for(const auto& q : planes) known = known || (nrm - q).squared_length() < 1e-18;
    if(!known) planes.push_back(nrm);
  }
  return planes;
}

/// The directions in which vertex v can move without changing the surface:
/// within the plane of its faces if they are coplanar, along the fold line if
/// they lie in two planes, none otherwise; a boundary vertex only along a
/// straight boundary (its two boundary neighbours aligned with it), if that
/// direction lies in its faces' planes.
inline std::vector<Vector_3> free_directions(const Mesh& m, Mesh::Vertex_index v)
{
  const std::vector<Vector_3> planes = incident_planes(m, v);
  for(auto h : CGAL::halfedges_around_target(m.halfedge(v), m))
  {
    if(!m.is_border(h)) continue;
    const Vector_3 d1 = unit(m.point(v) - m.point(m.source(h)));
    const Vector_3 d2 = unit(m.point(m.target(m.next(h))) - m.point(v));
    bool free = CGAL::cross_product(d1, d2).squared_length() < 1e-18 && d1 * d2 > 0;
    for(const auto& q : planes) free = free && std::abs(q * d1) < 1e-9;
    return free ? std::vector<Vector_3>{d1} : std::vector<Vector_3>();
  }
  if(planes.size() == 2) return {unit(CGAL::cross_product(planes[0], planes[1]))};
  if(planes.size() != 1) return {};
  const Vector_3& nrm = planes[0];
  const Vector_3 axis = std::abs(nrm.x()) < 0.5 ? Vector_3(1, 0, 0) : Vector_3(0, 1, 0);
  const Vector_3 e1 = unit(CGAL::cross_product(nrm, axis));
  return {e1, CGAL::cross_product(nrm, e1)};
}

} // namespace boundary_internal

/// Moves every vertex at random (seeded) by up to `perturbation` times its
/// shortest incident edge along each of its free directions
/// (`boundary_internal::free_directions`): points inside a flat region move in
/// its plane, points on a fold line or on a straight piece of boundary along
/// it, the other vertices (corners, curved parts) stay. The surface, and so
/// the exact geodesic distance and ridge, does not change.
inline void perturb_keeping_surface(Mesh& m, double perturbation, unsigned seed, const char* who)
{
  namespace BI = boundary_internal;
  if(perturbation <= 0) return;
  const std::size_t nv = m.number_of_vertices();
  std::vector<std::vector<Vector_3> > dirs(nv);
  std::vector<double> step(nv, std::numeric_limits<double>::infinity());
  std::vector<Point_3> base(nv);
  for(auto v : m.vertices())
  {
    dirs[std::size_t(v)] = BI::free_directions(m, v);
    base[std::size_t(v)] = m.point(v);
    for(auto h : CGAL::halfedges_around_target(m.halfedge(v), m))
      step[std::size_t(v)] = std::min(step[std::size_t(v)], std::sqrt(CGAL::squared_distance(m.point(m.source(h)), m.point(v))));
  }
  std::uniform_real_distribution<double> u(-1, 1);
  BI::perturb_vertices(m, [&](Mesh::Vertex_index v, std::mt19937& rng) {
    Vector_3 move(0, 0, 0);
    for(const auto& d : dirs[std::size_t(v)]) move = move + (u(rng) * perturbation * step[std::size_t(v)]) * d;
    return base[std::size_t(v)] + move;
  }, seed, who);
}

// --- flat square

/// The unit square [0,1]^2 at z = 0: b = 1, g = 0, rank 1. Convex, so shortest
/// paths are straight and unique: the ridge is empty for every source, inside
/// or on the boundary.
struct Flat_square : Surface_with_boundary
{
  /// vertex (i, j) (the point (i/n, j/n) before perturbation) is grid[i + (n+1) j]
  std::vector<Mesh::Vertex_index> grid;
  /// the exact geodesic distance: Euclidean
  static double geodesic_distance(const Point_3& a, const Point_3& b) { return std::sqrt(CGAL::squared_distance(a, b)); }
};

/// The n x n grid of the unit square (n >= 2), cells split alternately, the
/// four corner cells along the diagonal through the corner. With
/// `perturbation` in (0, 0.3]: `perturb_keeping_surface()` (inside points in
/// the plane, border points along their side, corners fixed).
inline Flat_square make_flat_square(int n, double perturbation = 0, unsigned seed = 1)
{
  namespace BI = boundary_internal;
  if(n < 2) throw std::invalid_argument("make_flat_square: n >= 2");
  Flat_square s;
  BI::set_common(s, "flat square", n, perturbation, seed, 1, 0, true);
  std::vector<Point_3> points;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) points.emplace_back(double(i) / n, double(j) / n, 0.0);
  auto id = [n](int i, int j) { return std::size_t(i + (n + 1) * j); };
  auto corner = [n](int i, int j) { return (i == 0 || i == n) && (j == 0 || j == n); };
  s.mesh = mesh_from_soup(points, BI::grid_triangles(n, n, id, BI::corner_diagonal(corner), [](int, int) { return true; }));
  perturb_keeping_surface(s.mesh, perturbation, seed, "make_flat_square");
  for(std::size_t k = 0; k < points.size(); ++k) s.grid.push_back(Mesh::Vertex_index(Mesh::size_type(k)));
  return s;
}

// --- flat L-shaped domain

/// The L-shaped domain [0,2]^2 minus (1,2]^2 at z = 0: b = 1, g = 0, rank 1.
/// Shortest paths are straight where the segment stays in the domain, else
/// they bend once, at the reflex corner (1,1); they are unique everywhere
/// (simply connected and flat, hence CAT(0)), so the ridge is empty: the
/// shadow line of the reflex corner (where the bent paths start) is no ridge,
/// the arrival direction is continuous across it.
struct Flat_L_domain : Surface_with_boundary
{
  Mesh::Vertex_index reflex_corner; ///< at (1, 1)
  /// vertex (i, j) (the point (i/n, j/n) before perturbation), or null if outside: grid[i + (2n+1) j]
  std::vector<Mesh::Vertex_index> grid;

  /// whether the segment ab crosses the open square (1,2)^2 (leaves the domain)
  static bool segment_leaves(const Point_3& a, const Point_3& b)
  {
    double lo = 0, hi = 1;
    auto open_slab = [&](double p0, double d) { // 1 < p0 + t d < 2
      if(std::abs(d) < 1e-300) { if(!(p0 > 1 + 1e-12 && p0 < 2 - 1e-12)) hi = -1; return; }
      const double t1 = (1 - p0) / d, t2 = (2 - p0) / d;
      lo = std::max(lo, std::min(t1, t2));
      hi = std::min(hi, std::max(t1, t2));
    };
    open_slab(a.x(), b.x() - a.x());
    open_slab(a.y(), b.y() - a.y());
    return lo < hi - 1e-12;
  }
  /// the exact geodesic distance: Euclidean, or through the reflex corner
  static double geodesic_distance(const Point_3& a, const Point_3& b)
  {
    if(!segment_leaves(a, b)) return std::sqrt(CGAL::squared_distance(a, b));
    const Point_3 c(1, 1, 0);
    return std::sqrt(CGAL::squared_distance(a, c)) + std::sqrt(CGAL::squared_distance(c, b));
  }
};

/// The L-domain on the grid of step 1/n (n >= 1; 3 n^2 cells), split as
/// make_flat_square() does (diagonals through the five convex corners).
/// Perturbation as for the square; the reflex corner stays.
inline Flat_L_domain make_flat_L_domain(int n, double perturbation = 0, unsigned seed = 1)
{
  namespace BI = boundary_internal;
  if(n < 1) throw std::invalid_argument("make_flat_L_domain: n >= 1");
  Flat_L_domain s;
  BI::set_common(s, "flat L-shaped domain", n, perturbation, seed, 1, 0, true);
  const int w = 2 * n + 1;
  auto inside = [n](int i, int j) { return !(i > n && j > n); };
  std::vector<std::size_t> index(std::size_t(w) * w, std::numeric_limits<std::size_t>::max());
  std::vector<Point_3> points;
  for(int j = 0; j < w; ++j)
    for(int i = 0; i < w; ++i)
      if(inside(i, j)) { index[std::size_t(i + w * j)] = points.size(); points.emplace_back(double(i) / n, double(j) / n, 0.0); }
  auto id = [&](int i, int j) { return index[std::size_t(i + w * j)]; };
  auto corner = [n](int i, int j) {
    return (i == 0 && (j == 0 || j == 2 * n)) || (i == 2 * n && (j == 0 || j == n)) || (i == n && j == 2 * n);
  };
  auto keep = [n](int i, int j) { return !(i >= n && j >= n); };
  s.mesh = mesh_from_soup(points, BI::grid_triangles(2 * n, 2 * n, id, BI::corner_diagonal(corner), keep));
  perturb_keeping_surface(s.mesh, perturbation, seed, "make_flat_L_domain");
  for(std::size_t k : index)
    s.grid.push_back(k == std::numeric_limits<std::size_t>::max() ? Mesh::null_vertex() : Mesh::Vertex_index(Mesh::size_type(k)));
  s.reflex_corner = s.grid[std::size_t(n + w * n)];
  return s;
}

// --- flat square with a slit

/// The unit square at z = 0 with a slit in its border: from the middle of
/// the bottom side, (1/2, 0), up to (1/2, 1/2), `width` wide (its two sides
/// at x = 1/2 -+ width / 2, meeting at the slit's end (1/2, 1/2), a reflex
/// corner of angle nearly 2 pi). b = 1, g = 0, rank 1. Simply connected and
/// flat, so shortest paths are unique (they bend at the slit's end) and the
/// ridge is empty for every source.
struct Flat_slit_square : Surface_with_boundary
{
  Mesh::Vertex_index slit_end; ///< at (1/2, 1/2)
};

/// The n x n grid of the unit square (n even, >= 4), cells split as
/// make_flat_square() does, cut open along the slit (0 < width < 1/n): the
/// grid points (n/2, j) for j < n/2 come twice, one per side of the slit.
inline Flat_slit_square make_flat_slit_square(int n, double width)
{
  namespace BI = boundary_internal;
  if(n < 4 || n % 2 != 0) throw std::invalid_argument("make_flat_slit_square: n even, >= 4");
  if(!(width > 0 && width < 1.0 / n)) throw std::invalid_argument("make_flat_slit_square: width in (0, 1/n)");
  Flat_slit_square s;
  BI::set_common(s, "flat square with a slit", n, 0, 0, 1, 0, true);
  std::vector<Point_3> points;
  auto on_slit = [n](int i, int j) { return i == n / 2 && j < n / 2; };
  std::vector<std::size_t> left((n + 1) * (n + 1)), right((n + 1) * (n + 1));
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      const std::size_t k = std::size_t(i + (n + 1) * j);
      left[k] = right[k] = points.size();
      if(!on_slit(i, j)) { points.emplace_back(double(i) / n, double(j) / n, 0.0); continue; }
      points.emplace_back(0.5 - width / 2, double(j) / n, 0.0);
      right[k] = points.size();
      points.emplace_back(0.5 + width / 2, double(j) / n, 0.0);
    }
  // a cell left of the slit takes the points of its left side, a cell right of it the right side's
  std::vector<BI::Triangle> tris;
  for(const bool west : {true, false})
  {
    auto id = [&](int i, int j) { return (west ? left : right)[std::size_t(i + (n + 1) * j)]; };
    auto corner = [n](int i, int j) { return (i == 0 || i == n) && (j == 0 || j == n); };
    const auto half = BI::grid_triangles(n, n, id, BI::corner_diagonal(corner),
                                         [&](int i, int) { return (i < n / 2) == west; });
    tris.insert(tris.end(), half.begin(), half.end());
  }
  s.mesh = mesh_from_soup(points, tris);
  s.slit_end = nearest_vertex(s.mesh, Point_3(0.5, 0.5, 0));
  return s;
}

// --- half-cylinder

/// Half of a cylinder of radius rho around the z axis, x = rho cos t,
/// y = rho sin t, t in [0, pi], z in [0, height], as n flat strips (chords of
/// the half circle) of m rows: b = 1, g = 0, rank 1. The strips are
/// rectangles, so the surface is intrinsically the flat rectangle
/// [0, n c] x [0, height] (c the chord): convex, the ridge is empty.
struct Half_cylinder : Surface_with_boundary
{
  double radius = 0, height = 0;
  int rows = 0; ///< m
  /// vertex (k, j) (angle pi k / n, z = height j / m before perturbation) is grid[k + (n+1) j]
  std::vector<Mesh::Vertex_index> grid;

  double chord() const { return 2 * radius * std::sin(0.5 * 3.14159265358979323846 / n); }
  /// the isometry to the flat rectangle: (arc length along the chords, z)
  std::array<double, 2> unfold(const Point_3& p) const
  {
    const double step = 3.14159265358979323846 / n;
    const double t = std::max(0.0, std::min(3.14159265358979323846, std::atan2(std::max(0.0, p.y()), p.x())));
    const int k = std::min(n - 1, int(t / step));
    const double ax = radius * std::cos(k * step), ay = radius * std::sin(k * step);
    const double bx = radius * std::cos((k + 1) * step), by = radius * std::sin((k + 1) * step);
    const double c = chord();
    const double along = ((p.x() - ax) * (bx - ax) + (p.y() - ay) * (by - ay)) / (c * c);
    return {{(k + along) * c, p.z()}};
  }
  /// the exact geodesic distance: Euclidean in the rectangle
  double geodesic_distance(const Point_3& a, const Point_3& b) const
  {
    const auto p = unfold(a), q = unfold(b);
    return std::hypot(p[0] - q[0], p[1] - q[1]);
  }
};

/// n >= 2 strips, m = max(1, round(height / chord)) rows (nearly square
/// cells), split alternately (corner cells through the corner). Perturbation:
/// `perturb_keeping_surface()`, which moves inner vertices along their fold
/// line (z) and vertices of the two straight sides along them.
inline Half_cylinder make_half_cylinder(int n, double radius = 1, double height = 2, double perturbation = 0,
                                        unsigned seed = 1)
{
  namespace BI = boundary_internal;
  if(n < 2 || !(radius > 0) || !(height > 0)) throw std::invalid_argument("make_half_cylinder: n >= 2, positive sizes");
  Half_cylinder s;
  BI::set_common(s, "half-cylinder", n, perturbation, seed, 1, 0, true);
  s.radius = radius;
  s.height = height;
  const int m = std::max(1, int(std::lround(height / s.chord())));
  s.rows = m;
  std::vector<Point_3> points;
  for(int j = 0; j <= m; ++j)
    for(int k = 0; k <= n; ++k)
    {
      const double t = 3.14159265358979323846 * k / n;
      points.emplace_back(k == n ? -radius : radius * std::cos(t), (k == 0 || k == n) ? 0.0 : radius * std::sin(t),
                          height * j / m);
    }
  auto id = [n](int k, int j) { return std::size_t(k + (n + 1) * j); };
  auto corner = [n, m](int k, int j) { return (k == 0 || k == n) && (j == 0 || j == m); };
  s.mesh = mesh_from_soup(points, BI::grid_triangles(n, m, id, BI::corner_diagonal(corner), [](int, int) { return true; }));
  perturb_keeping_surface(s.mesh, perturbation, seed, "make_half_cylinder");
  for(std::size_t k = 0; k < points.size(); ++k) s.grid.push_back(Mesh::Vertex_index(Mesh::size_type(k)));
  return s;
}

// --- flat annulus

/// The exact geodesic distance and ridge of a source in a flat polygonal
/// annulus: the plane region between a convex polygonal hole H (containing its
/// vertex centroid c) and a convex outer polygon containing H.
///
/// A path from the source winds around the hole one way or the other. In each
/// of the two classes the shortest path is unique (the universal cover is flat
/// and CAT(0)) and is the taut string: the straight segment if it is free and
/// passes c on the correct side, else the tangent from the source to H, the
/// chain of H's corners, and the tangent from H to the point (it bends only
/// at corners of H, whose inner angle in the domain exceeds pi; the convex
/// outer boundary never bends it). `path(p, +1)` keeps H on its left (goes
/// counter-clockwise around c), `path(p, -1)` on its right.
///
/// THE EXACT RIDGE is the set of points where the two classes tie,
/// d_ccw(p) = d_cw(p) (both are then shortest: any other class winds further):
/// one arc from the hole to the outer boundary, on the far side of the hole.
/// Where the two lengths differ, the shorter path is the unique shortest one
/// and no other point is on the ridge. For a source on a symmetry axis of
/// both polygons through c (for make_flat_annulus(): a line through c and a
/// corner, or through c and an edge midpoint) the arc is the straight segment
/// of that axis on the far side, from H to the outer boundary; otherwise it is
/// a curve made of pieces of hyperbolas (points equidistant from two corners
/// of H, with different offsets), traced here numerically.
///
/// `polyline()` samples it: on each of `samples` + 1 loops between the hole
/// (lambda = 0) and the outer boundary (lambda = 1), the points
/// (1 - lambda) H(phi) + lambda O(phi) (H(phi), O(phi): where the ray from c
/// at angle phi meets the polygons), the one sign change of d_ccw - d_cw in
/// phi (checked: a loop with another count throws) is found by bisection to
/// round-off (`samples` = 0: distances only, no polyline). Points: 2D (x, y).
class Flat_annulus_ridge
{
public:
  typedef std::array<double, 2> P2;
  /// a shortest path of one class: its length, and the start of its last
  /// straight leg (the source or a corner of the hole)
  struct Path
  {
    double length;
    P2 last;
  };

  Flat_annulus_ridge(const std::vector<P2>& hole, const std::vector<P2>& outer, const P2& source, int samples = 200)
    : outer_(outer), source_(source)
  {
    if(hole.size() < 3 || outer.size() < 3 || samples < 0) throw std::invalid_argument("Flat_annulus_ridge: polygons, samples");
    centre_ = {{0, 0}};
    for(const P2& q : hole) { centre_[0] += q[0] / double(hole.size()); centre_[1] += q[1] / double(hole.size()); }
    scale_ = 0;
    for(const P2& q : outer) scale_ = std::max(scale_, norm(sub(q, centre_)));
    hole_[0] = hole;
    for(auto it = hole.rbegin(); it != hole.rend(); ++it) hole_[1].push_back(mirror(*it));
    if(samples > 0) trace(samples);
  }

  /// the shortest path of one class: side +1 counter-clockwise around the hole, -1 clockwise
  Path path(const P2& p, int side) const
  {
    if(side > 0) return path_ccw(hole_[0], source_, p);
    Path q = path_ccw(hole_[1], mirror(source_), mirror(p));
    q.last = mirror(q.last);
    return q;
  }
  /// the exact geodesic distance from the source
  double distance(const P2& p) const { return std::min(path(p, 1).length, path(p, -1).length); }
  /// d_ccw - d_cw: zero exactly on the ridge
  double gap(const P2& p) const { return path(p, 1).length - path(p, -1).length; }
  /// the unit arrival direction at p of the shortest path of one class
  P2 arrival(const P2& p, int side) const
  {
    const P2 d = sub(p, path(p, side).last);
    const double l = norm(d);
    return {{d[0] / l, d[1] / l}};
  }
  const P2& source() const { return source_; }
  const P2& centre() const { return centre_; }
  /// the ridge, from the hole (first point) to the outer boundary (last point)
  const std::vector<P2>& polyline() const { return polyline_; }
  /// Euclidean distance from p to the polyline
  double distance_to_ridge(const P2& p) const
  {
    double d = std::numeric_limits<double>::infinity();
    for(std::size_t k = 0; k + 1 < polyline_.size(); ++k)
      d = std::min(d, point_segment_distance_2d(p, Segment_2d{polyline_[k], polyline_[k + 1]}));
    return d;
  }

private:
  std::vector<P2> hole_[2]; // [0] as given, [1] mirrored (y -> 2 c_y - y), both counter-clockwise
  std::vector<P2> outer_;
  P2 source_, centre_;
  double scale_ = 1;
  std::vector<P2> polyline_;

  static P2 sub(const P2& a, const P2& b) { return {{a[0] - b[0], a[1] - b[1]}}; }
  static double dot(const P2& a, const P2& b) { return a[0] * b[0] + a[1] * b[1]; }
  static double cross(const P2& a, const P2& b) { return a[0] * b[1] - a[1] * b[0]; }
  static double norm(const P2& a) { return std::hypot(a[0], a[1]); }
  static double wrap_pi(double a) // to (-pi, pi]
  {
    const double two_pi = 2 * 3.14159265358979323846;
    a = std::fmod(a, two_pi);
    if(a <= -0.5 * two_pi) a += two_pi;
    if(a > 0.5 * two_pi) a -= two_pi;
    return a;
  }
  P2 mirror(const P2& p) const { return {{p[0], 2 * centre_[1] - p[1]}}; }
  double polar(const P2& p) const { return std::atan2(p[1] - centre_[1], p[0] - centre_[0]); }

  Path path_ccw(const std::vector<P2>& H, const P2& s, const P2& p) const
  {
    const double tiny = 1e-12 * scale_, two_pi = 2 * 3.14159265358979323846;
    // the tangent corners: from s, the most clockwise direction to H (H on the
    // left of s -> H[a]); into p, the most counter-clockwise one seen from p
    // (H on the left of H[b] -> p); angles relative to the direction to c
    auto relative_angle = [&](const P2& from, const P2& to) {
      const P2 d = sub(centre_, from), w = sub(to, from);
      return std::atan2(cross(d, w), dot(d, w));
    };
    const std::size_t n = H.size();
    std::size_t a = 0, b = 0;
    double best_a = std::numeric_limits<double>::infinity(), best_b = -best_a;
    for(std::size_t j = 0; j < n; ++j)
    {
      if(norm(sub(H[j], s)) > tiny && relative_angle(s, H[j]) < best_a) { best_a = relative_angle(s, H[j]); a = j; }
      if(norm(sub(H[j], p)) > tiny && relative_angle(p, H[j]) > best_b) { best_b = relative_angle(p, H[j]); b = j; }
    }
    // unwrapped angles around c, from the source's: the string touches H from
    // theta_a to theta_b; if the tangents cross before (theta_b < theta_a) the
    // straight segment is free and of this class. With one tangent corner
    // (a == b) the angles tie: the string s -> H[a] -> p is taut iff it turns
    // left there, else H lies left of the segment s -> p, which is the path.
    double phi = std::fmod(polar(p) - polar(s), two_pi);
    if(phi < 0) phi += two_pi;
    const double theta_a = wrap_pi(polar(H[a]) - polar(s));
    const double theta_b = phi + wrap_pi(polar(H[b]) - polar(p));
    const bool straight = a == b ? cross(sub(H[a], s), sub(p, s)) <= 0 : theta_b < theta_a;
    if(straight) return {norm(sub(p, s)), s};
    double length = norm(sub(H[a], s));
    for(std::size_t k = a; k != b; k = (k + 1) % n) length += norm(sub(H[(k + 1) % n], H[k]));
    return {length + norm(sub(p, H[b])), H[b]};
  }

  // where the ray from c at angle phi meets a convex polygon around c
  P2 ray_hit(const std::vector<P2>& poly, double phi) const
  {
    const P2 d = {{std::cos(phi), std::sin(phi)}};
    double t = std::numeric_limits<double>::infinity();
    for(std::size_t k = 0; k < poly.size(); ++k)
    {
      const P2 A = poly[k], e = sub(poly[(k + 1) % poly.size()], A);
      const double den = cross(d, e);
      if(std::abs(den) < 1e-300) continue;
      const double tk = cross(sub(A, centre_), e) / den, u = cross(sub(A, centre_), d) / den;
      if(tk > 0 && u >= -1e-12 && u <= 1 + 1e-12) t = std::min(t, tk);
    }
    return {{centre_[0] + t * d[0], centre_[1] + t * d[1]}};
  }

  void trace(int samples)
  {
    const double two_pi = 2 * 3.14159265358979323846, phi_s = polar(source_);
    const int scan = 720;
    for(int i = 0; i <= samples; ++i)
    {
      const double lambda = double(i) / samples;
      auto point = [&](double phi) {
        const P2 h = ray_hit(hole_[0], phi), o = ray_hit(outer_, phi);
        return P2{{h[0] + lambda * (o[0] - h[0]), h[1] + lambda * (o[1] - h[1])}};
      };
      // d_ccw - d_cw < 0 just after the source's angle, > 0 just before it
      int changes = 0;
      double lo = 0, hi = 0, prev_phi = phi_s + two_pi * 0.5 / scan;
      bool prev_negative = gap(point(prev_phi)) < 0;
      for(int k = 1; k < scan; ++k)
      {
        const double phi = phi_s + two_pi * (k + 0.5) / scan;
        const bool negative = gap(point(phi)) < 0;
        if(negative != prev_negative) { ++changes; lo = prev_phi; hi = phi; }
        prev_negative = negative;
        prev_phi = phi;
      }
      if(changes != 1 || prev_negative)
        throw std::logic_error("Flat_annulus_ridge: the two ways around the hole do not tie exactly once on loop " +
                               std::to_string(i) + " (" + std::to_string(changes) + " sign changes)");
      for(int it = 0; it < 64; ++it)
      {
        const double mid = 0.5 * (lo + hi);
        (gap(point(mid)) < 0 ? lo : hi) = mid;
      }
      polyline_.push_back(point(0.5 * (lo + hi)));
    }
  }
};

/// A flat polygonal annulus at z = 0 around the origin: the hole is the
/// regular n-gon with corners at radius r and angles 2 pi k / n, the outer
/// boundary the same n-gon at radius R. b = 2, g = 0, rank 2: the exact ridge
/// of any source is one arc from the hole to the outer boundary, given by
/// `ridge()` (`Flat_annulus_ridge`). Both polygons are symmetric about the x
/// axis, so for a source (s, 0) the ridge is the segment of the negative x axis
/// from the hole (x = -r for even n, -r cos(pi/n) for odd n) to the outer
/// boundary (x = -R, resp. -R cos(pi/n)); the same holds after rotating by any
/// multiple of pi / n.
struct Flat_annulus : Surface_with_boundary
{
  double inner_radius = 0, outer_radius = 0;
  int rings = 0; ///< m: vertex rings 0 (the hole) to m (the outer boundary)
  /// vertex k of ring j (angle 2 pi k / n, radius r (R/r)^(j/m) before perturbation) is grid[k + n j]
  std::vector<Mesh::Vertex_index> grid;
  std::vector<std::array<double, 2> > hole, outer; ///< the polygons' corners, counter-clockwise

  /// the exact ridge and distance of a source point (x, y) of the annulus (`samples` = 0: no polyline)
  Flat_annulus_ridge ridge(const Point_3& source, int samples = 200) const
  {
    return Flat_annulus_ridge(hole, outer, {{source.x(), source.y()}}, samples);
  }
  double geodesic_distance(const Point_3& a, const Point_3& b) const { return ridge(a, 0).distance({{b.x(), b.y()}}); }
};

/// n >= 6 corners per polygon, r < R cos(pi/n); m = max(1, round(ln(R/r) /
/// ln(1 + 2 pi/n))) rings at geometric radii (nearly square cells), cells
/// split alternately. Perturbation: `perturb_keeping_surface()` (inner
/// vertices in the plane; the boundary vertices are all corners and stay).
inline Flat_annulus make_flat_annulus(int n, double inner_radius = 1, double outer_radius = 3, double perturbation = 0,
                                      unsigned seed = 1)
{
  namespace BI = boundary_internal;
  const double pi = 3.14159265358979323846;
  if(n < 6 || !(inner_radius > 0) || !(inner_radius < outer_radius * std::cos(pi / n)))
    throw std::invalid_argument("make_flat_annulus: n >= 6, 0 < r < R cos(pi/n)");
  Flat_annulus s;
  BI::set_common(s, "flat annulus", n, perturbation, seed, 2, 0, false);
  s.inner_radius = inner_radius;
  s.outer_radius = outer_radius;
  const int m = std::max(1, int(std::lround(std::log(outer_radius / inner_radius) / std::log(1 + 2 * pi / n))));
  s.rings = m;
  std::vector<Point_3> points;
  for(int j = 0; j <= m; ++j)
    for(int k = 0; k < n; ++k)
    {
      const double rho = inner_radius * std::pow(outer_radius / inner_radius, double(j) / m), t = 2 * pi * k / n;
      points.emplace_back(rho * std::cos(t), rho * std::sin(t), 0.0);
      if(j == 0) s.hole.push_back({{points.back().x(), points.back().y()}});
      if(j == m) s.outer.push_back({{points.back().x(), points.back().y()}});
    }
  // (ring, corner) is counter-clockwise as (x, y): radius first, angle second
  auto id = [n](int j, int k) { return std::size_t(k % n + n * j); };
  auto alternate = [](int j, int k) { return (j + k) % 2 == 0; };
  s.mesh = mesh_from_soup(points, BI::grid_triangles(m, n, id, alternate, [](int, int) { return true; }));
  perturb_keeping_surface(s.mesh, perturbation, seed, "make_flat_annulus");
  for(std::size_t k = 0; k < points.size(); ++k) s.grid.push_back(Mesh::Vertex_index(Mesh::size_type(k)));
  return s;
}

// --- open box

/// The unit cube [0,1]^3 without its top face (z = 1): b = 1 (the rim), g = 0,
/// rank 1. The four bottom corners are vertices of positive curvature (leaves
/// of the ridge); the rim bends no path (its corners have inner angle pi). For
/// a general source the ridge has no closed form: compare with the exact
/// solver's reference. From the bottom centre S = (1/2, 1/2, 0) it is the four
/// vertical edges, from the bottom corners to the rim: on the side x = 0 the
/// point (0, y, z) is reached across the bottom edge x = 0, unfolded length
/// sqrt((z + 1/2)^2 + (y - 1/2)^2), or around a vertical edge, across y = 0
/// (sqrt((z + 1/2)^2 + (y + 1/2)^2)) or y = 1 (same with 3/2 - y); paths
/// through corners are no shorter. The first is strictly shorter for
/// 0 < y < 1 and ties at y = 0 and y = 1 (the same on every side), and the
/// bottom is reached straight.
struct Open_box : Surface_with_boundary
{
  /// the mesh vertex at each corner of box_corners_and_faces() (corner k = (k&1, (k&2)/2, (k&4)/4)); 4..7 on the rim
  std::vector<Mesh::Vertex_index> corner_vertices;
  /// distance from p (on the box) to the ridge of the bottom centre: the four vertical edges
  static double distance_to_bottom_centre_ridge(const Point_3& p)
  {
    double d = std::numeric_limits<double>::infinity();
    for(double x : {0.0, 1.0})
      for(double y : {0.0, 1.0}) d = std::min(d, std::hypot(p.x() - x, p.y() - y));
    return d;
  }
};

/// The five faces subdivided n x n as make_subdivided_polyhedron() does
/// (5 * 2 n^2 triangles). Perturbation: `perturb_keeping_surface()` (face
/// points in their face, cube-edge and rim points along their edge, corners
/// fixed).
inline Open_box make_open_box(int n, double perturbation = 0, unsigned seed = 1)
{
  namespace BI = boundary_internal;
  if(n < 1) throw std::invalid_argument("make_open_box: n >= 1");
  Open_box s;
  BI::set_common(s, "open box", n, perturbation, seed, 1, 0, false);
  Polyhedron_description d = box_corners_and_faces();
  d.faces.erase(d.faces.begin() + 1); // {4, 5, 7, 6}: the top
  Subdivided_polyhedron p = make_subdivided_polyhedron(d, n);
  s.mesh = p.mesh;
  s.corner_vertices = p.corner_vertices;
  perturb_keeping_surface(s.mesh, perturbation, seed, "make_open_box");
  return s;
}

// --- torus with a hole

/// The torus ((R + r cos v) cos u, (R + r cos v) sin u, r sin v) on an
/// n x m grid of (u, v) cells, without a block of h x h cells at u, v in
/// [0, 2 pi h / n) x [0, 2 pi h / m) (on the outer equator): one boundary loop
/// of 4h edges, g = 1, b = 1, rank 3. No analytic ridge: compare with the
/// exact solver's reference and with the topology.
struct Torus_with_hole : Surface_with_boundary
{
  double major_radius = 0, minor_radius = 0;
  int across = 0;                ///< m: cells around the minor circle
  int hole_cells = 0;            ///< h
  std::size_t removed_faces = 0; ///< 2 h^2
};

/// n >= 4 cells around the major circle, m = max(4, round(n r / R)) around the
/// minor one, 1 <= h <= min(n, m) - 3, cells split alternately. Perturbation
/// (in (0, 0.3]): every vertex's (u, v) moves by up to `perturbation` cells in
/// each direction, so that vertices stay on the smooth torus (the polyhedral
/// surface changes, which is harmless: its ridge is not analytic).
inline Torus_with_hole make_torus_with_hole(int n, double major_radius = 1, double minor_radius = 0.4, int hole_cells = 2,
                                            double perturbation = 0, unsigned seed = 1)
{
  namespace BI = boundary_internal;
  const double two_pi = 2 * 3.14159265358979323846;
  const int m = std::max(4, int(std::lround(n * minor_radius / major_radius)));
  if(n < 4 || !(minor_radius > 0) || !(minor_radius < major_radius) || hole_cells < 1 || hole_cells > std::min(n, m) - 3)
    throw std::invalid_argument("make_torus_with_hole: n >= 4, 0 < r < R, 1 <= hole cells <= min(n, m) - 3");
  Torus_with_hole s;
  BI::set_common(s, "torus with a hole", n, perturbation, seed, 1, 1, false);
  s.major_radius = major_radius;
  s.minor_radius = minor_radius;
  s.across = m;
  s.hole_cells = hole_cells;
  auto at = [=](double u, double v) {
    const double w = major_radius + minor_radius * std::cos(v);
    return Point_3(w * std::cos(u), w * std::sin(u), minor_radius * std::sin(v));
  };
  std::vector<Point_3> points;
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < n; ++i) points.push_back(at(two_pi * i / n, two_pi * j / m));
  auto id = [n, m](int i, int j) { return std::size_t(i % n + n * (j % m)); };
  auto keep = [hole_cells](int i, int j) { return !(i < hole_cells && j < hole_cells); };
  std::vector<BI::Triangle> tris = BI::grid_triangles(n, m, id, [](int i, int j) { return (i + j) % 2 == 0; }, keep);
  s.removed_faces = std::size_t(2 * n * m) - tris.size();
  BI::drop_unused_points(points, tris);
  s.mesh = mesh_from_soup(points, tris);
  if(perturbation > 0)
  {
    std::uniform_real_distribution<double> d(-perturbation, perturbation);
    std::vector<std::array<double, 2> > uv;
    for(const Point_3& p : points)
      uv.push_back({{std::atan2(p.y(), p.x()), std::atan2(p.z(), std::hypot(p.x(), p.y()) - major_radius)}});
    BI::perturb_vertices(s.mesh, [&](Mesh::Vertex_index v, std::mt19937& rng) {
      const auto& q = uv[std::size_t(v)];
      const double du = d(rng) * two_pi / n, dv = d(rng) * two_pi / m; // in this order
      return at(q[0] + du, q[1] + dv);
    }, seed, "make_torus_with_hole");
  }
  return s;
}

} // namespace testing
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_TEST_SUPPORT_ANALYTIC_MESHES_H
