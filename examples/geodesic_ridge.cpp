// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// geodesic_ridge: the package's command-line program (DESIGN.md §8).
//
//   geodesic_ridge MESH (--source-vertex V | --source-point FACE X Y Z) [--repair]
//                  [--tolerance T] [--solver exact|vtp|fmm|heat|heat-idt|dijkstra] [--ridge OUT.polylines.txt]
//                  [--ridge-locations OUT.txt] [--rough-cut OUT.polylines.txt]
//                  [--refined OUT.ply [--ply-binary]]
//                  [--isolines N OUT | --isoline-values a,b,c OUT] [--isolines-from-vertices]
//                  [--query IN.txt [--query-barycentric] --query-out OUT.txt] [--field linear|cone]
//                  [--linear-ridge] [--no-corner-fallback]
//                  [--stats OUT.json] [--png OUT.png]
//   geodesic_ridge MESH --sources FILE --out-dir DIR [--repair] [--tolerance T] [--solver NAME]
//                  [--linear-ridge] [--no-corner-fallback]
//
// With the exact solver and vtp the ridge written and drawn is the cone ridge
// (where the solver's cones meet); --linear-ridge gives the linear field's.
//
// Exit status: 0 success, 1 bad input (mesh, source, parameter), 2 bad command
// line, 3 internal error. Every error is one line on stderr; so is every note
// (polygons triangulated, each kind of repair).
//
// With --sources, a file that does not parse is refused before any work; a
// source that fails (out of range, off its face, or an error while computing
// it) leaves DIR/ridge_k.error.txt and the others go on; DIR/summary.json lists
// every source's status, time and files; the exit status is 1 if any failed.
// Every output file is written beside its target and renamed onto it: whole,
// or not there at all.
//
// Indices in and out are the file's, whatever the triangulation of polygons
// and the repair changed (Geodesic_ridge::File_index_map).
//
// Besides the package it needs Boost.Program_options, nlohmann-json and libpng.
#include "cli/input_lines.h"
#include "cli/options.h"
#include "cli/statistics_json.h"

#include <Geodesic_ridge/IO/png.h>
#include <Geodesic_ridge/IO/polylines.h>
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/compute_geodesic_ridges.h>
#include <Geodesic_ridge/connected_component.h>
#include <Geodesic_ridge/distance_field.h>
#include <Geodesic_ridge/isolines.h>
#include <Geodesic_ridge/refined_mesh.h>
#include <Geodesic_ridge/solvers/Dijkstra_solver.h>
#include <Geodesic_ridge/solvers/Heat_method_solver.h>
#include <Geodesic_ridge/solvers/Window_propagation_solver.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/bounding_box.h>

#include <unistd.h>

#include <boost/iterator/function_output_iterator.hpp>
#include <boost/program_options.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

// the options (cli/options.h) and the query and source lines (cli/input_lines.h)
using namespace geodesic_ridge_cli;

typedef Geodesic_ridge::Ridge_curve<Mesh, Point_3>          Ridge;
typedef std::vector<std::vector<Geodesic_ridge::Ridge_point<Point_3> > > Ridge_polylines;
typedef Mesh::Property_map<vertex_descriptor, double>       Distance_map;
typedef Geodesic_ridge::Connected_component_map<Mesh>       Component_map;
typedef nlohmann::ordered_json                              Json; // keys stay in the order written

// Writes the file `target` whole or not at all: `write(path)` writes a
// temporary file beside it (in its directory, so that the rename is atomic),
// renamed onto the target when complete and removed on an error. A run killed
// at any moment leaves every output complete, or as it was.
template <class Write>
void write_atomically(const std::string& target, const Write& write)
{
  namespace fs = std::filesystem;
  const fs::path to(target);
  const fs::path temporary = to.parent_path() / ("." + to.filename().string() + ".tmp." + std::to_string(getpid()));
  // created here, so that an unwritable place is said with the target's name
  if(!std::ofstream(temporary)) throw Geodesic_ridge::Error("cannot open '" + target + "' for writing");
  try
  {
    write(temporary.string());
    std::error_code ec;
    fs::rename(temporary, to, ec);
    if(ec) throw Geodesic_ridge::Error("cannot write '" + target + "': " + ec.message());
  }
  catch(...)
  {
    std::error_code ec;
    fs::remove(temporary, ec);
    throw;
  }
}

// Same, through a stream: `write(os)`.
template <class Write>
void write_file(const std::string& target, const Write& write, bool binary = false)
{
  write_atomically(target, [&](const std::string& path) {
    std::ofstream os(path, binary ? std::ios::out | std::ios::binary : std::ios::out);
    if(!os) throw Geodesic_ridge::Error("cannot open '" + target + "' for writing");
    write(os);
    os.close();
    if(!os) throw Geodesic_ridge::Error("cannot write '" + target + "'");
  });
}

