// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Question: what does the exact lower envelope of one face cost, per number
// type, for m = 2, 4, 8 copies with solver-like distances?
//
//   bench_lower_envelope [--faces N]
//
// Distances: a point source at a random position in the plane of a unit
// triangle, seen from m mirror images (so that the fields cross inside the
// face, as copies of different fronts do), plus a tiny noise. Each column is
// the mean time per face over N random faces (default 20000). "Gmpq (Mpzf
// ring)" is what the pipeline uses: clipping in CGAL::Mpzf, normalization in
// CGAL::Gmpq; "Gmpq (Gmpq ring)" runs everything in CGAL::Gmpq.
#include <Geodesic_ridge/lower_envelope.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Random.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace GR = Geodesic_ridge;
typedef std::vector<std::array<double, 3> > Fields;

int main(int argc, char** argv)
{
  int faces = 20000;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--faces" && i + 1 < argc) faces = std::stoi(argv[++i]);
    else { std::cerr << "unknown option " << a << "\n"; return 2; }
  }
  const double corner[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  std::cout << "| copies m | faces with 2+ cells | Epeck FT (µs) | Gmpq, Mpzf ring (µs) | Gmpq, Gmpq ring (µs) "
               "| double (µs) |\n|---:|---:|---:|---:|---:|---:|\n";
  for(int m : {2, 4, 8})
  {
    CGAL::Random rng(20261201 + m);
    std::vector<Fields> input(faces, Fields(m));
    for(Fields& f : input)
      for(int i = 0; i < m; ++i)
      {
        // a virtual source per copy, at distance 3-6 from the face
        const double angle = rng.get_double(0, 2 * 3.141592653589793), r = rng.get_double(3, 6);
        const double sx = 0.33 + r * std::cos(angle), sy = 0.33 + r * std::sin(angle);
        const double offset = rng.get_double(0, 0.5);
        for(int k = 0; k < 3; ++k)
          f[i][k] = offset + std::hypot(corner[k][0] - sx, corner[k][1] - sy) + rng.get_double(0, 1e-9);
      }
    std::size_t split = 0;
    auto time = [&](auto compute) {
      const auto t0 = std::chrono::steady_clock::now();
      std::size_t cells = 0;
      for(const Fields& f : input) cells += compute(f);
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      split = cells;
      return 1e6 * t / faces;
    };
    const double t_epeck = time([](const Fields& f) {
      return GR::compute_lower_envelope<CGAL::Exact_predicates_exact_constructions_kernel::FT>(f).cells.size() > 1;
    });
    const double t_mpzf = time([](const Fields& f) { return GR::compute_lower_envelope<CGAL::Gmpq>(f).cells.size() > 1; });
    const double t_gmpq = time([](const Fields& f) {
      return GR::internal::lower_envelope::compute<CGAL::Gmpq, CGAL::Gmpq>(f).cells.size() > 1;
    });
    const double t_double = time([](const Fields& f) { return GR::compute_lower_envelope<double>(f).cells.size() > 1; });
    std::printf("| %d | %zu | %.1f | %.1f | %.1f | %.1f |\n", m, split, t_epeck, t_mpzf, t_gmpq, t_double);
  }
  return 0;
}
