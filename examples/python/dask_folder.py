#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The ridges of N sources on every mesh of a folder, on a Dask cluster: the
command line's batch outputs per mesh (ridge_K.polylines.txt, ridge_K.json,
ridge_K.error.txt, summary.json) under OUT_DIR, and a table of what each mesh
did.

    python3 dask_folder.py FOLDER [N [OUT_DIR [SCHEDULER_ADDRESS]]]

Without a scheduler's address it starts a LocalCluster on this machine.
"""
import os
import sys

import geodesic_ridge as gr
import geodesic_ridge.dask as grd

folder = sys.argv[1] if len(sys.argv) > 1 else "data"
n = int(sys.argv[2]) if len(sys.argv) > 2 else 4
out_dir = sys.argv[3] if len(sys.argv) > 3 else "dask_out"
scheduler = sys.argv[4] if len(sys.argv) > 4 else None

if __name__ == "__main__":  # (the local cluster's worker processes import this file)
    tasks = []
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if not name.lower().endswith((".off", ".obj", ".ply")):
            continue
        try:
            vertices = len(gr.read_mesh(path)[0])
        except gr.Error:
            vertices = 1  # the task records why it cannot be read
        tasks.append((path, [k * vertices // n for k in range(n)]))
    table = grd.ridges(tasks, client=scheduler, out_dir=out_dir)
    print("%-40s %8s %6s %9s  %s" % ("mesh", "sources", "failed", "seconds", "error"))
    for row in table:
        print("%-40s %8s %6s %9.3f  %s" % (row["mesh"], row["sources"], row["failed"], row["seconds"] or 0,
                                           row["error"] or ""))
    sys.exit(1 if any(row["error"] for row in table) else 0)
