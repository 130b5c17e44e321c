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
#include <Geodesic_ridge/internal/extended_surface_writer.h>
#include <Geodesic_ridge/internal/faces_by_index.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/union_find.h>
#include <Geodesic_ridge/rough_cut_locus.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// Counts of the growth of the extended surface and of the solves on it (part
/// of `Geodesic_ridge_statistics`).
struct Extension_growth_statistics
{
  int solves = 0;                 ///< solves of the solver on the extended surface
  int predicted_passes = 0;       ///< fast-marching passes on E that decided the extension steps
  std::size_t outer_copies_winning = 0; ///< at the last solve: copies still winning on a border edge of E (0: E holds every shortest path)
  bool ring_cap_hit = false;      ///< the growth stopped at `maximum_rings` with copies still winning
  int margin_rings = 0;           ///< fast marching: rings grown around the final E (`parameters::fast_marching_margin`)
};

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
template <class TriangleMesh, class Maps>
class Extended_surface_builder
{
  template <class, class> friend class Extended_surface_writer;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename Maps::Point Point_3;
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
    bool border;              // of a vertex on the border of M: its star is a path, never closed
  };

public:
  Extended_surface_builder(const TriangleMesh& tm, const Rough_cut_locus<TriangleMesh>& rcl, const Maps& maps)
    : tm_(tm), maps_(maps)
  {
    index_faces(rcl, maps.eim);
    make_disk();
    const std::size_t nf = num_faces(tm);
    for(std::uint32_t f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
        if(copies_[f].corner[k] == none) make_vertex_copy_of_sector(f, k);
    stats_.faces_per_ring.push_back(nf);
  }

  /// Grows one ring: a copy across every boundary edge of E (one at a time),
  /// or only across the boundary edges of the copies `c` with `from[c]` set
  /// (none of those before `first`).
  void grow_ring(const std::vector<char>* from = nullptr, std::size_t first = 0)
  {
    const int r = ++stats_.rings;
    std::vector<std::pair<std::uint32_t, int> > boundary;
    for(std::uint32_t c = static_cast<std::uint32_t>(first); c < copies_.size(); ++c)
      if(from == nullptr || (c < from->size() && (*from)[c]))
        for(int k = 0; k < 3; ++k)
          if(copies_[c].nb[k] == none && !on_border(copies_[c].face, k)) boundary.emplace_back(c, k);
    const std::size_t before = copies_.size();
    for(const auto& [c, k] : boundary)
      if(copies_[c].nb[k] == none) add_copy_across(c, k, r);
    stats_.faces_per_ring.push_back(copies_.size() - before);
  }

  /// Writes E as a `Surface_mesh` (`Extended_surface_writer`), then its
  /// statistics. With `validate`, checks that E is a valid polygon mesh
  /// (else only in debug builds: the growth checks the E it ends with).
  template <class Point>
  void materialize(Extended_surface<Point>& E, const Geodesic_source<TriangleMesh>& src, bool validate = true)
  {
    Extended_surface_writer<TriangleMesh, Extended_surface_builder>(*this).write(E, src, validate);
    stats_.number_of_faces = E.mesh.number_of_faces();
    stats_.number_of_vertices = E.mesh.number_of_vertices();
    E.statistics = stats_;
  }

  /// Throws `Algorithm_error` unless E is a valid polygon mesh.
  template <class Point>
  static void check_valid(const Extended_surface<Point>& E)
  {
    if(!CGAL::is_valid_polygon_mesh(E.mesh))
      throw Algorithm_error("the extended surface is not a valid polygon mesh");
  }

  const Extended_surface_statistics& statistics() const { return stats_; }
  /// per face of M and edge k: the face across it and that edge's index there
  const Faces_across& faces_across_edges() const { return across_; }
  std::size_t number_of_copies() const { return copies_.size(); }

private:
  // Per face: its corners, the face and edge across each edge, whether that
  // edge is cut; per vertex its degree (faces around it) and whether it is on
  // the border.
  void index_faces(const Rough_cut_locus<TriangleMesh>& rcl, typename Maps::Edge_index_map eim)
  {
    const Faces_by_index<TriangleMesh, typename Maps::Vertex_point_map> faces(tm_, maps_.vpm, maps_.fim);
    const std::size_t nv = num_vertices(tm_), nf = num_faces(tm_);
    corner_.resize(nf);
    across_ = faces_across(tm_, maps_.fim);
    edge_cut_.resize(nf);
    vertex_of_.resize(nv);
    for(vertex_descriptor v : vertices(tm_)) vertex_of_[get(maps_.vim, v)] = v;
    degree_.assign(nv, 0);
    for(std::uint32_t f = 0; f < nf; ++f)
    {
      const auto h = faces.corner_halfedges(f);
      for(int k = 0; k < 3; ++k)
      {
        corner_[f][k] = static_cast<std::uint32_t>(get(maps_.vim, source(h[k], tm_)));
        ++degree_[corner_[f][k]];
        edge_cut_[f][k] = rcl.is_cut_edge[get(eim, edge(h[k], tm_))] != 0;
      }
    }
    border_vertex_.assign(nv, 0);
    for(std::uint32_t f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
        if(on_border(f, k)) border_vertex_[corner_[f][k]] = border_vertex_[corner_[f][(k + 1) % 3]] = 1;
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
        if(edge_cut_[f][k] || on_border(f, k)) c.nb[k] = none;
        else { c.nb[k] = face_across(f, k); c.nb_edge[k] = static_cast<std::uint8_t>(across_[f][k].second); }
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
    while(!ends_sector(g, (kg + 2) % 3) && steps < degree_[v])
    {
      const std::uint32_t p = face_across(g, (kg + 2) % 3);
      kg = position_of(p, v);
      g = p;
      ++steps;
    }
    const bool closed = (steps == degree_[v]) && !ends_sector(g, (kg + 2) % 3);
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
      if(fan.size == degree_[v] || ends_sector(h, kh)) break;
      const std::uint32_t n = face_across(h, kh);
      kh = position_of(n, v);
      h = n;
    }
    fan.closed = closed;
    // one sector holding the whole star: a leaf of K (on the border: the whole path)
    fan.leaf = !closed && fan.size == degree_[v] && !fan.border;
    if(fan.leaf) ++stats_.number_of_leaf_vertices;
  }

  // the face of M across edge k of face f
  std::uint32_t face_across(std::uint32_t f, int k) const { return static_cast<std::uint32_t>(across_[f][k].first); }
  // edge k of face f is on the border of M: E never grows across it
  bool on_border(std::uint32_t f, int k) const { return across_[f][k].first == no_face_across; }
  // a sector of D ends at a cut edge or at the border
  bool ends_sector(std::uint32_t f, int k) const { return edge_cut_[f][k] || on_border(f, k); }

  int position_of(std::uint32_t f, std::uint32_t v) const
  {
    return corner_[f][0] == v ? 0 : (corner_[f][1] == v ? 1 : 2);
  }
  int position_of_copy(std::uint32_t c, std::uint32_t root) const
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
    fans_.push_back(Fan{v, first, first, 1, false, false, border_vertex_[v] != 0});
    return id;
  }
  std::uint32_t limit(const Fan& f) const { return f.leaf ? leaf_winding_stars * degree_[f.vertex] : degree_[f.vertex]; }

  std::uint32_t add_copy_across(std::uint32_t c, int k, int r)
  {
    const std::uint32_t f = copies_[c].face;
    const std::uint32_t g = face_across(f, k);
    const int kg = across_[f][k].second;
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
    close_if_complete(xu);
    close_if_complete(find(xw));
    return n;
  }

  void close_if_complete(std::uint32_t x0)
  {
    std::vector<std::uint32_t> pending{x0};
    while(!pending.empty())
    {
      const std::uint32_t x = find(pending.back());
      pending.pop_back();
      const Fan fx = fans_[x];
      if(fx.closed || fx.leaf || fx.border || fx.size != degree_[fx.vertex]) continue;
      // The end faces L (last) and F (first) hold the two copies of one edge (v, z).
      const std::uint32_t L = fx.last, F = fx.first;
      const int kL = position_of_copy(L, x), kF = position_of_copy(F, x);
      const int eL = kL, eF = (kF + 2) % 3; // L's next edge at v, F's prev edge at v
      if(copies_[L].nb[eL] != none || copies_[F].nb[eF] != none ||
         face_across(copies_[L].face, eL) != copies_[F].face)
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
        if(fz.leaf || fz.closed || fz.border || fz.first != L || fz.last != F || fz.size != degree_[fz.vertex])
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
  const Maps maps_;
  std::vector<vertex_descriptor> vertex_of_;
  std::vector<std::array<std::uint32_t, 3> > corner_;
  Faces_across across_;
  std::vector<std::array<bool, 3> > edge_cut_;
  std::vector<std::uint32_t> degree_;
  std::vector<char> border_vertex_; // per vertex of M
  std::vector<Copy> copies_;
  Union_find vertex_copies_; // vertex copies merged by closing fans
  std::vector<Fan> fans_;
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
  if(rings < 0) throw Invalid_parameter_error("the number of extension rings must be non-negative");
  typedef internal::Mesh_maps_of<TriangleMesh, NamedParameters> Maps;
  internal::Extended_surface_builder<TriangleMesh, Maps> builder(tm, rcl, internal::mesh_maps(tm, np));
  for(int r = 0; r < rings; ++r) builder.grow_ring();
  Extended_surface<typename Maps::Point> E;
  builder.materialize(E, rcl.source);
  return E;
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_EXTENDED_SURFACE_H
