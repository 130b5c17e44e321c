// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The region-wise distance field (user manual, "The Region-wise Distance
// Field"): on every face of M, the
// lower envelope of the fields of the copies that survive there. Linear (the
// paper's): the cells of `Ridge_curve::regions`, a query is the smallest of the
// face's cell fields at the point, which is the envelope by definition; a face
// the ridge does not cross has one cell, so its queries cost one dot product.
// Cone (beyond the paper, exact solver): the smallest of the cones of the
// face's copies (`Ridge_curve::cones`), the distance in the face's plane to
// each copy's apex plus its offset.
#ifndef GEODESIC_RIDGE_DISTANCE_FIELD_H
#define GEODESIC_RIDGE_DISTANCE_FIELD_H

#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/cone_ridge.h>
#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/mesh_maps.h>
#include <Geodesic_ridge/internal/normalization.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// The region-wise linear geodesic distance field of one source on a triangle
/// mesh: per face, the lower envelope of the linear fields of the copies that
/// win there (the cells of `Ridge_curve::regions`).
///
/// Built once (O(number of cells)), it owns its data and does not refer to the
/// mesh or the ridge afterwards, except through the index maps it was given.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexIndexMap, FaceIndexMap readable property maps to indices in
///         `[0, num_vertices)`, `[0, num_faces)`: the ones the ridge was
///         computed with
template <class TriangleMesh, class VertexIndexMap, class FaceIndexMap>
class Geodesic_distance_field
{
public:
  /// the graph traits of `TriangleMesh`
  typedef boost::graph_traits<TriangleMesh> GT;
  /// a vertex of the mesh
  typedef typename GT::vertex_descriptor vertex_descriptor;
  /// a face of the mesh
  typedef typename GT::face_descriptor face_descriptor;

  /// The linear field (`make_distance_field()` calls it).
  /// \param regions per face index, the cells of the lower envelope
  ///        (`Ridge_curve::regions`)
  /// \param vertex_distances per vertex index, the distance at the vertex
  ///        (`Ridge_curve::vertex_distances`)
  /// \param vim, fim the vertex and face index maps the ridge was computed with
  /// \pre every face has at least one cell (`Invalid_parameter_error` otherwise).
  Geodesic_distance_field(const std::vector<std::vector<Ridge_region_cell> >& regions,
                          const std::vector<double>& vertex_distances, VertexIndexMap vim, FaceIndexMap fim)
      : vertex_distances_(vertex_distances), vim_(vim), fim_(fim)
  {
    set_cells(regions);
  }

  /// The cone field: per face index, the cones of its copies (`Ridge_curve::cones`)
  /// and the face's corner points (in the order of a `Face_location`).
  /// \pre `cones` and `corners` have one entry per face, and every face has a
  ///      cone (`Invalid_parameter_error` otherwise).
  template <class Point_3>
  Geodesic_distance_field(const std::vector<std::vector<Ridge_region_cell> >& regions,
                          const std::vector<std::vector<Face_cone> >& cones,
                          const std::vector<std::array<Point_3, 3> >& corners,
                          const std::vector<double>& vertex_distances, VertexIndexMap vim, FaceIndexMap fim)
      : vertex_distances_(vertex_distances), vim_(vim), fim_(fim)
  {
    set_cells(regions);
    if(cones.size() != regions.size() || corners.size() != regions.size())
      throw Invalid_parameter_error("the cones are not those of the ridge curve");
    // the cones are evaluated on the unit mesh (internal/normalization.h):
    // their lengths square coordinates
    internal::Normalization_of_points all_corners;
    for(const auto& c : corners)
      for(const Point_3& p : c) all_corners.add(p);
    unit_ = all_corners.normalization();
    first_cone_.push_back(0);
    for(std::size_t f = 0; f < cones.size(); ++f)
    {
      if(cones[f].empty()) throw Invalid_parameter_error("a face has no cone");
      for(Face_cone c : cones[f])
      {
        c.offset = unit_.length_to_unit(c.offset);
        cones_.push_back(c);
      }
      first_cone_.push_back(cones_.size());
      planes_.emplace_back(std::array<Point_3, 3>{
          {unit_.to_unit(corners[f][0]), unit_.to_unit(corners[f][1]), unit_.to_unit(corners[f][2])}});
    }
  }

