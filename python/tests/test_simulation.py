"""breakshot.Simulation: stepping equals one run, copies restore a state,
the state arrays equal simulate()'s final state, and closed-form motion."""

import copy
import math
import pathlib
import threading

import numpy as np
import pytest

import breakshot

ROOT = pathlib.Path(__file__).resolve().parents[2]
BREAK9 = ROOT / "examples" / "pool" / "break_9ball.json"
LSHAPE = ROOT / "examples" / "lab" / "l_shaped_friction.json"


def final_arrays(result):
    balls = result.final["balls"]
    return (np.array([b["position"] for b in balls]),
            np.array([b["velocity"] for b in balls]),
            np.array([b["spin"] for b in balls]),
            [b["state"] for b in balls])


@pytest.mark.parametrize("path", [BREAK9, LSHAPE], ids=["break_9ball", "l_shaped_friction"])
def test_frames_equal_one_run_to_rest(path):
    whole = breakshot.simulate(path)
    sim = breakshot.Simulation(path)
    assert sim.time == 0.0
    frames = 0
    seen = []
    while not sim.at_rest:
        frames += 1
        assert sim.advance_to(frames / 60.0) == "reached"
        assert sim.time == frames / 60.0
        seen += sim.events_since(len(seen))
    assert frames > 10
    assert sim.advance_to_rest() == "reached"
    assert sim.next_event_time == math.inf
    assert sim.events == whole.events
    assert seen == whole.events
    assert sim.event_count == len(whole.events)
    pos, vel, spin, states = final_arrays(whole)
    assert np.array_equal(sim.positions(), pos)
    assert np.array_equal(sim.velocities(), vel)
    assert np.array_equal(sim.spins(), spin)
    assert [breakshot.Simulation.STATE_NAMES[c] for c in sim.states()] == states


def test_positions_at_the_end_equal_simulate_exactly():
    whole = breakshot.simulate(BREAK9)
    sim = breakshot.Simulation(breakshot.Scenario(BREAK9))
    assert sim.advance_to_rest() == "reached"
    pos, _, _, states = final_arrays(whole)
    assert sim.positions().shape == (len(states), 2)
    assert sim.positions().dtype == np.float64
    assert np.array_equal(sim.positions(), pos)
    assert sim.time == whole.final["time"]
    assert sim.ball_ids == [b["id"] for b in whole.final["balls"]]
    # A 9-ball break pockets something with seed 1 or leaves balls where
    # the result says; either way ball() agrees with the result file.
    for i, b in enumerate(whole.final["balls"]):
        d = sim.ball(i)
        assert d["id"] == b["id"] and d["state"] == b["state"]
        assert list(d["position"]) == b["position"]
        assert sim.ball(b["id"]) == d
    assert sim.ball(-1) == sim.ball(len(states) - 1)


def test_copy_mid_run_then_advanced_gives_identical_results():
    sim = breakshot.Simulation(BREAK9)
    sim.advance_to(0.25)
    assert not sim.at_rest
    saved = {"copy": copy.copy(sim), "deepcopy": copy.deepcopy(sim), "method": sim.copy()}
    events_at_saving = sim.event_count
    sim.advance_to_rest()
    for name, c in saved.items():
        assert c.time == 0.25, name
        assert c.event_count == events_at_saving, name
        assert c.advance_to_rest() == "reached"
        assert c.events == sim.events, name
        assert np.array_equal(c.positions(), sim.positions()), name
        assert np.array_equal(c.spins(), sim.spins()), name
        assert c.time == sim.time


def test_restore_puts_back_a_saved_state():
    sim = breakshot.Simulation(BREAK9)
    sim.advance_to(0.1)
    saved = sim.copy()
    p, v = sim.positions(), sim.velocities()
    sim.advance_to_rest()
    end = sim.positions()
    sim.restore(saved)
    assert sim.time == 0.1
    assert np.array_equal(sim.positions(), p)
    assert np.array_equal(sim.velocities(), v)
    # Restoring does not use up the saved state.
    sim.advance_to_rest()
    assert np.array_equal(sim.positions(), end)
    sim.restore(saved)
    assert sim.time == 0.1
    assert saved.time == 0.1


def test_friction_model_stopping_distance_closed_form():
    # A lone ball slowing at a constant deceleration d from speed v:
    # x(t) = x0 + v t - d t^2 / 2, stopping after v / d at distance v^2 / (2 d).
    v, d = 0.8, 0.2
    sim = breakshot.Simulation({
        "physics": {"model": "friction", "deceleration": d},
        "table": {"shape": "rectangle", "min": [-1.0, -1.0], "max": [3.0, 1.0]},
        "balls": [{"id": "a", "position": [0.0, 0.0], "velocity": [v, 0.0]}],
    })
    sim.advance_to(1.5)
    assert sim.positions()[0, 0] == pytest.approx(v * 1.5 - d * 1.5 ** 2 / 2, rel=1e-13)
    assert sim.velocities()[0, 0] == pytest.approx(v - d * 1.5, rel=1e-13)
    assert sim.next_event_time == pytest.approx(v / d, rel=1e-13)
    assert sim.advance_to_rest() == "reached"
    assert sim.positions()[0, 0] == pytest.approx(v * v / (2 * d), rel=1e-13)
    assert sim.positions()[0, 1] == 0.0
    assert sim.ball(0)["state"] == "stationary"


