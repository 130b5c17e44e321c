// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// geodesic_ridge: the package's command-line program (DESIGN.md §8).
//
//   geodesic_ridge MESH (--source-vertex V | --source-point FACE X Y Z) [--repair]
//                  [--tolerance T] [--solver exact|vtp|fmm|heat|heat-idt|dijkstra] [--ridge OUT.polylines.txt]
//                  [--ridge-locations OUT.txt] [--rough-cut OUT.polylines.txt]
//                  [--refined OUT.ply [--ply-ascii]]
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

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Mesh;
typedef Mesh::Vertex_index                                  vertex_descriptor;
typedef Mesh::Face_index                                    face_descriptor;
typedef std::pair<face_descriptor, std::array<double, 3> >  Location;
typedef Geodesic_ridge::Ridge_curve<Mesh, Point_3>          Ridge;
typedef std::vector<std::vector<Geodesic_ridge::Ridge_point<Point_3> > > Ridge_polylines;
typedef Mesh::Property_map<vertex_descriptor, double>       Distance_map;
typedef Geodesic_ridge::File_index_map<Mesh>                File_map;
typedef Geodesic_ridge::Connected_component_map<Mesh>       Component_map;
typedef nlohmann::ordered_json                              Json; // keys stay in the order written
namespace po = boost::program_options;
namespace PMP = CGAL::Polygon_mesh_processing;

struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

const char* synopsis =
    "usage: geodesic_ridge MESH (--source-vertex V | --source-point FACE X Y Z) [--repair]\n"
    "                      [--tolerance T] [--solver exact|vtp|fmm|heat|heat-idt|dijkstra] [--ridge OUT.polylines.txt]\n"
    "                      [--ridge-locations OUT.txt] [--rough-cut OUT.polylines.txt]\n"
    "                      [--refined OUT.ply [--ply-ascii]]\n"
    "                      [--isolines N OUT | --isoline-values a,b,c OUT] [--isolines-from-vertices]\n"
    "                      [--query IN.txt [--query-barycentric] --query-out OUT.txt]\n"
    "                      [--field linear|cone] [--linear-ridge] [--no-corner-fallback] [--stats OUT.json]\n"
    "                      [--png OUT.png]\n"
    "       geodesic_ridge MESH --sources FILE --out-dir DIR [--repair] [--tolerance T] [--solver NAME]\n"
    "                      [--linear-ridge] [--no-corner-fallback]\n"
    "  MESH: a manifold surface, closed or with borders (.off, .obj, .ply; PLY triangle strips too).\n"
    "  Polygons are triangulated (CGAL's triangulate_face rule; a note on stderr says how many, and how\n"
    "  many were not planar); dirty meshes are refused, naming what --repair would fix.\n"
    "  Indices are the file's, in and out: V, FACE, the FACE of query lines and of --ridge-locations, the\n"
    "  stats' source, the refined mesh's 'source_face'. A point on a polygon is located among its triangles;\n"
    "  barycentric coordinates (--query-barycentric, --ridge-locations) have one value per vertex of the\n"
    "  file face, in file order: for a polygon, those of the point in the triangle of it that holds the\n"
    "  point, 0 for its other vertices.\n"
    "  A mesh in several parts: the ridge is that of the source's connected component; the others are\n"
    "  unreachable (a note on stderr): 'inf' in --query-out, distance -1 in --refined, grey in --png.\n"
    "  Every output file is written beside its target, then renamed onto it: it is whole or not there.\n\n";

std::size_t parse_index(const std::string& what, const std::string& s)
{
  if(s.empty() || s.find_first_not_of("0123456789") != std::string::npos)
    throw Geodesic_ridge::Invalid_source_error(what + " '" + s + "' is not a non-negative integer");
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
  if(errno == ERANGE || v > std::numeric_limits<std::size_t>::max())
    throw Geodesic_ridge::Invalid_source_error(what + " '" + s + "' is out of range");
  return static_cast<std::size_t>(v);
}

double parse_number(const std::string& what, const std::string& s)
{
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if(s.empty() || end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v))
    throw Geodesic_ridge::Invalid_parameter_error(what + " '" + s + "' is not a finite number");
  return v;
}