  /// `Field::cone` or `Field::linear`.
  Field field() const { return cones_.empty() ? Field::linear : Field::cone; }

private:
  void set_cells(const std::vector<std::vector<Ridge_region_cell> >& regions)
  {
    first_cell_.reserve(regions.size() + 1);
    first_cell_.push_back(0);
    for(const auto& cells : regions)
    {
      if(cells.empty()) throw Invalid_parameter_error("a face has no cell: the regions are not those of a ridge curve");
      for(const Ridge_region_cell& c : cells) fields_.push_back(c.field);
      first_cell_.push_back(fields_.size());
    }
  }

public:

  /// The number of faces of the mesh.
  std::size_t number_of_faces() const { return first_cell_.size() - 1; }

  /// The number of cells of the envelope on face `f` (1 where no ridge
  /// crosses it, nor any boundary between fronts).
  std::size_t number_of_cells(face_descriptor f) const
  {
    const std::size_t i = face_index(f);
    return first_cell_[i + 1] - first_cell_[i];
  }

  /// The linear field (distances at the face's three corners, in the order of
  /// a `Face_location`) of cell `c` of face `f`.
  const std::array<double, 3>& cell_field(face_descriptor f, std::size_t c) const
  {
    return fields_[first_cell_[face_index(f)] + c];
  }

  /// The cell of face `loc.first` that holds the point `loc`: the one whose
  /// field is lowest there (an index into `Ridge_curve::regions[f]`, or into
  /// `Ridge_curve::cones[f]` for the cone field). On a boundary between cells,
  /// where their fields agree, the first of them.
  template <class FT>
  std::size_t locate(const std::pair<face_descriptor, std::array<FT, 3> >& loc) const
  {
    const std::size_t f = face_index(loc.first);
    return (cones_.empty() ? lowest(f, barycentric(loc.second)) : lowest_cone(f, barycentric(loc.second))).first;
  }

  /// The distance at the surface point `loc` (a `Face_location`: a face and
  /// barycentric coordinates in CGAL's corner order).
  template <class FT>
  double distance(const std::pair<face_descriptor, std::array<FT, 3> >& loc) const
  {
    const std::size_t f = face_index(loc.first);
    return (cones_.empty() ? lowest(f, barycentric(loc.second)) : lowest_cone(f, barycentric(loc.second))).second;
  }

  /// The distance at vertex `v`: the solver's distance there (the smallest over
  /// its copies in the extended surface).
  double distance(vertex_descriptor v) const
  {
    const std::size_t i = static_cast<std::size_t>(get(vim_, v));
    if(i >= vertex_distances_.size()) throw Invalid_parameter_error("vertex index out of range");
    return vertex_distances_[i];
  }

  /// The distances at a range of `Face_location`s, written to `out` in order.
  template <class LocationRange, class OutputIterator>
  OutputIterator distances(const LocationRange& locations, OutputIterator out) const
  {
    for(const auto& loc : locations) *out++ = distance(loc);
    return out;
  }

  /// The largest vertex distance.
  double maximum_distance() const
  {
    double m = 0;
    for(double d : vertex_distances_) m = (std::max)(m, d);
    return m;
  }

private:
  std::size_t face_index(face_descriptor f) const
  {
    const std::size_t i = static_cast<std::size_t>(get(fim_, f));
    if(i + 1 >= first_cell_.size()) throw Invalid_parameter_error("face index out of range");
    return i;
  }
  template <class FT>
  static std::array<double, 3> barycentric(const std::array<FT, 3>& b)
  {
    return {{CGAL::to_double(b[0]), CGAL::to_double(b[1]), CGAL::to_double(b[2])}};
  }
  std::pair<std::size_t, double> lowest(std::size_t f, const std::array<double, 3>& b) const
  {
    std::pair<std::size_t, double> best(0, std::numeric_limits<double>::infinity());
    for(std::size_t c = first_cell_[f]; c < first_cell_[f + 1]; ++c)
    {
      const std::array<double, 3>& d = fields_[c];
      const double value = b[0] * d[0] + b[1] * d[1] + b[2] * d[2];
      if(value < best.second) best = {c - first_cell_[f], value};
    }
    return best;
  }
  std::pair<std::size_t, double> lowest_cone(std::size_t f, const std::array<double, 3>& b) const
  {
    const internal::Face_cone_field cones(planes_[f], cones_.data() + first_cone_[f], first_cone_[f + 1] - first_cone_[f]);
    std::pair<std::size_t, double> lowest = cones.lowest(planes_[f].point(b));
    lowest.second = unit_.length_from_unit(lowest.second);
    return lowest;
  }

