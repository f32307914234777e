"""hrspace.design: the same files as `hrspace design` for the same inputs and
seed (layout.json, tours.json and design.svg byte for byte, report.json but
for its wall-clock times); progress; errors."""

import html
import json

import pytest

import hrspace
from conftest import BEDROOM, SOURCE_DIR, cli_error, drop_timings, run_cli

SMALL_BEDROOM = SOURCE_DIR / "scenes" / "small_bedroom.json"
FILES = ["layout.json", "tours.json", "design.svg", "report.json", "manifest.json",
         "accessibility.json", "design.html"]


def compare_with_command(tmp_path, scene_path, seed, iterations, planner, threads):
    scene = hrspace.Scene(scene_path)
    steps = []
    result = hrspace.design(scene, seed=seed, iterations=iterations, planner=planner,
                            threads=threads, progress=steps.append)
    result.save(tmp_path / "py")
    status, out, err = run_cli("design", scene_path, "--out", tmp_path / "cli", "--seed", seed,
                               "--iterations", iterations, "--planner", planner, "--threads", threads)
    assert status == 0, err
    for name in FILES[:3] + ["accessibility.json", "design.html"]:
        ours, theirs = (tmp_path / "py" / name).read_bytes(), (tmp_path / "cli" / name).read_bytes()
        assert ours == theirs, name
    ours = json.loads((tmp_path / "py" / "report.json").read_text())
    theirs = json.loads((tmp_path / "cli" / "report.json").read_text())
    assert drop_timings(ours) == drop_timings(theirs)
    assert sorted(p.name for p in (tmp_path / "py").iterdir()) == sorted(FILES)
    # The objects equal the files.
    assert result.layout == hrspace.Scene(tmp_path / "cli" / "layout.json")
    assert result.tours == json.loads((tmp_path / "cli" / "tours.json").read_text())["tours"]
    assert drop_timings(result.report) == drop_timings(theirs)
    assert result.svg.encode() == (tmp_path / "cli" / "design.svg").read_bytes()
    page = (tmp_path / "cli" / "design.html").read_text(encoding="utf-8")
    assert result.html == page
    # A notebook's view: the page whole, escaped into a sandboxed iframe.
    frame = result._repr_html_()
    assert frame.startswith("<iframe sandbox=\"allow-scripts\"")
    assert html.unescape(frame.split('srcdoc="', 1)[1].rsplit('"></iframe>', 1)[0]) == page
    assert [s["iteration"] for s in steps] == list(range(1, iterations + 1))
    # The last step's best is the annealer's; the arrangement and the polish
    # may change the layout after it. progress hears chain 0 (of the default
    # two restarts): the steps are the kept design's when chain 0 is kept.
    restarts = result.report.get("restarts")
    assert restarts is not None and restarts["chains"] == 2
    assert restarts["tried"][0]["seed"] == seed
    assert result.cost == min(c["cost"] for c in restarts["tried"])
    post = result.report["arrange"]["rounds_kept"] + result.report["polish"]["kept"] + \
        result.report["polish"]["squared"]
    if restarts["kept_seed"] != seed:
        post = -1  # another chain's design: its annealer's steps were not heard
    if post == 0:
        assert steps[-1]["best"] == pytest.approx(result.cost)
    if post >= 0 and result.report["arrange"]["rounds_kept"] > 0 \
            and result.report["polish"]["kept"] == 0 and result.report["polish"]["squared"] == 0:
        assert result.cost < steps[-1]["best"]
    assert not result.stopped
    return result


def test_proposed_design_equals_the_command(tmp_path):
    compare_with_command(tmp_path, BEDROOM, seed=2, iterations=40, planner="proposed", threads=2)


@pytest.mark.parametrize("planner", ["literal", "paper", "baseline,-escape", "default,-trees"])
def test_every_preset_equals_the_command(tmp_path, planner):
    result = compare_with_command(tmp_path, BEDROOM, seed=3, iterations=6, planner=planner,
                                  threads=2)
    assert result.report["planner"] == planner


