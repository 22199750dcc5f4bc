"""breakshot on a Dask cluster: matches, ladders, shot maps and sweeps spread
over the workers of a ``dask.distributed.Client``, with results identical to
one machine (docs/distributed.md).

    from dask.distributed import Client
    import breakshot.distributed as bd

    client = Client("tcp://scheduler:8786")          # or bd.local_client()
    summary = bd.match(client, "nine_ball", ("club", "expert"), games=200, seed=1)

How determinism is kept: every unit of work is a pure function of its
arguments. Game g of a match has the seed ``mix_seed(seed, g)`` and is broken
by seat ``g % 2``, however the games are split into tasks; a chunk's summary
holds only counts, so the chunk summaries add up (in any order) to the one
``breakshot match`` prints. Cell k of a shot map is ``pot_chance`` with the
seed ``mix_seed(seed, k)`` on one thread. A task that is lost with its
worker runs again elsewhere and gives the same bytes.

Every task runs players with one thread (``threads=1``): a worker process
already has a core of its own. Before work is sent, every worker's
breakshot version and determinism hash are compared with the client's
(check_workers); a worker that differs is refused, and a task that lands on
a differing worker (one that joined later) fails saying so.
"""

from __future__ import annotations

import json
import math
import os
import sys
from pathlib import Path
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from .errors import ScenarioError
from .game import _default_table, _pair, _physics, mix_seed
from .result import Result

__all__ = [
    "WorkerMismatch", "MatchError", "local_client", "check_workers", "identity", "match",
    "match_json", "ladder", "shot_map", "sweep",
]


class WorkerMismatch(RuntimeError):
    """A worker whose breakshot differs from the client's (another version,
    or a build whose results differ: its determinism hash)."""


class MatchError(RuntimeError):
    """A game of a distributed match failed. ``game`` is its index and
    ``seed`` its seed; ``command`` reproduces that game alone."""

    def __init__(self, message: str, game: Optional[int] = None,
                 seed: Optional[int] = None, command: Optional[str] = None):
        super().__init__(message)
        self.game = game
        self.seed = seed
        self.command = command

    def __reduce__(self):
        return (type(self), (str(self), self.game, self.seed, self.command))


# --- identity of a process's breakshot ------------------------------------

_identity_cache: Optional[Tuple[str, str]] = None


def identity() -> Tuple[str, str]:
    """This process's breakshot: (version, determinism hash). The hash is
    computed once per process (``_core.determinism_hash``: a pool break and
    a short match, digested)."""
    global _identity_cache
    if _identity_cache is None:
        _identity_cache = (_core.version, _core.determinism_hash())
    return _identity_cache


def _verify(expected: Tuple[str, str]) -> None:
    """Run at the start of every task: refuses to work on a worker whose
    breakshot differs from the client's."""
    got = identity()
    if tuple(got) != tuple(expected):
        raise WorkerMismatch(
            f"this worker's breakshot {got[0]} (determinism hash {got[1]}) differs from the "
            f"client's {expected[0]} ({expected[1]}); install the client's build on it")


def check_workers(client) -> Dict[str, Tuple[str, str]]:
    """Asks every worker for its breakshot version and determinism hash and
    raises WorkerMismatch naming the workers that differ from this process.
    Returns {worker address: (version, hash)}."""
    expected = identity()
    if not client.scheduler_info().get("workers"):
        client.wait_for_workers(1)
    found = client.run(identity)
    bad = {addr: tuple(v) for addr, v in found.items() if tuple(v) != expected}
    if bad:
        listing = "; ".join(f"{a}: breakshot {v[0]}, hash {v[1]}" for a, v in sorted(bad.items()))
        raise WorkerMismatch(
            f"{len(bad)} of {len(found)} workers differ from the client (breakshot "
            f"{expected[0]}, hash {expected[1]}): {listing}")
    return {a: tuple(v) for a, v in found.items()}


