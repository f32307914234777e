"""hrspace from Python (type stubs; docs/python.md)."""

import os
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import rs as rs

__version__: str
"""The version of hrspace, as `hrspace --version` prints it ("0.9.0")."""
__commit__: str
"""The git commit it was built from (short hash), or "unknown"."""

Pose = Sequence[float]
"""(x, y, theta): metres and radians."""

PoseArray = npt.ArrayLike
"""Poses of shape (N, 3), one (x, y, theta) per row."""

class Object:
    """One piece of furniture of a Scene (a view: edits change the scene)."""

    @property
    def id(self) -> str:
        """The object's id."""
    @property
    def pose(self) -> Tuple[float, float, float]:
        """Position and heading (x, y, theta); settable."""
    @pose.setter
    def pose(self, value: Pose) -> None: ...
    @property
    def fixed(self) -> bool:
        """True when the optimizer never moves the object; settable."""
    @fixed.setter
    def fixed(self, value: bool) -> None: ...
    @property
    def footprint(self) -> npt.NDArray[np.float64]:
        """The outline in the object's own frame: shape (V, 2)."""
    @property
    def world_footprint(self) -> npt.NDArray[np.float64]:
        """The outline placed at the object's pose: shape (V, 2)."""

class Scene:
    """A scene (hrspace-scene/1): room, door, wheelchair, furniture, preferences, activity graph."""

    def __init__(self, source: Union[str, os.PathLike[str]]) -> None:
        """Reads a scene from a file path or from JSON text (a str starting with '{');
        ValueError with the command line's message when it breaks a rule of the format."""
    @staticmethod
    def load(path: str) -> Scene:
        """Reads and validates a scene file."""
    @staticmethod
    def from_json(text: str, label: str = "<string>") -> Scene:
        """Parses and validates scene JSON text; `label` names it in error messages."""
    def to_json(self) -> str:
        """The scene as hrspace-scene/1 JSON text."""
    def validate(self) -> None:
        """Checks the scene as it is now (after edits); ValueError with the reader's message."""
    def copy(self) -> Scene:
        """An independent copy."""
    def __copy__(self) -> Scene: ...
    def __deepcopy__(self, memo: Dict[int, Any]) -> Scene: ...
    def __eq__(self, other: object) -> bool: ...
    @property
    def name(self) -> str:
        """The scene's name; settable."""
    @name.setter
    def name(self, value: str) -> None: ...
    @property
    def label(self) -> str:
        """Where the scene came from (its path or '<string>')."""
    @property
    def objects(self) -> List[Object]:
        """The objects in file order, as views."""
    def object(self, id: str) -> Object:
        """The object with this id; KeyError when there is none."""
    @property
    def object_ids(self) -> List[str]:
        """The objects' ids in file order."""
    @property
    def poses(self) -> npt.NDArray[np.float64]:
        """Every object's (x, y, theta): shape (N, 3); settable."""
    @poses.setter
    def poses(self, value: PoseArray) -> None: ...
    @property
    def room(self) -> npt.NDArray[np.float64]:
        """The room's inner wall outline: shape (V, 2)."""
    @property
    def door(self) -> Dict[str, Any]:
        """center, width, clear_depth, clear_zone (shape (4, 2))."""
    @property
    def start_pose(self) -> Tuple[float, float, float]:
        """The wheelchair's start pose at the door."""
    @property
    def wheelchair(self) -> Dict[str, float]:
        """length, width, turning_radius (metres)."""
    @property
    def weights(self) -> Dict[str, Tuple[float, ...]]:
        """{'path': (length, rotation, clearance), 'interior': (distance, angle)}; settable."""
    @weights.setter
    def weights(self, value: Dict[str, Sequence[float]]) -> None: ...
    @property
    def activity(self) -> Dict[str, Any]:
        """transitions {from: {to: probability}}, sequences (M), visits."""

