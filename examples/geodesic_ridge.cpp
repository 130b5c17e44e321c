// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// geodesic_ridge: the package's command-line program (DESIGN.md §8).
//
//   geodesic_ridge MESH (--source-vertex V | --source-point FACE X Y Z)
//                  [--tolerance T] [--solver exact|fmm] [--ridge OUT.polylines.txt]
//                  [--ridge-locations OUT.txt] [--rough-cut OUT.polylines.txt]
//                  [--refined OUT.ply [--ply-ascii]]
//                  [--isolines N OUT | --isoline-values a,b,c OUT] [--isolines-from-vertices]
//                  [--query IN.txt [--query-barycentric] --query-out OUT.txt] [--field linear|cone]
//                  [--stats OUT.json] [--png OUT.png]
//
// Exit status: 0 success, 1 bad input (mesh, source, parameter), 2 bad command
// line, 3 internal error. Every error is one line on stderr.
#include <Geodesic_ridge/IO/png.h>
#include <Geodesic_ridge/IO/polylines.h>
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/distance_field.h>
#include <Geodesic_ridge/isolines.h>
#include <Geodesic_ridge/refined_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/bounding_box.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
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

struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

const char* usage_text =
    "usage: geodesic_ridge MESH (--source-vertex V | --source-point FACE X Y Z)\n"
    "                      [--tolerance T] [--solver exact|fmm] [--ridge OUT.polylines.txt]\n"
    "                      [--ridge-locations OUT.txt] [--rough-cut OUT.polylines.txt]\n"
    "                      [--refined OUT.ply [--ply-ascii]]\n"
    "                      [--isolines N OUT | --isoline-values a,b,c OUT] [--isolines-from-vertices]\n"
    "                      [--query IN.txt [--query-barycentric] --query-out OUT.txt]\n"
    "                      [--field linear|cone] [--stats OUT.json] [--png OUT.png]\n"
    "  MESH              closed, connected, manifold triangle mesh (.off, .obj, .ply)\n"
    "  --source-vertex V source at vertex V (0-based, file order)\n"
    "  --source-point FACE X Y Z\n"
    "                    source at the point (X,Y,Z) of face FACE (0-based, file order)\n"
    "  --tolerance T     significance tolerance in [0, 0.5) (default 0.025)\n"
    "  --solver NAME     geodesic solver on the extended surface: exact (CGAL\n"
    "                    Surface_mesh_shortest_path, default) or fmm (fast marching,\n"
    "                    first order; heat and dijkstra are not in this version)\n"
    "  --ridge OUT       write the ridge curve as CGAL polylines (n x1 y1 z1 ... per line)\n"
    "  --ridge-locations OUT\n"
    "                    write every ridge point as 'FACE B0 B1 B2 ANGLE' (barycentric in the\n"
    "                    file order of the face's vertices; ANGLE: degrees between the fronts)\n"
    "  --refined OUT.ply the ridge-refined mesh: faces the ridge crosses split along it, a\n"
    "                    'distance' per vertex, a 'source_face' per face (binary PLY;\n"
    "                    --ply-ascii for ASCII)\n"
    "  --isolines N OUT  N iso-lines equally spaced strictly between 0 and the largest\n"
    "                    distance, as CGAL polylines, from the region-wise field\n"
    "  --isoline-values a,b,c OUT\n"
    "                    iso-lines at the given distances\n"
    "  --isolines-from-vertices\n"
    "                    iso-lines from linear interpolation of the vertex distances instead\n"
    "  --query IN.txt    distance queries, one per line: 'FACE X Y Z' (a point of the face,\n"
    "                    within 1e-7 of its size), or with --query-barycentric 'FACE B0 B1 B2'\n"
    "                    (summing to 1 within 1e-9); '#' starts a comment\n"
    "  --query-out OUT   the distances, one per line in the order of IN, 17 digits\n"
    "  --field KIND      the field the queries evaluate: linear (default, the paper's\n"
    "                    region-wise linear field) or cone (exact solver only: per face\n"
    "                    copy, the exact solver's cones; --ridge, --ridge-locations and the\n"
    "                    picture's ridge are where the cones meet; the refined mesh, the\n"
    "                    iso-lines and the picture's colours stay linear)\n"
    "  --rough-cut OUT   write the rough cut locus K (stage 1) as CGAL polylines\n"
    "  --stats OUT.json  write counts, timings and parameters as JSON\n"
    "  --png OUT.png     picture: the mesh from two opposite sides coloured by the distance\n"
    "                    (viridis, dark bands at 20 levels), the ridge in red, the rough\n"
    "                    cut locus in white, the source in green\n";

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