template <class Polylines>
void write_polylines(const std::string& filename, const Polylines& polylines)
{
  write_file(filename, [&](std::ostream& os) { Geodesic_ridge::IO::write_polylines(os, polylines); });
}

template <class Lines>
void write_isolines(const std::string& filename, const Lines& lines)
{
  std::vector<std::vector<Point_3> > polylines;
  for(const auto& l : lines) polylines.push_back(l.points);
  write_polylines(filename, polylines);
}

void write_json(const std::string& filename, const Json& j)
{
  // a file name that is not UTF-8 gets U+FFFD rather than an exception
  write_file(filename, [&](std::ostream& os) { os << j.dump(2, ' ', false, Json::error_handler_t::replace) << '\n'; });
}

void write_stats(const std::string& filename, const Options& o, const Ridge& rc, const Mesh& mesh,
                 const File_map& map, const Component_map* cc, double read_seconds,
                 const Geodesic_ridge::Refined_mesh_statistics* refined)
{
  // the source in the file's terms: the file face and one coordinate per vertex of it
  const auto file_source = map.file_location(rc.rough_cut_locus.source.location, mesh);
  const Json source = o.source_vertex ? Json{{"vertex", *o.source_vertex}}
                                      : Json{{"face", file_source.face}, {"barycentric", file_source.coordinates}};
  Json j = {{"parameters", {{"mesh", o.mesh}, {"source", source}, {"tolerance", o.tolerance}, {"solver", o.solver},
                            {"field", o.field == Geodesic_ridge::Field::cone ? "cone" : "linear"},
                            {"linear_ridge", o.linear_ridge}, {"corner_fallback", corner_fallback_used(o)},
                            {"repair", o.repair}}},
            {"input", {{"file_vertices", map.number_of_file_vertices()},
                       {"file_faces", map.number_of_file_faces()},
                       {"connected_components", cc ? cc->number_of_components() : 1},
                       {"other_components_vertices", cc ? cc->number_of_other_vertices() : 0},
                       {"other_components_faces", cc ? cc->number_of_other_faces() : 0},
                       {"triangulation_and_repair", map.statistics()}}}};
  j.update(ridge_json(rc));
  if(refined) j["refined_mesh"] = *refined;
  j["timings_seconds"] = timings_json(rc, read_seconds);
  write_json(filename, j);
}

// The source the options name, on the mesh as read: a vertex or a point.
struct Source
{
  std::optional<vertex_descriptor> vertex;
  Location point;

  // a face that holds the source
  face_descriptor face(const Mesh& mesh) const
  {
    if(!vertex) return point.first;
    for(face_descriptor f : CGAL::faces_around_target(mesh.halfedge(*vertex), mesh))
      if(f != Mesh::null_face()) return f;
    return Mesh::null_face(); // (a validated mesh has no isolated vertex)
  }
};


Source named_source(const Mesh& mesh, const File_map& map, const Options& o)
{
  if(o.source_vertex) return {source_vertex(mesh, map, *o.source_vertex), Location()};
  const Point_3 q(parse_number("source x", o.source_point_text[0]),
                  parse_number("source y", o.source_point_text[1]),
                  parse_number("source z", o.source_point_text[2]));
  return {std::nullopt, source_point(mesh, map, *o.source_face, q)};
}

// The source's connected component copied into `component` when the mesh has
// several (said on stderr: the others are unreachable); none if it has one.
std::optional<Component_map> source_component(const Mesh& mesh, const Source& source, Mesh& component)
{
  std::vector<std::size_t> id(mesh.number_of_faces());
  if(PMP::connected_components(mesh, boost::make_iterator_property_map(id.begin(), get(CGAL::face_index, mesh))) < 2)
    return std::nullopt;
  Component_map cc = Geodesic_ridge::extract_connected_component(mesh, source.face(mesh), component);
  const std::size_t others = cc.number_of_components() - 1;
  std::cerr << "geodesic_ridge: note: the mesh has " << cc.number_of_components()
            << " connected components; the ridge is that of the source's (" << component.number_of_faces()
            << " of " << mesh.number_of_faces() << " faces); the other " << others << " ("
            << cc.number_of_other_faces() << " faces) " << (others == 1 ? "is" : "are")
            << " unreachable from it\n";
  return cc;
}

// The source in the component.
Source in_component(const Component_map& cc, const Source& source)
{
  if(source.vertex) return {*cc.component_vertex(*source.vertex), Location()};
  return {std::nullopt, *cc.component_location(source.point)};
}

