// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The map between a mesh read from a file (triangulated, perhaps repaired)
// and the file's own vertex and face indices, both ways, for vertices and for
// surface points.
#ifndef GEODESIC_RIDGE_FILE_INDEX_MAP_H
#define GEODESIC_RIDGE_FILE_INDEX_MAP_H

#include <Geodesic_ridge/connected_component.h>
#include <Geodesic_ridge/repair.h>
#include <Geodesic_ridge/internal/normalization.h>

#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// vertices(tm) and faces(tm), where the names are the map's member functions
template <class Graph>
auto vertices_of(const Graph& g) { return vertices(g); }
template <class Graph>
auto faces_of(const Graph& g) { return faces(g); }

} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
/// A point of a face of a mesh file, in the file's terms: the file face and
/// one coordinate per vertex of that face, in the file order of its vertices.
/// For a triangle these are the barycentric coordinates; for a polygon, which
/// was triangulated, they are the barycentric coordinates of the point in the
/// triangle of the polygon that holds it, the polygon's other vertices having
/// coordinate 0. In both cases the point is the sum of the coordinates times
/// the vertices' positions.
struct File_face_location
{
  /// the file face
  std::size_t face = 0;
  /// one coordinate per vertex of the file face, in file order
  std::vector<double> coordinates;
};

/// \ingroup PkgGeodesicRidgeRef
///
/// \brief The map between a triangle mesh read from a file by
/// `IO::read_triangle_mesh()` and the file's vertex and face indices.
///
/// The mesh may differ from the file: polygons are triangulated, and with
/// `parameters::repair(true)` the mesh is repaired (`repair_mesh()`): vertices
/// merged, split or removed, faces removed or reoriented. This map answers,
/// both ways, which file vertex and file face a mesh vertex and a mesh face
/// come from, and converts surface points: a file face with a point on it
/// (what a user gives) to a `Face_location` of the mesh, and a `Face_location`
/// (what the algorithm gives) to a `File_face_location`.
///
/// The mesh must be the one the reader built, unchanged, or the component of
/// it that `extract_connected_component()` copied, with the map that
/// `restricted_to_component()` makes: the map refers to the mesh's vertices
/// and faces by descriptor, and to their indices through its initialized
/// vertex and face index maps (for a `CGAL::Surface_mesh`, the order in
/// which they were added).
///
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal
///         `CGAL::vertex_point` property map
template <class TriangleMesh>
class File_index_map
{
public:
  /// the point type of the file's vertices as the map keeps them
  typedef internal::repair::Epick::Point_3 Point_3;
  /// "no such index"
  static constexpr std::size_t no_index = internal::repair::no_index;
  /// the graph traits of `TriangleMesh`
  typedef boost::graph_traits<TriangleMesh> GT;
  /// a vertex of the mesh
  typedef typename GT::vertex_descriptor vertex_descriptor;
  /// a face of the mesh
  typedef typename GT::face_descriptor face_descriptor;
  /// a point of a face of the mesh: \cgal's `Polygon_mesh_processing::Face_location`
  /// (barycentric coordinates in the order `source(halfedge(f))`,
  /// `target(halfedge(f))`, `target(next(halfedge(f)))`)
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;

  /// an empty map
  File_index_map() = default;

  /// The map of a mesh made from `soup`, whose vertex `i` is `vertices[i]` and
  /// face `j` is `faces[j]`; `file_points` and `file_faces` are the file's
  /// soup. (`IO::read_triangle_mesh()` makes it.)
  template <class FilePoint, class SoupPoint>
  File_index_map(const std::vector<FilePoint>& file_points, std::vector<std::vector<std::size_t>> file_faces,
                 const Repaired_soup<SoupPoint>& soup, std::vector<vertex_descriptor> vertices,
                 std::vector<face_descriptor> faces)
    : file_faces_(std::move(file_faces)), vertex_to_file_(soup.vertex_to_file), face_to_file_(soup.face_to_file),
      merged_into_(soup.file_vertex_merged_into), vertices_(std::move(vertices)), faces_(std::move(faces)),
      statistics_(soup.statistics)
  {
    file_points_.reserve(file_points.size());
    for(const FilePoint& p : file_points)
      file_points_.push_back(internal::validation::to_epick(p));
    bucket(vertex_to_file_, file_points_.size(), vertex_begin_, vertex_order_);
    bucket(face_to_file_, file_faces_.size(), face_begin_, face_order_);
  }

