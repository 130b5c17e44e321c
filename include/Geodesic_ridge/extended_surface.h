// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 2a: the extended surface E (user manual, "The Extended Surface";
// paper §3.2.1).
//
// Cut the mesh M open along the cut graph K of stage 1 into a disk D, then grow
// copies of faces across the boundary, one face at a time, ring by ring. Copies
// grown from one side of the cut form one continuous sheet: the moment the fan of
// faces around a vertex copy covers the vertex's whole star, its two end faces
// are glued (fan closure), which may merge and close further fans. At a leaf of
// K the fan winds past 2π, as at the end of a slit in a double cover; it is
// bounded at three turns (see `leaf_winding_stars`).
#ifndef GEODESIC_RIDGE_EXTENDED_SURFACE_H
#define GEODESIC_RIDGE_EXTENDED_SURFACE_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/union_find.h>
#include <Geodesic_ridge/rough_cut_locus.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// Counts of the extension.
struct Extended_surface_statistics
{
  int rings = 0;                        ///< extension rings grown
  std::size_t number_of_faces = 0;      ///< faces of E (copies, including D)
  std::size_t number_of_vertices = 0;   ///< vertices of E
  std::vector<std::size_t> faces_per_ring; ///< faces added by ring k (ring 0 = D)
  std::size_t number_of_closures = 0;   ///< fans closed by gluing their two end faces
  std::size_t winding_bound_hits = 0;   ///< faces not added at a leaf of K: its fan reached three turns
  std::size_t refused_faces = 0;        ///< faces not added elsewhere: a fan would exceed its star (should be 0)
  std::size_t refused_gluings = 0;      ///< closures refused: end faces not adjacent (should be 0)
  std::size_t open_fans = 0;            ///< full fans left open: closing them would overlap another fan
  std::size_t number_of_leaf_vertices = 0; ///< copies of leaves of K (fans winding past 2π)
  std::size_t guided_faces = 0;         ///< copies added by the growth guided by the exact distance on M
  int guided_rings = 0;                 ///< rings the guided growth took (its deepest copy)
  bool guided_ring_cap_hit = false;     ///< the guided growth stopped at the ring cap
};

/// \ingroup PkgGeodesicRidgeRef
/// The extended surface: a `CGAL::Surface_mesh` E with, for every face and
/// vertex, its original in M. Faces 0..F-1 of E are the faces of M (the disk D),
/// in M's face order and with the same corner order, so a `Face_location` of M
/// in D is the same location in E.
template <class Point_3>
struct Extended_surface
{
  /// the type of E
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  /// a vertex of E
  typedef typename Mesh::Vertex_index vertex_descriptor;
  /// a face of E (a copy of a face of M)
  typedef typename Mesh::Face_index   face_descriptor;

  /// E: a valid oriented 2-manifold triangle mesh with a border
  Mesh mesh;
  /// per face of E: index of its original face in M
  std::vector<std::size_t> original_face;
  /// per vertex of E: index of its original vertex in M
  std::vector<std::size_t> original_vertex;
  /// per face of E: 0 for D, k for the k-th extension ring
  std::vector<int> ring;
  /// the source in E (a vertex of E for a vertex source, else a face location in D)
  vertex_descriptor source_vertex;
  /// the source in E as a face location in D (barycentric coordinates in CGAL's order)
  std::pair<face_descriptor, std::array<double, 3> > source_location;
  /// whether the source is a vertex (`source_vertex`) or a surface point (`source_location`)
  bool source_is_vertex = true;

  /// counts of the extension
  Extended_surface_statistics statistics;
};

namespace internal {

/// Builds E from M and K. Works on indices: face f of M has corners
/// c_k = source(h_k) with h_0 = halfedge(f), h_{k+1} = next(h_k); its edge k
/// runs from corner k to corner k+1 (CGAL's `Face_location` order).
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap,
          class EdgeIndexMap>
class Extended_surface_builder
{
  typedef boost::graph_traits<TriangleMesh>                   GT;
  typedef typename GT::vertex_descriptor                      vertex_descriptor;
  typedef typename GT::halfedge_descriptor                    halfedge_descriptor;
  typedef typename GT::face_descriptor                        face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  // A fan at a leaf of K holds at most this many copies of the vertex's star.
  // The sheets grown across the slit from its two sides share that one fan,
  // and each may need to wind once around the leaf (a front that crosses the
  // slit beyond the true ridge's end, on a saddle even past π): 1 + 1 + 1. At
  // two stars (4π) the sheets starved each other (knot_3k, teddy_3k: vertices
  // left without their exact copy); the growth only goes where fronts still
  // win, so the bound costs nothing where it is not needed.
  static constexpr std::uint32_t leaf_winding_stars = 3;

