// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Question: how close is the computed ridge to the exact one, over many
// sources, with each solver (user manual, "How Accuracy Is Measured")? And,
// with --diagnose: does the extended surface hold every shortest path?
//
//   bench_ridge_accuracy [--max-faces N] [--tolerance T] [--recall-tolerance T]
//                        [--sources-per-mesh N] [--random-sources R] [--seed S]
//                        [--solver exact|vtp|fmm|cone|heat|heat-idt|dijkstra|both|exact+cone|exact+vtp|approximate] [--diagnose] [--no-reference] [--source-vertex V]...
//                        [--spacing S] [--max-subdivisions N] [--min-jump DEG] [--outliers] [--hole R] [--repair]
//                        [--split-long-edges L] [--caps P] [--boxes]
//                        [--fmm-reference-rings K] [--fmm-skip-rings K] [--fmm-tolerance T]
//                        [pipeline options] [MESH ...]
//
// --hole R: surfaces with a border. Each mesh loses the faces with a corner
// within R times its bounding box diagonal of its last vertex (one more border
// loop; the name gets "_hole") before the sources are drawn.
//
// --split-long-edges L: the same surface triangulated otherwise. Every edge
// longer than L mean edges is split at its midpoint (CGAL's `split_long_edges`,
// until none is left; the name gets "_split"): a ridge that moves with the
// triangulation is wrong on one of them. The vertices keep their indices
// (`--source-vertex` names the same point, and the vertex sources are those
// of the mesh before the split); the distances are in the split mesh's mean
// edges.
//
// --caps P: the same surface with needles (test/support's `add_caps`). In a
// share P of the faces (drawn with std::mt19937(seed)) a vertex is inserted
// at 1 % of the face's longest edge from that edge's midpoint and joined to
// the corners: a cap (three nearly collinear corners, as the beetle's
// needles) along the longest edge. The vertices keep their indices (the
// vertex sources are those of the mesh without caps); distances are in the
// new mesh's mean edges (the name gets "_caps").
//
// --boxes: two boxes 2 x 1 x 0.7 made as CAD models are (flat faces, sharp
// creases; test/support's analytic meshes), after the MESH arguments (alone
// when there are none): "box_subdivided", every side split 8 x 8 and
// perturbed within its plane (seed 20260202, as the test "convex polyhedra:
// the ridge reaches every corner"), and "box_fans", every side a fan of 24
// long faces from an inner point. The cut locus of a convex polyhedron ends
// at its corners only.
//
// --repair: meshes as people have them (OFF, OBJ, PLY: polygons, non-manifold,
// in parts): each is read with the repair (`parameters::repair(true)`) and, if
// it is in several parts, measured on its largest (the name gets "_part").
//
// Solver vtp: our exact window propagation (Window_propagation_solver), with
// its cones as the exact solver's (the cone ridge, the kink split) and the
// exact checks of --diagnose ('exact+vtp' runs both exact solvers);
// 'vtp-cone' with the cone field (the exact lower envelope of its windows),
// 'vtp+vtp-cone' both.
// Solvers heat, heat-idt and dijkstra are the baselines (issue 14); the heat
// method runs from the vertex sources only ('approximate' runs fmm and the
// three).
//
// The ridge measured is the one reported (`Ridge_curve::ridge_polylines()`):
// with the exact solver the cone ridge, or with --cone-ridge 0 the linear
// field's. Solver 'cone': the exact solver with the cone field (every copy's
// cones read, not only near kinks); 'exact+cone' runs both.
//
// Without MESH arguments it runs every .off file of ../shared/data (or of the
// repository's data/ when ../shared is absent) with at most N faces (default
// 20000), sorted by size.
//
// Sources (the rule is printed): vertices floor(i V / N) for i = 0 .. N-1
// (N = --sources-per-mesh, default 10), then R random `Face_location`s (default
// 2): a face drawn uniformly by index and barycentric coordinates drawn
// uniformly on the triangle, from std::mt19937(seed + mesh's face count).
//
// The reference ridge is built from exact SMSP arrival directions
// (test/support/reference_ridge.h; it shares no code with the pipeline): it
// marks every front boundary with a direction jump of 2 degrees or more, and
// no saddle shadow line. Precision (computed -> reference, samples every 0.1
// mean edge) is reported on the part near reference points with a jump >= 30
// degrees and overall; recall is from reference points with a jump >= 60
// degrees, at the default tolerance and at the small recall tolerance (0.002,
// where branches are not pruned). All distances in mean edge lengths.
//
// --diagnose adds the checks that name the culprit when a ridge is off:
//  * exact copies: every vertex of M has a copy in E whose distance is its
//    distance on M: with the exact solver against SMSP on M (relative 1e-9 of
//    the distance, plus 1e-9 mean edge); with fast marching against fast
//    marching on a much larger E (the pipeline's, grown from
//    --fmm-reference-rings rings everywhere, default 10, without the margin
//    of `parameters::fast_marching_margin`: 2.4-3.8 times as many faces on
//    teddy_3k and armadillo_2k), to --fmm-tolerance (default
//    0.01) of the distance plus a mean edge. With --fmm-reference-rings 0
//    against fast marching on M beyond --fmm-skip-rings rings (default 3) of
//    the ridge: there fast marching mixes the two fronts in the triangles
//    that straddle the ridge, and the mix spreads (teddy_3k v0: 154 vertices
//    up to 0.29 mean edges below E's best copy, the same with E 1.8 times
//    larger). Reported: how many vertices miss it, by how much at worst.
//    With fast marching also, after ' / ', whether its E holds the shortest
//    paths at all: the E that its growth rule builds (the exact pipeline
//    with its fast-marching passes deciding the growth and one exact solve:
//    predicted_extension, maximum_solves(1)), against SMSP on M to
//    --fmm-tolerance. Without its margin (--fast-marching-margin 0), fast
//    marching's value at a vertex depends on E's border by more than that
//    where E holds every path (kitten_5k v1250: E from 3, 5 or 10 initial
//    rings 0.74 mean edges above the exact distance at v1043, from 20 rings
//    0.13 above).
//  * ridge fronts: on every face that the ridge crosses, the winning copies'
//    smallest value at each corner equals that corner's distance on M (the
//    fronts that meet there are the exact ones), same tolerances.
// 'read back' (issue 38): the ridge reported, and with cones the linear one
// after ' / ', written as the program writes it and read back with no code of
// the pipeline (test/support/written_ridge_topology.h: points within 1e-12 of
// the diagonal are one point, border points joined to their loop): 'ok' when
// it is connected with 2g + b independent cycles. With --no-reference only
// this is measured (fast: no reference ridge).
// Prints one row per (mesh, source, solver), then per solver the distribution
// over the pairs (median, worst and where).
#include "../test/support/analytic_meshes.h"
#include "../test/support/reference_ridge.h"
#include "../test/support/written_ridge_topology.h"