  /// The map of `component`, the connected component of `tm` that
  /// `extract_connected_component()` copied (`cc` is its map), where this is
  /// the map of `tm`: the file's vertices and faces are those of `component`,
  /// and the ones in the other components of `tm` have none
  /// (`in_other_component()`, `vertex_in_other_component()`).
  File_index_map restricted_to_component(const Connected_component_map<TriangleMesh>& cc, const TriangleMesh& tm,
                                         const TriangleMesh& component) const
  {
    File_index_map r;
    r.file_points_ = file_points_;
    r.file_faces_ = file_faces_;
    r.merged_into_ = merged_into_;
    r.statistics_ = statistics_;
    // the component's element i (by its index map): its descriptor and its
    // file index, through the element of tm it was copied from
    auto number = [](const auto& elements, const auto& index_map, std::size_t n, auto file_index,
                     std::vector<std::size_t>& to_file, auto& descriptors) {
      to_file.resize(n);
      descriptors.resize(n);
      for(const auto& x : elements)
      {
        const std::size_t i = static_cast<std::size_t>(get(index_map, x));
        to_file[i] = file_index(x);
        descriptors[i] = x;
      }
    };
    number(internal::vertices_of(component), CGAL::get_initialized_vertex_index_map(component),
           num_vertices(component), [&](vertex_descriptor v) { return file_vertex(cc.mesh_vertex(v), tm); },
           r.vertex_to_file_, r.vertices_);
    number(internal::faces_of(component), CGAL::get_initialized_face_index_map(component), num_faces(component),
           [&](face_descriptor f) { return file_face(cc.mesh_face(f), tm); }, r.face_to_file_, r.faces_);
    bucket(r.vertex_to_file_, file_points_.size(), r.vertex_begin_, r.vertex_order_);
    bucket(r.face_to_file_, file_faces_.size(), r.face_begin_, r.face_order_);
    r.face_elsewhere_.assign(file_faces_.size(), false);
    for(std::size_t j = 0; j < file_faces_.size(); ++j)
      r.face_elsewhere_[j] = r.faces(j).empty() && (!faces(j).empty() || face_elsewhere(j));
    r.vertex_elsewhere_.assign(file_points_.size(), false);
    for(std::size_t i = 0; i < file_points_.size(); ++i)
      r.vertex_elsewhere_[i] = r.vertices(i).empty() && (!vertices(i).empty() || vertex_elsewhere(i));
    return r;
  }

  /// whether file face `file_face` is in a connected component that the
  /// mesh leaves out (`restricted_to_component()`): it has no mesh face,
  /// and a point on it is unreachable from a source in the mesh
  bool in_other_component(std::size_t file_face) const { return face_elsewhere(file_face); }

  /// whether file vertex `file_vertex` is in a connected component that the
  /// mesh leaves out (`restricted_to_component()`)
  bool vertex_in_other_component(std::size_t file_vertex) const { return vertex_elsewhere(file_vertex); }

  /// what the triangulation and the repair changed
  const Repair_statistics& statistics() const { return statistics_; }
  /// the number of vertices of the file
  std::size_t number_of_file_vertices() const { return file_points_.size(); }
  /// the number of faces of the file
  std::size_t number_of_file_faces() const { return file_faces_.size(); }
  /// the vertices of file face `file_face` (file indices, file order)
  const std::vector<std::size_t>& file_face_vertices(std::size_t file_face) const { return file_faces_[file_face]; }