  struct Copy
  {
    std::uint32_t face;                  // original face
    int ring;
    std::array<std::uint32_t, 3> corner; // vertex copies (use find())
    std::array<std::uint32_t, 3> nb;     // copy across edge k, or none (boundary)
    std::array<std::uint8_t, 3> nb_edge; // edge index of that copy
  };
  struct Fan // of a vertex copy (valid at union-find roots)
  {
    std::uint32_t vertex;     // original vertex
    std::uint32_t first, last; // end face copies, in rotation order around the vertex
    std::uint32_t size;       // number of face copies
    bool leaf;                // at a leaf of K, or left open (leave_open): winds past 2π, never closes
    bool closed;
  };
  // A copy laid out in the plane of its chain (the copies it was grown from,
  // back to the cut edge where the chain left D), with the front it carries:
  // the virtual source of that front and the predicted distance at its
  // corners. A corner is live when the front is still exact there (within the
  // slack, against the exact distance on M) and its straight path crosses the
  // chain's root cut edge: only such fronts need copies beyond the cut.
  typedef std::array<double, 2> Point_2;
  struct Unfolding
  {
    std::array<Point_2, 3> corner;
    Point_2 source;
    std::array<Point_2, 2> root;
    std::array<double, 3> value;
    std::array<bool, 3> live;
  };

public:
  Extended_surface_builder(const TriangleMesh& tm, const Rough_cut_locus<TriangleMesh>& rcl,
                           VertexPointMap vpm, VertexIndexMap vim, FaceIndexMap fim, EdgeIndexMap eim)
    : tm_(tm), vpm_(vpm), vim_(vim), fim_(fim)
  {
    index_faces(rcl, eim);
    make_disk();
    const std::size_t nf = num_faces(tm);
    for(std::uint32_t f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
        if(copies_[f].corner[k] == none) make_vertex_copy_of_sector(f, k);
    stats_.faces_per_ring.push_back(nf);
    on_cut_.assign(num_vertices(tm), 0);
    for(std::uint32_t f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
        if(edge_cut_[f][k]) on_cut_[corner_[f][k]] = on_cut_[corner_[f][(k + 1) % 3]] = 1;
  }

  /// Grows one ring: a copy across every boundary edge of E (one at a time),
  /// or only across the boundary edges of the copies `c` with `from[c]` set.
  void grow_ring(const std::vector<char>* from = nullptr)
  {
    const int r = ++stats_.rings;
    std::vector<std::pair<std::uint32_t, int> > boundary;
    for(std::uint32_t c = 0; c < copies_.size(); ++c)
      if(from == nullptr || (c < from->size() && (*from)[c]))
        for(int k = 0; k < 3; ++k)
          if(copies_[c].nb[k] == none) boundary.emplace_back(c, k);
    const std::size_t before = copies_.size();
    for(const auto& [c, k] : boundary)
      if(copies_[c].nb[k] == none) add_copy_across(c, k, r);
    stats_.faces_per_ring.push_back(copies_.size() - before);
  }

  /// Gives the builder the exact geodesic distance on M (per vertex index), which
  /// guides `grow_guided` (with the tree of `rcl`, for the shadows of the cut);
  /// `slack` is how far from it a predicted distance still counts as exact.
  /// Call it before growing any ring.
  void set_exact_distance(const std::vector<double>* exact, double slack,
                          const Rough_cut_locus<TriangleMesh>& rcl)
  {
    exact_ = exact;
    slack_ = slack;
    find_shadowed_vertices(rcl);
  }


  /// Grows copies across the boundary of E, one face at a time in rings, while
  /// the front they continue is predicted (by unfolding) to be exact at a
  /// vertex it reaches through the cut: the shadow of every cut edge, however
  /// wide, plus one face of margin. Stops when no such front is left or at
  /// `maximum_rings`.
  void grow_guided(int maximum_rings)
  {
    if(exact_ == nullptr) return;
    std::vector<std::pair<std::uint32_t, int> > frontier;
    for(std::uint32_t c = 0; c < copies_.size(); ++c)
      for(int k = 0; k < 3; ++k)
        if(copies_[c].nb[k] == none && edge_is_live(c, k)) frontier.emplace_back(c, k);
    int deepest = stats_.rings;
    const std::size_t start = copies_.size();
    while(!frontier.empty())
    {
      if(stats_.rings >= maximum_rings)
      {
        stats_.guided_ring_cap_hit = true;
        break;
      }
      const int r = ++stats_.rings;
      const std::size_t before = copies_.size();
      std::vector<std::pair<std::uint32_t, int> > next;
      for(const auto& [c, k] : frontier)
      {
        if(copies_[c].nb[k] != none) continue;
        const std::uint32_t n = add_copy_across(c, k, r);
        if(n == none) continue;
        for(int j = 0; j < 3; ++j)
          if(copies_[n].nb[j] == none && edge_is_live(n, j)) next.emplace_back(n, j);
      }
      stats_.faces_per_ring.push_back(copies_.size() - before);
      if(copies_.size() > before) deepest = r;
      frontier.swap(next);
    }
    stats_.guided_faces += copies_.size() - start;
    stats_.guided_rings = std::max(stats_.guided_rings, deepest);
  }

  /// Writes E as a `Surface_mesh`: its vertices (one per merged vertex copy),
  /// its glued halfedges, its faces (one per copy) and its border, then the
  /// source in it.
  template <class Point>
  void materialize(Extended_surface<Point>& E, const Geodesic_source<TriangleMesh>& src,
                   VertexIndexMap vim, FaceIndexMap fim)
  {
    typedef typename Extended_surface<Point>::Mesh Mesh;
    E.mesh.clear();
    const std::vector<std::uint32_t> evertex = add_vertices(E);
    // halfedge (c, k) runs from corner k to corner k+1 of copy c
    const std::vector<std::array<typename Mesh::Halfedge_index, 3> > he = add_edges(E.mesh);
    add_faces(E, evertex, he);
    link_border(E.mesh, evertex, he);
    if(!CGAL::is_valid_polygon_mesh(E.mesh))
      throw Algorithm_error("the extended surface is not a valid polygon mesh");
    place_source(E, src, vim, fim, evertex);
    stats_.number_of_faces = E.mesh.number_of_faces();
    stats_.number_of_vertices = E.mesh.number_of_vertices();
    E.statistics = stats_;
  }

  const Extended_surface_statistics& statistics() const { return stats_; }
  std::size_t number_of_copies() const { return copies_.size(); }

private:
  // Per face: its corners, the face and edge across each edge, whether that
  // edge is cut; per vertex its degree.
  template <class EdgeIndexMap_>
  void index_faces(const Rough_cut_locus<TriangleMesh>& rcl, EdgeIndexMap_ eim)
  {
    const std::size_t nv = num_vertices(tm_), nf = num_faces(tm_);
    corner_.resize(nf);
    across_.resize(nf);
    across_edge_.resize(nf);
    edge_cut_.resize(nf);
    vertex_of_.resize(nv);
    for(vertex_descriptor v : vertices(tm_)) vertex_of_[get(vim_, v)] = v;
    degree_.assign(nv, 0);
    for(face_descriptor f : faces(tm_))
    {
      const std::uint32_t fi = static_cast<std::uint32_t>(get(fim_, f));
      halfedge_descriptor h = halfedge(f, tm_);
      for(int k = 0; k < 3; ++k, h = next(h, tm_))
      {
        corner_[fi][k] = static_cast<std::uint32_t>(get(vim_, source(h, tm_)));
        ++degree_[corner_[fi][k]];
        const halfedge_descriptor o = opposite(h, tm_);
        const face_descriptor g = face(o, tm_);
        across_[fi][k] = static_cast<std::uint32_t>(get(fim_, g));
        std::uint8_t kk = 0;
        for(halfedge_descriptor x = halfedge(g, tm_); x != o; x = next(x, tm_)) ++kk;
        across_edge_[fi][k] = kk;
        edge_cut_[fi][k] = rcl.is_cut_edge[get(eim, edge(h, tm_))] != 0;
      }
    }
  }

  // The disk D: one copy per face, glued across every edge not in K.
  void make_disk()
  {
    const std::size_t nf = num_faces(tm_);
    copies_.resize(nf);
    for(std::uint32_t f = 0; f < nf; ++f)
    {
      Copy& c = copies_[f];
      c.face = f;
      c.ring = 0;
      for(int k = 0; k < 3; ++k)
      {
        c.corner[k] = none;
        if(edge_cut_[f][k]) c.nb[k] = none;
        else { c.nb[k] = across_[f][k]; c.nb_edge[k] = across_edge_[f][k]; }
      }
    }
  }

  // A vertex copy of D: one per sector between consecutive cut edges around a
  // vertex, here the sector of corner k of face f.
  void make_vertex_copy_of_sector(std::uint32_t f, int k)
  {
    // walk backwards (prev) around the vertex to the start of the sector
    std::uint32_t g = f;
    int kg = k;
    const std::uint32_t v = corner_[f][k];
    std::uint32_t steps = 0;
    while(!edge_cut_[g][(kg + 2) % 3] && steps < degree_[v])
    {
      const std::uint32_t p = across_[g][(kg + 2) % 3];
      kg = position_of(p, v);
      g = p;
      ++steps;
    }
    const bool closed = (steps == degree_[v]) && !edge_cut_[g][(kg + 2) % 3];
    const std::uint32_t id = new_vertex_copy(v, g);
    Fan& fan = fans_[id];
    fan.size = 0;
    // walk forwards (next) to the end of the sector
    std::uint32_t h = g;
    int kh = kg;
    for(;;)
    {
      copies_[h].corner[kh] = id;
      ++fan.size;
      fan.last = h;
      if(fan.size == degree_[v] || edge_cut_[h][kh]) break;
      const std::uint32_t n = across_[h][kh];
      kh = position_of(n, v);
      h = n;
    }
    fan.closed = closed;
    fan.leaf = !closed && fan.size == degree_[v]; // one sector holding the whole star: a leaf of K
    if(fan.leaf) ++stats_.number_of_leaf_vertices;
  }

  // the vertex of E at corner k of copy c
  template <class Mesh>
  typename Mesh::Vertex_index vertex_at(const std::vector<std::uint32_t>& evertex, std::uint32_t c, int k)
  {
    return typename Mesh::Vertex_index(evertex[find(copies_[c].corner[k % 3])]);
  }

  // one vertex of E per merged vertex copy, in order of first use; returns
  // the vertex of E of every root vertex copy
  template <class Point>
  std::vector<std::uint32_t> add_vertices(Extended_surface<Point>& E)
  {
    std::vector<std::uint32_t> evertex(vertex_copies_.size(), none);
    E.original_vertex.clear();
    for(std::uint32_t c = 0; c < copies_.size(); ++c)
      for(int k = 0; k < 3; ++k)
      {
        const std::uint32_t root = find(copies_[c].corner[k]);
        if(evertex[root] != none) continue;
        evertex[root] = static_cast<std::uint32_t>(E.mesh.number_of_vertices());
        E.mesh.add_vertex(get(vpm_, vertex_of_[fans_[root].vertex]));
        E.original_vertex.push_back(fans_[root].vertex);
      }
    return evertex;
  }

  // one edge of E per glued pair of copy edges or border copy edge
  template <class Mesh>
  std::vector<std::array<typename Mesh::Halfedge_index, 3> > add_edges(Mesh& m) const
  {
    std::vector<std::array<typename Mesh::Halfedge_index, 3> > he(copies_.size());
    for(std::uint32_t c = 0; c < copies_.size(); ++c)
      for(int k = 0; k < 3; ++k)
      {
        const Copy& cc = copies_[c];
        if(cc.nb[k] != none && cc.nb[k] < c) continue; // created from the other side
        const auto h = m.add_edge();
        he[c][k] = h;
        if(cc.nb[k] != none) he[cc.nb[k]][cc.nb_edge[k]] = m.opposite(h);
      }
    return he;
  }

  template <class Point, class Halfedges>
  void add_faces(Extended_surface<Point>& E, const std::vector<std::uint32_t>& evertex, const Halfedges& he)
  {
    typedef typename Extended_surface<Point>::Mesh Mesh;
    Mesh& m = E.mesh;
    E.original_face.resize(copies_.size());
    E.ring.resize(copies_.size());
    for(std::uint32_t c = 0; c < copies_.size(); ++c)
    {
      const typename Mesh::Face_index f = m.add_face();
      E.original_face[c] = copies_[c].face;
      E.ring[c] = copies_[c].ring;
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
  void link_border(Mesh& m, const std::vector<std::uint32_t>& evertex, const Halfedges& he)
  {
    for(std::uint32_t c = 0; c < copies_.size(); ++c)
      for(int k = 0; k < 3; ++k)
      {
        if(copies_[c].nb[k] != none) continue;
        const auto b = m.opposite(he[c][k]);
        const std::uint32_t u = find(copies_[c].corner[k]);
        m.set_face(b, Mesh::null_face());
        m.set_target(b, vertex_at<Mesh>(evertex, c, k));
        const std::uint32_t first = fans_[u].first;
        const int kf = position_of_copy(first, u);
        m.set_next(b, m.opposite(he[first][(kf + 2) % 3]));
        m.set_halfedge(vertex_at<Mesh>(evertex, c, k), b);
      }
  }

  template <class Point>
  void place_source(Extended_surface<Point>& E, const Geodesic_source<TriangleMesh>& src, VertexIndexMap vim,
                    FaceIndexMap fim, const std::vector<std::uint32_t>& evertex)
  {
    typedef typename Extended_surface<Point>::Mesh Mesh;
    E.source_is_vertex = (src.kind == Geodesic_source<TriangleMesh>::ON_VERTEX);
    E.source_location.first =
        typename Mesh::Face_index(static_cast<typename Mesh::size_type>(get(fim, src.location.first)));
    E.source_location.second = src.location.second;
    if(!E.source_is_vertex) return;
    // Looked up now that the mesh is final: vertex numbering changes as copies merge.
    const std::uint32_t sv = static_cast<std::uint32_t>(get(vim, src.vertex));
    const std::uint32_t f = static_cast<std::uint32_t>(get(fim, src.location.first));
    E.source_vertex = vertex_at<Mesh>(evertex, f, position_of(f, sv));
    if(E.original_vertex[E.source_vertex] != sv || CGAL::is_border(E.source_vertex, E.mesh))
      throw Algorithm_error("the source is not an interior vertex of the extended surface");
  }

  int position_of(std::uint32_t f, std::uint32_t v) const
  {
    return corner_[f][0] == v ? 0 : (corner_[f][1] == v ? 1 : 2);
  }
  int position_of_copy(std::uint32_t c, std::uint32_t root)
  {
    for(int k = 0; k < 3; ++k)
      if(find(copies_[c].corner[k]) == root) return k;
    return 0;
  }
  // a vertex copy's id after merges: the id its merged set keeps
  std::uint32_t find(std::uint32_t x) const { return static_cast<std::uint32_t>(vertex_copies_.find(x)); }
  std::uint32_t new_vertex_copy(std::uint32_t v, std::uint32_t first)
  {
    const std::uint32_t id = static_cast<std::uint32_t>(vertex_copies_.add());
    fans_.push_back(Fan{v, first, first, 1, false, false});
    return id;
  }
  std::uint32_t limit(const Fan& f) const { return f.leaf ? leaf_winding_stars * degree_[f.vertex] : degree_[f.vertex]; }

  std::uint32_t add_copy_across(std::uint32_t c, int k, int r)
  {
    const std::uint32_t f = copies_[c].face;
    const std::uint32_t g = across_[f][k];
    const int kg = across_edge_[f][k];
    const std::uint32_t xu = find(copies_[c].corner[k]), xw = find(copies_[c].corner[(k + 1) % 3]);
    Fan& fu = fans_[xu];
    Fan& fw = fans_[xw];
    if(fu.last != c || fw.first != c || fu.closed || fw.closed)
    {
      ++stats_.refused_gluings;
      return none;
    }
    if(fu.size + 1 > limit(fu) || fw.size + 1 > limit(fw))
    {
      if((fu.leaf && fu.size + 1 > limit(fu)) || (fw.leaf && fw.size + 1 > limit(fw)))
        ++stats_.winding_bound_hits;
      else
        ++stats_.refused_faces;
      return none;
    }
    const std::uint32_t n = static_cast<std::uint32_t>(copies_.size());
    Copy nc;
    nc.face = g;
    nc.ring = r;
    nc.corner[kg] = xw;
    nc.corner[(kg + 1) % 3] = xu;
    nc.nb = {none, none, none};
    nc.nb_edge = {0, 0, 0};
    nc.nb[kg] = c;
    nc.nb_edge[kg] = static_cast<std::uint8_t>(k);
    copies_.push_back(nc);
    const std::uint32_t y = new_vertex_copy(corner_[g][(kg + 2) % 3], n);
    copies_[n].corner[(kg + 2) % 3] = y;
    copies_[c].nb[k] = n;
    copies_[c].nb_edge[k] = static_cast<std::uint8_t>(kg);
    fans_[xu].last = n;
    ++fans_[xu].size;
    fans_[xw].first = n;
    ++fans_[xw].size;
    if(exact_ != nullptr)
    {
      // the new copy continues the front of c across edge k
      if(unfold_.size() <= n) unfold_.resize(n + 1);
      unfold_[n] = unfold_across(copies_[c].ring > 0 ? unfold_[c] : root_unfolding(c, k), k, g, kg);
    }
    close_if_complete(xu);
    close_if_complete(find(xw));
    return n;
  }

  // A vertex is shadowed when its path in the tree of stage 1 (which follows
  // the geodesics) goes through a vertex of K from one of its sectors in D to
  // another: its shortest path crosses the cut, so its copy in D is inexact and
  // the front that crossed needs copies there.
  void find_shadowed_vertices(const Rough_cut_locus<TriangleMesh>& rcl)
  {
    const std::size_t nv = vertex_of_.size();
    shadowed_.assign(nv, 0);
    if(rcl.parent.size() != nv) return;
    // the sector of p in D that holds the (uncut) edge from p to q
    auto sector = [&](std::uint32_t p, std::uint32_t q) -> std::uint32_t {
      for(auto h : CGAL::halfedges_around_source(vertex_of_[p], tm_))
        if(static_cast<std::uint32_t>(get(vim_, target(h, tm_))) == q && !is_border(h, tm_))
        {
          const std::uint32_t f = static_cast<std::uint32_t>(get(fim_, face(h, tm_)));
          return find(copies_[f].corner[position_of(f, p)]);
        }
      return none;
    };
    // parents before children: by depth in the tree
    std::vector<std::uint32_t> parent(nv), order, depth(nv, none);
    for(std::uint32_t v = 0; v < nv; ++v) parent[v] = static_cast<std::uint32_t>(get(vim_, rcl.parent[v]));
    for(std::uint32_t v = 0; v < nv; ++v)
    {
      std::vector<std::uint32_t> chain;
      std::uint32_t x = v;
      while(depth[x] == none && parent[x] != x && chain.size() <= nv) { chain.push_back(x); x = parent[x]; }
      if(depth[x] == none) depth[x] = 0;
      for(auto it = chain.rbegin(); it != chain.rend(); ++it) depth[*it] = depth[parent[*it]] + 1;
    }
    order.resize(nv);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return depth[a] < depth[b]; });
    for(std::uint32_t x : order)
    {
      const std::uint32_t p = parent[x];
      if(p == x) continue;
      bool crosses = false;
      const std::uint32_t pp = parent[p];
      if(on_cut_[p] && pp != p) crosses = sector(p, pp) != sector(p, x);
      shadowed_[x] = shadowed_[p] || crosses;
    }
  }

  Point_2 planar_third(const Point_2& a, const Point_2& b, double la, double lb, double side) const
  {
    // the point at distances la from a and lb from b, on the given side of ab
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double l = std::sqrt(ex * ex + ey * ey);
    const double t = (la * la - lb * lb + l * l) / (2 * l);
    const double h = std::sqrt(std::max(0.0, la * la - t * t));
    const double ux = ex / l, uy = ey / l;
    const double s = side >= 0 ? 1.0 : -1.0;
    return {{a[0] + t * ux - s * h * uy, a[1] + t * uy + s * h * ux}};
  }
  double length(std::uint32_t v, std::uint32_t w) const
  {
    const auto p = get(vpm_, vertex_of_[v]), q = get(vpm_, vertex_of_[w]);
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
  }
  static double cross(const Point_2& o, const Point_2& a, const Point_2& b)
  {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  }
  static bool segments_meet(const Point_2& p, const Point_2& q, const Point_2& a, const Point_2& b)
  {
    const double d1 = cross(p, q, a), d2 = cross(p, q, b), d3 = cross(a, b, p), d4 = cross(a, b, q);
    return ((d1 <= 0 && d2 >= 0) || (d1 >= 0 && d2 <= 0)) && ((d3 <= 0 && d4 >= 0) || (d3 >= 0 && d4 <= 0));
  }
  static double distance_2(const Point_2& a, const Point_2& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

  // (Unfoldings exist only when an exact distance is given.)
  // D copy c laid out with its cut edge k on the x axis and the face above it;
  // its front is the exact distance on M, its virtual source found from the
  // distances at the edge's ends, on the face's side (the front reaches the
  // cut from there).
  Unfolding root_unfolding(std::uint32_t c, int k) const
  {
    Unfolding u;
    const std::uint32_t f = copies_[c].face;
    const std::uint32_t va = corner_[f][k], vb = corner_[f][(k + 1) % 3], vq = corner_[f][(k + 2) % 3];
    const double l = length(va, vb);
    u.corner[k] = {{0, 0}};
    u.corner[(k + 1) % 3] = {{l, 0}};
    u.corner[(k + 2) % 3] = planar_third(u.corner[k], u.corner[(k + 1) % 3], length(va, vq), length(vb, vq), 1);
    // the root: the cut edge, prolonged by twice its length at both ends (the
    // cut is a zigzag of edges: a front crossing it nearby is the one this
    // chain continues; the sheet grown across the neighbouring edges is the
    // same, made once)
    u.root = {{Point_2{{-2 * l, 0}}, Point_2{{3 * l, 0}}}};
    u.live = {{false, false, false}};
    for(int j = 0; j < 3; ++j) u.value[j] = (*exact_)[corner_[f][j]];
    u.source = planar_third(u.corner[k], u.corner[(k + 1) % 3], u.value[k], u.value[(k + 1) % 3], 1);
    u.live[k] = u.live[(k + 1) % 3] = true;
    return u;
  }

  // The copy of face g grown across edge k of a copy laid out as p: its edge kg
  // is that edge, reversed; its third corner goes on the other side.
  Unfolding unfold_across(const Unfolding& p, int k, std::uint32_t g, int kg) const
  {
    Unfolding u;
    u.source = p.source;
    u.root = p.root;
    const int a = kg, b = (kg + 1) % 3, x = (kg + 2) % 3;
    u.corner[a] = p.corner[(k + 1) % 3];
    u.corner[b] = p.corner[k];
    u.value[a] = p.value[(k + 1) % 3];
    u.value[b] = p.value[k];
    u.live[a] = p.live[(k + 1) % 3];
    u.live[b] = p.live[k];
    const double side = -cross(u.corner[a], u.corner[b], p.corner[(k + 2) % 3]); // the parent's third corner's other side
    u.corner[x] = planar_third(u.corner[a], u.corner[b], length(corner_[g][a], corner_[g][x]),
                               length(corner_[g][b], corner_[g][x]), side >= 0 ? 1 : -1);
    u.value[x] = distance_2(u.source, u.corner[x]);
    const std::uint32_t vx = corner_[g][x];
    u.live[x] = std::abs(u.value[x] - (*exact_)[vx]) <= slack_ && (shadowed_[vx] || on_cut_[vx]) &&
                segments_meet(u.source, u.corner[x], u.root[0], u.root[1]);
    return u;
  }

  bool edge_is_live(std::uint32_t c, int k) const
  {
    if(copies_[c].ring == 0) return exact_ != nullptr; // a cut edge of D: its front crosses it
    return c < unfold_.size() && (unfold_[c].live[k] || unfold_[c].live[(k + 1) % 3]);
  }

  void close_if_complete(std::uint32_t x0)
  {
    std::vector<std::uint32_t> pending{x0};
    while(!pending.empty())
    {
      const std::uint32_t x = find(pending.back());
      pending.pop_back();
      const Fan fx = fans_[x];
      if(fx.closed || fx.leaf || fx.size != degree_[fx.vertex]) continue;
      // The end faces L (last) and F (first) hold the two copies of one edge (v, z).
      const std::uint32_t L = fx.last, F = fx.first;
      const int kL = position_of_copy(L, x), kF = position_of_copy(F, x);
      const int eL = kL, eF = (kF + 2) % 3; // L's next edge at v, F's prev edge at v
      if(copies_[L].nb[eL] != none || copies_[F].nb[eF] != none ||
         across_[copies_[L].face][eL] != copies_[F].face)
      {
        ++stats_.refused_gluings;
        continue;
      }
      const std::uint32_t zL = find(copies_[L].corner[(kL + 1) % 3]);
      const std::uint32_t zF = find(copies_[F].corner[eF]);
      if(zL == zF)
      {
        // this gluing closes z's fan too: only right if it is a whole star
        const Fan& fz = fans_[zL];
        if(fz.leaf || fz.closed || fz.first != L || fz.last != F || fz.size != degree_[fz.vertex])
        {
          leave_open(x);
          continue;
        }
        glue(L, eL, F, eF);
        fans_[x].closed = true;
        fans_[zL].closed = true;
        ++stats_.number_of_closures;
        continue;
      }
      // around z, F comes before L: fan(zF) ends with F, fan(zL) starts with L
      const Fan a = fans_[zF], b = fans_[zL];
      if(a.last != F || b.first != L || a.closed || b.closed || (a.leaf && b.leaf) ||
         a.size + b.size > ((a.leaf || b.leaf) ? leaf_winding_stars * degree_[a.vertex] : degree_[a.vertex]))
      {
        leave_open(x);
        continue;
      }
      glue(L, eL, F, eF);
      fans_[x].closed = true;
      ++stats_.number_of_closures;
      vertex_copies_.unite_into(zL, zF); // the merged copy keeps zF's id
      fans_[zF].last = b.last;
      fans_[zF].size = a.size + b.size;
      fans_[zF].leaf = a.leaf || b.leaf;
      pending.push_back(zF);
    }
  }

  // The fan of x covers its star, but gluing its end faces would make a copy
  // of the vertex z at their far end wind past its star: the sheet grew
  // around x and z from two sides that E does not know to be one (copies of
  // one face of the cover of M, made twice). x is left open, a boundary
  // vertex of E like a leaf of K, and may wind on, so the growth goes on
  // around it (else its fronts stop there and vertices lose their exact copy).
  void leave_open(std::uint32_t x)
  {
    fans_[x].leaf = true;
    ++stats_.open_fans;
  }

  void glue(std::uint32_t a, int ea, std::uint32_t b, int eb)
  {
    copies_[a].nb[ea] = b;
    copies_[a].nb_edge[ea] = static_cast<std::uint8_t>(eb);
    copies_[b].nb[eb] = a;
    copies_[b].nb_edge[eb] = static_cast<std::uint8_t>(ea);
  }

  const TriangleMesh& tm_;
  VertexPointMap vpm_;
  VertexIndexMap vim_;
  FaceIndexMap fim_;
  std::vector<vertex_descriptor> vertex_of_;
  std::vector<std::array<std::uint32_t, 3> > corner_, across_;
  std::vector<std::array<std::uint8_t, 3> > across_edge_;
  std::vector<std::array<bool, 3> > edge_cut_;
  std::vector<std::uint32_t> degree_;
  std::vector<Copy> copies_;
  Union_find vertex_copies_; // vertex copies merged by closing fans
  std::vector<Fan> fans_;
  std::vector<Unfolding> unfold_; // per copy (entries of D copies unused)
  std::vector<char> on_cut_, shadowed_; // per vertex of M
  const std::vector<double>* exact_ = nullptr;
  double slack_ = 0;
  Extended_surface_statistics stats_;
};

} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
/// \brief builds the extended surface of `tm` cut along `rcl.cut_edges`, with
/// `rings` extension rings grown everywhere (\ref GeodesicRidgeSecExtendedSurface).
///
/// The pipeline grows E by the growth rule instead, with the same builder
/// (`compute_ridge_curve()`); this function is stage 2a alone.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param rcl its rough cut locus (`compute_rough_cut_locus()`)
/// \param rings the number of extension rings
/// \param np an optional sequence of named parameters among the ones listed
///        below: the same as given to `compute_rough_cut_locus()`
///
/// \pre `rcl` was computed on `tm` with the same index maps.
/// \pre `rings >= 0` (`Invalid_parameter_error` otherwise).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in [0, `num_vertices(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in [0, `num_faces(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_index_map}
///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in [0, `num_edges(tm)`)}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns E, an `Extended_surface<Point_3>` (`Point_3` the value type of the
///          vertex point map)
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Extended_surface<typename boost::property_traits<typename CGAL::GetVertexPointMap<
    TriangleMesh, NamedParameters>::const_type>::value_type>
build_extended_surface(const TriangleMesh& tm, const Rough_cut_locus<TriangleMesh>& rcl, int rings,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(rings < 0) throw Invalid_parameter_error("the number of extension rings must be non-negative");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto eim = CGAL::get_initialized_edge_index_map(tm, np);
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  internal::Extended_surface_builder<TriangleMesh, std::decay_t<decltype(vpm)>, std::decay_t<decltype(vim)>,
                                     std::decay_t<decltype(fim)>, std::decay_t<decltype(eim)> >
      builder(tm, rcl, vpm, vim, fim, eim);
  for(int r = 0; r < rings; ++r) builder.grow_ring();
  Extended_surface<Point> E;
  builder.materialize(E, rcl.source, vim, fim);
  return E;
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_EXTENDED_SURFACE_H
