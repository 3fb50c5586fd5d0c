"""The native API: a scene file or a shape, rendered into numpy and meshed
into numpy by the same jobs as `marchstudio render` and `marchstudio mesh`."""
import json
import os
import shutil
import tempfile
import weakref

import numpy as np

from . import _marchstudio as _ext

_BACKENDS = ('auto', 'egl', 'osmesa')


class Mesh:
    """A mesh in numpy: vertices (N, 3) float32, faces (M, 3) uint32
    (counter-clockwise from outside), and the mesh report as a dict (its
    "check" says whether the surface is closed, manifold and oriented)."""

    def __init__(self, vertices, faces, report):
        self.vertices = vertices
        self.faces = faces
        self.report = report

    @property
    def watertight(self):
        c = self.report['check']
        return c['boundary_edges'] == 0 and c['nonmanifold_edges'] == 0

    def triangles(self):
        """The corners, 3 per triangle: (3M, 3) float32, as fogleman's generate()."""
        return self.vertices[self.faces].reshape(-1, 3)


class Scene:
    """A scene file (.toml, a graph .json, a Shadertoy shader) or a shape of
    marchstudio.sdf, which is written to a graph file kept for the scene's life."""

    PREVIEW_SIZE = (320, 180)  # _repr_png_'s picture, width x height

    def __init__(self, source, backend='auto'):
        from .sdf.core import SDF
        if backend not in _BACKENDS:
            raise ValueError(f"marchstudio: backend must be one of {', '.join(_BACKENDS)}, not {backend!r}")
        self.backend = backend
        if isinstance(source, SDF):
            if source.dim != 3:
                raise ValueError("marchstudio: a 2D shape is not a scene: extrude() or revolve() it")
            d = tempfile.mkdtemp(prefix='marchstudio-')
            self._cleanup = weakref.finalize(self, shutil.rmtree, d, True)
            self.path = os.path.join(d, 'shape.json')
            source.to_json(self.path)
        elif isinstance(source, (str, os.PathLike)):
            self.path = os.path.abspath(os.fspath(source))
        else:
            raise ValueError(f"marchstudio: a Scene is made from a path or a marchstudio.sdf shape, not {source!r}")

    def render(self, size=None, time=None, spp=0, preset='', dtype=np.float32):
        """The image as (H, W, 4): float32 linear (what an .exr holds) or,
        with dtype=np.uint8, the display values a .png holds. `size` (w, h)
        and the rest default to the scene's. Releases the GIL while drawing."""
        w, h = (0, 0) if size is None else _size(size)
        if np.dtype(dtype) not in (np.dtype(np.float32), np.dtype(np.uint8)):
            raise ValueError(f"marchstudio: dtype must be float32 or uint8, not {dtype!r}")
        if not 0 <= int(spp) <= 1024:
            raise ValueError(f"marchstudio: spp must be 1..1024 (0: the scene's), not {spp!r}")
        return _ext.render(self.path, w, h, _time(time), int(spp), str(preset), self.backend,
                           np.dtype(dtype) == np.dtype(np.uint8))

    def mesh(self, resolution=None, voxel=None, bounds=None, time=None):
        """The surface as a Mesh: `resolution` cells along the box's longest
        side (256) or cells of side `voxel`, over `bounds` ((x0, y0, z0),
        (x1, y1, z1)) or the scene's own box."""
        report, v, f = _ext.mesh(self.path, '', *_grid(resolution, voxel), _bounds(bounds), _time(time),
                                 self.backend, True)
        return Mesh(v, f, json.loads(report))

    def save_mesh(self, path, resolution=None, voxel=None, bounds=None, time=None):
        """Writes the mesh (.stl .obj .ply .glb) or level set (.vdb) atomically;
        returns the mesh report as a dict."""
        report, _, _ = _ext.mesh(self.path, os.fspath(path), *_grid(resolution, voxel), _bounds(bounds),
                                 _time(time), self.backend, False)
        return json.loads(report)

    def _repr_png_(self):
        """Jupyter's picture: the PNG file a 320x180 render writes, as bytes."""
        w, h = self.PREVIEW_SIZE
        return _ext.render_png(self.path, w, h, self.backend)

    def bench(self, size=None, frames=30, warmup=3, spp=0):
        """`marchstudio bench --json`'s figures as a dict (docs/bench.md):
        compile and frame times, steps and map() calls per pixel. Timed in
        this process's GL context, the one renders use."""
        w, h = (0, 0) if size is None else _size(size)
        if not 1 <= int(frames) or not 0 <= int(warmup):
            raise ValueError(f"marchstudio: frames must be >= 1 and warmup >= 0, not {frames!r}, {warmup!r}")
        if not 0 <= int(spp) <= 1024:
            raise ValueError(f"marchstudio: spp must be 1..1024 (0: the scene's), not {spp!r}")
        return json.loads(_ext.bench(self.path, w, h, int(frames), int(warmup), int(spp), self.backend))

    def level_set(self, path, resolution=None, voxel=None, bounds=None, time=None, band=3):
        """Writes the narrow band of the distance field, `band` voxels each
        side, as an OpenVDB level set (`path` ends in .vdb), atomically,
        through the mesh job (`marchstudio mesh -o x.vdb --band N`); returns
        the mesh report (its band_voxels: the active voxels written)."""
        if path is None or not os.fspath(path).lower().endswith('.vdb'):
            raise ValueError(f"marchstudio: level_set writes a .vdb file: give its path, not {path!r}")
        if not 1 <= int(band) <= 64:
            raise ValueError(f"marchstudio: band must be 1..64 voxels, not {band!r}")
        report, _, _ = _ext.mesh(self.path, os.fspath(path), *_grid(resolution, voxel), _bounds(bounds),
                                 _time(time), self.backend, False, int(band))
        return json.loads(report)

    def box(self):
        """The scene's own box ((x0, y0, z0), (x1, y1, z1)), or None."""
        b = _ext.scene_box(self.path)
        return None if b is None else (tuple(b[:3]), tuple(b[3:]))


def load(path, backend='auto'):
    """A Scene from a file."""
    return Scene(os.fspath(path), backend=backend)


def _size(size):
    try:
        w, h = (int(x) for x in size)
    except (TypeError, ValueError):
        raise ValueError(f"marchstudio: size must be (width, height), not {size!r}") from None
    if w < 1 or h < 1:
        raise ValueError(f"marchstudio: size must be positive, not {size!r}")
    return w, h


def _time(time):
    return None if time is None else float(time)


def _grid(resolution, voxel):
    if resolution is not None and voxel is not None:
        raise ValueError("marchstudio: give resolution or voxel, not both")
    if voxel is not None:
        if not float(voxel) > 0:
            raise ValueError(f"marchstudio: voxel must be > 0, not {voxel!r}")
        return 256, float(voxel)
    r = 256 if resolution is None else int(resolution)
    if not 1 <= r <= 4096:
        raise ValueError(f"marchstudio: resolution must be 1..4096, not {resolution!r}")
    return r, 0.0


def _bounds(bounds):
    if bounds is None:
        return None
    try:
        lo, hi = bounds
        b = tuple(float(x) for x in tuple(lo) + tuple(hi))
    except (TypeError, ValueError):
        raise ValueError(f"marchstudio: bounds must be ((x0, y0, z0), (x1, y1, z1)), not {bounds!r}") from None
    if len(b) != 6 or not all(b[i] < b[i + 3] for i in range(3)):
        raise ValueError(f"marchstudio: bounds must be ((x0, y0, z0), (x1, y1, z1)) with x0 < x1 ..., not {bounds!r}")
    return b
