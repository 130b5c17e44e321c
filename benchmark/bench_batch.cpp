// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bench_batch: how much faster is a batch of sources (compute_ridge_curves)
// than a loop of single calls (compute_ridge_curve) in one process?
//
//   bench_batch [MESH] [--sources N] [--solver fmm|exact] [--repeats R]
//
// Default: torus_10k of ../shared/data (data/torus_1k.off without it), 64
// vertex sources floor(i V / N), fast marching, the fastest of 3 repeats.
// Prints one Markdown row per way: the loop of single calls, the batch run
// serially (the source-independent work shared), the batch in parallel (TBB,
// all cores); speed-ups against the loop, and per core. Every way's ridges
// are compared with the loop's, point for point: a difference is an error.
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/compute_geodesic_ridges.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <boost/iterator/function_output_iterator.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Geodesic_ridge::Ridge_curve<Mesh, K::Point_3> Ridge;

namespace {

template <class F>
double fastest(int repeats, const F& f)
{
  double best = 1e300;
  for(int r = 0; r < repeats; ++r)
  {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

// A ridge's points, all that is kept of a result (keeping whole results would
// measure the allocator more than the pipeline)
typedef std::vector<std::vector<K::Point_3> > Points;

Points points_of(const Ridge& r)
{
  Points p;
  Geodesic_ridge::ridge_polyline_points(r.polylines, std::back_inserter(p));
  return p;
}

template <class NP>
int run(const Mesh& mesh, const std::vector<vertex_descriptor>& sources, int repeats, const NP& np)
{
  std::vector<Points> loop, serial, parallel;
  auto keep_in = [](std::vector<Points>& v) {
    return boost::make_function_output_iterator([&v](const Ridge& r) { v.push_back(points_of(r)); });
  };
  const double t_loop = fastest(repeats, [&] {
    loop.clear();
    for(vertex_descriptor s : sources) loop.push_back(points_of(Geodesic_ridge::compute_ridge_curve(mesh, s, np)));
  });
  const double t_serial = fastest(repeats, [&] {
    serial.clear();
    Geodesic_ridge::compute_ridge_curves<CGAL::Sequential_tag>(mesh, sources, keep_in(serial), np);
  });
  const double t_parallel = fastest(repeats, [&] {
    parallel.clear();
    Geodesic_ridge::compute_ridge_curves<CGAL::Parallel_if_available_tag>(mesh, sources, keep_in(parallel), np);
  });
  int cores = 1;
#ifdef CGAL_LINKED_WITH_TBB
  cores = tbb::this_task_arena::max_concurrency();
#endif
  std::printf("| way | seconds | per source (ms) | speed-up over the loop | per core |\n|---|---:|---:|---:|---:|\n");
  const double n = double(sources.size());
  std::printf("| loop of single calls | %.3f | %.1f | 1.00 | 1.00 |\n", t_loop, 1e3 * t_loop / n);
  std::printf("| batch, serial | %.3f | %.1f | %.2f | %.2f |\n", t_serial, 1e3 * t_serial / n, t_loop / t_serial,
              t_loop / t_serial);
  std::printf("| batch, parallel (%d threads) | %.3f | %.1f | %.2f | %.2f |\n", cores, t_parallel,
              1e3 * t_parallel / n, t_loop / t_parallel, t_loop / t_parallel / cores);
  const bool ok = loop == serial && loop == parallel;
  std::printf("\nridges identical to the loop's: %s\n", ok ? "yes" : "NO");
  return ok ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  std::string file = std::string(GEODESIC_RIDGE_SHARED_DATA_DIR) + "/torus_10k.off";
  if(!fs::exists(file)) file = std::string(GEODESIC_RIDGE_DATA_DIR) + "/torus_1k.off";
  std::size_t n = 64;
  int repeats = 3;
  std::string solver = "fmm";
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--sources" && i + 1 < argc) n = std::stoul(argv[++i]);
    else if(a == "--repeats" && i + 1 < argc) repeats = std::stoi(argv[++i]);
    else if(a == "--solver" && i + 1 < argc) solver = argv[++i];
    else if(!a.empty() && a[0] != '-') file = a;
    else { std::cerr << "usage: bench_batch [MESH] [--sources N] [--solver fmm|exact] [--repeats R]\n"; return 2; }
  }
  if(solver != "fmm" && solver != "exact") { std::cerr << "unknown solver " << solver << "\n"; return 2; }
  Mesh mesh;
  Geodesic_ridge::IO::read_triangle_mesh(file, mesh);
  std::vector<vertex_descriptor> sources;
  for(std::size_t i = 0; i < n; ++i)
    sources.push_back(vertex_descriptor(static_cast<Mesh::size_type>(i * mesh.number_of_vertices() / n)));
  std::printf("bench_batch: %s (%zu faces), %zu vertex sources floor(i V / %zu), solver %s, fastest of %d\n\n",
              fs::path(file).filename().string().c_str(), std::size_t(mesh.number_of_faces()), n, n, solver.c_str(),
              repeats);
  namespace p = Geodesic_ridge::parameters;
  if(solver == "fmm") return run(mesh, sources, repeats, p::solver(Geodesic_ridge::Fast_marching_solver()));
  return run(mesh, sources, repeats, p::solver(Geodesic_ridge::Exact_solver()));
}
