// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The meshes a benchmark runs on when none is given: every .off file of
// ../shared/data, or of the repository's data/ when ../shared is absent,
// smallest file first.
#ifndef GEODESIC_RIDGE_BENCHMARK_MESHES_H
#define GEODESIC_RIDGE_BENCHMARK_MESHES_H

#include <Geodesic_ridge/compute_geodesic_ridge.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

inline std::vector<std::string> benchmark_meshes(std::vector<std::string> files)
{
  namespace fs = std::filesystem;
  if(files.empty())
  {
    fs::path dir = GEODESIC_RIDGE_SHARED_DATA_DIR;
    if(!fs::is_directory(dir)) dir = GEODESIC_RIDGE_DATA_DIR;
    for(const auto& entry : fs::directory_iterator(dir))
      if(entry.path().extension() == ".off") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end(),
            [](const std::string& a, const std::string& b) { return fs::file_size(a) < fs::file_size(b); });
  return files;
}

/// The pipeline's knobs, settable from a benchmark's command line, so that
/// schedules can be compared on the same meshes:
///   --max-faces N (default 20000; larger meshes are skipped) --tolerance T
///   --initial-rings K --extension-step K --maximum-rings K --maximum-solves K --fast-marching-margin K
///   --spur-angle DEG --tree-from-solver 0|1 --predicted 0|1
///   --leaf-curvature DEG --branch-curvature DEG --kink-angle DEG --corner-fallback 0|1
///   --cone-ridge 0|1 (with the solvers that have cones: `cone_parameters()`)
///   --without PASS[,PASS...]: stage 3's optional passes and spur rules switched off (the names:
///     `internal::ridge_pass_names()`, printed for an unknown one)
struct Pipeline_options
{
  int initial_rings = Geodesic_ridge::default_initial_rings, extension_step = Geodesic_ridge::default_extension_step,
      maximum_rings = Geodesic_ridge::default_maximum_rings,
      maximum_solves = Geodesic_ridge::default_maximum_solves,
      fast_marching_margin = Geodesic_ridge::default_fast_marching_margin;
  bool tree_from_solver = false, predicted = true, corner_fallback = true, cone_ridge = true;
  double spur_angle = Geodesic_ridge::default_minimum_spur_angle,
         leaf_curvature = Geodesic_ridge::default_leaf_curvature, kink_angle = Geodesic_ridge::default_kink_angle,
         branch_curvature = Geodesic_ridge::default_branch_curvature;
  unsigned disabled_passes = 0; // a bit per switched-off pass (`internal::Ridge_pass`)
  std::size_t max_faces = 20000; // larger meshes are skipped
  double tolerance = Geodesic_ridge::default_tolerance;

  /// consumes argv[i] (and its value) if it is one of the options above
  bool parse(int argc, char** argv, int& i)
  {
    const std::string a = argv[i];
    if(i + 1 >= argc) return false;
    if(a == "--max-faces") max_faces = std::stoul(argv[++i]);
    else if(a == "--tolerance") tolerance = std::stod(argv[++i]);
    else if(a == "--initial-rings") initial_rings = std::stoi(argv[++i]);
    else if(a == "--extension-step") extension_step = std::stoi(argv[++i]);
    else if(a == "--maximum-rings") maximum_rings = std::stoi(argv[++i]);
    else if(a == "--maximum-solves") maximum_solves = std::stoi(argv[++i]);
    else if(a == "--fast-marching-margin") fast_marching_margin = std::stoi(argv[++i]);
    else if(a == "--leaf-curvature") leaf_curvature = std::stod(argv[++i]);
    else if(a == "--predicted") predicted = std::stoi(argv[++i]) != 0;
    else if(a == "--tree-from-solver") tree_from_solver = std::stoi(argv[++i]) != 0;
    else if(a == "--spur-angle") spur_angle = std::stod(argv[++i]);
    else if(a == "--kink-angle") kink_angle = std::stod(argv[++i]);
    else if(a == "--corner-fallback") corner_fallback = std::stoi(argv[++i]) != 0;
    else if(a == "--cone-ridge") cone_ridge = std::stoi(argv[++i]) != 0;
    else if(a == "--branch-curvature") branch_curvature = std::stod(argv[++i]);
    else if(a == "--without") disabled_passes |= ridge_passes(argv[++i]);
    else return false;
    return true;
  }

  /// the bits of a comma-separated list of pass names; exits on an unknown one
  static unsigned ridge_passes(const std::string& list)
  {
    unsigned bits = 0;
    std::stringstream names(list);
    for(std::string name; std::getline(names, name, ',');)
    {
      bool known = false;
      for(const auto& [n, pass] : Geodesic_ridge::internal::ridge_pass_names())
        if(name == n) { bits |= static_cast<unsigned>(pass); known = true; }
      if(known) continue;
      std::cerr << "--without: unknown pass '" << name << "'; the passes:";
      for(const auto& np : Geodesic_ridge::internal::ridge_pass_names()) std::cerr << ' ' << np.first;
      std::cerr << '\n';
      std::exit(2);
    }
    return bits;
  }

  auto parameters(double tolerance) const
  {
    namespace p = Geodesic_ridge::parameters;
    return p::tolerance(tolerance, p::initial_rings(initial_rings, p::extension_step(extension_step,
           p::maximum_rings(maximum_rings, p::maximum_solves(maximum_solves,
           p::minimum_spur_angle(spur_angle, p::tree_from_solver(tree_from_solver, p::predicted_extension(predicted,
           p::leaf_curvature(leaf_curvature, p::branch_curvature(branch_curvature, p::kink_angle(kink_angle,
           p::corner_fallback(corner_fallback, p::fast_marching_margin(fast_marching_margin,
           p::disabled_ridge_passes(disabled_passes))))))))))))));
  }

  /// with a solver that has cones (exact, vtp): the parameters and whether
  /// the ridge is the cone ridge
  template <class Solver>
  auto cone_parameters(double tolerance, const Solver& solver) const
  {
    namespace p = Geodesic_ridge::parameters;
    return p::cone_ridge(cone_ridge, p::solver(solver, parameters(tolerance)));
  }

  /// with the exact solver: `cone_parameters()`
  auto exact_parameters(double tolerance) const { return cone_parameters(tolerance, Geodesic_ridge::Exact_solver()); }
};

#endif
