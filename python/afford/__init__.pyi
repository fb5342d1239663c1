# Type stubs of the package afford (python/afford/__init__.py): units are SI
# (m, N, s, rad); see the docstrings and docs/python.md.
import os
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

PathLike = Union[str, os.PathLike[str]]
Sample = Union[Tuple[float, float, float], Sequence[float], npt.NDArray[np.float64]]

class DataError(ValueError):
    file: str     # the file the mistake is in
    line: int     # 1-based; 0 when it is about the whole file
    column: int   # 1-based
    message: str  # "expected X, found Y"

class FrameEvent:
    @property
    def kind(self) -> str: ...      # node_reached, node_lost or inferred
    @property
    def function(self) -> str: ...
    @property
    def node(self) -> int: ...      # 0-based
    @property
    def text(self) -> str: ...      # the node's `when`
    @property
    def t(self) -> float: ...       # s

class Frame:
    @property
    def t(self) -> float: ...             # s
    @property
    def angle(self) -> float: ...         # rad, the lever's opening
    @property
    def effort_force(self) -> float: ...  # N, the hand's push at the thumb
    @property
    def actee_force(self) -> float: ...   # N, between the jaws and the actee
    @property
    def actee_load(self) -> float: ...    # N, along the actee's axis
    @property
    def finger_forces(self) -> List[float]: ...  # N, haptic force per finger, thumb first
    @property
    def grasped(self) -> bool: ...
    @property
    def held(self) -> bool: ...
    @property
    def broken(self) -> bool: ...
    @property
    def events(self) -> List[FrameEvent]: ...

class State:
    def step(self, sample: Optional[Sample] = None) -> Frame: ...  # the thumb's target, m, world; None: the script's
    def script_thumb(self, t: Optional[float] = None) -> List[float]: ...  # m, world, at t s (default: the next frame)
    @property
    def t(self) -> float: ...       # s, of the last frame
    @property
    def frame(self) -> int: ...     # frames stepped
    @property
    def next_t(self) -> float: ...  # s, the next frame's time
    @property
    def hash(self) -> int: ...      # of every simulated field (determinism)
    def functions(self) -> List[Dict[str, Any]]: ...  # inferred so far, as Model.run()'s "functions"

class Model:
    @property
    def name(self) -> str: ...
    @property
    def description(self) -> str: ...
    @property
    def timestep(self) -> float: ...  # s
    @property
    def duration(self) -> float: ...  # s
    @property
    def functions(self) -> List[str]: ...
    @property
    def files(self) -> List[str]: ...
    @property
    def warnings(self) -> List[str]: ...
    def run(self) -> Dict[str, Any]: ...  # {"session", "functions", "frames", "trace": {column: ndarray}}
    def state(self) -> State: ...

def data_dir() -> str: ...
def load(session_path: PathLike) -> Model: ...
def compile(object: PathLike, actee: Union[None, PathLike, Mapping[str, Any]] = ..., *,
            script: Sequence[Mapping[str, Any]], agent: Optional[PathLike] = ..., rules: Optional[PathLike] = ...,
            grasps: Optional[PathLike] = ..., name: str = ..., timestep: Optional[str] = ...) -> Model: ...
def explore(object: PathLike, actees: Optional[Sequence[PathLike]] = ..., *, agent: Optional[PathLike] = ...,
            rules: Optional[PathLike] = ..., taxonomy: Optional[PathLike] = ..., placements: int = ...,
            thumbs: int = ..., efforts: int = ..., max_effort: float = ..., fixed_efforts: bool = ...,
            grasps: Sequence[str] = ..., tolerance: float = ..., threads: int = ...) -> Dict[str, npt.NDArray[Any]]: ...
def gap(measurement_path: PathLike, effects: Sequence[str] = ...) -> Dict[str, Any]: ...
def check(path: PathLike) -> Dict[str, Any]: ...
def effects() -> List[Dict[str, Any]]: ...
def signals() -> List[Dict[str, Any]]: ...
def export_mjcf(session: Union[PathLike, Model]) -> str: ...