def local_client(workers: Optional[int] = None, **kwargs):
    """A Client on a new local cluster: ``workers`` worker processes (default
    this machine's cores) of one thread each, on 127.0.0.1, with no
    dashboard unless ``dashboard_address`` is given. Close it (or use it in
    a ``with`` block) when done; closing the client closes the cluster."""
    from dask.distributed import Client

    n = (os.cpu_count() or 1) if workers is None else int(workers)
    if n < 1:
        raise ValueError(f"workers must be at least 1, not {workers!r}")
    options = dict(n_workers=n, threads_per_worker=1, processes=True, host="127.0.0.1",
                   dashboard_address=None)
    options.update(kwargs)
    # Given the cluster's options, the Client starts the cluster and owns it.
    return Client(set_as_default=False, **options)


# --- progress ---------------------------------------------------------------

class _Progress:
    """A progress bar on standard error (tqdm when installed, else a plain
    counter line), or nothing."""

    def __init__(self, total: int, what: str, enabled: Optional[bool]):
        if enabled is None:
            enabled = sys.stderr.isatty()
        self.bar = None
        self.plain = False
        self.done = 0
        self.total = total
        self.what = what
        if not enabled:
            return
        try:
            from tqdm import tqdm
            self.bar = tqdm(total=total, unit=what, file=sys.stderr, dynamic_ncols=True)
        except ImportError:
            self.plain = True

    def update(self, n: int) -> None:
        self.done += n
        if self.bar is not None:
            self.bar.update(n)
        elif self.plain:
            sys.stderr.write(f"\r{self.done}/{self.total} {self.what}")
            sys.stderr.flush()

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
        elif self.plain:
            sys.stderr.write("\n")


# --- matches ----------------------------------------------------------------

def _check_int(value, name: str, low: int, high: Optional[int] = None) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise ValueError(f"{name}: expected a whole number, not {value!r}")
    value = int(value)
    if value < low or (high is not None and value > high):
        bound = f">= {low}" if high is None else f"in [{low}, {high}]"
        raise ValueError(f"{name}: expected a whole number {bound}, not {value}")
    return value


def _match_chunk(expected, game, players, seed, noise, table, first, count, records,
                 physics=None):
    """The task of a match: games first .. first + count - 1. ``physics`` is
    the physics JSON text of the match (None: the default)."""
    _verify(expected)
    try:
        summary, recs = _core.match_chunk(game, list(players), seed, noise, table, first, count,
                                          1, records, physics)
    except RuntimeError as e:
        raise MatchError(str(e)) from None
    return first, count, summary, recs


def _check_names(game, names, table) -> None:
    """Refuses an unknown game, player or table before any task is sent (a
    bad noise spec is refused by the first task, as ValueError)."""
    if game not in _core.game_names():
        raise ValueError(f"game: unknown game {game!r} (known: {', '.join(_core.game_names())})")
    for name in names:
        why = _core.check_player(name, game) if isinstance(name, str) else "expected a name"
        if why is not None:
            raise ValueError(f"players: {why}")
    own = _default_table(game)
    if own != "9ft":
        # snooker and three-cushion have one table each
        if table != own:
            raise ValueError(f"table: unknown table size {table!r} ({game}: {own})")
    else:
        _core.pool_table(table)  # ValueError naming an unknown table size


def _number(v) -> str:
    """A number as the command line takes it back exactly."""
    return repr(float(v)) if isinstance(v, float) else str(v)


def _physics_flags(physics) -> str:
    """``breakshot match``'s physics options for a physics argument (None,
    a preset's name or a dict, possibly partial: the options it gives)."""
    if physics is None:
        return ""
    if isinstance(physics, str):
        return f" --physics {physics}"
    flags = []
    if "cushion_model" in physics:
        flags.append(f"--cushion-model {physics['cushion_model']}")
    if "ball_ball_model" in physics:
        flags.append(f"--ball-ball-model {physics['ball_ball_model']}")
    if "ball_ball_friction" in physics:
        f = physics["ball_ball_friction"]
        spec = (",".join(_number(f[k]) for k in "abc") if isinstance(f, dict) else _number(f))
        flags.append(f"--ball-ball-friction {spec}")
    if "airborne" in physics:
        flags.append(f"--airborne {'on' if physics['airborne'] else 'off'}")
    if "spinning_friction" in physics:
        flags.append(f"--spinning-friction {_number(physics['spinning_friction'])}")
    return "".join(" " + f for f in flags)