def test_docstring_and_help_list_the_same_presets_and_switches():
    status, out, _ = run_cli("design", "--help")
    assert status == 0
    def listed(text):
        return {line.split()[0] for line in text.splitlines() if line.startswith("    ")
                and len(line) > 4 and line[4] != " "}
    names = listed(out)
    assert {"default", "baseline", "paper", "literal", "goalskip", "escape", "trees"} <= names
    assert names == listed(hrspace.design.__doc__)


def test_baseline_design_equals_the_command(tmp_path):
    compare_with_command(tmp_path, SOURCE_DIR / "scenes" / "small_bedroom.json", seed=1,
                         iterations=4, planner="baseline", threads=1)


def test_an_exception_in_progress_stops_the_design_and_carries_it():
    def progress(step):
        if step["iteration"] == 3:
            raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough") as e:
        hrspace.design(hrspace.Scene(BEDROOM), iterations=500, planner="proposed", progress=progress,
                       restarts=1)
    best = e.value.design
    assert best.stopped and len(best.report["trace"]) == 3
    best.layout.validate()
    # With restarts, the stop stops every chain; the cheapest is kept, stopped too.
    with pytest.raises(RuntimeError, match="enough") as e:
        hrspace.design(hrspace.Scene(BEDROOM), iterations=500, planner="proposed", progress=progress,
                       restarts=2)
    best = e.value.design
    record = best.report["restarts"]
    assert best.stopped and len(best.report["trace"]) < 500
    assert best.cost == min(c["cost"] for c in record["tried"])
    best.layout.validate()


def test_scene_without_sequences_gives_the_commands_message(tmp_path):
    data = json.loads(BEDROOM.read_text())
    # Every object row only stays put: no walk of `visits` moves from the door.
    rows = data["activity"]["transitions"]
    for name in rows:
        if name != "door":
            rows[name] = {name: 1.0}
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(data))
    with pytest.raises(ValueError) as e:
        hrspace.design(hrspace.Scene(path), iterations=1)
    assert str(e.value) == cli_error("design", path, "--out", tmp_path / "out")


def test_save_into_an_unwritable_place_is_an_error(tmp_path):
    result = hrspace.design(hrspace.Scene(BEDROOM), iterations=0, planner="proposed")
    blocker = tmp_path / "file"
    blocker.write_text("x")
    with pytest.raises(ValueError) as e:
        result.save(blocker / "out")
    assert str(e.value) == cli_error("design", BEDROOM, "--out", blocker / "out")


def access_failures(a):
    """The failed checks of an accessibility.json, counted here from its fields."""
    return ((a["tours"]["total"] - a["tours"]["found"])
            + sum(not r["pass"] for r in a["routes"])
            + sum(not s["clear_floor_space"] for s in a["stops"])
            + (not a["turning_space"]["pass"]) + (not a["door"]["pass"]))


def test_access_goal_keeps_the_first_design_that_passes_or_the_fewest_failures(tmp_path):
    scene = hrspace.Scene(BEDROOM)
    goal = hrspace.design(scene, seed=1, iterations=50, threads=1, access_goal=4)
    record = goal.report["access_goal"]
    tried = record["tried"]
    assert 1 <= record["tries"] == len(tried) <= 4
    assert [t["seed"] for t in tried] == list(range(1, len(tried) + 1))
    # Each try is the plain design of its seed: its accessibility, counted independently.
    plain = {}
    for t in tried:
        d = hrspace.design(scene, seed=t["seed"], iterations=50, threads=1)
        plain[t["seed"]] = d
        assert t["pass"] == d.accessibility["pass"]
        assert t["failures"] == access_failures(d.accessibility)
        assert t["cost"] == pytest.approx(d.cost, rel=1e-12)
    # Tries stop at the first pass; the kept one has the fewest failures, then the lower cost.
    assert all(not t["pass"] for t in tried[:-1])
    kept = min(tried, key=lambda t: (t["failures"], t["cost"]))
    assert record["kept_seed"] == kept["seed"] == goal.report["seed"]
    assert record["pass"] == kept["pass"] == goal.accessibility["pass"]
    assert goal.layout == plain[kept["seed"]].layout
    # The command keeps the same design, byte for byte.
    goal.save(tmp_path / "py")
    status, _, err = run_cli("design", BEDROOM, "--out", tmp_path / "cli", "--seed", 1,
                             "--iterations", 50, "--threads", 1, "--access-goal", 4)
    assert status == 0, err
    for name in ["layout.json", "tours.json", "design.svg", "accessibility.json", "design.html"]:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    cli_report = json.loads((tmp_path / "cli" / "report.json").read_text())
    assert cli_report["access_goal"] == record


