"""hrspace.CSpace: vectorized is_free and clearance equal `hrspace collide`."""

import numpy as np
import pytest

import hrspace
from conftest import BEDROOM, run_cli


def random_poses(scene, n, seed):
    rng = np.random.default_rng(seed)
    lo, hi = scene.room.min(axis=0) - 0.3, scene.room.max(axis=0) + 0.3
    xy = rng.uniform(lo, hi, size=(n, 2))
    theta = rng.uniform(-np.pi, np.pi, size=(n, 1))
    return np.hstack([xy, theta])


@pytest.mark.parametrize("scene_name", ["bedroom", "office"])
def test_ten_thousand_poses_equal_hrspace_collide(tmp_path, scene_name):
    path = BEDROOM.parent / f"{scene_name}.json"
    scene = hrspace.Scene(path)
    poses = random_poses(scene, 10_000, 7)
    csv = tmp_path / "poses.csv"
    # repr() is the shortest text that reads back exactly, as the command expects.
    csv.write_text("x,y,theta\n" + "".join(f"{x!r},{y!r},{t!r}\n" for x, y, t in poses.tolist()))
    status, out, err = run_cli("collide", path, "--poses", csv)
    assert status == 0, err
    rows = [line.split(",") for line in out.strip().splitlines()[1:]]
    assert len(rows) == len(poses)
    cli = np.array([[float(v) for v in r] for r in rows])
    assert np.array_equal(cli[:, :3], poses)

    cspace = hrspace.CSpace(scene)
    free = cspace.is_free(poses)
    clearance = cspace.clearance(poses)
    assert free.dtype == np.bool_ and free.shape == (10_000,)
    assert clearance.shape == (10_000, 2)
    assert np.array_equal(free, cli[:, 3] == 1)
    assert np.array_equal(clearance, cli[:, 4:6])  # bit for bit
    assert 0 < free.sum() < len(free)


def test_single_pose_and_lists():
    cspace = hrspace.CSpace(hrspace.Scene(BEDROOM))
    pose = [0.9, 1.2, 0.0]
    assert cspace.is_free(pose) is True
    assert cspace.is_free([pose, [0.0, 0.0, 0.0]]).tolist() == [True, False]
    assert cspace.clearance(pose).shape == (2,)
    assert cspace.is_free(np.zeros((0, 3))).shape == (0,)


def test_move_object_matches_a_rebuilt_cspace():
    scene = hrspace.Scene(BEDROOM)
    cspace = hrspace.CSpace(scene)
    target = (2.0, 2.0, 0.3)
    cspace.move_object("bed", target)
    assert cspace.object_pose("bed") == target
    moved = scene.copy()
    moved.object("bed").pose = target
    poses = random_poses(scene, 2000, 3)
    rebuilt = hrspace.CSpace(moved)
    assert np.array_equal(cspace.is_free(poses), rebuilt.is_free(poses))
    assert np.array_equal(cspace.clearance(poses), rebuilt.clearance(poses))
    with pytest.raises(KeyError):
        cspace.move_object("piano", target)


def test_bad_pose_arrays_are_value_errors():
    cspace = hrspace.CSpace(hrspace.Scene(BEDROOM))
    with pytest.raises(ValueError):
        cspace.is_free(np.zeros((4, 2)))
    with pytest.raises(ValueError, match=r"poses\[1\]"):
        cspace.is_free([[0.0, 0.0, 0.0], [np.nan, 0.0, 0.0]])
    with pytest.raises(ValueError, match="outside"):
        cspace.clearance([[5000.0, 0.0, 0.0]])
    with pytest.raises(ValueError, match="--slices"):
        hrspace.CSpace(hrspace.Scene(BEDROOM), slices=2)