  /// the file vertex of mesh vertex `v` (for a vertex that merged several file
  /// vertices, the first; for a copy made by a split, the vertex copied)
  std::size_t file_vertex(vertex_descriptor v, const TriangleMesh& tm) const
  {
    return vertex_to_file_[static_cast<std::size_t>(get(CGAL::get_initialized_vertex_index_map(tm), v))];
  }

  /// the file face of mesh face `f` (for a triangle of a polygon, the polygon)
  std::size_t file_face(face_descriptor f, const TriangleMesh& tm) const
  {
    return face_to_file_[static_cast<std::size_t>(get(CGAL::get_initialized_face_index_map(tm), f))];
  }

  /// the mesh vertices of file vertex `file_vertex`: one, several if the
  /// repair split it, none if it removed it
  std::vector<vertex_descriptor> vertices(std::size_t file_vertex) const
  {
    std::vector<vertex_descriptor> result;
    const std::size_t key = merged_into_.empty() ? file_vertex : merged_into_[file_vertex];
    for(std::size_t i = vertex_begin_[key]; i < vertex_begin_[key + 1]; ++i)
      result.push_back(vertices_[vertex_order_[i]]);
    return result;
  }

  /// the mesh faces of file face `file_face`: one for a triangle, several for
  /// a polygon, none if the repair removed it
  std::vector<face_descriptor> faces(std::size_t file_face) const
  {
    std::vector<face_descriptor> result;
    for(std::size_t i = face_begin_[file_face]; i < face_begin_[file_face + 1]; ++i)
      result.push_back(faces_[face_order_[i]]);
    return result;
  }

  /// The mesh vertex that stands for file vertex `file_vertex`: its only
  /// vertex, or, if the repair split it, the copy with the largest incident
  /// area; none if the repair removed it.
  std::optional<vertex_descriptor> vertex(std::size_t file_vertex, const TriangleMesh& tm) const
  {
    std::optional<vertex_descriptor> best;
    double best_area = -1;
    // the areas on the copies' faces moved to a unit size (at 1e160 an area
    // is not a double)
    const auto vpm = get(CGAL::vertex_point, tm);
    internal::Normalization_of_points around;
    for(vertex_descriptor v : vertices(file_vertex))
      for(vertex_descriptor w : CGAL::vertices_around_target(halfedge(v, tm), tm)) around.add(get(vpm, w));
    const internal::Normalized_point_map<std::decay_t<decltype(vpm)> > unit_vpm{vpm, around.normalization()};
    for(vertex_descriptor v : vertices(file_vertex))
    {
      double area = 0;
      for(face_descriptor f : CGAL::faces_around_target(halfedge(v, tm), tm))
        if(f != GT::null_face())
          area += CGAL::to_double(
              CGAL::Polygon_mesh_processing::face_area(f, tm, CGAL::parameters::vertex_point_map(unit_vpm)));
      if(area > best_area)
      {
        best_area = area;
        best = v;
      }
    }
    return best;
  }

  /// The mesh location of the point `p` of file face `file_face`: among the
  /// mesh faces of the file face (the triangles of a polygon), the one whose
  /// smallest barycentric coordinate of `p` is the largest (and if `p` is
  /// outside all of them, among their neighbours too). The coordinates are
  /// those of `p`'s projection on the face's plane, as
  /// `CGAL::Polygon_mesh_processing::locate_in_face()` gives them: a caller
  /// checks that `p` is on the face. None if the repair removed the face.
  std::optional<Face_location> locate(std::size_t file_face, const Point_3& p, const TriangleMesh& tm) const
  {
    std::vector<face_descriptor> candidates = faces(file_face);
    std::optional<Face_location> best = best_location(candidates, p, tm);
    if(!best || smallest(best->second) >= 0)
      return best;
    for(face_descriptor f : faces(file_face)) // beyond the file face: after a degenerate face was repaired
      for(face_descriptor g : CGAL::faces_around_face(halfedge(f, tm), tm))
        if(g != GT::null_face())
          candidates.push_back(g);
    return best_location(candidates, p, tm);
  }

