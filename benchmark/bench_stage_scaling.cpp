// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Question: with the fast-marching solver, how does each stage of the whole
// process (file -> ridge) grow with the mesh, from 1k to 200k faces, and how
// far is the whole process above a floor that any geodesic tool pays: CGAL's
// plain reader (CGAL::IO::read_polygon_mesh into a Surface_mesh) and one
// fast-marching solve on M?
//
//   bench_stage_scaling [MESH ...]
//
// MESH is a file or a name of ../shared/data (or of the repository's data/)
// without ".off"; the default list is the torus family (torus_1k, torus_10k,
// torus_100k, 3torus_200k) and bunny, kitten and armadillo at several sizes.
// Source vertex 0, `parameters::solver(Fast_marching_solver())`, every other
// parameter at its default.
//
// Every mesh runs in a fresh process (the program calls itself with
// `--one MESH`), so that its peak resident set size is its own. There, rounds
// of the floor and of the whole process alternate, for at least 1 s and 3
// rounds, at most 20 rounds, and each column is the fastest of its rounds:
//   read        Geodesic_ridge::IO::read_triangle_mesh (parsing, triangulation,
//               the soup's validation, building the mesh, the file index map)
//   validation  validate_triangle_mesh, which compute_ridge_curve runs first
//               (timed alone, next to the call)
//   other       the rest of compute_ridge_curve outside its named steps
//   tree, stage 1, extension, solves, envelope, assembly: the steps of
//               `Ridge_curve::timings` (tree_distances, rough_cut_locus,
//               extended_surface, solve, envelope_and_dominance, ridge_assembly)
//   whole       read + compute_ridge_curve, wall clock
//   whole, 1st round  the same in the first round (not the fastest): what one
//               run in a fresh process pays (first touch of its memory)
// Times are in microseconds per face. F(E)/F, rings and passes (fast-marching
// passes on E, all of them solves here) say how much the extension grew.
// Peak RSS is that of the child process after its first floor (floor) and at
// its end (whole), also in KB per face (a process starts at about 4.5 MB).
// Then the growth exponents: least-squares slopes of log(time) against log(F)
// per column, over the torus family and over all meshes.
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/mesh_validation.h>
#include <Geodesic_ridge/solvers/Fast_marching_solver.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
namespace fs = std::filesystem;

// The measured columns, in the order of the tables and of the child's line.
enum Column { READ, VALIDATION, OTHER, TREE, STAGE_1, EXTENSION, SOLVES, ENVELOPE, ASSEMBLY, WHOLE, FIRST_WHOLE,
              FLOOR_READ, FLOOR_SOLVE, FLOOR, NUMBER_OF_COLUMNS };
const char* const column_names[NUMBER_OF_COLUMNS] = {
  "read", "validation", "other", "tree", "stage 1", "extension", "solves", "envelope", "assembly", "whole",
  "whole, 1st round", "floor read", "floor solve", "floor"};

struct Measurement
{
  std::string mesh;
  std::size_t faces = 0;
  int rounds = 0;
  // what the pipeline did (the same in every round): E's size, rings, fast-marching passes on E
  std::size_t extended_faces = 0;
  int rings = 0, passes = 0;
  std::array<double, NUMBER_OF_COLUMNS> seconds{};
  double floor_rss_kb = 0, whole_rss_kb = 0;
};

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double peak_rss_kb()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss); // kilobytes on Linux
}

std::string mesh_file(const std::string& name)
{
  if(fs::is_regular_file(name)) return name;
  for(const fs::path& dir : {fs::path(GEODESIC_RIDGE_SHARED_DATA_DIR), fs::path(GEODESIC_RIDGE_DATA_DIR)})
    if(fs::is_regular_file(dir / (name + ".off"))) return (dir / (name + ".off")).string();
  return name; // the reader says what is wrong with it
}