def test_restarts_keep_the_cheapest_chain_and_its_seed_repeats_it_alone():
    scene = hrspace.Scene(SMALL_BEDROOM)
    best = hrspace.design(scene, seed=1, iterations=20, restarts=3)
    record = best.report["restarts"]
    assert record["chains"] == 3 and best.report["seed"] == 1
    costs = [c["cost"] for c in record["tried"]]
    assert record["tried"][0]["seed"] == 1
    assert best.cost == min(costs)
    # Each chain alone (restarts=1 at its seed) has the cost the record gives it.
    for c in record["tried"]:
        alone = hrspace.design(scene, seed=c["seed"], iterations=20, restarts=1, threads=1)
        assert "restarts" not in alone.report
        assert alone.cost == c["cost"]
        if c["seed"] == record["kept_seed"]:
            assert alone.layout == best.layout


def test_access_goal_out_of_range_is_refused():
    with pytest.raises(ValueError, match="access-goal"):
        hrspace.design(hrspace.Scene(BEDROOM), iterations=1, access_goal=0)
    assert "--access-goal" in cli_error("design", BEDROOM, "--out", "/tmp/unused", "--access-goal", "0")


@pytest.mark.parametrize("kwargs, options", [
    ({"seed": -1}, ["--seed", "-1"]),
    ({"iterations": -5}, ["--iterations", "-5"]),
    ({"designs": 0}, ["--designs", "0"]),
    ({"threads": 5000}, ["--threads", "5000"]),
    ({"rules": "din"}, ["--rules", "din"]),
    ({"access_goal": 101}, ["--access-goal", "101"]),
    ({"restarts": 0}, ["--restarts", "0"]),
    ({"weights": "1,2"}, ["--weights", "1,2"]),
    ({"weights": "1,x,1"}, ["--weights", "1,x,1"]),
    ({"weights": [1, -1, 1]}, ["--weights", "1,-1,1"]),
    ({"planner": "fast"}, ["--planner", "fast"]),
    ({"planner": "baseline", "disable": "frobnicate"}, ["--planner", "baseline", "--disable", "frobnicate"]),
])
def test_the_command_and_python_refuse_a_request_with_the_same_message(tmp_path, kwargs, options):
    with pytest.raises(ValueError) as e:
        hrspace.design(hrspace.Scene(BEDROOM), **kwargs)
    assert str(e.value) == cli_error("design", BEDROOM, "--out", tmp_path / "d", *options)


def test_weights_and_designs_equal_the_command(tmp_path):
    scene = hrspace.Scene(BEDROOM)
    results = hrspace.design(scene, seed=5, iterations=8, threads=1, weights=[2, 0.5, 1, 1, 3],
                             designs=2)
    assert isinstance(results, list) and len(results) == 2
    assert [r.report["seed"] for r in results] == [5, 6]
    status, _, err = run_cli("design", BEDROOM, "--out", tmp_path / "cli", "--seed", 5,
                             "--iterations", 8, "--threads", 1, "--weights", "2,0.5,1,1,3",
                             "--designs", 2)
    assert status == 0, err
    for k, r in enumerate(results, start=1):
        r.save(tmp_path / "py" / str(k))
        for name in ["layout.json", "tours.json", "design.svg", "accessibility.json", "design.html"]:
            ours = (tmp_path / "py" / str(k) / name).read_bytes()
            assert ours == (tmp_path / "cli" / str(k) / name).read_bytes(), (k, name)
    # The weights reached the objective: the same run with the scene's own weights differs.
    plain = hrspace.design(scene, seed=5, iterations=8, threads=1)
    assert plain.initial_cost != pytest.approx(results[0].initial_cost)
