// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command line of geodesic_ridge (examples/geodesic_ridge.cpp): its
// options, their help and their checks. A header of its own so that the
// options fuzz target (fuzz/) runs the very parser the program runs.
#ifndef GEODESIC_RIDGE_CLI_OPTIONS_H
#define GEODESIC_RIDGE_CLI_OPTIONS_H

#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/parameters.h>

#include <boost/program_options.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace geodesic_ridge_cli {

namespace po = boost::program_options;

struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

inline const char* const synopsis =
    "usage: geodesic_ridge MESH (--source-vertex V | --source-point FACE X Y Z) [--repair]\n"
    "                      [--tolerance T] [--solver exact|vtp|fmm|heat|heat-idt|dijkstra] [--ridge OUT.polylines.txt]\n"
    "                      [--ridge-locations OUT.txt] [--rough-cut OUT.polylines.txt]\n"
    "                      [--refined OUT.ply [--ply-binary]]\n"
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

inline std::size_t parse_index(const std::string& what, const std::string& s)
{
  if(s.empty() || s.find_first_not_of("0123456789") != std::string::npos)
    throw Geodesic_ridge::Invalid_source_error(what + " '" + s + "' is not a non-negative integer");
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), nullptr, 10);
  if(errno == ERANGE || v > std::numeric_limits<std::size_t>::max())
    throw Geodesic_ridge::Invalid_source_error(what + " '" + s + "' is out of range");
  return static_cast<std::size_t>(v);
}

inline double parse_number(const std::string& what, const std::string& s)
{
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if(s.empty() || end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v))
    throw Geodesic_ridge::Invalid_parameter_error(what + " '" + s + "' is not a finite number");
  return v;
}

inline std::vector<double> parse_values(const std::string& s)
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
  bool ply_binary = false;
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

// the solvers that offer cones: the cone field, the cone ridge, the kink split
inline bool solver_has_cones(const std::string& solver) { return solver == "exact" || solver == "vtp"; }

// whether the corner fallback applies: the exact solver's kink split, linear field
inline bool corner_fallback_used(const Options& o)
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
inline po::options_description describe()
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
                                 "vertex (-1: unreachable, in another connected component), a 'source_face' per face (ASCII "
                                 "PLY, which CGAL, meshio, trimesh and plyfile read; --ply-binary for binary)")
    ("ply-binary", po::bool_switch(), "write the refined mesh as binary PLY (a third of the size; meshio 5 reads "
                                      "no face property of a binary PLY: it fails on 'source_face')")
    ("ply-ascii", po::bool_switch(), "the refined mesh as ASCII PLY (the default)")
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
inline po::variables_map read_command_line(int argc, char** argv, const po::options_description& visible)
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

inline std::string text(const po::variables_map& vm, const char* name)
{
  return vm.count(name) ? vm[name].as<std::string>() : std::string();
}

inline std::vector<std::string> tokens(const po::variables_map& vm, const char* name)
{
  return vm.count(name) ? vm[name].as<std::vector<std::string> >() : std::vector<std::string>();
}

// The options whose values are numbers or names, read with messages that name them.
inline void read_values(const po::variables_map& vm, Options& o)
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
inline Options parse(int argc, char** argv)
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
  o.ply_binary = vm["ply-binary"].as<bool>();
  if(o.ply_binary && vm["ply-ascii"].as<bool>()) throw Usage_error("give --ply-binary or --ply-ascii, not both");
  if((o.ply_binary || vm["ply-ascii"].as<bool>()) && text(vm, "refined").empty())
    throw Usage_error(std::string(o.ply_binary ? "--ply-binary" : "--ply-ascii") + " needs --refined");
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

} // namespace geodesic_ridge_cli

#endif // GEODESIC_RIDGE_CLI_OPTIONS_H
