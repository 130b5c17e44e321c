// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 2a: E written as a `CGAL::Surface_mesh` from the copies the builder
// (`Extended_surface_builder`, extended_surface.h) grew. E is rebuilt after
// every growth pass, so its arrays are sized once and filled by index.
#ifndef GEODESIC_RIDGE_INTERNAL_EXTENDED_SURFACE_WRITER_H
#define GEODESIC_RIDGE_INTERNAL_EXTENDED_SURFACE_WRITER_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/source.h>

#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cstdint>
#include <vector>

namespace Geodesic_ridge {

template <class Point_3>
struct Extended_surface;

namespace internal {

// The copies of an `Extended_surface_builder` (`Builder`) as the mesh of E.
template <class TriangleMesh, class Builder>
class Extended_surface_writer
{
  typedef typename Builder::Copy Copy;
  static constexpr std::uint32_t none = Builder::none;

public:
  explicit Extended_surface_writer(const Builder& builder) : b_(builder) {}

  /// Writes E: its vertices (one per merged vertex copy), its glued
  /// halfedges, its faces (one per copy) and its border, then the source in
  /// it. With `validate`, checks that E is a valid polygon mesh (else only in
  /// debug builds).
  template <class Point>
  void write(Extended_surface<Point>& E, const Geodesic_source<TriangleMesh>& src, bool validate) const
  {
    typedef typename Extended_surface<Point>::Mesh Mesh;
    E.mesh.clear();
    const std::vector<std::array<std::uint32_t, 3> > corner_vertex = number_vertices(E);
    // E is rebuilt at every pass: its arrays are sized once and filled by
    // index (vertex v, edge e with halfedges 2e and 2e + 1, face c = copy c)
    E.mesh.resize(static_cast<typename Mesh::size_type>(E.original_vertex.size()),
                  static_cast<typename Mesh::size_type>(number_of_edges()),
                  static_cast<typename Mesh::size_type>(b_.copies_.size()));
    for(std::size_t v = 0; v < E.original_vertex.size(); ++v)
      E.mesh.point(typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(v))) =
          get(b_.maps_.vpm, b_.vertex_of_[E.original_vertex[v]]);
    // halfedge (c, k) runs from corner k to corner k+1 of copy c
    const std::vector<std::array<typename Mesh::Halfedge_index, 3> > he = add_edges(E.mesh);
    add_faces(E, corner_vertex, he);
    link_border(E.mesh, corner_vertex, he);
#ifndef NDEBUG
    validate = true; // every E is checked in debug builds
#endif
    if(validate) Builder::check_valid(E);
    place_source(E, src, corner_vertex);
  }

  /// Throws `Algorithm_error` unless E is a valid polygon mesh.
  template <class Point>
  static void check_valid(const Extended_surface<Point>& E)
  {
    if(!CGAL::is_valid_polygon_mesh(E.mesh))
      throw Algorithm_error("the extended surface is not a valid polygon mesh");
  }

private:
  // the vertex of E at corner k of copy c
  template <class Mesh>
  static typename Mesh::Vertex_index vertex_at(const std::vector<std::array<std::uint32_t, 3> >& corner_vertex,
                                               std::uint32_t c, int k)
  {
    return typename Mesh::Vertex_index(corner_vertex[c][k % 3]);
  }

  // one vertex of E per merged vertex copy, numbered in order of first use
  // (with its original in `E.original_vertex`); returns the vertex of E at
  // every corner of every copy
  template <class Point>
  std::vector<std::array<std::uint32_t, 3> > number_vertices(Extended_surface<Point>& E) const
  {
    std::vector<std::uint32_t> evertex(b_.vertex_copies_.size(), none);
    std::vector<std::array<std::uint32_t, 3> > corner_vertex(b_.copies_.size());
    E.original_vertex.clear();
    for(std::uint32_t c = 0; c < b_.copies_.size(); ++c)
      for(int k = 0; k < 3; ++k)
      {
        const std::uint32_t root = b_.find(b_.copies_[c].corner[k]);
        if(evertex[root] == none)
        {
          evertex[root] = static_cast<std::uint32_t>(E.original_vertex.size());
          E.original_vertex.push_back(b_.fans_[root].vertex);
        }
        corner_vertex[c][k] = evertex[root];
      }
    return corner_vertex;
  }

  // the edges of E: one per glued pair of copy edges or border copy edge
  std::size_t number_of_edges() const
  {
    std::size_t n = 0;
    for(std::uint32_t c = 0; c < b_.copies_.size(); ++c)
      for(int k = 0; k < 3; ++k) n += b_.copies_[c].nb[k] == none || b_.copies_[c].nb[k] >= c;
    return n;
  }

