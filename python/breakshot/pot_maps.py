"""Pot maps: how often a computer player pots one ball in one pocket from
one cue-ball position (pot_chance) or from every point of a grid (pot_map).

The level plays the pot as it plays in a game, limited to that ball and
that pocket: its own shot generation (direct, bank, kick and combination
pots of that ball into that pocket, its own speeds and spins; no
safeties), its own number of shortlisted candidates and, for the champion,
its centred aims. The shortlist is sampled under the level's own noise and
the shot that pots most often is its best shot; how often that shot pots
is then measured on fresh noise draws. A play counts as the game's own
ruling counts a pot (no foul, the game not lost by it), in every game with
pockets: 8-ball, 9-ball, 10-ball and snooker. The work is done in C++
(include/breakshot/pot_map.hpp) with the GIL released.
"""

from __future__ import annotations

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
    table = _core.pot_table(pos)["table"]
    return (pos, table, _ball(ball), _pocket_index(table, pocket), str(level),
            _count(samples, "samples"), _count(candidates, "candidates"), _seed(seed),
            _count(threads, "threads"))


def _cue(cue):
    try:
        x, y = (float(v) for v in cue)
    except (TypeError, ValueError):
        raise ValueError(f"cue must be a point (x, y) in metres, not {cue!r}") from None
    return x, y


def pot_chance(position, cue, ball, pocket, level="champion", *, samples=None,
               candidates=None, seed=0, threads=None) -> dict:
    """The chance that ``level`` pots ``ball`` in ``pocket`` with the cue
    ball lying at ``cue`` = (x, y) and the other balls as in ``position``.

    ``position`` is a game position (docs/python.md, "Game positions": a
    game, its state, or a dict with ``balls``); the cue ball's own place
    and any ball in hand in it are ignored. ``ball`` is a ball number,
    ``pocket`` an index into the table's pockets or a pocket name
    ("top_right", ...), ``level`` a computer player's level ("beginner",
    "amateur", "club", "expert", "champion"). ``samples`` (plays per
    candidate and for the measurement) and ``candidates`` default to the
    level's own; ``threads`` defaults to all cores; the answer is the same
    for any number. Returns a dict: ``placeable`` (True), ``probability``
    (0 when no shot was found), ``aim`` (phi, theta, speed, a, b) of the
    best shot, its ``kind``, ``shots`` (candidates found), ``plays`` and
    ``simulations``. Raises ValueError naming a bad ball, pocket, level or
    position, a game without pockets, and a ``cue`` where the cue ball
    cannot lie (on or against a ball, off the playing surface), with the
    rules' reason.
    """
    pos, _, ball, pocket, level, samples, candidates, seed, threads = _args(
        position, ball, pocket, level, samples, candidates, seed, threads)
    x, y = _cue(cue)
    c = _core.pot_chance(pos, x, y, ball, pocket, level, samples, candidates, seed, threads)
    if not c["placeable"]:
        raise ValueError(f"the cue ball cannot be placed at ({x:g}, {y:g}): {c['unplaceable']}")
    del c["unplaceable"]
    return c


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
    data = _core.pot_map(pos, ball, pocket_i, level, xs.tolist(), ys.tolist(), samples,
                         candidates, seed, threads)
    return PotMap(data, xs, ys, pos, ball, pocket_i, level, samples, seed)


class PotMap:
    """A pot map (breakshot.pot_map): arrays over the grid, row j for ys[j]
    and column i for xs[i]. No array holds NaN.

    ``probability`` (ny, nx) numpy masked array
        share of the measuring plays that potted the ball in the pocket
        (as the game's ruling counts a pot); masked where the cue ball
        cannot be placed (on or against a ball, or off the playing
        surface: ``valid`` False), 0 where the level found no shot.
        ``probability.mean()`` is over the cells that are not masked;
        ``probability.filled(0.0)`` a plain array.
    ``aims`` (ny, nx, 5) numpy masked array
        the best shot's phi, theta (degrees), speed (m/s), a, b (fractions
        of the radius); masked where there is none (the cue ball cannot be
        placed, or no shot was found).
    ``valid`` (ny, nx) bool
        the cue ball can be placed there.
    ``shots``, ``plays`` (ny, nx) int
        candidate shots found; measuring plays counted.
    ``kinds``
        nested list (ny by nx) of the best shot's kind ('direct', 'bank',
        'kick', 'combination', 'jump') or None.
    ``xs`` (nx,), ``ys`` (ny,)
        the grid, metres.

    Also ``ball``, ``pocket`` (index), ``pocket_name``, ``level``,
    ``samples`` (0: the level's own), ``seed``, ``simulations`` (total
    noisy plays run), ``position`` (the game position used) and ``table``
    (the table's outline and pockets), for breakshot.plot.pot_map.
    """

    def __init__(self, data, xs, ys, position, ball, pocket, level, samples, seed):
        self.valid = np.asarray(data["valid"], dtype=bool)
        self.shots = data["shots"]
        self.plays = data["plays"]
        self.probability = np.ma.MaskedArray(np.asarray(data["probability"], dtype=float),
                                             mask=~self.valid, fill_value=0.0)
        aimed = self.valid & (np.asarray(self.shots) > 0)
        aims = np.asarray(data["aims"], dtype=float)
        self.aims = np.ma.MaskedArray(aims, mask=np.repeat(~aimed[..., None], 5, axis=-1),
                                      fill_value=0.0)
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
        placed. Raises ValueError when there is none."""
        if not self.valid.any():
            raise ValueError("the cue ball can be placed in no cell of the map")
        return float(self.probability.data[self.valid].mean())

    def __repr__(self) -> str:
        ny, nx = self.shape
        mean = f"{self.mean():.3f}" if self.valid.any() else "none"
        return (f"<breakshot.PotMap ball={self.ball} pocket={self.pocket_name} "
                f"level={self.level} grid={nx}x{ny} valid={int(self.valid.sum())} "
                f"mean={mean}>")