// The queries in the component: none for a point of another component.
std::vector<std::optional<Location> > in_component(const Component_map* cc, const std::vector<Location>& queries)
{
  std::vector<std::optional<Location> > result;
  for(const Location& q : queries) result.push_back(cc ? cc->component_location(q) : std::optional<Location>(q));
  return result;
}

// Calls f with the named parameters of the options; the solver is a type:
// one instantiation per model.
template <class F>
auto with_parameters(const Options& o, const F& f)
{
  namespace p = Geodesic_ridge::parameters;
  auto with = [&](const auto& solver) { return f(p::solver(solver).tolerance(o.tolerance)); };
  if(o.solver == "fmm") return with(Geodesic_ridge::Fast_marching_solver());
  if(o.solver == "vtp")
    return f(p::solver(Geodesic_ridge::Window_propagation_solver())
                 .tolerance(o.tolerance)
                 .field(o.field)
                 .corner_fallback(o.corner_fallback)
                 .cone_ridge(!o.linear_ridge));
  if(o.solver == "heat") return with(Geodesic_ridge::Heat_method_solver<>());
  if(o.solver == "heat-idt") return with(Geodesic_ridge::Heat_method_idt_solver());
  if(o.solver == "dijkstra") return with(Geodesic_ridge::Dijkstra_solver());
  return f(p::tolerance(o.tolerance).field(o.field).corner_fallback(o.corner_fallback).cone_ridge(!o.linear_ridge));
}

// The ridge of the source.
Ridge compute(const Mesh& mesh, const Source& source, const Options& o)
{
  return with_parameters(o, [&](const auto& np) {
    return source.vertex ? Geodesic_ridge::compute_ridge_curve(mesh, *source.vertex, np)
                         : Geodesic_ridge::compute_ridge_curve(mesh, source.point, np);
  });
}

void print_summary(const Options& o, const Ridge& ridge, const File_map& map)
{
  const auto& s = ridge.rough_cut_locus.statistics;
  const auto& g = ridge.statistics;
  std::cout << "mesh " << o.mesh << ": " << s.number_of_vertices << " vertices, "
            << s.number_of_faces << " faces, genus " << s.genus;
  if(s.number_of_vertices != map.number_of_file_vertices() || s.number_of_faces != map.number_of_file_faces())
    std::cout << " (the file: " << map.number_of_file_vertices() << " vertices, " << map.number_of_file_faces()
              << " faces)";
  std::cout << "\n"
            << "rough cut locus (tolerance " << o.tolerance << "): " << s.number_of_kept_dual_edges
            << " of " << s.number_of_dual_edges << " dual edges kept; cut graph K: "
            << s.number_of_cut_edges << " edges, " << s.number_of_cut_leaves << " leaves\n"
            << "extended surface: " << g.extended_surface.number_of_faces << " faces ("
            << double(g.extended_surface.number_of_faces) / s.number_of_faces << " x), "
            << g.extended_surface.rings << " rings, " << g.solves << " " << g.solver << " solves\n"
            << "ridge: " << ridge.ridge_polylines().size() << " polylines, " << g.ridge.junctions << " junctions, "
            << g.ridge.free_ends << " free ends, " << g.ridge.cycles << " cycles, length "
            << g.ridge.total_length << "; " << ridge.timings.total() << " s\n";
  if(g.cone_ridge.kept_linear_ridge)
    std::cout << "cone ridge: the traced curve changed the ridge's graph; the linear ridge is written\n";
  else if(g.cone_ridge_traced)
    std::cout << "cone ridge: " << g.cone_ridge.points_moved << " points and " << g.cone_ridge.junctions_moved
              << " junctions moved onto the cones' curves, " << g.cone_ridge.points_kept << " kept, "
              << g.cone_ridge.points_added << " added (tolerance " << g.cone_ridge.tolerance << ")\n";
}

// The mesh split along the ridge, with a distance per vertex, the input face of
// each face ("f:source_face") and the ridge's edges ("e:ridge").
Geodesic_ridge::Refined_mesh_statistics refine(const Mesh& mesh, const File_map& map, const Ridge& ridge,
                                               Mesh& refined, Distance_map distance)
{
  auto source_face = refined.add_property_map<face_descriptor, std::int32_t>("f:source_face", -1).first;
  auto on_ridge = refined.add_property_map<Mesh::Edge_index, bool>("e:ridge", false).first;
  // the file face of each face
  struct Record_source_face
  {
    Mesh::Property_map<face_descriptor, std::int32_t> source_face;
    const File_map& map;
    const Mesh& mesh;
    void face_created(face_descriptor original, face_descriptor created)
    { source_face[created] = static_cast<std::int32_t>(map.file_face(original, mesh)); }
  } visitor{source_face, map, mesh};
  const auto st = Geodesic_ridge::refine_mesh_along_ridge(
      mesh, ridge, refined, CGAL::parameters::default_values(),
      Geodesic_ridge::parameters::vertex_distance_map(distance).edge_is_constrained_map(on_ridge).visitor(visitor));
  std::cout << "refined mesh: " << st.faces << " faces (" << st.split_faces
            << " faces of the mesh split), largest disagreement " << st.largest_disagreement << "\n";
  if(st.unmatched_ridge_segments > 0)
    throw Geodesic_ridge::Algorithm_error(std::to_string(st.unmatched_ridge_segments) +
                                          " ridge segments are not edges of the refined mesh");
  return st;
}

