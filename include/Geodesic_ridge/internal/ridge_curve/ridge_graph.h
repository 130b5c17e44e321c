// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3's shared state, `Ridge_graph`: what every pass of the ridge curve
// (`assemble_ridge_curve.h` lists them) reads and writes.
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_RIDGE_GRAPH_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_RIDGE_GRAPH_H

#include <Geodesic_ridge/extended_surface.h>
#include <Geodesic_ridge/internal/border_loops.h>
#include <Geodesic_ridge/internal/coincident_points.h>
#include <Geodesic_ridge/internal/face_copies.h>
#include <Geodesic_ridge/internal/faces_by_index.h>
#include <Geodesic_ridge/internal/field_gradients.h>
#include <Geodesic_ridge/internal/tuning.h>
#include <Geodesic_ridge/internal/union_find.h>
#include <Geodesic_ridge/lower_envelope.h>
#include <Geodesic_ridge/ridge_curve.h>
#include <Geodesic_ridge/solvers/Face_cone.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

typedef CGAL::Gmpq Exact_number;

// The solver's cones: S per copy of E at the S `samples` (a copy whose cones
// were not read has no apex), and per copy split at a kink the cones of its
// fronts in the order of its fields (`Kink_splitter`).
struct Copy_cones
{
  const std::vector<Face_cone>* per_copy;
  const std::map<std::size_t, std::vector<Face_cone> >* split_fronts;
  const std::vector<std::array<double, 3> >* samples;
};

// The state stage 3's passes share (`assemble_ridge_curve()` runs them in
// order): per face of M the lower envelope of its copies and its cells (one
// per surviving copy), which cells are one front, the ridge's nodes (one per
// surface point: exact keys, and coincident points merged) and its segments,
// the border's loops; and the lookups every pass uses.
template <class TriangleMesh, class Maps>
struct Ridge_graph
{
  typedef typename Maps::Point Point;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef Exact_number Q;
  static constexpr std::size_t none = std::size_t(-1);

  // a cell: its copy, its linear field and the field's gradient (in the face's plane)
  // (entry: its index among the face's copies, as in `Face_copies`)
  struct Cell { std::size_t copy; std::array<double, 3> field, gradient; bool split; std::size_t entry; };
  struct Segment { std::size_t a, b, left, right; double strength; double angle; bool ridge; };
  // an interval of an edge (t along it) and the cell that wins there on one side
  struct Interval { Q lo, hi; std::size_t cell; };
  // nodes, keyed exactly: (0, vertex) | (1, edge, t along the edge) | (2, face, λ1, λ2)
  typedef std::tuple<int, std::size_t, Q, Q> Key;

  // A piece [ta, tb] of edge k1 of f1 (t from corner k1 to k1 + 1) between the
  // cell boundaries of both sides, with the cells on either side.
  struct Edge_piece { Q ta, tb; std::size_t c1, c2; Gradient_jump jump; };
  // the boundaries between cells as a graph: per node, the links at it (`Link_paths`)
  struct Link_graph { std::vector<Segment> links; std::vector<std::vector<std::size_t> > at; };

  Ridge_graph(const TriangleMesh& tm, const Extended_surface<Point>& E, const std::vector<Face_copies>& face_copies,
              double mean_edge, double minimum_angle, double kink_angle, const Maps& maps,
              const std::vector<double>& angle_sum, std::vector<std::vector<Ridge_region_cell> >& regions,
              Ridge_curve_statistics& statistics, const Copy_cones* cones)
    : tm(tm), maps(maps), E(E), face_copies(face_copies), mean_edge(mean_edge), minimum_angle(minimum_angle),
      kink_angle(kink_angle), angle_sum(angle_sum), regions(regions), statistics(statistics),
      faces(tm, maps.vpm, maps.fim), nf(num_faces(tm)),
      same_front_tolerance(tuning::ridge::same_front * mean_edge), cones(cones), thin(nf, 0),
      coincident(coincident_tolerance(tm, maps.vpm))
  {}


  // equal fields within the tolerance are one front (solver noise)
  bool same_field(const std::array<double, 3>& a, const std::array<double, 3>& b) const
  {
    return std::abs(a[0] - b[0]) <= same_front_tolerance && std::abs(a[1] - b[1]) <= same_front_tolerance &&
           std::abs(a[2] - b[2]) <= same_front_tolerance;
  }

