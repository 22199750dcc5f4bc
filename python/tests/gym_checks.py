"""A hand-written version of Gymnasium's environment checks
(gymnasium.utils.env_checker.check_env), for environments used without
gymnasium installed. Each check raises AssertionError naming what is
wrong."""

from __future__ import annotations

import numbers

import numpy as np


def check_space(space, name: str, samples: int = 200) -> None:
    """A Box-like space: low/high/shape/dtype, sample() within it,
    contains() refusing what lies outside."""
    for attr in ("low", "high", "shape", "dtype", "sample", "contains", "seed"):
        assert hasattr(space, attr), f"{name} has no {attr}"
    assert space.low.shape == space.shape and space.high.shape == space.shape, name
    assert np.all(space.low <= space.high), f"{name}: low above high"
    assert np.all(np.isfinite(space.low)) and np.all(np.isfinite(space.high)), name
    space.seed(123)
    first = [space.sample() for _ in range(5)]
    space.seed(123)
    again = [space.sample() for _ in range(5)]
    assert all(np.array_equal(a, b) for a, b in zip(first, again)), f"{name}: seed() ignored"
    for _ in range(samples):
        x = space.sample()
        assert isinstance(x, np.ndarray) and x.dtype == space.dtype, f"{name}: sample's dtype"
        assert x.shape == space.shape, f"{name}: sample's shape"
        assert space.contains(x), f"{name}: sample() not contained: {x}"
    assert not space.contains(space.high + 1), f"{name}: contains() above high"
    assert not space.contains(space.low - 1), f"{name}: contains() below low"
    assert not space.contains(np.zeros(space.shape[0] + 1, space.dtype)), f"{name}: wrong shape"


def check_obs(obs, space, where: str) -> None:
    assert isinstance(obs, np.ndarray), f"{where}: observation is {type(obs).__name__}"
    assert obs.dtype == space.dtype, f"{where}: observation dtype {obs.dtype}, space {space.dtype}"
    assert obs.shape == space.shape, f"{where}: observation shape {obs.shape}"
    assert space.contains(obs), f"{where}: observation outside observation_space"


def check_reset(env) -> None:
    """reset returns (obs, info); a seed makes it reproducible; options pass."""
    out = env.reset(seed=5)
    assert isinstance(out, tuple) and len(out) == 2, "reset must return (obs, info)"
    obs, info = out
    check_obs(obs, env.observation_space, "reset")
    assert isinstance(info, dict), "reset's info must be a dict"
    obs2, _ = env.reset(seed=5)
    assert np.array_equal(obs, obs2), "reset(seed=s) twice gave different observations"
    obs3, _ = env.reset()
    check_obs(obs3, env.observation_space, "reset() without a seed")
    obs4, info4 = env.reset(seed=5, options=None)
    assert np.array_equal(obs, obs4)


def check_step(env, steps: int = 20) -> None:
    """step returns (obs, reward, terminated, truncated, info) of the right
    types, for sampled actions and for actions outside the box (clipped)."""
    env.reset(seed=1)
    env.action_space.seed(1)
    for i in range(steps):
        action = env.action_space.sample()
        if i % 5 == 4:
            action = action * 10 - 3  # far outside the box: clipped, never an error
        out = env.step(action)
        assert isinstance(out, tuple) and len(out) == 5, "step must return a 5-tuple"
        obs, reward, terminated, truncated, info = out
        check_obs(obs, env.observation_space, f"step {i}")
        assert isinstance(reward, numbers.Real) and np.isfinite(reward), "reward"
        assert isinstance(terminated, (bool, np.bool_)), "terminated must be a bool"
        assert isinstance(truncated, (bool, np.bool_)), "truncated must be a bool"
        assert isinstance(info, dict), "info must be a dict"
        if terminated or truncated:
            env.reset()


def trajectory(env, seed: int, steps: int) -> list:
    """(obs, reward, terminated, truncated) of `steps` steps with actions
    sampled from a space seeded with `seed`, resetting at episode ends."""
    obs, _ = env.reset(seed=seed)
    env.action_space.seed(seed)
    out = [(obs.tobytes(),)]
    for _ in range(steps):
        obs, r, te, tr, _ = env.step(env.action_space.sample())
        out.append((obs.tobytes(), r, te, tr))
        if te or tr:
            obs, _ = env.reset()
            out.append((obs.tobytes(),))
    return out


def check_determinism(make_env, seed: int = 3, steps: int = 40) -> None:
    """Two environments made alike and seeded alike step alike."""
    a = trajectory(make_env(), seed, steps)
    b = trajectory(make_env(), seed, steps)
    assert a == b, "the same seed gave different trajectories"


def check_env(make_env) -> None:
    """Every check above on environments from make_env()."""
    env = make_env()
    for attr in ("reset", "step", "observation_space", "action_space", "close", "render",
                 "metadata"):
        assert hasattr(env, attr), f"the environment has no {attr}"
    check_space(env.observation_space, "observation_space")
    check_space(env.action_space, "action_space")
    check_reset(env)
    check_step(env)
    check_determinism(make_env)
    env.close()
