"""breakshot.env: a reinforcement-learning environment with the Gymnasium
API (docs/python.md, "Reinforcement learning (PoolEnv)").

    from breakshot.env import PoolEnv
    env = PoolEnv(game="nine_ball", opponent="baseline", seed=0)
    obs, info = env.reset(seed=1)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())

When the ``gymnasium`` package is importable, PoolEnv subclasses
``gymnasium.Env``, its spaces are ``gymnasium.spaces.Box`` and it is
registered as ``breakshot/PoolEnv-v0``; otherwise it works alone with the
same methods and this module's :class:`Box`.
"""

from __future__ import annotations

import math
from typing import Any, Optional, Tuple

import numpy as np

from .game import Call, Game, PlaceCue, Player, Shot, mix_seed

try:  # pragma: no cover - gymnasium is not installed where this is tested
    import gymnasium as _gym
except ImportError:  # the standalone path
    _gym = None

__all__ = ["Box", "PoolEnv", "ACTION_FIELDS", "GYMNASIUM"]

#: True when gymnasium was importable: PoolEnv is then a gymnasium.Env.
GYMNASIUM = _gym is not None

#: The action vector's entries, in order.
ACTION_FIELDS = ("phi", "theta", "speed", "a", "b", "place_x", "place_y", "call", "push_out")

_MAX_SPEED = 20.0  # kMaxCueSpeed (game.hpp)
_MAX_THETA = 89.0  # what perturb() keeps theta within
_MAX_OFFSET = 0.5  # the miscue limit: larger offsets only miscue


class Box:
    """A box of float arrays, as gymnasium.spaces.Box: ``low``, ``high``,
    ``shape``, ``dtype``; ``sample()`` draws uniformly from it with the
    space's own generator (``seed(s)`` seeds it), ``contains(x)`` says
    whether x has the shape and dtype and lies within the bounds."""

    def __init__(self, low, high, shape=None, dtype=np.float32, seed: Optional[int] = None):
        self.dtype = np.dtype(dtype)
        if shape is None:
            shape = np.shape(low)
        self.shape = tuple(int(n) for n in shape)
        self.low = np.broadcast_to(np.asarray(low, dtype=self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=self.dtype), self.shape).copy()
        if np.any(self.low > self.high):
            raise ValueError("Box: low must not exceed high")
        self.np_random = np.random.default_rng(seed)

    def seed(self, seed: Optional[int] = None) -> list:
        """Seeds the generator of sample(); returns [seed]."""
        self.np_random = np.random.default_rng(seed)
        return [seed]

    def sample(self) -> np.ndarray:
        """A uniform draw from the box (of the space's dtype)."""
        u = self.np_random.random(self.shape)
        x = self.low.astype(np.float64) + u * (self.high.astype(np.float64) - self.low)
        return np.clip(x.astype(self.dtype), self.low, self.high)

    def contains(self, x) -> bool:
        """True when x is an array of this shape and dtype within the bounds."""
        if not isinstance(x, np.ndarray):
            try:
                x = np.asarray(x, dtype=self.dtype)
            except (TypeError, ValueError):
                return False
        return (x.shape == self.shape and np.can_cast(x.dtype, self.dtype)
                and bool(np.all(x >= self.low)) and bool(np.all(x <= self.high)))

    __contains__ = contains

    def __eq__(self, other) -> bool:
        return (isinstance(other, Box) and self.shape == other.shape
                and self.dtype == other.dtype and np.array_equal(self.low, other.low)
                and np.array_equal(self.high, other.high))

    def __repr__(self) -> str:
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"


def _box(low, high):
    if _gym is not None:  # pragma: no cover
        return _gym.spaces.Box(low=np.asarray(low, np.float32), high=np.asarray(high, np.float32),
                               dtype=np.float32)
    return Box(low, high, dtype=np.float32)


_PHASES = ("break_shot", "shot", "push_out_choice", "illegal_break_choice",
           "eight_on_break_choice", "game_over")
_GROUPS = ("none", "solids", "stripes")
_IN_HAND = ("none", "kitchen", "anywhere")

_Base = _gym.Env if _gym is not None else object