def _reproduce(game, players, seed, noise, table, g, physics=None) -> str:
    return (f"breakshot match --game {game} --players {players[0]},{players[1]} --games 1 "
            f"--first-game {g} --seed {seed} --noise {noise} --table {table}"
            f"{_physics_flags(physics)}")


def _as_match_error(e: BaseException, args) -> MatchError:
    """A task's failure as a MatchError that names the game and how to
    reproduce it (the C++ message starts with "game G (seed S): "), with
    the match's physics options."""
    game, players, seed, noise, table, physics = args
    text = str(e)
    g = s = None
    if text.startswith("game "):
        head = text.split(":", 1)[0]  # "game G (seed S)"
        try:
            g = int(head.split()[1])
            s = int(head.split("seed ")[1].rstrip(")"))
        except (IndexError, ValueError):
            g = s = None
    command = None if g is None else _reproduce(game, players, seed, noise, table, g, physics)
    message = text if command is None else f"{text}; reproduce it alone with: {command}"
    return MatchError(message, g, s, command)


def _cancel_pending(client, futures) -> None:
    """Cancels the tasks still to run (after a failure or an interrupt), in
    one call; finished ones are left alone."""
    pending = [f for f in futures if not f.done()]
    if pending:
        client.cancel(pending)


def _chunk_size(games: int, workers: int, chunk: Optional[int]) -> int:
    if chunk is not None:
        return _check_int(chunk, "chunk", 1)
    # About four tasks a worker (so that a slow or lost task is a small part
    # of the run), at most 50 games a task (so that a chunk's records are
    # little to hold).
    return max(1, min(50, math.ceil(games / (4 * max(workers, 1)))))


def _workers(client) -> int:
    return max(1, len(client.scheduler_info().get("workers", {})))


def _submit_match(client, expected, game, names, seed, noise, table, games, first_game, size,
                  records: bool, tag: str, physics=None):
    futures = []
    for first in range(first_game, first_game + games, size):
        count = min(size, first_game + games - first)
        futures.append(client.submit(
            _match_chunk, expected, game, names, seed, noise, table, first, count, records,
            physics, key=f"breakshot-match-{tag}-{first}-{count}", pure=False, retries=0))
    return futures


def match_json(client, game: str, players: Sequence[str], games: int, seed: int = 0,
               noise: str = "none", table: Optional[str] = None,
               records: Union[None, str, os.PathLike] = None, chunk: Optional[int] = None,
               first_game: int = 0, progress: Optional[bool] = None,
               physics: Union[None, str, dict] = None) -> str:
    """The summary text ``breakshot match`` prints for the same arguments,
    byte for byte, with the games played on the cluster.

    The games are split into tasks of ``chunk`` games (default: about four
    tasks a worker, at most 50 games a task); each task returns its chunk's
    summary (and, with ``records``, its games' records, which the client
    writes to ``records``/game-NNNN.json as ``breakshot match --records``
    does, as each task ends). ``first_game`` plays games first_game ..
    first_game + games - 1 (``breakshot match --first-game``). ``progress``
    shows a bar on standard error (default: when it is a terminal). A game
    that fails raises MatchError naming the game, its seed and the command
    that reproduces it alone. ``physics`` chooses the games' physics as
    for breakshot.match (a dict, breakshot.physics_of).
    """
    from dask.distributed import as_completed

    physics_text = _physics(physics)
    names = _pair(players, "players")
    games = _check_int(games, "games", 1)
    seed = _check_int(seed, "seed", 0, 2**64 - 1)
    first_game = _check_int(first_game, "first_game", 0)
    if not all(isinstance(n, str) for n in names):
        raise ValueError("players: expected two player names")
    if table is None:
        table = _default_table(game)  # the game's table, as breakshot match
    _check_names(game, names, table)
    check_workers(client)
    expected = identity()
    size = _chunk_size(games, _workers(client), chunk)
    folder = None
    if records is not None:
        folder = Path(records)
        folder.mkdir(parents=True, exist_ok=True)
    tag = f"{os.getpid()}-{id(names)}-{seed}"
    futures = _submit_match(client, expected, game, names, seed, noise, table, games,
                            first_game, size, folder is not None, tag, physics_text)
    bar = _Progress(games, "games", progress)
    summaries: Dict[int, str] = {}
    try:
        for future in as_completed(futures, loop=client.loop):
            try:
                first, count, summary, recs = future.result()
            except (MatchError, RuntimeError) as e:
                if isinstance(e, WorkerMismatch):
                    raise
                raise _as_match_error(e, (game, names, seed, noise, table, physics)) from None
            summaries[first] = summary
            for g, text in recs:
                (folder / _core.record_file_name(g)).write_text(text)
            future.release()
            bar.update(count)
    finally:
        bar.close()
        _cancel_pending(client, futures)
    return _core.add_match_summaries([summaries[k] for k in sorted(summaries)])