// The faces of the other components, added to the refined mesh as they are:
// unreachable (distance infinity, -1 in the PLY), with their file face.
void append_other_components(const Mesh& file_mesh, const File_map& file_map, const Component_map& cc,
                             Mesh& refined, Distance_map distance)
{
  std::vector<face_descriptor> others;
  for(face_descriptor f : file_mesh.faces())
    if(!cc.component_face(f)) others.push_back(f);
  const CGAL::Face_filtered_graph<Mesh> part(file_mesh, others);
  std::vector<std::pair<vertex_descriptor, vertex_descriptor> > v2v;
  std::vector<std::pair<face_descriptor, face_descriptor> > f2f;
  CGAL::copy_face_graph(part, refined,
                        CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v))
                            .face_to_face_output_iterator(std::back_inserter(f2f)));
  auto source_face = refined.property_map<face_descriptor, std::int32_t>("f:source_face").first;
  for(const auto& [from, to] : v2v) distance[to] = std::numeric_limits<double>::infinity();
  for(const auto& [from, to] : f2f) source_face[to] = static_cast<std::int32_t>(file_map.file_face(from, file_mesh));
}

void write_refined(const std::string& filename, const Mesh& refined, bool ascii)
{
  // the ridge flags stay in memory: PLY readers disagree on edge elements
  Mesh copy = refined;
  auto ridge_flags = copy.property_map<Mesh::Edge_index, bool>("e:ridge").first;
  copy.remove_property_map(ridge_flags);
  // the documented sentinel of "unreachable": every reader takes -1, not all take inf
  auto distance = copy.property_map<vertex_descriptor, double>("v:distance").first;
  for(vertex_descriptor v : copy.vertices())
    if(!std::isfinite(distance[v])) distance[v] = -1;
  write_file(
      filename,
      [&](std::ostream& os) {
        if(ascii) CGAL::IO::set_ascii_mode(os);
        else CGAL::IO::set_binary_mode(os);
        os.precision(17);
        if(!CGAL::IO::write_PLY(os, copy, "geodesic distance field, refined along the geodesic ridge"))
          throw Geodesic_ridge::Error("cannot write '" + filename + "'");
      },
      true);
  std::cout << "wrote " << filename << " (" << refined.number_of_faces() << " faces, vertex property 'distance', "
            << "face property 'source_face')\n";
}

void write_ridge_locations(const std::string& filename, const Ridge_polylines& ridge, const Mesh& mesh,
                           const File_map& map)
{
  std::size_t points = 0;
  write_file(filename, [&](std::ostream& os) {
    os << "# FACE B0 B1 B2 ANGLE: a ridge point, barycentric in the file order of the face's vertices\n"
          "# (file indices; one value per vertex of the face: for a polygon, the point's coordinates in the\n"
          "# triangle of it that holds the point, 0 for its other vertices);\n"
          "# ANGLE: degrees between the two fronts; one polyline after another, '# polyline' between\n";
    os.precision(17);
    for(const auto& pl : ridge)
    {
      os << "# polyline\n";
      for(const auto& p : pl)
      {
        const Geodesic_ridge::File_face_location l =
            map.file_location(Location(face_descriptor(Mesh::size_type(p.face)), p.barycentric), mesh);
        os << l.face;
        for(double b : l.coordinates) os << ' ' << b;
        os << ' ' << p.angle << '\n';
        ++points;
      }
    }
  });
  std::cout << "wrote " << filename << " (" << points << " ridge points)\n";
}

// The distances of the queries; infinity for a point of another component.
template <class Field>
void write_distances(const std::string& filename, const Field& field,
                     const std::vector<std::optional<Location> >& queries)
{
  std::vector<Location> reachable;
  for(const auto& q : queries) if(q) reachable.push_back(*q);
  std::vector<double> found;
  found.reserve(reachable.size());
  field.distances(reachable, std::back_inserter(found));
  std::vector<double> distances;
  auto next = found.begin();
  for(const auto& q : queries) distances.push_back(q ? *next++ : std::numeric_limits<double>::infinity());
  write_file(filename, [&](std::ostream& os) {
    os.precision(17);
    for(double d : distances) os << d << '\n';
  });
  std::cout << "wrote " << filename << " (" << distances.size() << " distances)\n";
}

