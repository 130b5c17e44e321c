// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Question: how long does stage 1 (the rough cut locus) take, next to one
// exact geodesic solve (CGAL Surface_mesh_shortest_path) on the same mesh?
//
//   bench_rough_cut_locus [--max-faces N] [--no-exact] [--runs R] [MESH ...]
//
// Without MESH arguments it runs every .off file of ../shared/data (or of the
// repository's data/ when ../shared is absent), sorted by size. Times are the
// median of R runs (default 3) of stage 1 from vertex 0 at the default
// tolerance; the exact solve is run once (it dominates). Prints a Markdown table.
#include "benchmark_meshes.h"

#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/rough_cut_locus.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef CGAL::Surface_mesh_shortest_path_traits<K, Mesh>    SMSP_traits;
typedef CGAL::Surface_mesh_shortest_path<SMSP_traits>       SMSP;

namespace fs = std::filesystem;

static double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int main(int argc, char** argv)
{
  std::size_t max_faces = 250000;
  bool exact = true;
  int runs = 3;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--max-faces" && i + 1 < argc) max_faces = std::stoul(argv[++i]);
    else if(a == "--no-exact") exact = false;
    else if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::stoi(argv[++i]));
    else if(!a.empty() && a[0] == '-') { std::cerr << "unknown option " << a << "\n"; return 2; }
    else files.push_back(a);
  }
  files = benchmark_meshes(files);

  std::cout << "| mesh | V | F | genus | Dijkstra (s) | significance (s) | cut graph (s) | disk check (s) "
               "| stage 1 total (s) | kept dual | K edges | K leaves | exact SMSP solve (s) | stage 1 / SMSP |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const std::string& file : files)
  {
    Mesh mesh;
    try { Geodesic_ridge::IO::read_triangle_mesh(file, mesh); }
    catch(const Geodesic_ridge::Error& e) { std::cerr << file << ": " << e.what() << "\n"; continue; }
    if(mesh.number_of_faces() > max_faces) continue;

    std::vector<double> t_tree, t_sig, t_cut, t_check, t_total;
    Geodesic_ridge::Rough_cut_locus<Mesh> r;
    for(int k = 0; k < runs; ++k)
    {
      r = Geodesic_ridge::compute_rough_cut_locus(mesh, Mesh::Vertex_index(0));
      const auto& time = r.timings;
      t_tree.push_back(time["shortest_path_tree"]);
      t_sig.push_back(time["significance"]);
      t_cut.push_back(time["cut_graph"]);
      t_check.push_back(time["disk_check"]);
      t_total.push_back(time.total());
    }
    double t_exact = -1;
    if(exact)
    {
      const auto t0 = std::chrono::steady_clock::now();
      SMSP smsp(mesh);
      smsp.add_source_point(Mesh::Vertex_index(0));
      smsp.build_sequence_tree();
      t_exact = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    const auto& s = r.statistics;
    char line[1024];
    std::snprintf(line, sizeof line,
                  "| %s | %zu | %zu | %d | %.4f | %.4f | %.4f | %.4f | %.4f | %zu | %zu | %zu | %s | %s |\n",
                  fs::path(file).filename().string().c_str(), s.number_of_vertices, s.number_of_faces,
                  s.genus, median(t_tree), median(t_sig), median(t_cut), median(t_check), median(t_total),
                  s.number_of_kept_dual_edges, s.number_of_cut_edges, s.number_of_cut_leaves,
                  t_exact >= 0 ? std::to_string(t_exact).c_str() : "-",
                  t_exact > 0 ? (std::to_string(100 * median(t_total) / t_exact) + " %").c_str() : "-");
    std::cout << line << std::flush;
  }
  return 0;
}