  // are the copies of cells c1 and c2 glued in E across edge k1 of c1's face (one sheet)?
  bool glued_across(std::size_t c1, int k1, std::size_t c2) const
  {
    typedef typename Extended_surface<Point>::Mesh Mesh;
    const Mesh& em = E.mesh;
    auto eh = em.halfedge(typename Mesh::Face_index(static_cast<typename Mesh::size_type>(cells[c1].copy)));
    for(int j = 0; j < k1; ++j) eh = em.next(eh);
    const auto eo = em.opposite(eh);
    return !em.is_border(eo) && std::size_t(em.face(eo)) == cells[c2].copy;
  }

  std::size_t cell_of(std::size_t f, std::size_t local_copy) const
  {
    for(std::size_t i = 0; i < envelope_of[f]->cells.size(); ++i)
      if(envelope_of[f]->cells[i].copy == local_copy) return first_cell[f] + i;
    return none;
  }

  // The node of a point: one per surface point. A point within the
  // coincidence tolerance of a node (the same point computed from another
  // face, or an envelope edge that ends 1e-12 from a vertex) is that node; the
  // node then takes the point's location if it is on a lower feature (a
  // vertex, then an edge), so that nodes at vertices are exactly there.
  std::size_t add_node(const Key& key, std::size_t f, const std::array<Q, 3>& lambda, std::size_t loop = none)
  {
    auto it = node_of.find(key);
    if(it != node_of.end()) return it->second;
    Ridge_point<Point> p;
    p.face = f;
    p.barycentric = {{CGAL::to_double(lambda[0]), CGAL::to_double(lambda[1]), CGAL::to_double(lambda[2])}};
    const auto cp = faces.corner_points(f);
    p.point = barycentric_to_point(lambda, cp[0], cp[1], cp[2]);
    const std::array<double, 3> xyz = {{CGAL::to_double(p.point.x()), CGAL::to_double(p.point.y()),
                                        CGAL::to_double(p.point.z())}};
    // (a key's kind is the dimension of the feature it lies on: 0 vertex, 1 edge, 2 face)
    const int feature = std::get<0>(key);
    const std::size_t same = coincident.find(xyz, [&](std::size_t n) { return faces_share_a_vertex(nodes[n].face, f); });
    if(same != Coincident_points::none)
    {
      if(feature < node_feature[same])
      {
        nodes[same] = p;
        node_feature[same] = feature;
        coincident.insert(same, xyz);
      }
      if(node_loop[same] == none) node_loop[same] = loop;
      ++statistics.coincident_points;
      node_of.emplace(key, same);
      return same;
    }
    node_loop.push_back(loop);
    node_feature.push_back(feature);
    nodes.push_back(p);
    coincident.insert(nodes.size() - 1, xyz);
    node_of.emplace(key, nodes.size() - 1);
    return nodes.size() - 1;
  }
  // (points of two sheets of a surface that touches itself may coincide in space)
  bool faces_share_a_vertex(std::size_t f, std::size_t g) const
  {
    if(f == g) return true;
    const auto hf = faces.corner_halfedges(f), hg = faces.corner_halfedges(g);
    for(const auto& a : hf)
      for(const auto& b : hg)
        if(source(a, tm) == source(b, tm)) return true;
    return false;
  }

  // The loops of the border of M (b of them): per vertex its loop, or none
  // inside. K ∪ ∂M, and so the ridge with the border, is one connected graph;
  // each loop counts as one node of it (`loop_node`), joined to the ridge
  // nodes on it.
  void label_border_loops()
  {
    Border_loops b = border_loops(tm, maps.vim);
    loop_of_vertex = std::move(b.loop_of_vertex);
    number_of_loops = b.number_of_loops;
  }
  std::size_t loop_node(std::size_t loop) const { return nodes.size() + loop; }
  // `uf`, over the ridge nodes and then the loops: the nodes on a loop joined to it
  void join_border_nodes(Union_find& uf) const
  {
    for(std::size_t v = 0; v < nodes.size(); ++v)
      if(node_loop[v] != none) uf.unite(v, loop_node(node_loop[v]));
  }