def match(client, game: str, players: Sequence[str], games: int, seed: int = 0,
          noise: str = "none", table: Optional[str] = None,
          records: Union[None, str, os.PathLike] = None, chunk: Optional[int] = None,
          first_game: int = 0, progress: Optional[bool] = None,
          physics: Union[None, str, dict] = None) -> dict:
    """A match on the cluster: the summary of ``breakshot match`` with the
    same arguments, parsed (field for field what ``breakshot.match`` gives
    on one machine). See match_json for the arguments."""
    return json.loads(match_json(client, game, players, games, seed, noise, table, records,
                                 chunk, first_game, progress, physics))


# --- ladders ----------------------------------------------------------------

def ladder(client, game: str, levels: Sequence[str], games: int, seed: int = 0,
           noise: str = "none", table: Optional[str] = None, chunk: Optional[int] = None,
           progress: Optional[bool] = None,
           physics: Union[None, str, dict] = None) -> dict:
    """Every adjacent pair of ``levels`` (levels[i] against levels[i + 1])
    plays a match of ``games`` games with ``seed``; all pairs' games run on
    the cluster at once. ``table`` (None: the game's, as match) and
    ``physics`` (as match) are every pair's. Returns one table:
    ``{"game", "table", "games", "seed", "noise", "rows": [{"players": [a,
    b], "won": [wa, wb], "draws", "summary": the pair's match summary}]}``;
    each summary is what ``breakshot match`` prints for that pair (with the
    physics options, shown in it when not the default)."""
    from dask.distributed import as_completed

    physics_text = _physics(physics)
    if table is None:
        table = _default_table(game)
    levels = list(levels)
    if len(levels) < 2 or not all(isinstance(n, str) for n in levels):
        raise ValueError("levels: expected at least two player names")
    games = _check_int(games, "games", 1)
    seed = _check_int(seed, "seed", 0, 2**64 - 1)
    pairs = [(levels[i], levels[i + 1]) for i in range(len(levels) - 1)]
    for pair in pairs:
        _check_names(game, pair, table)
    check_workers(client)
    expected = identity()
    size = _chunk_size(games * len(pairs), _workers(client), chunk)
    owner: Dict[Any, int] = {}
    futures = []
    for p, pair in enumerate(pairs):
        tag = f"ladder-{os.getpid()}-{id(levels)}-{p}"
        for f in _submit_match(client, expected, game, pair, seed, noise, table, games, 0,
                               size, False, tag, physics_text):
            owner[f.key] = p
            futures.append(f)
    parts: List[Dict[int, str]] = [{} for _ in pairs]
    bar = _Progress(games * len(pairs), "games", progress)
    try:
        for future in as_completed(futures, loop=client.loop):
            p = owner[future.key]
            try:
                first, count, summary, _ = future.result()
            except RuntimeError as e:
                if isinstance(e, WorkerMismatch):
                    raise
                raise _as_match_error(e, (game, pairs[p], seed, noise, table, physics)) from None
            parts[p][first] = summary
            future.release()
            bar.update(count)
    finally:
        bar.close()
        _cancel_pending(client, futures)
    rows = []
    for pair, part in zip(pairs, parts):
        summary = json.loads(_core.add_match_summaries([part[k] for k in sorted(part)]))
        rows.append({
            "players": list(pair),
            "won": [summary["players"][0]["games_won"], summary["players"][1]["games_won"]],
            "draws": summary["draws"],
            "summary": summary,
        })
    return {"game": game, "table": table, "games": games, "seed": seed, "noise": noise,
            "rows": rows}


