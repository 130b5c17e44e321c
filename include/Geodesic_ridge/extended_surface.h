// Copyright (c) 2026 Geodesic_ridge developers.
//
// Stage 2a: the extended surface E (DESIGN.md §3, paper §3.2.1).
//
// Cut the mesh M open along the cut graph K of stage 1 into a disk D, then grow
// copies of faces across the boundary, one face at a time, ring by ring. Copies
// grown from one side of the cut form one continuous sheet: the moment the fan of
// faces around a vertex copy covers the vertex's whole star, its two end faces
// are glued (fan closure), which may merge and close further fans. At a leaf of
// K the fan winds past 2π, as at the end of a slit in a double cover; it is
// bounded at 4π.
#ifndef GEODESIC_RIDGE_EXTENDED_SURFACE_H
#define GEODESIC_RIDGE_EXTENDED_SURFACE_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/rough_cut_locus.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <chrono>
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
  std::size_t winding_bound_hits = 0;   ///< faces not added at a leaf of K: its fan reached 4π
  std::size_t refused_faces = 0;        ///< faces not added elsewhere: a fan would exceed its star (should be 0)
  std::size_t refused_gluings = 0;      ///< closures refused: wrong cone angle, overlap or order (should be 0)
  std::size_t number_of_leaf_vertices = 0; ///< copies of leaves of K (fans winding past 2π)
  double time = 0;
};

/// \ingroup PkgGeodesicRidgeRef
/// The extended surface: a `CGAL::Surface_mesh` E with, for every face and
/// vertex, its original in M. Faces 0..F-1 of E are the faces of M (the disk D),
/// in M's face order and with the same corner order, so a `Face_location` of M
/// in D is the same location in E.
template <class Point_3>
struct Extended_surface
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename Mesh::Vertex_index vertex_descriptor;
  typedef typename Mesh::Face_index   face_descriptor;

  Mesh mesh;
  /// per face of E: index of its original face in M
  std::vector<std::size_t> original_face;
  /// per vertex of E: index of its original vertex in M
  std::vector<std::size_t> original_vertex;
  /// per face of E: 0 for D, k for the k-th extension ring
  std::vector<int> ring;
  /// the source in E (a vertex of E for a vertex source, else a face location in D)
  vertex_descriptor source_vertex;
  std::pair<face_descriptor, std::array<double, 3> > source_location;
  bool source_is_vertex = true;

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
    bool leaf;                // the copy at a leaf of K: winds past 2π, never closes
    bool closed;
  };

