// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads a triangle mesh from an OFF, OBJ or PLY file, keeping the file's
// vertex and face order, triangulating polygons (and repairing the mesh on
// request) with a map back to the file's indices, and turns every problem
// into a typed exception.
#ifndef GEODESIC_RIDGE_IO_READ_TRIANGLE_MESH_H
#define GEODESIC_RIDGE_IO_READ_TRIANGLE_MESH_H

#include <Geodesic_ridge/internal/mesh_file_text.h>
#include <Geodesic_ridge/internal/off_file_checks.h>
#include <Geodesic_ridge/internal/ply_file_checks.h>
#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/file_index_map.h>
#include <Geodesic_ridge/internal/ply_face_layouts.h>
#include <Geodesic_ridge/mesh_validation.h>
#include <Geodesic_ridge/parameters.h>
#include <Geodesic_ridge/repair.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace Geodesic_ridge {
namespace internal {
namespace mesh_io {


// Runs f; an `Invalid_mesh_error` it throws is thrown again, of the same type,
// with the file name in front of its message.
template <class F>
auto with_file_name(const std::string& filename, F&& f)
{
  try
  {
    return f();
  }
  catch(const Repairable_mesh_error& e)
  {
    throw Repairable_mesh_error(filename + ": " + e.what());
  }
  catch(const Invalid_mesh_error& e)
  {
    throw Invalid_mesh_error(filename + ": " + e.what());
  }
}

// Throws for a file CGAL's reader rejected: the validation's error if our own
// parse of the file (`have_soup`) has an index out of range or a non-finite
// coordinate, else a generic syntax error.
template <class Point>
[[noreturn]] void report_rejected_file(const std::string& filename, Mesh_file_format format, bool have_soup,
                                       const std::vector<Point>& points,
                                       const std::vector<std::vector<std::size_t>>& polygons)
{
  if(have_soup)
    with_file_name(filename, [&] {
      validation::Triangle_soup_validator<Point, std::vector<std::size_t>>(points, polygons).run_polygon_rules(false);
    });
  const char* name = format == Mesh_file_format::OFF ? "OFF" : format == Mesh_file_format::OBJ ? "OBJ" : "PLY";
  file_error(filename, std::string("malformed or truncated ") + name +
                         " content (CGAL's reader rejected it: a value that is not a number, a missing"
                         " value, or fewer elements than the header announces)");
}

// Reads the soup with CGAL's reader and throws `Mesh_file_error` (or, for a
// file CGAL rejected because of an out-of-range index or a NaN, the
// validation's `Invalid_mesh_error`) when it cannot be read entirely.
template <class Point>
void read_polygon_soup_or_throw(const std::string& filename, std::vector<Point>& points,
                                std::vector<std::vector<std::size_t>>& polygons)
{
  const Mesh_file_format format = mesh_file_format(filename);
  check_file_can_be_opened(filename);
  if(format == Mesh_file_format::OFF)
    OFF_file_checks(filename).check_counts();
  else if(format == Mesh_file_format::PLY)
    PLY_file_checks(filename).check_counts();

  std::vector<Point> strict_points;
  std::vector<std::vector<std::size_t>> strict_polygons;
  if(format == Mesh_file_format::OBJ)
    parse_OBJ_strictly(filename, strict_points, strict_polygons);

  points.clear();
  polygons.clear();
  if(format == Mesh_file_format::PLY && ply::needs_own_reader(filename))
  {
    try
    {
      ply::read(filename, points, polygons); // triangle strips, or 8- and 16-bit indices
    }
    catch(const std::length_error&)
    {
      // (CGAL's list reader, which it calls, sizes a list from the file: a
      // count the walk of PLY_file_checks let through)
      file_error(filename, "malformed or truncated PLY content: a list size the reader cannot allocate");
    }
    catch(const std::bad_alloc&)
    {
      file_error(filename, "malformed or truncated PLY content: a list size the reader cannot allocate");
    }
    return;
  }
  if(format == Mesh_file_format::OFF && read_plain_OFF(filename, points, polygons))
    return;
  if(format == Mesh_file_format::OFF)
    OFF_file_checks(filename).check_face_sizes();
  // verbose(false): some of CGAL's readers print to std::cerr by default; we
  // report through the exception only.
  bool read = false;
  try
  {
    read = CGAL::IO::read_polygon_soup(filename, points, polygons, CGAL::parameters::verbose(false));
  }
  catch(const std::length_error&)
  {
    // CGAL's OFF scanner resizes a face to its announced size, which a
    // negative count ("-8") turns into a huge size_t (found by fuzz/): a
    // malformed file, diagnosed below like any other that CGAL refuses
  }
  catch(const std::bad_alloc&)
  {
  }
  if(read)
    return; // CGAL's OFF and PLY readers fail on a truncated file (checked), so the soup is complete.

  // CGAL failed: explain why as precisely as we can. On failure its soup may hold
  // uninitialized points, so it is dropped.
  points.clear();
  polygons.clear();
  bool have_soup = false;
  if(format == Mesh_file_format::OBJ)
  {
    strict_points.swap(points);
    strict_polygons.swap(polygons);
    have_soup = true;
  }
  else if(format == Mesh_file_format::OFF)
    have_soup = diagnose_OFF(filename, points, polygons);
  else
  {
    std::ifstream in(filename, std::ios::binary);
    std::string magic;
    std::getline(in, magic);
    if(magic.compare(0, 3, "ply") != 0)
      file_error(filename, "does not start with 'ply': not a PLY file");
  }
  report_rejected_file(filename, format, have_soup, points, polygons);
}

} // namespace mesh_io
} // namespace internal

