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
// A file that defines GR_FUZZ_READERS, GR_FUZZ_PIPELINE or GR_FUZZ_CLI before
// including this header instantiates only that group of targets (shorter
// builds); without any, all of them (the regression runner).

#ifndef GEODESIC_RIDGE_FUZZ_TARGETS_H
#define GEODESIC_RIDGE_FUZZ_TARGETS_H

#if !defined(GR_FUZZ_READERS) && !defined(GR_FUZZ_PIPELINE) && !defined(GR_FUZZ_CLI)
#define GR_FUZZ_READERS
#define GR_FUZZ_PIPELINE
#define GR_FUZZ_CLI
#endif

#include <Geodesic_ridge/exceptions.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#if defined(GR_FUZZ_READERS) || defined(GR_FUZZ_CLI)
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <unistd.h>
#endif
#ifdef GR_FUZZ_PIPELINE
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <algorithm>
#include <array>
#endif
#ifdef GR_FUZZ_CLI
#include "../examples/cli/input_lines.h"
#include "../examples/cli/options.h"
#include <sstream>
#include <vector>
#endif

namespace gr_fuzz {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

#if defined(GR_FUZZ_READERS) || defined(GR_FUZZ_CLI)
// The bytes as a file of this process's own (the pid: parallel fuzzers do not
// clash), with the given extension; removed when the object goes.
struct Bytes_file
{
  std::string path;
  Bytes_file(const char* extension, const uint8_t* data, std::size_t size)
    : path("/tmp/geodesic_ridge_fuzz_" + std::to_string(::getpid()) + "." + extension)
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  ~Bytes_file() { std::remove(path.c_str()); }
};
#endif

#ifdef GR_FUZZ_READERS
// The reader takes a file name (its extension picks the format), so the bytes
// go to a file of this process's own (the pid: parallel fuzzers do not clash).
inline int read_bytes_as(const char* extension, const uint8_t* data, std::size_t size, bool repair)
{
  const Bytes_file file(extension, data, size);
  try
  {
    Mesh mesh;
    Geodesic_ridge::IO::read_triangle_mesh(file.path, mesh, Geodesic_ridge::parameters::repair(repair));
  }
  catch(const Geodesic_ridge::Error&)
  {
    // a refused file is a correct answer
  }
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

#ifdef GR_FUZZ_PIPELINE
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

#ifdef GR_FUZZ_CLI
// The command line: the bytes split at newlines (and NULs) are the arguments
// after the program's name, parsed as geodesic_ridge parses them. A usage
// error or a typed error is a correct answer; --help's text goes nowhere.
inline int fuzz_options(const uint8_t* data, std::size_t size)
{
  std::vector<std::string> words(1, "geodesic_ridge");
  std::string word;
  for(std::size_t i = 0; i <= size; ++i)
    if(i == size || data[i] == '\n' || data[i] == '\0')
    {
      words.push_back(word);
      word.clear();
    }
    else
      word += static_cast<char>(data[i]);
  if(words.back().empty()) words.pop_back(); // a final newline ends the last argument
  std::vector<char*> argv;
  for(std::string& w : words) argv.push_back(&w[0]);
  argv.push_back(nullptr);
  std::ostringstream discard;
  std::streambuf* cout_buffer = std::cout.rdbuf(discard.rdbuf());
  try
  {
    geodesic_ridge_cli::parse(static_cast<int>(words.size()), argv.data());
  }
  catch(const geodesic_ridge_cli::Usage_error&)
  {
  }
  catch(const Geodesic_ridge::Error&)
  {
  }
  std::cout.rdbuf(cout_buffer);
  return 0;
}

// The mesh the query and source lines refer to: a cube of quads and an open
// pentagon pyramid, so that file faces of 4 and 5 corners (triangulated) and
// triangles are all there. Read once, as the program reads a mesh.
struct Line_mesh
{
  geodesic_ridge_cli::Mesh mesh;
  geodesic_ridge_cli::File_map map;

  static const Line_mesh& get()
  {
    static const Line_mesh m;
    return m;
  }

private:
  Line_mesh() : map(read()) {}
  geodesic_ridge_cli::File_map read()
  {
    const char obj[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                       "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
                       "v 3 0 0\nv 4 0 0\nv 4.3 1 0\nv 3.5 1.6 0\nv 2.7 1 0\nv 3.5 0.7 1\n"
                       "f 9 10 14\nf 10 11 14\nf 11 12 14\nf 12 13 14\nf 13 9 14\n";
    const Bytes_file file("obj", reinterpret_cast<const uint8_t*>(obj), sizeof(obj) - 1);
    return Geodesic_ridge::IO::read_triangle_mesh(file.path, mesh);
  }
};

// A query file (--query): "FACE X Y Z" lines, or barycentric ones when the
// last byte is even (as the readers' repair flag), on Line_mesh.
inline int fuzz_query(const uint8_t* data, std::size_t size)
{
  const Line_mesh& m = Line_mesh::get();
  const Bytes_file file("txt", data, size);
  try
  {
    const bool barycentric = size > 0 && (data[size - 1] & 1) == 0;
    for(const geodesic_ridge_cli::Location& q : geodesic_ridge_cli::read_queries(file.path, m.mesh, m.map, barycentric))
    {
      // the documented postcondition: a point of a face, coordinates >= 0 summing to 1
      const double sum = q.second[0] + q.second[1] + q.second[2];
      if(!(q.first.idx() < m.mesh.number_of_faces()) || !(std::abs(sum - 1) < 1e-9) ||
         *std::min_element(q.second.begin(), q.second.end()) < 0)
      {
        std::fprintf(stderr, "fuzz_query: face %u, coordinates %.17g %.17g %.17g\n", static_cast<unsigned>(q.first),
                     q.second[0], q.second[1], q.second[2]);
        std::abort();
      }
    }
  }
  catch(const Geodesic_ridge::Error&)
  {
  }
  return 0;
}

// A sources file (--sources): parsed as a whole (a bad line refuses it), then
// every source put on Line_mesh on its own, as the batch does.
inline int fuzz_sources(const uint8_t* data, std::size_t size)
{
  const Line_mesh& m = Line_mesh::get();
  const Bytes_file file("txt", data, size);
  try
  {
    const auto sources = geodesic_ridge_cli::read_lines(file.path, "source", geodesic_ridge_cli::read_source_line);
    for(const geodesic_ridge_cli::Source_line& s : sources)
    {
      try
      {
        const geodesic_ridge_cli::Location q = geodesic_ridge_cli::resolve(s, m.mesh, m.map);
        if(!(q.first.idx() < m.mesh.number_of_faces()))
        {
          std::fprintf(stderr, "fuzz_sources: line %zu resolved to no face\n", s.line);
          std::abort();
        }
      }
      catch(const Geodesic_ridge::Error&)
      {
        // this source fails alone
      }
    }
  }
  catch(const Geodesic_ridge::Error&)
  {
  }
  return 0;
}
#endif

} // namespace gr_fuzz

#endif // GEODESIC_RIDGE_FUZZ_TARGETS_H
