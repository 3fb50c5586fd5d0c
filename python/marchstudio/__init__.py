"""marchstudio from Python (docs/python.md): render and mesh scene files and
graphs through the C++ pipeline, and build graphs in fogleman/sdf's words
(`from marchstudio.sdf import *`).

    import marchstudio
    scene = marchstudio.load('part.json')
    rgba = scene.render(size=(320, 180))        # (180, 320, 4) float32
    m = scene.mesh(resolution=64)               # m.vertices, m.faces, m.report
"""
import os as _os

_here = _os.path.dirname(_os.path.abspath(__file__))
# The package's own modules, beside it in the build tree and when installed:
# passed explicitly (io/module_file.h's variables), never searched for.
_os.environ.setdefault('MARCH_IMAGE_MODULE', _os.path.join(_here, 'marchstudio-oiio.so'))
_os.environ.setdefault('MARCH_VDB_MODULE', _os.path.join(_here, 'marchstudio-vdb.so'))

from . import _marchstudio  # noqa: E402

_marchstudio.set_shader_dir(_os.path.join(_here, 'sdf_shaders'))

Error = _marchstudio.Error
Error.__doc__ = "A scene, flag or file marchstudio refused: the command line's one-line message."

from ._scene import Scene, Mesh, load  # noqa: E402


def read_image(path):
    """An image file (PNG, EXR, anything OpenImageIO reads) as an (H, W, C) float32 array."""
    return _marchstudio.read_image(_os.fspath(path))


__all__ = ['Error', 'Scene', 'Mesh', 'load', 'read_image']
