"""hrspace.plan and hrspace.tour: the same objects as `hrspace plan` and
`hrspace tour` for the same inputs and seed; the same error messages."""

import json

import pytest

import hrspace
from conftest import BEDROOM, cli_error, drop_timings, run_cli

START, GOAL = (0.9, 1.2, 0.0), (2.0, 1.2, 0.0)


def pose_text(p):
    return ",".join(repr(float(v)) for v in p)


@pytest.mark.parametrize("planner,seed", [("baseline", 1), ("baseline", 5), ("proposed", 2)])
def test_plan_equals_the_command(planner, seed):
    scene = hrspace.Scene(BEDROOM)
    ours = hrspace.plan(scene, START, GOAL, seed=seed, planner=planner)
    status, out, err = run_cli("plan", BEDROOM, "--from", pose_text(START), "--to", pose_text(GOAL),
                               "--seed", seed, "--planner", planner)
    assert status == 0, err
    theirs = json.loads(out)
    assert ours["found"] and set(ours) == set(theirs)
    assert drop_timings(ours) == drop_timings(theirs)


def test_plan_options():
    scene = hrspace.Scene(BEDROOM)
    few = hrspace.plan(scene, START, (4.0, 2.4, -1.7), seed=3, iterations=1)
    assert few["iterations"] <= 1
    status, out, _ = run_cli("plan", BEDROOM, "--from", pose_text(START), "--to", "4.0,2.4,-1.7",
                             "--seed", 3, "--iterations", 1)
    assert drop_timings(json.loads(out)) == drop_timings(few)


@pytest.mark.parametrize("planner", ["baseline", "proposed"])
def test_tour_equals_the_command(planner):
    scene = hrspace.Scene(BEDROOM)
    ours = hrspace.tour(scene, ["door", "tv", "bed"], seed=4, planner=planner)
    assert hrspace.tour(scene, "door,tv,bed", seed=4, planner=planner)["legs"] == ours["legs"]
    status, out, err = run_cli("tour", BEDROOM, "--sequence", "door,tv,bed", "--seed", 4,
                               "--planner", planner)
    assert status == 0, err
    assert drop_timings(ours) == drop_timings(json.loads(out))


def test_plan_in_an_edited_layout_uses_the_new_poses(tmp_path):
    scene = hrspace.Scene(BEDROOM)
    scene.object("tv").pose = (2.6, 0.25, 1.5707963267948966)
    path = tmp_path / "edited.json"
    path.write_text(scene.to_json())
    ours = hrspace.tour(scene, "door,tv", seed=2)
    status, out, _ = run_cli("tour", path, "--sequence", "door,tv", "--seed", 2)
    assert drop_timings(ours) == drop_timings(json.loads(out))


ERRORS = [
    # (Python call, command arguments)
    (lambda s: hrspace.plan(s, (0.0, 0.0, 0.0), GOAL),
     ["plan", BEDROOM, "--from", "0,0,0", "--to", pose_text(GOAL)]),
    (lambda s: hrspace.plan(s, START, (2.6, 2.99, 0.0)),
     ["plan", BEDROOM, "--from", pose_text(START), "--to", "2.6,2.99,0"]),
    (lambda s: hrspace.plan(s, START, GOAL, planner="fast"),
     ["plan", BEDROOM, "--from", pose_text(START), "--to", pose_text(GOAL), "--planner", "fast"]),
    (lambda s: hrspace.plan(s, START, GOAL, reuse="samples"),
     ["plan", BEDROOM, "--from", pose_text(START), "--to", pose_text(GOAL), "--reuse", "samples"]),
    (lambda s: hrspace.plan(s, START, GOAL, planner="proposed", reuse="paths"),
     ["plan", BEDROOM, "--from", pose_text(START), "--to", pose_text(GOAL), "--planner", "proposed",
      "--reuse", "paths"]),
    (lambda s: hrspace.plan(s, START, GOAL, iterations=0),
     ["plan", BEDROOM, "--from", pose_text(START), "--to", pose_text(GOAL), "--iterations", "0"]),
    (lambda s: hrspace.tour(s, "door,piano"), ["tour", BEDROOM, "--sequence", "door,piano"]),
    (lambda s: hrspace.tour(s, "door,,tv"), ["tour", BEDROOM, "--sequence", "door,,tv"]),
    (lambda s: hrspace.tour(s, "door,tv", planner="proposed", reuse="trees"),
     ["tour", BEDROOM, "--sequence", "door,tv", "--planner", "proposed", "--reuse", "trees"]),
    (lambda s: hrspace.design(s, planner="slow"),
     ["design", BEDROOM, "--out", "{tmp}", "--planner", "slow"]),
    (lambda s: hrspace.design(s, iterations=-1),
     ["design", BEDROOM, "--out", "{tmp}", "--iterations", "-1"]),
]


@pytest.mark.parametrize("index", range(len(ERRORS)))
def test_errors_are_value_errors_with_the_commands_message(tmp_path, index):
    call, args = ERRORS[index]
    with pytest.raises(ValueError) as e:
        call(hrspace.Scene(BEDROOM))
    args = [str(a).replace("{tmp}", str(tmp_path / "out")) for a in args]
    assert str(e.value) == cli_error(*args)
