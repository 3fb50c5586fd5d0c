"""marchstudio from Python (docs/python.md)."""
import os
from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from ._marchstudio import Error as Error
from .sdf.core import SDF

Point = Sequence[float]
Bounds = Tuple[Point, Point]

class Mesh:
    vertices: npt.NDArray[np.float32]  # (N, 3)
    faces: npt.NDArray[np.uint32]      # (M, 3), counter-clockwise from outside
    report: Dict[str, Any]             # the mesh report (schema marchstudio.mesh/1)
    @property
    def watertight(self) -> bool: ...
    def triangles(self) -> npt.NDArray[np.float32]: ...

class Scene:
    path: str
    backend: str
    def __init__(self, source: Union[str, os.PathLike, SDF], backend: str = "auto") -> None: ...
    def render(self, size: Optional[Tuple[int, int]] = None, time: Optional[float] = None, spp: int = 0,
               preset: str = "", dtype: Any = np.float32) -> npt.NDArray: ...
    def mesh(self, resolution: Optional[int] = None, voxel: Optional[float] = None,
             bounds: Optional[Bounds] = None, time: Optional[float] = None) -> Mesh: ...
    def save_mesh(self, path: Union[str, os.PathLike], resolution: Optional[int] = None,
                  voxel: Optional[float] = None, bounds: Optional[Bounds] = None,
                  time: Optional[float] = None) -> Dict[str, Any]: ...
    PREVIEW_SIZE: Tuple[int, int]
    def _repr_png_(self) -> bytes: ...
    def bench(self, size: Optional[Tuple[int, int]] = None, frames: int = 30, warmup: int = 3,
              spp: int = 0) -> Dict[str, Any]: ...
    def level_set(self, path: Union[str, os.PathLike], resolution: Optional[int] = None,
                  voxel: Optional[float] = None, bounds: Optional[Bounds] = None,
                  time: Optional[float] = None, band: int = 3) -> Dict[str, Any]: ...
    def box(self) -> Optional[Tuple[Tuple[float, float, float], Tuple[float, float, float]]]: ...

def load(path: Union[str, os.PathLike], backend: str = "auto") -> Scene: ...
def read_image(path: Union[str, os.PathLike]) -> npt.NDArray[np.float32]: ...