# --- shot maps --------------------------------------------------------------

def _pot_cells(expected, position, ball, pocket, level, points, samples, candidates, seed):
    """The task of a shot map: pot_chance at each (k, x, y) of ``points``,
    cell k with the seed mix_seed(seed, k) on one thread (as pot_map does);
    a cell where the cue ball cannot be placed has ``placeable`` False."""
    _verify(expected)
    from ._position import game_position

    pos = game_position(position)
    return [(k, _core.pot_chance(pos, x, y, ball, pocket, level, samples, candidates,
                                 _core.mix_seed(seed, k), 1))
            for k, x, y in points]


def shot_map(client, state, ball, pocket, level: str = "champion", *, xs=None, ys=None,
             nx: int = 40, ny: int = 20, samples: Optional[int] = None,
             candidates: Optional[int] = None, seed: int = 0, cells_per_task: Optional[int] = None,
             progress: Optional[bool] = None):
    """The pot map of ``breakshot.pot_map`` (the probability that ``level``
    pots ``ball`` in ``pocket`` from every cue-ball position of a grid, and
    its best aim at each) with the cells computed on the cluster. The
    arguments are pot_map's (``state`` is a game position: docs/python.md,
    "Game positions"); the returned breakshot.PotMap equals pot_map's with
    the same arguments, array for array, however the cells are split
    (``cells_per_task``, default: about eight tasks a worker)."""
    from dask.distributed import as_completed

    from .pot_maps import PotMap, _args, _grid
    from ._position import game_position, plain

    pos, table, ball_n, pocket_i, level, samples, candidates, seed, _ = _args(
        state, ball, pocket, level, samples, candidates, seed, None)
    if level not in _core.level_names():
        raise ValueError(f"level: unknown level {level!r} (known: "
                         f"{', '.join(_core.level_names())})")
    xs, ys = _grid(table, xs, ys, nx, ny)
    if xs.size == 0 or ys.size == 0:
        raise ValueError("the grid is empty (xs and ys need at least one point each)")
    if not (np.isfinite(xs).all() and np.isfinite(ys).all()):
        raise ValueError("the grid's coordinates must be finite")
    points = [(j * xs.size + i, float(xs[i]), float(ys[j]))
              for j in range(ys.size) for i in range(xs.size)]
    # The position as plain values that the workers read exactly as here.
    plain_pos = plain(pos)
    check_workers(client)
    expected = identity()
    per = (_check_int(cells_per_task, "cells_per_task", 1) if cells_per_task is not None
           else max(1, math.ceil(len(points) / (8 * _workers(client)))))
    futures = [client.submit(_pot_cells, expected, plain_pos, ball_n, pocket_i, level,
                             points[a:a + per], samples, candidates, seed, pure=False)
               for a in range(0, len(points), per)]
    cells: Dict[int, dict] = {}
    bar = _Progress(len(points), "cells", progress)
    try:
        for future in as_completed(futures, loop=client.loop):
            got = future.result()
            cells.update(got)
            future.release()
            bar.update(len(got))
    finally:
        bar.close()
        _cancel_pending(client, futures)
    shape = (ys.size, xs.size)
    order = [cells[k] for k in range(len(points))]
    data = {
        "probability": np.array([c["probability"] for c in order], dtype=float).reshape(shape),
        "aims": np.array([c["aim"] if c["placeable"] and c["shots"] > 0 else [0.0] * 5
                          for c in order], dtype=float).reshape(shape + (5,)),
        "valid": np.array([c["placeable"] for c in order], dtype=bool).reshape(shape),
        "shots": np.array([c["shots"] for c in order], dtype=np.int32).reshape(shape),
        "plays": np.array([c["plays"] for c in order], dtype=np.int32).reshape(shape),
        "kinds": [[order[j * xs.size + i]["kind"] if order[j * xs.size + i]["placeable"] and
                   order[j * xs.size + i]["shots"] > 0 else None for i in range(xs.size)]
                  for j in range(ys.size)],
        "simulations": int(sum(c["simulations"] for c in order)),
        "table": table,
        "ball_radius": _core.pot_table(pos)["ball_radius"],
    }
    return PotMap(data, xs, ys, game_position(plain_pos), ball_n, pocket_i, level, samples,
                  seed)


