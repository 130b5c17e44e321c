// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Convenience header: includes every public header of the package.
#ifndef GEODESIC_RIDGE_H
#define GEODESIC_RIDGE_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/parameters.h>
#include <Geodesic_ridge/source.h>
#include <Geodesic_ridge/mesh_validation.h>
#include <Geodesic_ridge/repair.h>
#include <Geodesic_ridge/file_index_map.h>
#include <Geodesic_ridge/rough_cut_locus.h>
#include <Geodesic_ridge/extended_surface.h>
#include <Geodesic_ridge/lower_envelope.h>
#include <Geodesic_ridge/ridge_curve.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/compute_geodesic_ridges.h>
#include <Geodesic_ridge/distance_field.h>
#include <Geodesic_ridge/refined_mesh.h>
#include <Geodesic_ridge/isolines.h>
#include <Geodesic_ridge/solvers/Exact_solver.h>
#include <Geodesic_ridge/solvers/Fast_marching_solver.h>
#include <Geodesic_ridge/solvers/Dijkstra_solver.h>
#include <Geodesic_ridge/solvers/Window_propagation_solver.h>
#ifdef CGAL_EIGEN3_ENABLED // the heat method needs Eigen
#include <Geodesic_ridge/solvers/Heat_method_solver.h>
#endif
#include <Geodesic_ridge/IO/png.h>
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/IO/polylines.h>

#endif // GEODESIC_RIDGE_H