std::vector<double> parse_values(const std::string& s)
{
  std::vector<double> values;
  std::size_t start = 0;
  for(;;)
  {
    const std::size_t comma = s.find(',', start);
    values.push_back(parse_number("iso-line value", s.substr(start, comma == std::string::npos ? comma : comma - start)));
    if(comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

struct Options
{
  bool help = false;
  bool repair = false;
  std::string mesh;
  std::optional<std::size_t> source_vertex;
  std::optional<std::size_t> source_face;
  std::array<std::string, 3> source_point_text;
  double tolerance = Geodesic_ridge::default_tolerance;
  std::string rough_cut, stats, ridge, png, ridge_locations, refined;
  bool ply_ascii = false;
  std::string solver = "exact";
  std::string isolines;                   // output file
  std::optional<std::size_t> isoline_count;
  std::vector<double> isoline_values;
  bool isolines_from_vertices = false;
  std::string query, query_out;
  bool query_barycentric = false;
  Geodesic_ridge::Field field = Geodesic_ridge::Field::linear;
  bool corner_fallback = true;
  bool linear_ridge = false;
  std::string sources, out_dir;           // many sources: --sources FILE --out-dir DIR
};

// whether the corner fallback applies: the exact solver's kink split, linear field
// the solvers that offer cones: the cone field, the cone ridge, the kink split
bool solver_has_cones(const std::string& solver) { return solver == "exact" || solver == "vtp"; }

bool corner_fallback_used(const Options& o)
{
  return o.corner_fallback && solver_has_cones(o.solver) && o.field == Geodesic_ridge::Field::linear;
}

// Boost's multitoken() takes any number of values; --source-point takes 4, the
// iso-line options 2, so that the mesh may follow them.
class Tokens : public po::typed_value<std::vector<std::string> >
{
public:
  Tokens(unsigned n, const char* name) : po::typed_value<std::vector<std::string> >(nullptr), n_(n)
  { value_name(name); }
  unsigned min_tokens() const override { return n_; }
  unsigned max_tokens() const override { return n_; }

private:
  unsigned n_;
};

// The options and their help. Values stay text here: parse() reads them with
// messages that name the value.
po::options_description describe()
{
  po::options_description d("options", 100, 50);
  auto text = [](const char* name) { return po::value<std::string>()->value_name(name); };
  d.add_options()
    ("help,h", "print this help")
    ("source-vertex", text("V"), "source at vertex V (0-based, file order)")
    ("source-point", new Tokens(4, "FACE X Y Z"), "source at the point (X,Y,Z) of face FACE (0-based, file order)")
    ("repair", po::bool_switch(), "repair the mesh with CGAL's Polygon_mesh_processing: merge vertices at one "
                                  "position, remove faces with fewer than 3 distinct vertices, duplicate and "
                                  "degenerate faces and isolated vertices, split non-manifold edges and vertices, "
                                  "orient consistently; one line per kind of repair on stderr. A source vertex that "
                                  "is split becomes the copy with the largest incident area")
    ("tolerance", text("T"), "significance tolerance in [0, 0.5) (default 0.025)")
    ("solver", text("NAME"), "geodesic solver on the extended surface: exact (CGAL Surface_mesh_shortest_path, "
                             "default; the reference), vtp (exact too: our window propagation, with the same cone "
                             "ridge and an exact cone field; some 10 times faster and leaner from 10k faces on: "
                             "the choice for large meshes), fmm (fast marching, first order), heat or heat-idt "
                             "(CGAL's heat method on the mesh or on its intrinsic Delaunay triangulation; vertex "
                             "sources only) or dijkstra (paths along edges; a baseline)")
    ("ridge", text("OUT"), "write the ridge curve as CGAL polylines (n x1 y1 z1 ... per line)")
    ("ridge-locations", text("OUT"), "write every ridge point as 'FACE B0 B1 B2 ANGLE' (barycentric in the file "
                                     "order of the face's vertices, one value per vertex; ANGLE: degrees between the "
                                     "fronts)")
    ("refined", text("OUT.ply"), "the ridge-refined mesh: faces the ridge crosses split along it, a 'distance' per "
                                 "vertex (-1: unreachable, in another connected component), a 'source_face' per face (binary PLY; "
                                 "--ply-ascii for ASCII)")
    ("ply-ascii", po::bool_switch(), "write the refined mesh as ASCII PLY")
    ("isolines", new Tokens(2, "N OUT"), "N iso-lines equally spaced strictly between 0 and the largest distance, "
                                         "as CGAL polylines, from the region-wise field")
    ("isoline-values", new Tokens(2, "a,b,c OUT"), "iso-lines at the given distances")
    ("isolines-from-vertices", po::bool_switch(),
     "iso-lines from linear interpolation of the vertex distances instead")
    ("query", text("IN.txt"), "distance queries, one per line: 'FACE X Y Z' (a point of the face, within 1e-7 of "
                              "its size), or with --query-barycentric 'FACE B0 B1 B2' (summing to 1 within 1e-9; "
                              "one value per vertex of the file face); '#' starts a comment")
    ("query-barycentric", po::bool_switch(), "the queries are barycentric coordinates")
    ("query-out", text("OUT"), "the distances, one per line in the order of IN, 17 digits; 'inf' for a point in "
                               "another connected component than the source's")
    ("field", text("KIND"), "the field the queries evaluate: linear (default, the paper's region-wise linear "
                            "field) or cone (solvers exact and vtp: per face copy, the solver's cones; with vtp "
                            "the exact lower envelope of its windows; the refined mesh, the iso-lines and the "
                            "picture's colours stay linear)")
    ("linear-ridge", po::bool_switch(),
     "solvers exact and vtp: report the ridge of the region-wise linear field (the refined mesh's) instead of the "
     "cone ridge, where the solver's cones meet (parameters::cone_ridge(false))")
    ("no-corner-fallback", po::bool_switch(),
     "solvers exact and vtp: a face copy whose corner no cone sample reaches exactly stays whole instead of taking that "
     "corner's front from a sample next to it (parameters::corner_fallback(false): fewer branches found at small "
     "tolerances)")
    ("sources", text("FILE"), "many sources instead of one, one per line: 'V' (a vertex) or 'FACE X Y Z' (a point of "
                              "the face); '#' starts a comment; a line that does not parse refuses the file. With "
                              "--out-dir; in parallel when built with TBB")
    ("out-dir", text("DIR"), "with --sources: for the k-th source (0-based) DIR/ridge_k.polylines.txt and "
                             "DIR/ridge_k.json (its source, counts and timings), or, if it fails (out of range, off its "
                             "face, an error while computing it), DIR/ridge_k.error.txt (its message; the others go on, "
                             "the exit status is 1); DIR/summary.json: every source's status, time and files; a "
                             "progress line on stderr when it is a terminal")
    ("rough-cut", text("OUT"), "write the rough cut locus K (stage 1) as CGAL polylines")
    ("stats", text("OUT.json"), "write counts, timings and parameters as JSON")
    ("png", text("OUT.png"), "picture: the mesh from two opposite sides coloured by the distance (viridis, dark "
                             "bands at 20 levels), the ridge in red, the rough cut locus in white, the source in "
                             "green");
  return d;
}

// Boost's errors, said as this program always said them.
po::variables_map read_command_line(int argc, char** argv, const po::options_description& visible)
{
  po::options_description all;
  all.add(visible).add_options()("mesh", po::value<std::vector<std::string> >());
  po::positional_options_description positional;
  positional.add("mesh", -1);
  po::variables_map vm;
  try
  {
    // no guessing: --tol is not --tolerance
    const int style = po::command_line_style::default_style & ~po::command_line_style::allow_guessing;
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).style(style).run(), vm);
  }
  catch(const po::unknown_option& e)
  {
    throw Usage_error("unknown option '" + e.get_option_name() + "'");
  }
  catch(const po::invalid_command_line_syntax& e)
  {
    if(e.kind() != po::invalid_command_line_syntax::missing_parameter) throw Usage_error(e.what());
    const auto* d = visible.find_nothrow(e.get_option_name().substr(2), false);
    throw Usage_error("option " + e.get_option_name() + " needs " +
                      (d && d->semantic()->max_tokens() > 1 ? d->semantic()->name() : "a value"));
  }
  catch(const po::multiple_occurrences& e)
  {
    if(e.get_option_name() == "--source-vertex") throw Usage_error("give one source only");
    throw Usage_error("option " + e.get_option_name() + " is given more than once");
  }
  catch(const po::error& e)
  {
    throw Usage_error(e.what());
  }
  return vm;
}

std::string text(const po::variables_map& vm, const char* name)
{
  return vm.count(name) ? vm[name].as<std::string>() : std::string();
}

std::vector<std::string> tokens(const po::variables_map& vm, const char* name)
{
  return vm.count(name) ? vm[name].as<std::vector<std::string> >() : std::vector<std::string>();
}

// The options whose values are numbers or names, read with messages that name them.
void read_values(const po::variables_map& vm, Options& o)
{
  const auto point = tokens(vm, "source-point");
  if((vm.count("source-vertex") && !point.empty()) || point.size() > 4) throw Usage_error("give one source only");
  if(vm.count("source-vertex")) o.source_vertex = parse_index("source vertex", text(vm, "source-vertex"));
  if(!point.empty())
  {
    o.source_face = parse_index("source face", point[0]);
    std::copy(point.begin() + 1, point.end(), o.source_point_text.begin());
  }
  const auto isolines = tokens(vm, "isolines"), values = tokens(vm, "isoline-values");
  if(isolines.size() + values.size() > 2) throw Usage_error("give --isolines or --isoline-values once");
  if(!isolines.empty())
  {
    o.isoline_count = parse_index("iso-line count", isolines[0]);
    if(*o.isoline_count == 0) throw Geodesic_ridge::Invalid_parameter_error("iso-line count must be positive");
    o.isolines = isolines[1];
  }
  if(!values.empty()) { o.isoline_values = parse_values(values[0]); o.isolines = values[1]; }
  const std::string field = vm.count("field") ? text(vm, "field") : "linear";
  if(field != "linear" && field != "cone")
    throw Geodesic_ridge::Invalid_parameter_error("unknown field '" + field + "': linear or cone");
  o.field = field == "cone" ? Geodesic_ridge::Field::cone : Geodesic_ridge::Field::linear;
  if(vm.count("solver")) o.solver = text(vm, "solver");
  if(o.solver != "exact" && o.solver != "vtp" && o.solver != "fmm" && o.solver != "heat" &&
     o.solver != "heat-idt" && o.solver != "dijkstra")
    throw Geodesic_ridge::Invalid_parameter_error("unknown solver '" + o.solver +
                                                  "': exact, vtp, fmm, heat, heat-idt or dijkstra");
}

// The options, checked. The tolerance's range is the library's to check: it
// does so when the ridge is computed, before any work.
Options parse(int argc, char** argv)
{
  const po::options_description visible = describe();
  const po::variables_map vm = read_command_line(argc, argv, visible);
  Options o;
  if(vm.count("help"))
  {
    std::cout << synopsis << visible;
    o.help = true;
    return o;
  }
  read_values(vm, o);
  const auto mesh = tokens(vm, "mesh");
  if(mesh.empty()) throw Usage_error("missing the MESH argument");
  if(mesh.size() > 1) throw Usage_error("unexpected argument '" + mesh[1] + "' (the mesh is '" + mesh[0] + "')");
  o.mesh = mesh[0];
  o.rough_cut = text(vm, "rough-cut"), o.stats = text(vm, "stats"), o.ridge = text(vm, "ridge");
  o.png = text(vm, "png"), o.ridge_locations = text(vm, "ridge-locations"), o.refined = text(vm, "refined");
  o.query = text(vm, "query"), o.query_out = text(vm, "query-out");
  o.ply_ascii = vm["ply-ascii"].as<bool>();
  o.repair = vm["repair"].as<bool>();
  o.isolines_from_vertices = vm["isolines-from-vertices"].as<bool>();
  o.query_barycentric = vm["query-barycentric"].as<bool>();
  o.corner_fallback = !vm["no-corner-fallback"].as<bool>();
  o.linear_ridge = vm["linear-ridge"].as<bool>();
  o.sources = text(vm, "sources"), o.out_dir = text(vm, "out-dir");
  if(o.sources.empty() != o.out_dir.empty()) throw Usage_error("--sources and --out-dir go together");
  if(!o.sources.empty())
  {
    if(o.source_vertex || o.source_face) throw Usage_error("give --sources or one source, not both");
    if(!o.rough_cut.empty() || !o.stats.empty() || !o.ridge.empty() || !o.png.empty() || !o.ridge_locations.empty() ||
       !o.refined.empty() || !o.query.empty() || !o.isolines.empty())
      throw Usage_error("with --sources the outputs go to --out-dir; the other outputs are for one source");
  }
  else if(!o.source_vertex && !o.source_face)
    throw Usage_error("missing the source: --source-vertex V or --source-point FACE X Y Z (or --sources FILE)");
  if(o.query.empty() != o.query_out.empty()) throw Usage_error("--query and --query-out go together");
  if(o.query_barycentric && o.query.empty()) throw Usage_error("--query-barycentric needs --query");
  if(o.isolines_from_vertices && o.isolines.empty())
    throw Usage_error("--isolines-from-vertices needs --isolines or --isoline-values");
  if(o.ply_ascii && o.refined.empty()) throw Usage_error("--ply-ascii needs --refined");
  if(o.field == Geodesic_ridge::Field::cone && !solver_has_cones(o.solver))
    throw Geodesic_ridge::Invalid_parameter_error("the cone field needs a solver with cones: exact or vtp");
  if(!o.corner_fallback && !solver_has_cones(o.solver))
    throw Geodesic_ridge::Invalid_parameter_error("--no-corner-fallback is for the solvers with cones (exact, vtp)");
  if(!o.corner_fallback && o.field == Geodesic_ridge::Field::cone)
    throw Geodesic_ridge::Invalid_parameter_error("--no-corner-fallback is for the linear field (the cone field's "
                                                  "samples are next to the corners already)");
  if(o.linear_ridge && !solver_has_cones(o.solver))
    throw Geodesic_ridge::Invalid_parameter_error("--linear-ridge is for the solvers with cones, exact and vtp (the "
                                                  "others have no cone ridge)");
  if(o.linear_ridge && o.field == Geodesic_ridge::Field::cone)
    throw Geodesic_ridge::Invalid_parameter_error("--linear-ridge is not for the cone field (it reports the cone "
                                                  "ridge)");
  if(vm.count("tolerance")) o.tolerance = parse_number("tolerance", text(vm, "tolerance"));
  return o;
}

// The point q of file face `face` as a Face_location (CGAL's order): for a
// polygon, in the triangle of it that holds q. A point farther than 1e-7 of
// the face's size from the face is an error; round-off below that is clamped,
// so that the coordinates are >= 0 and sum to 1.
Location locate(const File_map& map, const Mesh& m, std::size_t face, const Point_3& q,
                const std::string& what = "source point")
{
  const std::optional<Location> found = map.locate(face, q, m);
  if(!found)
    throw Geodesic_ridge::Invalid_source_error("face " + std::to_string(face) + " was removed by the repair");
  Location loc = *found; // the coordinates of q's projection on the face's plane
  const face_descriptor f = loc.first;
  const double off_plane = std::sqrt(CGAL::squared_distance(q, PMP::construct_point(loc, m)));
  double size2 = 0;
  for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m))
    size2 = std::max(size2, CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h))));
  const double eps = 1e-7;
  std::array<double, 3>& w = loc.second;
  if(w[0] < -eps || w[1] < -eps || w[2] < -eps || off_plane > eps * std::sqrt(size2))
  {
    std::ostringstream s;
    s.precision(17);
    s << what << " (" << q << ") is not on face " << face;
    throw Geodesic_ridge::Invalid_source_error(s.str());
  }
  for(double& x : w) x = std::max(x, 0.);
  const double sum = w[0] + w[1] + w[2];
  for(double& x : w) x /= sum;
  return loc;
}