  /// The mesh location of the point with coordinates `coordinates` (one per
  /// vertex of the file face, in file order, as in `File_face_location`). For
  /// a file face that is one mesh face with the same vertices, the
  /// coordinates are only reordered (no rounding); otherwise the point is
  /// constructed and located with `locate()`.
  std::optional<Face_location> location(std::size_t file_face, const std::vector<double>& coordinates,
                                        const TriangleMesh& tm) const
  {
    const std::vector<face_descriptor> fs = faces(file_face);
    if(fs.size() == 1 && file_faces_[file_face].size() == 3)
    {
      const std::array<std::size_t, 3> k = corners_in_file_face(fs[0], file_face, tm);
      if(k[0] != no_index && k[1] != no_index && k[2] != no_index)
        return Face_location(fs[0], {{coordinates[k[0]], coordinates[k[1]], coordinates[k[2]]}});
    }
    double x = 0, y = 0, z = 0;
    for(std::size_t i = 0; i < coordinates.size(); ++i)
    {
      const Point_3& q = file_points_[file_faces_[file_face][i]];
      x += coordinates[i] * q.x();
      y += coordinates[i] * q.y();
      z += coordinates[i] * q.z();
    }
    return locate(file_face, Point_3(x, y, z), tm);
  }

  /// The file face and coordinates of the mesh location `loc`. When the mesh
  /// face's vertices are vertices of its file face (always, unless a
  /// degenerate face was repaired next to it), the coordinates are only moved
  /// to the file face's order (no rounding); otherwise they are those of the
  /// point in the triangle of the file face that holds it.
  File_face_location file_location(const Face_location& loc, const TriangleMesh& tm) const
  {
    File_face_location result;
    result.face = file_face(loc.first, tm);
    const std::vector<std::size_t>& corners = file_faces_[result.face];
    result.coordinates.assign(corners.size(), 0.);
    const std::array<std::size_t, 3> k = corners_in_file_face(loc.first, result.face, tm);
    if(k[0] != no_index && k[1] != no_index && k[2] != no_index)
    {
      for(int i = 0; i < 3; ++i)
        result.coordinates[k[i]] += loc.second[i];
      return result;
    }
    const auto p = CGAL::Polygon_mesh_processing::construct_point(loc, tm);
    place_in_file_face(internal::validation::to_epick(p), result);
    return result;
  }

private:
  // Items 0..n-1 with keys in [0, n_keys), grouped by key.
  static void bucket(const std::vector<std::size_t>& key, std::size_t n_keys, std::vector<std::size_t>& begin,
                     std::vector<std::size_t>& order)
  {
    order = internal::validation::bucket_sort(key.size(), n_keys, [&](std::size_t i) { return key[i]; }, begin);
  }

  bool face_elsewhere(std::size_t j) const { return j < face_elsewhere_.size() && face_elsewhere_[j]; }
  bool vertex_elsewhere(std::size_t i) const { return i < vertex_elsewhere_.size() && vertex_elsewhere_[i]; }

  static double smallest(const std::array<double, 3>& b) { return (std::min)({b[0], b[1], b[2]}); }

