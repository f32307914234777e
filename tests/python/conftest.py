"""Shared fixtures of the Python suite (run by ctest: tests/python/CMakeLists.txt).

The module under test is the built one (PYTHONPATH=build/python); the
command it is compared with is HRSPACE_BIN (default build/cli/hrspace).
"""

import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("HRSPACE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
HRSPACE_BIN = os.environ.get("HRSPACE_BIN", str(SOURCE_DIR / "build" / "cli" / "hrspace"))
BEDROOM = SOURCE_DIR / "scenes" / "bedroom.json"


def run_cli(*args, stdin=None):
    """Runs the hrspace command; returns (exit status, stdout, stderr)."""
    proc = subprocess.run([HRSPACE_BIN, *map(str, args)], input=stdin, capture_output=True, text=True, timeout=600)
    return proc.returncode, proc.stdout, proc.stderr


def cli_error(command, *args):
    """The one-line message of a command that must fail with exit status 2,
    without its 'hrspace COMMAND: ' prefix."""
    status, _, err = run_cli(command, *args)
    assert status == 2, f"hrspace {command} exited {status}: {err}"
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    prefix = f"hrspace {command}: "
    assert lines[0].startswith(prefix), lines[0]
    return lines[0][len(prefix):]


def drop_timings(value):
    """A JSON value without its wall-clock fields (they differ between any
    two runs): keys named time*, *_ms, *_s; and without the work counter
    reachability_fills, which with several threads varies like a timing
    (docs/scene-format.md, report.json refused_legs)."""
    if isinstance(value, dict):
        return {k: drop_timings(v) for k, v in value.items()
                if not (k.startswith("time") or k.endswith("_ms") or k.endswith("_s")
                        or k == "reachability_fills")}
    if isinstance(value, list):
        return [drop_timings(v) for v in value]
    return value


@pytest.fixture(scope="session")
def bedroom_path():
    return BEDROOM
