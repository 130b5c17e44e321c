// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Question: what do the two exact solvers cost, alone on M and driving the
// whole pipeline, and does the window-propagation solver give CGAL's
// distances? And on a mesh refined by midpoint subdivision (each triangle into
// four, the surface unchanged), is the exact ridge the coarse mesh's?
//
//   bench_exact_solvers [--source-vertex V] [--smsp-max-faces F] [--subdivide K] [--windows] [MESH ...]
//
// Default meshes: bunny_70k, torus_100k and 3torus_200k of ../shared/data (or
// every mesh of the repository's data/). Each measurement runs in a child
// process (fork), so its peak memory is its own: the whole process is reading
// the file (the package's reader) and computing the ridge with the default
// tolerance from vertex V (default 0). Columns: one solve on M by each
// solver, their largest relative difference over the vertices, then the
// whole process with `--solver vtp`, with `--solver vtp --field cone` (the
// exact cone field: every face's windows kept) and with `--solver exact`
// (skipped above F faces, default 250,000: the exact pipeline needs about 40
// KB per face).
//
// With --windows, what the cone field keeps, on M from vertex V: the windows
// per face (each a `Face_cone`), and how many of them are the lowest at some
// point of a grid of 91 points per face (barycentric steps of 1/12): the most
// that trimming the windows no point needs could save (an estimate from
// above: a window lowest only between the grid's points counts as unneeded);
// how many a safe test drops (`beaten_by_corners`), and the pairs of windows
// of one face with the same cone (apex and offset within 1e-9).
//
// With --subdivide K, each mesh is also subdivided K times and the ridge of
// the fine mesh (vtp) is compared with the coarse mesh's (vtp): distances from
// every fine ridge point to the coarse ridge and back (p95 and max, in mean
// edges of the coarse mesh). The coarse kinks and fine vertices differ, so
// the two ridges agree up to how the pipeline samples them.
#include "benchmark_meshes.h"

#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/solvers/Exact_solver.h>
#include <Geodesic_ridge/solvers/Window_propagation_solver.h>
#include <Geodesic_ridge/internal/face_cone_field.h>
#include <Geodesic_ridge/internal/faces_by_index.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
namespace fs = std::filesystem;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// What a child process measured, sent back through a pipe.
struct Measure
{
  double seconds = 0;
  double ridge_to_ridge[4] = {0, 0, 0, 0}; // fine -> coarse p95, max; coarse -> fine p95, max
  double smsp_seconds = -1, difference = 0;   // one solve on M
  double ridge_length[2] = {0, 0};              // coarse, fine (coarse mean edges)
  int rings[2] = {0, 0}, solves[2] = {0, 0};
  std::size_t mesh_faces = 0, faces = 0, polylines = 0;
  long peak_kb = 0;
  bool ok = false;
};