  // a point of face f given by exact barycentric coordinates: normalized to its feature
  std::size_t node_at(std::size_t f, const std::array<Q, 3>& lambda)
  {
    const auto h = faces.corner_halfedges(f);
    int zeros = 0, nz = -1;
    for(int k = 0; k < 3; ++k) { if(CGAL::is_zero(lambda[k])) ++zeros; else nz = k; }
    if(zeros == 2)
    {
      const std::size_t v = get(maps.vim, source(h[nz], tm));
      return add_node(Key(0, v, Q(0), Q(0)), f, lambda, loop_of_vertex[v]);
    }
    for(int k = 0; k < 3; ++k)
      if(CGAL::is_zero(lambda[(k + 2) % 3])) // on edge k, from corner k to corner k+1
      {
        // t runs from the endpoint of smaller vertex index (an edge descriptor may
        // remember the halfedge it was made from, so halfedge(e) is no orientation)
        const bool forward = get(maps.vim, source(h[k], tm)) < get(maps.vim, target(h[k], tm));
        const Q t = forward ? lambda[(k + 1) % 3] : lambda[k];
        const std::size_t loop =
            is_border(edge(h[k], tm), tm) ? loop_of_vertex[get(maps.vim, source(h[k], tm))] : none;
        return add_node(Key(1, get(maps.eim, edge(h[k], tm)), t, Q(0)), f, lambda, loop);
      }
    return add_node(Key(2, f, lambda[1], lambda[2]), f, lambda);
  }

  // the jump between the linear fields of two cells of one face
  static Gradient_jump gradient_jump_in_face(const Cell& a, const Cell& b)
  {
    return jump_between(a.gradient, b.gradient);
  }

  // the jump between two gradients of one face
  static Gradient_jump jump_between(const std::array<double, 3>& ga, const std::array<double, 3>& gb)
  {
    typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
    const Vector va(ga[0], ga[1], ga[2]), vb(gb[0], gb[1], gb[2]);
    const double strength = std::sqrt(CGAL::to_double((va - vb).squared_length()));
    const double angle =
        (va == CGAL::NULL_VECTOR || vb == CGAL::NULL_VECTOR) ? 0.0 : CGAL::to_double(CGAL::approximate_angle(va, vb));
    return Gradient_jump{strength, angle};
  }

  // the jump of the gradient across edge k1 of face f1 (edge k2 of f2) between
  // cells c1 and c2
  // None at the source: the distance is a cone there, and the kinks of its
  // linear interpolation across the edges at the source vertex, or of the
  // source's face, are no fronts meeting.
  Gradient_jump edge_jump(std::size_t f1, int k1, std::size_t c1, std::size_t f2, int k2, std::size_t c2) const
  {
    if(at_source(f1, k1) || at_source(f2, k2)) return Gradient_jump{0, 0};
    const auto cp1 = faces.corner_points(f1), cp2 = faces.corner_points(f2);
    return gradient_jump_across_edge(cp1[k1], cp1[(k1 + 1) % 3], cp1[(k1 + 2) % 3], cp2[(k2 + 2) % 3],
                                     cells[c1].gradient, cells[c2].gradient);
  }

  // edge k of face f: an edge of the source's face, or at the source vertex
  bool at_source(std::size_t f, int k) const
  {
    if(!E.source_is_vertex) return f == std::size_t(E.source_location.first);
    const std::size_t s = E.original_vertex[E.source_vertex];
    const auto h = faces.corner_halfedges(f);
    return std::size_t(get(maps.vim, source(h[k], tm))) == s || std::size_t(get(maps.vim, target(h[k], tm))) == s;
  }