// The file face `text` names, checked.
std::size_t file_face(const std::string& text, const File_map& map)
{
  const std::size_t face = parse_index("face", text);
  if(face >= map.number_of_file_faces())
    throw Geodesic_ridge::Invalid_parameter_error("face " + text + " is out of range: the mesh has " +
                                                  std::to_string(map.number_of_file_faces()) + " faces");
  return face;
}

// The barycentric query "FACE B0 ... Bn-1": one coordinate per vertex of the
// file face, in file order.
Location barycentric_query(const std::vector<std::string>& t, const Mesh& mesh, const File_map& map)
{
  const std::size_t face = file_face(t[0], map);
  const std::size_t n = map.file_face_vertices(face).size();
  if(t.size() != n + 1)
    throw Geodesic_ridge::Invalid_parameter_error(
        n == 3 ? "expected 'FACE B0 B1 B2', got " + std::to_string(t.size()) + " fields"
               : "expected 'FACE' and " + std::to_string(n) + " coordinates (face " + t[0] + " has " +
                     std::to_string(n) + " vertices), got " + std::to_string(t.size()) + " fields");
  std::vector<double> v(n);
  double sum = 0;
  bool negative = false;
  for(std::size_t k = 0; k < n; ++k)
  {
    v[k] = parse_number("coordinate", t[k + 1]);
    sum += v[k];
    negative = negative || v[k] < -1e-9;
  }
  if(std::abs(sum - 1) > 1e-9 || negative)
    throw Geodesic_ridge::Invalid_parameter_error("barycentric coordinates must be >= 0 and sum to 1 within 1e-9");
  for(double& x : v) x = std::max(x, 0.);
  const std::optional<Location> loc = map.location(face, v, mesh);
  if(!loc)
    throw Geodesic_ridge::Invalid_parameter_error("face " + t[0] + " was removed by the repair");
  Location l = *loc;
  for(double& x : l.second) x = std::max(x, 0.);
  return l;
}