  // one edge of E per glued pair of copy edges or border copy edge (E's
  // arrays are sized: edge e is the e-th met)
  template <class Mesh>
  std::vector<std::array<typename Mesh::Halfedge_index, 3> > add_edges(Mesh& m) const
  {
    std::vector<std::array<typename Mesh::Halfedge_index, 3> > he(b_.copies_.size());
    typename Mesh::size_type e = 0;
    for(std::uint32_t c = 0; c < b_.copies_.size(); ++c)
      for(int k = 0; k < 3; ++k)
      {
        const Copy& cc = b_.copies_[c];
        if(cc.nb[k] != none && cc.nb[k] < c) continue; // created from the other side
        const auto h = m.halfedge(typename Mesh::Edge_index(e++));
        he[c][k] = h;
        if(cc.nb[k] != none) he[cc.nb[k]][cc.nb_edge[k]] = m.opposite(h);
      }
    return he;
  }

  template <class Point, class Halfedges>
  void add_faces(Extended_surface<Point>& E, const std::vector<std::array<std::uint32_t, 3> >& evertex,
                 const Halfedges& he) const
  {
    typedef typename Extended_surface<Point>::Mesh Mesh;
    Mesh& m = E.mesh;
    E.original_face.resize(b_.copies_.size());
    E.ring.resize(b_.copies_.size());
    for(std::uint32_t c = 0; c < b_.copies_.size(); ++c)
    {
      const typename Mesh::Face_index f(static_cast<typename Mesh::size_type>(c));
      E.original_face[c] = b_.copies_[c].face;
      E.ring[c] = b_.copies_[c].ring;
      m.set_halfedge(f, he[c][0]);
      for(int k = 0; k < 3; ++k)
      {
        const auto h = he[c][k];
        m.set_face(h, f);
        m.set_target(h, vertex_at<Mesh>(evertex, c, k + 1));
        m.set_next(h, he[c][(k + 1) % 3]);
        m.set_halfedge(vertex_at<Mesh>(evertex, c, k + 1), h);
      }
    }
  }

  // border halfedges: opposite of (c, k) unglued, from corner k+1 to corner k;
  // its next leaves corner k at the other end of that vertex copy's fan.
  template <class Mesh, class Halfedges>
  void link_border(Mesh& m, const std::vector<std::array<std::uint32_t, 3> >& evertex, const Halfedges& he) const
  {
    for(std::uint32_t c = 0; c < b_.copies_.size(); ++c)
      for(int k = 0; k < 3; ++k)
      {
        if(b_.copies_[c].nb[k] != none) continue;
        const auto b = m.opposite(he[c][k]);
        const std::uint32_t u = b_.find(b_.copies_[c].corner[k]);
        m.set_face(b, Mesh::null_face());
        m.set_target(b, vertex_at<Mesh>(evertex, c, k));
        const std::uint32_t first = b_.fans_[u].first;
        const int kf = b_.position_of_copy(first, u);
        m.set_next(b, m.opposite(he[first][(kf + 2) % 3]));
        m.set_halfedge(vertex_at<Mesh>(evertex, c, k), b);
      }
  }

  template <class Point>
  void place_source(Extended_surface<Point>& E, const Geodesic_source<TriangleMesh>& src,
                    const std::vector<std::array<std::uint32_t, 3> >& evertex) const
  {
    typedef typename Extended_surface<Point>::Mesh Mesh;
    E.source_is_vertex = (src.kind == Geodesic_source<TriangleMesh>::ON_VERTEX);
    E.source_location.first =
        typename Mesh::Face_index(static_cast<typename Mesh::size_type>(get(b_.maps_.fim, src.location.first)));
    E.source_location.second = src.location.second;
    if(!E.source_is_vertex) return;
    // Looked up now that the mesh is final: vertex numbering changes as copies merge.
    const std::uint32_t sv = static_cast<std::uint32_t>(get(b_.maps_.vim, src.vertex));
    const std::uint32_t f = static_cast<std::uint32_t>(get(b_.maps_.fim, src.location.first));
    E.source_vertex = vertex_at<Mesh>(evertex, f, b_.position_of(f, sv));
    if(E.original_vertex[E.source_vertex] != sv || (CGAL::is_border(E.source_vertex, E.mesh) && !b_.border_vertex_[sv]))
      throw Algorithm_error("the source is not an interior vertex of the extended surface");
  }

  const Builder& b_;
};

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_EXTENDED_SURFACE_WRITER_H
