"""breakshot.simulate, breakshot.Scenario and breakshot.ScenarioError
against the command line: same bytes, same messages."""

import copy
import json
import pathlib

import pytest

import breakshot

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "examples").glob("*/*.json"))


def good():
    return {
        "physics": {"model": "ideal"},
        "table": {"shape": "rectangle", "min": [-1.0, -0.5], "max": [1.0, 0.5]},
        "balls": [
            {"id": "white", "position": [-0.5, 0.0], "velocity": [1.0, 0.1]},
            {"id": "black", "position": [0.3, 0.0]},
        ],
        "until": {"time": 3.0},
        "samples": {"dt": 0.5},
    }


def test_examples_exist():
    assert len(EXAMPLES) >= 15, EXAMPLES


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_simulate_equals_cli_bytes(path, run_cli):
    r = run_cli("simulate", path)
    assert r.returncode == 0, r.stderr
    from_path = breakshot.simulate(path)
    assert from_path.to_json() == r.stdout
    # The same scenario as a str path, as JSON text, as a dict, parsed once.
    text = path.read_text()
    assert breakshot.simulate(str(path)).to_json() == r.stdout
    assert breakshot.simulate(text).to_json() == r.stdout
    assert breakshot.simulate(json.loads(text)).to_json() == r.stdout
    assert breakshot.simulate(breakshot.Scenario(path)).to_json() == r.stdout


def test_result_fields_are_plain_values():
    r = breakshot.simulate(good())
    assert r.complete is True
    assert isinstance(r.events, list) and isinstance(r.events[0], dict)
    assert r.events[0] == {"time": pytest.approx(1.471425), "type": "ball_cushion",
                           "balls": ["white"], "cushion": "right"}
    assert r.final["time"] == 3.0
    assert [b["id"] for b in r.final["balls"]] == ["white", "black"]
    assert len(r.samples) == 7  # 0, 0.5, ..., 3
    assert r.cue is None
    assert "complete=True" in repr(r)


def test_head_on_equal_masses_exchange_velocities():
    # Closed form: an elastic head-on collision of equal masses swaps the
    # velocities; the moving ball stops dead.
    s = {
        "physics": {"model": "ideal"},
        "table": {"shape": "rectangle", "min": [-1.0, -0.5], "max": [1.0, 0.5]},
        "balls": [
            {"id": "a", "position": [-0.5, 0.0], "velocity": [1.0, 0.0]},
            {"id": "b", "position": [0.0, 0.0]},
        ],
        "until": {"time": 0.6},
    }
    r = breakshot.simulate(s)
    hit = r.events[0]
    assert hit["type"] == "ball_ball"
    radius = 0.028575  # the pool ball, the ideal model's default
    assert hit["time"] == pytest.approx((0.5 - 2 * radius) / 1.0, rel=1e-12)
    a, b = r.final["balls"]
    assert a["velocity"] == pytest.approx([0.0, 0.0], abs=1e-12)
    assert b["velocity"] == pytest.approx([1.0, 0.0], rel=1e-12)


def test_limit_gives_incomplete_result():
    s = json.loads((ROOT / "examples" / "lab" / "two_balls.json").read_text())
    assert len(breakshot.simulate(s).events) > 3
    s["max_events"] = 3
    r = breakshot.simulate(s)
    assert r.complete is False
    assert len(r.events) == 3


def _cases():
    def edit(f):
        d = good()
        f(d)
        return d

    def setp(d, keys, value):
        for k in keys[:-1]:
            d = d[k]
        d[keys[-1]] = value

    return [
        ("overlap", edit(lambda d: setp(d, ["balls", 1, "position"], [-0.48, 0.0])), "balls[1].position"),
        ("wall", edit(lambda d: setp(d, ["balls", 0, "position"], [-0.99, 0.0])), "balls[0].position"),
        ("radius", edit(lambda d: setp(d, ["balls", 1, "radius"], -0.1)), "balls[1].radius"),
        ("mass", edit(lambda d: setp(d, ["balls", 0, "mass"], 0)), "balls[0].mass"),
        ("restitution", edit(lambda d: setp(d, ["balls", 1, "wall_restitution"], 1.2)),
         "balls[1].wall_restitution"),
        ("unknown", edit(lambda d: setp(d, ["balls", 1, "colour"], "black")), "balls[1].colour"),
        ("missing", edit(lambda d: d["physics"].pop("model")), "physics.model"),
        ("type", edit(lambda d: setp(d, ["balls", 1, "radius"], "big")), "balls[1].radius"),
        ("duplicate", edit(lambda d: setp(d, ["balls", 1, "id"], "white")), "balls[1].id"),
        ("polygon", edit(lambda d: setp(d, ["table"], {
            "shape": "polygon", "vertices": [[-1, -1], [1, 1], [1, -1], [-1, 2]]})),
         "table.vertices"),
        ("pool size", {"physics": {"model": "pool"}, "table": {"shape": "pool", "size": "10ft"},
                       "rack": {"game": "eight_ball"}}, "table.size"),
        ("cue theta", {"physics": {"model": "pool"}, "table": {"shape": "pool", "size": "9ft"},
                       "rack": {"game": "eight_ball"}, "cue": {"speed": 3.0, "theta": 90.0}},
         "cue.theta"),
    ]


