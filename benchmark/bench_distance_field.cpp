// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Question: how exact is the region-wise distance field at surface points,
// against linear interpolation of exact vertex distances? The paper's Table 1
// (manual, companion page "Details, Measurements and History": "The Distance Field: Table 1 of the Paper, Reproduced"),
// reproduced with both solvers, and the query throughput.
//
//   bench_distance_field [--max-faces N] [--sources-per-mesh N] [--points N] [--seed S]
//                        [--tolerance T] [MESH ...]
//
// Without MESH arguments: the paper's models first (bunny_1k, cheburashka_13k,
// armadillo_2k, trim_star_10k, knot_13k), then every other .off file of
// ../shared/data (or of data/ when ../shared is absent) with at most N faces
// (default 20000), by size.
//
// Per mesh: sources at vertices floor(i V / N), i = 0..N-1 (N default 10);
// P (default 10000) area-uniform random surface points from std::mt19937(seed)
// (seed default 1, printed); the exact distance at each by CGAL's
// Surface_mesh_shortest_path on M. Mean relative error (%) of
//   (a) linear interpolation of the exact vertex distances,
//   (b) the region-wise field with the exact solver,
//   (c) the cone field (exact solver; beyond the paper),
//   (d) the region-wise field with fast marching,
//   (e) the cone field with the window-propagation solver (vtp: the exact
//       lower envelope of its windows),
// over the points (those at distance 0 skipped), and the largest relative
// error at one point of (c) and (e) over all sources (issue 38's target for
// (e): 1e-9). The table gives, per mesh, the
// median over sources of each, the median and the worst of (b)/(a) and (c)/(a),
// the least over sources of the share of (a)'s error in the faces that hold
// one cell (there (b) is (a), so (b)/(a) cannot fall below that share),
// and the in-process query throughput of the linear and the cone field
// (queries per second, a million queries over the same points), and the time
// of the exact pipeline with and without the cones and of vtp's with the cone
// field (median over sources).
#include "benchmark_meshes.h"

#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/distance_field.h>
#include <Geodesic_ridge/solvers/Window_propagation_solver.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index face_descriptor;
typedef std::pair<face_descriptor, std::array<double, 3> > Location;

// n points uniform by area: a face drawn with probability proportional to its
// area, then a point uniform on it.
std::vector<Location> area_uniform_points(const Mesh& m, std::size_t n, unsigned seed)
{
  std::vector<double> area;
  for(auto f : m.faces())
  {
    const auto h = m.halfedge(f);
    area.push_back(std::sqrt(CGAL::squared_area(m.point(m.source(h)), m.point(m.target(h)),
                                                m.point(m.target(m.next(h))))));
  }
  std::mt19937 rng(seed);
  std::discrete_distribution<std::size_t> face(area.begin(), area.end());
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Location> out;
  for(std::size_t i = 0; i < n; ++i)
  {
    const face_descriptor f(static_cast<Mesh::size_type>(face(rng)));
    const double r1 = std::sqrt(unit(rng)), r2 = unit(rng);
    out.emplace_back(f, std::array<double, 3>{{1 - r1, r1 * (1 - r2), r1 * r2}});
  }
  return out;
}

