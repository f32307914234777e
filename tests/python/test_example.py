"""examples/design_bedroom.py runs (a few iterations, no display)."""

import os
import subprocess
import sys

from conftest import SOURCE_DIR


def test_the_example_designs_and_plots(tmp_path):
    env = dict(os.environ, MPLBACKEND="Agg")
    proc = subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "design_bedroom.py"),
                           "--iterations", "15", "--out", str(tmp_path)],
                          env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    assert "cost" in proc.stdout
    for name in ["layout.json", "tours.json", "design.svg", "report.json", "design.png"]:
        assert (tmp_path / name).stat().st_size > 0, name