# --- sweeps -----------------------------------------------------------------

def _simulate_many(expected, texts: List[str]) -> List[str]:
    _verify(expected)
    return [_core.simulate_text(t) for t in texts]


def sweep(client, scenarios: Iterable, per_task: Optional[int] = None,
          progress: Optional[bool] = None) -> List[Result]:
    """Simulates every scenario (dicts, JSON text, paths or
    breakshot.Scenario... anything breakshot.simulate takes) on the cluster
    and returns their Results in the order given; each equals
    ``breakshot.simulate`` of that scenario. The scenarios are read and
    checked here first, so an invalid one raises ScenarioError with its
    index ("scenarios[3]." before the field's path) before any work is
    sent."""
    from dask.distributed import as_completed

    from ._input import scenario_text

    texts = []
    for i, s in enumerate(scenarios):
        text = scenario_text(s) if not isinstance(s, _core.Scenario) else None
        if text is None:
            raise TypeError(f"scenarios[{i}]: pass the scenario itself (dict, JSON text or "
                            "path), not a breakshot.Scenario, to send it to the workers")
        try:
            _core.Scenario(text)
        except ScenarioError as e:
            raise ScenarioError(f"scenarios[{i}].{e.path}" if e.path else f"scenarios[{i}]",
                                e.reason, e.unsupported) from None
        texts.append(text)
    if not texts:
        return []
    check_workers(client)
    expected = identity()
    per = (_check_int(per_task, "per_task", 1) if per_task is not None
           else max(1, math.ceil(len(texts) / (8 * _workers(client)))))
    futures = {client.submit(_simulate_many, expected, texts[a:a + per], pure=False): a
               for a in range(0, len(texts), per)}
    out: List[Optional[Result]] = [None] * len(texts)
    bar = _Progress(len(texts), "scenarios", progress)
    try:
        for future in as_completed(list(futures), loop=client.loop):
            a = futures[future]
            for i, text in enumerate(future.result()):
                out[a + i] = Result(text)
            future.release()
            bar.update(len(texts[a:a + per]))
    finally:
        bar.close()
        _cancel_pending(client, futures)
    return out  # type: ignore[return-value]


# --- the command ------------------------------------------------------------

def _pot_map_json(pm) -> dict:
    def plain(a):
        return [[None if isinstance(v, float) and math.isnan(v) else v for v in row]
                for row in np.asarray(a, dtype=float).tolist()]

    return {
        "ball": pm.ball, "pocket": pm.pocket_name, "level": pm.level, "seed": pm.seed,
        "samples": pm.samples, "xs": pm.xs.tolist(), "ys": pm.ys.tolist(),
        "probability": plain(pm.probability),
        "aims": [[None if np.isnan(c).any() else c.tolist() for c in row] for row in pm.aims],
        "kinds": pm.kinds, "valid": pm.valid.tolist(), "shots": pm.shots.tolist(),
        "plays": pm.plays.tolist(), "simulations": pm.simulations,
    }