namespace internal {
namespace mesh_io {

// The default visitor of `read_triangle_mesh()`: nothing to do.
struct Default_read_visitor
{
  void after_repair(const Repair_statistics&) const {}
};

// The number of points at the position of an earlier point.
template <class Point>
std::size_t count_repeated_positions(const std::vector<Point>& points)
{
  std::vector<validation::Epick_point_3> sorted;
  sorted.reserve(points.size());
  for(const Point& p : points)
    sorted.push_back(validation::to_epick(p));
  std::sort(sorted.begin(), sorted.end());
  std::size_t n = 0;
  for(std::size_t i = 1; i < sorted.size(); ++i)
    n += sorted[i] == sorted[i - 1] ? 1 : 0;
  return n;
}

// Validates the soup, its messages in the file's indices, keeping every
// connected component (the algorithm takes the source's). After the repair,
// what is left is no longer repairable.
template <class Point>
void validate(const Repaired_soup<Point>& soup, bool repaired)
{
  validation::Triangle_soup_validator<Point, std::array<std::size_t, 3>> validator(soup.points, soup.triangles);
  validator.set_file_indices(&soup.vertex_to_file, &soup.face_to_file);
  validator.allow_several_components();
  try
  {
    validator.run();
  }
  catch(const Repairable_mesh_error& e)
  {
    if(repaired)
      throw Invalid_mesh_error(std::string(e.what()) + " (left by the repair)");
    throw;
  }
}

// Builds tm from the soup, in its order; returns the descriptors of its
// vertices and faces. The soup is a valid closed manifold triangle mesh, so
// Euler::add_face cannot fail whatever the face order; if it does, it is a
// bug here or in the validation.
template <class TriangleMesh, class Point>
std::pair<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>,
          std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>>
build_mesh(const std::string& filename, const Repaired_soup<Point>& soup, TriangleMesh& tm)
{
  using GT = boost::graph_traits<TriangleMesh>;
  CGAL::clear(tm);
  auto vpm = get(CGAL::vertex_point, tm);
  std::pair<std::vector<typename GT::vertex_descriptor>, std::vector<typename GT::face_descriptor>> result;
  auto& vds = result.first;
  vds.reserve(soup.points.size());
  result.second.reserve(soup.triangles.size());
  // sized once (3F/2 edges on a closed mesh), not grown by doubling
  reserve(tm, static_cast<typename GT::vertices_size_type>(soup.points.size()),
          static_cast<typename GT::edges_size_type>((3 * soup.triangles.size() + 1) / 2),
          static_cast<typename GT::faces_size_type>(soup.triangles.size()));
  for(const Point& p : soup.points)
  {
    vds.push_back(add_vertex(tm));
    put(vpm, vds.back(), p);
  }
  for(std::size_t j = 0; j < soup.triangles.size(); ++j)
  {
    const auto& t = soup.triangles[j];
    const std::array<typename GT::vertex_descriptor, 3> corners = {vds[t[0]], vds[t[1]], vds[t[2]]};
    result.second.push_back(CGAL::Euler::add_face(corners, tm));
    if(result.second.back() == GT::null_face())
    {
      CGAL::clear(tm);
      throw Algorithm_error(filename + ": face " + std::to_string(soup.face_to_file[j]) +
                            " could not be added to the mesh although the mesh validated; please report this bug");
    }
  }
  return result;
}

} // namespace mesh_io
} // namespace internal