// One mesh, in this process: the floor and the whole process, alternating.
Measurement measure(const std::string& file)
{
  namespace p = Geodesic_ridge::parameters;
  Measurement m;
  m.mesh = fs::path(file).stem().string();
  m.seconds.fill(std::numeric_limits<double>::infinity());
  auto keep_fastest = [&](Column c, double t) { m.seconds[c] = std::min(m.seconds[c], t); };
  double spent = 0;
  for(int round = 0; round < 20 && (round < 3 || spent < 1.0); ++round, ++m.rounds)
  {
    const auto round_start = std::chrono::steady_clock::now();
    { // the floor
      Mesh mesh;
      auto t0 = std::chrono::steady_clock::now();
      if(!CGAL::IO::read_polygon_mesh(file, mesh))
        throw Geodesic_ridge::Mesh_file_error(file + ": CGAL cannot read it");
      const double t_read = seconds_since(t0);
      std::vector<double> d(mesh.number_of_vertices());
      t0 = std::chrono::steady_clock::now();
      Geodesic_ridge::Fast_marching_solver()(mesh, Mesh::Vertex_index(0), CGAL::make_property_map(d));
      const double t_solve = seconds_since(t0);
      keep_fastest(FLOOR_READ, t_read);
      keep_fastest(FLOOR_SOLVE, t_solve);
      keep_fastest(FLOOR, t_read + t_solve);
      if(round == 0) m.floor_rss_kb = peak_rss_kb();
    }
    { // the whole process
      Mesh mesh;
      auto t0 = std::chrono::steady_clock::now();
      Geodesic_ridge::IO::read_triangle_mesh(file, mesh);
      const double t_read = seconds_since(t0);
      t0 = std::chrono::steady_clock::now();
      const auto ridge = Geodesic_ridge::compute_ridge_curve(mesh, Mesh::Vertex_index(0),
                                                             p::solver(Geodesic_ridge::Fast_marching_solver()));
      const double t_call = seconds_since(t0);
      t0 = std::chrono::steady_clock::now();
      Geodesic_ridge::validate_triangle_mesh(mesh);
      const double t_validation = seconds_since(t0);
      const Geodesic_ridge::Timings& steps = ridge.timings;
      m.faces = mesh.number_of_faces();
      m.extended_faces = ridge.statistics.extended_surface.number_of_faces;
      m.rings = ridge.statistics.extended_surface.rings;
      m.passes = ridge.statistics.solves + ridge.statistics.predicted_passes;
      keep_fastest(READ, t_read);
      keep_fastest(VALIDATION, t_validation);
      keep_fastest(OTHER, std::max(0.0, t_call - steps.total() - t_validation));
      keep_fastest(TREE, steps["tree_distances"]);
      keep_fastest(STAGE_1, steps["rough_cut_locus"]);
      keep_fastest(EXTENSION, steps["extended_surface"]);
      keep_fastest(SOLVES, steps["solve"]);
      keep_fastest(ENVELOPE, steps["envelope_and_dominance"]);
      keep_fastest(ASSEMBLY, steps["ridge_assembly"]);
      keep_fastest(WHOLE, t_read + t_call);
      if(round == 0) m.seconds[FIRST_WHOLE] = t_read + t_call;
    }
    spent += seconds_since(round_start);
  }
  m.whole_rss_kb = peak_rss_kb();
  return m;
}

// The child's answer, one line:
// "RESULT mesh faces rounds extended_faces rings passes seconds... floor_rss whole_rss".
std::string to_line(const Measurement& m)
{
  std::ostringstream out;
  out.precision(9);
  out << "RESULT " << m.mesh << ' ' << m.faces << ' ' << m.rounds << ' ' << m.extended_faces << ' ' << m.rings << ' '
      << m.passes;
  for(double s : m.seconds) out << ' ' << s;
  out << ' ' << m.floor_rss_kb << ' ' << m.whole_rss_kb;
  return out.str();
}

bool from_line(const std::string& line, Measurement& m)
{
  std::istringstream in(line);
  std::string tag;
  in >> tag >> m.mesh >> m.faces >> m.rounds >> m.extended_faces >> m.rings >> m.passes;
  for(double& s : m.seconds) in >> s;
  in >> m.floor_rss_kb >> m.whole_rss_kb;
  return tag == "RESULT" && bool(in);
}

