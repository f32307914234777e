"""hrspace.rs: shortest paths equal `hrspace rs`; sampling."""

import math

import numpy as np
import pytest

from hrspace import rs
from conftest import cli_error, run_cli


def test_shortest_equals_hrspace_rs(tmp_path):
    rng = np.random.default_rng(11)
    pairs = np.hstack([rng.uniform(-3, 3, (300, 2)), rng.uniform(-4, 4, (300, 1)),
                       rng.uniform(-3, 3, (300, 2)), rng.uniform(-4, 4, (300, 1))])
    pairs[0, 3:] = pairs[0, :3]  # identical poses: an empty path
    radius = 0.7
    csv = tmp_path / "pairs.csv"
    csv.write_text("".join(",".join(repr(v) for v in row) + "\n" for row in pairs.tolist()))
    status, out, err = run_cli("rs", "--radius", radius, "--pairs", csv)
    assert status == 0, err
    lines = out.strip("\n").split("\n")[1:]
    assert len(lines) == len(pairs)
    for row, line in zip(pairs.tolist(), lines):
        length, word, segments = line.split(",")
        path = rs.shortest(row[:3], row[3:], radius)
        assert path.length == float(length)
        assert path.word == word
        assert path.signed_lengths == [float(v) for v in segments.split()]
        assert all(s in "LSR" and g in (1, -1) and n >= 0 for s, g, n in path.segments)
    assert rs.shortest(pairs[0, :3], pairs[0, 3:], radius).segments == []


def test_sample_runs_from_start_to_end():
    path = rs.shortest((0.0, 0.0, 0.0), (1.0, 1.5, 2.0), 0.5)
    poses = rs.sample(path, 0.05)
    assert poses.shape[1] == 3 and len(poses) >= path.length / 0.05
    assert np.allclose(poses[0], path.start)
    assert np.allclose(poses[-1], path.end, atol=1e-9)
    assert np.allclose(path.end, (1.0, 1.5, 2.0), atol=1e-9)
    steps = np.hypot(*np.diff(poses[:, :2], axis=0).T)
    assert steps.max() <= 0.05 + 1e-12


def test_path_from_segments():
    path = rs.Path((0, 0, 0), [("S", 1, 1.0), ("L", -1, math.pi / 2)], 1.0)
    assert path.word == "S+L-" and path.length == pytest.approx(1 + math.pi / 2)


def test_bad_radius_gives_the_commands_message():
    with pytest.raises(ValueError) as e:
        rs.shortest((0, 0, 0), (1, 1, 1), 0)
    assert str(e.value) == cli_error("rs", "--radius", "0")
    with pytest.raises(ValueError):
        rs.sample(rs.shortest((0, 0, 0), (1, 1, 1), 1.0), 0.0)