// Iso-lines of the refined mesh's distances or, from the vertices, of the linear
// interpolation of `vertex_distance` on the mesh.
template <class VertexDistance>
void contour(const Options& o, const Mesh& contoured, const VertexDistance& vertex_distance)
{
  double largest = 0;
  for(vertex_descriptor v : contoured.vertices())
    if(std::isfinite(vertex_distance(v))) largest = std::max(largest, vertex_distance(v));
  const std::vector<double> levels =
      o.isoline_count ? Geodesic_ridge::equally_spaced_levels(*o.isoline_count, largest) : o.isoline_values;
  std::vector<double> values(contoured.number_of_vertices());
  for(vertex_descriptor v : contoured.vertices()) values[std::size_t(v)] = vertex_distance(v);
  std::vector<Geodesic_ridge::Isoline<Point_3> > lines;
  Geodesic_ridge::isolines(contoured, CGAL::make_property_map(values), levels, std::back_inserter(lines));
  write_isolines(o.isolines, lines);
  std::cout << "wrote " << o.isolines << " (" << lines.size() << " iso-lines at " << levels.size() << " levels, from "
            << (o.isolines_from_vertices ? "the vertex distances" : "the region-wise field") << ")\n";
}

std::vector<std::vector<Point_3> > points_of(const Ridge_polylines& ridge)
{
  std::vector<std::vector<Point_3> > polylines;
  Geodesic_ridge::ridge_polyline_points(ridge, std::back_inserter(polylines));
  return polylines;
}

void write_picture(const std::string& filename, const Mesh& mesh, const Ridge& ridge,
                   const std::vector<std::vector<Point_3> >& reported, const Mesh& refined, Distance_map distance)
{
  std::vector<Geodesic_ridge::IO::Png_curves<Point_3> > curves(3);
  Geodesic_ridge::cut_graph_polylines(mesh, ridge.rough_cut_locus, std::back_inserter(curves[0].polylines));
  curves[0].rgb = {{235, 235, 235}};
  curves[0].width_pixels = 1;
  curves[1].polylines = reported;
  curves[1].width_pixels = 3;
  // the source: a small cross
  const Point_3 src = PMP::construct_point(ridge.rough_cut_locus.source.location, mesh);
  const auto box = CGAL::bounding_box(mesh.points().begin(), mesh.points().end());
  // (hypot: no square leaves double's range, at 1e-300 or 1e300)
  const double arm = 0.015 * std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin());
  for(int k = 0; k < 3; ++k)
  {
    const double dx = k == 0 ? arm : 0, dy = k == 1 ? arm : 0, dz = k == 2 ? arm : 0;
    curves[2].polylines.push_back({Point_3(src.x() - dx, src.y() - dy, src.z() - dz),
                                   Point_3(src.x() + dx, src.y() + dy, src.z() + dz)});
  }
  curves[2].rgb = {{20, 170, 40}};
  curves[2].width_pixels = 5;
  double largest = 0; // (other components, unreachable, are infinitely far: grey)
  for(vertex_descriptor v : refined.vertices())
    if(std::isfinite(distance[v])) largest = std::max(largest, distance[v]);
  write_atomically(filename, [&](const std::string& path) {
    Geodesic_ridge::IO::write_png(path, refined, refined.points(), distance, largest, 20, curves);
  });
  std::cout << "wrote " << filename << "\n";
}

// Says on stderr what the reading changed, before the mesh is validated (so
// also when it is then refused): one line for the polygons, one per kind of repair.
struct Report_repair
{
  void after_repair(const Geodesic_ridge::Repair_statistics& st) const
  {
    const std::string note = st.triangulation_note();
    if(!note.empty()) std::cerr << "geodesic_ridge: note: " << note << "\n";
    for(const std::string& line : st.repair_report()) std::cerr << "geodesic_ridge: " << line << "\n";
    if(st.repeated_positions > 0)
      std::cerr << "geodesic_ridge: note: " << st.repeated_positions
                << (st.repeated_positions == 1 ? " vertex is" : " vertices are") << " at the position of an "
                << "earlier vertex: the surface is read open or in several parts there (--repair merges them)\n";
  }
};

// Reads the mesh: polygons triangulated, repaired with --repair.
File_map read_mesh(const Options& o, Mesh& mesh)
{
  return Geodesic_ridge::IO::read_triangle_mesh(o.mesh, mesh,
                                                Geodesic_ridge::parameters::repair(o.repair).visitor(Report_repair()));
}