public:
  Extended_surface_builder(const TriangleMesh& tm, const Rough_cut_locus<TriangleMesh>& rcl,
                           VertexPointMap vpm, VertexIndexMap vim, FaceIndexMap fim, EdgeIndexMap eim)
    : tm_(tm), vpm_(vpm)
  {
    const std::size_t nv = num_vertices(tm), nf = num_faces(tm);
    corner_.resize(nf);
    across_.resize(nf);
    across_edge_.resize(nf);
    edge_cut_.resize(nf);
    vertex_of_.resize(nv);
    for(vertex_descriptor v : vertices(tm)) vertex_of_[get(vim, v)] = v;
    degree_.assign(nv, 0);
    for(face_descriptor f : faces(tm))
    {
      const std::uint32_t fi = static_cast<std::uint32_t>(get(fim, f));
      halfedge_descriptor h = halfedge(f, tm);
      for(int k = 0; k < 3; ++k, h = next(h, tm))
      {
        corner_[fi][k] = static_cast<std::uint32_t>(get(vim, source(h, tm)));
        ++degree_[corner_[fi][k]];
        const halfedge_descriptor o = opposite(h, tm);
        const face_descriptor g = face(o, tm);
        across_[fi][k] = static_cast<std::uint32_t>(get(fim, g));
        std::uint8_t kk = 0;
        for(halfedge_descriptor x = halfedge(g, tm); x != o; x = next(x, tm)) ++kk;
        across_edge_[fi][k] = kk;
        edge_cut_[fi][k] = rcl.is_cut_edge[get(eim, edge(h, tm))] != 0;
      }
    }
    // The disk D: one copy per face, glued across every edge not in K.
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
    // Vertex copies of D: one per sector between consecutive cut edges.
    for(std::uint32_t f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
      {
        if(copies_[f].corner[k] != none) continue;
        // walk backwards (prev) around the vertex to the start of the sector
        std::uint32_t g = f;
        int kg = k;
        const std::uint32_t v = corner_[f][k];
        std::uint32_t steps = 0;
        while(!edge_cut_[g][(kg + 2) % 3] && steps < degree_[v])
        {
          const std::uint32_t p = across_[g][(kg + 2) % 3];
          const int kp = position_of(p, v);
          g = p;
          kg = kp;
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
    stats_.faces_per_ring.push_back(nf);
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

  template <class Point>
  void materialize(Extended_surface<Point>& E, const Geodesic_source<TriangleMesh>& src,
                   VertexIndexMap vim, FaceIndexMap fim)
  {
    typedef typename Extended_surface<Point>::Mesh Mesh;
    typedef typename Mesh::Vertex_index   V;
    typedef typename Mesh::Halfedge_index H;
    typedef typename Mesh::Face_index     F;
    Mesh& m = E.mesh;
    m.clear();
    const std::size_t nc = copies_.size();
    std::vector<std::uint32_t> evertex(uf_parent_.size(), none);
    E.original_vertex.clear();
    for(std::uint32_t c = 0; c < nc; ++c)
      for(int k = 0; k < 3; ++k)
      {
        const std::uint32_t root = find(copies_[c].corner[k]);
        if(evertex[root] == none)
        {
          evertex[root] = static_cast<std::uint32_t>(m.number_of_vertices());
          m.add_vertex(get(vpm_, vertex_of_[fans_[root].vertex]));
          E.original_vertex.push_back(fans_[root].vertex);
        }
      }
    // halfedge (c, k) runs from corner k to corner k+1 of copy c
    std::vector<std::array<H, 3> > he(nc);
    for(std::uint32_t c = 0; c < nc; ++c)
      for(int k = 0; k < 3; ++k)
      {
        const Copy& cc = copies_[c];
        if(cc.nb[k] != none && cc.nb[k] < c) continue; // created from the other side
        const H h = m.add_edge();
        he[c][k] = h;
        if(cc.nb[k] != none) he[cc.nb[k]][cc.nb_edge[k]] = m.opposite(h);
      }
    E.original_face.resize(nc);
    E.ring.resize(nc);
    auto vtx = [&](std::uint32_t c, int k) { return V(evertex[find(copies_[c].corner[k % 3])]); };
    for(std::uint32_t c = 0; c < nc; ++c)
    {
      const F f = m.add_face();
      E.original_face[c] = copies_[c].face;
      E.ring[c] = copies_[c].ring;
      m.set_halfedge(f, he[c][0]);
      for(int k = 0; k < 3; ++k)
      {
        const H h = he[c][k];
        m.set_face(h, f);
        m.set_target(h, vtx(c, k + 1));
        m.set_next(h, he[c][(k + 1) % 3]);
        m.set_halfedge(vtx(c, k + 1), h);
      }
    }
    // border halfedges: opposite of (c, k) unglued, from corner k+1 to corner k;
    // its next leaves corner k at the other end of that vertex copy's fan.
    for(std::uint32_t c = 0; c < nc; ++c)
      for(int k = 0; k < 3; ++k)
      {
        if(copies_[c].nb[k] != none) continue;
        const H b = m.opposite(he[c][k]);
        const std::uint32_t u = find(copies_[c].corner[k]);
        m.set_face(b, Mesh::null_face());
        m.set_target(b, vtx(c, k));
        const std::uint32_t first = fans_[u].first;
        const int kf = position_of_copy(first, u);
        m.set_next(b, m.opposite(he[first][(kf + 2) % 3]));
        m.set_halfedge(vtx(c, k), b);
      }
    if(!CGAL::is_valid_polygon_mesh(m))
      throw Algorithm_error("the extended surface is not a valid polygon mesh");

    E.source_is_vertex = (src.kind == Geodesic_source<TriangleMesh>::ON_VERTEX);
    E.source_location.first = F(static_cast<typename Mesh::size_type>(get(fim, src.location.first)));
    E.source_location.second = src.location.second;
    if(E.source_is_vertex)
    {
      // Looked up now that the mesh is final: vertex numbering changes as copies merge.
      const std::uint32_t sv = static_cast<std::uint32_t>(get(vim, src.vertex));
      const std::uint32_t f = static_cast<std::uint32_t>(get(fim, src.location.first));
      E.source_vertex = vtx(f, position_of(f, sv));
      if(E.original_vertex[E.source_vertex] != sv || CGAL::is_border(E.source_vertex, m))
        throw Algorithm_error("the source is not an interior vertex of the extended surface");
    }
    stats_.number_of_faces = m.number_of_faces();
    stats_.number_of_vertices = m.number_of_vertices();
    E.statistics = stats_;
  }

  const Extended_surface_statistics& statistics() const { return stats_; }
  std::size_t number_of_copies() const { return copies_.size(); }

private:
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
  std::uint32_t find(std::uint32_t x)
  {
    while(uf_parent_[x] != x) { uf_parent_[x] = uf_parent_[uf_parent_[x]]; x = uf_parent_[x]; }
    return x;
  }
  std::uint32_t new_vertex_copy(std::uint32_t v, std::uint32_t first)
  {
    const std::uint32_t id = static_cast<std::uint32_t>(uf_parent_.size());
    uf_parent_.push_back(id);
    fans_.push_back(Fan{v, first, first, 1, false, false});
    return id;
  }
  std::uint32_t limit(const Fan& f) const { return f.leaf ? 2 * degree_[f.vertex] : degree_[f.vertex]; }

  void add_copy_across(std::uint32_t c, int k, int r)
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
      return;
    }
    if(fu.size + 1 > limit(fu) || fw.size + 1 > limit(fw))
    {
      if((fu.leaf && fu.size + 1 > limit(fu)) || (fw.leaf && fw.size + 1 > limit(fw)))
        ++stats_.winding_bound_hits;
      else
        ++stats_.refused_faces;
      return;
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
    close_if_complete(xu);
    close_if_complete(find(xw));
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
          ++stats_.refused_gluings;
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
         a.size + b.size > ((a.leaf || b.leaf) ? 2 * degree_[a.vertex] : degree_[a.vertex]))
      {
        ++stats_.refused_gluings;
        continue;
      }
      glue(L, eL, F, eF);
      fans_[x].closed = true;
      ++stats_.number_of_closures;
      uf_parent_[zL] = zF; // zF stays the root
      fans_[zF].last = b.last;
      fans_[zF].size = a.size + b.size;
      fans_[zF].leaf = a.leaf || b.leaf;
      pending.push_back(zF);
    }
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
  std::vector<vertex_descriptor> vertex_of_;
  std::vector<std::array<std::uint32_t, 3> > corner_, across_;
  std::vector<std::array<std::uint8_t, 3> > across_edge_;
  std::vector<std::array<bool, 3> > edge_cut_;
  std::vector<std::uint32_t> degree_;
  std::vector<Copy> copies_;
  std::vector<std::uint32_t> uf_parent_;
  std::vector<Fan> fans_;
  Extended_surface_statistics stats_;
};

} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
/// Builds the extended surface of `tm` cut along `rcl.cut_edges`, with `rings`
/// extension rings.
///
/// \param np CGAL's `vertex_point_map`, `vertex_index_map`, `face_index_map`,
///        `edge_index_map` (the same as given to stage 1).
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Extended_surface<typename boost::property_traits<typename CGAL::GetVertexPointMap<
    TriangleMesh, NamedParameters>::const_type>::value_type>
build_extended_surface(const TriangleMesh& tm, const Rough_cut_locus<TriangleMesh>& rcl, int rings,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto t0 = std::chrono::steady_clock::now();
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
  E.statistics.time = internal::seconds_since(t0);
  return E;
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_EXTENDED_SURFACE_H
