// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Question: what does the whole pipeline cost, stage by stage, next to one
// exact geodesic solve (CGAL Surface_mesh_shortest_path) on the original mesh?
//
//   bench_geodesic_ridge [--max-faces N] [--tolerance T] [MESH ...]
//
// Without MESH arguments it runs every .off file of ../shared/data (or of the
// repository's data/), smallest first, from vertex 0. Prints a Markdown table.
// Every timing is the fastest of repeated runs (at least 1 s of them, at most 40),
// SMSP and the pipeline alternating.
// Peak memory is the process's maximum resident set size after that mesh
// (meshes run in increasing size, so it is that mesh's peak or an earlier one's).
#include "benchmark_meshes.h"

#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
namespace fs = std::filesystem;

int main(int argc, char** argv)
{
  std::vector<std::string> files;
  Pipeline_options options;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(options.parse(argc, argv, i)) continue;
    if(!a.empty() && a[0] == '-') { std::cerr << "unknown option " << a << "\n"; return 2; }
    else files.push_back(a);
  }
  files = benchmark_meshes(files);

  std::cout << "| mesh | F | genus | F(E)/F | rings | solves | tree distances (s) | stage 1 (s) | extension (s) | solves (s) "
               "| envelope+dominance (s) | assembly (s) | total (s) | one SMSP on M (s) | total / SMSP | peak RSS (MB) "
               "| junctions | cycles |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const std::string& file : files)
  {
    Mesh mesh;
    try { Geodesic_ridge::IO::read_triangle_mesh(file, mesh); }
    catch(const Geodesic_ridge::Error& e) { std::cerr << file << ": " << e.what() << "\n"; continue; }
    if(mesh.number_of_faces() > options.max_faces) continue;
    const Mesh::Vertex_index source(0);

    // Small meshes take milliseconds, and a shared machine is noisy: one SMSP
    // solve and one pipeline run alternate (so both see the same machine),
    // for at least 1 s or 40 rounds, and the fastest of each is reported.
    typedef decltype(Geodesic_ridge::compute_ridge_curve(mesh, source, options.exact_parameters(options.tolerance))) Result;
    Result rc;
    double t_smsp = 1e300, spent = 0;
    try
    {
      for(int k = 0; k < 40 && (k < 1 || spent < 1.0); ++k)
      {
        std::vector<double> d(mesh.number_of_vertices());
        const auto t0 = std::chrono::steady_clock::now();
        Geodesic_ridge::Exact_solver()(mesh, source, CGAL::make_property_map(d));
        const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        t_smsp = std::min(t_smsp, t);
        Result r = Geodesic_ridge::compute_ridge_curve(mesh, source, options.exact_parameters(options.tolerance));
        if(k == 0 || r.timings.total() < rc.timings.total()) rc = std::move(r);
        spent += t + rc.timings.total();
      }
      const auto& s = rc.statistics;
      const auto& time = rc.timings;
      rusage usage;
      getrusage(RUSAGE_SELF, &usage);
      char line[1024];
      std::snprintf(line, sizeof line,
                    "| %s | %zu | %d | %.2f | %d | %d | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.2f | %.0f | %zu | %zu |\n",
                    fs::path(file).filename().string().c_str(), std::size_t(mesh.number_of_faces()), s.rough_cut_locus.genus,
                    double(s.extended_surface.number_of_faces) / mesh.number_of_faces(), s.extended_surface.rings,
                    s.solves, time["tree_distances"], time["rough_cut_locus"], time["extended_surface"], time["solve"],
                    time["envelope_and_dominance"], time["ridge_assembly"], time.total(), t_smsp, time.total() / t_smsp,
                    usage.ru_maxrss / 1024.0,
                    s.ridge.junctions, s.ridge.cycles);
      std::cout << line << std::flush;
    }
    catch(const Geodesic_ridge::Error& e)
    {
      std::cout << "| " << fs::path(file).filename().string() << " | " << mesh.number_of_faces()
                << " | FAILED: " << e.what() << " |\n" << std::flush;
    }
  }
  return 0;
}
