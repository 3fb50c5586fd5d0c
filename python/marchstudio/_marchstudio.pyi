"""marchstudio's native half (python/src/marchstudio_ext.cpp)."""
from typing import Optional, Tuple

import numpy as np
import numpy.typing as npt

Box = Tuple[float, float, float, float, float, float]

class Error(RuntimeError):
    """The command line's one-line message: file:line: pointer: what (hint)."""

def set_shader_dir(dir: str) -> None: ...
def render(input: str, width: int = 0, height: int = 0, time: Optional[float] = None, spp: int = 0,
           preset: str = "", backend: str = "auto", uint8: bool = False) -> npt.NDArray: ...
def mesh(input: str, output: str = "", resolution: int = 256, voxel: float = 0.0, bounds: Optional[Box] = None,
         time: Optional[float] = None, backend: str = "auto",
         arrays: bool = True) -> Tuple[str, Optional[npt.NDArray[np.float32]], Optional[npt.NDArray[np.uint32]]]: ...
def read_image(path: str) -> npt.NDArray[np.float32]: ...
def scene_box(input: str) -> Optional[Box]: ...
