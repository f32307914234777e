"""hrspace.Scene: loading, editing, validation and its messages."""

import copy
import json
import pathlib

import numpy as np
import pytest

import hrspace
from conftest import BEDROOM, cli_error, run_cli


def test_load_from_path_pathlike_and_json_text_agree():
    a = hrspace.Scene(str(BEDROOM))
    b = hrspace.Scene(pathlib.Path(BEDROOM))
    c = hrspace.Scene(BEDROOM.read_text())
    d = hrspace.Scene.from_json(a.to_json())
    assert a == b == c == d
    assert a.label == str(BEDROOM) and c.label == "<string>"
    assert a.name == "bedroom"


def test_objects_and_poses_are_readable():
    s = hrspace.Scene(BEDROOM)
    data = json.loads(BEDROOM.read_text())
    assert s.object_ids == [o["id"] for o in data["objects"]]
    assert s.poses.shape == (len(data["objects"]), 3)
    for obj, row in zip(s.objects, s.poses):
        assert obj.pose == tuple(row)
    assert s.room.shape[1] == 2 and s.wheelchair["turning_radius"] > 0
    assert len(s.start_pose) == 3
    assert s.object("bed").world_footprint.shape[1] == 2


def test_edits_change_the_scene_and_copies_are_independent():
    s = hrspace.Scene(BEDROOM)
    c = copy.deepcopy(s)
    s.object("bed").pose = (2.6, 2.9, -1.5707963267948966)
    assert s.object("bed").pose == (2.6, 2.9, -1.5707963267948966)
    assert c.object("bed").pose == tuple(hrspace.Scene(BEDROOM).poses[0])
    poses = s.poses
    poses[1, 0] += 0.05
    s.poses = poses
    assert np.array_equal(s.poses, poses)
    s.validate()
    # The edited scene's text is a valid scene file with the new poses.
    assert np.array_equal(hrspace.Scene.from_json(s.to_json()).poses, poses)
    with pytest.raises(KeyError):
        s.object("piano")


def test_an_edit_that_breaks_a_rule_gives_the_readers_message(tmp_path):
    path = tmp_path / "bedroom.json"
    path.write_text(BEDROOM.read_text())
    s = hrspace.Scene(path)
    s.object("bed").pose = (100.0, 100.0, 0.0)
    with pytest.raises(ValueError) as e:
        s.validate()
    path.write_text(s.to_json())
    assert str(e.value) == cli_error("validate", path)
    with pytest.raises(ValueError):
        hrspace.CSpace(s)


BROKEN = {
    "not json": "{ oops",
    "empty": "",
    "wrong format": '{"format": "x"}',
}


@pytest.mark.parametrize("name", sorted(BROKEN))
def test_broken_files_give_the_commands_message(tmp_path, name):
    path = tmp_path / "scene.json"
    path.write_text(BROKEN[name])
    with pytest.raises(ValueError) as e:
        hrspace.Scene(path)
    assert str(e.value) == cli_error("validate", path)


def test_field_errors_give_the_commands_message(tmp_path):
    data = json.loads(BEDROOM.read_text())
    data["wheelchair"]["width"] = -1
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(data))
    with pytest.raises(ValueError) as e:
        hrspace.Scene(path)
    assert str(e.value) == cli_error("validate", path)
    assert "/wheelchair/width" in str(e.value)


def test_missing_file_gives_the_commands_message(tmp_path):
    with pytest.raises(ValueError) as e:
        hrspace.Scene(tmp_path / "none.json")
    assert str(e.value) == cli_error("validate", tmp_path / "none.json")


def test_bad_pose_values_are_value_errors():
    s = hrspace.Scene(BEDROOM)
    with pytest.raises(ValueError):
        s.object("bed").pose = (float("nan"), 0.0, 0.0)
    with pytest.raises(ValueError):
        s.object("bed").pose = (1.0, 2.0)
    with pytest.raises(ValueError):
        s.poses = np.zeros((2, 3))


HOME_OFFICE = {
    "format": "hrspace-scene/1",
    "name": "home office",
    "room": {"size": [5, 4]},
    "door": {"center": [0, 2], "width": 0.9},
    "wheelchair": {"length": 1.1, "width": 0.65, "turning_radius": 0.7},
    "objects": [
        {"id": "desk", "size": [0.6, 1.2], "pose": [2.5, 0.3, -1.5708]},
        {"id": "sink", "size": [0.6, 0.5], "pose": [4.0, 0.3, 1.5707963267948966], "fixed": True},
    ],
    "activity": {"transitions": {"door": {"desk": 0.5, "sink": 0.5},
                                 "desk": {"sink": 1.0}, "sink": {"desk": 1.0}}},
}


def test_furniture_flush_with_a_wall_is_valid_and_past_it_is_not():
    # The typed heading -1.5708 moves a corner of the desk 2 µm past y = 0:
    # contact within the tolerance, as in `hrspace validate`.
    s = hrspace.Scene(json.dumps(HOME_OFFICE))
    assert s.object("desk").world_footprint[:, 1].min() < 0.0
    s.validate()
    s.object("desk").pose = (2.5, 0.29, -1.5708)
    with pytest.raises(ValueError, match=r'/objects/0/pose: the footprint of "desk" sticks out '
                                         r"0\.01 m past the wall from \(0,0\) to \(5,0\)"):
        s.validate()


def test_version_is_the_commands():
    assert hrspace.__version__.count(".") == 2
    assert all(part.isdigit() for part in hrspace.__version__.split("."))
    status, out, _ = run_cli("--version")  # "hrspace X.Y.Z (commit ...)"
    assert status == 0
    assert out.split()[:2] == ["hrspace", hrspace.__version__]


def test_special_files_and_nul_paths_are_value_errors():
    """Issue 33: reads are bounded; a device or a path with a NUL is refused."""
    with pytest.raises(ValueError, match="not a regular file"):
        hrspace.Scene("/dev/zero")
    with pytest.raises(ValueError, match="NUL character"):
        hrspace.Scene(str(BEDROOM) + "\0junk")


def test_weights_setter_refuses_unknown_keys_and_nan():
    s = hrspace.Scene(BEDROOM)
    before = s.weights
    with pytest.raises(ValueError, match="unknown key 'pathh'"):
        s.weights = {"pathh": (1, 1, 1)}
    with pytest.raises(ValueError, match=r"weights\['path'\]\[1\].*got NaN"):
        s.weights = {"path": (1, float("nan"), 1)}
    with pytest.raises(ValueError, match="expected 2 numbers"):
        s.weights = {"interior": (1,)}
    assert s.weights == before
    s.weights = {"path": (1, 2, 3)}
    assert s.weights["path"] == (1.0, 2.0, 3.0)