// Runs f() in a child process; its return value and the child's peak memory.
template <class F>
Measure in_child(const F& f)
{
  int fd[2];
  if(pipe(fd) != 0) return Measure();
  const pid_t pid = fork();
  if(pid == 0)
  {
    close(fd[0]);
    Measure m;
    try { m = f(); m.ok = true; }
    catch(const std::exception& e) { std::cerr << "  failed: " << e.what() << "\n"; }
    if(write(fd[1], &m, sizeof m) != static_cast<ssize_t>(sizeof m)) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  Measure m;
  const bool got = read(fd[0], &m, sizeof m) == static_cast<ssize_t>(sizeof m);
  close(fd[0]);
  int status = 0;
  rusage usage;
  wait4(pid, &status, 0, &usage);
  if(!got) m.ok = false;
  m.peak_kb = usage.ru_maxrss;
  return m;
}

// Each triangle into four at its edges' midpoints: the same surface, four
// times the faces.
Mesh midpoint_subdivision(const Mesh& coarse)
{
  Mesh fine;
  for(auto v : coarse.vertices()) fine.add_vertex(coarse.point(v));
  std::map<std::size_t, Mesh::Vertex_index> midpoint; // by edge
  auto mid = [&](Mesh::Halfedge_index h) {
    const std::size_t e = coarse.edge(h);
    auto it = midpoint.find(e);
    if(it != midpoint.end()) return it->second;
    const auto v = fine.add_vertex(CGAL::midpoint(coarse.point(coarse.source(h)), coarse.point(coarse.target(h))));
    midpoint.emplace(e, v);
    return v;
  };
  for(auto f : coarse.faces())
  {
    const auto h0 = coarse.halfedge(f), h1 = coarse.next(h0), h2 = coarse.next(h1);
    const Mesh::Vertex_index a(std::size_t(coarse.source(h0))), b(std::size_t(coarse.source(h1))),
        c(std::size_t(coarse.source(h2)));
    const auto ab = mid(h0), bc = mid(h1), ca = mid(h2);
    fine.add_face(a, ab, ca);
    fine.add_face(ab, b, bc);
    fine.add_face(ca, bc, c);
    fine.add_face(ab, bc, ca);
  }
  return fine;
}

template <class Ridge>
double length_of(const Ridge& rc)
{
  double l = 0;
  for(const auto& pl : rc.polylines)
    for(std::size_t i = 1; i < pl.size(); ++i) l += std::sqrt(CGAL::squared_distance(pl[i - 1].point, pl[i].point));
  return l;
}

template <class Ridge>
std::vector<K::Segment_3> segments_of(const Ridge& rc)
{
  std::vector<K::Segment_3> out;
  for(const auto& pl : rc.polylines)
    for(std::size_t i = 1; i < pl.size(); ++i)
      if(pl[i - 1].point != pl[i].point) out.emplace_back(pl[i - 1].point, pl[i].point);
  return out;
}

// p95 and max of the distances from the points of `from` to the segments of `to`
template <class Ridge>
std::pair<double, double> ridge_to_ridge(const Ridge& from, const std::vector<K::Segment_3>& to)
{
  std::vector<double> d;
  for(const auto& pl : from.polylines)
    for(const auto& p : pl)
    {
      double best = std::numeric_limits<double>::infinity();
      for(const auto& s : to) best = std::min(best, CGAL::squared_distance(p.point, s));
      d.push_back(std::sqrt(best));
    }
  if(d.empty()) return {0., 0.};
  std::sort(d.begin(), d.end());
  return {d[static_cast<std::size_t>(0.95 * (d.size() - 1))], d.back()};
}

std::string difference_text(double d)
{
  char b[32];
  std::snprintf(b, sizeof b, "%.1e", d);
  return b;
}

// The windows of every face of m from vertex `source` (all kept, as for the
// cone field), and those lowest at some point of a grid of 91 points per face.
struct Window_use
{
  std::size_t faces = 0, windows = 0, lowest_somewhere = 0, dropped_by_corners = 0, same_cone_pairs = 0;
  double seconds = 0;
};

// Whether the paths through the corners of face (plane, D: its corners'
// distances) are shorter than window w everywhere in the face: w's value at a
// point x is at least its offset plus |x - apex|, at least its straight value
// at corner k minus |x - c_k|, and the distance at x at most D_k + |x - c_k|;
// so w loses within half of (straight value at c_k - D_k) of c_k. True if
// those disks cover the face's three kites (corner, edge midpoints, centroid).
bool beaten_by_corners(const Geodesic_ridge::internal::Face_plane& plane, const std::array<double, 3>& D,
                       const Geodesic_ridge::Face_cone& w)
{
  const auto a = plane.point(w.apex);
  const K::Point_2 c[3] = {plane.corner(0), plane.corner(1), plane.corner(2)};
  const K::Point_2 g = CGAL::centroid(c[0], c[1], c[2]);
  for(int k = 0; k < 3; ++k)
  {
    const double reach = (w.offset + std::sqrt(CGAL::squared_distance(a, c[k])) - D[k]) / 2;
    const double kite = std::sqrt((std::max)({CGAL::squared_distance(c[k], CGAL::midpoint(c[k], c[(k + 1) % 3])),
                                              CGAL::squared_distance(c[k], CGAL::midpoint(c[k], c[(k + 2) % 3])),
                                              CGAL::squared_distance(c[k], g)}));
    if(!(reach > kite * (1 + 1e-9) + 1e-12 * D[k])) return false;
  }
  return true;
}

Window_use window_use(const Mesh& m, std::size_t source)
{
  Window_use u;
  u.faces = m.number_of_faces();
  std::vector<double> d(m.number_of_vertices());
  std::vector<Geodesic_ridge::Face_cone> sampled;
  std::vector<std::vector<Geodesic_ridge::Face_cone> > windows;
  const auto t = std::chrono::steady_clock::now();
  Geodesic_ridge::Window_propagation_solver()(m, Mesh::Vertex_index(static_cast<Mesh::size_type>(source)),
                                              CGAL::make_property_map(d), sampled, [](std::size_t) { return true; },
                                              Geodesic_ridge::Cone_samples::cone_samples(), &windows);
  u.seconds = seconds_since(t);
  const int steps = 12;
  const Geodesic_ridge::internal::Faces_by_index<Mesh, Mesh::Property_map<Mesh::Vertex_index, K::Point_3> > corners(
      m, m.points(), get(CGAL::face_index, m));
  for(auto f : m.faces())
  {
    const auto& w = windows[std::size_t(f)];
    u.windows += w.size();
    const auto h = corners.corner_halfedges(std::size_t(f)); // (CGAL's corner order, as the windows')
    const Geodesic_ridge::internal::Face_plane plane(corners.corner_points(std::size_t(f)));
    const std::array<double, 3> D = {{d[std::size_t(m.source(h[0]))], d[std::size_t(m.source(h[1]))],
                                      d[std::size_t(m.source(h[2]))]}};
    for(std::size_t k = 0; k < w.size(); ++k)
    {
      u.dropped_by_corners += beaten_by_corners(plane, D, w[k]);
      const double tolerance = 1e-9 * (plane.l + w[k].offset);
      for(std::size_t j = k + 1; j < w.size(); ++j)
        u.same_cone_pairs += std::sqrt(CGAL::squared_distance(plane.point(w[k].apex), plane.point(w[j].apex))) <= tolerance &&
                             std::abs(w[k].offset - w[j].offset) <= tolerance;
    }
    std::vector<char> lowest(w.size(), 0);
    for(int i = 0; i <= steps; ++i)
      for(int j = 0; i + j <= steps; ++j)
      {
        const auto x = plane.point({{double(steps - i - j) / steps, double(i) / steps, double(j) / steps}});
        double best = std::numeric_limits<double>::infinity();
        std::size_t at = w.size();
        for(std::size_t k = 0; k < w.size(); ++k)
        {
          const double v = Geodesic_ridge::internal::cone_path(plane, w[k], x).second;
          if(v < best) { best = v; at = k; }
        }
        if(at < w.size()) lowest[at] = 1;
      }
    u.lowest_somewhere += std::size_t(std::count(lowest.begin(), lowest.end(), 1));
  }
  return u;
}

double mean_edge(const Mesh& m)
{
  double sum = 0;
  for(auto e : m.edges()) sum += std::sqrt(CGAL::squared_distance(m.point(m.source(m.halfedge(e))), m.point(m.target(m.halfedge(e)))));
  return sum / m.number_of_edges();
}

} // namespace