// Runs `self --one file` and reads its answer (its error on failure).
bool measure_in_child(const std::string& self, const std::string& file, Measurement& m, std::string& error)
{
  auto quoted = [](const std::string& s) {
    std::string q = "'";
    for(char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  FILE* child = popen((quoted(self) + " --one " + quoted(file) + " 2>&1").c_str(), "r");
  if(!child) { error = "cannot start a child process"; return false; }
  std::string output;
  char buffer[4096];
  while(std::fgets(buffer, sizeof buffer, child)) output += buffer;
  pclose(child);
  std::istringstream lines(output);
  for(std::string line; std::getline(lines, line);)
    if(from_line(line, m)) return true;
  error = output.empty() ? std::string("the child process died") : output;
  while(!error.empty() && error.back() == '\n') error.pop_back();
  return false;
}

// The least-squares slope of log(y) against log(x) (NaN with fewer than two points).
double growth_exponent(const std::vector<double>& x, const std::vector<double>& y)
{
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for(std::size_t i = 0; i < x.size(); ++i)
  {
    if(!(x[i] > 0 && y[i] > 0)) continue;
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    n += 1; sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly;
  }
  const double det = n * sxx - sx * sx;
  return n >= 2 && det > 0 ? (n * sxy - sx * sy) / det : std::numeric_limits<double>::quiet_NaN();
}

void print_tables(const std::vector<Measurement>& ms)
{
  std::printf("\n### Time per face (microseconds; fastest of the rounds)\n\n"
              "| mesh | F | F(E)/F | rings | passes | rounds |");
  for(int c = 0; c < NUMBER_OF_COLUMNS; ++c) std::printf(" %s |", column_names[c]);
  std::printf(" whole / floor |\n|---|---:|---:|---:|---:|---:|");
  for(int c = 0; c <= NUMBER_OF_COLUMNS; ++c) std::printf("---:|");
  std::printf("\n");
  for(const Measurement& m : ms)
  {
    std::printf("| %s | %zu | %.2f | %d | %d | %d |", m.mesh.c_str(), m.faces,
                double(m.extended_faces) / double(m.faces), m.rings, m.passes, m.rounds);
    for(double s : m.seconds) std::printf(" %.3f |", 1e6 * s / double(m.faces));
    std::printf(" %.2f |\n", m.seconds[WHOLE] / m.seconds[FLOOR]);
  }

  std::printf("\n### Peak resident set size\n\n"
              "| mesh | F | floor (MB) | whole (MB) | floor (KB/face) | whole (KB/face) | whole / floor |\n"
              "|---|---:|---:|---:|---:|---:|---:|\n");
  for(const Measurement& m : ms)
    std::printf("| %s | %zu | %.1f | %.1f | %.2f | %.2f | %.2f |\n", m.mesh.c_str(), m.faces, m.floor_rss_kb / 1024,
                m.whole_rss_kb / 1024, m.floor_rss_kb / double(m.faces), m.whole_rss_kb / double(m.faces),
                m.whole_rss_kb / m.floor_rss_kb);

  // the fits: over the torus family (the same shape refined) and over all meshes
  auto is_torus = [](const Measurement& m) { return m.mesh.rfind("torus_", 0) == 0; };
  std::vector<double> f_torus, f_all;
  for(const Measurement& m : ms)
  {
    f_all.push_back(double(m.faces));
    if(is_torus(m)) f_torus.push_back(double(m.faces));
  }
  auto exponent = [&](auto value, bool torus_only) {
    std::vector<double> y;
    for(const Measurement& m : ms)
      if(!torus_only || is_torus(m)) y.push_back(value(m));
    return growth_exponent(torus_only ? f_torus : f_all, y);
  };
  std::printf("\n### Growth exponents: time (or memory) ~ F^e, least squares on log-log\n\n"
              "| column | e over torus_* (%zu meshes) | e over all (%zu meshes) |\n|---|---:|---:|\n",
              f_torus.size(), f_all.size());
  for(int c = 0; c < NUMBER_OF_COLUMNS; ++c)
  {
    auto value = [c](const Measurement& m) { return m.seconds[c]; };
    std::printf("| %s | %.2f | %.2f |\n", column_names[c], exponent(value, true), exponent(value, false));
  }
  auto rss = [](const Measurement& m) { return m.whole_rss_kb; };
  std::printf("| peak RSS (whole) | %.2f | %.2f |\n", exponent(rss, true), exponent(rss, false));
}

int main(int argc, char** argv)
{
  if(argc == 3 && std::string(argv[1]) == "--one")
  {
    try { std::cout << to_line(measure(mesh_file(argv[2]))) << std::endl; }
    catch(const std::exception& e) { std::cout << "FAILED: " << e.what() << std::endl; return 1; }
    return 0;
  }
  std::vector<std::string> names(argv + 1, argv + argc);
  if(names.empty())
    names = {"torus_1k", "torus_10k", "torus_100k", "3torus_200k", "bunny_1k", "bunny_7k", "bunny_70k",
             "kitten_5k", "kitten_80k", "armadillo_2k", "armadillo_86k"};

  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec); // argv[0] may be a bare name found on PATH
  const std::string self = ec ? std::string(argv[0]) : exe.string();
  std::vector<Measurement> ms;
  for(const std::string& name : names)
  {
    Measurement m;
    std::string error;
    if(measure_in_child(self, mesh_file(name), m, error))
    {
      ms.push_back(m);
      std::cerr << m.mesh << ": F " << m.faces << ", whole " << m.seconds[WHOLE] << " s, floor " << m.seconds[FLOOR]
                << " s, " << m.rounds << " rounds\n";
    }
    else std::cerr << name << ": " << error << "\n";
  }
  print_tables(ms);
  return 0;
}