#include "../test/support/extension_checks.h"
#include "benchmark_meshes.h"

#include <Geodesic_ridge/IO/polylines.h>
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/connected_component.h>
#include <Geodesic_ridge/solvers/Dijkstra_solver.h>
#include <Geodesic_ridge/solvers/Heat_method_solver.h>
#include <Geodesic_ridge/solvers/Window_propagation_solver.h>

#include <unistd.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef Mesh::Face_index                                    face_descriptor;
typedef std::pair<face_descriptor, std::array<double, 3> >  Face_location;

namespace fs = std::filesystem;
namespace GT = Geodesic_ridge::testing;

namespace {

struct Source
{
  bool on_vertex = true;
  Mesh::Vertex_index vertex;
  Face_location location;
  std::string name() const
  {
    if(on_vertex) return "v" + std::to_string(std::size_t(vertex));
    char buf[96];
    std::snprintf(buf, sizeof buf, "f%zu(%.3f,%.3f,%.3f)", std::size_t(location.first), location.second[0],
                  location.second[1], location.second[2]);
    return buf;
  }
};

std::vector<Source> sources_of(const Mesh& mesh, std::size_t per_mesh, std::size_t random, unsigned seed)
{
  std::vector<Source> out;
  const std::size_t nv = mesh.number_of_vertices();
  for(std::size_t i = 0; i < per_mesh; ++i)
  {
    Source s;
    s.vertex = Mesh::Vertex_index(static_cast<Mesh::size_type>(i * nv / per_mesh));
    out.push_back(s);
  }
  for(const Face_location& loc : GT::random_face_locations(mesh, random, seed + static_cast<unsigned>(mesh.number_of_faces())))
  {
    Source s;
    s.on_vertex = false;
    s.location = loc;
    out.push_back(s);
  }
  return out;
}

struct Pair_result
{
  std::string mesh, source, failure;
  double precision_major_p95 = 0, precision_all_p95 = 0, recall_p95 = 0, recall_small_p95 = 0;
  std::size_t missing = 0, ridge_front_errors = 0;
  std::size_t paths_missing = 0; // fmm: vertices whose exact copy fast marching's E lacks
  double worst_excess = 0; // mean edges
  bool diagnosed = false;
  // the written ridge read back (the reported one, and with cones the linear one too)
  std::string topology;
  bool topology_ok = true;
};

// The ridge written to a file as the program writes it, read back with no
// code of the pipeline (test/support/written_ridge_topology.h): "ok" when it
// is connected with 2g + b cycles, else what it has.
template <class RidgePolylines>
std::string read_back(const Mesh& mesh, const RidgePolylines& ridge, bool& ok)
{
  std::vector<std::vector<K::Point_3> > points;
  Geodesic_ridge::ridge_polyline_points(ridge, std::back_inserter(points));
  // one file per process: two benchmarks may run at once
  const fs::path file =
      fs::temp_directory_path() / ("bench_ridge_accuracy_ridge." + std::to_string(::getpid()) + ".polylines.txt");
  Geodesic_ridge::IO::write_polylines(file.string(), points);
  const GT::Written_ridge_topology t = GT::written_ridge_topology(mesh, file.string());
  fs::remove(file);
  if(t.holds()) return "ok";
  ok = false;
  return std::to_string(t.components) + " comp. " + std::to_string(t.cycles) + " cyc. (2g+b " +
         std::to_string(t.expected_cycles()) + ")";
}

// 'missing': with fast marching, against the larger E / the paths (its E solved exactly)
std::string missing_column(std::size_t missing, std::size_t paths_missing, const std::string& solver)
{
  return solver == "fmm" ? std::to_string(missing) + " / " + std::to_string(paths_missing) : std::to_string(missing);
}

double quantile(std::vector<double> v, double q) { return GT::internal::quantile(std::move(v), q); }

// Keeps the largest connected component of `mesh` only; false if it had one.
bool keep_largest_part(Mesh& mesh)
{
  std::vector<std::size_t> id(mesh.number_of_faces());
  const std::size_t n = CGAL::Polygon_mesh_processing::connected_components(
      mesh, boost::make_iterator_property_map(id.begin(), get(CGAL::face_index, mesh)));
  if(n < 2) return false;
  std::vector<std::size_t> size(n, 0);
  for(std::size_t i : id) ++size[i];
  const std::size_t largest = std::size_t(std::max_element(size.begin(), size.end()) - size.begin());
  const std::size_t f = std::size_t(std::find(id.begin(), id.end(), largest) - id.begin());
  Mesh part;
  Geodesic_ridge::extract_connected_component(mesh, face_descriptor(Mesh::size_type(f)), part);
  mesh = std::move(part);
  return true;
}

// Splits every edge longer than `factor` mean edges at its midpoint (the same surface).
void split_long_edges(Mesh& mesh, double factor)
{
  const double longest = factor * GT::mean_edge_length(mesh);
  std::vector<Mesh::Edge_index> all(mesh.edges().begin(), mesh.edges().end());
  CGAL::Polygon_mesh_processing::split_long_edges(all, longest, mesh);
}

// Removes the faces with a corner within `radius` (times the bounding box
// diagonal) of the last vertex: a hole, one more border loop.
void cut_hole(Mesh& mesh, double radius)
{
  const CGAL::Bbox_3 box = CGAL::bbox_3(mesh.points().begin(), mesh.points().end());
  const double r2 = radius * radius * (CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                       CGAL::square(box.zmax() - box.zmin()));
  const auto centre = mesh.point(*std::prev(mesh.vertices().end()));
  std::vector<Mesh::Face_index> doomed;
  for(auto f : mesh.faces())
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      if(CGAL::squared_distance(mesh.point(v), centre) <= r2) { doomed.push_back(f); break; }
  for(auto f : doomed) CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
  mesh.collect_garbage();
}

} // namespace

