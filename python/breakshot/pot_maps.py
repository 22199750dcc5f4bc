"""Pot maps: how often a computer player pots one ball in one pocket from
one cue-ball position (pot_chance) or from every point of a grid (pot_map).

The level plays the pot as it plays in a game, limited to that ball and
that pocket: its own shot generation (direct, bank, kick and combination
pots of that ball into that pocket, its own speeds and spins; no
safeties), its own number of shortlisted candidates and, for the champion,
its centred aims. The shortlist is sampled under the level's own noise and
the shot that pots most often is its best shot; how often that shot pots
is then measured on fresh noise draws. The work is done in C++
(include/breakshot/pot_map.hpp) with the GIL released.
"""

from __future__ import annotations

import math

import numpy as np

from . import _core
from ._position import ball_number, game_position

__all__ = ["PotMap", "pot_chance", "pot_map"]


def _pocket_index(table: dict, pocket) -> int:
    names = [p[0] for p in table["pockets"]]
    if isinstance(pocket, str):
        if pocket not in names:
            raise ValueError(f"unknown pocket {pocket!r} (pockets: {', '.join(names)})")
        return names.index(pocket)
    if isinstance(pocket, bool) or not isinstance(pocket, (int, np.integer)):
        raise TypeError(f"pocket is an index or a name, not {pocket!r}")
    return int(pocket)


def _ball(ball) -> int:
    return ball_number(ball)


def _count(value, name, default=0) -> int:
    if value is None:
        return default
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
        raise ValueError(f"{name} must be an int >= 0, not {value!r}")
    return int(value)


def _seed(seed) -> int:
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not 0 <= seed < 2**64:
        raise ValueError(f"seed must be an int in [0, 2**64), not {seed!r}")
    return int(seed)


def _grid(table: dict, xs, ys, nx, ny):
    """The grid's xs and ys: as given, or the centres of nx by ny equal
    cells covering the playing surface."""
    if xs is None:
        nx = _count(nx, "nx")
        xs = (np.arange(nx) + 0.5) * table["length"] / max(nx, 1)
    if ys is None:
        ny = _count(ny, "ny")
        ys = (np.arange(ny) + 0.5) * table["width"] / max(ny, 1)
    return np.asarray(xs, dtype=float).ravel(), np.asarray(ys, dtype=float).ravel()


def _args(position, ball, pocket, level, samples, candidates, seed, threads):
    pos = game_position(position)
    table = _core.pool_table(pos["table_size"])
    return (pos, table, _ball(ball), _pocket_index(table, pocket), str(level),
            _count(samples, "samples"), _count(candidates, "candidates"), _seed(seed),
            _count(threads, "threads"))


def pot_chance(position, cue, ball, pocket, level="champion", *, samples=None,
               candidates=None, seed=0, threads=None) -> dict:
    """The chance that ``level`` pots ``ball`` in ``pocket`` with the cue
    ball at ``cue`` = (x, y) and the other balls as in ``position``.

    ``position`` is a game position (docs/python.md, "Game positions": a
    dict with ``balls``, a list of (id, x, y), or a game with a ``state``);
    the cue ball's own place in it is ignored. ``ball`` is a ball number,
    ``pocket`` an index into the table's pockets or a pocket name
    ("top_right", ...), ``level`` a computer player's level ("beginner",
    "amateur", "club", "expert", "champion"). ``samples`` (plays per
    candidate and for the measurement) and ``candidates`` default to the
    level's own; ``threads`` defaults to all cores; the answer is the same
    for any number. Returns a dict: ``placeable``, ``probability`` (0
    where the cue ball cannot be placed or no shot was found),
    ``aim`` (phi, theta, speed, a, b) of the best shot, its ``kind``,
    ``shots`` (candidates found), ``plays`` and ``simulations``. Raises
    ValueError naming a bad ball, pocket, level or position.
    """
    pos, _, ball, pocket, level, samples, candidates, seed, threads = _args(
        position, ball, pocket, level, samples, candidates, seed, threads)
    x, y = (float(v) for v in cue)
    return _core.pot_chance(pos["game"], pos["table_size"], pos["positions"], pos["on_table"],
                            pos["player"], pos["groups"], x, y, ball, pocket, level, samples,
                            candidates, seed, threads)


