"""fogleman/sdf's save() and generate() over the mesh job: `samples` is the
total cell count over the bounds, `step` a cell's side, `bounds` by default
the graph's own box."""
import os

import numpy as np

from ._scene import Scene


def _voxel(scene, step, bounds, samples):
    if step is not None:
        s = np.asarray(step, dtype=float).reshape(-1)
        if not np.allclose(s, s[0]) or not s[0] > 0:
            raise ValueError(f"marchstudio.sdf: step must be one size > 0 (cells are cubes), not {step!r}")
        return float(s[0]), bounds
    box = bounds if bounds is not None else scene.box()
    if box is None:
        raise ValueError("marchstudio.sdf: the shape has no box: give bounds=((x0, y0, z0), (x1, y1, z1))")
    lo, hi = np.asarray(box[0], float), np.asarray(box[1], float)
    if not float(samples) >= 1:
        raise ValueError(f"marchstudio.sdf: samples must be >= 1, not {samples!r}")
    return float(np.prod(hi - lo) / float(samples)) ** (1 / 3), bounds


def save(shape, path, step=None, bounds=None, samples=2**22):
    scene = Scene(shape)
    voxel, bounds = _voxel(scene, step, bounds, samples)
    return scene.save_mesh(os.fspath(path), voxel=voxel, bounds=bounds)


def generate(shape, step=None, bounds=None, samples=2**22):
    scene = Scene(shape)
    voxel, bounds = _voxel(scene, step, bounds, samples)
    return scene.mesh(voxel=voxel, bounds=bounds).triangles()