struct Options
{
  std::string mesh;
  std::optional<std::size_t> source_vertex;
  std::optional<std::size_t> source_face;
  std::string source_face_text;
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
};

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

Options parse(int argc, char** argv)
{
  Options o;
  std::vector<std::string> args(argv + 1, argv + argc);
  auto value = [&](std::size_t& i, const std::string& opt) -> const std::string& {
    if(i + 1 >= args.size()) throw Usage_error("option " + opt + " needs a value");
    return args[++i];
  };
  bool have_tolerance = false;
  std::string tolerance_text;
  for(std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if(a == "--help" || a == "-h") { std::cout << usage_text; std::exit(0); }
    else if(a == "--source-vertex")
    {
      if(o.source_vertex || o.source_face) throw Usage_error("give one source only");
      o.source_vertex = parse_index("source vertex", value(i, a));
    }
    else if(a == "--source-point")
    {
      if(o.source_vertex || o.source_face) throw Usage_error("give one source only");
      if(i + 4 >= args.size()) throw Usage_error("option --source-point needs FACE X Y Z");
      o.source_face = parse_index("source face", args[++i]);
      for(int k = 0; k < 3; ++k) o.source_point_text[k] = args[++i];
    }
    else if(a == "--tolerance") { tolerance_text = value(i, a); have_tolerance = true; }
    else if(a == "--rough-cut") o.rough_cut = value(i, a);
    else if(a == "--ridge") o.ridge = value(i, a);
    else if(a == "--ridge-locations") o.ridge_locations = value(i, a);
    else if(a == "--refined") o.refined = value(i, a);
    else if(a == "--ply-ascii") o.ply_ascii = true;
    else if(a == "--isolines" || a == "--isoline-values")
    {
      if(!o.isolines.empty()) throw Usage_error("give --isolines or --isoline-values once");
      if(i + 2 >= args.size()) throw Usage_error("option " + a + " needs a value and an output file");
      const std::string& v = args[++i];
      if(a == "--isolines")
      {
        o.isoline_count = parse_index("iso-line count", v);
        if(*o.isoline_count == 0) throw Geodesic_ridge::Invalid_parameter_error("iso-line count must be positive");
      }
      else o.isoline_values = parse_values(v);
      o.isolines = args[++i];
    }
    else if(a == "--isolines-from-vertices") o.isolines_from_vertices = true;
    else if(a == "--query") o.query = value(i, a);
    else if(a == "--query-out") o.query_out = value(i, a);
    else if(a == "--query-barycentric") o.query_barycentric = true;
    else if(a == "--field")
    {
      const std::string& kind = value(i, a);
      if(kind == "linear") o.field = Geodesic_ridge::Field::linear;
      else if(kind == "cone") o.field = Geodesic_ridge::Field::cone;
      else throw Geodesic_ridge::Invalid_parameter_error("unknown field '" + kind + "': linear or cone");
    }
    else if(a == "--png") o.png = value(i, a);
    else if(a == "--solver")
    {
      o.solver = value(i, a);
      if(o.solver != "exact" && o.solver != "fmm")
        throw Geodesic_ridge::Invalid_parameter_error("unknown solver '" + o.solver +
                                                      "': this version has 'exact' and 'fmm'");
    }
    else if(a == "--stats") o.stats = value(i, a);
    else if(a.size() > 1 && a[0] == '-')
      throw Usage_error("unknown option '" + a + "'");
    else if(o.mesh.empty()) o.mesh = a;
    else throw Usage_error("unexpected argument '" + a + "' (the mesh is '" + o.mesh + "')");
  }
  if(o.mesh.empty()) throw Usage_error("missing the MESH argument");
  if(!o.source_vertex && !o.source_face)
    throw Usage_error("missing the source: --source-vertex V or --source-point FACE X Y Z");
  if(o.query.empty() != o.query_out.empty()) throw Usage_error("--query and --query-out go together");
  if(o.query_barycentric && o.query.empty()) throw Usage_error("--query-barycentric needs --query");
  if(o.isolines_from_vertices && o.isolines.empty()) throw Usage_error("--isolines-from-vertices needs --isolines or --isoline-values");
  if(o.ply_ascii && o.refined.empty()) throw Usage_error("--ply-ascii needs --refined");
  if(o.field == Geodesic_ridge::Field::cone && o.solver != "exact")
    throw Geodesic_ridge::Invalid_parameter_error("the cone field needs the exact solver");
  if(have_tolerance) o.tolerance = parse_number("tolerance", tolerance_text);
  // a bad tolerance is reported before the mesh is read
  Geodesic_ridge::internal::get_tolerance(Geodesic_ridge::parameters::tolerance(o.tolerance));
  return o;
}