def _physics_args(args) -> Union[None, str, dict]:
    """The physics options of `match` and `ladder` as the physics argument:
    None when none is given, the preset's name when only --physics is,
    else breakshot.physics_of's dict, each option given winning over the
    preset's value (as breakshot match)."""
    preset = getattr(args, "physics", None)
    airborne = getattr(args, "airborne", None)
    spin = getattr(args, "spinning_friction", None)
    if not (args.cushion_model or args.ball_ball_model or args.ball_ball_friction or airborne
            or spin):
        if preset is not None:
            from .game import PHYSICS_PRESETS

            if preset not in PHYSICS_PRESETS:
                raise ValueError(f"--physics: unknown physics preset {preset!r} "
                                 f"({' or '.join(PHYSICS_PRESETS)})")
        return preset
    from .game import PHYSICS_PRESETS, physics_of

    if preset is not None and preset not in PHYSICS_PRESETS:
        raise ValueError(f"--physics: unknown physics preset {preset!r} "
                         f"({' or '.join(PHYSICS_PRESETS)})")
    friction: Any = args.ball_ball_friction
    if friction is not None and friction not in ("tpa28", "tpb3"):
        parts = friction.split(",")
        try:
            values = [float(v) for v in parts]
        except ValueError:
            raise ValueError(f"--ball-ball-friction: expected tpa28, tpb3, A,B,C or MU, "
                             f"not {friction!r}") from None
        if len(values) == 3:
            friction = dict(zip("abc", values))
        elif len(values) == 1:
            friction = values[0]
        else:
            raise ValueError(f"--ball-ball-friction: expected tpa28, tpb3, A,B,C or MU, "
                             f"not {friction!r}")
    if airborne not in (None, "on", "off"):
        raise ValueError(f"--airborne: expected on or off, not {airborne!r}")
    spinning: Any = spin
    if spinning is not None and spinning not in ("measured", "legacy"):
        try:
            spinning = float(spinning)
        except ValueError:
            raise ValueError(f"--spinning-friction: expected measured, legacy or a number > 0, "
                             f"not {spin!r}") from None
        if not spinning > 0 or spinning == float("inf"):
            raise ValueError(f"--spinning-friction: expected measured, legacy or a number > 0, "
                             f"not {spin!r}")
    return physics_of(args.cushion_model, args.ball_ball_model, friction,
                      None if airborne is None else airborne == "on", spinning,
                      preset=preset or "default")


def _physics_options(p) -> None:
    """The physics options of ``breakshot match``, for match and ladder."""
    p.add_argument("--physics", help="as breakshot match --physics: a preset, default or "
                   "legacy; an option below given with it wins over the preset's value")
    p.add_argument("--cushion-model", help="as breakshot match --cushion-model")
    p.add_argument("--ball-ball-model", help="as breakshot match --ball-ball-model")
    p.add_argument("--ball-ball-friction",
                   help="as breakshot match --ball-ball-friction: tpb3, tpa28, A,B,C or MU")
    p.add_argument("--airborne", help="as breakshot match --airborne: on (default) or off")
    p.add_argument("--spinning-friction",
                   help="as breakshot match --spinning-friction: measured (default), legacy or MU")


def _client_for(args):
    if args.scheduler:
        from dask.distributed import Client

        return Client(args.scheduler, set_as_default=False)
    return local_client(args.workers)