namespace IO {

/// \ingroup PkgGeodesicRidgeIO
///
/// \brief reads a triangle mesh (closed or with a border, in one or several parts) from an OFF, OBJ or PLY file,
/// triangulates its polygons, repairs it if asked to, checks it with
/// `validate_triangle_soup()`, and builds `tm` from it; returns the map from
/// `tm` back to the file's indices.
///
/// The format is chosen by the file extension (`.off`, `.obj`, `.ply`, in any
/// letter case) and the file is read with `CGAL::IO::read_polygon_soup()`;
/// a plain ASCII OFF file (the counts on one line, one vertex or face per
/// line, no comment, no color) is parsed by the package itself, to the same
/// soup, several times faster.
/// Faces with more than three vertices are triangulated with
/// `triangulate_polygons()` (\cgal's `triangulate_face()` rule); with
/// `parameters::repair(true)` the soup is repaired with `repair_mesh()`
/// instead, which triangulates too. Then the mesh is validated, and only then
/// is `tm` cleared and built: every failure is an exception, never a partial
/// mesh.
///
/// Every rule of `validate_triangle_soup()` is checked but rule 12: a mesh of
/// several connected components is read whole, and
/// `extract_connected_component()` copies the one the algorithm is to run on
/// (the source's). Without the repair, the vertices at the position of an
/// earlier vertex are counted (`Repair_statistics::repeated_positions`): the
/// surface is read open or in several parts there, which the repair would
/// merge.
///
/// Indices. Without polygons and without repair, vertex `i` and face `j` of
/// the file are the `i`-th vertex and the `j`-th face added to `tm` (for a
/// `CGAL::Surface_mesh`, vertex `i` and face `j`). With polygons, the first
/// triangle of file face `j` is face `j` and the polygons' other triangles come
/// after the file's faces. A repair renumbers both. In every case the
/// returned `File_index_map` maps vertices, faces and surface points between
/// `tm` and the file, and counts what changed (`File_index_map::statistics()`);
/// the validation's messages use the file's indices.
///
/// PLY: besides the `face` element that \cgal reads (32-bit index lists), the
/// function reads 8- and 16-bit index lists and triangle strips (element
/// `tristrips` with a `vertex_indices` list, -1 restarting a strip): file face
/// `j` is then the `j`-th face of the file's face and strip elements, in the
/// order of the file, a strip counting each of its triangles (the triangles
/// that repeat a vertex, which only join strips, are not faces). Any other
/// element that holds vertex-index lists is refused, naming the element.
///
/// Beyond \cgal's readers, the function
/// - checks the extension and that the file can be opened before reading;
/// - refuses, before anything is allocated, a header, an OFF face or a PLY
///   list that announces more elements than the rest of the file can hold
///   (\cgal's readers allocate what the file announces);
/// - re-reads an ASCII OFF file that \cgal rejected to name the line at fault
///   (a non-numeric token, a missing value, a truncation: the header announces
///   more vertices or faces than the file holds), and reports a NaN, infinite
///   or overflowing coordinate or an out-of-range index as the corresponding
///   validation error;
/// - parses every OBJ file strictly as well, because \cgal's OBJ reader
///   silently drops a non-numeric face token and maps the invalid index 0 to
///   a vertex defined later in the file.
///
/// Known leniencies kept from \cgal's readers: an OFF file with more face lines
/// than its header announces is read up to the announced count; an OFF face
/// index such as `1.7` is truncated to `1`; extra values at the end of an OFF
/// vertex or face line (colors) are ignored.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal
///         `CGAL::vertex_point` property map, e.g. `CGAL::Surface_mesh<Point_3>`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param filename the path of the file
/// \param tm the mesh to fill
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{repair}
///     \cgalParamDescription{whether the mesh is repaired with `repair_mesh()` (`Geodesic_ridge::parameters::repair`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{told what the triangulation and the repair changed, before the mesh is validated
///                           (so also when it is then refused): its member function
///                           `after_repair(const Geodesic_ridge::Repair_statistics&)` is called once}
///     \cgalParamType{a class with that member function}
///     \cgalParamDefault{a visitor that does nothing}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Mesh_file_error if the file cannot be opened, has an unsupported
///         extension, or its content is malformed or truncated; the message
///         names the file (and the line or the PLY element, when it can)
/// \throws Repairable_mesh_error if the mesh breaks a rule of
///         `validate_triangle_soup()` that `parameters::repair(true)` would fix
///         (only without it); the message starts with the file name
/// \throws Invalid_mesh_error if the mesh breaks another rule; the message
///         starts with the file name
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
File_index_map<TriangleMesh> read_triangle_mesh(const std::string& filename, TriangleMesh& tm,
                                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using VPM = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type;
  using Point = typename boost::property_traits<VPM>::value_type;
  namespace mio = internal::mesh_io;
  const bool repair =
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::repair_t()), false);
  const auto visitor = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::visitor),
                                                          mio::Default_read_visitor());

  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  mio::read_polygon_soup_or_throw(filename, points, polygons);
  Repaired_soup<Point> soup = mio::with_file_name(filename, [&] {
    return repair ? repair_mesh(points, polygons) : triangulate_polygons(points, polygons);
  });
  if(!repair)
    soup.statistics.repeated_positions = mio::count_repeated_positions(points);
  visitor.after_repair(soup.statistics);
  mio::with_file_name(filename, [&] { mio::validate(soup, repair); });
  auto descriptors = mio::build_mesh(filename, soup, tm);
  return File_index_map<TriangleMesh>(points, std::move(polygons), soup, std::move(descriptors.first),
                                      std::move(descriptors.second));
}

} // namespace IO

// Also reachable as Geodesic_ridge::read_triangle_mesh; IO:: is the spelling
// that follows CGAL (CGAL::IO::read_polygon_mesh).
using IO::read_triangle_mesh;

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_IO_READ_TRIANGLE_MESH_H