// The point (x,y,z) of face f as barycentric coordinates (CGAL's order). The
// point must lie on the face up to round-off; tiny negative weights are clamped.
std::array<double, 3> locate_in_face(const Mesh& m, face_descriptor f, const Point_3& q,
                                     const std::string& what = "source point")
{
  const auto h = m.halfedge(f);
  const Point_3 a = m.point(m.source(h)), b = m.point(m.target(h)),
                c = m.point(m.target(m.next(h)));
  const K::Vector_3 n = CGAL::cross_product(b - a, c - a);
  const double nn = n.squared_length();
  const double wa = CGAL::cross_product(c - b, q - b) * n / nn;
  const double wb = CGAL::cross_product(a - c, q - c) * n / nn;
  const double wc = CGAL::cross_product(b - a, q - a) * n / nn;
  const double off_plane = std::abs((q - a) * n) / std::sqrt(nn);
  const double size = std::sqrt(std::max({(b - a).squared_length(), (c - a).squared_length(),
                                          (c - b).squared_length()}));
  const double eps = 1e-7;
  if(wa < -eps || wb < -eps || wc < -eps || off_plane > eps * size)
  {
    std::ostringstream s;
    s.precision(17);
    s << what << " (" << q << ") is not on face " << std::size_t(f);
    throw Geodesic_ridge::Invalid_source_error(s.str());
  }
  std::array<double, 3> w = {std::max(wa, 0.), std::max(wb, 0.), std::max(wc, 0.)};
  const double sum = w[0] + w[1] + w[2];
  for(double& x : w) x /= sum;
  return w;
}

std::string json_number(double x)
{
  if(!std::isfinite(x)) return "null";
  // the shortest decimal that reads back as the same double
  for(int digits = 6; digits <= 17; ++digits)
  {
    std::ostringstream s;
    s.precision(digits);
    s << x;
    if(std::strtod(s.str().c_str(), nullptr) == x || digits == 17) return s.str();
  }
  return "null";
}

std::string json_string(const std::string& x)
{
  std::string out = "\"";
  for(char c : x)
  {
    if(c == '"' || c == '\\') { out += '\\'; out += c; }
    else if(static_cast<unsigned char>(c) < 0x20) { char buf[8]; std::snprintf(buf, sizeof buf, "\\u%04x", c); out += buf; }
    else out += c;
  }
  return out + "\"";
}

typedef Geodesic_ridge::Ridge_curve<Mesh, Point_3> Ridge;

// The reader adds each face (v0, v1, v2) of the file with CGAL::Euler::add_face,
// whose halfedge(f) runs from v2 to v0: a Face_location's corners are (v2, v0,
// v1). These convert barycentric coordinates between the two orders.
std::array<double, 3> file_order_to_location(const std::array<double, 3>& b) { return {{b[2], b[0], b[1]}}; }
std::array<double, 3> location_to_file_order(const std::array<double, 3>& l) { return {{l[1], l[2], l[0]}}; }

// One query per line of `filename`: "FACE X Y Z" or, barycentric, "FACE B0 B1
// B2"; '#' starts a comment. Errors name the line.
std::vector<std::pair<face_descriptor, std::array<double, 3> > > read_queries(const std::string& filename,
                                                                             const Mesh& mesh, bool barycentric)
{
  std::ifstream is(filename);
  if(!is) throw Geodesic_ridge::Invalid_parameter_error("cannot open query file '" + filename + "'");
  std::vector<std::pair<face_descriptor, std::array<double, 3> > > queries;
  std::string line;
  for(std::size_t number = 1; std::getline(is, line); ++number)
  {
    const std::string where = "query file '" + filename + "' line " + std::to_string(number) + ": ";
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line.erase(hash);
    std::istringstream tokens(line);
    std::vector<std::string> t;
    for(std::string x; tokens >> x;) t.push_back(x);
    if(t.empty()) continue;
    try
    {
      if(t.size() != 4)
        throw Geodesic_ridge::Invalid_parameter_error(std::string("expected 'FACE ") +
                                                      (barycentric ? "B0 B1 B2'" : "X Y Z'") + ", got " +
                                                      std::to_string(t.size()) + " fields");
      const std::size_t face = parse_index("face", t[0]);
      if(face >= mesh.number_of_faces())
        throw Geodesic_ridge::Invalid_parameter_error("face " + t[0] + " is out of range: the mesh has " +
                                                      std::to_string(mesh.number_of_faces()) + " faces");
      const face_descriptor f{static_cast<Mesh::size_type>(face)};
      std::array<double, 3> v;
      for(int k = 0; k < 3; ++k) v[k] = parse_number("coordinate", t[k + 1]);
      if(barycentric)
      {
        const double sum = v[0] + v[1] + v[2];
        if(std::abs(sum - 1) > 1e-9 || v[0] < -1e-9 || v[1] < -1e-9 || v[2] < -1e-9)
          throw Geodesic_ridge::Invalid_parameter_error(
              "barycentric coordinates must be >= 0 and sum to 1 within 1e-9");
        for(double& x : v) x = std::max(x, 0.);
        queries.emplace_back(f, file_order_to_location(v));
      }
      else
        queries.emplace_back(f, locate_in_face(mesh, f, Point_3(v[0], v[1], v[2]), "point"));
    }
    catch(const Geodesic_ridge::Error& e)
    {
      throw Geodesic_ridge::Invalid_parameter_error(where + e.what());
    }
  }
  if(is.bad()) throw Geodesic_ridge::Invalid_parameter_error("cannot read query file '" + filename + "'");
  return queries;
}

