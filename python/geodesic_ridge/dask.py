# Copyright (c) 2026 Geodesic_ridge developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Many meshes on a Dask cluster: ``ridges(tasks, client=None, out_dir=...)``.

A task is ``(mesh_file, sources)`` (or a dict with keys ``mesh``, ``sources``
and optionally ``repair``, ``solver`` and named parameters): the mesh is read
as the command line reads it, and the ridge of each source is written as the
command line's batch writes it (``--sources``), in ``out_dir/NAME/`` where NAME
is the task's index and the mesh file's stem: ``ridge_K.polylines.txt`` (CGAL
polylines), ``ridge_K.json`` (the statistics), or ``ridge_K.error.txt`` with
the message when source K fails; and ``summary.json``. Every file is written
beside its target and renamed onto it: whole, or not there at all.

A task that fails (its mesh cannot be read, a source is not on it) records its
error and the other tasks complete. Needs Debian's python3-dask and
python3-distributed.
"""
import json
import os
import time

__all__ = ["ridges", "run_task"]


def _write(path, text):
    temporary = os.path.join(os.path.dirname(path), "." + os.path.basename(path) + ".tmp.%d" % os.getpid())
    with open(temporary, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(temporary, path)


def _polylines_text(polylines):
    # CGAL's polylines format: per line the number of points, then their coordinates
    out = []
    for line in polylines:
        out.append(" ".join([str(len(line))] + ["%.17g %.17g %.17g" % tuple(p) for p in line]))
    return "\n".join(out) + ("\n" if out else "")


def _task_parts(task):
    if isinstance(task, dict):
        options = dict(task)
        mesh = options.pop("mesh")
        sources = options.pop("sources")
    else:
        mesh, sources = task
        options = {}
    return mesh, list(sources), options


def run_task(index, task, out_dir):
    """Runs one task in this process and returns its row of the table (see `ridges`)."""
    import geodesic_ridge as gr

    mesh, sources, options = _task_parts(task)
    repair = bool(options.pop("repair", False))
    solver_name = options.pop("solver", "exact")
    name = "%d_%s" % (index, os.path.splitext(os.path.basename(str(mesh)))[0])
    folder = os.path.join(out_dir, name)
    os.makedirs(folder, exist_ok=True)
    row = {"task": index, "mesh": str(mesh), "out_dir": folder, "sources": len(sources), "succeeded": 0,
           "failed": 0, "error": None, "seconds": 0.0}
    start = time.perf_counter()
    summary = []
    try:
        read = gr.read_mesh(str(mesh), repair=repair)
        solver = gr.RidgeSolver(read[0], read[1], solver=solver_name, **options)
    except Exception as e:  # the task fails as a whole; the others go on
        row["error"] = "%s: %s" % (type(e).__name__, e)
        row["failed"] = len(sources)
        row["seconds"] = time.perf_counter() - start
        _write(os.path.join(folder, "task.error.txt"), row["error"] + "\n")
        return row
    for k, source in enumerate(sources):
        t = time.perf_counter()
        entry = {"source": source if isinstance(source, int) else [int(source[0]), [float(x) for x in source[1]]]}
        try:
            if not isinstance(source, int):
                source = gr.SurfacePoint(int(source[0]), source[1])
            ridge = solver.ridge(source)
            _write(os.path.join(folder, "ridge_%d.polylines.txt" % k), _polylines_text(ridge.polylines))
            _write(os.path.join(folder, "ridge_%d.json" % k), json.dumps(ridge.statistics, indent=2) + "\n")
            error_file = os.path.join(folder, "ridge_%d.error.txt" % k)
            if os.path.exists(error_file):
                os.remove(error_file)  # of an earlier run
            entry.update(status="ok", files=["ridge_%d.polylines.txt" % k, "ridge_%d.json" % k])
            row["succeeded"] += 1
        except gr.Error as e:
            _write(os.path.join(folder, "ridge_%d.error.txt" % k), "%s\n" % e)
            entry.update(status="failed", error=str(e), files=["ridge_%d.error.txt" % k])
            row["failed"] += 1
        entry["seconds"] = time.perf_counter() - t
        summary.append(entry)
    _write(os.path.join(folder, "summary.json"), json.dumps({"mesh": str(mesh), "sources": summary}, indent=2) + "\n")
    row["seconds"] = time.perf_counter() - start
    if row["failed"]:
        row["error"] = "%d of %d sources failed" % (row["failed"], len(sources))
    return row


def ridges(tasks, client=None, out_dir="ridges"):
    """Maps the tasks over a Dask cluster and returns a table of what each task did: a list of dicts with
    ``task``, ``mesh``, ``out_dir``, ``sources``, ``succeeded``, ``failed``, ``error`` (None, or why) and
    ``seconds``, in the order of `tasks`.

    `client` is a ``distributed.Client``, a scheduler's address (``"tcp://host:8786"``), or None for a
    ``LocalCluster`` on this machine (closed at the end)."""
    from distributed import Client, LocalCluster

    tasks = list(tasks)
    os.makedirs(out_dir, exist_ok=True)
    out_dir = os.path.abspath(out_dir)
    own = None
    if client is None:
        own = LocalCluster(processes=True, dashboard_address=None)
        client = Client(own)
    elif isinstance(client, str):
        client = Client(client)
    try:
        futures = [client.submit(run_task, i, task, out_dir, pure=False) for i, task in enumerate(tasks)]
        rows = []
        for i, f in enumerate(futures):
            try:
                rows.append(f.result())
            except Exception as e:  # a worker lost, say: the task's row says so
                mesh = _task_parts(tasks[i])[0]
                rows.append({"task": i, "mesh": str(mesh), "out_dir": None, "sources": None, "succeeded": 0,
                             "failed": None, "error": "%s: %s" % (type(e).__name__, e), "seconds": None})
        return rows
    finally:
        if own is not None:
            client.close()
            own.close()