double median(std::vector<double> v)
{
  if(v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

struct Paper_row { const char* name; double linear, split; };
const Paper_row paper[] = {{"bunny_1k", 0.4427, 0.1945},      {"cheburashka_13k", 0.2201, 0.0884},
                           {"armadillo_2k", 0.1966, 0.0726},  {"trim_star_10k", 0.2243, 0.0312},
                           {"knot_13k", 0.0421, 0.0150}};

} // namespace

int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  std::size_t max_faces = 20000, per_mesh = 10, points = 10000;
  unsigned seed = 1;
  double tolerance = Geodesic_ridge::default_tolerance;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--max-faces" && i + 1 < argc) max_faces = std::stoul(argv[++i]);
    else if(a == "--sources-per-mesh" && i + 1 < argc) per_mesh = std::stoul(argv[++i]);
    else if(a == "--points" && i + 1 < argc) points = std::stoul(argv[++i]);
    else if(a == "--seed" && i + 1 < argc) seed = static_cast<unsigned>(std::stoul(argv[++i]));
    else if(a == "--tolerance" && i + 1 < argc) tolerance = std::stod(argv[++i]);
    else if(a.size() > 1 && a[0] == '-') { std::cerr << "unknown option " << a << "\n"; return 2; }
    else files.push_back(a);
  }
  const bool chosen = !files.empty();
  files = benchmark_meshes(files);
  // the paper's models first
  std::stable_sort(files.begin(), files.end(), [](const std::string& a, const std::string& b) {
    auto rank = [](const std::string& f) {
      const std::string stem = fs::path(f).stem().string();
      for(std::size_t i = 0; i < sizeof(paper) / sizeof(paper[0]); ++i)
        if(stem == paper[i].name) return int(i);
      return 100;
    };
    return rank(a) < rank(b);
  });
  std::printf("# Region-wise distance field vs linear interpolation (DESIGN.md §6, paper Table 1)\n\n"
              "%zu sources per mesh (vertices floor(i V / %zu)), %zu area-uniform points per source "
              "(std::mt19937 seed %u), tolerance %g. Mean relative error in %%, median over sources; "
              "(b)/(a): median and worst over sources.\n\n",
              per_mesh, per_mesh, points, seed, tolerance);
  std::printf("| mesh | faces | (a) linear | (b) ridge-split, exact | (c) cone | (d) ridge-split, fmm | (b)/(a) median | "
              "(b)/(a) worst | (a) in unsplit faces / (a), least | (c)/(a) median | (c)/(a) worst | (d)/(a) median | "
              "(c) largest | (e) cone, vtp | (e) largest | "
              "paper (a) → (b) | queries/s linear, cone, vtp cone | exact pipeline s, with cones; vtp with cones |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n");
  std::fflush(stdout);
  for(const std::string& file : files)
  {
    Mesh mesh;
    Geodesic_ridge::IO::read_triangle_mesh(file, mesh);
    if(!chosen && mesh.number_of_faces() > max_faces) continue;
    const std::vector<Location> sample = area_uniform_points(mesh, points, seed);
    std::vector<double> a_err, b_err, c_err, d_err, e_err, ratio_b, ratio_c, ratio_d, time_linear, time_cone,
        time_vtp, unsplit_share;
    double queries_per_second = 0, cone_queries_per_second = 0, vtp_queries_per_second = 0;
    double c_largest = 0, e_largest = 0;
    for(std::size_t s = 0; s < per_mesh; ++s)
    {
      const Mesh::Vertex_index source(static_cast<Mesh::size_type>(s * mesh.number_of_vertices() / per_mesh));
      typedef CGAL::Surface_mesh_shortest_path_traits<K, Mesh> Traits;
      CGAL::Surface_mesh_shortest_path<Traits> sp(mesh);
      sp.add_source_point(source);
      sp.build_sequence_tree();
      std::vector<double> exact_vertex(mesh.number_of_vertices());
      for(auto v : mesh.vertices()) exact_vertex[std::size_t(v)] = sp.shortest_distance_to_source_points(v).first;
      std::vector<double> exact(sample.size());
      for(std::size_t i = 0; i < sample.size(); ++i)
        exact[i] = sp.shortest_distance_to_source_points(
                         sample[i].first, {{sample[i].second[0], sample[i].second[1], sample[i].second[2]}})
                       .first;
      namespace p = Geodesic_ridge::parameters;
      auto t0 = std::chrono::steady_clock::now();
      const auto ridge_linear = Geodesic_ridge::compute_ridge_curve(mesh, source, p::tolerance(tolerance));
      time_linear.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      t0 = std::chrono::steady_clock::now();
      const auto ridge_cone =
          Geodesic_ridge::compute_ridge_curve(mesh, source, p::tolerance(tolerance, p::field(Geodesic_ridge::Field::cone)));
      time_cone.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      t0 = std::chrono::steady_clock::now();
      const auto ridge_vtp = Geodesic_ridge::compute_ridge_curve(
          mesh, source,
          p::tolerance(tolerance, p::field(Geodesic_ridge::Field::cone, p::solver(Geodesic_ridge::Window_propagation_solver()))));
      time_vtp.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      const auto field_exact = Geodesic_ridge::make_distance_field(mesh, ridge_linear);
      const auto field_cone = Geodesic_ridge::make_distance_field(mesh, ridge_cone, p::field(Geodesic_ridge::Field::cone));
      const auto field_fmm = Geodesic_ridge::compute_distance_field(
          mesh, source, p::tolerance(tolerance, p::solver(Geodesic_ridge::Fast_marching_solver())));
      const auto field_vtp = Geodesic_ridge::make_distance_field(mesh, ridge_vtp, p::field(Geodesic_ridge::Field::cone));
      std::vector<double> b, c, d, e;
      field_exact.distances(sample, std::back_inserter(b));
      field_cone.distances(sample, std::back_inserter(c));
      field_fmm.distances(sample, std::back_inserter(d));
      field_vtp.distances(sample, std::back_inserter(e));
      double ea = 0, eb = 0, ec = 0, ed = 0, ee = 0, ea_unsplit = 0;
      std::size_t n = 0;
      for(std::size_t i = 0; i < sample.size(); ++i)
      {
        if(!(exact[i] > 0)) continue;
        const auto h = mesh.halfedge(sample[i].first);
        const std::array<std::size_t, 3> corner = {{std::size_t(mesh.source(h)), std::size_t(mesh.target(h)),
                                                    std::size_t(mesh.target(mesh.next(h)))}};
        const double linear = sample[i].second[0] * exact_vertex[corner[0]] +
                              sample[i].second[1] * exact_vertex[corner[1]] +
                              sample[i].second[2] * exact_vertex[corner[2]];
        ea += std::abs(linear - exact[i]) / exact[i];
        if(field_exact.number_of_cells(sample[i].first) == 1) ea_unsplit += std::abs(linear - exact[i]) / exact[i];
        eb += std::abs(b[i] - exact[i]) / exact[i];
        ec += std::abs(c[i] - exact[i]) / exact[i];
        ed += std::abs(d[i] - exact[i]) / exact[i];
        ee += std::abs(e[i] - exact[i]) / exact[i];
        c_largest = (std::max)(c_largest, std::abs(c[i] - exact[i]) / exact[i]);
        e_largest = (std::max)(e_largest, std::abs(e[i] - exact[i]) / exact[i]);
        if(!(std::abs(e[i] - exact[i]) <= 1e-9 * exact[i]))
          std::fprintf(stderr, "  vtp cone field off at face %zu (%.17g %.17g %.17g): %.17g, exact %.17g\n",
                       std::size_t(sample[i].first), sample[i].second[0], sample[i].second[1], sample[i].second[2],
                       e[i], exact[i]);
        ++n;
      }
      a_err.push_back(100 * ea / n);
      b_err.push_back(100 * eb / n);
      c_err.push_back(100 * ec / n);
      ratio_c.push_back(ec / ea);
      d_err.push_back(100 * ed / n);
      e_err.push_back(100 * ee / n);
      ratio_b.push_back(eb / ea);
      ratio_d.push_back(ed / ea);
      unsplit_share.push_back(ea_unsplit / ea);
      if(s == 0)
      {
        // throughput: a million queries over the sample, in process
        auto throughput = [&](const auto& field) {
          std::vector<double> out(sample.size());
          const std::size_t rounds = (1000000 + sample.size() - 1) / sample.size();
          double checksum = 0;
          const auto t1 = std::chrono::steady_clock::now();
          for(std::size_t r = 0; r < rounds; ++r)
          {
            field.distances(sample, out.begin());
            checksum += out[r % out.size()];
          }
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
          if(checksum < 0) std::printf("impossible\n");
          return double(rounds * sample.size()) / seconds;
        };
        queries_per_second = throughput(field_exact);
        cone_queries_per_second = throughput(field_cone);
        vtp_queries_per_second = throughput(field_vtp);
      }
      std::fprintf(stderr, "%s source %zu: (a) %.4f (b) %.4f (c) %.4f (d) %.4f (e) %.3g\n", fs::path(file).stem().c_str(),
                   std::size_t(source), a_err.back(), b_err.back(), c_err.back(), d_err.back(), e_err.back());
    }
    const std::string stem = fs::path(file).stem().string();
    std::string paper_text = "";
    for(const Paper_row& r : paper)
      if(stem == r.name)
      {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.4f → %.4f", r.linear, r.split);
        paper_text = buf;
      }
    std::printf("| %s | %zu | %.4f | %.4f | %.5f | %.4f | %.3f | %.3f | %.3f | %.4f | %.4f | %.3f | %.2g | %.2g | %.2g | %s | "
                "%.3g, %.3g, %.3g | %.3g, %.3g; %.3g |\n",
                stem.c_str(), std::size_t(mesh.number_of_faces()), median(a_err), median(b_err), median(c_err),
                median(d_err), median(ratio_b), *std::max_element(ratio_b.begin(), ratio_b.end()),
                *std::min_element(unsplit_share.begin(), unsplit_share.end()), median(ratio_c),
                *std::max_element(ratio_c.begin(), ratio_c.end()), median(ratio_d), c_largest, median(e_err),
                e_largest, paper_text.c_str(), queries_per_second, cone_queries_per_second, vtp_queries_per_second,
                median(time_linear), median(time_cone), median(time_vtp));
    std::fflush(stdout);
  }
  return 0;
}
