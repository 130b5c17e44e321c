// Copyright (c) 2026 Geodesic_ridge developers.
//
// geodesic_ridge: the package's command-line program (DESIGN.md §8).
//
//   geodesic_ridge MESH (--source-vertex V | --source-point FACE X Y Z)
//                  [--tolerance T] [--solver exact|fmm] [--ridge OUT.polylines.txt]
//                  [--rough-cut OUT.polylines.txt] [--stats OUT.json]
//
// Exit status: 0 success, 1 bad input (mesh, source, parameter), 2 bad command
// line, 3 internal error. Every error is one line on stderr.
#include <Geodesic_ridge/IO/png.h>
#include <Geodesic_ridge/IO/polylines.h>
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/bounding_box.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
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
    "                      [--rough-cut OUT.polylines.txt] [--stats OUT.json] [--png OUT.png]\n"
    "  MESH              closed, connected, manifold triangle mesh (.off, .obj, .ply)\n"
    "  --source-vertex V source at vertex V (0-based, file order)\n"
    "  --source-point FACE X Y Z\n"
    "                    source at the point (X,Y,Z) of face FACE (0-based, file order)\n"
    "  --tolerance T     significance tolerance in [0, 0.5) (default 0.025)\n"
    "  --solver NAME     geodesic solver on the extended surface: exact (CGAL\n"
    "                    Surface_mesh_shortest_path, default) or fmm (fast marching,\n"
    "                    first order; heat and dijkstra are not in this version)\n"
    "  --ridge OUT       write the ridge curve as CGAL polylines (n x1 y1 z1 ... per line)\n"
    "  --rough-cut OUT   write the rough cut locus K (stage 1) as CGAL polylines\n"
    "  --stats OUT.json  write counts, timings and parameters as JSON\n"
    "  --png OUT.png     picture: the mesh from two opposite sides, the ridge in red,\n"
    "                    the rough cut locus in blue, the source in green\n";

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
  std::string rough_cut, stats, ridge, png;
  std::string solver = "exact";
};

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
  if(have_tolerance) o.tolerance = parse_number("tolerance", tolerance_text);
  // a bad tolerance is reported before the mesh is read
  Geodesic_ridge::internal::get_tolerance(Geodesic_ridge::parameters::tolerance(o.tolerance));
  return o;
}

// The point (x,y,z) of face f as barycentric coordinates (CGAL's order). The
// point must lie on the face up to round-off; tiny negative weights are clamped.
std::array<double, 3> locate_in_face(const Mesh& m, face_descriptor f, const Point_3& q)
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
    s << "source point (" << q << ") is not on face " << std::size_t(f);
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

void write_stats(const std::string& filename, const Options& o, const Ridge& rc, double read_seconds)
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
     << "    \"envelope_segments\": " << q.envelope_segments << ",\n"
     << "    \"edge_segments\": " << q.edge_segments << ",\n"
     << "    \"regions_before_merge\": " << q.regions_before_merge << ",\n"
     << "    \"merged_segments\": " << q.merged_segments << ",\n"
     << "    \"pruned_spur_segments\": " << q.pruned_spur_segments << ",\n"
     << "    \"pruned_flat_end_segments\": " << q.pruned_flat_end_segments << ",\n"
     << "    \"dropped_components\": " << q.dropped_components << "\n"
     << "  },\n"
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

  namespace p = Geodesic_ridge::parameters;
  // the solver is a type: one call per model
  auto compute = [&](const auto& source) {
    if(o.solver == "fmm")
      return Geodesic_ridge::compute_ridge_curve(
          mesh, source, p::tolerance(o.tolerance, p::solver(Geodesic_ridge::Fast_marching_solver())));
    return Geodesic_ridge::compute_ridge_curve(mesh, source, p::tolerance(o.tolerance));
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
  if(!o.ridge.empty())
  {
    std::vector<std::vector<Point_3> > polylines;
    for(const auto& pl : ridge->polylines)
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
    curves[0].rgb = {{60, 90, 230}};
    curves[0].width_pixels = 1;
    for(const auto& pl : ridge->polylines)
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
    Geodesic_ridge::IO::write_png(o.png, mesh, mesh.points(), curves);
    std::cout << "wrote " << o.png << "\n";
  }
  if(!o.stats.empty())
  {
    write_stats(o.stats, o, *ridge, read_seconds);
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
