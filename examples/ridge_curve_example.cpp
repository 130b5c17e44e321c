// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The geodesic ridge of a vertex, with the one-shot function and with the
// result class, and its region-wise distance field (queries, linear and cone;
// the mesh refined along the ridge; iso-lines), as in the README.
#include <Geodesic_ridge.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <iostream>
#include <utility>
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

    // everything: points with their surface location, regions, statistics;
    // the ridge reported (the cone ridge with the exact solver) and the
    // linear field's (rc.polylines, the refined mesh's)
    const auto rc = Geodesic_ridge::compute_ridge_curve(mesh, Mesh::Vertex_index(3));
    const auto& p = rc.ridge_polylines().front().front();
    std::cout << "first point " << p.point << " on face " << p.face << " at (" << p.barycentric[0] << ", "
              << p.barycentric[1] << ", " << p.barycentric[2] << ")\n"
              << rc.statistics.ridge.junctions << " junctions, " << rc.statistics.ridge.cycles
              << " cycles, " << rc.statistics.solves << " exact solves on an extended surface of "
              << rc.statistics.extended_surface.number_of_faces << " faces\n";

    // the region-wise field: queries at any Face_location, O(1) off the ridge
    const auto field = Geodesic_ridge::make_distance_field(mesh, rc);
    const std::pair<Mesh::Face_index, std::array<double, 3> > where(Mesh::Face_index(7), {{0.2, 0.3, 0.5}});
    std::cout << "distance at face 7 (0.2, 0.3, 0.5): " << field.distance(where) << " (linear)";
    // the cone field: the ridge computed with the exact solver's cones kept
    namespace gp = Geodesic_ridge::parameters;
    const auto cone = gp::field(Geodesic_ridge::Field::cone);
    const auto rc_cone = Geodesic_ridge::compute_ridge_curve(mesh, Mesh::Vertex_index(3), cone);
    std::cout << ", " << Geodesic_ridge::make_distance_field(mesh, rc_cone, cone).distance(where) << " (cone)\n";

    // the mesh split along the ridge, one distance per vertex
    Mesh refined;
    auto distance = refined.add_property_map<Mesh::Vertex_index, double>("v:distance", 0).first;
    const auto st = Geodesic_ridge::refine_mesh_along_ridge(mesh, rc, refined, CGAL::parameters::default_values(),
                                                            gp::vertex_distance_map(distance));
    std::cout << "refined mesh: " << st.faces << " faces, " << st.split_faces << " faces of the mesh split\n";

    // iso-lines of the region-wise field, sharp where they cross the ridge
    std::vector<Geodesic_ridge::Isoline<Mesh::Point> > lines;
    Geodesic_ridge::isolines(refined, distance, Geodesic_ridge::equally_spaced_levels(20, field.maximum_distance()),
                             std::back_inserter(lines));
    std::cout << lines.size() << " iso-lines\n";
  }
  catch(const Geodesic_ridge::Error& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
