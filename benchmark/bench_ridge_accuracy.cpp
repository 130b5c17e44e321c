// Copyright (c) 2026 Geodesic_ridge developers.
//
// Question: how close is the computed ridge to the exact one (DESIGN.md §6)?
//
//   bench_ridge_accuracy [--max-faces N] [--tolerance T] [--recall-tolerance T]
//                        [--spacing S] [--min-jump DEG] [--outliers] [MESH ...]
//
// Without MESH arguments it runs every .off file of ../shared/data (or of the
// repository's data/ when ../shared is absent) with at most N faces (default
// 20000), sorted by size. Sources: vertex 0 and vertex V/2. The reference ridge
// is built from exact SMSP arrival directions (test/support/reference_ridge.h).
// Precision (computed -> reference, samples every 0.1 mean edge) is split into
// the part near reference points with a direction jump >= 30 degrees and the
// ill-conditioned rest; recall is from reference points with a jump >= 60
// degrees, at the default tolerance and at a small one (0.005, where branches
// are not pruned). All distances in mean edge lengths. Prints a Markdown table;
// with --outliers, also where the computed samples > 0.5 mean edge off lie.
#include "../test/support/reference_ridge.h"

#include "benchmark_meshes.h"

#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

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
namespace GT = Geodesic_ridge::testing;

int main(int argc, char** argv)
{
  std::size_t max_faces = 20000;
  double tolerance = 0.025, recall_tolerance = 0.005;
  bool outliers = false;
  GT::Reference_ridge_options ref_opt;
  std::vector<std::string> files;
  Pipeline_options options;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(options.parse(argc, argv, i)) continue;
    if(a == "--max-faces" && i + 1 < argc) max_faces = std::stoul(argv[++i]);
    else if(a == "--tolerance" && i + 1 < argc) tolerance = std::stod(argv[++i]);
    else if(a == "--recall-tolerance" && i + 1 < argc) recall_tolerance = std::stod(argv[++i]);
    else if(a == "--spacing" && i + 1 < argc) ref_opt.spacing = std::stod(argv[++i]);
    else if(a == "--min-jump" && i + 1 < argc) ref_opt.min_jump_degrees = std::stod(argv[++i]);
    else if(a == "--outliers") outliers = true;
    else if(!a.empty() && a[0] == '-') { std::cerr << "unknown option " << a << "\n"; return 2; }
    else files.push_back(a);
  }
  files = benchmark_meshes(files);

  std::cout << "Distances in mean edge lengths. Precision: computed ridge samples -> reference ridge, "
               "split by the jump of the nearest reference point (>= 30 deg | < 30 deg); recall: reference "
               "points with jump >= 60 deg -> computed ridge, at tolerance "
            << tolerance << " and " << recall_tolerance << ".\n\n"
            << "| mesh | F | genus | source | prec. median | prec. p95 | prec. max | prec. p95 (<30 deg) "
               "| recall median | recall p95 | recall p95 @" << recall_tolerance << " | ridge length "
               "| outliers > 0.5 | compute_ridge_curve (s) | reference (s) | ref. points | ref. queries |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const std::string& file : files)
  {
    Mesh mesh;
    try { Geodesic_ridge::IO::read_triangle_mesh(file, mesh); }
    catch(const Geodesic_ridge::Error& e) { std::cerr << file << ": " << e.what() << "\n"; continue; }
    if(mesh.number_of_faces() > max_faces) continue;
    const long chi = long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces());
    const long genus = (2 - chi) / 2;

    for(std::size_t sv : {std::size_t(0), std::size_t(mesh.number_of_vertices() / 2)})
    {
      const Mesh::Vertex_index s(static_cast<Mesh::size_type>(sv));
      const GT::Reference_ridge<K::Point_3> ref = GT::reference_ridge(mesh, s, ref_opt);
      double t_ridge = 0;
      GT::Ridge_accuracy<K::Point_3> acc, acc_small;
      std::string failure;
      try
      {
        const auto t0 = std::chrono::steady_clock::now();
        const auto rc = Geodesic_ridge::compute_ridge_curve(mesh, s, options.parameters(tolerance));
        t_ridge = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        acc = GT::ridge_accuracy(ref, rc.polylines, ref_opt);
        const auto rc_small =
            Geodesic_ridge::compute_ridge_curve(mesh, s, options.parameters(recall_tolerance));
        acc_small = GT::ridge_accuracy(ref, rc_small.polylines, ref_opt);
      }
      catch(const std::exception& e) { failure = e.what(); }
      char line[1024];
      if(!failure.empty())
      {
        std::snprintf(line, sizeof line, "| %s | %zu | %ld | v%zu | failed: %s |\n",
                      fs::path(file).filename().string().c_str(), std::size_t(mesh.number_of_faces()), genus, sv,
                      failure.c_str());
        std::cout << line << std::flush;
        continue;
      }
      std::snprintf(line, sizeof line,
                    "| %s | %zu | %ld | v%zu | %.3f | %.3f | %.2f | %.3f | %.3f | %.3f | %.3f | %.1f | %zu / %zu "
                    "| %.3f | %.3f | %zu | %zu |\n",
                    fs::path(file).filename().string().c_str(), std::size_t(mesh.number_of_faces()), genus, sv,
                    acc.precision_median, acc.precision_p95, acc.precision_max, acc.precision_minor_p95,
                    acc.recall_median, acc.recall_p95, acc_small.recall_p95, acc.ridge_length,
                    acc.outliers.size(), acc.computed_samples, t_ridge, ref.time_total, ref.points.size(),
                    ref.samples);
      std::cout << line << std::flush;
      if(outliers && !acc.outliers.empty())
      {
        std::size_t near_leaf = 0, near_junction = 0, near_source = 0, minor = 0;
        double worst = 0;
        for(const auto& o : acc.outliers)
        {
          near_leaf += o.to_leaf <= 1.0;
          near_junction += o.to_junction <= 1.0;
          near_source += o.to_source <= 3.0;
          minor += o.nearest_jump < 30;
          worst = std::max(worst, o.distance);
        }
        std::cout << "  outliers: " << acc.outliers.size() << " (worst " << worst << "): within 1 edge of a leaf "
                  << near_leaf << ", of a junction " << near_junction << ", within 3 edges of the source "
                  << near_source << ", nearest reference jump < 30 deg " << minor << "\n";
      }
    }
  }
  return 0;
}
