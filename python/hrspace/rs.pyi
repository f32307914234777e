"""Reeds-Shepp curves: shortest paths and sampling (type stubs)."""

from typing import Iterable, Sequence, Tuple

import numpy as np
import numpy.typing as npt

Pose = Sequence[float]
"""(x, y, theta): metres and radians."""

Segment = Tuple[str, int, float]
"""(steer 'L'|'S'|'R', gear 1|-1, length in metres)."""

class Path:
    """A Reeds-Shepp path: segments driven in order from `start` with turning radius `radius`."""

    def __init__(self, start: Pose, segments: Iterable[Segment], radius: float) -> None:
        """A path from `start` of `segments` with turning radius `radius`."""
    @property
    def start(self) -> Tuple[float, float, float]:
        """Start pose (x, y, theta)."""
    @property
    def end(self) -> Tuple[float, float, float]:
        """Pose (x, y, theta) reached at the end."""
    @property
    def radius(self) -> float:
        """Turning radius, metres."""
    @property
    def length(self) -> float:
        """Total length, metres (hrspace rs's `length`)."""
    @property
    def word(self) -> str:
        """Steering letter and gear sign per segment, e.g. 'L+S+R-'."""
    @property
    def segments(self) -> list[Segment]:
        """[(steer, gear, length), ...]."""
    @property
    def signed_lengths(self) -> list[float]:
        """Segment lengths signed by gear (hrspace rs's `segments` column)."""

def shortest(a: Pose, b: Pose, radius: float) -> Path:
    """The exact shortest Reeds-Shepp path from pose a to pose b with turning radius `radius`
    (metres, 0.001 to 2000)."""

def sample(path: Path, step: float) -> npt.NDArray[np.float64]:
    """Poses along `path`, at most `step` metres apart, both ends included: shape (N, 3)."""
