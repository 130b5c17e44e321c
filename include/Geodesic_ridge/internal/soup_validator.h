// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rules of `validate_triangle_soup()` (mesh_validation.h) on a soup of
// points and polygons: `Triangle_soup_validator` checks them in order and
// throws `Invalid_mesh_error` (or `Repairable_mesh_error`) at the first that
// fails, naming it and the first offending index. Also used by the repair
// (soup_repair.h), which shares its helpers.
#ifndef GEODESIC_RIDGE_INTERNAL_SOUP_VALIDATOR_H
#define GEODESIC_RIDGE_INTERNAL_SOUP_VALIDATOR_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/union_find.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {
namespace validation {

constexpr std::size_t invalid_index = (std::numeric_limits<std::size_t>::max)();

// Polygons may hold signed indices (e.g. `int`): a negative one is out of
// range, it must not wrap around to a valid-looking unsigned value.
template <class I>
std::size_t to_index(I i)
{
  if constexpr(std::is_signed<I>::value)
    if(i < 0)
      return invalid_index;
  return static_cast<std::size_t>(i);
}

template <class I>
std::string index_to_string(I i)
{
  std::ostringstream out;
  out << +i; // `+` so that a `char`-sized index prints as a number
  return out.str();
}

// Stable counting sort of `n` records by a key in [0, n_keys): O(n + n_keys).
// Returns the record order and fills `begin` (size n_keys + 1) with the
// bucket bounds. This is what keeps every check linear: no hash map, no
// global sort, and the order inside a bucket is the input (file) order.
template <class KeyOf>
std::vector<std::size_t> bucket_sort(std::size_t n, std::size_t n_keys, KeyOf key_of,
                                     std::vector<std::size_t>& begin)
{
  begin.assign(n_keys + 1, 0);
  for(std::size_t r = 0; r < n; ++r)
    ++begin[key_of(r) + 1];
  std::partial_sum(begin.begin(), begin.end(), begin.begin());
  std::vector<std::size_t> fill(begin.begin(), begin.end() - 1);
  std::vector<std::size_t> order(n);
  for(std::size_t r = 0; r < n; ++r)
    order[fill[key_of(r)]++] = r;
  return order;
}

// A stable sort of one bucket: by insertion when it is small (most buckets,
// a vertex's few halfedges or faces: std::stable_sort would take a buffer
// from the heap for each), else std::stable_sort. Both give the one stable order.
template <class Iterator, class Less>
void stable_sort_bucket(Iterator first, Iterator last, Less less)
{
  if(last - first > 32)
  {
    std::stable_sort(first, last, less);
    return;
  }
  for(Iterator i = first; i != last; ++i)
  {
    const auto x = *i;
    Iterator j = i;
    for(; j != first && less(x, *(j - 1)); --j)
      *j = *(j - 1);
    *j = x;
  }
}

template <class Point_3>
bool has_finite_coordinates(const Point_3& p)
{
  return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
         std::isfinite(CGAL::to_double(p.z()));
}

// The degeneracy test runs on Epick points, whose `collinear` is exact: a face
// is rejected only if its corners are exactly collinear, never because of an
// epsilon. Points of another kernel are rounded to double first, which is
// lossless for the usual double-based kernels (and is what the algorithm,
// which works in Epick, will see anyway).
using Epick_point_3 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

inline const Epick_point_3& to_epick(const Epick_point_3& p) { return p; }

template <class Point_3>
Epick_point_3 to_epick(const Point_3& p)
{
  return Epick_point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// `repairable`: the repair (`repair_mesh()`) would fix the problem, and the
// exception says so by its type.
[[noreturn]] inline void fail(const std::ostringstream& message, bool repairable = false)
{
  if(repairable)
    throw Repairable_mesh_error(message.str());
  throw Invalid_mesh_error(message.str());
}

// in the link of vertex `owner`, the link vertex after this one
struct Link_step { std::size_t owner, to; };

// The fans of vertex v (corners [first, last)): the components of its link.
// Each corner (v; a, b) of a face gives the link edge a -> b; the mesh being
// oriented and edge-manifold, each link vertex has at most one successor.
// Paths start at a link vertex with no predecessor (at the border); cycles
// are the rest. `next`, `visited` and `has_predecessor` are stamped with v.
// (`tri`: face f is tri[3f], tri[3f + 1], tri[3f + 2].)
template <class Iterator>
std::size_t count_link_fans(const std::vector<std::size_t>& tri, std::size_t v, Iterator first, Iterator last,
                          std::vector<Link_step>& next, std::vector<std::size_t>& visited,
                          std::vector<std::size_t>& has_predecessor)
{
  auto first_of = [&tri](std::size_t c) { return tri[3 * (c / 3) + (c % 3 + 1) % 3]; };
  for(Iterator it = first; it != last; ++it)
  {
    const std::size_t c = *it, f = c / 3, k = c % 3;
    const std::size_t a = tri[3 * f + (k + 1) % 3], b = tri[3 * f + (k + 2) % 3];
    next[a] = {v, b};
    has_predecessor[b] = v;
  }
  auto walk = [&](std::size_t x) {
    while(visited[x] != v)
    {
      visited[x] = v;
      if(next[x].owner != v) return; // the end of a path
      x = next[x].to;
    }
  };
  std::size_t fans = 0;
  for(Iterator it = first; it != last; ++it) // paths first: from their starts
    if(has_predecessor[first_of(*it)] != v && visited[first_of(*it)] != v) { ++fans; walk(first_of(*it)); }
  for(Iterator it = first; it != last; ++it) // then cycles
    if(visited[first_of(*it)] != v) { ++fans; walk(first_of(*it)); }
  return fans;
}

// The rules of `validate_triangle_soup()`, one member function each, run in
// the documented order by `run()`: the first failing rule throws. Messages
// name vertex v and face f as `file_vertex(v)` and `file_face(f)`: the soup's
// own indices, or the file's when the soup was made from a file by
// triangulating (and repairing) it (`set_file_indices()`).
template <class Point_3, class Polygon>
class Triangle_soup_validator
{
public:
  Triangle_soup_validator(const std::vector<Point_3>& points, const std::vector<Polygon>& polygons)
    : points_(points), polygons_(polygons), nv_(points.size()), nf_(polygons.size())
  {}

  // Null, or one file index per vertex / face of the soup.
  void set_file_indices(const std::vector<std::size_t>* vertex_to_file, const std::vector<std::size_t>* face_to_file)
  {
    vertex_to_file_ = vertex_to_file;
    face_to_file_ = face_to_file;
  }

  // Rule 12 skipped: a reader keeps every component, and the algorithm takes
  // the source's (`extract_connected_component()`).
  void allow_several_components() { several_components_allowed_ = true; }

  // The rules that hold for polygons of any size, before they are
  // triangulated: 1, at least three corners per face (2), 3, 4 and 5; without
  // the ones the repair fixes (2 and 4) if `repairable_too` is false.
  void run_polygon_rules(bool repairable_too = true) const
  {
    check_not_empty();
    if(repairable_too)
      check_at_least_three_corners();
    check_indices_in_range();
    if(repairable_too)
      check_no_repeated_corner();
    check_finite_coordinates();
  }

  void run()
  {
    check_not_empty();                  // 1
    check_triangles();                  // 2
    copy_faces_checking_indices();      // 3
    check_no_repeated_vertex();         // 4
    check_finite_coordinates();         // 5
    check_no_isolated_vertex();         // 6
    check_no_duplicate_faces();         // 7
    check_edges();                      // 8-10
    check_manifold_vertices();          // 11
    if(!several_components_allowed_)
      check_connected();                // 12
    check_no_degenerate_face();         // 13
  }

private:
  // The first offending halfedge of each edge rule (invalid_index: none) and
  // what its message needs.

  struct Edge_problems
  {
    std::size_t non_manifold = invalid_index, non_manifold_count = 0;
    std::size_t misoriented = invalid_index, misoriented_other = 0;
  };

  // Halfedge h runs from corner h % 3 of face h / 3 to the next corner.
  std::size_t source(std::size_t h) const { return tri_[h]; }
  std::size_t target(std::size_t h) const { return tri_[h % 3 == 2 ? h - 2 : h + 1]; }
  std::size_t low(std::size_t h) const { return (std::min)(source(h), target(h)); }
  std::size_t high(std::size_t h) const { return (std::max)(source(h), target(h)); }

  void check_not_empty() const
  {
    if(nv_ == 0 || nf_ == 0)
    {
      std::ostringstream msg;
      msg << "mesh is empty (" << nv_ << " vertices, " << nf_ << " faces)";
      fail(msg);
    }
  }

  std::size_t file_vertex(std::size_t v) const { return vertex_to_file_ ? (*vertex_to_file_)[v] : v; }
  std::size_t file_face(std::size_t f) const { return face_to_file_ ? (*face_to_file_)[f] : f; }

  void check_at_least_three_corners() const
  {
    for(std::size_t f = 0; f < nf_; ++f)
    {
      const std::size_t n = static_cast<std::size_t>(polygons_[f].size());
      if(n < 3)
      {
        std::ostringstream msg;
        msg << "face " << file_face(f) << " has " << n << (n == 1 ? " vertex" : " vertices")
            << "; a face needs at least 3";
        fail(msg, true);
      }
    }
  }

  void check_indices_in_range() const
  {
    for(std::size_t f = 0; f < nf_; ++f)
      for(const auto raw : polygons_[f])
        if(to_index(raw) >= nv_)
        {
          std::ostringstream msg;
          msg << "face " << file_face(f) << " refers to vertex " << index_to_string(raw)
              << ", out of range (the mesh has " << nv_ << " vertices, numbered from 0)";
          fail(msg);
        }
  }

  // Rule 4 for a polygon of any size (indices in range).
  void check_no_repeated_corner() const
  {
    std::vector<std::size_t> corners, sorted; // reused: no heap block per face
    for(std::size_t f = 0; f < nf_; ++f)
    {
      corners.clear();
      for(const auto raw : polygons_[f])
        corners.push_back(to_index(raw));
      sorted = corners;
      std::sort(sorted.begin(), sorted.end());
      const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
      if(twice == sorted.end())
        continue;
      std::ostringstream msg;
      msg << "face " << file_face(f) << " repeats vertex " << file_vertex(*twice) << " (vertices ";
      for(std::size_t k = 0; k < corners.size(); ++k)
        msg << (k == 0 ? "" : ", ") << file_vertex(corners[k]);
      msg << ")";
      fail(msg, true);
    }
  }

  void check_triangles() const
  {
    for(std::size_t f = 0; f < nf_; ++f)
    {
      const std::size_t n = static_cast<std::size_t>(polygons_[f].size());
      if(n != 3)
      {
        std::ostringstream msg;
        msg << "face " << file_face(f) << " has " << n << (n == 1 ? " vertex" : " vertices")
            << "; only triangle meshes are supported";
        fail(msg, n > 3);
      }
    }
  }

  // From here on, faces are read from `tri_`, as size_t triples.
  void copy_faces_checking_indices()
  {
    tri_.resize(3 * nf_);
    for(std::size_t f = 0; f < nf_; ++f)
    {
      for(std::size_t k = 0; k < 3; ++k)
      {
        const auto raw = polygons_[f][k];
        const std::size_t v = to_index(raw);
        if(v >= nv_)
        {
          std::ostringstream msg;
          msg << "face " << file_face(f) << " refers to vertex " << index_to_string(raw)
              << ", out of range (the mesh has " << nv_ << " vertices, numbered from 0)";
          fail(msg);
        }
        tri_[3 * f + k] = v;
      }
    }
  }

  void check_no_repeated_vertex() const
  {
    for(std::size_t f = 0; f < nf_; ++f)
    {
      const std::size_t a = tri_[3 * f], b = tri_[3 * f + 1], c = tri_[3 * f + 2];
      if(a == b || a == c || b == c)
      {
        std::ostringstream msg;
        msg << "face " << file_face(f) << " repeats vertex " << file_vertex(a == b || a == c ? a : b)
            << " (vertices " << file_vertex(a) << ", " << file_vertex(b) << ", " << file_vertex(c) << ")";
        fail(msg, true);
      }
    }
  }

  void check_finite_coordinates() const
  {
    for(std::size_t v = 0; v < nv_; ++v)
    {
      if(!has_finite_coordinates(points_[v]))
      {
        std::ostringstream msg;
        msg << "vertex " << file_vertex(v) << " has a non-finite coordinate (" << CGAL::to_double(points_[v].x()) << " "
            << CGAL::to_double(points_[v].y()) << " " << CGAL::to_double(points_[v].z()) << ")";
        fail(msg);
      }
    }
  }

  void check_no_isolated_vertex() const
  {
    std::vector<bool> used(nv_, false);
    for(std::size_t v : tri_)
      used[v] = true;
    const auto it = std::find(used.begin(), used.end(), false);
    if(it != used.end())
    {
      std::ostringstream msg;
      msg << "vertex " << file_vertex(static_cast<std::size_t>(it - used.begin())) << " is isolated (used by no face)";
      fail(msg, true);
    }
  }

  // Bucket the sorted triples by their smallest vertex, sort each bucket by
  // the two others (stable, so equal triples stay in face order), and compare
  // neighbours. Report the pair whose later face comes first in the file.
  void check_no_duplicate_faces() const
  {
    std::vector<std::size_t> sorted(tri_);
    for(std::size_t f = 0; f < nf_; ++f)
      std::sort(sorted.begin() + 3 * f, sorted.begin() + 3 * f + 3);
    std::vector<std::size_t> begin;
    std::vector<std::size_t> order = bucket_sort(nf_, nv_, [&](std::size_t f) { return sorted[3 * f]; }, begin);
    auto key = [&](std::size_t f) { return std::make_pair(sorted[3 * f + 1], sorted[3 * f + 2]); };
    for(std::size_t v = 0; v < nv_; ++v)
      stable_sort_bucket(order.begin() + begin[v], order.begin() + begin[v + 1],
                         [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
    std::size_t first = invalid_index, other = invalid_index;
    for(std::size_t i = 1; i < nf_; ++i)
    {
      const std::size_t f = order[i], g = order[i - 1];
      if(sorted[3 * f] == sorted[3 * g] && key(f) == key(g) && f < first)
      {
        first = f;
        other = g; // an earlier face on the same vertices (stable order)
      }
    }
    if(first != invalid_index)
    {
      std::ostringstream msg;
      msg << "faces " << file_face(other) << " and " << file_face(first) << " are duplicates (both on vertices "
          << file_vertex(sorted[3 * first]) << ", " << file_vertex(sorted[3 * first + 1]) << ", "
          << file_vertex(sorted[3 * first + 2]) << ")";
      fail(msg, true);
    }
  }

  // The 3F halfedges bucketed by their lower vertex, each bucket sorted by the
  // higher one (stable): the halfedges of an edge are adjacent, in face order.
  std::vector<std::size_t> halfedges_by_edge() const
  {
    std::vector<std::size_t> begin;
    std::vector<std::size_t> order = bucket_sort(3 * nf_, nv_, [this](std::size_t h) { return low(h); }, begin);
    for(std::size_t v = 0; v < nv_; ++v)
      stable_sort_bucket(order.begin() + begin[v], order.begin() + begin[v + 1],
                         [this](std::size_t a, std::size_t b) { return high(a) < high(b); });
    return order;
  }

  // One pass over the groups of equal edges; "first" is the offending edge
  // that appears in the earliest face.
  Edge_problems find_edge_problems() const
  {
    const std::vector<std::size_t> order = halfedges_by_edge();
    const std::size_t nh = order.size();
    Edge_problems p;
    for(std::size_t i = 0; i < nh;)
    {
      std::size_t j = i + 1;
      while(j < nh && low(order[j]) == low(order[i]) && high(order[j]) == high(order[i]))
        ++j;
      const std::size_t h = order[i]; // the halfedge of the earliest face (stable)
      if(j - i >= 3)
      {
        if(h < p.non_manifold)
        {
          p.non_manifold = h;
          p.non_manifold_count = j - i;
        }
      }
      else if(j - i == 1)
        ; // a border edge
      else if(source(order[i]) == source(order[i + 1]) && h < p.misoriented)
      {
        p.misoriented = h;
        p.misoriented_other = order[i + 1];
      }
      i = j;
    }
    return p;
  }

  // 8-10, each over the whole mesh before the next.
  void check_edges() const
  {
    const Edge_problems p = find_edge_problems();
    std::ostringstream msg;
    if(p.non_manifold != invalid_index)
    {
      const std::size_t h = p.non_manifold;
      msg << "edge " << file_vertex(low(h)) << "-" << file_vertex(high(h)) << " is non-manifold: it is shared by "
          << p.non_manifold_count << " faces (first: face " << file_face(h / 3)
          << "); only manifold meshes are supported";
      fail(msg, true);
    }
    if(p.misoriented != invalid_index)
    {
      const std::size_t h = p.misoriented;
      msg << "faces " << file_face(h / 3) << " and " << file_face(p.misoriented_other / 3)
          << " are inconsistently oriented (both traverse edge " << file_vertex(source(h)) << "->"
          << file_vertex(target(h)) << " in the same direction)";
      fail(msg, true);
    }
  }

  // A vertex is manifold iff its link is one cycle (inside) or one path (on
  // the border).
  void check_manifold_vertices() const
  {
    std::vector<std::size_t> begin;
    const std::vector<std::size_t> corners =
      bucket_sort(3 * nf_, nv_, [this](std::size_t c) { return tri_[c]; }, begin);
    std::vector<Link_step> next(nv_, Link_step{invalid_index, invalid_index});
    std::vector<std::size_t> visited(nv_, invalid_index), has_predecessor(nv_, invalid_index);
    for(std::size_t v = 0; v < nv_; ++v)
    {
      const std::size_t fans = count_link_fans(tri_, v, corners.begin() + begin[v], corners.begin() + begin[v + 1], next,
                                               visited, has_predecessor);
      if(fans > 1)
      {
        std::ostringstream msg;
        msg << "vertex " << file_vertex(v) << " is non-manifold (its faces form " << fans
            << " separate fans); only manifold meshes are supported";
        fail(msg, true);
      }
    }
  }

  void check_connected() const
  {
    Union_find uf(nv_);
    for(std::size_t f = 0; f < nf_; ++f)
    {
      uf.unite(tri_[3 * f], tri_[3 * f + 1]);
      uf.unite(tri_[3 * f], tri_[3 * f + 2]);
    }
    const std::size_t components = uf.number_of_sets();
    if(components > 1)
    {
      std::ostringstream msg;
      msg << "mesh has " << components << " connected components; the algorithm takes one "
          << "(extract_connected_component() copies the source's)";
      fail(msg);
    }
  }

  // With an exact predicate, no epsilon.
  void check_no_degenerate_face() const
  {
    for(std::size_t f = 0; f < nf_; ++f)
    {
      if(CGAL::collinear(to_epick(points_[tri_[3 * f]]), to_epick(points_[tri_[3 * f + 1]]),
                         to_epick(points_[tri_[3 * f + 2]])))
      {
        std::ostringstream msg;
        msg << "face " << file_face(f) << " is degenerate (its corners are collinear)";
        fail(msg, true);
      }
    }
  }

  const std::vector<Point_3>& points_;
  const std::vector<Polygon>& polygons_;
  const std::size_t nv_, nf_;
  const std::vector<std::size_t>* vertex_to_file_ = nullptr;
  const std::vector<std::size_t>* face_to_file_ = nullptr;
  bool several_components_allowed_ = false;
  std::vector<std::size_t> tri_; // face f is tri_[3f], tri_[3f + 1], tri_[3f + 2]
};

} // namespace validation
} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_SOUP_VALIDATOR_H
