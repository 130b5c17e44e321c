# Copyright (c) 2026 Geodesic_ridge developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tests of the Python module: analytic oracles (the octahedron's distances and
ridge leaves, the genus of eight), agreement with the C++ results read back
from the command line's conventions, NumPy in and out, errors as exceptions,
the GIL released, and the Dask map."""
import json
import math
import os
import pathlib
import threading

import numpy as np
import pytest

import geodesic_ridge as gr

DATA = pathlib.Path(os.environ.get("GEODESIC_RIDGE_DATA_DIR", pathlib.Path(__file__).resolve().parents[2] / "data"))
SEED = 20261207


def octahedron():
    V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=np.float64)
    F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return V, F


def eight():
    return gr.read_mesh(str(DATA / "eight.off"))


def points_from_locations(V, F, ridge):
    return np.einsum("pi,pij->pj", ridge.barycentric, V[F[ridge.faces]])


def face_areas(V, F):
    return 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1)


# --- analytic oracles ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("solver", ["exact", "vtp"])
def test_octahedron_distances_and_leaves(solver):
    V, F = octahedron()
    ridge = gr.RidgeSolver(V, F, solver=solver).ridge(0)
    # from a vertex: its four neighbours at one edge (sqrt 2), the opposite vertex across two faces (sqrt 6)
    expected = [0, math.sqrt(6), math.sqrt(2), math.sqrt(2), math.sqrt(2), math.sqrt(2)]
    assert np.allclose(ridge.vertex_distances, expected, rtol=0, atol=1e-12)
    # a convex polyhedron: every vertex but the source is on the ridge, the four neighbours are leaves
    points = np.concatenate(ridge.polylines)
    ends = np.array([p for line in ridge.polylines for p in (line[0], line[-1])])
    for v in range(1, 6):
        assert np.min(np.linalg.norm(points - V[v], axis=1)) < 1e-9, "vertex %d is not on the ridge" % v
    for v in (2, 3, 4, 5):
        assert np.min(np.linalg.norm(ends - V[v], axis=1)) < 1e-9, "vertex %d is not a ridge end" % v
    stats = ridge.statistics["statistics"]["ridge"]
    assert stats["cycles"] == 0 and stats["components"] == 1


def test_eight_has_four_cycles_every_solver():
    V, F = eight()
    for solver in ["exact", "vtp", "fmm", "heat", "heat-idt", "dijkstra"]:
        ridge = gr.RidgeSolver(V, F, solver=solver).ridge(3)
        stats = ridge.statistics
        assert stats["mesh"]["genus"] == 2
        assert stats["statistics"]["ridge"]["cycles"] == 4, solver
        assert stats["statistics"]["ridge"]["components"] == 1, solver
        assert stats["statistics"]["solver"] == ("exact" if solver == "exact" else stats["statistics"]["solver"])
        assert len(ridge) == len(ridge.polylines) > 0


def test_fast_solvers_agree_with_exact_distances():
    V, F = eight()
    exact = gr.RidgeSolver(V, F).ridge(3).vertex_distances
    vtp = gr.RidgeSolver(V, F, solver="vtp").ridge(3).vertex_distances
    assert np.allclose(vtp, exact, rtol=1e-9, atol=1e-12)
    fmm = gr.RidgeSolver(V, F, solver="fmm").ridge(3).vertex_distances
    assert np.max(np.abs(fmm - exact)) / np.max(exact) < 0.05


# --- NumPy in and out ---------------------------------------------------------------------------------------

def test_ridge_points_are_their_locations():
    V, F = eight()
    ridge = gr.compute_ridge(V, F, 3)
    points = np.concatenate(ridge.polylines)
    assert points.shape == (len(ridge.faces), 3) == ridge.barycentric.shape
    assert ridge.faces.dtype == np.int64 and ridge.barycentric.dtype == np.float64
    assert ridge.angles.shape == ridge.faces.shape
    assert np.allclose(ridge.barycentric.sum(axis=1), 1)
    assert np.max(np.abs(points_from_locations(V, F, ridge) - points)) < 1e-12


def test_any_dtype_contiguity_and_corner_order_give_the_same_ridge():
    V, F = eight()
    reference = gr.RidgeSolver(V, F).ridge(3)
    F_rolled = np.roll(F, 1, axis=1)  # the same faces, from another corner
    for V2, F2 in [(np.asfortranarray(V), F.astype(np.int32)), (V.astype(np.float32).astype(np.float64), F),
                   (V, np.asfortranarray(F_rolled)), (V[:, [0, 1, 2]], F_rolled[::1].astype(np.int32))]:
        ridge = gr.RidgeSolver(V2, F2).ridge(3)
        assert len(ridge.polylines) == len(reference.polylines)
        # barycentric coordinates are in the caller's corner order
        assert np.max(np.abs(points_from_locations(V2, F2, ridge) - np.concatenate(ridge.polylines))) < 1e-9
    # the same ridge within round-off (CGAL's halfedge of a face starts at another corner)
    same = gr.RidgeSolver(V, F_rolled).ridge(3)
    assert len(same.polylines) == len(reference.polylines)
    for a, b in zip(same.polylines, reference.polylines):
        assert a.shape == b.shape and np.max(np.abs(a - b)) < 1e-9


def test_surface_point_sources():
    V, F = eight()
    solver = gr.RidgeSolver(V, F)
    rng = np.random.default_rng(SEED)
    print("seed", SEED)
    face = int(rng.integers(len(F)))
    b = rng.random(3)
    b /= b.sum()
    a = solver.ridge(gr.SurfacePoint(face, b))
    c = solver.ridge((face, list(b)))
    assert len(a.polylines) == len(c.polylines)
    # the exact (cone) field is 0 at the source; the linear one interpolates the corners in its face
    d = solver.distance_field(gr.SurfacePoint(face, b), field="cone")
    assert d.distance(np.array([face]), b[None, :])[0] < 1e-9
    # a vertex given as a corner of a face is that vertex
    corner = gr.SurfacePoint(face, [1.0, 0.0, 0.0])
    at_vertex = solver.ridge(int(F[face, 0]))
    assert np.allclose(solver.ridge(corner).vertex_distances, at_vertex.vertex_distances, atol=1e-12)


# --- distance fields ----------------------------------------------------------------------------------------

def test_distance_field_linear_and_cone():
    V, F = eight()
    solver = gr.RidgeSolver(V, F)
    linear = solver.distance_field(3)
    cone = solver.distance_field(3, field="cone")
    assert linear.kind == "linear" and cone.kind == "cone"
    rng = np.random.default_rng(SEED)
    k = 500
    faces = rng.integers(len(F), size=k)
    b = rng.random((k, 3))
    b /= b.sum(axis=1, keepdims=True)
    dl, dc = linear.distance(faces, b), cone.distance(faces, b)
    assert dl.shape == dc.shape == (k,)
    # at a corner both are the vertex distance
    corners = np.tile([0.0, 1.0, 0.0], (len(F), 1))
    assert np.allclose(linear.distance(np.arange(len(F)), corners), linear.vertex_distances[F[:, 1]], atol=1e-12)
    # the cone field is the exact distance, the linear one within a few percent of it inside faces
    assert np.all(dc >= 0) and np.max(np.abs(dl - dc)) / linear.maximum_distance < 0.05
    # the vertex distances (one-off function) and at points
    assert np.allclose(gr.compute_distance(V, F, 3), linear.vertex_distances)
    assert np.allclose(gr.compute_distance(V, F, 3, faces, b), dl)


def test_refined_mesh_covers_the_mesh():
    V, F = eight()
    solver = gr.RidgeSolver(V, F)
    V2, F2, distance, original = solver.refine(3)
    assert V2.shape[1] == 3 and F2.shape[1] == 3 and distance.shape == (len(V2),) and original.shape == (len(F2),)
    assert original.min() >= 0 and original.max() < len(F)
    # the pieces of every face add up to it
    area, area2 = face_areas(V, F), face_areas(V2, F2)
    assert np.allclose(np.bincount(original, weights=area2, minlength=len(F)), area, rtol=1e-9, atol=1e-15)
    # the mesh's vertices keep their distances
    ridge = solver.ridge(3)
    for v in range(0, len(V), 50):
        i = np.argmin(np.linalg.norm(V2 - V[v], axis=1))
        assert abs(distance[i] - ridge.vertex_distances[v]) < 1e-9


def test_isolines():
    V, F = eight()
    solver = gr.RidgeSolver(V, F)
    lines = solver.isolines(3, 10)
    levels = sorted({line.level for line in lines})
    maximum = solver.distance_field(3).maximum_distance
    assert len(levels) == 10 and 0 < levels[0] and levels[-1] < maximum
    for line in lines:
        assert isinstance(line, gr.Isoline) and line.points.shape[1] == 3 and np.all(np.isfinite(line.points))
        if line.closed:
            assert np.allclose(line.points[0], line.points[-1])
    chosen = solver.isolines(3, [0.5, 1.0])
    assert {line.level for line in chosen} == {0.5, 1.0}


def test_many_sources_match_one_at_a_time():
    V, F = eight()
    solver = gr.RidgeSolver(V, F, solver="fmm")
    sources = [0, 3, gr.SurfacePoint(5, [0.2, 0.3, 0.5]), 100]
    batch = solver.ridges(sources, threads=2)
    assert len(batch) == len(sources)
    for s, r in zip(sources, batch):
        one = solver.ridge(s)
        assert len(one.polylines) == len(r.polylines)
        assert np.allclose(one.vertex_distances, r.vertex_distances, atol=1e-12)


# --- errors -------------------------------------------------------------------------------------------------

def test_errors_are_typed_exceptions():
    V, F = eight()
    # the octahedron with a third face on its edge 0-2
    Vn = np.vstack([octahedron()[0], [[2.0, 2.0, 2.0]]])
    Fn = np.vstack([octahedron()[1], [[2, 0, 6]]])
    cases = [
        (lambda: gr.RidgeSolver(Vn, Fn), gr.InvalidMeshError, "edge 0-2 is non-manifold"),
        (lambda: gr.RidgeSolver(V[:, :2], F), gr.InvalidMeshError, "shape"),
        (lambda: gr.RidgeSolver(V, F.astype(np.float64)), gr.InvalidMeshError, "integers"),
        (lambda: gr.RidgeSolver(V, F + len(V)), gr.InvalidMeshError, "out of range"),
        (lambda: gr.RidgeSolver(V, np.vstack([F, F[:1]])), gr.InvalidMeshError, "duplicates"),
        (lambda: gr.RidgeSolver(np.where(V == V[0, 0], np.nan, V), F), gr.InvalidMeshError, "finite"),
        (lambda: gr.RidgeSolver(V, F, tolerance=0.7), gr.InvalidParameterError, "tolerance"),
        (lambda: gr.RidgeSolver(V, F, tolerence=0.1), gr.InvalidParameterError, "unknown named parameter"),
        (lambda: gr.RidgeSolver(V, F, solver="magic"), gr.InvalidParameterError, "unknown solver"),
        (lambda: gr.RidgeSolver(V, F, solver="fmm", field="cone"), gr.InvalidParameterError, "cones"),
        (lambda: gr.RidgeSolver(V, F).ridge(len(V)), gr.InvalidSourceError, "not a vertex"),
        (lambda: gr.RidgeSolver(V, F).ridge(gr.SurfacePoint(0, [0.5, 0.6, 0.1])), gr.InvalidSourceError, "sum to 1"),
        (lambda: gr.RidgeSolver(V, F).ridge(gr.SurfacePoint(len(F), [1, 0, 0])), gr.InvalidSourceError, "not a face"),
        (lambda: gr.read_mesh(str(DATA / "no such mesh.off")), gr.MeshFileError, "cannot open"),
    ]
    for call, kind, words in cases:
        with pytest.raises(kind) as info:
            call()
        assert words in str(info.value)
        assert isinstance(info.value, gr.Error)
        assert isinstance(info.value, ValueError)
    assert issubclass(gr.AlgorithmError, RuntimeError) and issubclass(gr.AlgorithmError, gr.Error)


def test_bad_queries():
    V, F = eight()
    field = gr.RidgeSolver(V, F).distance_field(3)
    with pytest.raises(gr.InvalidSourceError):
        field.distance(np.array([len(F)]), np.array([[1.0, 0, 0]]))
    with pytest.raises(gr.InvalidSourceError):
        field.distance(np.array([0]), np.array([[-0.5, 1.0, 0.5]]))
    with pytest.raises(gr.InvalidParameterError):
        field.distance(np.array([0, 1]), np.array([[1.0, 0, 0]]))


def test_read_mesh_with_polygons_maps_back_to_the_file(tmp_path):
    # a cube of quads: triangulated, so the faces are numbered anew and mapped back
    path = tmp_path / "cube.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n")
    V, F, back = gr.read_mesh(str(path))
    assert F.shape == (12, 3) and len(back.faces) == 12 and set(back.faces) == set(range(6))
    assert len(back.vertices) == len(V)
    ridge = gr.compute_ridge(V, F, 0)
    # the cube's ridge from a corner reaches the other corners (its vertices are leaves or on it)
    points = np.concatenate(ridge.polylines)
    far = int(np.argmax(np.linalg.norm(V - V[0], axis=1)))
    assert np.min(np.linalg.norm(points - V[far], axis=1)) < 1e-9


def test_read_mesh_repair(tmp_path):
    # the octahedron with a vertex no face uses: refused, or removed by the repair
    V, F = octahedron()
    V = np.vstack([V[:3], [[5.0, 5.0, 5.0]], V[3:]])
    F = np.where(F >= 3, F + 1, F)
    path = tmp_path / "dirty.off"
    path.write_text("OFF\n%d %d 0\n" % (len(V), len(F)) + "".join("%r %r %r\n" % tuple(p) for p in V)
                    + "".join("3 %d %d %d\n" % tuple(f) for f in F))
    with pytest.raises(gr.InvalidMeshError) as info:
        gr.read_mesh(str(path))
    assert "repair" in str(info.value)
    V2, F2, back = gr.read_mesh(str(path), repair=True)
    assert len(V2) == 6 and len(F2) == 8 and len(back.vertices) == 6 and len(back.faces) == 8
    assert 3 not in back.vertices and np.allclose(V[back.vertices], V2)
    ridge = gr.compute_ridge(V2, F2, 0)
    assert ridge.statistics["statistics"]["ridge"]["cycles"] == 0
    assert ridge.statistics["parameters"]["solver"] == "exact"
    assert ridge.statistics["parameters"]["tolerance"] == 0.025


# --- the GIL ------------------------------------------------------------------------------------------------

def test_computations_release_the_gil():
    V, F = gr.read_mesh(str(DATA / "teddy_3k.off"))
    solver = gr.RidgeSolver(V, F)
    done = threading.Event()
    results = []

    def work():
        results.append(solver.ridges([0, 100, 200], threads=1))
        done.set()

    worker = threading.Thread(target=work)
    ticks = 0
    worker.start()
    while not done.is_set():
        ticks += 1
        done.wait(0.001)
    worker.join()
    assert len(results[0]) == 3
    # this thread ran all along (with the GIL held it would have waited for the whole computation)
    assert ticks > 20


# --- many meshes on Dask ------------------------------------------------------------------------------------

def test_dask_map_records_failures_and_goes_on(tmp_path):
    pytest.importorskip("distributed")
    from distributed import Client, LocalCluster

    import geodesic_ridge.dask as grd

    tasks = [(str(DATA / "eight.off"), [0, 3, 10**6]), (str(tmp_path / "missing.off"), [0]),
             {"mesh": str(DATA / "torus_1k.off"), "sources": [0], "solver": "fmm"}]
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        table = grd.ridges(tasks, client=client, out_dir=str(tmp_path / "out"))
    assert [row["task"] for row in table] == [0, 1, 2]
    assert table[0]["succeeded"] == 2 and table[0]["failed"] == 1
    assert table[1]["error"] is not None and "cannot open" in table[1]["error"]
    assert table[2]["succeeded"] == 1 and table[2]["error"] is None
    folder = pathlib.Path(table[0]["out_dir"])
    summary = json.loads((folder / "summary.json").read_text())
    assert [s["status"] for s in summary["sources"]] == ["ok", "ok", "failed"]
    assert "not a vertex" in (folder / "ridge_2.error.txt").read_text()
    # the polylines read back as CGAL's format: the ridge of eight has 4 cycles
    lines = (folder / "ridge_1.polylines.txt").read_text().splitlines()
    stats = json.loads((folder / "ridge_1.json").read_text())
    assert len(lines) == stats["ridge"]["cone_polylines"] and stats["statistics"]["ridge"]["cycles"] == 4
    for line in lines:
        values = line.split()
        assert len(values) == 1 + 3 * int(values[0])
    torus = json.loads((pathlib.Path(table[2]["out_dir"]) / "ridge_0.json").read_text())
    assert torus["statistics"]["ridge"]["cycles"] == 2


# --- the same as the command line ---------------------------------------------------------------------------

def run_cli(tmp_path, *arguments):
    import subprocess
    cli = os.environ.get("GEODESIC_RIDGE_CLI")
    if not cli:
        pytest.skip("GEODESIC_RIDGE_CLI (the geodesic_ridge program) is not set")
    subprocess.run([cli, *map(str, arguments)], cwd=tmp_path, check=True, capture_output=True)


def read_polylines(path):
    lines = []
    for line in path.read_text().splitlines():
        values = line.split()
        lines.append(np.array([float(x) for x in values[1:]]).reshape(int(values[0]), 3))
    return lines


@pytest.mark.parametrize("solver", ["exact", "fmm"])
def test_outputs_equal_the_command_lines(tmp_path, solver):
    V, F = eight()
    solver_object = gr.RidgeSolver(V, F, solver=solver)
    rng = np.random.default_rng(SEED)
    faces = rng.integers(len(F), size=50)
    b = rng.random((50, 3))
    b /= b.sum(axis=1, keepdims=True)
    (tmp_path / "queries.txt").write_text("".join("%d %.17g %.17g %.17g\n" % (f, *c) for f, c in zip(faces, b)))
    run_cli(tmp_path, DATA / "eight.off", "--source-vertex", 3, "--solver", solver, "--ridge", "ridge.txt",
            "--ridge-locations", "locations.txt", "--refined", "refined.ply", "--query", "queries.txt",
            "--query-barycentric", "--query-out", "distances.txt", "--stats", "stats.json")
    ridge = solver_object.ridge(3)
    # the ridge's points, bit for bit (17 digits read back), and their faces
    cli_lines = read_polylines(tmp_path / "ridge.txt")
    assert len(cli_lines) == len(ridge.polylines)
    for a, b_ in zip(cli_lines, ridge.polylines):
        assert np.array_equal(a, b_)
    located = [line.split() for line in (tmp_path / "locations.txt").read_text().splitlines() if line[0] != "#"]
    assert np.array_equal([int(x[0]) for x in located], ridge.faces)
    # the distances at the queries, bit for bit
    field = solver_object.distance_field(3)
    cli_distances = np.array([float(x) for x in (tmp_path / "distances.txt").read_text().split()])
    assert np.array_equal(cli_distances, field.distance(faces, b))
    # the refined mesh, read with meshio: the same points, distances and source faces
    meshio = pytest.importorskip("meshio")
    mesh = meshio.read(str(tmp_path / "refined.ply"))
    V2, F2, distance, source_face = solver_object.refine(3)
    assert np.array_equal(mesh.points, V2) and np.array_equal(mesh.point_data["distance"], distance)
    assert np.array_equal(mesh.cells_dict["triangle"], F2)
    assert np.array_equal(mesh.cell_data["source_face"][0], source_face)
    stats = json.loads((tmp_path / "stats.json").read_text())
    assert stats["statistics"]["ridge"] == ridge.statistics["statistics"]["ridge"]


# --- the examples (examples/python/) ------------------------------------------------------------------------

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python"


def run_example(name, *arguments, cwd):
    import subprocess
    import sys
    # the module this test imported, wherever it is
    env = dict(os.environ, PYTHONPATH=str(pathlib.Path(gr.__file__).resolve().parents[1]))
    return subprocess.run([sys.executable, str(EXAMPLES / name), *map(str, arguments)], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600)


def test_example_ridge_and_field(tmp_path):
    done = run_example("ridge_and_field.py", DATA / "eight.off", 3, tmp_path / "picture.png", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "11 polylines" in done.stdout or "polylines" in done.stdout
    assert " 4 cycles" in done.stdout
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return
    png = (tmp_path / "picture.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10000


def test_example_dask_folder(tmp_path):
    pytest.importorskip("distributed")
    folder = tmp_path / "meshes"
    folder.mkdir()
    for name in ["eight.off", "torus_1k.off"]:
        (folder / name).write_bytes((DATA / name).read_bytes())
    (folder / "broken.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    done = run_example("dask_folder.py", folder, 3, tmp_path / "out", cwd=tmp_path)
    assert done.returncode == 1, done.stdout + done.stderr  # one mesh failed
    rows = [line for line in done.stdout.splitlines()[1:]]
    assert len(rows) == 3 and "MeshFileError" in [r for r in rows if "broken" in r][0]
    for name in ["1_eight", "2_torus_1k"]:
        summary = json.loads((tmp_path / "out" / name / "summary.json").read_text())
        assert [s["status"] for s in summary["sources"]] == ["ok"] * 3
