// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef GEODESIC_RIDGE_INTERNAL_FACES_BY_INDEX_H
#define GEODESIC_RIDGE_INTERNAL_FACES_BY_INDEX_H

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

/// The faces of a triangle mesh by face index, with their corners in the
/// order of a `Face_location`: corner k is source(next^k(halfedge(f))).
template <class TriangleMesh, class VertexPointMap>
class Faces_by_index
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

  template <class FaceIndexMap>
  Faces_by_index(const TriangleMesh& tm, VertexPointMap vpm, FaceIndexMap fim)
      : tm_(tm), vpm_(vpm), face_of_(num_faces(tm))
  {
    for(face_descriptor f : faces(tm)) face_of_[get(fim, f)] = f;
  }

  face_descriptor face(std::size_t f) const { return face_of_[f]; }

  std::array<halfedge_descriptor, 3> corner_halfedges(std::size_t f) const
  {
    const halfedge_descriptor h0 = halfedge(face_of_[f], tm_);
    return {{h0, next(h0, tm_), next(next(h0, tm_), tm_)}};
  }

  std::array<Point, 3> corner_points(std::size_t f) const
  {
    const auto h = corner_halfedges(f);
    return {{get(vpm_, source(h[0], tm_)), get(vpm_, source(h[1], tm_)), get(vpm_, source(h[2], tm_))}};
  }

private:
  const TriangleMesh& tm_;
  VertexPointMap vpm_;
  std::vector<face_descriptor> face_of_;
};

// Per face of M (by index) and edge k (corner k to k+1): the face across it and
// that edge's index there.
typedef std::vector<std::array<std::pair<std::size_t, int>, 3> > Faces_across;
template <class TriangleMesh, class FaceIndexMap>
Faces_across faces_across(const TriangleMesh& tm, FaceIndexMap fim)
{
  Faces_across across(num_faces(tm));
  for(auto f : faces(tm))
  {
    auto h = halfedge(f, tm);
    for(int k = 0; k < 3; ++k, h = next(h, tm))
    {
      const auto o = opposite(h, tm);
      const auto g = face(o, tm);
      int kg = 0;
      for(auto x = halfedge(g, tm); x != o; x = next(x, tm)) ++kg;
      across[get(fim, f)][k] = {static_cast<std::size_t>(get(fim, g)), kg};
    }
  }
  return across;
}

} // namespace internal
} // namespace Geodesic_ridge

#endif