int main(int argc, char** argv)
{
  std::size_t source = 0, smsp_max_faces = 250000;
  int subdivide = 0;
  bool windows_table = false;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--source-vertex" && i + 1 < argc) source = std::stoul(argv[++i]);
    else if(a == "--smsp-max-faces" && i + 1 < argc) smsp_max_faces = std::stoul(argv[++i]);
    else if(a == "--subdivide" && i + 1 < argc) subdivide = std::stoi(argv[++i]);
    else if(a == "--windows") windows_table = true;
    else if(!a.empty() && a[0] == '-') { std::cerr << "unknown option " << a << "\n"; return 2; }
    else files.push_back(a);
  }
  if(files.empty())
  {
    const fs::path shared = GEODESIC_RIDGE_SHARED_DATA_DIR;
    for(const char* name : {"bunny_70k.off", "torus_100k.off", "3torus_200k.off"})
      if(fs::exists(shared / name)) files.push_back((shared / name).string());
  }
  files = benchmark_meshes(files);
  namespace p = Geodesic_ridge::parameters;
  typedef Mesh::Vertex_index vertex_descriptor;

  std::cout << "| mesh | F | SMSP on M (s) | vtp on M (s) | max rel. difference | vtp windows / face "
               "| pipeline vtp (s) | peak (MB) | KB / face | F(E)/F | vtp cone field (s) | peak (MB) | KB / face "
               "| pipeline exact (s) | peak (MB) |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const std::string& file : files)
  {
    // first the whole process, each in a child forked while this process is
    // small (a child's peak counts the pages it shares with its parent)
    const vertex_descriptor s(static_cast<Mesh::size_type>(source));
    auto whole = [&](auto solver, Geodesic_ridge::Field field) {
      return in_child([&] {
        const auto t = std::chrono::steady_clock::now();
        Mesh m;
        Geodesic_ridge::IO::read_triangle_mesh(file, m);
        const auto rc = Geodesic_ridge::compute_ridge_curve(m, s, p::solver(solver, p::field(field)));
        Measure r;
        r.seconds = seconds_since(t);
        r.mesh_faces = m.number_of_faces();
        r.faces = rc.statistics.extended_surface.number_of_faces;
        r.polylines = rc.polylines.size();
        return r;
      });
    };
    const Measure vtp = whole(Geodesic_ridge::Window_propagation_solver(), Geodesic_ridge::Field::linear);
    const Measure vtp_cone = whole(Geodesic_ridge::Window_propagation_solver(), Geodesic_ridge::Field::cone);
    const Measure exact = vtp.ok && vtp.mesh_faces <= smsp_max_faces
                              ? whole(Geodesic_ridge::Exact_solver(), Geodesic_ridge::Field::linear)
                              : Measure();
    // one solve on M by each solver, and the largest difference
    const Measure on_mesh = in_child([&] {
      Mesh mesh;
      Geodesic_ridge::IO::read_triangle_mesh(file, mesh);
      Measure r;
      r.mesh_faces = mesh.number_of_faces();
      std::vector<double> by_vtp(mesh.number_of_vertices()), by_smsp(mesh.number_of_vertices());
      auto t0 = std::chrono::steady_clock::now();
      Geodesic_ridge::internal::Window_propagation propagation(mesh, mesh.points(), get(CGAL::vertex_index, mesh),
                                                               get(CGAL::face_index, mesh));
      propagation.from_vertex(source, by_vtp);
      r.seconds = seconds_since(t0);
      r.polylines = propagation.propagated_windows();
      r.smsp_seconds = -1;
      if(mesh.number_of_faces() <= smsp_max_faces)
      {
        t0 = std::chrono::steady_clock::now();
        Geodesic_ridge::Exact_solver()(mesh, s, CGAL::make_property_map(by_smsp));
        r.smsp_seconds = seconds_since(t0);
        for(std::size_t v = 0; v < by_vtp.size(); ++v)
          if(by_smsp[v] > 0) r.difference = std::max(r.difference, std::abs(by_vtp[v] - by_smsp[v]) / by_smsp[v]);
      }
      return r;
    });
    const std::size_t F = on_mesh.mesh_faces;
    const double t_vtp = on_mesh.seconds, t_smsp = on_mesh.smsp_seconds, difference = on_mesh.difference;
    const double windows = F ? double(on_mesh.polylines) / F : 0.;
    auto cell = [](bool ok, double x, int digits) {
      if(!ok) return std::string("–");
      char b[32];
      std::snprintf(b, sizeof b, "%.*f", digits, x);
      return std::string(b);
    };
    std::printf("| %s | %zu | %s | %.3f | %s | %.1f | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
                fs::path(file).stem().string().c_str(), F, cell(t_smsp >= 0, t_smsp, 2).c_str(), t_vtp,
                t_smsp >= 0 ? difference_text(difference).c_str() : "–", windows,
                cell(vtp.ok, vtp.seconds, 2).c_str(), cell(vtp.ok, vtp.peak_kb / 1024., 0).c_str(),
                cell(vtp.ok, double(vtp.peak_kb) / F, 2).c_str(), cell(vtp.ok, double(vtp.faces) / F, 3).c_str(),
                cell(vtp_cone.ok, vtp_cone.seconds, 2).c_str(), cell(vtp_cone.ok, vtp_cone.peak_kb / 1024., 0).c_str(),
                cell(vtp_cone.ok, double(vtp_cone.peak_kb) / F, 2).c_str(), cell(exact.ok, exact.seconds, 2).c_str(), cell(exact.ok, exact.peak_kb / 1024., 0).c_str());
    std::fflush(stdout);
  }

  if(windows_table)
  {
    std::cout << "\nThe windows the cone field keeps, on M from vertex " << source << " (each a Face_cone of "
              << sizeof(Geodesic_ridge::Face_cone) << " bytes)\n\n"
                 "| mesh | F | windows / face | lowest at a grid point / face | share | beaten by the corners / face "
                 "| pairs with one cone | KB / face kept | solve keeping them (s) |\n"
                 "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for(const std::string& file : files)
    {
      Mesh m;
      Geodesic_ridge::IO::read_triangle_mesh(file, m);
      const Window_use u = window_use(m, source);
      const double per_face = double(u.windows) / double(u.faces);
      std::printf("| %s | %zu | %.1f | %.1f | %.2f | %.4f | %zu | %.2f | %.2f |\n", fs::path(file).stem().string().c_str(),
                  u.faces, per_face, double(u.lowest_somewhere) / double(u.faces),
                  double(u.lowest_somewhere) / double(u.windows), double(u.dropped_by_corners) / double(u.faces),
                  u.same_cone_pairs, per_face * sizeof(Geodesic_ridge::Face_cone) / 1024., u.seconds);
      std::fflush(stdout);
    }
  }

  if(subdivide <= 0) return 0;
  std::cout << "\nMidpoint subdivision: the fine mesh's exact ridge (vtp) against the coarse mesh's, in coarse mean edges\n\n"
               "| mesh | subdivisions | F fine | pipeline on fine (s) | peak (MB) | fine -> coarse p95 / max "
               "| coarse -> fine p95 / max | ridge length coarse / fine | rings coarse / fine | solves coarse / fine |\n"
               "|---|---:|---:|---:|---:|---|---|---|---|---|\n";
  for(const std::string& file : files)
  {
    const vertex_descriptor s(static_cast<Mesh::size_type>(source));
    // all in a child, so that its peak memory is the fine mesh's run
    const Measure fine = in_child([&] {
      Mesh coarse;
      Geodesic_ridge::IO::read_triangle_mesh(file, coarse);
      const double h = mean_edge(coarse);
      const auto coarse_ridge =
          Geodesic_ridge::compute_ridge_curve(coarse, s, p::solver(Geodesic_ridge::Window_propagation_solver()));
      const auto coarse_segments = segments_of(coarse_ridge);
      Mesh m = coarse;
      for(int k = 0; k < subdivide; ++k) m = midpoint_subdivision(m);
      const auto t = std::chrono::steady_clock::now();
      const auto rc = Geodesic_ridge::compute_ridge_curve(m, s, p::solver(Geodesic_ridge::Window_propagation_solver()));
      Measure r;
      r.seconds = seconds_since(t);
      r.faces = m.number_of_faces();
      r.polylines = rc.polylines.size();
      const auto a = ridge_to_ridge(rc, coarse_segments);
      const auto b = ridge_to_ridge(coarse_ridge, segments_of(rc));
      r.ridge_to_ridge[0] = a.first / h;
      r.ridge_to_ridge[1] = a.second / h;
      r.ridge_to_ridge[2] = b.first / h;
      r.ridge_to_ridge[3] = b.second / h;
      r.ridge_length[0] = length_of(coarse_ridge) / h;
      r.ridge_length[1] = length_of(rc) / h;
      r.rings[0] = coarse_ridge.statistics.extended_surface.rings;
      r.rings[1] = rc.statistics.extended_surface.rings;
      r.solves[0] = coarse_ridge.statistics.solves;
      r.solves[1] = rc.statistics.solves;
      return r;
    });
    if(!fine.ok) { std::printf("| %s | %d | failed | | | | | | | |\n", fs::path(file).stem().string().c_str(), subdivide); continue; }
    const double* d = fine.ridge_to_ridge;
    std::printf("| %s | %d | %zu | %.2f | %ld | %.3f / %.3f | %.3f / %.3f | %.1f / %.1f | %d / %d | %d / %d |\n",
                fs::path(file).stem().string().c_str(), subdivide, fine.faces, fine.seconds, fine.peak_kb / 1024, d[0],
                d[1], d[2], d[3], fine.ridge_length[0], fine.ridge_length[1], fine.rings[0], fine.rings[1],
                fine.solves[0], fine.solves[1]);
    std::fflush(stdout);
  }
  return 0;
}