def main(argv: Optional[Sequence[str]] = None) -> int:
    """``python -m breakshot.distributed match|ladder|shot-map ...``: the
    work of ``breakshot match``, ladder and shot_map on a Dask cluster
    (``--scheduler tcp://HOST:8786``) or, without it, on a local cluster of
    this machine's cores. ``match`` prints what ``breakshot match`` prints;
    ``ladder`` and ``shot-map`` print the JSON of the Python functions.
    Exit status: 0 done, 2 a bad argument, 1 anything else."""
    import argparse

    ap = argparse.ArgumentParser(prog="python -m breakshot.distributed",
                                 description="breakshot matches, ladders and shot maps on a "
                                             "Dask cluster (docs/distributed.md)")
    sub = ap.add_subparsers(dest="command", required=True)

    def common(p):
        p.add_argument("--scheduler", help="the scheduler's address, tcp://HOST:8786 "
                       "(default: start a local cluster)")
        p.add_argument("--workers", type=int, default=None,
                       help="worker processes of the local cluster (default: the cores)")
        p.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                       help="a progress bar on standard error (default: when a terminal)")

    m = sub.add_parser("match", help="a match, as breakshot match")
    m.add_argument("--game", required=True)
    m.add_argument("--players", required=True, help="A,B")
    m.add_argument("--games", type=int, required=True)
    m.add_argument("--seed", type=int, required=True)
    m.add_argument("--noise", required=True)
    m.add_argument("--table", default=None, help="the table size (default: the game's, 9ft, snooker's 12ft or three_cushion's 10ft)")
    m.add_argument("--records", help="write each game's record to DIR/game-NNNN.json")
    m.add_argument("--first-game", type=int, default=0)
    m.add_argument("--chunk", type=int, default=None, help="games per task")
    _physics_options(m)
    common(m)

    lad = sub.add_parser("ladder", help="every adjacent pair of levels")
    lad.add_argument("--game", required=True)
    lad.add_argument("--levels", required=True, help="A,B,C,... weakest first")
    lad.add_argument("--games", type=int, required=True)
    lad.add_argument("--seed", type=int, default=0)
    lad.add_argument("--noise", default="none")
    lad.add_argument("--table", default=None, help="the table size (default: the game's, 9ft, "
                     "snooker's 12ft or three_cushion's 10ft)")
    lad.add_argument("--chunk", type=int, default=None)
    _physics_options(lad)
    common(lad)

    sm = sub.add_parser("shot-map", help="a pot probability map over a grid")
    sm.add_argument("--position", required=True,
                    help="a JSON file with a game position (docs/python.md, Game positions)")
    sm.add_argument("--ball", required=True)
    sm.add_argument("--pocket", required=True, help="a pocket name or index")
    sm.add_argument("--level", default="champion")
    sm.add_argument("--nx", type=int, default=40)
    sm.add_argument("--ny", type=int, default=20)
    sm.add_argument("--samples", type=int, default=None)
    sm.add_argument("--seed", type=int, default=0)
    common(sm)

    args = ap.parse_args(argv)
    try:
        if args.command == "shot-map":
            with open(args.position, encoding="utf-8") as f:
                position = json.load(f)
            pocket = int(args.pocket) if args.pocket.lstrip("-").isdigit() else args.pocket
            ball = int(args.ball) if args.ball.isdigit() else args.ball
        else:
            physics = _physics_args(args)  # a bad option before any cluster starts
        with _client_for(args) as client:
            if args.command == "match":
                players = args.players.split(",")
                text = match_json(client, args.game, players, args.games, args.seed, args.noise,
                                  args.table, args.records, args.chunk, args.first_game,
                                  args.progress, physics)
                sys.stdout.write(text)
            elif args.command == "ladder":
                table = ladder(client, args.game, args.levels.split(","), args.games, args.seed,
                               args.noise, args.table, args.chunk, args.progress, physics)
                sys.stdout.write(json.dumps(table, indent=2) + "\n")
            else:
                pm = shot_map(client, position, ball, pocket, args.level, nx=args.nx,
                              ny=args.ny, samples=args.samples, seed=args.seed,
                              progress=args.progress)
                sys.stdout.write(json.dumps(_pot_map_json(pm)) + "\n")
    except (ValueError, TypeError) as e:
        print(f"breakshot.distributed: {e}", file=sys.stderr)
        return 2
    except (OSError, RuntimeError) as e:
        print(f"breakshot.distributed: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    # Run through the imported module, so that the tasks sent to the
    # workers are breakshot.distributed's functions (which the workers
    # import), not copies of this __main__'s.
    from breakshot.distributed import main as _main

    sys.exit(_main())
