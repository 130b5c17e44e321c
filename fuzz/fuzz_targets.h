// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fuzz targets (issue 41): one function per target, shared by the libFuzzer
// binaries (fuzz_<name>.cpp, built by scripts/fuzz.sh with clang) and by the
// regression runner (fuzz_regression.cpp, built by CMake with any compiler).
// Every target returns 0 on any input: the library's typed exceptions
// (Geodesic_ridge::Error and its subclasses) are expected and ignored; any
// other exception escapes, and a wrong result calls abort(), so that libFuzzer
// (or the runner) reports them.
//
// A file that defines GR_FUZZ_READERS_ONLY or GR_FUZZ_PIPELINE_ONLY before
// including this header instantiates only that half (shorter builds).

#ifndef GEODESIC_RIDGE_FUZZ_TARGETS_H
#define GEODESIC_RIDGE_FUZZ_TARGETS_H

#include <Geodesic_ridge/exceptions.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#ifndef GR_FUZZ_PIPELINE_ONLY
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <unistd.h>
#endif
#ifndef GR_FUZZ_READERS_ONLY
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <algorithm>
#include <array>
#endif

namespace gr_fuzz {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

#ifndef GR_FUZZ_PIPELINE_ONLY
// The reader takes a file name (its extension picks the format), so the bytes
// go to a file of this process's own (the pid: parallel fuzzers do not clash).
inline int read_bytes_as(const char* extension, const uint8_t* data, std::size_t size, bool repair)
{
  const std::string path = "/tmp/geodesic_ridge_fuzz_" + std::to_string(::getpid()) + "." + extension;
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try
  {
    Mesh mesh;
    Geodesic_ridge::IO::read_triangle_mesh(path, mesh, Geodesic_ridge::parameters::repair(repair));
  }
  catch(const Geodesic_ridge::Error&)
  {
    // a refused file is a correct answer
  }
  std::remove(path.c_str());
  return 0;
}

// Both branches of the reader (plain validation, and repair_mesh()) are
// exercised; the last byte picks one, so the corpus stays plain files.
inline bool repair_flag(const uint8_t* data, std::size_t size) { return size > 0 && (data[size - 1] & 1) == 0; }

inline int fuzz_off(const uint8_t* data, std::size_t size) { return read_bytes_as("off", data, size, repair_flag(data, size)); }
inline int fuzz_obj(const uint8_t* data, std::size_t size) { return read_bytes_as("obj", data, size, repair_flag(data, size)); }
// ASCII and binary PLY both go through the one PLY reader.
inline int fuzz_ply(const uint8_t* data, std::size_t size) { return read_bytes_as("ply", data, size, repair_flag(data, size)); }
#endif

#ifndef GR_FUZZ_READERS_ONLY
// The whole pipeline on a tiny mesh built from the bytes: byte 0 gives the
// vertex count (3..40), then 3 bytes per vertex (coordinates in [-2, 2), on a
// grid of 1/64 so that degeneracies are frequent), then 3 bytes per face
// (indices mod the vertex count, at most 64 faces). Missing bytes read as 0.
inline int fuzz_pipeline(const uint8_t* data, std::size_t size)
{
  std::size_t pos = 0;
  auto next = [&]() -> uint8_t { return pos < size ? data[pos++] : (++pos, 0); };
  const std::size_t n_vertices = 3 + next() % 38;
  Mesh mesh;
  for(std::size_t i = 0; i < n_vertices; ++i)
  {
    std::array<double, 3> c;
    for(double& x : c) x = static_cast<int8_t>(next()) / 64.0;
    mesh.add_vertex(Kernel::Point_3(c[0], c[1], c[2]));
  }
  const std::size_t n_faces = std::min<std::size_t>(64, size > pos ? (size - pos) / 3 : 0);
  if(n_faces == 0) return 0;
  for(std::size_t f = 0; f < n_faces; ++f)
  {
    const Mesh::Vertex_index a(next() % n_vertices), b(next() % n_vertices), c(next() % n_vertices);
    // CGAL refuses non-manifold or repeated faces: not a mesh, nothing to test
    if(a == b || b == c || a == c || mesh.add_face(a, b, c) == Mesh::null_face()) return 0;
  }
  try
  {
    const auto rc = Geodesic_ridge::compute_ridge_curve(mesh, Mesh::Vertex_index(0));
    // the documented postcondition: the ridge is connected
    if(rc.statistics.ridge.components != 1)
    {
      std::fprintf(stderr, "fuzz_pipeline: ridge with %zu components\n",
                   static_cast<std::size_t>(rc.statistics.ridge.components));
      std::abort();
    }
  }
  catch(const Geodesic_ridge::Error&)
  {
    // an invalid mesh (or source) refused with a typed error is a correct answer
  }
  return 0;
}
#endif

} // namespace gr_fuzz

#endif // GEODESIC_RIDGE_FUZZ_TARGETS_H
