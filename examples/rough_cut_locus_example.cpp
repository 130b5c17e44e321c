// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The smallest use of stage 1: read a mesh, compute the rough cut locus of a
// vertex, print what it found and write the cut graph K as polylines.
#include <Geodesic_ridge.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : GEODESIC_RIDGE_DATA_DIR "/torus_1k.off";
  try
  {
    Mesh mesh;
    Geodesic_ridge::IO::read_triangle_mesh(filename, mesh); // validates, keeps file order

    const Mesh::Vertex_index source(0);
    const auto rcl = Geodesic_ridge::compute_rough_cut_locus(
        mesh, source, Geodesic_ridge::parameters::tolerance(0.02));

    std::cout << "genus " << rcl.statistics.genus << ", |T*| = " << rcl.dual_edges.size()
              << ", kept " << rcl.kept_dual_edges.size() << ", |K| = " << rcl.cut_edges.size()
              << ", cycle rank of K = " << rcl.statistics.cut_cycle_rank << "\n";

    std::vector<std::vector<K::Point_3> > polylines;
    Geodesic_ridge::cut_graph_polylines(mesh, rcl, std::back_inserter(polylines));
    Geodesic_ridge::IO::write_polylines("rough_cut.polylines.txt", polylines);
    std::cout << "wrote rough_cut.polylines.txt\n";
  }
  catch(const Geodesic_ridge::Error& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