  std::vector<std::size_t> first_cell_;        // per face index, into fields_
  std::vector<std::array<double, 3> > fields_;  // per cell: corner distances
  std::vector<std::size_t> first_cone_;        // per face index, into cones_ (cone field only)
  std::vector<Face_cone> cones_;
  std::vector<internal::Face_plane> planes_;    // per face index: the face in its plane (cone field only)
  internal::Normalization unit_;                // of the planes and cones' offsets (cone field only)
  std::vector<double> vertex_distances_;
  VertexIndexMap vim_;
  FaceIndexMap fim_;
};

/// \ingroup PkgGeodesicRidgeRef
/// \brief returns the region-wise distance field of a computed ridge, a
/// `Geodesic_distance_field` (\ref GeodesicRidgeSecField).
///
/// \param tm the mesh
/// \param ridge its ridge curve (`compute_ridge_curve()`)
/// \param np an optional sequence of named parameters among the ones listed
///        below; the maps must be those that computed `ridge`
///
/// \pre `ridge` was computed on `tm` (`Invalid_parameter_error` otherwise),
///      and, if `np` asks for the cone field, with `field(Field::cone)` too.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{field}
///     \cgalParamDescription{`Field::cone` asks for the cone field instead of the linear one}
///     \cgalParamType{`Field`}
///     \cgalParamDefault{`Field::linear`}
///   \cgalParamNEnd
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
/// \cgalNamedParamsEnd
template <class TriangleMesh, class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto make_distance_field(const TriangleMesh& tm, const Ridge_curve<TriangleMesh, Point>& ridge,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto maps = internal::mesh_maps(tm, np);
  typedef decltype(maps) Maps;
  typedef Geodesic_distance_field<TriangleMesh, typename Maps::Vertex_index_map, typename Maps::Face_index_map>
      Field_type;
  if(ridge.regions.size() != num_faces(tm) || ridge.vertex_distances.size() != num_vertices(tm))
    throw Invalid_parameter_error("the ridge curve was not computed on this mesh");
  const Field kind = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::field_t()), Field::linear);
  if(kind == Field::linear) return Field_type(ridge.regions, ridge.vertex_distances, maps.vim, maps.fim);
  if(ridge.cones.size() != num_faces(tm))
    throw Invalid_parameter_error("the ridge curve has no cones: compute it with parameters::field(Field::cone)");
  const internal::Faces_by_index<TriangleMesh, typename Maps::Vertex_point_map> faces_by_index(tm, maps.vpm, maps.fim);
  std::vector<std::array<Point, 3> > corners;
  for(std::size_t f = 0; f < num_faces(tm); ++f) corners.push_back(faces_by_index.corner_points(f));
  return Field_type(ridge.regions, ridge.cones, corners, ridge.vertex_distances, maps.vim, maps.fim);
}

/// \ingroup PkgGeodesicRidgeRef
/// \brief computes the ridge of `source` (a vertex or a `Face_location`) with
/// `compute_ridge_curve()` and returns its region-wise distance field, a
/// `Geodesic_distance_field` (`make_distance_field()`).
///
/// \copydetails compute_ridge_curve(const TriangleMesh&, typename boost::graph_traits<TriangleMesh>::vertex_descriptor, const NamedParameters&)
template <class TriangleMesh, class Source, class NamedParameters = CGAL::parameters::Default_named_parameters>
auto compute_distance_field(const TriangleMesh& tm, const Source& source,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  return make_distance_field(tm, compute_ridge_curve(tm, source, np), np);
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_DISTANCE_FIELD_H
