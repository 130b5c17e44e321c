// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The loops of a mesh's border: per vertex (by index) the loop it lies on.
// Stage 1 counts them (b in 2g + b), stage 3 joins the ridge's pieces to
// them, and the cone ridge's check counts the graph of the ridge with them.
#ifndef GEODESIC_RIDGE_INTERNAL_BORDER_LOOPS_H
#define GEODESIC_RIDGE_INTERNAL_BORDER_LOOPS_H

#include <Geodesic_ridge/internal/union_find.h>

#include <CGAL/boost/graph/helpers.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <map>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

struct Border_loops
{
  static constexpr std::size_t none = std::size_t(-1);
  // per vertex: its loop (numbered by their smallest vertex index), or none inside
  std::vector<std::size_t> loop_of_vertex;
  std::size_t number_of_loops = 0;

  bool on_border(std::size_t v) const { return loop_of_vertex[v] != none; }
};

template <class TriangleMesh, class VertexIndexMap>
Border_loops border_loops(const TriangleMesh& tm, VertexIndexMap vim)
{
  const std::size_t nv = num_vertices(tm);
  Union_find loops(nv);
  std::vector<char> on_border(nv, 0);
  for(auto h : halfedges(tm))
    if(is_border(h, tm))
    {
      const std::size_t a = get(vim, source(h, tm)), b = get(vim, target(h, tm));
      on_border[a] = on_border[b] = 1;
      loops.unite(a, b);
    }
  Border_loops result;
  result.loop_of_vertex.assign(nv, Border_loops::none);
  std::map<std::size_t, std::size_t> label; // per loop's root
  for(std::size_t v = 0; v < nv; ++v)
    if(on_border[v]) result.loop_of_vertex[v] = label.emplace(loops.find(v), label.size()).first->second;
  result.number_of_loops = label.size();
  return result;
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_BORDER_LOOPS_H