int run(const Options& o)
{
  namespace p = Geodesic_ridge::parameters;
  const auto t0 = std::chrono::steady_clock::now();
  Mesh file_mesh;
  const File_map file_map = read_mesh(o, file_mesh);
  const double read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Source file_source = named_source(file_mesh, file_map, o);
  // bad queries are reported before the ridge is computed
  const auto file_queries =
      o.query.empty() ? std::vector<Location>() : read_queries(o.query, file_mesh, file_map, o.query_barycentric);
  // the ridge is computed on the source's component, the others unreachable
  Mesh component;
  const std::optional<Component_map> cc = source_component(file_mesh, file_source, component);
  const std::optional<File_map> component_map =
      cc ? std::optional<File_map>(file_map.restricted_to_component(*cc, file_mesh, component)) : std::nullopt;
  const Mesh& mesh = cc ? component : file_mesh;
  const File_map& map = cc ? *component_map : file_map;
  const auto queries = in_component(cc ? &*cc : nullptr, file_queries);
  const Ridge ridge = compute(mesh, cc ? in_component(*cc, file_source) : file_source, o);
  print_summary(o, ridge, map);
  // the ridge written and drawn: the cone ridge, unless --linear-ridge
  const auto& reported = ridge.ridge_polylines();
  // queries answer from the chosen field; the rest is linear
  const auto field = Geodesic_ridge::make_distance_field(mesh, ridge);
  Mesh refined;
  const auto refined_distance = refined.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  std::optional<Geodesic_ridge::Refined_mesh_statistics> refined_stats;
  if(!o.refined.empty() || !o.png.empty() || (!o.isolines.empty() && !o.isolines_from_vertices))
  {
    refined_stats = refine(mesh, map, ridge, refined, refined_distance);
    if(cc) append_other_components(file_mesh, file_map, *cc, refined, refined_distance);
  }
  if(!o.refined.empty()) write_refined(o.refined, refined, !o.ply_binary);
  if(!o.ridge_locations.empty()) write_ridge_locations(o.ridge_locations, reported, mesh, map);
  if(!o.query.empty() && o.field == Geodesic_ridge::Field::cone)
    write_distances(o.query_out, Geodesic_ridge::make_distance_field(mesh, ridge, p::field(o.field)), queries);
  else if(!o.query.empty())
    write_distances(o.query_out, field, queries);
  if(!o.isolines.empty() && o.isolines_from_vertices)
    contour(o, mesh, [&](vertex_descriptor v) { return field.distance(v); });
  else if(!o.isolines.empty())
    contour(o, refined, [&](vertex_descriptor v) { return refined_distance[v]; });
  if(!o.ridge.empty())
  {
    write_polylines(o.ridge, points_of(reported));
    std::cout << "wrote " << o.ridge << " (" << reported.size() << " polylines)\n";
  }
  if(!o.rough_cut.empty())
  {
    std::vector<std::vector<Point_3> > polylines;
    Geodesic_ridge::cut_graph_polylines(mesh, ridge.rough_cut_locus, std::back_inserter(polylines));
    write_polylines(o.rough_cut, polylines);
    std::cout << "wrote " << o.rough_cut << " (" << polylines.size() << " polylines)\n";
  }
  if(!o.png.empty()) write_picture(o.png, mesh, ridge, points_of(reported), refined, refined_distance);
  if(!o.stats.empty())
  {
    write_stats(o.stats, o, ridge, mesh, map, cc ? &*cc : nullptr, read_seconds,
                refined_stats ? &*refined_stats : nullptr);
    std::cout << "wrote " << o.stats << "\n";
  }
  return 0;
}

Json batch_parameters(const Options& o)
{
  return {{"tolerance", o.tolerance}, {"solver", o.solver}, {"linear_ridge", o.linear_ridge},
          {"corner_fallback", corner_fallback_used(o)}, {"repair", o.repair}};
}

// The one-line message of a source's failure; a bug says so.
std::string message_of(const Geodesic_ridge::Error& e)
{
  return dynamic_cast<const Geodesic_ridge::Algorithm_error*>(&e) ? std::string("internal error: ") + e.what()
                                                                   : std::string(e.what());
}

// The outputs of a batch in DIR: per source its files, or its error file, and
// its outcome for DIR/summary.json.
class Batch_outputs
{
public:
  Batch_outputs(const Options& o, const std::vector<Source_line>& sources)
    : o_(o), sources_(sources), outcomes_(sources.size()), terminal_(isatty(fileno(stderr)))
  {}