// One query of a query file: "FACE X Y Z" or, barycentric, "FACE B0 B1 B2".
Location read_query(const std::vector<std::string>& t, const Mesh& mesh, const File_map& map, bool barycentric)
{
  if(barycentric) return barycentric_query(t, mesh, map);
  if(t.size() != 4)
    throw Geodesic_ridge::Invalid_parameter_error("expected 'FACE X Y Z', got " + std::to_string(t.size()) +
                                                  " fields");
  const std::size_t face = file_face(t[0], map);
  std::array<double, 3> v;
  for(int k = 0; k < 3; ++k) v[k] = parse_number("coordinate", t[k + 1]);
  return locate(map, mesh, face, Point_3(v[0], v[1], v[2]), "point");
}

// One item per line of `filename` (`kind`: "query", "source"), made by
// `read(tokens, line number)`; '#' starts a comment. Errors name the file and the line.
template <class Read>
auto read_lines(const std::string& filename, const std::string& kind, const Read& read)
{
  std::ifstream is(filename);
  if(!is) throw Geodesic_ridge::Invalid_parameter_error("cannot open " + kind + " file '" + filename + "'");
  std::vector<decltype(read(std::vector<std::string>(), std::size_t()))> items;
  std::string line;
  for(std::size_t number = 1; std::getline(is, line); ++number)
  {
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line.erase(hash);
    std::istringstream tokens(line);
    std::vector<std::string> t;
    for(std::string x; tokens >> x;) t.push_back(x);
    if(t.empty()) continue;
    try
    {
      items.push_back(read(t, number));
    }
    catch(const Geodesic_ridge::Error& e)
    {
      throw Geodesic_ridge::Invalid_parameter_error(kind + " file '" + filename + "' line " + std::to_string(number) +
                                                    ": " + e.what());
    }
  }
  if(is.bad()) throw Geodesic_ridge::Invalid_parameter_error("cannot read " + kind + " file '" + filename + "'");
  return items;
}