int main(int argc, char** argv)
{
  std::size_t per_mesh = 10, random_sources = 2;
  unsigned seed = 1;
  double recall_tolerance = 0.002;
  double fmm_tolerance = 0.01;
  int fmm_skip_rings = 3, fmm_reference_rings = 10;
  bool outliers = false, diagnose = false, reference = true;
  double hole = 0, split = 0, caps = 0;
  bool repair = false, boxes = false;
  std::vector<std::string> solvers = {"exact", "fmm"};
  GT::Reference_ridge_options ref_opt;
  std::vector<std::string> files;
  std::vector<std::size_t> fixed_sources; // --source-vertex V (repeatable): these instead of the rule
  Pipeline_options options;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(options.parse(argc, argv, i)) continue;
    if(a == "--recall-tolerance" && i + 1 < argc) recall_tolerance = std::stod(argv[++i]);
    else if(a == "--sources-per-mesh" && i + 1 < argc) per_mesh = std::stoul(argv[++i]);
    else if(a == "--random-sources" && i + 1 < argc) random_sources = std::stoul(argv[++i]);
    else if(a == "--seed" && i + 1 < argc) seed = static_cast<unsigned>(std::stoul(argv[++i]));
    else if(a == "--solver" && i + 1 < argc)
    {
      const std::string s = argv[++i];
      if(s == "both") solvers = {"exact", "fmm"};
      else if(s == "exact+cone") solvers = {"exact", "cone"};
      else if(s == "exact+vtp") solvers = {"exact", "vtp"};
      else if(s == "vtp+vtp-cone") solvers = {"vtp", "vtp-cone"};
      else if(s == "approximate") solvers = {"fmm", "heat", "heat-idt", "dijkstra"};
      else if(s == "exact" || s == "vtp" || s == "vtp-cone" || s == "fmm" || s == "cone" || s == "heat" ||
              s == "heat-idt" || s == "dijkstra")
        solvers = {s};
      else { std::cerr << "unknown solver " << s << "\n"; return 2; }
    }
    else if(a == "--spacing" && i + 1 < argc) ref_opt.spacing = std::stod(argv[++i]);
    else if(a == "--max-subdivisions" && i + 1 < argc) ref_opt.max_subdivisions = std::stoi(argv[++i]);
    else if(a == "--min-jump" && i + 1 < argc) ref_opt.min_jump_degrees = std::stod(argv[++i]);
    else if(a == "--outliers") outliers = true;
    else if(a == "--diagnose") diagnose = true;
    else if(a == "--source-vertex" && i + 1 < argc) fixed_sources.push_back(std::stoul(argv[++i]));
    else if(a == "--fmm-tolerance" && i + 1 < argc) fmm_tolerance = std::stod(argv[++i]);
    else if(a == "--fmm-skip-rings" && i + 1 < argc) fmm_skip_rings = std::stoi(argv[++i]);
    else if(a == "--fmm-reference-rings" && i + 1 < argc) fmm_reference_rings = std::stoi(argv[++i]);
    else if(a == "--no-reference") reference = false;
    else if(a == "--hole" && i + 1 < argc) hole = std::stod(argv[++i]);
    else if(a == "--repair") repair = true;
    else if(a == "--split-long-edges" && i + 1 < argc) split = std::stod(argv[++i]);
    else if(a == "--caps" && i + 1 < argc) caps = std::stod(argv[++i]);
    else if(a == "--boxes") boxes = true;
    else if(!a.empty() && a[0] == '-') { std::cerr << "unknown option " << a << "\n"; return 2; }
    else files.push_back(a);
  }
  if(!boxes || !files.empty()) files = benchmark_meshes(files);
  const double tolerance = options.tolerance;
  const std::size_t max_faces = options.max_faces;
  if(boxes) { files.push_back("box_subdivided"); files.push_back("box_fans"); }

  std::cout << "Sources per mesh: vertices floor(i V / " << per_mesh << "), i = 0.." << per_mesh - 1 << ", and "
            << random_sources << " random Face_locations (face uniform by index, point uniform on it; "
            << "std::mt19937 seeded with " << seed << " + F).\n"
            << "Distances in mean edge lengths. Precision: computed ridge samples -> reference ridge, on the part "
               "near reference jumps >= 30 deg and overall; recall: reference points with jump >= 60 deg -> "
               "computed ridge, at tolerance " << tolerance << " and " << recall_tolerance << ".\n";
  if(diagnose)
    std::cout << "Diagnosis: 'missing' = vertices of M whose best copy in E exceeds the distance on M (exact: SMSP "
                 "on M, 1e-9 relative; fmm: fast marching on an E grown from " << fmm_reference_rings
              << " rings everywhere (0: on M, beyond " << fmm_skip_rings << " rings of the ridge), " << fmm_tolerance
              << " relative; then ' / ' the vertices whose exact copy fast marching's E lacks: the E of its growth "
                 "rule (predicted passes, one exact solve) against SMSP, " << fmm_tolerance << " relative), worst "
                 "excess in mean edges; "
                 "'front err.' = corners of faces the ridge crosses where the winning copies miss that "
                 "distance.\n";
  std::cout << "\n| mesh | F | g | source | solver | prec. p95 (>= 30 deg) | prec. p95 (all) | prec. max | recall p95 "
               "| recall p95 @" << recall_tolerance << " | F(E)/F | rings | solves | outer winning | missing | worst excess "
               "| front err. | read back | time (s) |\n"
               "|---|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|\n";

  std::map<std::string, std::vector<Pair_result> > results;
  for(const std::string& file : files)
  {
    Mesh mesh;
    if(file == "box_subdivided") mesh = GT::make_subdivided_polyhedron(GT::box_corners_and_faces(2, 1, 0.7), 8, 0.25, 20260202).mesh;
    else if(file == "box_fans") mesh = GT::make_fan_box(2, 1, 0.7, 6).mesh;
    else
      try { Geodesic_ridge::IO::read_triangle_mesh(file, mesh, Geodesic_ridge::parameters::repair(repair)); }
      catch(const Geodesic_ridge::Error& e) { std::cerr << file << ": " << e.what() << "\n"; continue; }
    bool part = keep_largest_part(mesh);
    if(mesh.number_of_faces() > max_faces) continue;
    if(hole > 0)
    {
      // a hole may pinch a vertex (two border loops through it) or cut a
      // part off: the bench measures the manifold largest part that is left
      cut_hole(mesh, hole);
      CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices(mesh);
      part = keep_largest_part(mesh) || part;
    }
    // the vertex sources of the surface before it is triangulated otherwise
    // (the vertices keep their indices), the random ones on the new faces
    std::vector<Source> sources = sources_of(mesh, per_mesh, 0, seed);
    if(split > 0) split_long_edges(mesh, split);
    if(caps > 0)
    {
      const double before = GT::mean_edge_length(mesh);
      const std::size_t n = GT::add_caps(mesh, caps, seed);
      std::cout << fs::path(file).stem().string() << ": " << n << " caps; mean edge " << GT::mean_edge_length(mesh) / before
                << " of the mesh's without them\n";
    }
    std::vector<Mesh::Halfedge_index> border_cycles;
    CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(border_cycles));
    const long loops = long(border_cycles.size());
    const long chi = long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces());
    const long genus = (2 - chi - loops) / 2;
    const std::string mesh_name = fs::path(file).stem().string() + (part ? "_part" : "") + (hole > 0 ? "_hole" : "") +
                                  (split > 0 ? "_split" : "") + (caps > 0 ? "_caps" : "");

    const std::vector<Source> random = sources_of(mesh, 0, random_sources, seed);
    sources.insert(sources.end(), random.begin(), random.end());
    if(!fixed_sources.empty())
    {
      sources.clear();
      for(std::size_t v : fixed_sources)
        if(v < mesh.number_of_vertices()) { Source s; s.vertex = Mesh::Vertex_index(static_cast<Mesh::size_type>(v)); sources.push_back(s); }
    }
    for(const Source& src : sources)
    {
      GT::Reference_ridge<K::Point_3> ref;
      if(reference) ref = src.on_vertex ? GT::reference_ridge(mesh, src.vertex, ref_opt)
                                        : GT::reference_ridge(mesh, src.location, ref_opt);
      std::vector<double> exact_on_mesh;
      auto on_mesh_of = [&](bool exact) {
        return src.on_vertex ? GT::distances_on_mesh<K>(mesh, src.vertex, exact)
                             : GT::distances_on_mesh<K>(mesh, src.location, exact);
      };
      if(diagnose) exact_on_mesh = on_mesh_of(true);
      auto ridge_of = [&](const auto& np) {
        return src.on_vertex ? Geodesic_ridge::compute_ridge_curve(mesh, src.vertex, np)
                             : Geodesic_ridge::compute_ridge_curve(mesh, src.location, np);
      };
      for(const std::string& solver : solvers)
      {
        // CGAL 5.5's heat method takes vertex sources only (the solver refuses points)
        if(!src.on_vertex && solver.compare(0, 4, "heat") == 0) continue;
        Pair_result r;
        r.mesh = mesh_name;
        r.source = src.name();
        double t_ridge = 0, ratio = 0;
        int rings = 0, solves = 0;
        std::size_t winning = 0;
        double precision_max = 0;
        try
        {
          auto run = [&](double t) {
            namespace p = Geodesic_ridge::parameters;
            if(solver == "fmm") return ridge_of(p::solver(Geodesic_ridge::Fast_marching_solver(), options.parameters(t)));
            if(solver == "vtp") return ridge_of(options.cone_parameters(t, Geodesic_ridge::Window_propagation_solver()));
            if(solver == "vtp-cone")
              return ridge_of(p::field(Geodesic_ridge::Field::cone,
                                       options.cone_parameters(t, Geodesic_ridge::Window_propagation_solver())));
            if(solver == "heat") return ridge_of(p::solver(Geodesic_ridge::Heat_method_solver<>(), options.parameters(t)));
            if(solver == "heat-idt")
              return ridge_of(p::solver(Geodesic_ridge::Heat_method_idt_solver(), options.parameters(t)));
            if(solver == "dijkstra") return ridge_of(p::solver(Geodesic_ridge::Dijkstra_solver(), options.parameters(t)));
            if(solver == "cone")
              return ridge_of(p::field(Geodesic_ridge::Field::cone, options.exact_parameters(t)));
            return ridge_of(options.exact_parameters(t));
          };
          // the ridge measured: the one reported (the cone ridge with the exact solver)
          auto measured = [&](const auto& rc) -> const auto& { return rc.ridge_polylines(); };
          const auto t0 = std::chrono::steady_clock::now();
          const auto rc = run(tolerance);
          t_ridge = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          r.topology = read_back(mesh, measured(rc), r.topology_ok);
          if(&measured(rc) != &rc.polylines) r.topology += " / " + read_back(mesh, rc.polylines, r.topology_ok);
          ratio = double(rc.statistics.extended_surface.number_of_faces) / double(mesh.number_of_faces());
          rings = rc.statistics.extended_surface.rings;
          solves = rc.statistics.solves;
          winning = rc.statistics.outer_copies_winning;
          if(reference)
          {
            const auto acc = GT::ridge_accuracy(ref, measured(rc), ref_opt);
            r.precision_major_p95 = acc.precision_p95;
            r.precision_all_p95 = acc.precision_all_p95;
            r.recall_p95 = acc.recall_p95;
            precision_max = acc.precision_max;
            const auto rc_small = run(recall_tolerance);
            r.recall_small_p95 = GT::ridge_accuracy(ref, measured(rc_small), ref_opt).recall_p95;
            if(outliers && !acc.outliers.empty())
            {
              std::size_t near_leaf = 0, near_junction = 0, near_source = 0, minor = 0;
              for(const auto& o : acc.outliers)
              {
                near_leaf += o.to_leaf <= 1.0;
                near_junction += o.to_junction <= 1.0;
                near_source += o.to_source <= 3.0;
                minor += o.nearest_jump < 30;
              }
              std::cout << "  outliers: " << acc.outliers.size() << ": within 1 edge of a leaf " << near_leaf
                        << ", of a junction " << near_junction << ", within 3 edges of the source " << near_source
                        << ", nearest reference jump < 30 deg " << minor << "\n";
            }
          }
          if(diagnose)
          {
            r.diagnosed = true;
            const bool exact = solver == "exact" || solver == "cone" || solver == "vtp" || solver == "vtp-cone";
            auto larger_e = [&] { // fast marching on an E grown from fmm_reference_rings rings everywhere
              namespace p = Geodesic_ridge::parameters;
              const auto np = p::initial_rings(fmm_reference_rings, p::fast_marching_margin(0, p::tolerance(tolerance,
                                               p::solver(Geodesic_ridge::Fast_marching_solver()))));
              return ridge_of(np).vertex_distances;
            };
            const GT::Extension_check check =
                exact ? GT::check_extension(mesh, rc, exact_on_mesh, 1e-9)
                : solver == "fmm" && fmm_reference_rings > 0
                    ? GT::check_extension(mesh, rc, larger_e(), fmm_tolerance)
                    : GT::check_extension(mesh, rc, on_mesh_of(false), fmm_tolerance, fmm_skip_rings);
            r.missing = check.missing.size();
            r.worst_excess = check.worst_excess;
            r.ridge_front_errors = check.front_errors;
            if(solver == "fmm") // the paths: fast marching's E (its growth rule), solved once exactly, against SMSP
            {
              namespace p = Geodesic_ridge::parameters;
              const auto np = p::predicted_extension(true, p::maximum_solves(1, p::cone_ridge(false,
                                                     options.exact_parameters(tolerance))));
              const auto solved = ridge_of(np);
              r.paths_missing = GT::check_extension(mesh, solved, exact_on_mesh, fmm_tolerance).missing.size();
              if(solved.statistics.extended_surface.number_of_faces != rc.statistics.extended_surface.number_of_faces)
                std::cout << "  fast marching's E has " << rc.statistics.extended_surface.number_of_faces
                          << " faces, the E of its growth rule solved exactly "
                          << solved.statistics.extended_surface.number_of_faces << "\n";
            }
          }
        }
        catch(const std::exception& e) { r.failure = e.what(); }
        char line[1024];
        if(!r.failure.empty())
          std::snprintf(line, sizeof line, "| %s | %zu | %ld | %s | %s | failed: %s |\n", mesh_name.c_str(),
                        std::size_t(mesh.number_of_faces()), genus, r.source.c_str(), solver.c_str(), r.failure.c_str());
        else
          std::snprintf(line, sizeof line,
                        "| %s | %zu | %ld | %s | %s | %.3f | %.3f | %.2f | %.3f | %.3f | %.2f | %d | %d | %zu | %s | %s | %s | %s | %.3f |\n",
                        mesh_name.c_str(), std::size_t(mesh.number_of_faces()), genus, r.source.c_str(), solver.c_str(),
                        r.precision_major_p95, r.precision_all_p95, precision_max, r.recall_p95, r.recall_small_p95,
                        ratio, rings, solves, winning, diagnose ? missing_column(r.missing, r.paths_missing, solver).c_str() : "-",
                        diagnose ? std::to_string(r.worst_excess).substr(0, 6).c_str() : "-",
                        diagnose ? std::to_string(r.ridge_front_errors).c_str() : "-", r.topology.c_str(), t_ridge);
        std::cout << line << std::flush;
        results[solver].push_back(r);
      }
    }
  }

  // distribution over the pairs, per solver
  std::cout << "\n| solver | pairs | failed | prec. p95 (>= 30 deg): median / worst (where) | <= 0.25 | <= 0.5 "
               "| prec. p95 (all): median / worst | <= 1 | recall p95 @small: median / worst (where) | <= 0.5 "
               "| pairs missing exact copies | read back not connected with 2g + b cycles |\n"
               "|---|---:|---:|---|---:|---:|---|---:|---|---:|---:|---:|\n";
  for(const auto& [solver, rs] : results)
  {
    std::vector<double> pm, pa, rs_small;
    std::size_t failed = 0, le025 = 0, le05 = 0, le1 = 0, rle05 = 0, with_missing = 0, paths_missing = 0;
    std::size_t wrong_topology = 0;
    const Pair_result* worst_p = nullptr;
    const Pair_result* worst_r = nullptr;
    for(const auto& r : rs)
    {
      if(!r.failure.empty()) { ++failed; continue; }
      wrong_topology += !r.topology_ok;
      pm.push_back(r.precision_major_p95);
      pa.push_back(r.precision_all_p95);
      rs_small.push_back(r.recall_small_p95);
      le025 += r.precision_major_p95 <= 0.25;
      le05 += r.precision_major_p95 <= 0.5;
      le1 += r.precision_all_p95 <= 1.0;
      rle05 += r.recall_small_p95 <= 0.5;
      with_missing += r.missing > 0;
      paths_missing += r.paths_missing > 0;
      if(!worst_p || r.precision_major_p95 > worst_p->precision_major_p95) worst_p = &r;
      if(!worst_r || r.recall_small_p95 > worst_r->recall_small_p95) worst_r = &r;
    }
    const std::size_t n = pm.size();
    char line[1024];
    std::snprintf(line, sizeof line,
                  "| %s | %zu | %zu | %.3f / %.3f (%s %s) | %zu | %zu | %.3f / %.3f | %zu | %.3f / %.3f (%s %s) | %zu | %s | %zu |\n",
                  solver.c_str(), rs.size(), failed, quantile(pm, 0.5), n ? *std::max_element(pm.begin(), pm.end()) : 0.0,
                  worst_p ? worst_p->mesh.c_str() : "-", worst_p ? worst_p->source.c_str() : "-", le025, le05,
                  quantile(pa, 0.5), n ? *std::max_element(pa.begin(), pa.end()) : 0.0, le1, quantile(rs_small, 0.5),
                  n ? *std::max_element(rs_small.begin(), rs_small.end()) : 0.0, worst_r ? worst_r->mesh.c_str() : "-",
                  worst_r ? worst_r->source.c_str() : "-", rle05,
                  diagnose ? missing_column(with_missing, paths_missing, solver).c_str() : "-", wrong_topology);
    std::cout << line;
  }
  return 0;
}