class PoolEnv(_Base):
    """A game of pool against a breakshot player, as a Gymnasium environment.

    ``PoolEnv(game="nine_ball", opponent="club", seed=0, table="9ft",
    noise="none", breaker=0, max_steps=200, pot_reward=0.0,
    foul_penalty=0.0, decider="baseline", opponent_threads=None)``.

    The agent sits in seat 0 and acts whenever the game waits for its shot
    (the break included); the opponent's turns, and the decisions the rules
    offer the agent (answering a push-out, an illegal 8-ball break, the 8 on
    the break), are played inside ``step`` by breakshot players:
    ``opponent`` (a name of :func:`breakshot.players`) and ``decider``.

    Observation (float32, shape (4 n + 9,) for n balls with the cue ball:
    49 in 9-ball, 73 in 8-ball): the positions x, y of balls 0..n-1 in
    metres (0 for a ball off the table), n on-table flags, n flags of the
    balls the agent may legally hit first (its group, or the 9-ball lowest
    ball), the agent's group one-hot (none, solids, stripes; 8-ball), ball
    in hand one-hot (none, kitchen, anywhere), push-out allowed, and the
    agent's and the opponent's fouls in a row.

    Action (float32, 9 entries, ``ACTION_FIELDS``), clipped to its box:
    ``phi`` [0, 360) degrees, ``theta`` [0, 89] degrees, ``speed`` [0.1, 20]
    m/s, ``a``, ``b`` [-0.5, 0.5] radii; ``place_x``, ``place_y`` in [0, 1]:
    where to place the cue ball when it is in hand, as fractions of the
    region allowed (the kitchen or the whole bed, a ball's radius inside
    the cushions); ``call`` in [-1, 5], rounded: a pocket index, or -1 to
    let the environment call the pocket nearest the path of the object
    ball the aim line meets first; ``push_out`` > 0.5 declares a 9-ball
    push-out when one is allowed. A call the rules refuse is dropped. A
    placement the rules refuse (a ball in the way) is a foul, never an
    exception: the cue ball goes to the nearest legal spot and the turn is
    played as a miscue, which the rules call a foul; ``info`` says so.

    Reward: +1 when the agent wins, -1 when it loses, 0 for a draw and
    every other step; plus ``pot_reward`` for each object ball the agent's
    shot pockets and minus ``foul_penalty`` for each of its fouls (both 0
    by default: no shaping). ``terminated`` when the game is over,
    ``truncated`` after ``max_steps`` steps of an episode.

    Determinism: episode k after ``reset(seed=s)`` (k = 0, 1, ... for the
    resets without a seed that follow) plays the game with seed
    ``mix_seed(s, k)``; the same seed and the same actions give the same
    observations, rewards and game. ``env.game`` is the breakshot.Game being
    played: ``env.game.save(path)`` writes a record ``breakshot replay``
    checks.
    """

    metadata = {"render_modes": []}
    render_mode = None

    def __init__(self, game: str = "nine_ball", opponent: str = "club", seed: int = 0,
                 table: str = "9ft", noise: str = "none", breaker: int = 0,
                 max_steps: int = 200, pot_reward: float = 0.0, foul_penalty: float = 0.0,
                 decider: str = "baseline", opponent_threads: Optional[int] = None):
        if breaker not in (0, 1) or isinstance(breaker, bool):
            raise ValueError(f"breaker: must be 0 (the agent) or 1 (the opponent), not {breaker!r}")
        if isinstance(max_steps, bool) or not isinstance(max_steps, int) or max_steps < 1:
            raise ValueError(f"max_steps: expected a whole number >= 1, not {max_steps!r}")
        if game not in ("eight_ball", "nine_ball"):
            # Its observation and action are the pool games' (groups,
            # calls, push-outs); snooker's score and nominations have no
            # place in them.
            raise ValueError(f"game: PoolEnv plays eight_ball and nine_ball, not {game!r}")
        self.game_name = game
        self.table_size = table
        self.noise = noise
        self.breaker = breaker
        self.max_steps = max_steps
        self.pot_reward = float(pot_reward)
        self.foul_penalty = float(foul_penalty)
        self.opponent = Player(opponent, threads=opponent_threads)
        self.decider = Player(decider)
        self._seed = int(seed)
        self._episode = -1
        # A game only to read the table and the ball count from.
        self.game = Game(game, table, seed=0, players=("agent", self.opponent.name), noise=noise)
        t = self.game.table
        self._t = t
        self.n_balls = int(t["ball_count"])
        n = self.n_balls
        self._steps = 0
        low = np.zeros(4 * n + 9, np.float32)
        high = np.ones(4 * n + 9, np.float32)
        high[0:2 * n:2] = t["length"]
        high[1:2 * n:2] = t["width"]
        high[4 * n + 7:] = 3.0  # fouls in a row: at most 2 before the third loses (9-ball)
        self.observation_space = _box(low, high)
        self.action_space = _box([0.0, 0.0, 0.1, -_MAX_OFFSET, -_MAX_OFFSET, 0.0, 0.0, -1.0, 0.0],
                                 [360.0, _MAX_THETA, _MAX_SPEED, _MAX_OFFSET, _MAX_OFFSET,
                                  1.0, 1.0, 5.0, 1.0])

    # -- Gymnasium API -------------------------------------------------------

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None
              ) -> Tuple[np.ndarray, dict]:
        """Starts an episode: a new game (its seed from the env's seed and the
        episode's index), the opponent's turns played until the agent must
        act. ``seed`` reseeds the environment (and the action space's
        sampler); ``options`` may hold ``"breaker"`` (0 or 1) for this
        episode."""
        if seed is not None:
            self._seed = int(seed)
            self._episode = -1
            self.action_space.seed(int(seed))
        if _gym is not None:  # pragma: no cover
            super().reset(seed=seed)
        self._episode += 1
        breaker = self.breaker
        if options:
            unknown = set(options) - {"breaker"}
            if unknown:
                raise ValueError(f"options: unknown key {sorted(unknown)[0]!r} (known: breaker)")
            breaker = options.get("breaker", breaker)
            if breaker not in (0, 1) or isinstance(breaker, bool):
                raise ValueError(f"options['breaker']: must be 0 or 1, not {breaker!r}")
        game_seed = mix_seed(self._seed % (1 << 64), self._episode)
        self.game = Game(self.game_name, self.table_size, seed=game_seed, breaker=breaker,
                         players=("agent", self.opponent), noise=self.noise)
        self._steps = 0
        rulings = self._others()
        info = self._info(rulings=rulings)
        info["game_seed"] = game_seed
        return self._obs(), info

    def step(self, action) -> Tuple[np.ndarray, float, bool, bool, dict]:
        """Plays the agent's shot (placing the cue ball first when it is in
        hand), then the opponent's turns, until the agent must act again or
        the game ends. Returns (obs, reward, terminated, truncated, info)."""
        if self.game.over:
            raise RuntimeError("step: the episode is over; call reset()")
        a = np.asarray(action, dtype=np.float64).reshape(-1)
        if a.shape != (len(ACTION_FIELDS),):
            raise ValueError(f"action: expected {len(ACTION_FIELDS)} numbers "
                             f"({', '.join(ACTION_FIELDS)}), not shape {np.shape(action)}")
        if not np.all(np.isfinite(a)):
            raise ValueError("action: every entry must be a finite number")
        a = np.clip(a, self.action_space.low, self.action_space.high)
        self._steps += 1
        reward = 0.0
        illegal = None
        called = None
        legal = self.game.legal_actions()
        state = self.game.state
        before = state.on_table
        miscue = False
        if legal.place != "none":
            x, y = self._place_point(legal.place, a[5], a[6])
            illegal = self.game.check_placement(x, y)
            if illegal is not None:
                x, y = self._nearest_legal(legal.place, x, y)
                miscue = True
            self.game.apply(PlaceCue(x, y))
            legal = self.game.legal_actions()
        phi = float(a[0]) % 360.0
        if miscue:
            shot = Shot(phi=phi, theta=0.0, speed=1.0, a=0.95, b=0.0)
        else:
            shot = Shot(phi=phi, theta=float(a[1]), speed=float(a[2]), a=float(a[3]),
                        b=float(a[4]))
            push = bool(a[8] > 0.5) and legal.push_out
            pocket = int(round(float(a[7])))
            call = self._call(phi, pocket, legal)
            if call is not None and not push:
                c = Shot(shot.phi, shot.theta, shot.speed, shot.a, shot.b, call=call)
                if self.game.check(c) is None:
                    shot, called = c, call
            if push:
                p = Shot(shot.phi, shot.theta, shot.speed, shot.a, shot.b, push_out=True)
                if self.game.check(p) is None:
                    shot = p
        out = self.game.apply(shot)
        after = out.state.on_table
        potted = sum(1 for b in range(1, len(before)) if before[b] and not after[b])
        reward += self.pot_reward * potted - self.foul_penalty * len(out.fouls)
        rulings = [out.text] + self._others()
        terminated = self.game.over
        if terminated:
            w = self.game.winner
            reward += 0.0 if w is None else (1.0 if w == 0 else -1.0)
        truncated = (not terminated) and self._steps >= self.max_steps
        info = self._info(rulings=rulings)
        info.update(fouls=list(out.fouls), pocketed=potted, illegal_placement=illegal,
                    call=None if called is None else (called.ball, called.pocket))
        return self._obs(), float(reward), bool(terminated), bool(truncated), info

    def render(self):
        """No rendering (breakshot.plot.table draws a state)."""
        return None

    def close(self) -> None:
        """Nothing to release."""

    # -- helpers -------------------------------------------------------------

    def _others(self) -> list:
        """Plays every action that is not the agent's shot: the opponent's
        turns and the agent's decisions (by the decider). Returns their
        rulings."""
        texts = []
        g = self.game
        while not g.over:
            s = g.state
            if s.player == 0 and s.phase in ("break_shot", "shot"):
                break
            who = self.opponent if s.player == 1 else self.decider
            texts.append(g.apply(who.decide(g)).text)
        return texts

    def _place_point(self, place: str, u: float, v: float) -> Tuple[float, float]:
        r = self._t["ball_radius"]
        x_hi = self._t["head_string"] if place == "kitchen" else self._t["length"] - r
        x = r + float(u) * (x_hi - r)
        y = r + float(v) * (self._t["width"] - 2 * r)
        return x, y

    def _nearest_legal(self, place: str, x: float, y: float) -> Tuple[float, float]:
        r = self._t["ball_radius"]
        step = r
        x_hi = self._t["head_string"] if place == "kitchen" else self._t["length"] - r
        xs = np.arange(r, x_hi + 1e-12, step)
        ys = np.arange(r, self._t["width"] - r + 1e-12, step)
        gx, gy = np.meshgrid(xs, ys)
        pts = np.stack([gx.ravel(), gy.ravel()], axis=1)
        order = np.lexsort((pts[:, 1], pts[:, 0], np.hypot(pts[:, 0] - x, pts[:, 1] - y)))
        for k in order:
            px, py = float(pts[k, 0]), float(pts[k, 1])
            if self.game.check_placement(px, py) is None:
                return px, py
        raise RuntimeError("no legal place for the cue ball (an engine bug)")

    def _call(self, phi: float, pocket: int, legal) -> Optional[Call]:
        """The call of a shot aimed at phi: the object ball the aim line meets
        first and ``pocket``, or (pocket -1) the pocket nearest that ball's
        path from a full-ball contact along the line of centres."""
        s = self.game.state
        if s.phase == "break_shot" or not s.on_table[0]:
            return None
        r = self._t["ball_radius"]
        c = np.array(s.position[0])
        d = np.array([math.cos(math.radians(phi)), math.sin(math.radians(phi))])
        best, best_t = None, math.inf
        for b in range(1, len(s.on_table)):
            if not s.on_table[b]:
                continue
            p = np.array(s.position[b]) - c
            along = float(p @ d)
            off2 = float(p @ p) - along * along
            if along <= 0 or off2 >= (2 * r) ** 2:
                continue
            t = along - math.sqrt((2 * r) ** 2 - off2)  # where the cue ball touches it
            if t < best_t:
                best, best_t = b, t
        if best is None:
            return None
        if pocket >= 0:
            return Call(best, pocket)
        ghost = c + best_t * d
        obj = np.array(s.position[best])
        path = obj - ghost
        path /= np.linalg.norm(path)
        choice, choice_dist = None, math.inf
        for i, pk in enumerate(self._t["pockets"]):
            q = np.array(pk["centre"]) - obj
            along = float(q @ path)
            if along <= 0:
                continue
            dist = math.sqrt(max(float(q @ q) - along * along, 0.0))
            if dist < choice_dist:
                choice, choice_dist = i, dist
        return None if choice is None else Call(best, choice)

    def _obs(self) -> np.ndarray:
        s = self.game.state
        n = self.n_balls
        o = np.zeros(4 * n + 9, np.float32)
        for b in range(n):
            if s.on_table[b]:
                o[2 * b] = s.position[b][0]
                o[2 * b + 1] = s.position[b][1]
                o[2 * n + b] = 1.0
        for b in s.targets:
            o[3 * n + b] = 1.0
        base = 4 * n
        o[base + _GROUPS.index(s.group[0])] = 1.0 if s.game == "eight_ball" else 0.0
        o[base + 3 + _IN_HAND.index(s.ball_in_hand)] = 1.0
        o[base + 6] = 1.0 if s.push_out_allowed else 0.0
        o[base + 7] = min(s.fouls_in_a_row[0], 3)
        o[base + 8] = min(s.fouls_in_a_row[1], 3)
        return np.clip(o, self.observation_space.low, self.observation_space.high)

    def _info(self, rulings: list) -> dict:
        s = self.game.state
        return {"phase": s.phase, "shots": s.shots, "actions": self.game.actions,
                "rulings": rulings, "winner": self.game.winner, "steps": self._steps}

    def __repr__(self) -> str:
        return (f"<breakshot.env.PoolEnv {self.game_name} opponent={self.opponent.name} "
                f"seed={self._seed} episode={self._episode} steps={self._steps}>")


if _gym is not None:  # pragma: no cover
    try:
        _gym.register(id="breakshot/PoolEnv-v0", entry_point="breakshot.env:PoolEnv")
    except Exception:  # already registered (a reload)
        pass
