#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""What the Python module costs and what it gains, as a Markdown table:

1. one ridge from Python against the same call's C++ pipeline time (the
   ridge's own `timings_seconds.total`), and the arrays' conversion;
2. two ridges on two Python threads against one thread (the GIL released);
3. `ridges()` with 64 sources against a Python loop of `ridge()`;
4. `geodesic_ridge.dask.ridges` on 8 meshes x 4 sources, a LocalCluster of 2
   worker processes against 1.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/bench_python.py [--quick]

Meshes from ../shared/data (bunny_70k, torus_10k and the small ones); --quick
takes smaller ones. Times are the best of 3 (the dask row: of 1).
"""
import os
import pathlib
import sys
import tempfile
import threading
import time

import geodesic_ridge as gr

ROOT = pathlib.Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "data"
DATA = ROOT / "data"
quick = "--quick" in sys.argv


def mesh_path(name):
    for folder in (SHARED, DATA):
        if (folder / name).exists():
            return folder / name
    sys.exit("bench_python: %s not found in %s or %s" % (name, SHARED, DATA))


def best(f, repeat=3):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    rows = []

    def row(question, mesh, measured, target, ok):
        rows.append((question, mesh, measured, target, "yes" if ok else "**no**"))

    # 1. the call's cost over C++
    name = "bunny_7k.off" if quick else "bunny_70k.off"
    V, F = gr.read_mesh(str(mesh_path(name)))[:2]
    solver = gr.RidgeSolver(V, F, solver="vtp")
    results = []
    python_seconds = best(lambda: results.append(solver.ridge(0)))
    cpp_seconds = min(r.statistics["timings_seconds"]["total"] for r in results)
    r = results[-1]
    convert_seconds = best(lambda: (r.polylines, r.faces, r.barycentric, r.angles, r.vertex_distances))
    over = python_seconds / cpp_seconds - 1
    row("`ridge()` (vtp) over the C++ pipeline's time", name,
        "%.3f s against %.3f s: +%.1f %%; its arrays %.1e s" % (python_seconds, cpp_seconds, 100 * over, convert_seconds),
        "<= 5 %", over <= 0.05)

    # 2. two threads
    name = "torus_1k.off" if quick else "torus_10k.off"
    V, F = gr.read_mesh(str(mesh_path(name)))[:2]
    solver = gr.RidgeSolver(V, F, solver="exact")
    sources = [0, len(V) // 2]
    one = best(lambda: [solver.ridge(s) for s in sources])

    def two_threads():
        threads = [threading.Thread(target=solver.ridge, args=(s,)) for s in sources]
        for t in threads:
            t.start()
        for t in threads:
            t.join()

    two = best(two_threads)
    row("two ridges (exact) on two threads against one", name, "%.3f s against %.3f s: %.2fx" % (two, one, one / two),
        ">= 1.7x", one / two >= 1.7)

    # 3. ridges() against a loop
    solver = gr.RidgeSolver(V, F, solver="fmm")
    sources = [k * len(V) // 64 for k in range(64)]
    loop = best(lambda: [solver.ridge(s) for s in sources], repeat=1)
    batch = best(lambda: solver.ridges(sources), repeat=1)
    row("`ridges()` of 64 sources (fmm) against a loop of `ridge()`", name,
        "%.3f s against %.3f s: %.2fx (TBB: %s)" % (batch, loop, loop / batch, gr.parallel), ">= 1.8x", loop / batch >= 1.8)

    # 4. dask
    try:
        from distributed import Client, LocalCluster

        import geodesic_ridge.dask as grd
    except ImportError:
        row("dask, 2 workers against 1", "-", "python3-distributed is not installed", ">= 1.6x", False)
    else:
        names = ["eight.off", "torus_1k.off", "bunny_1k.off", "armadillo_2k.off", "knot_3k.off", "teddy_3k.off",
                 "3holes_7k.off", "kitten_5k.off"]
        tasks = []
        for n in names:
            path = mesh_path(n)
            count = len(gr.read_mesh(str(path))[0])
            tasks.append((str(path), [k * count // 4 for k in range(4)]))
        seconds = {}
        with tempfile.TemporaryDirectory() as out:
            for workers in (1, 2):
                with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, Client(cluster) as client:
                    client.run(lambda: __import__("geodesic_ridge"))  # (the import is not what is measured)
                    start = time.perf_counter()
                    table = grd.ridges(tasks, client=client, out_dir=os.path.join(out, str(workers)))
                    seconds[workers] = time.perf_counter() - start
                    assert all(t["error"] is None for t in table), table
        gain = seconds[1] / seconds[2]
        row("dask: 8 meshes x 4 sources, 2 worker processes against 1", "8 meshes, 1k-7k faces",
            "%.2f s against %.2f s: %.2fx" % (seconds[2], seconds[1], gain), ">= 1.6x", gain >= 1.6)

    print("| question | mesh | measured | target | met |")
    print("|---|---|---|---|---|")
    for r in rows:
        print("| %s | %s | %s | %s | %s |" % r)


if __name__ == "__main__":  # (the LocalCluster's worker processes import this file)
    main()