  // the intervals of edge k of face f (t from corner k to k + 1, or back if
  // `reversed`) and the cell that wins on each, by increasing t
  std::vector<Interval> edge_intervals(std::size_t f, int k, bool reversed) const
  {
    std::vector<Interval> out;
    for(std::size_t i = 0; i < envelope_of[f]->cells.size(); ++i)
    {
      const auto& c = envelope_of[f]->cells[i];
      const std::size_t n = c.polygon.size();
      for(std::size_t j = 0; j < n; ++j)
        if(is_triangle_edge_label(c.edge_label[j]) && triangle_edge_of_label(c.edge_label[j]) == k)
        {
          Q ta = c.polygon[j][(k + 1) % 3], tb = c.polygon[(j + 1) % n][(k + 1) % 3];
          if(reversed) { ta = Q(1) - ta; tb = Q(1) - tb; }
          if(tb < ta) std::swap(ta, tb);
          if(ta < tb) out.push_back(Interval{ta, tb, first_cell[f] + i});
        }
    }
    std::sort(out.begin(), out.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
    return out;
  }

  static std::size_t cell_at(const std::vector<Interval>& side, const Q& t)
  {
    for(const auto& iv : side) if(iv.lo <= t && t <= iv.hi) return iv.cell;
    return none;
  }

  // The pieces of edge k1 of f1 (k2 of f2).
  std::vector<Edge_piece> edge_pieces(std::size_t f1, int k1, std::size_t f2, int k2) const
  {
    const std::vector<Interval> side1 = edge_intervals(f1, k1, false), side2 = edge_intervals(f2, k2, true);
    std::vector<Q> cuts;
    for(const auto* side : {&side1, &side2})
      for(const auto& i : *side) { cuts.push_back(i.lo); cuts.push_back(i.hi); }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    std::vector<Edge_piece> out;
    for(std::size_t i = 0; i + 1 < cuts.size(); ++i)
    {
      const Q mid = (cuts[i] + cuts[i + 1]) / 2;
      const std::size_t c1 = cell_at(side1, mid), c2 = cell_at(side2, mid);
      if(c1 != none && c2 != none)
        out.push_back(Edge_piece{cuts[i], cuts[i + 1], c1, c2, edge_jump(f1, k1, c1, f2, k2, c2)});
    }
    return out;
  }

  // the nodes at the ends of piece p of edge k1 of f1
  std::pair<std::size_t, std::size_t> piece_nodes(std::size_t f1, int k1, const Edge_piece& p)
  {
    std::array<Q, 3> la = {{Q(0), Q(0), Q(0)}}, lb = la;
    la[k1] = Q(1) - p.ta; la[(k1 + 1) % 3] = p.ta;
    lb[k1] = Q(1) - p.tb; lb[(k1 + 1) % 3] = p.tb;
    return {node_at(f1, la), node_at(f1, lb)};
  }

  double length(const Segment& s) const
  {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(nodes[s.a].point, nodes[s.b].point)));
  }

  // the input
  const TriangleMesh& tm;
  const Maps maps;
  const Extended_surface<Point>& E;
  const std::vector<Face_copies>& face_copies;
  const double mean_edge, minimum_angle, kink_angle;
  const std::vector<double>& angle_sum; // per vertex of M (by index): the sum of its corner angles
  std::vector<std::vector<Ridge_region_cell> >& regions;
  Ridge_curve_statistics& statistics;
  const Faces_by_index<TriangleMesh, typename Maps::Vertex_point_map> faces;
  const std::size_t nf;
  const double same_front_tolerance;
  const Copy_cones* cones; // the solver's cones, if read (else the linear fields' jumps)
  std::vector<char> thin; // per face of M: thin (none until thin_faces() marks them)
  // per face: its envelope, either the shared whole-triangle one or one of
  // `computed_envelopes` (a deque: pointers into it stay valid as it grows)
  Lower_envelope<Q> whole_triangle;
  std::deque<Lower_envelope<Q> > computed_envelopes;
  std::vector<const Lower_envelope<Q>*> envelope_of;
  std::vector<Cell> cells;
  std::vector<std::size_t> first_cell; // per face, then the number of cells
  std::map<Key, std::size_t> node_of;
  std::vector<Ridge_point<Point> > nodes;
  std::vector<Segment> segments;
  std::optional<Link_graph> links; // the boundaries between cells, once needed
  Union_find fronts; // cells that are one front
  // the border: per vertex of M its loop (or none), per node its loop (or none)
  std::vector<std::size_t> loop_of_vertex, node_loop;
  std::size_t number_of_loops = 0;
  // one node per surface point: the nodes' points, and per node the
  // dimension of the feature its location is on (0 vertex, 1 edge, 2 face)
  Coincident_points coincident;
  std::vector<int> node_feature;
};

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_RIDGE_GRAPH_H