class CSpace:
    """The wheelchair's exact, conservative configuration space in a scene's layout."""

    def __init__(self, scene: Scene, slices: int = 72) -> None:
        """Builds the C-space of the scene's room, chair and object poses."""
    @overload
    def is_free(self, poses: Pose) -> bool: ...
    @overload
    def is_free(self, poses: PoseArray) -> npt.NDArray[np.bool_]:
        """Shape (N, 3) -> bool array (N,): True only when the chair is certainly free."""
    @overload
    def clearance(self, poses: Pose) -> npt.NDArray[np.float64]: ...
    @overload
    def clearance(self, poses: PoseArray) -> npt.NDArray[np.float64]:
        """Shape (N, 3) -> (N, 2): distance to the nearest outline left and right."""
    def move_object(self, object: Union[str, int], pose: Pose) -> None:
        """Moves one object (by id or index); the Scene is not changed."""
    def object_pose(self, object: Union[str, int]) -> Tuple[float, float, float]:
        """The pose of one object (by id or index)."""
    @property
    def slices(self) -> int:
        """Number of orientation slices."""
    @property
    def piece_count(self) -> int:
        """Convex C-obstacle pieces over all slices."""

class Design:
    """The result of design(): the best layout, its tours and the report."""

    @property
    def layout(self) -> Scene:
        """The best layout (layout.json); a new copy at each access."""
    @property
    def tours(self) -> List[Dict[str, Any]]:
        """The tours of the best layout (tours.json's `tours`)."""
    @property
    def report(self) -> Dict[str, Any]:
        """report.json as a dict."""
    @property
    def stopped(self) -> bool:
        """True when the run was interrupted."""
    @property
    def valid(self) -> bool:
        """True when the best layout passed every exact check."""
    @property
    def cost(self) -> float:
        """Total cost of the best layout."""
    @property
    def initial_cost(self) -> float:
        """Total cost of the input layout."""
    @property
    def svg(self) -> str:
        """design.svg's text."""
    @property
    def accessibility(self) -> Dict[str, Any]:
        """accessibility.json as a dict: route widths, clear floor spaces, turning space, door."""
    @property
    def html(self) -> str:
        """design.html's text: the interactive page (layout, tours with the chair animated,
        annealing trace, accessibility overlays), self-contained."""
    def _repr_html_(self) -> str:
        """The interactive page (design.html) in an iframe, for notebooks."""
    def save(self, dir: Union[str, os.PathLike[str]]) -> None:
        """Writes accessibility.json, design.html, layout.json, tours.json, design.svg,
        report.json and manifest.json into `dir`, byte for byte what `hrspace design --out
        dir` writes for the same run."""

def plan(
    scene: Scene,
    start: Pose,
    goal: Pose,
    *,
    seed: int = 1,
    planner: str = "baseline",
    reuse: Optional[str] = None,
    iterations: int = 3000,
    step: float = 0.25,
) -> Dict[str, Any]:
    """One wheelchair leg, as `hrspace plan`: its JSON object as a dict."""

def tour(
    scene: Scene,
    sequence: Union[str, Sequence[str]],
    *,
    seed: int = 1,
    planner: str = "baseline",
    reuse: Optional[str] = None,
) -> Dict[str, Any]:
    """One tour of an object sequence from the door, as `hrspace tour`: its JSON object."""

def design(
    scene: Scene,
    *,
    seed: int = 1,
    iterations: int = 700,
    planner: str = "default",
    reuse: Optional[str] = None,
    disable: Optional[str] = None,
    threads: int = 0,
    rules: str = "ada",
    progress: Optional[Callable[[Dict[str, Any]], None]] = None,
    access_goal: int = 1,
    weights: Optional[Union[str, Sequence[float]]] = None,
    designs: int = 1,
    restarts: int = 2,
) -> Union[Design, List[Design]]:
    """Optimizes the layout as `hrspace design` (the cheapest of `restarts` annealing
    chains); Ctrl-C raises KeyboardInterrupt whose `design` attribute holds the best
    design so far."""