std::vector<Location> read_queries(const std::string& filename, const Mesh& mesh, const File_map& map,
                                   bool barycentric)
{
  return read_lines(filename, "query", [&](const std::vector<std::string>& t, std::size_t) {
    return read_query(t, mesh, map, barycentric);
  });
}

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

// The statistics as JSON objects, one key per member, named as the member (the
// reference manual documents each), through nlohmann-json's field macros.
#define GEODESIC_RIDGE_JSON_FIELDS(Type, ...)                                                           \
  inline void to_json(Json& nlohmann_json_j, const Type& nlohmann_json_t)                               \
  {                                                                                                     \
    NLOHMANN_JSON_EXPAND(NLOHMANN_JSON_PASTE(NLOHMANN_JSON_TO, __VA_ARGS__))                            \
  }
} // namespace

// (found by argument-dependent lookup: in the statistics' namespace)
namespace Geodesic_ridge {
GEODESIC_RIDGE_JSON_FIELDS(Rough_cut_locus_statistics, genus, number_of_boundary_loops, number_of_vertices, number_of_edges, number_of_faces,
                           number_of_dual_edges, number_of_core_dual_edges, number_of_kept_dual_edges,
                           number_of_kept_dual_leaves, number_of_extended_dual_leaves, number_of_leaf_extension_edges,
                           number_of_cut_edges, number_of_cut_vertices, number_of_cut_leaves, cut_cycle_rank,
                           number_of_closing_rungs, number_of_teeth_pruned, number_of_curvature_pruned_dual_edges,
                           number_of_corner_moves, fallback_single_rung)
GEODESIC_RIDGE_JSON_FIELDS(Extended_surface_statistics, rings, number_of_faces, number_of_vertices, faces_per_ring,
                           number_of_closures, winding_bound_hits, refused_faces, refused_gluings, open_fans,
                           number_of_leaf_vertices)
GEODESIC_RIDGE_JSON_FIELDS(Ridge_curve_statistics, ridge_segments, junctions, free_ends, components, cycles,
                           total_length, faces_with_several_copies, surviving_copies, split_copies, recombined_copies,
                           envelope_segments,
                           edge_segments, thin_face_pieces, regions_before_merge, merged_segments, rejoined_segments,
                           border_joining_segments,
                           dropped_components, piece_joining_segments,
                           pruned_spur_segments, pruned_flat_end_segments, coincident_points)
GEODESIC_RIDGE_JSON_FIELDS(Cone_ridge_statistics, tolerance, points_moved, junctions_moved, points_kept, points_added,
                           kept_linear_ridge,
                           largest_move)
GEODESIC_RIDGE_JSON_FIELDS(Geodesic_ridge_statistics, solver, tolerance, tree_from_solver, solves, predicted_passes,
                           outer_copies_winning, ring_cap_hit, margin_rings, rough_cut_locus, extended_surface, ridge,
                           cone_ridge_traced, cone_ridge)
GEODESIC_RIDGE_JSON_FIELDS(Refined_mesh_statistics, vertices, faces, split_faces, centre_vertices, ridge_edges,
                           unmatched_ridge_segments, largest_disagreement)
GEODESIC_RIDGE_JSON_FIELDS(Repair_statistics, triangulated_polygons, non_planar_polygons, triangles_from_polygons,
                           repaired, merged_vertices, removed_invalid_faces, removed_duplicate_faces,
                           split_non_manifold_edges, split_non_manifold_vertices, added_vertex_copies,
                           removed_degenerate_faces, reoriented_faces, removed_isolated_vertices)
} // namespace Geodesic_ridge

