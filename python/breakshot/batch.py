"""Batch shots: many cue strikes on pool scenarios, on every core, as numpy
arrays (breakshot.shots)."""

from __future__ import annotations

import operator
import os

import numpy as np

from . import _core

__all__ = ["shots", "ShotResults", "STRIKE_COLUMNS"]

#: The columns of a strikes array, in order.
STRIKE_COLUMNS = ("phi", "theta", "speed", "a", "b")


class ShotResults:
    """What a batch of k shots did, as numpy arrays (shot-major).

    Balls are in scenario order: ``ball_ids`` are the first scenario's ids
    (a list of scenarios keeps each one's own order).

    Attributes (k shots, n balls):

    - ``final_positions``: float64 (k, n, 2), every ball's centre at the end
      of the run, exactly ``simulate``'s final positions for that cue
      (a pocketed ball is where it entered the pocket, as in the result file).
    - ``pocketed``: bool (k, n); ``pockets``: int32 (k, n), the pocket's
      index in ``pocket_names``, -1 for a ball on the table.
    - ``cushions``: int32 (k, n), cushion contacts of every ball
      (``cushions[:, cue]`` for the cue ball).
    - ``first_hit``: int32 (k,), the index of the first ball the cue ball
      touches, -1 when it touches none.
    - ``cushions_before_hit``: int32 (k,), cushions the cue ball touches
      before its first ball contact (all of them when it touches none).
    - ``cue_index``: int32 (k,), the index of the ball ``"cue"``.
    - ``event_counts``: int64 (k,); ``final_times``: float64 (k,) seconds.
    - ``complete``: bool (k,), False where max_events stopped the run.
    - ``miscue``: bool (k,), the tip offset was beyond the miscue limit
      (nothing was played).
    - ``played``: float64 (k, 5), the strikes actually played (columns
      ``breakshot.STRIKE_COLUMNS``); equal to the strikes given unless ``noise``.
    """

    __slots__ = (
        "ball_ids", "pocket_names", "final_positions", "pocketed", "pockets",
        "cushions", "first_hit", "cushions_before_hit", "cue_index",
        "event_counts", "final_times", "complete", "miscue", "played",
        "noise", "seed",
    )

    def __init__(self, arrays: dict, noise: str, seed: int):
        self.noise = noise
        self.seed = seed
        for name, value in arrays.items():
            setattr(self, name, value)
        self.pocketed = self.pockets >= 0

    def __len__(self) -> int:
        return int(self.event_counts.shape[0])

    def __repr__(self) -> str:
        k, n = self.pockets.shape
        incomplete = int(np.count_nonzero(~self.complete))
        return (
            f"<breakshot.ShotResults shots={k} balls={n} "
            f"pocketed={int(np.count_nonzero(self.pocketed))} "
            f"hits={int(np.count_nonzero(self.first_hit >= 0))} "
            f"incomplete={incomplete} noise={self.noise}>"
        )


def _count(value, name: str, default: int) -> int:
    if value is None:
        return default
    try:
        n = operator.index(value)
    except TypeError:
        raise TypeError(f"{name}: expected an int, not {type(value).__name__}") from None
    return n


def shots(scenario, strikes, threads=None, noise=None, seed=0) -> ShotResults:
    """Play k cue strikes on a pool scenario and return a ShotResults.

    Arguments:

    - ``scenario``: a pool scenario with a ball ``"cue"`` and no ``cue`` of
      its own (balls at rest, or a ``rack``, which adds ``"cue"``), as a
      dict, JSON text, a path or a breakshot.Scenario, played with every
      strike; or a list (any sequence) of k such scenarios, one for each
      strike. Every scenario of a list has the same number of balls.
    - ``strikes``: an array-like of shape (k, 5), the columns ``phi, theta,
      speed, a, b`` as in the scenario format's ``cue`` (phi and theta in
      degrees, speed in m/s, a and b as fractions of the ball's radius),
      applied to the ball ``"cue"`` with the default cue stick. Checked as
      the scenario reader checks a ``cue``: speed finite and > 0, phi finite,
      theta in [0, 90), a and b finite.
    - ``threads``: worker threads; None or 0 uses every core. The arrays are
      the same for any value.
    - ``noise``: None (or ``"none"``) plays the strikes as given; otherwise a
      spec of ``breakshot match --noise`` (``"tournament"``, ``"2x"``,
      ``"custom:phi=..,speed=.."``): shot i is played perturbed by that model
      from the seed mixed with i (the match's perturbation), so the results
      depend on ``seed`` and not on ``threads``.
    - ``seed``: an int in [0, 2**64) for the noise.

    Each shot runs to the scenario's ``until`` exactly as ``simulate`` runs it
    with that ``cue`` (samples are not taken): ``final_positions`` are
    ``simulate``'s bit for bit. The GIL is released while the shots run.

    Raises ScenarioError (path, reason) for a scenario that cannot take the
    strikes (``"cue"``: it has its own; ``"balls"``: no ball ``"cue"``;
    ``"scenarios[3]...."`` in a list), ValueError naming the strike and the
    column for a bad strike (``"strikes[3].theta: ..."``) or the argument
    for the others.
    """
    one = isinstance(scenario, (_core.Scenario, dict, str, bytes, bytearray, os.PathLike))
    if not one:
        try:
            scenario = list(scenario)
        except TypeError:
            raise TypeError(
                "scenario: expected a scenario (breakshot.Scenario, dict, JSON text or "
                f"path) or a list of them, not {type(scenario).__name__}") from None
    try:
        arr = np.asarray(strikes, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise ValueError(f"strikes: not an array of numbers ({e})") from None
    if arr.ndim == 1 and arr.shape[0] == 5:
        raise ValueError("strikes: expected shape (k, 5), not (5,); one strike is "
                         "strikes[None, :] or [[phi, theta, speed, a, b]]")
    if arr.ndim != 2 or arr.shape[1] != 5:
        raise ValueError(f"strikes: expected shape (k, 5) (columns phi, theta, speed, a, b), "
                         f"not {arr.shape}")
    if not one and len(scenario) != arr.shape[0]:
        raise ValueError(f"scenario: {len(scenario)} scenarios for {arr.shape[0]} strikes "
                         "(give one scenario, or one per strike)")
    if not one and len(scenario) == 0:
        raise ValueError("scenario: an empty list (give one scenario, or one per strike)")
    n_threads = _count(threads, "threads", 0)
    if n_threads < 0:
        raise ValueError(f"threads: must be >= 0 (0 or None: every core), not {n_threads}")
    n_threads = min(n_threads, 1 << 16)
    n_seed = _count(seed, "seed", 0)
    if not 0 <= n_seed < 1 << 64:
        raise ValueError(f"seed: must be in [0, 2**64), not {n_seed}")
    spec = "none" if noise is None else noise
    if not isinstance(spec, str):
        raise TypeError(f"noise: expected a spec string such as 'tournament', "
                        f"not {type(noise).__name__}")
    arrays = _core.play_shots(scenario, one, arr, n_threads, spec, n_seed)
    return ShotResults(arrays, spec, n_seed)