  void succeed(std::size_t k, const Ridge& rc)
  {
    Json j = {{"parameters", {{"mesh", o_.mesh}, {"source", sources_[k].text}}}};
    j["parameters"].update(batch_parameters(o_));
    j.update(ridge_json(rc)); // the keys of a single run's --stats
    j["timings_seconds"] = timings_json(rc, 0);
    const std::string polylines = name(k, ".polylines.txt"), json = name(k, ".json");
    write_polylines(path(polylines), points_of(rc.ridge_polylines()));
    write_json(path(json), j);
    remove(name(k, ".error.txt")); // of an earlier run
    outcomes_[k] = {std::string(), rc.timings.total(), {polylines, json}};
    progress();
  }

  void fail(std::size_t k, const std::string& message)
  {
    const std::string error = name(k, ".error.txt");
    write_file(path(error), [&](std::ostream& os) { os << message << '\n'; });
    remove(name(k, ".polylines.txt")); // of an earlier run
    remove(name(k, ".json"));
    outcomes_[k] = {message, std::nullopt, {error}};
    std::cerr << (terminal_ ? "\r" : "") << "geodesic_ridge: error: source " << k << " (line " << sources_[k].line
              << ": '" << sources_[k].text << "'): " << message << "\n";
    progress();
  }

  std::size_t failures() const
  {
    return std::count_if(outcomes_.begin(), outcomes_.end(), [](const Outcome& x) { return !x.error.empty(); });
  }

  // every source in file order: its status, time and files (relative to DIR)
  void write_summary(double seconds) const
  {
    Json list = Json::array();
    for(std::size_t k = 0; k < sources_.size(); ++k)
    {
      const Outcome& x = outcomes_[k];
      Json s = {{"k", k}, {"source", sources_[k].text}, {"line", sources_[k].line},
                {"status", x.error.empty() ? "ok" : "error"}};
      if(!x.error.empty()) s["error"] = x.error;
      s["seconds"] = x.seconds ? Json(*x.seconds) : Json(nullptr);
      s["files"] = x.files;
      list.push_back(std::move(s));
    }
    write_json(path("summary.json"),
               {{"mesh", o_.mesh}, {"sources_file", o_.sources}, {"parameters", batch_parameters(o_)},
                {"number_of_sources", sources_.size()}, {"failed", failures()}, {"total_seconds", seconds},
                {"sources", std::move(list)}});
  }

  std::string path(const std::string& name) const { return (std::filesystem::path(o_.out_dir) / name).string(); }

  void remove(const std::string& name) const
  {
    std::error_code ec;
    std::filesystem::remove(path(name), ec);
  }

private:
  struct Outcome
  {
    std::string error;              // none: ok
    std::optional<double> seconds;  // its computation's; none when it failed
    std::vector<std::string> files; // relative to DIR
  };

  static std::string name(std::size_t k, const char* suffix) { return "ridge_" + std::to_string(k) + suffix; }

  void progress()
  {
    ++done_;
    if(terminal_) std::cerr << "\rgeodesic_ridge: " << done_ << " of " << sources_.size() << " ridges" << std::flush;
  }

  const Options& o_;
  const std::vector<Source_line>& sources_;
  std::vector<Outcome> outcomes_;
  bool terminal_;
  std::size_t done_ = 0;
};

// The ridges of one component's sources, in file order. A source that the
// library refuses fails first; then the library's batch stops at the first
// source whose computation throws, having written those before it: that one
// fails and the batch goes on after it.
template <class NamedParameters>
void compute_component(const Mesh& mesh, const std::vector<std::size_t>& sources, const std::vector<Location>& locations,
                       Batch_outputs& out, const NamedParameters& np)
{
  std::vector<std::size_t> members;
  std::vector<Location> valid;
  for(std::size_t i = 0; i < sources.size(); ++i)
  {
    try
    {
      Geodesic_ridge::make_source(mesh, locations[i], np);
      members.push_back(sources[i]);
      valid.push_back(locations[i]);
    }
    catch(const Geodesic_ridge::Error& e)
    {
      out.fail(sources[i], message_of(e));
    }
  }
  std::size_t next = 0;
  auto write = [&](const Ridge& rc) { out.succeed(members[next], rc); ++next; };
  while(next < members.size())
  {
    try
    {
      const std::vector<Location> rest(valid.begin() + next, valid.end());
      Geodesic_ridge::compute_ridge_curves(mesh, rest, boost::make_function_output_iterator(write), np);
    }
    catch(const Geodesic_ridge::Error& e)
    {
      out.fail(members[next++], message_of(e));
    }
  }
}