@pytest.mark.parametrize("name,doc,path", _cases(), ids=[c[0] for c in _cases()])
def test_scenario_error_is_the_cli_message(name, doc, path, run_cli, tmp_path):
    f = tmp_path / "s.json"
    f.write_text(json.dumps(doc))
    r = run_cli("simulate", f)
    assert r.returncode == 2, r.stderr
    with pytest.raises(breakshot.ScenarioError) as info:
        breakshot.simulate(doc)
    e = info.value
    assert isinstance(e, ValueError)
    assert e.path == path
    assert e.reason
    assert not e.unsupported
    assert r.stderr == f"breakshot: {e}\n"
    # The same error when the scenario is parsed on its own.
    with pytest.raises(breakshot.ScenarioError) as again:
        breakshot.Scenario(doc)
    assert str(again.value) == str(e)


def test_not_json_text(run_cli, tmp_path):
    f = tmp_path / "bad.json"
    f.write_text('{"physics": NaN}')
    r = run_cli("simulate", f)
    with pytest.raises(breakshot.ScenarioError) as info:
        breakshot.simulate(f)
    assert r.stderr == f"breakshot: {info.value}\n"


def test_carom_table(run_cli, tmp_path):
    # The carom table with its default (carom) balls: the bytes of the command.
    d = good()
    d["table"] = {"shape": "carom"}
    d["balls"][0]["position"] = [0.5, 0.7]
    d["balls"][1]["position"] = [1.5, 0.7]
    f = tmp_path / "carom.json"
    f.write_text(json.dumps(d))
    r = run_cli("simulate", f)
    assert r.returncode == 0, r.stderr
    assert breakshot.simulate(d).to_json() == r.stdout
    # A ball off the carom table is an invalid scenario, as everywhere.
    d["balls"][0]["position"] = [-0.5, 0.0]
    with pytest.raises(breakshot.ScenarioError) as info:
        breakshot.simulate(d)
    assert not info.value.unsupported
    assert info.value.path == "balls[0].position"


def test_dict_that_is_not_json():
    d = good()
    d["balls"][0]["velocity"] = [float("nan"), 0.0]
    with pytest.raises(breakshot.ScenarioError, match="not JSON"):
        breakshot.simulate(d)


def test_wrong_argument_type_and_missing_file(tmp_path):
    with pytest.raises(TypeError, match="scenario"):
        breakshot.simulate(42)
    with pytest.raises(FileNotFoundError):
        breakshot.simulate(tmp_path / "no-such-file.json")


def test_scenario_object():
    s = breakshot.Scenario(ROOT / "examples" / "pool" / "break_8ball.json")
    assert s.model == "pool"
    assert s.ball_ids[0] == "cue" and len(s.ball_ids) == 16
    assert s.has_cue and s.until_rest
    assert "balls=16" in repr(s)
    c = copy.copy(s)
    assert breakshot.simulate(c) == breakshot.simulate(s)


def test_scenario_error_pickles():
    import pickle
    e = breakshot.ScenarioError("balls[0].mass", "must be positive")
    e2 = pickle.loads(pickle.dumps(e))
    assert (e2.path, e2.reason, str(e2)) == (e.path, e.reason, str(e))


def test_version_matches_the_library(run_cli):
    r = run_cli("--version", check=True)
    assert r.stdout.split()[1] == breakshot.__version__
    from importlib.metadata import version
    assert version("breakshot") == breakshot.__version__
