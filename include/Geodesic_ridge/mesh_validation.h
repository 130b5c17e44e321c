// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks that an input mesh is one the algorithm supports, before any work is
// done, so that a bad mesh ends with a one-line message instead of a crash, a
// hang or a silently wrong ridge.
#ifndef GEODESIC_RIDGE_MESH_VALIDATION_H
#define GEODESIC_RIDGE_MESH_VALIDATION_H

#include <Geodesic_ridge/exceptions.h>
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

[[noreturn]] inline void fail(const std::ostringstream& message)
{
  throw Invalid_mesh_error(message.str());
}

} // namespace validation
} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
///
/// \brief checks that a triangle soup, as read from a file, describes a mesh
/// that the package supports, and throws `Invalid_mesh_error` otherwise.
///
/// Vertex `i` is `points[i]` and face `j` is `polygons[j]` (the file order);
/// messages use these indices. The rules are checked in the following order,
/// and the first one that fails gives the message (one line, naming the
/// problem and the first offending index in vertex / face order):
///
/// 1. the mesh is not empty: it has at least one vertex and one face;
/// 2. every face is a triangle. Other polygons are rejected, not triangulated,
///    because triangulating would renumber the faces and the user's face
///    indices (`--source-point FACE ...`) would silently point elsewhere;
/// 3. every face index is in `[0, points.size())`;
/// 4. no face repeats a vertex;
/// 5. every coordinate is finite (no NaN, no infinity);
/// 6. no vertex is isolated (every vertex is used by a face): the algorithm
///    computes a distance per vertex, and an isolated vertex has none;
/// 7. no two faces are on the same three vertices (whatever their orientation);
/// 8. every edge is shared by at most two faces (edge-manifold);
/// 9. every edge is shared by exactly two faces: only closed meshes are supported;
/// 10. the orientation is consistent: the two faces of an edge traverse it in
///     opposite directions;
/// 11. every vertex is manifold: its faces form a single fan (its link, walked
///     face to face, is one cycle), so that two surfaces touching at a vertex
///     are rejected;
/// 12. the mesh is connected (one connected component);
/// 13. no face is degenerate: its corners are not collinear, decided with the
///     exact predicate `CGAL::collinear()` of
///     `CGAL::Exact_predicates_inexact_constructions_kernel`, without
///     epsilon (coordinates of another kernel are first converted to `double`).
///
/// Each rule relies on the previous ones (for instance the fan walk of rule 11
/// needs closed, oriented, edge-manifold input). The cost is
/// O(V + F) time and memory (bucket sorts, no hash map): a 200k-face
/// mesh validates in a few tens of milliseconds.
///
/// \tparam Point_3 a point type of a \cgal kernel (`CGAL::Kernel_traits` is used
///         only through `x()`, `y()`, `z()` and `CGAL::to_double()`)
/// \tparam Polygon a random access range of integer indices, such as
///         `std::vector<std::size_t>`; negative indices are out of range
///
/// \param points the vertex positions
/// \param polygons the faces, as indices into `points`
///
/// \throws Invalid_mesh_error if a rule fails
template <class Point_3, class Polygon>
void validate_triangle_soup(const std::vector<Point_3>& points, const std::vector<Polygon>& polygons)
{
  namespace iv = internal::validation;
  using iv::fail;
  const std::size_t nv = points.size();
  const std::size_t nf = polygons.size();
  std::ostringstream msg;

  // 1. Empty.
  if(nv == 0 || nf == 0)
  {
    msg << "mesh is empty (" << nv << " vertices, " << nf << " faces)";
    fail(msg);
  }

  // 2. Triangles only.
  for(std::size_t f = 0; f < nf; ++f)
  {
    const std::size_t n = static_cast<std::size_t>(polygons[f].size());
    if(n != 3)
    {
      msg << "face " << f << " has " << n << (n == 1 ? " vertex" : " vertices")
          << "; only triangle meshes are supported";
      fail(msg);
    }
  }

  // 3. Indices in range. From here on, faces are copied as size_t triples.
  std::vector<std::size_t> tri(3 * nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    for(std::size_t k = 0; k < 3; ++k)
    {
      const auto raw = polygons[f][k];
      const std::size_t v = iv::to_index(raw);
      if(v >= nv)
      {
        msg << "face " << f << " refers to vertex " << iv::index_to_string(raw)
            << ", out of range (the mesh has " << nv << " vertices, numbered from 0)";
        fail(msg);
      }
      tri[3 * f + k] = v;
    }
  }

  // 4. No repeated vertex in a face.
  for(std::size_t f = 0; f < nf; ++f)
  {
    const std::size_t a = tri[3 * f], b = tri[3 * f + 1], c = tri[3 * f + 2];
    if(a == b || a == c || b == c)
    {
      msg << "face " << f << " repeats vertex " << (a == b || a == c ? a : b)
          << " (vertices " << a << ", " << b << ", " << c << ")";
      fail(msg);
    }
  }

  // 5. Finite coordinates.
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(!iv::has_finite_coordinates(points[v]))
    {
      msg << "vertex " << v << " has a non-finite coordinate (" << CGAL::to_double(points[v].x()) << " "
          << CGAL::to_double(points[v].y()) << " " << CGAL::to_double(points[v].z()) << ")";
      fail(msg);
    }
  }

  // 6. No isolated vertex.
  {
    std::vector<bool> used(nv, false);
    for(std::size_t v : tri)
      used[v] = true;
    const auto it = std::find(used.begin(), used.end(), false);
    if(it != used.end())
    {
      msg << "vertex " << (it - used.begin()) << " is isolated (used by no face)";
      fail(msg);
    }
  }

  // 7. Duplicate faces: bucket the sorted triples by their smallest vertex, sort
  // each bucket by the two others (stable, so equal triples stay in face
  // order), and compare neighbours. Report the pair whose later face comes
  // first in the file.
  {
    std::vector<std::size_t> sorted(tri);
    for(std::size_t f = 0; f < nf; ++f)
      std::sort(sorted.begin() + 3 * f, sorted.begin() + 3 * f + 3);
    std::vector<std::size_t> begin;
    std::vector<std::size_t> order =
      iv::bucket_sort(nf, nv, [&](std::size_t f) { return sorted[3 * f]; }, begin);
    auto key = [&](std::size_t f) { return std::make_pair(sorted[3 * f + 1], sorted[3 * f + 2]); };
    for(std::size_t v = 0; v < nv; ++v)
      std::stable_sort(order.begin() + begin[v], order.begin() + begin[v + 1],
                       [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
    std::size_t first = iv::invalid_index, other = iv::invalid_index;
    for(std::size_t i = 1; i < nf; ++i)
    {
      const std::size_t f = order[i], g = order[i - 1];
      if(sorted[3 * f] == sorted[3 * g] && key(f) == key(g) && f < first)
      {
        first = f;
        other = g; // an earlier face on the same vertices (stable order)
      }
    }
    if(first != iv::invalid_index)
    {
      msg << "faces " << other << " and " << first << " are duplicates (both on vertices "
          << sorted[3 * first] << ", " << sorted[3 * first + 1] << ", " << sorted[3 * first + 2] << ")";
      fail(msg);
    }
  }

  // 8-10. Edges: bucket the 3F halfedges by their smaller vertex, sort each
  // bucket by the larger one, and look at each group of equal edges. The three
  // rules are checked in order over the whole mesh; "first" is the offending
  // edge that appears in the earliest face.
  {
    const std::size_t nh = 3 * nf;
    auto src = [&](std::size_t h) { return tri[h]; };
    auto tgt = [&](std::size_t h) { return tri[h % 3 == 2 ? h - 2 : h + 1]; };
    auto lo = [&](std::size_t h) { return (std::min)(src(h), tgt(h)); };
    auto hi = [&](std::size_t h) { return (std::max)(src(h), tgt(h)); };
    std::vector<std::size_t> begin;
    std::vector<std::size_t> order = iv::bucket_sort(nh, nv, lo, begin);
    for(std::size_t v = 0; v < nv; ++v)
      std::stable_sort(order.begin() + begin[v], order.begin() + begin[v + 1],
                       [&](std::size_t a, std::size_t b) { return hi(a) < hi(b); });

    std::size_t nm_h = iv::invalid_index, nm_count = 0; // non-manifold edge
    std::size_t bd_h = iv::invalid_index, bd_count = 0; // boundary edge
    std::size_t or_h = iv::invalid_index, or_other = 0; // orientation
    for(std::size_t i = 0; i < nh;)
    {
      std::size_t j = i + 1;
      while(j < nh && lo(order[j]) == lo(order[i]) && hi(order[j]) == hi(order[i]))
        ++j;
      const std::size_t h = order[i]; // the halfedge of the earliest face (stable)
      if(j - i >= 3)
      {
        if(h < nm_h)
        {
          nm_h = h;
          nm_count = j - i;
        }
      }
      else if(j - i == 1)
      {
        ++bd_count;
        bd_h = (std::min)(bd_h, h);
      }
      else if(src(order[i]) == src(order[i + 1]) && h < or_h)
      {
        or_h = h;
        or_other = order[i + 1];
      }
      i = j;
    }
    if(nm_h != iv::invalid_index)
    {
      msg << "edge " << lo(nm_h) << "-" << hi(nm_h) << " is non-manifold: it is shared by " << nm_count
          << " faces (first: face " << nm_h / 3 << "); only manifold meshes are supported";
      fail(msg);
    }
    if(bd_count > 0)
    {
      msg << "mesh has " << bd_count << " boundary edge" << (bd_count == 1 ? "" : "s") << " (first: vertices "
          << src(bd_h) << "-" << tgt(bd_h) << " of face " << bd_h / 3 << "); only closed meshes are supported";
      fail(msg);
    }
    if(or_h != iv::invalid_index)
    {
      msg << "faces " << or_h / 3 << " and " << or_other / 3 << " are inconsistently oriented (both traverse edge "
          << src(or_h) << "->" << tgt(or_h) << " in the same direction)";
      fail(msg);
    }
  }

  // 11. Manifold vertices. Each corner (v; a, b) of a face gives the link edge
  // a -> b of v. The mesh being closed, oriented and edge-manifold, `next` is a
  // permutation of the link vertices of v; v is manifold iff it is one cycle.
  {
    std::vector<std::size_t> begin;
    const std::vector<std::size_t> corners = iv::bucket_sort(3 * nf, nv, [&](std::size_t c) { return tri[c]; }, begin);
    std::vector<std::size_t> next(nv, iv::invalid_index);
    std::vector<std::size_t> visited(nv, iv::invalid_index); // stamp = the vertex being checked
    for(std::size_t v = 0; v < nv; ++v)
    {
      for(std::size_t i = begin[v]; i < begin[v + 1]; ++i)
      {
        const std::size_t c = corners[i], f = c / 3, k = c % 3;
        next[tri[3 * f + (k + 1) % 3]] = tri[3 * f + (k + 2) % 3];
      }
      std::size_t cycles = 0;
      for(std::size_t i = begin[v]; i < begin[v + 1]; ++i)
      {
        const std::size_t c = corners[i];
        std::size_t x = tri[3 * (c / 3) + (c % 3 + 1) % 3];
        if(visited[x] == v)
          continue;
        ++cycles;
        while(x != iv::invalid_index && visited[x] != v)
        {
          visited[x] = v;
          x = next[x];
        }
      }
      if(cycles > 1)
      {
        msg << "vertex " << v << " is non-manifold (its faces form " << cycles
            << " separate fans); only manifold meshes are supported";
        fail(msg);
      }
    }
  }

  // 12. One connected component.
  {
    internal::Union_find uf(nv);
    for(std::size_t f = 0; f < nf; ++f)
    {
      uf.unite(tri[3 * f], tri[3 * f + 1]);
      uf.unite(tri[3 * f], tri[3 * f + 2]);
    }
    const std::size_t components = uf.number_of_sets();
    if(components > 1)
    {
      msg << "mesh has " << components << " connected components; only one is supported";
      fail(msg);
    }
  }

  // 13. Degenerate faces, with an exact predicate.
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(CGAL::collinear(iv::to_epick(points[tri[3 * f]]), iv::to_epick(points[tri[3 * f + 1]]),
                       iv::to_epick(points[tri[3 * f + 2]])))
    {
      msg << "face " << f << " is degenerate (its corners are collinear)";
      fail(msg);
    }
  }
}