def test_pool_centre_strike_slides_then_rolls_to_the_closed_form_distance():
    # docs/physics.md: a ball struck at its centre slides until
    # 2 v0 / (7 mu_s g), covering 12 v0^2 / (49 mu_s g), then rolls at 5/7 v0
    # and stops after (5/7 v0)^2 / (2 mu_r g).
    mu_s, mu_r, g = 0.2, 0.01, 9.81
    sim = breakshot.Simulation({
        "physics": {"model": "pool"},
        "table": {"shape": "pool", "size": "9ft"},
        "balls": [{"id": "cue", "position": [0.3, 0.635]}],
        "cue": {"speed": 0.3, "phi": 0.0},
    })
    v0 = sim.velocities()[0, 0]
    assert sim.ball("cue")["state"] == "sliding"
    t_roll = 2 * v0 / (7 * mu_s * g)
    assert sim.next_event_time == pytest.approx(t_roll, rel=1e-12)
    sim.advance_to(t_roll)
    assert sim.ball(0)["state"] == "rolling"
    assert sim.velocities()[0, 0] == pytest.approx(5 / 7 * v0, rel=1e-12)
    assert sim.advance_to_rest() == "reached"
    distance = 12 * v0 ** 2 / (49 * mu_s * g) + (5 / 7 * v0) ** 2 / (2 * mu_r * g)
    assert sim.positions()[0, 0] - 0.3 == pytest.approx(distance, rel=1e-12)
    assert [e["type"] for e in sim.events] == ["cue_strike", "state_change", "state_change"]


def test_ideal_model_constant_velocity_between_events():
    sim = breakshot.Simulation({
        "physics": {"model": "ideal"},
        "table": {"shape": "rectangle", "min": [-1.0, -1.0], "max": [1.0, 1.0]},
        "balls": [{"id": "a", "position": [0.0, 0.0], "velocity": [0.3, -0.2]}],
        "until": {"time": 1.0},
    })
    for t in (0.5, 1.0, 2.0):
        assert sim.advance_to(t) == "reached"
        assert sim.positions()[0] == pytest.approx([0.3 * t, -0.2 * t], rel=1e-15)
    assert sim.event_count == 0
    assert not sim.at_rest


def test_event_limit_is_reported():
    sim = breakshot.Simulation({
        "physics": {"model": "ideal"},
        "table": {"shape": "rectangle", "min": [-0.1, -0.1], "max": [0.1, 0.1]},
        "balls": [{"id": "a", "position": [0.0, 0.0], "velocity": [1.0, 0.3]}],
        "until": {"time": 1.0},
        "max_events": 5,
    })
    assert sim.advance_to(100.0) == "event_limit"
    assert sim.event_count == 5
    assert sim.time < 100.0


def test_bad_arguments_name_the_argument():
    sim = breakshot.Simulation(LSHAPE)
    sim.advance_to(0.5)
    with pytest.raises(ValueError, match=r"^t: must be a finite time"):
        sim.advance_to(float("nan"))
    with pytest.raises(ValueError, match=r"^t: must be a finite time"):
        sim.advance_to(math.inf)
    with pytest.raises(ValueError, match=r"^t: 0.25 is before the simulation's time 0.5"):
        sim.advance_to(0.25)
    with pytest.raises(TypeError, match=r"^t: expected a number"):
        sim.advance_to("1.0")
    with pytest.raises(TypeError, match=r"^t: expected a number"):
        sim.advance_to(None)
    with pytest.raises(KeyError, match="no ball has the id 'nope'"):
        sim.ball("nope")
    with pytest.raises(IndexError, match="index 3 out of range for 3 balls"):
        sim.ball(3)
    assert sim.time == 0.5  # nothing moved
    with pytest.raises(breakshot.ScenarioError) as e:
        breakshot.Simulation({"physics": {"model": "pool"}, "table": {"shape": "pool"}})
    assert e.value.path


def test_repr_and_state_codes():
    sim = breakshot.Simulation(LSHAPE)
    assert repr(sim) == "<breakshot.Simulation t=0 balls=3 events=0 moving>"
    sim.advance_to_rest()
    r = repr(sim)
    assert r.startswith("<breakshot.Simulation t=") and r.endswith(" at_rest>")
    assert f"events={sim.event_count}" in r
    assert breakshot.Simulation.STATE_NAMES == (
        "stationary", "moving", "sliding", "rolling", "spinning", "pocketed")
    assert sim.states().dtype == np.int8
    assert set(sim.states().tolist()) == {0}
    assert sim.spins().shape == (3, 3)
    assert "advance_to" in breakshot.Simulation.advance_to.__doc__


def test_advancing_in_threads_gives_the_same_results():
    # The GIL is released while advancing: simulations in threads finish
    # with the results of a run in the main thread.
    expected = breakshot.simulate(BREAK9).events
    sims = [breakshot.Simulation(BREAK9) for _ in range(4)]
    threads = [threading.Thread(target=s.advance_to_rest) for s in sims]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for s in sims:
        assert s.events == expected