// The sources on the mesh, grouped by the connected component of their face
// (`component_of_face`), in file order; a source the mesh does not have fails.
std::map<std::size_t, std::vector<std::size_t> > resolve_all(const std::vector<Source_line>& sources,
                                                             const Mesh& mesh, const File_map& map,
                                                             const std::vector<std::size_t>& component_of_face,
                                                             std::vector<Location>& locations, Batch_outputs& out)
{
  std::map<std::size_t, std::vector<std::size_t> > by_component;
  for(std::size_t k = 0; k < sources.size(); ++k)
  {
    try
    {
      locations[k] = resolve(sources[k], mesh, map);
      by_component[component_of_face[std::size_t(locations[k].first)]].push_back(k);
    }
    catch(const Geodesic_ridge::Error& e)
    {
      out.fail(k, message_of(e));
    }
  }
  return by_component;
}

// The library's checks of the mesh and the parameters, on no source (on one
// component: the library takes one): a bad parameter stops the batch before
// any work; what throws later is a source's.
void check_parameters(const Options& o, const Mesh& mesh, std::size_t components)
{
  Mesh component;
  if(components > 1) Geodesic_ridge::extract_connected_component(mesh, *mesh.faces().begin(), component);
  with_parameters(o, [&](const auto& np) {
    Geodesic_ridge::compute_ridge_curves(components > 1 ? component : mesh, std::vector<Location>(),
                                         boost::make_function_output_iterator([](const Ridge&) {}), np);
    return 0;
  });
}

// Many sources: grouped by connected component (each group one batch, the
// source-independent work done once per component), outputs per source. A
// source that fails leaves DIR/ridge_k.error.txt, and the others go on.
int run_batch(const Options& o)
{
  const auto t0 = std::chrono::steady_clock::now();
  Mesh file_mesh;
  const File_map file_map = read_mesh(o, file_mesh);
  const std::vector<Source_line> sources = read_lines(o.sources, "source", read_source_line);
  if(sources.empty()) throw Geodesic_ridge::Invalid_parameter_error("source file '" + o.sources + "' has no source");
  std::vector<std::size_t> id(file_mesh.number_of_faces());
  const std::size_t components =
      PMP::connected_components(file_mesh, boost::make_iterator_property_map(id.begin(), get(CGAL::face_index, file_mesh)));
  check_parameters(o, file_mesh, components);
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if(ec || !std::filesystem::is_directory(o.out_dir))
    throw Geodesic_ridge::Error("cannot create the output directory '" + o.out_dir + "'");
  Batch_outputs out(o, sources);
  out.remove("summary.json"); // an earlier run's: there is none until this one ends
  std::vector<Location> locations(sources.size());
  const auto by_component = resolve_all(sources, file_mesh, file_map, id, locations, out);
  for(const auto& [component_id, members] : by_component)
  {
    Mesh component;
    std::optional<Component_map> cc;
    if(components > 1) cc = Geodesic_ridge::extract_connected_component(file_mesh, locations[members[0]].first, component);
    std::vector<Location> in_component;
    for(std::size_t k : members) in_component.push_back(cc ? *cc->component_location(locations[k]) : locations[k]);
    with_parameters(o, [&](const auto& np) {
      compute_component(cc ? component : file_mesh, members, in_component, out, np);
      return 0;
    });
  }
  if(isatty(fileno(stderr))) std::cerr << "\n";
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.write_summary(seconds);
  const std::size_t failed = out.failures();
  std::cout << "mesh " << o.mesh << ": " << sources.size() << " sources, " << failed << " failed, "
            << by_component.size() << (by_component.size() == 1 ? " component" : " components") << "; wrote "
            << out.path("summary.json") << " (" << seconds << " s";
#ifdef CGAL_LINKED_WITH_TBB
  std::cout << ", in parallel";
#endif
  std::cout << ")\n";
  return failed == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options o = parse(argc, argv);
    return o.help ? 0 : !o.sources.empty() ? run_batch(o) : run(o);
  }
  catch(const Usage_error& e)
  {
    std::cerr << "geodesic_ridge: error: " << e.what() << " (see --help)\n";
    return 2;
  }
  catch(const Geodesic_ridge::Repairable_mesh_error& e)
  {
    std::cerr << "geodesic_ridge: error: " << e.what() << " (use --repair)\n";
    return 1;
  }
  catch(const Geodesic_ridge::Algorithm_error& e)
  {
    std::cerr << "geodesic_ridge: internal error: " << e.what() << "\n";
    return 3;
  }
  catch(const Geodesic_ridge::Error& e)
  {
    std::cerr << "geodesic_ridge: error: " << e.what() << "\n";
    return 1;
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "geodesic_ridge: error: out of memory\n";
    return 3;
  }
  catch(const std::exception& e)
  {
    std::cerr << "geodesic_ridge: internal error: " << e.what() << "\n";
    return 3;
  }
}