namespace {

void write_json(const std::string& filename, const Json& j)
{
  // a file name that is not UTF-8 gets U+FFFD rather than an exception
  write_file(filename, [&](std::ostream& os) { os << j.dump(2, ' ', false, Json::error_handler_t::replace) << '\n'; });
}

// every step the pipeline timed, stage 1's split into its own steps
Json timings_of(const Ridge& rc, double read_seconds)
{
  Json timings = {{"read_and_validate", read_seconds}};
  for(const auto& [step, seconds] : rc.timings.steps()) timings[step] = seconds;
  for(const auto& [step, seconds] : rc.rough_cut_locus.timings.steps()) timings["rough_cut_locus." + step] = seconds;
  timings["total"] = read_seconds + rc.timings.total();
  return timings;
}

void write_stats(const std::string& filename, const Options& o, const Ridge& rc, const Mesh& mesh,
                 const File_map& map, const Component_map* cc, double read_seconds,
                 const Geodesic_ridge::Refined_mesh_statistics* refined)
{
  const auto& r = rc.rough_cut_locus;
  const auto& s = r.statistics;
  // the source in the file's terms: the file face and one coordinate per vertex of it
  const auto file_source = map.file_location(r.source.location, mesh);
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
                       {"triangulation_and_repair", map.statistics()}}},
            {"mesh", {{"vertices", s.number_of_vertices}, {"edges", s.number_of_edges},
                      {"faces", s.number_of_faces}, {"genus", s.genus}, {"total_area", r.total_area}}},
            {"ridge", {{"polylines", rc.polylines.size()}, {"cone_polylines", rc.cone_polylines.size()}}},
            {"statistics", rc.statistics}};
  if(refined) j["refined_mesh"] = *refined;
  j["timings_seconds"] = timings_of(rc, read_seconds);
  write_json(filename, j);
}

