# Copyright (c) 2026 Geodesic_ridge developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The geodesic ridge (cut locus) of a source on a triangle mesh, from NumPy.

A mesh is ``V`` (n, 3) float64 and ``F`` (m, 3) int32 or int64, 0-based; a
surface point is a face and barycentric coordinates (``SurfacePoint``), in the
corner order of ``F``. A source is a vertex index or a ``SurfacePoint``.

    import geodesic_ridge as gr
    V, F = gr.read_mesh("data/eight.off")
    solver = gr.RidgeSolver(V, F)                 # solver="exact" (SMSP), tolerance=0.025, ...
    ridge = solver.ridge(3)                       # ridge.polylines: list of (k, 3) arrays
    field = solver.distance_field(3)              # field.distance(faces, barycentric)
    V2, F2, d, face_of = solver.refine(3)         # the mesh split along the ridge
    lines = solver.isolines(3, 20)                # [Isoline(level, points, closed), ...]

The named parameters of the C++ API are keyword arguments of ``RidgeSolver``
and of the one-off functions (tolerance, leaf_curvature, branch_curvature,
initial_rings, extension_step, maximum_rings, maximum_solves, tree_from_solver,
predicted_extension, fast_marching_margin, minimum_spur_angle, kink_angle,
corner_fallback, field, cone_ridge, cone_ridge_tolerance). Errors are
exceptions: ``Error`` and its subclasses ``MeshFileError``,
``InvalidMeshError``, ``InvalidSourceError``, ``InvalidParameterError`` (also
``ValueError``) and ``AlgorithmError`` (also ``RuntimeError``). Every
computation releases the GIL.
"""
from collections import namedtuple

import numpy as np

SurfacePoint = namedtuple("SurfacePoint", ["face", "barycentric"])
SurfacePoint.__doc__ = "A point of face `face` with barycentric coordinates `barycentric` (3 numbers, sum 1)."

Isoline = namedtuple("Isoline", ["level", "points", "closed"])
Isoline.__doc__ = ("An iso-line of the distance: its level, its points (k, 3) on the edges of the refined mesh, "
                   "and whether it is closed (else it ends on the border).")

FileIndexMap = namedtuple("FileIndexMap", ["vertices", "faces"])
FileIndexMap.__doc__ = ("From the mesh read back to the file: the file's vertex index of each mesh vertex (n,) "
                        "and the file's face index (the polygon) of each mesh face (m,).")

from ._geodesic_ridge import (  # noqa: E402  (the module uses the tuples above)
    AlgorithmError,
    DistanceField,
    Error,
    InvalidMeshError,
    InvalidParameterError,
    InvalidSourceError,
    MeshFileError,
    Ridge,
    RidgeSolver,
    parallel,
    read_mesh,
)

__all__ = [
    "AlgorithmError", "DistanceField", "Error", "FileIndexMap", "InvalidMeshError", "InvalidParameterError",
    "InvalidSourceError", "Isoline", "MeshFileError", "Ridge", "RidgeSolver", "SurfacePoint", "compute_distance",
    "compute_ridge", "parallel", "read_mesh",
]

__version__ = "0.1.0"


def compute_ridge(V, F, source, solver="exact", **named_parameters):
    """The ridge of `source` on the mesh (V, F): a `Ridge` (a one-off `RidgeSolver(V, F, ...).ridge(source)`)."""
    return RidgeSolver(V, F, solver=solver, **named_parameters).ridge(source)


def compute_distance(V, F, source, faces=None, barycentric=None, solver="exact", field="linear",
                     **named_parameters):
    """Geodesic distances from `source`: at every vertex (n,), or at the surface points `faces` (k,) and
    `barycentric` (k, 3) when given, through the region-wise field (`field` "linear" or "cone")."""
    if (faces is None) != (barycentric is None):
        raise InvalidParameterError("faces and barycentric go together")
    ridge_solver = RidgeSolver(V, F, solver=solver, field=field, **named_parameters)
    if faces is None:
        return ridge_solver.ridge(source).vertex_distances  # (no field needed)
    distance_field = ridge_solver.distance_field(source, field)
    return distance_field.distance(np.asarray(faces), np.asarray(barycentric, dtype=np.float64))
