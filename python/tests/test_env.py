"""breakshot.env.PoolEnv: the Gymnasium API (checked by gym_checks, a
hand-written version of Gymnasium's environment checks), random play
without exceptions, determinism, and episodes that replay with the CLI."""

from __future__ import annotations

import numpy as np
import pytest

from breakshot import PlaceCue, Shot
from breakshot.env import ACTION_FIELDS, Box, PoolEnv

import gym_checks


@pytest.mark.parametrize("game", ["nine_ball", "eight_ball"])
def test_gymnasium_checks(game):
    gym_checks.check_env(lambda: PoolEnv(game=game, opponent="baseline", seed=0))


def test_spaces():
    env = PoolEnv(game="nine_ball", opponent="baseline")
    assert env.observation_space.shape == (4 * 10 + 9,)
    assert PoolEnv(game="eight_ball", opponent="baseline").observation_space.shape == (73,)
    assert env.action_space.shape == (len(ACTION_FIELDS),) == (9,)
    assert env.observation_space.dtype == np.float32 == env.action_space.dtype
    b = Box(-1.0, 1.0, shape=(3,))
    assert b.contains(np.zeros(3, np.float32)) and not b.contains(np.full(3, 2.0, np.float32))


def test_1000_random_steps_without_an_exception(tmp_path, run_cli):
    env = PoolEnv(game="nine_ball", opponent="baseline", seed=0, max_steps=60)
    obs, info = env.reset(seed=0)
    returns, ret, episodes_over = [], 0.0, 0
    for i in range(1000):
        obs, r, terminated, truncated, info = env.step(env.action_space.sample())
        assert env.observation_space.contains(obs)
        ret += r
        if terminated:
            assert r in (1.0, -1.0, 0.0) and info["winner"] in (0, 1, None)
            assert r == {0: 1.0, 1: -1.0, None: 0.0}[info["winner"]]
            episodes_over += 1
            if episodes_over == 1:  # an episode is a game that replays with the CLI
                env.game.save(tmp_path / "episode.json")
                assert run_cli("replay", tmp_path / "episode.json").returncode == 0
        if terminated or truncated:
            returns.append(ret)
            ret = 0.0
            obs, info = env.reset()
    assert episodes_over > 0 and all(abs(x) <= 1.0 for x in returns)


def test_eight_ball_random_steps():
    env = PoolEnv(game="eight_ball", opponent="baseline", seed=4)
    env.reset(seed=4)
    for _ in range(200):
        _, _, te, tr, _ = env.step(env.action_space.sample())
        if te or tr:
            env.reset()


def test_short_run_against_an_ai_level():
    env = PoolEnv(game="nine_ball", opponent="club", seed=1, opponent_threads=1)
    env.reset(seed=1)
    for _ in range(15):
        _, _, te, tr, info = env.step(env.action_space.sample())
        assert isinstance(info["rulings"], list)
        if te or tr:
            env.reset()


def test_same_seed_same_trajectory():
    make = lambda: PoolEnv(game="nine_ball", opponent="baseline", seed=0, max_steps=30)
    a = gym_checks.trajectory(make(), 11, 120)
    assert a == gym_checks.trajectory(make(), 11, 120)
    assert a != gym_checks.trajectory(make(), 12, 120)
    # The episode's game follows the seed: reset(seed) twice, the same rack.
    env = make()
    o1, i1 = env.reset(seed=2)
    o2, i2 = env.reset(seed=2)
    assert np.array_equal(o1, o2) and i1["game_seed"] == i2["game_seed"]


def test_truncation_after_max_steps():
    env = PoolEnv(game="nine_ball", opponent="baseline", max_steps=2)
    env.reset(seed=0)
    # Soft shots that reach nothing: the game goes on.
    soft = np.array([180.0, 0, 0.1, 0, 0, 0.9, 0.5, -1, 0], np.float32)
    _, _, te, tr, _ = env.step(soft)
    assert not tr
    if not te:
        _, _, te, tr, _ = env.step(soft)
        assert tr or te


def test_an_illegal_placement_is_a_foul_not_an_exception():
    env = PoolEnv(game="nine_ball", opponent="baseline", seed=3)
    env.reset(seed=3)
    g = env.game
    miscue = Shot(0.0, 0.0, 1.0, a=0.95)
    # Fouls on both sides (miscues) until the agent has ball in hand anywhere.
    for _ in range(6):
        s = g.state
        if s.player == 0 and s.ball_in_hand == "anywhere":
            break
        if g.legal_actions().choices:
            from breakshot import Decide
            g.apply(Decide(g.legal_actions().choices[0]))
            continue
        if s.ball_in_hand != "none":
            g.apply(PlaceCue(0.4, 0.3))
        g.apply(miscue)
    s = g.state
    assert s.player == 0 and s.ball_in_hand == "anywhere"
    t = g.table
    ball = s.lowest_ball
    x, y = s.position[ball]
    u = (x - t["ball_radius"]) / (t["length"] - 2 * t["ball_radius"])
    v = (y - t["ball_radius"]) / (t["width"] - 2 * t["ball_radius"])
    obs, r, te, tr, info = env.step(np.array([0, 0, 2, 0, 0, u, v, -1, 0], np.float32))
    assert "overlap" in info["illegal_placement"]
    assert info["fouls"], info


def test_the_environment_calls_the_pocket_on_the_object_balls_path():
    env = PoolEnv(game="nine_ball", opponent="baseline", seed=0)
    env.reset(seed=0)
    g = env.game
    # After a break the agent's aim straight at the lowest ball is called.
    g.apply(PlaceCue(0.5, 0.635))
    g.apply(Shot(0.0, 0.0, 0.05))  # a break that barely moves: a foul or the turn passes
    env._others()
    if g.over or g.state.player != 0 or g.state.ball_in_hand != "none":
        pytest.skip("the position did not come up")
    s = g.state
    c, o = np.array(s.position[0]), np.array(s.position[s.lowest_ball])
    phi = float(np.degrees(np.arctan2(*(o - c)[::-1])))
    call = env._call(phi, -1, g.legal_actions())
    assert call.ball == s.lowest_ball and 0 <= call.pocket < 6
