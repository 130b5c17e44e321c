// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A solver of one's own drives the pipeline: any model of the GeodesicSolver
// concept (distances from a vertex or a Face_location to every vertex) goes in
// through parameters::solver(). This one wraps another solver and logs what
// the pipeline asks of it: how many solves, on how many vertices, how long.
#include <Geodesic_ridge.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Named_function_parameters.h>

#include <chrono>
#include <iostream>
#include <memory>

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

// A model of GeodesicSolver: the wrapped solver's distances, with a log.
// Solvers are passed by value (a copy per call of the pipeline), so the log is
// shared.
template <class Solver>
class Logging_solver
{
public:
  struct Log { std::size_t solves = 0, vertices = 0; double seconds = 0; };

  explicit Logging_solver(const Solver& solver = Solver()) : solver_(solver), log_(std::make_shared<Log>()) {}

  static const char* name() { return "logging"; }

  // One template for both kinds of source: a vertex, or a face and its
  // barycentric coordinates (std::pair<face_descriptor, std::array<FT, 3> >).
  template <class TriangleMesh, class Source, class VertexDistanceMap,
            class NamedParameters = CGAL::parameters::Default_named_parameters>
  void operator()(const TriangleMesh& tm, const Source& source, VertexDistanceMap distance,
                  const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    const auto start = std::chrono::steady_clock::now();
    solver_(tm, source, distance, np);
    log_->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    log_->vertices += num_vertices(tm);
    ++log_->solves;
  }

  const Log& log() const { return *log_; }

private:
  Solver solver_;
  std::shared_ptr<Log> log_;
};

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : GEODESIC_RIDGE_DATA_DIR "/eight.off";
  try
  {
    Mesh mesh;
    Geodesic_ridge::IO::read_triangle_mesh(filename, mesh);
    const Logging_solver<Geodesic_ridge::Fast_marching_solver> solver;
    const auto rc = Geodesic_ridge::compute_ridge_curve(mesh, Mesh::Vertex_index(0),
                                                        Geodesic_ridge::parameters::solver(solver));
    const auto& log = solver.log();
    std::cout << "solver '" << rc.statistics.solver << "': " << log.solves << " solves on the extended surface ("
              << log.vertices / log.solves << " vertices each), " << log.seconds << " s\n"
              << "ridge: " << rc.ridge_polylines().size() << " polylines, " << rc.statistics.ridge.cycles << " cycles\n";
    return log.solves == std::size_t(rc.statistics.solves) ? 0 : 1; // every solve went through it
  }
  catch(const Geodesic_ridge::Error& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
