"""Reeds-Shepp curves: the exact shortest path between two poses of a car
that drives forwards and backwards with a minimum turning radius
(``hrspace rs`` on the command line).

>>> from hrspace import rs
>>> path = rs.shortest((0, 0, 0), (1, 1, 1.57), 0.7)
>>> path.length, path.word, path.segments
>>> poses = rs.sample(path, 0.05)        # array of shape (N, 3)
"""

from ._core.rs import Path, sample, shortest

__all__ = ["Path", "sample", "shortest"]
