"""Game positions given from Python: the forms that breakshot.plot.table,
breakshot.pot_map and breakshot.pot_chance accept (docs/python.md, "Game
positions").

A position is

* a game (a breakshot.Game): its state as it is, with its table and its
  physics;
* a state (a breakshot.State, or a dict in the records' JSON form of a
  state, with ``phase``): that state as it is, on the game's own table
  (a dict may add ``table`` and ``physics``);
* a dict ``{"game": "nine_ball", "table": "9ft", "balls": BALLS,
  "player": 0, "groups": ["solids", "stripes"]}`` where only ``balls`` is
  required and BALLS is a mapping ``{number: (x, y)}``, a list of
  ``(id, x, y)`` or a list of ``{"id": id, "position": [x, y]}``; in
  snooker also ``"score": [a, b]`` and ``"colour_on": True``;
* a dict ``{"game": ..., "positions": (n, 2), "on_table": (n,)}`` with an
  entry per ball number (a game state's arrays), with the same keys;
* a list of ``(id, x, y)`` (a 9 ft table);
* anything with a ``state`` attribute holding one of the above.

Ids are ball numbers (0 is the cue ball) as ints or digit strings, or
"cue". Without ``game`` the position is 9-ball when every number is at most
9, else 8-ball. A dict's balls are put on the game's start state (whose
turn, the groups and snooker's score as given), as after the break; a
state is taken whole.
"""

from __future__ import annotations

import json
from collections.abc import Mapping

import numpy as np

# Balls by game, the cue ball included.
GAMES = {"eight_ball": 16, "nine_ball": 10, "ten_ball": 11, "snooker": 22, "three_cushion": 3}
# The table a game is played on when none is named (a position, Game,
# match, the distributed functions): the package's one map of it.
_TABLES = {"snooker": "12ft", "three_cushion": "10ft"}


def default_table(game) -> str:
    """The table ``game`` is played on when none is named: snooker's 12 ft
    table, three-cushion's 10 ft carom table, else the 9 ft pool table (as
    ``breakshot match``)."""
    return _TABLES.get(game, "9ft")
# The keys a records'-form state has besides its own: where it is played.
_PLACE_KEYS = ("table", "table_size", "physics")


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
    or a breakshot.Game), with a game's table and physics added."""
    place = {}
    config = getattr(obj, "config", None)
    if isinstance(config, Mapping) and "table_size" in config:  # a breakshot.Game
        place["table_size"] = config["table_size"]
        physics = getattr(obj, "physics", None)
        if isinstance(physics, Mapping):
            place["physics"] = dict(physics)
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
            f"a state, a list of (id, x, y), or a game with a .state; not {type(obj).__name__}")
    if "position" in obj and "positions" not in obj and "phase" not in obj:
        obj = dict(obj, positions=obj["position"])
    if place and not any(k in obj for k in ("table", "table_size")):
        obj = dict(obj, **place)
    return obj


def _table(d, game) -> str:
    table = d.get("table", d.get("table_size", default_table(game)))
    if isinstance(table, Mapping):  # a scenario's {"shape": "pool", "size": ...}
        table = table.get("size", default_table(game))
    return str(table)


def _physics_text(d):
    physics = d.get("physics")
    if physics is None:
        return None
    if not isinstance(physics, Mapping):
        raise ValueError(f"physics: expected a dict or None, not {type(physics).__name__}")
    return json.dumps(dict(physics), allow_nan=False)


def _known(game) -> str:
    if game not in GAMES:
        raise ValueError(f"unknown game {game!r} (known: {', '.join(GAMES)})")
    return str(game)


def _whole_state(d) -> dict:
    """A position from the records' form of a state: the state as it is."""
    game = _known(d.get("game"))
    state = {k: v for k, v in d.items() if k not in _PLACE_KEYS}
    positions = np.asarray(state.get("position", ()), dtype=float).reshape(-1, 2)
    on_table = np.asarray(state.get("on_table", ()), dtype=bool).ravel()
    if positions.shape[0] != GAMES[game] or on_table.shape != (GAMES[game],):
        raise ValueError(f"{game} has {GAMES[game]} balls; the state's position has "
                         f"{positions.shape[0]} and its on_table {on_table.size}")
    try:
        text = json.dumps(state, allow_nan=False)
    except (TypeError, ValueError) as e:
        raise ValueError(f"state: {e}") from None
    return {
        "game": game,
        "table_size": _table(d, game),
        "positions": positions,
        "on_table": on_table,
        "player": int(state.get("player", 0)),
        "groups": [str(g) for g in state.get("group", ())],
        "score": None,
        "colour_on": None,
        "state": text,
        "physics": _physics_text(d),
    }


def game_position(obj) -> dict:
    """Normalises a position: game, table_size, positions (n, 2) and
    on_table (n,) by ball number, player, groups, snooker's score and
    colour_on, and physics (JSON text or None); ``state`` is the records'
    JSON text of a game's own state, or None for balls to be put on the
    game's start state."""
    d = _state_dict(obj)
    if "phase" in d:
        return _whole_state(d)
    game = d.get("game")
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
        n = GAMES[_known(game)]
        positions = np.zeros((n, 2))
        on_table = np.zeros(n, dtype=bool)
        for num, xy in balls.items():
            if not 0 <= num < n:
                raise ValueError(f"ball {num} is not a ball of {game} (0 to {n - 1})")
            positions[num] = xy
            on_table[num] = True
    else:
        raise ValueError("a game position needs 'balls', 'positions' or a state's 'phase'")
    game = _known(game)
    if len(positions) != GAMES[game]:
        raise ValueError(f"{game} has {GAMES[game]} balls; positions has {len(positions)}")
    groups = d.get("groups") or d.get("group") or []
    groups = [] if all(g in (None, "none") for g in groups) else [str(g or "none") for g in groups]
    score = d.get("score")
    if score is not None:
        if (isinstance(score, (str, bytes)) or len(score) != 2 or
                not all(isinstance(v, (int, np.integer)) and not isinstance(v, bool)
                        for v in score)):
            raise ValueError(f"score must be two whole numbers (players 0 and 1), not {score!r}")
        score = [int(v) for v in score]
    colour_on = d.get("colour_on")
    if colour_on is not None and not isinstance(colour_on, (bool, np.bool_)):
        raise ValueError(f"colour_on must be True or False, not {colour_on!r}")
    player = d.get("player", 0)
    if isinstance(player, bool) or player not in (0, 1):
        raise ValueError(f"player must be 0 or 1, not {player!r}")
    return {
        "game": game,
        "table_size": _table(d, game),
        "positions": positions,
        "on_table": on_table,
        "player": int(player),
        "groups": groups,
        "score": score,
        "colour_on": None if colour_on is None else bool(colour_on),
        "state": None,
        "physics": _physics_text(d),
    }


def plain(position: dict) -> dict:
    """A normalised position (game_position's) as plain Python values that
    game_position reads back to the same position (for cluster workers)."""
    if position["state"] is not None:
        d = json.loads(position["state"])
    else:
        d = {"game": position["game"], "positions": position["positions"].tolist(),
             "on_table": position["on_table"].tolist(), "player": position["player"],
             "groups": list(position["groups"]), "score": position["score"],
             "colour_on": position["colour_on"]}
    d["table_size"] = position["table_size"]
    if position["physics"] is not None:
        d["physics"] = json.loads(position["physics"])
    return d