  std::optional<Face_location> best_location(const std::vector<face_descriptor>& candidates, const Point_3& p,
                                             const TriangleMesh& tm) const
  {
    using Mesh_point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
    std::optional<Face_location> best;
    const auto vpm = get(CGAL::vertex_point, tm);
    // located among the candidates moved to a unit size (at 1e-160 a squared
    // length is 0): the same coordinates at any scale. The size is theirs, not
    // p's: a point far away made them a point, "degenerate", and the face
    // "removed by the repair"; now it gets huge (or NaN) coordinates, which
    // the caller refuses.
    internal::Normalization_of_points around;
    for(face_descriptor f : candidates)
      for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm)) around.add(get(vpm, v));
    const internal::Normalization unit = around.normalization();
    const internal::Normalized_point_map<std::decay_t<decltype(vpm)> > unit_vpm{vpm, unit};
    const Mesh_point q = unit.to_unit(Mesh_point(p.x(), p.y(), p.z()));
    for(face_descriptor f : candidates)
    {
      const auto h = halfedge(f, tm);
      if(!internal::repair::has_barycentric_coordinates(get(unit_vpm, source(h, tm)), get(unit_vpm, target(h, tm)),
                                                        get(unit_vpm, target(next(h, tm), tm))))
        continue; // a degenerate face holds no point
      const auto loc =
          CGAL::Polygon_mesh_processing::locate_in_face(q, f, tm, CGAL::parameters::vertex_point_map(unit_vpm));
      const Face_location l(f, {{CGAL::to_double(loc.second[0]), CGAL::to_double(loc.second[1]),
                                 CGAL::to_double(loc.second[2])}});
      if(!best || smallest(l.second) > smallest(best->second))
        best = l;
    }
    return best;
  }

  // For each corner of mesh face f (in CGAL's order), its position in file
  // face `file_face` (no_index if it is none of its vertices).
  std::array<std::size_t, 3> corners_in_file_face(face_descriptor f, std::size_t file_face,
                                                  const TriangleMesh& tm) const
  {
    const auto vpm = get(CGAL::vertex_point, tm);
    const auto h = halfedge(f, tm);
    const std::array<vertex_descriptor, 3> c = {{source(h, tm), target(h, tm), target(next(h, tm), tm)}};
    const std::vector<std::size_t>& corners = file_faces_[file_face];
    std::array<std::size_t, 3> k = {{no_index, no_index, no_index}};
    for(int i = 0; i < 3; ++i)
      for(std::size_t j = 0; j < corners.size(); ++j)
        if(file_points_[corners[j]] == internal::validation::to_epick(get(vpm, c[i])))
          k[i] = j;
    return k;
  }

  // The coordinates of p in the triangle of the file face that holds it (the
  // file face triangulated by the rule of the reading).
  void place_in_file_face(const Point_3& p, File_face_location& result) const
  {
    namespace ir = internal::repair;
    const std::vector<std::size_t>& corners = file_faces_[result.face];
    std::vector<std::vector<std::size_t>> one = {std::vector<std::size_t>(corners.size())};
    std::iota(one[0].begin(), one[0].end(), std::size_t(0));
    std::vector<Point_3> points;
    for(std::size_t c : corners)
      points.push_back(file_points_[c]);
    ir::Soup soup = ir::make_soup(points, one);
    ir::triangulate(points, soup);
    double best = -std::numeric_limits<double>::infinity();
    for(const ir::Tracked_polygon& t : soup.polygons)
    {
      if(t.size() != 3 || !ir::has_barycentric_coordinates(points[t[0]], points[t[1]], points[t[2]]))
        continue;
      const auto b = CGAL::Polygon_mesh_processing::barycentric_coordinates(points[t[0]], points[t[1]],
                                                                            points[t[2]], p);
      if(smallest({{b[0], b[1], b[2]}}) <= best)
        continue;
      best = smallest({{b[0], b[1], b[2]}});
      result.coordinates.assign(corners.size(), 0.);
      for(int i = 0; i < 3; ++i)
        result.coordinates[t[i]] = b[i];
    }
  }

  std::vector<Point_3> file_points_;
  std::vector<std::vector<std::size_t>> file_faces_;
  std::vector<std::size_t> vertex_to_file_, face_to_file_, merged_into_;
  std::vector<vertex_descriptor> vertices_;
  std::vector<face_descriptor> faces_;
  std::vector<std::size_t> vertex_begin_, vertex_order_, face_begin_, face_order_;
  Repair_statistics statistics_;
  // the file faces and vertices in the components a restriction left out
  std::vector<bool> face_elsewhere_, vertex_elsewhere_;
};

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_FILE_INDEX_MAP_H
