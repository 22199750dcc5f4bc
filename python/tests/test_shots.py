"""breakshot.shots: the same arrays for any thread count, each shot equal to a
simulate() run with that cue, reproducible noise, and clear refusals."""

import json
import pathlib

import numpy as np
import pytest

import breakshot

ROOT = pathlib.Path(__file__).resolve().parents[2]
POOL = ROOT / "examples" / "pool"
TWO_BALL_EXAMPLES = ["bank", "cut_with_throw", "draw_shot", "follow_shot", "stop_shot",
                     "stun_shot"]

RACK9 = {
    "physics": {"model": "pool", "ball_clusters": True},
    "table": {"shape": "pool", "size": "9ft"},
    "rack": {"game": "nine_ball", "seed": 1},
}
BREAK = [0.0, 0.0, 7.5, 0.0, 0.0]  # examples/pool/break_9ball.json's cue


def random_strikes(k, seed=5):
    rng = np.random.default_rng(seed)
    return np.column_stack([
        rng.uniform(-180, 180, k),  # phi
        np.where(rng.random(k) < 0.2, rng.uniform(0, 30, k), 0.0),  # theta
        rng.uniform(0.5, 6.0, k),  # speed
        rng.uniform(-0.3, 0.3, k),  # a
        rng.uniform(-0.3, 0.3, k),  # b
    ])


def with_cue(scenario: dict, strike) -> dict:
    phi, theta, speed, a, b = (float(x) for x in strike)
    return {**scenario, "cue": {"ball": "cue", "speed": speed, "phi": phi, "theta": theta,
                                "a": a, "b": b}}


ARRAYS = ["final_positions", "pocketed", "pockets", "cushions", "first_hit",
          "cushions_before_hit", "cue_index", "event_counts", "final_times", "complete",
          "miscue", "played"]


def assert_same(x, y):
    for name in ARRAYS:
        a, b = getattr(x, name), getattr(y, name)
        assert a.dtype == b.dtype and a.shape == b.shape, name
        assert np.array_equal(a, b), name


def test_same_arrays_for_one_and_two_threads():
    strikes = np.vstack([BREAK, random_strikes(40)])
    one = breakshot.shots(RACK9, strikes, threads=1)
    two = breakshot.shots(RACK9, strikes, threads=2)
    every = breakshot.shots(breakshot.Scenario(RACK9), strikes)
    assert_same(one, two)
    assert_same(one, every)
    assert one.final_positions.shape == (41, 10, 2)
    assert one.pocketed.shape == (41, 10) and one.pocketed.dtype == bool
    assert one.first_hit.shape == (41,)
    assert len(one) == 41


def test_each_shot_equals_simulate_with_that_cue():
    strikes = np.vstack([BREAK, random_strikes(8, seed=9)])
    got = breakshot.shots(RACK9, strikes, threads=2)
    assert got.ball_ids == breakshot.Scenario(RACK9).ball_ids
    cue = got.ball_ids.index("cue")
    assert (got.cue_index == cue).all()
    pocketed_any = False
    for j, strike in enumerate(strikes):
        r = breakshot.simulate(with_cue(RACK9, strike))
        if j == 0:
            assert r == breakshot.simulate(POOL / "break_9ball.json")
        final = r.final["balls"]
        assert np.array_equal(got.final_positions[j], np.array([b["position"] for b in final]))
        states = [b["state"] == "pocketed" for b in final]
        assert got.pocketed[j].tolist() == states
        pocketed_any |= any(states)
        assert got.event_counts[j] == len(r.events)
        assert got.final_times[j] == r.final["time"]
        assert got.complete[j] == r.complete
        hits = [e for e in r.events if e["type"] == "ball_ball" and "cue" in e["balls"]]
        first = -1
        if hits:
            a, b = hits[0]["balls"]
            first = got.ball_ids.index(b if a == "cue" else a)
        assert got.first_hit[j] == first
        for i, ball in enumerate(got.ball_ids):
            n = sum(e["type"] == "ball_cushion" and e["balls"] == [ball] for e in r.events)
            assert got.cushions[j, i] == n
            pockets = [e["pocket"] for e in r.events if e["type"] == "ball_pocket"
                       and e["balls"] == [ball]]
            expected = got.pocket_names.index(pockets[0]) if pockets else -1
            assert got.pockets[j, i] == expected
    assert pocketed_any
    assert got.first_hit[0] == got.ball_ids.index("1")  # the break hits the apex ball


def test_a_list_of_scenarios_one_strike_each_equals_the_examples():
    scenarios, strikes, expected = [], [], []
    for name in TWO_BALL_EXAMPLES:
        d = json.loads((POOL / f"{name}.json").read_text())
        c = d.pop("cue")
        scenarios.append(d)
        strikes.append([c["phi"], c["theta"], c["speed"], c["a"], c["b"]])
        expected.append(breakshot.simulate(POOL / f"{name}.json"))
    # Dicts and parsed scenarios mixed in one list.
    scenarios[1] = breakshot.Scenario(scenarios[1])
    got = breakshot.shots(scenarios, strikes, threads=2)
    for j, r in enumerate(expected):
        assert np.array_equal(got.final_positions[j],
                              np.array([b["position"] for b in r.final["balls"]]))
        assert got.event_counts[j] == len(r.events)
    assert np.array_equal(got.played, np.array(strikes))