template <class Lines>
void write_isolines(const std::string& filename, const Lines& lines)
{
  std::vector<std::vector<Point_3> > polylines;
  for(const auto& l : lines) polylines.push_back(l.points);
  Geodesic_ridge::IO::write_polylines(filename, polylines);
}

void write_stats(const std::string& filename, const Options& o, const Ridge& rc, double read_seconds,
                 const Geodesic_ridge::Refined_mesh_statistics* refined)
{
  const auto& r = rc.rough_cut_locus;
  const auto& s = r.statistics;
  const auto& g = rc.statistics;
  const auto& x = g.extended_surface;
  const auto& q = g.ridge;
  std::ofstream os(filename);
  if(!os) throw Geodesic_ridge::Error("cannot open '" + filename + "' for writing");
  os << "{\n"
     << "  \"parameters\": {\n"
     << "    \"mesh\": " << json_string(o.mesh) << ",\n"
     << "    \"source\": " << (o.source_vertex
                                ? "{\"vertex\": " + std::to_string(*o.source_vertex) + "}"
                                : "{\"face\": " + std::to_string(*o.source_face) + ", \"barycentric\": [" +
                                      json_number(r.source.location.second[0]) + ", " +
                                      json_number(r.source.location.second[1]) + ", " +
                                      json_number(r.source.location.second[2]) + "]}") << ",\n"
     << "    \"tolerance\": " << json_number(o.tolerance) << ",\n"
     << "    \"solver\": " << json_string(g.solver) << ",\n"
     << "    \"leaf_curvature_degrees\": " << json_number(Geodesic_ridge::default_leaf_curvature) << ",\n"
     << "    \"branch_curvature_degrees\": " << json_number(Geodesic_ridge::default_branch_curvature) << ",\n"
     << "    \"tree_from_solver\": " << (g.tree_from_solver ? "true" : "false") << "\n"
     << "  },\n"
     << "  \"mesh\": {\"vertices\": " << s.number_of_vertices << ", \"edges\": " << s.number_of_edges
     << ", \"faces\": " << s.number_of_faces << ", \"genus\": " << s.genus
     << ", \"total_area\": " << json_number(r.total_area) << "},\n"
     << "  \"rough_cut_locus\": {\n"
     << "    \"dual_edges\": " << s.number_of_dual_edges << ",\n"
     << "    \"core_dual_edges\": " << s.number_of_core_dual_edges << ",\n"
     << "    \"kept_dual_edges\": " << s.number_of_kept_dual_edges << ",\n"
     << "    \"false_branch_dual_edges\": " << s.number_of_curvature_pruned_dual_edges << ",\n"
     << "    \"kept_dual_leaves\": " << s.number_of_kept_dual_leaves << ",\n"
     << "    \"leaf_extension_dual_edges\": " << s.number_of_leaf_extension_edges << ",\n"
     << "    \"extended_dual_leaves\": " << s.number_of_extended_dual_leaves << ",\n"
     << "    \"cut_edges\": " << s.number_of_cut_edges << ",\n"
     << "    \"cut_vertices\": " << s.number_of_cut_vertices << ",\n"
     << "    \"cut_leaves\": " << s.number_of_cut_leaves << ",\n"
     << "    \"cut_cycle_rank\": " << s.cut_cycle_rank << ",\n"
     << "    \"closing_rungs\": " << s.number_of_closing_rungs << ",\n"
     << "    \"teeth_pruned\": " << s.number_of_teeth_pruned << ",\n"
     << "    \"corner_moves\": " << s.number_of_corner_moves << ",\n"
     << "    \"fallback_single_rung\": " << (s.fallback_single_rung ? "true" : "false") << "\n"
     << "  },\n"
     << "  \"extended_surface\": {\n"
     << "    \"faces\": " << x.number_of_faces << ",\n"
     << "    \"vertices\": " << x.number_of_vertices << ",\n"
     << "    \"faces_over_mesh_faces\": " << json_number(double(x.number_of_faces) / s.number_of_faces) << ",\n"
     << "    \"rings\": " << x.rings << ",\n"
     << "    \"solves\": " << g.solves << ",\n"
     << "    \"predicted_passes\": " << g.predicted_passes << ",\n"
     << "    \"outer_copies_still_winning\": " << g.outer_copies_winning << ",\n"
     << "    \"ring_cap_hit\": " << (g.ring_cap_hit ? "true" : "false") << ",\n"
     << "    \"closures\": " << x.number_of_closures << ",\n"
     << "    \"leaf_vertices\": " << x.number_of_leaf_vertices << ",\n"
     << "    \"winding_bound_hits\": " << x.winding_bound_hits << ",\n"
     << "    \"refused_faces\": " << x.refused_faces << ",\n"
     << "    \"refused_gluings\": " << x.refused_gluings << ",\n"
     << "    \"open_fans\": " << x.open_fans << "\n"
     << "  },\n"
     << "  \"ridge\": {\n"
     << "    \"polylines\": " << rc.polylines.size() << ",\n"
     << "    \"segments\": " << q.ridge_segments << ",\n"
     << "    \"junctions\": " << q.junctions << ",\n"
     << "    \"free_ends\": " << q.free_ends << ",\n"
     << "    \"components\": " << q.components << ",\n"
     << "    \"cycles\": " << q.cycles << ",\n"
     << "    \"total_length\": " << json_number(q.total_length) << ",\n"
     << "    \"faces_with_several_copies\": " << q.faces_with_several_copies << ",\n"
     << "    \"surviving_copies\": " << q.surviving_copies << ",\n"
     << "    \"split_copies\": " << q.split_copies << ",\n"
     << "    \"envelope_segments\": " << q.envelope_segments << ",\n"
     << "    \"edge_segments\": " << q.edge_segments << ",\n"
     << "    \"regions_before_merge\": " << q.regions_before_merge << ",\n"
     << "    \"merged_segments\": " << q.merged_segments << ",\n"
     << "    \"pruned_spur_segments\": " << q.pruned_spur_segments << ",\n"
     << "    \"pruned_flat_end_segments\": " << q.pruned_flat_end_segments << ",\n"
     << "    \"dropped_components\": " << q.dropped_components << "\n"
     << "  },\n";
  if(!rc.cone_polylines.empty())
  {
    const auto& c = g.cone_ridge;
    os << "  \"cone_ridge\": {\"tolerance\": " << json_number(c.tolerance) << ", \"points_moved\": " << c.points_moved
       << ", \"junctions_moved\": " << c.junctions_moved << ", \"points_kept\": " << c.points_kept
       << ", \"points_added\": " << c.points_added << ", \"largest_move_mean_edges\": " << json_number(c.largest_move)
       << ", \"time\": " << json_number(c.time) << "},\n";
  }
  if(refined)
    os << "  \"refined_mesh\": {\"vertices\": " << refined->vertices << ", \"faces\": " << refined->faces
       << ", \"split_faces\": " << refined->split_faces << ", \"centre_vertices\": " << refined->centre_vertices
       << ", \"ridge_edges\": " << refined->ridge_edges
       << ", \"unmatched_ridge_segments\": " << refined->unmatched_ridge_segments
       << ", \"largest_disagreement\": " << json_number(refined->largest_disagreement) << "},\n";
  os
     << "  \"timings_seconds\": {\n"
     << "    \"read_and_validate\": " << json_number(read_seconds) << ",\n"
     << "    \"tree_distances\": " << json_number(g.time_solve_on_mesh) << ",\n"
     << "    \"shortest_path_tree\": " << json_number(s.time_shortest_path_tree) << ",\n"
     << "    \"significance\": " << json_number(s.time_significance) << ",\n"
     << "    \"cut_graph\": " << json_number(s.time_cut_graph) << ",\n"
     << "    \"disk_check\": " << json_number(s.time_disk_check) << ",\n"
     << "    \"rough_cut_locus_total\": " << json_number(s.time_total) << ",\n"
     << "    \"extended_surface\": " << json_number(g.time_extension) << ",\n"
     << "    \"solve\": " << json_number(g.time_solve) << ",\n"
     << "    \"envelope_and_dominance\": " << json_number(g.time_envelope) << ",\n"
     << "    \"ridge_assembly\": " << json_number(g.time_assembly) << ",\n"
     << "    \"total\": " << json_number(g.time_total) << "\n"
     << "  }\n"
     << "}\n";
  os.flush();
  if(!os) throw Geodesic_ridge::Error("cannot write '" + filename + "'");
}