// The mesh vertex of the file's source vertex, said on stderr when the repair
// merged or split it.
vertex_descriptor source_vertex(const Mesh& mesh, const File_map& map, std::size_t v)
{
  if(v >= map.number_of_file_vertices())
    throw Geodesic_ridge::Invalid_source_error("source vertex " + std::to_string(v) +
                                               " is out of range: the mesh has " +
                                               std::to_string(map.number_of_file_vertices()) + " vertices");
  const std::optional<vertex_descriptor> found = map.vertex(v, mesh);
  if(!found)
    throw Geodesic_ridge::Invalid_source_error("source vertex " + std::to_string(v) +
                                               " was removed by the repair (no face of the repaired mesh uses it)");
  const std::size_t copies = map.vertices(v).size(), merged_into = map.file_vertex(*found, mesh);
  if(merged_into != v)
    std::cerr << "geodesic_ridge: note: source vertex " << v << " was merged by the repair into vertex "
              << merged_into << " (same position)\n";
  if(copies > 1)
    std::cerr << "geodesic_ridge: note: source vertex " << v << " was split by the repair into " << copies
              << " copies; the source is the copy with the largest incident area\n";
  return *found;
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

// The point q of file face `face`, checked: the face is the file's and the
// repair kept it, q is on it.
Location source_point(const Mesh& mesh, const File_map& map, std::size_t face, const Point_3& q)
{
  if(face >= map.number_of_file_faces())
    throw Geodesic_ridge::Invalid_source_error("source face " + std::to_string(face) +
                                               " is out of range: the mesh has " +
                                               std::to_string(map.number_of_file_faces()) + " faces");
  if(map.faces(face).empty())
    throw Geodesic_ridge::Invalid_source_error("source face " + std::to_string(face) +
                                               " was removed by the repair (degenerate, duplicate, or with "
                                               "fewer than 3 distinct vertices)");
  return locate(map, mesh, face, q);
}

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
  auto with = [&](const auto& solver) { return f(p::tolerance(o.tolerance, p::solver(solver))); };
  if(o.solver == "fmm") return with(Geodesic_ridge::Fast_marching_solver());
  if(o.solver == "vtp")
    return f(p::tolerance(o.tolerance, p::solver(Geodesic_ridge::Window_propagation_solver(),
                                                 p::field(o.field, p::corner_fallback(o.corner_fallback,
                                                                                      p::cone_ridge(!o.linear_ridge))))));
  if(o.solver == "heat") return with(Geodesic_ridge::Heat_method_solver<>());
  if(o.solver == "heat-idt") return with(Geodesic_ridge::Heat_method_idt_solver());
  if(o.solver == "dijkstra") return with(Geodesic_ridge::Dijkstra_solver());
  return f(p::tolerance(o.tolerance, p::field(o.field, p::corner_fallback(o.corner_fallback,
                                                                          p::cone_ridge(!o.linear_ridge)))));
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
  if(!o.refined.empty()) write_refined(o.refined, refined, o.ply_ascii);
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

// --sources: a line 'V' (a file vertex) or 'FACE X Y Z' (a point of a file
// face). Its syntax is checked when the file is read (a bad line refuses the
// file); whether the mesh has that vertex, or the point on that face, is the
// source's own success or failure (resolve()).
struct Source_line
{
  std::string text;             // the line, for the outputs
  std::size_t line = 0;         // its number in the file
  std::size_t index = 0;        // V, or FACE
  std::optional<Point_3> point; // X Y Z
};

Source_line read_source_line(const std::vector<std::string>& t, std::size_t line)
{
  if(t.size() != 1 && t.size() != 4)
    throw Geodesic_ridge::Invalid_parameter_error("expected 'V' or 'FACE X Y Z', got " + std::to_string(t.size()) +
                                                  " fields");
  Source_line s;
  s.text = t[0];
  for(std::size_t k = 1; k < t.size(); ++k) s.text += " " + t[k];
  s.line = line;
  s.index = parse_index(t.size() == 1 ? "source vertex" : "source face", t[0]);
  if(t.size() == 4)
    s.point = Point_3(parse_number("coordinate", t[1]), parse_number("coordinate", t[2]),
                      parse_number("coordinate", t[3]));
  return s;
}

// The source on the mesh as read (a vertex as a corner of a face of it).
Location resolve(const Source_line& s, const Mesh& mesh, const File_map& map)
{
  if(s.point) return source_point(mesh, map, s.index, *s.point);
  return PMP::locate_vertex<double>(source_vertex(mesh, map, s.index), mesh);
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
    Json j = {{"parameters", {{"mesh", o_.mesh}, {"source", sources_[k].text}}},
              {"ridge", {{"polylines", rc.polylines.size()}, {"cone_polylines", rc.cone_polylines.size()}}},
              {"statistics", rc.statistics}};
    j["parameters"].update(batch_parameters(o_));
    j["timings_seconds"] = timings_of(rc, 0);
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