def pot_map(position, ball, pocket, level="champion", *, xs=None, ys=None, nx=40, ny=20,
            samples=None, candidates=None, seed=0, threads=None) -> "PotMap":
    """A pot map: pot_chance at every point (xs[i], ys[j]) of a grid.

    ``xs`` and ``ys`` default to the centres of ``nx`` by ``ny`` equal cells
    covering the playing surface. Cell k (row-major, k = j * nx + i) is
    pot_chance with the seed derived from ``seed`` and k, run on one
    thread; the cells run in parallel on ``threads`` threads (default all
    cores) and the arrays are the same for any number. Other arguments as
    for pot_chance. Returns a breakshot.PotMap.
    """
    pos, table, ball, pocket_i, level, samples, candidates, seed, threads = _args(
        position, ball, pocket, level, samples, candidates, seed, threads)
    xs, ys = _grid(table, xs, ys, nx, ny)
    data = _core.pot_map(pos["game"], pos["table_size"], pos["positions"], pos["on_table"],
                         pos["player"], pos["groups"], ball, pocket_i, level, xs.tolist(),
                         ys.tolist(), samples, candidates, seed, threads)
    return PotMap(data, xs, ys, pos, ball, pocket_i, level, samples, seed)


class PotMap:
    """A pot map (breakshot.pot_map): arrays over the grid, row j for ys[j]
    and column i for xs[i].

    ``probability`` (ny, nx)
        share of the measuring plays that potted the ball in the pocket
        with no foul; 0 where the cue ball cannot be placed (on or
        against a ball, off the playing surface, in a pocket: ``valid``
        False) and where the level found no shot.
    ``aims`` (ny, nx, 5)
        the best shot's phi, theta (degrees), speed (m/s), a, b (fractions
        of the radius); NaN where there is none.
    ``valid`` (ny, nx) bool
        the cue ball can be placed there.
    ``shots``, ``plays`` (ny, nx) int
        candidate shots found; measuring plays counted.
    ``kinds``
        nested list (ny by nx) of the best shot's kind ('direct', 'bank',
        'kick', 'combination') or None.
    ``xs`` (nx,), ``ys`` (ny,)
        the grid, metres.

    Also ``ball``, ``pocket`` (index), ``pocket_name``, ``level``,
    ``samples`` (0: the level's own), ``seed``, ``simulations`` (total
    noisy plays run), ``position`` (the game position used) and ``table``
    (the table's outline and pockets), for breakshot.plot.pot_map.
    """

    def __init__(self, data, xs, ys, position, ball, pocket, level, samples, seed):
        self.probability = data["probability"]
        self.aims = data["aims"]
        self.valid = data["valid"]
        self.shots = data["shots"]
        self.plays = data["plays"]
        self.kinds = data["kinds"]
        self.simulations = data["simulations"]
        self.table = data["table"]
        self.ball_radius = data["ball_radius"]
        self.xs = xs
        self.ys = ys
        self.position = position
        self.ball = ball
        self.pocket = pocket
        self.pocket_name = self.table["pockets"][pocket][0]
        self.level = level
        self.samples = samples
        self.seed = seed

    @property
    def shape(self):
        """(ny, nx)."""
        return self.probability.shape

    def mean(self) -> float:
        """The mean probability over the cells where the cue ball can be
        placed (NaN if there are none)."""
        p = self.probability[self.valid]
        return float(p.mean()) if p.size else math.nan

    def __repr__(self) -> str:
        ny, nx = self.shape
        return (f"<breakshot.PotMap ball={self.ball} pocket={self.pocket_name} "
                f"level={self.level} grid={nx}x{ny} valid={int(self.valid.sum())} "
                f"mean={self.mean():.3f}>")