def test_noise_is_reproducible_for_a_seed_and_differs_for_another():
    strikes = np.tile([10.0, 0.0, 3.0, 0.0, 0.0], (12, 1))
    a = breakshot.shots(RACK9, strikes, noise="tournament", seed=7, threads=1)
    b = breakshot.shots(RACK9, strikes, noise="tournament", seed=7, threads=2)
    c = breakshot.shots(RACK9, strikes, noise="tournament", seed=8)
    plain = breakshot.shots(RACK9, strikes)
    assert_same(a, b)
    assert not np.array_equal(a.played, c.played)
    assert not np.array_equal(a.final_positions, c.final_positions)
    # Every shot of the batch gets its own draw; none is the strike given.
    assert len({tuple(row) for row in a.played}) == 12
    assert (a.played != strikes).any(axis=1).all()
    # Tournament noise is small: 0.125 degrees on phi, 0.075 m/s on speed.
    assert np.abs(a.played[:, 0] - 10.0).max() < 1.0
    assert np.abs(a.played[:, 2] - 3.0).max() < 0.6
    assert np.array_equal(plain.played, strikes)
    assert breakshot.shots(RACK9, strikes, noise="none").played.tolist() == strikes.tolist()
    # A played strike is a strike: playing it without noise gives the same shot.
    again = breakshot.shots(RACK9, a.played[:3])
    assert np.array_equal(again.final_positions, a.final_positions[:3])


def test_refusals_name_the_row_the_column_or_the_argument():
    good = np.array([BREAK, [0.0, 0.0, 2.0, 0.0, 0.0]])
    bad = good.copy()
    bad[1, 1] = 90.0
    with pytest.raises(ValueError, match=r"^strikes\[1\]\.theta: the cue elevation must be in "
                                         r"\[0, 90\) degrees, not 90"):
        breakshot.shots(RACK9, bad)
    bad = good.copy()
    bad[0, 2] = np.nan
    with pytest.raises(ValueError, match=r"^strikes\[0\]\.speed: must be finite and positive"):
        breakshot.shots(RACK9, bad)
    bad = good.copy()
    bad[1, 3] = np.inf
    with pytest.raises(ValueError, match=r"^strikes\[1\]\.a: must be finite"):
        breakshot.shots(RACK9, bad)
    with pytest.raises(ValueError, match=r"^strikes: expected shape \(k, 5\)"):
        breakshot.shots(RACK9, good[:, :4])
    with pytest.raises(ValueError, match=r"^strikes: expected shape \(k, 5\), not \(5,\)"):
        breakshot.shots(RACK9, BREAK)
    with pytest.raises(ValueError, match=r"^strikes: not an array of numbers"):
        breakshot.shots(RACK9, [["a", 0, 1, 0, 0]])

    with pytest.raises(breakshot.ScenarioError) as e:
        breakshot.shots(POOL / "break_9ball.json", good)
    assert e.value.path == "cue" and "cue strike of its own" in e.value.reason
    no_cue = {"physics": {"model": "pool"}, "table": {"shape": "pool", "size": "9ft"},
              "balls": [{"id": "white", "position": [1.0, 0.6]}]}
    with pytest.raises(breakshot.ScenarioError) as e:
        breakshot.shots(no_cue, good)
    assert e.value.path == "balls" and "'cue'" in e.value.reason
    friction = {"physics": {"model": "friction"}, "table": {"shape": "rectangle",
                "min": [0, 0], "max": [1, 1]}, "balls": [{"id": "cue", "position": [0.5, 0.5]}]}
    with pytest.raises(breakshot.ScenarioError) as e:
        breakshot.shots(friction, good)
    assert e.value.path == "physics.model"
    with pytest.raises(breakshot.ScenarioError) as e:
        breakshot.shots([RACK9, {**RACK9, "rack": {"game": "snooker"}}], good)
    assert e.value.path == "scenarios[1].rack.game"
    with pytest.raises(breakshot.ScenarioError) as e:
        breakshot.shots([RACK9, no_cue], good)
    assert e.value.path == "scenarios[1].balls"
    with pytest.raises(ValueError, match=r"^scenario: 3 scenarios for 2 strikes"):
        breakshot.shots([RACK9] * 3, good)
    with pytest.raises(ValueError, match=r"^scenarios\[1\]\.balls: has 16 balls"):
        breakshot.shots([RACK9, {**RACK9, "rack": {"game": "eight_ball"}}], good)
    with pytest.raises(ValueError, match=r"^threads: must be >= 0"):
        breakshot.shots(RACK9, good, threads=-1)
    with pytest.raises(TypeError, match=r"^threads: expected an int"):
        breakshot.shots(RACK9, good, threads=1.5)
    with pytest.raises(ValueError, match=r"^noise: "):
        breakshot.shots(RACK9, good, noise="loud")
    with pytest.raises(ValueError, match=r"^seed: must be in \[0, 2\*\*64\)"):
        breakshot.shots(RACK9, good, seed=-1)
    with pytest.raises(TypeError, match=r"^scenario: expected a scenario"):
        breakshot.shots(3, good)


def test_empty_batch_and_repr():
    empty = breakshot.shots(RACK9, np.zeros((0, 5)))
    assert empty.final_positions.shape == (0, 10, 2)
    assert len(empty) == 0
    r = breakshot.shots(RACK9, [BREAK])
    text = repr(r)
    assert text.startswith("<breakshot.ShotResults shots=1 balls=10 pocketed=")
    assert "noise=none" in text
    assert len(set(r.pocket_names)) == 6
    assert "strikes" in breakshot.shots.__doc__
