// Copyright (c) 2026 Geodesic_ridge developers.
//
// The geodesic ridge of a vertex, with the one-shot function and with the
// result class, as in the README.
#include <Geodesic_ridge.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>
#include <vector>

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : GEODESIC_RIDGE_DATA_DIR "/eight.off";
  try
  {
    Mesh mesh;
    Geodesic_ridge::IO::read_triangle_mesh(filename, mesh);

    // one shot: polylines of points
    std::vector<std::vector<Mesh::Point> > ridge;
    Geodesic_ridge::compute_geodesic_ridge(mesh, Mesh::Vertex_index(3), std::back_inserter(ridge),
                                           Geodesic_ridge::parameters::tolerance(0.025));
    std::cout << ridge.size() << " polylines\n";

    // everything: points with their surface location, regions, statistics
    const auto rc = Geodesic_ridge::compute_ridge_curve(mesh, Mesh::Vertex_index(3));
    const auto& p = rc.polylines.front().front();
    std::cout << "first point " << p.point << " on face " << p.face << " at (" << p.barycentric[0] << ", "
              << p.barycentric[1] << ", " << p.barycentric[2] << ")\n"
              << rc.statistics.ridge.junctions << " junctions, " << rc.statistics.ridge.cycles
              << " cycles, " << rc.statistics.solves << " exact solves on an extended surface of "
              << rc.statistics.extended_surface.number_of_faces << " faces\n";
  }
  catch(const Geodesic_ridge::Error& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
