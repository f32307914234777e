"""hrspace from Python: scenes, collision checks, Reeds-Shepp paths, legs,
tours and whole layout designs, computed by the same C++ code as the
``hrspace`` command (docs/python.md).

>>> import hrspace
>>> scene = hrspace.Scene("scenes/bedroom.json")
>>> result = hrspace.design(scene, seed=1, iterations=50)
>>> result.save("out/bedroom")          # layout.json, tours.json, design.svg, report.json

Bad input raises ``ValueError`` with the command line's one-line message.
"""

from . import rs
from ._core import CSpace, Design, Object, Scene, design, plan, tour
from ._core import __commit__, __version__

__all__ = ["CSpace", "Design", "Object", "Scene", "design", "plan", "rs", "tour"]