/// \ingroup PkgGeodesicRidgeRef
///
/// \brief checks that a mesh given through the API (for example a
/// `CGAL::Surface_mesh` built by the user) is one the package supports, with the
/// same rules as `validate_triangle_soup()`, and throws `Invalid_mesh_error`
/// otherwise.
///
/// Vertex `i` and face `j` in the messages are the `i`-th element of
/// `vertices(tm)` and the `j`-th element of `faces(tm)`: for a `CGAL::Surface_mesh`
/// without removed elements, these are its vertex and face indices.
/// A halfedge data structure cannot represent some of the rules' violations
/// (an out-of-range index, a non-manifold edge, an inconsistent orientation),
/// but it can represent all the others (non-triangle faces, isolated vertices,
/// boundaries, two faces glued on the same three vertices, non-finite
/// coordinates, several components, degenerate faces).
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam NamedParameters a sequence of named parameters (\ref GeodesicRidgeSecParameters)
///
/// \param tm the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_mesh_error if a rule fails
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
void validate_triangle_mesh(const TriangleMesh& tm,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  namespace iv = internal::validation;

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  using Point_3 = typename boost::property_traits<std::remove_const_t<decltype(vpm)>>::value_type;
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);

  // Flatten to a soup in iteration order and reuse the soup checks: one set
  // of rules and messages for both entry points. The index map may be sparse
  // (a Surface_mesh with removed vertices), hence the position table.
  std::vector<Point_3> points;
  std::vector<vertex_descriptor> vds;
  std::size_t max_index = 0;
  for(vertex_descriptor v : vertices(tm))
  {
    vds.push_back(v);
    points.push_back(get(vpm, v));
    max_index = (std::max)(max_index, static_cast<std::size_t>(get(vim, v)));
  }
  std::vector<std::size_t> position(vds.empty() ? 0 : max_index + 1, iv::invalid_index);
  for(std::size_t i = 0; i < vds.size(); ++i)
    position[static_cast<std::size_t>(get(vim, vds[i]))] = i;

  std::vector<std::vector<std::size_t>> polygons;
  for(auto f : faces(tm))
  {
    polygons.emplace_back();
    for(vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
      polygons.back().push_back(position[static_cast<std::size_t>(get(vim, v))]);
  }
  validate_triangle_soup(points, polygons);
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_MESH_VALIDATION_H
