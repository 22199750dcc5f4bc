"""Game positions given from Python: the forms that breakshot.plot.table,
breakshot.pot_map and breakshot.pot_chance accept (docs/python.md, "Game
positions").

A position is

* a dict ``{"game": "nine_ball", "table": "9ft", "balls": BALLS,
  "player": 0, "groups": ["solids", "stripes"]}`` where only ``balls`` is
  required and BALLS is a mapping ``{number: (x, y)}``, a list of
  ``(id, x, y)`` or a list of ``{"id": id, "position": [x, y]}``;
* a dict ``{"game": ..., "positions": (n, 2), "on_table": (n,)}`` with an
  entry per ball number (a game state's arrays);
* a list of ``(id, x, y)`` (a 9 ft table);
* anything with a ``state`` attribute holding one of the above (a game).

Ids are ball numbers (0 is the cue ball) as ints or digit strings, or
"cue". Without ``game`` the position is 9-ball when every number is at most
9, else 8-ball.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

GAMES = {"eight_ball": 16, "nine_ball": 10}


def ball_number(ball_id) -> int:
    """A ball number from an id: an int, a digit string or "cue" (0)."""
    if isinstance(ball_id, (bool, np.bool_)):
        raise ValueError(f"a ball id is a number or 'cue', not {ball_id!r}")
    if isinstance(ball_id, (int, np.integer)):
        return int(ball_id)
    if isinstance(ball_id, str):
        if ball_id == "cue":
            return 0
        if ball_id.isdigit():
            return int(ball_id)
    raise ValueError(f"a ball id is a number or 'cue', not {ball_id!r}")


def _balls(balls) -> dict:
    """{number: (x, y)} from any of the BALLS forms."""
    out = {}
    if isinstance(balls, Mapping):
        items = list(balls.items())
    else:
        items = []
        for entry in balls:
            if isinstance(entry, Mapping):
                if "id" not in entry or "position" not in entry:
                    raise ValueError(f"a ball dict needs 'id' and 'position': {entry!r}")
                items.append((entry["id"], entry["position"]))
            else:
                entry = tuple(entry)
                if len(entry) != 3:
                    raise ValueError(f"a ball is (id, x, y), not {entry!r}")
                items.append((entry[0], entry[1:]))
    for ball_id, xy in items:
        n = ball_number(ball_id)
        x, y = (float(v) for v in xy)
        if n in out:
            raise ValueError(f"ball {n} is given twice")
        out[n] = (x, y)
    return out


def _state_dict(obj):
    """The mapping behind obj (a dict, a list of balls, a breakshot.State
    or a breakshot.Game)."""
    table_size = None
    config = getattr(obj, "config", None)
    if isinstance(config, Mapping) and "table_size" in config:  # a breakshot.Game
        table_size = config["table_size"]
    seen = 0
    while not isinstance(obj, (Mapping, list, tuple)) and hasattr(obj, "state") and seen < 4:
        obj = obj.state
        obj = obj() if callable(obj) else obj
        seen += 1
    if hasattr(obj, "to_dict") and not isinstance(obj, Mapping):
        obj = obj.to_dict()
    if isinstance(obj, (list, tuple)):
        return {"balls": obj}
    if not isinstance(obj, Mapping):
        raise TypeError(
            "a game position is a dict with 'balls' (or 'positions' and 'on_table'), "
            f"a list of (id, x, y), or a game with a .state; not {type(obj).__name__}")
    if "position" in obj and "positions" not in obj:  # the records' form of a state
        obj = dict(obj, positions=obj["position"])
    if table_size is not None and "table" not in obj and "table_size" not in obj:
        obj = dict(obj, table_size=table_size)
    return obj


def game_position(obj) -> dict:
    """Normalises a position: game, table_size, positions (n, 2) and
    on_table (n,) by ball number, player, groups."""
    d = _state_dict(obj)
    game = d.get("game")
    table = d.get("table", d.get("table_size", "9ft"))
    if isinstance(table, Mapping):  # a scenario's {"shape": "pool", "size": ...}
        table = table.get("size", "9ft")
    if "positions" in d:
        positions = np.asarray(d["positions"], dtype=float)
        if positions.ndim != 2 or positions.shape[1] != 2:
            raise ValueError(f"positions must have the shape (n, 2), not {positions.shape}")
        on_table = np.asarray(d.get("on_table", np.ones(len(positions))), dtype=bool)
        if on_table.shape != (len(positions),):
            raise ValueError(f"on_table must have the shape ({len(positions)},)")
        if game is None:
            game = "nine_ball" if len(positions) <= 10 else "eight_ball"
    elif "balls" in d:
        balls = _balls(d["balls"])
        if game is None:
            game = "nine_ball" if max(balls, default=0) <= 9 else "eight_ball"
        if game not in GAMES:
            raise ValueError(f"unknown game {game!r} (known: {', '.join(GAMES)})")
        n = GAMES[game]
        positions = np.zeros((n, 2))
        on_table = np.zeros(n, dtype=bool)
        for num, xy in balls.items():
            if not 0 <= num < n:
                raise ValueError(f"ball {num} is not a ball of {game} (0 to {n - 1})")
            positions[num] = xy
            on_table[num] = True
    else:
        raise ValueError("a game position needs 'balls' or 'positions'")
    if game not in GAMES:
        raise ValueError(f"unknown game {game!r} (known: {', '.join(GAMES)})")
    if len(positions) != GAMES[game]:
        raise ValueError(f"{game} has {GAMES[game]} balls; positions has {len(positions)}")
    groups = d.get("groups") or d.get("group") or []
    groups = [] if all(g in (None, "none") for g in groups) else [str(g or "none") for g in groups]
    return {
        "game": str(game),
        "table_size": str(table),
        "positions": positions,
        "on_table": on_table,
        "player": int(d.get("player", 0)),
        "groups": groups,
    }
