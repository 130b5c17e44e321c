#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The ridge of a vertex, distances at points inside faces, iso-lines and the
refined mesh, from NumPy; with matplotlib installed, a picture of the ridge on
the distance field (OUT.png).

    python3 ridge_and_field.py [MESH [VERTEX [OUT.png]]]
"""
import sys

import numpy as np

import geodesic_ridge as gr

mesh = sys.argv[1] if len(sys.argv) > 1 else "data/eight.off"
source = int(sys.argv[2]) if len(sys.argv) > 2 else 3
picture = sys.argv[3] if len(sys.argv) > 3 else "ridge_and_field.png"

V, F = gr.read_mesh(mesh)[:2]
solver = gr.RidgeSolver(V, F, solver="exact", tolerance=0.025)
ridge = solver.ridge(source)
s = ridge.statistics["statistics"]["ridge"]
print("%s from vertex %d: %d polylines, %d junctions, %d cycles, length %.6g"
      % (mesh, source, len(ridge.polylines), s["junctions"], s["cycles"], s["total_length"]))

# distances at the centroids of all faces, linear and exact (cone) field
field = solver.distance_field(source, field="cone")
centroids = np.full((len(F), 3), 1.0 / 3.0)
d = field.distance(np.arange(len(F)), centroids)
print("distance at the face centroids: min %.6g, max %.6g" % (d.min(), d.max()))

V2, F2, distance, source_face = solver.refine(source)
lines = solver.isolines(source, 12)
print("refined mesh: %d faces (%d faces of the mesh split); %d iso-lines"
      % (len(F2), int(np.sum(np.bincount(source_face, minlength=len(F)) > 1)), len(lines)))

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
except ImportError:
    print("matplotlib is not installed: no picture")
    sys.exit(0)

figure = plt.figure(figsize=(8, 6))
axes = figure.add_subplot(projection="3d")
axes.computed_zorder = False  # the curves over the surface (matplotlib does not sort lines with faces)
colours = plt.get_cmap("viridis")(distance[F2].mean(axis=1) / max(distance.max(), 1e-300))
axes.add_collection3d(Poly3DCollection(V2[F2], facecolors=colours, linewidths=0, alpha=0.45, zorder=1))
for line in lines:
    axes.plot(line.points[:, 0], line.points[:, 1], line.points[:, 2], color="black", linewidth=0.5, zorder=2)
for line in ridge.polylines:
    axes.plot(line[:, 0], line[:, 1], line[:, 2], color="red", linewidth=2.5, zorder=3)
low, high = V.min(axis=0), V.max(axis=0)
axes.set_xlim(low[0], high[0])
axes.set_ylim(low[1], high[1])
axes.set_zlim(low[2], high[2])
axes.set_box_aspect(high - low)
axes.view_init(elev=55, azim=-60)
figure.subplots_adjust(0, 0, 1, 0.93)
axes.set_axis_off()
axes.set_title("geodesic ridge (red) and iso-lines of vertex %d" % source)
figure.savefig(picture, dpi=100)
print("wrote", picture)