int run(const Options& o)
{
  const auto t0 = std::chrono::steady_clock::now();
  Mesh mesh;
  Geodesic_ridge::IO::read_triangle_mesh(o.mesh, mesh);
  const double read_seconds = Geodesic_ridge::internal::seconds_since(t0);
  // bad queries are reported before the ridge is computed
  const auto queries = o.query.empty() ? std::vector<std::pair<face_descriptor, std::array<double, 3> > >()
                                       : read_queries(o.query, mesh, o.query_barycentric);

  namespace p = Geodesic_ridge::parameters;
  // the solver is a type: one call per model
  auto compute = [&](const auto& source) {
    if(o.solver == "fmm")
      return Geodesic_ridge::compute_ridge_curve(
          mesh, source, p::tolerance(o.tolerance, p::solver(Geodesic_ridge::Fast_marching_solver())));
    return Geodesic_ridge::compute_ridge_curve(mesh, source, p::tolerance(o.tolerance, p::field(o.field)));
  };
  std::optional<Ridge> ridge;
  if(o.source_vertex)
  {
    if(*o.source_vertex >= mesh.number_of_vertices())
      throw Geodesic_ridge::Invalid_source_error(
          "source vertex " + std::to_string(*o.source_vertex) + " is out of range: the mesh has " +
          std::to_string(mesh.number_of_vertices()) + " vertices");
    ridge = compute(vertex_descriptor(Mesh::size_type(*o.source_vertex)));
  }
  else
  {
    if(*o.source_face >= mesh.number_of_faces())
      throw Geodesic_ridge::Invalid_source_error(
          "source face " + std::to_string(*o.source_face) + " is out of range: the mesh has " +
          std::to_string(mesh.number_of_faces()) + " faces");
    Point_3 q(parse_number("source x", o.source_point_text[0]),
              parse_number("source y", o.source_point_text[1]),
              parse_number("source z", o.source_point_text[2]));
    const face_descriptor f(Mesh::size_type(*o.source_face));
    const std::pair<face_descriptor, std::array<double, 3> > loc(f, locate_in_face(mesh, f, q));
    ridge = compute(loc);
  }
  const auto& r = ridge->rough_cut_locus;
  const auto& s = r.statistics;
  const auto& g = ridge->statistics;
  std::cout << "mesh " << o.mesh << ": " << s.number_of_vertices << " vertices, "
            << s.number_of_faces << " faces, genus " << s.genus << "\n"
            << "rough cut locus (tolerance " << o.tolerance << "): " << s.number_of_kept_dual_edges
            << " of " << s.number_of_dual_edges << " dual edges kept; cut graph K: "
            << s.number_of_cut_edges << " edges, " << s.number_of_cut_leaves << " leaves\n"
            << "extended surface: " << g.extended_surface.number_of_faces << " faces ("
            << double(g.extended_surface.number_of_faces) / s.number_of_faces << " x), "
            << g.extended_surface.rings << " rings, " << g.solves << " " << g.solver << " solves\n"
            << "ridge: " << ridge->polylines.size() << " polylines, " << g.ridge.junctions << " junctions, "
            << g.ridge.free_ends << " free ends, " << g.ridge.cycles << " cycles, length "
            << g.ridge.total_length << "; " << g.time_total << " s\n";
  // the ridge written and drawn: with the cone field, the cones' own
  const auto& reported = o.field == Geodesic_ridge::Field::cone ? ridge->cone_polylines : ridge->polylines;
  if(o.field == Geodesic_ridge::Field::cone)
    std::cout << "cone ridge: " << g.cone_ridge.points_moved << " points and " << g.cone_ridge.junctions_moved
              << " junctions moved onto the cones' curves, " << g.cone_ridge.points_kept << " kept, "
              << g.cone_ridge.points_added << " added (tolerance " << g.cone_ridge.tolerance << ")\n";
  // the region-wise field, and the refined mesh where something needs it
  // queries answer from the chosen field; the rest is linear
  const auto field = Geodesic_ridge::make_distance_field(mesh, *ridge);
  std::optional<std::decay_t<decltype(field)> > cone_field;
  if(o.field == Geodesic_ridge::Field::cone)
    cone_field = Geodesic_ridge::make_distance_field(mesh, *ridge, Geodesic_ridge::parameters::field(o.field));
  const auto& query_field = cone_field ? *cone_field : field;
  Mesh refined;
  std::optional<Geodesic_ridge::Refined_mesh_statistics> refined_stats;
  auto refined_distance = refined.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
  if(!o.refined.empty() || !o.png.empty() || (!o.isolines.empty() && !o.isolines_from_vertices))
  {
    auto source_face = refined.add_property_map<face_descriptor, std::int32_t>("f:source_face", -1).first;
    auto on_ridge = refined.add_property_map<Mesh::Edge_index, bool>("e:ridge", false).first;
    struct Record_source_face
    {
      Mesh::Property_map<face_descriptor, std::int32_t> map;
      void face_created(face_descriptor original, face_descriptor created)
      { map[created] = static_cast<std::int32_t>(std::size_t(original)); }
    } visitor{source_face};
    refined_stats = Geodesic_ridge::refine_mesh_along_ridge(
        mesh, *ridge, refined, CGAL::parameters::default_values(),
        Geodesic_ridge::parameters::vertex_distance_map(refined_distance)
            .edge_is_constrained_map(on_ridge)
            .visitor(visitor));
    std::cout << "refined mesh: " << refined_stats->faces << " faces (" << refined_stats->split_faces
              << " faces of the mesh split), largest disagreement " << refined_stats->largest_disagreement << "\n";
    if(refined_stats->unmatched_ridge_segments > 0)
      throw Geodesic_ridge::Algorithm_error(std::to_string(refined_stats->unmatched_ridge_segments) +
                                            " ridge segments are not edges of the refined mesh");
  }
  if(!o.refined.empty())
  {
    std::ofstream os(o.refined, std::ios::binary);
    if(!os) throw Geodesic_ridge::Error("cannot open '" + o.refined + "' for writing");
    if(o.ply_ascii) CGAL::IO::set_ascii_mode(os);
    else CGAL::IO::set_binary_mode(os);
    // the ridge flags stay in memory: PLY readers disagree on edge elements
    Mesh copy = refined;
    auto ridge_flags = copy.property_map<Mesh::Edge_index, bool>("e:ridge").first;
    copy.remove_property_map(ridge_flags);
    os.precision(17);
    if(!CGAL::IO::write_PLY(os, copy, "geodesic distance field, refined along the geodesic ridge") || !os)
      throw Geodesic_ridge::Error("cannot write '" + o.refined + "'");
    std::cout << "wrote " << o.refined << " (" << refined.number_of_faces() << " faces, vertex property 'distance', "
              << "face property 'source_face')\n";
  }
  if(!o.ridge_locations.empty())
  {
    std::ofstream os(o.ridge_locations);
    if(!os) throw Geodesic_ridge::Error("cannot open '" + o.ridge_locations + "' for writing");
    os << "# FACE B0 B1 B2 ANGLE: a ridge point, barycentric in the file order of the face's vertices;\n"
          "# ANGLE: degrees between the two fronts; one polyline after another, '# polyline' between\n";
    os.precision(17);
    std::size_t points = 0;
    for(const auto& pl : reported)
    {
      os << "# polyline\n";
      for(const auto& p : pl)
      {
        const auto b = location_to_file_order(p.barycentric);
        os << p.face << ' ' << b[0] << ' ' << b[1] << ' ' << b[2] << ' ' << p.angle << '\n';
        ++points;
      }
    }
    os.flush();
    if(!os) throw Geodesic_ridge::Error("cannot write '" + o.ridge_locations + "'");
    std::cout << "wrote " << o.ridge_locations << " (" << points << " ridge points)\n";
  }
  if(!o.query.empty())
  {
    std::vector<double> distances;
    distances.reserve(queries.size());
    query_field.distances(queries, std::back_inserter(distances));
    std::ofstream os(o.query_out);
    if(!os) throw Geodesic_ridge::Error("cannot open '" + o.query_out + "' for writing");
    os.precision(17);
    for(double d : distances) os << d << '\n';
    os.flush();
    if(!os) throw Geodesic_ridge::Error("cannot write '" + o.query_out + "'");
    std::cout << "wrote " << o.query_out << " (" << distances.size() << " distances)\n";
  }
  if(!o.isolines.empty())
  {
    std::vector<Geodesic_ridge::Isoline<Point_3> > lines;
    const Mesh& contoured = o.isolines_from_vertices ? mesh : refined;
    auto vertex_distance = [&](vertex_descriptor v) {
      return o.isolines_from_vertices ? field.distance(v) : refined_distance[v];
    };
    double largest = 0;
    for(vertex_descriptor v : contoured.vertices()) largest = std::max(largest, vertex_distance(v));
    const std::vector<double> levels =
        o.isoline_count ? Geodesic_ridge::equally_spaced_levels(*o.isoline_count, largest) : o.isoline_values;
    std::vector<double> values(contoured.number_of_vertices());
    for(vertex_descriptor v : contoured.vertices()) values[std::size_t(v)] = vertex_distance(v);
    Geodesic_ridge::isolines(contoured, CGAL::make_property_map(values), levels, std::back_inserter(lines));
    write_isolines(o.isolines, lines);
    std::cout << "wrote " << o.isolines << " (" << lines.size() << " iso-lines at " << levels.size() << " levels, from "
              << (o.isolines_from_vertices ? "the vertex distances" : "the region-wise field") << ")\n";
  }
  if(!o.ridge.empty())
  {
    std::vector<std::vector<Point_3> > polylines;
    for(const auto& pl : reported)
    {
      polylines.emplace_back();
      for(const auto& p : pl) polylines.back().push_back(p.point);
    }
    Geodesic_ridge::IO::write_polylines(o.ridge, polylines);
    std::cout << "wrote " << o.ridge << " (" << polylines.size() << " polylines)\n";
  }
  if(!o.rough_cut.empty())
  {
    std::vector<std::vector<Point_3> > polylines;
    Geodesic_ridge::cut_graph_polylines(mesh, r, std::back_inserter(polylines));
    Geodesic_ridge::IO::write_polylines(o.rough_cut, polylines);
    std::cout << "wrote " << o.rough_cut << " (" << polylines.size() << " polylines)\n";
  }
  if(!o.png.empty())
  {
    std::vector<Geodesic_ridge::IO::Png_curves<Point_3> > curves(3);
    Geodesic_ridge::cut_graph_polylines(mesh, r, std::back_inserter(curves[0].polylines));
    curves[0].rgb = {{235, 235, 235}};
    curves[0].width_pixels = 1;
    for(const auto& pl : reported)
    {
      curves[1].polylines.emplace_back();
      for(const auto& p : pl) curves[1].polylines.back().push_back(p.point);
    }
    curves[1].width_pixels = 3;
    // the source: a small cross
    const auto& loc = r.source.location;
    const auto h = mesh.halfedge(loc.first);
    const Point_3 a = mesh.point(mesh.source(h)), b = mesh.point(mesh.target(h)), c = mesh.point(mesh.target(mesh.next(h)));
    const Point_3 src(loc.second[0] * a.x() + loc.second[1] * b.x() + loc.second[2] * c.x(),
                      loc.second[0] * a.y() + loc.second[1] * b.y() + loc.second[2] * c.y(),
                      loc.second[0] * a.z() + loc.second[1] * b.z() + loc.second[2] * c.z());
    const double arm = 0.015 * std::sqrt(CGAL::squared_distance(
        CGAL::bounding_box(mesh.points().begin(), mesh.points().end()).min(),
        CGAL::bounding_box(mesh.points().begin(), mesh.points().end()).max()));
    for(int k = 0; k < 3; ++k)
    {
      const double dx = k == 0 ? arm : 0, dy = k == 1 ? arm : 0, dz = k == 2 ? arm : 0;
      curves[2].polylines.push_back({Point_3(src.x() - dx, src.y() - dy, src.z() - dz),
                                     Point_3(src.x() + dx, src.y() + dy, src.z() + dz)});
    }
    curves[2].rgb = {{20, 170, 40}};
    curves[2].width_pixels = 5;
    double largest = 0;
    for(vertex_descriptor v : refined.vertices()) largest = std::max(largest, refined_distance[v]);
    Geodesic_ridge::IO::write_png(o.png, refined, refined.points(), refined_distance, largest, 20, curves);
    std::cout << "wrote " << o.png << "\n";
  }
  if(!o.stats.empty())
  {
    write_stats(o.stats, o, *ridge, read_seconds, refined_stats ? &*refined_stats : nullptr);
    std::cout << "wrote " << o.stats << "\n";
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    return run(parse(argc, argv));
  }
  catch(const Usage_error& e)
  {
    std::cerr << "geodesic_ridge: error: " << e.what() << " (see --help)\n";
    return 2;
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
