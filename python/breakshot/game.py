"""Games, computer players and matches (docs/python.md, "Games" and
"Players and matches").

A :class:`Game` is the C++ game session: the rules of one game on one
table, its seed streams and its record. Actions are the small classes
:class:`Shot`, :class:`PlaceCue` and :class:`Decide`, or dicts in the
records' JSON form of an action (``{"type": "shoot", "strike": {...},
...}``); a game played here is saved as a record that ``breakshot replay``
checks. :class:`Player` is a computer player by name; :func:`match` plays
a match exactly as ``breakshot match`` does.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from typing import Any, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._position import default_table

__all__ = [
    "Call", "Shot", "PlaceCue", "Decide", "Action", "action_from_dict",
    "State", "LegalActions", "Outcome", "Game", "Player",
    "games", "players", "match", "match_json", "mix_seed",
]


# ---------------------------------------------------------------------------
# Actions


@dataclass(frozen=True)
class Call:
    """A called shot: the object ``ball`` (its number) and the ``pocket``
    (an index into ``Game.table["pockets"]``)."""

    ball: int
    pocket: int

    def to_dict(self) -> dict:
        """The records' JSON form: ``{"ball": ..., "pocket": ...}``."""
        return {"ball": int(self.ball), "pocket": int(self.pocket)}


@dataclass(frozen=True)
class Shot:
    """A shot: the cue stick's strike on the cue ball, and what is declared.

    ``phi`` is the aim in degrees counter-clockwise from +x, ``theta`` the
    cue's elevation in degrees (0 <= theta < 90), ``speed`` the stick's
    speed in m/s (at most 20), ``a`` and ``b`` the tip offsets across
    (right english > 0) and up (follow > 0) as fractions of the ball's
    radius. ``call`` is None or a :class:`Call` (or a (ball, pocket)
    pair): required in 8-ball when the 8 is the target and in 10-ball on
    every shot but the break (unless ``safety``), informational in 9-ball.
    ``safety`` declares a safety (8-ball, 10-ball), ``push_out`` a push-out
    (9-ball, 10-ball). ``nominate`` (snooker only) is the ball number nominated as
    the ball on: required after a red (a colour, 16 yellow ... 21 black,
    see ``LegalActions.must_nominate``) and to take a free ball.
    ``cue_ball`` (three-cushion only) names the ball the cue strikes; None
    strikes the player's own (another ball is played, and is a foul). JSON
    type ``"shoot"``.
    """

    phi: float
    theta: float
    speed: float
    a: float = 0.0
    b: float = 0.0
    call: Optional[Call] = None
    safety: bool = False
    push_out: bool = False
    nominate: Optional[int] = None
    cue_ball: Optional[int] = None

    def __post_init__(self):
        if self.call is not None and not isinstance(self.call, Call):
            ball, pocket = self.call
            object.__setattr__(self, "call", Call(int(ball), int(pocket)))

    def to_dict(self) -> dict:
        """The records' JSON form of the action."""
        return {
            "type": "shoot",
            "strike": {"speed": float(self.speed), "phi": float(self.phi),
                       "theta": float(self.theta), "a": float(self.a), "b": float(self.b)},
            "call": None if self.call is None else self.call.to_dict(),
            "safety": bool(self.safety),
            "push_out": bool(self.push_out),
            # snooker only, and only when given (the records' form)
            **({} if self.nominate is None else {"nominate": int(self.nominate)}),
            # three-cushion only, and only when given
            **({} if self.cue_ball is None else {"cue_ball": int(self.cue_ball)}),
        }


@dataclass(frozen=True)
class PlaceCue:
    """Places the cue ball at (x, y) metres (ball in hand). JSON type
    ``"place_cue_ball"``."""

    x: float
    y: float

    def to_dict(self) -> dict:
        """The records' JSON form of the action."""
        return {"type": "place_cue_ball", "position": [float(self.x), float(self.y)]}


@dataclass(frozen=True)
class Decide:
    """A decision the rules offer (``LegalActions.choices``): ``"shoot"``,
    ``"pass_back"``, ``"accept_table"``, ``"rerack_and_break"``,
    ``"rerack_opponent_breaks"`` or ``"respot_eight"``; in snooker
    ``"play_on"``, ``"offender_again"``, ``"replace_balls"`` (after a
    miss) and ``"concede"``. JSON type ``"decide"``."""

    choice: str

    def to_dict(self) -> dict:
        """The records' JSON form of the action."""
        return {"type": "decide", "choice": str(self.choice)}


Action = Union[Shot, PlaceCue, Decide]


def action_from_dict(d: dict) -> Action:
    """The action object of a dict in the records' JSON form.

    Missing optional fields take their defaults (``call`` and ``nominate``
    None, ``safety`` and ``push_out`` False, ``theta``, ``a`` and ``b`` 0); unknown fields
    and wrong types raise ValueError naming them.
    """
    if not isinstance(d, dict):
        raise ValueError(f"action: expected a dict, not {type(d).__name__}")
    t = d.get("type")
    if t == "shoot":
        _only(d, {"type", "strike", "call", "safety", "push_out", "nominate", "cue_ball"})
        s = d.get("strike")
        if not isinstance(s, dict):
            raise ValueError("action.strike: expected a dict with speed, phi, theta, a, b")
        _only(s, {"speed", "phi", "theta", "a", "b"}, "action.strike")
        for key in ("speed", "phi"):
            if key not in s:
                raise ValueError(f"action.strike.{key}: missing required field")
        call = d.get("call")
        if isinstance(call, dict):
            _only(call, {"ball", "pocket"}, "action.call")
            call = Call(call["ball"], call["pocket"])
        return Shot(phi=s["phi"], theta=s.get("theta", 0.0), speed=s["speed"],
                    a=s.get("a", 0.0), b=s.get("b", 0.0), call=call,
                    safety=d.get("safety", False), push_out=d.get("push_out", False),
                    nominate=d.get("nominate"), cue_ball=d.get("cue_ball"))
    if t == "place_cue_ball":
        _only(d, {"type", "position"})
        p = d.get("position")
        if not isinstance(p, (list, tuple)) or len(p) != 2:
            raise ValueError("action.position: expected [x, y]")
        return PlaceCue(p[0], p[1])
    if t == "decide":
        _only(d, {"type", "choice"})
        if "choice" not in d:
            raise ValueError("action.choice: missing required field")
        return Decide(d["choice"])
    raise ValueError(f"action.type: unknown action type {t!r} "
                     "(\"place_cue_ball\", \"shoot\" or \"decide\")")


def _only(d: dict, keys: set, path: str = "action") -> None:
    extra = sorted(set(d) - keys)
    if extra:
        raise ValueError(f"{path}.{extra[0]}: unknown field (known: {', '.join(sorted(keys))})")


def _action_text(action) -> str:
    if isinstance(action, (Shot, PlaceCue, Decide)):
        d = action.to_dict()
    elif isinstance(action, dict):
        d = action_from_dict(action).to_dict()
    else:
        raise ValueError("action: expected a Shot, PlaceCue, Decide or a dict, "
                         f"not {type(action).__name__}")
    try:
        return json.dumps(d, allow_nan=False)
    except (TypeError, ValueError) as e:
        raise ValueError(f"action: {e}") from None


# ---------------------------------------------------------------------------
# The engine's JSON of tables and figures (src/io/table_json.hpp,
# game_json.hpp) as Python values: points and pairs by seat as tuples.


def _xy(p) -> Tuple[float, float]:
    return (p[0], p[1])


def _table(d: dict) -> dict:
    """Game.table from the engine's table JSON: every point a tuple."""
    for k in ("head_spot", "foot_spot"):
        d[k] = _xy(d[k])
    d["outline"] = [_xy(p) for p in d["outline"]]
    for w in d["walls"]:
        for k in ("a", "b", "normal"):
            w[k] = _xy(w[k])
    for p in d["pockets"]:
        p["centre"] = _xy(p["centre"])
    if "snooker" in d:
        m = d["snooker"]
        m["d_centre"] = _xy(m["d_centre"])
        m["spots"] = {colour: _xy(p) for colour, p in m["spots"].items()}
    if "carom" in d:
        m = d["carom"]
        for k in ("top_spot", "centre_spot", "bottom_spot"):
            m[k] = _xy(m[k])
        m["starting_spots"] = tuple(_xy(p) for p in m["starting_spots"])
        m["diamonds"] = [_xy(p) for p in m["diamonds"]]
    return d


def _figures(d: dict) -> dict:
    """State.snooker_figures and carom_figures: values by seat as tuples."""
    for k in ("snookers_required", "general_average", "highest_run"):
        if k in d:
            d[k] = tuple(d[k])
    return d


# ---------------------------------------------------------------------------
# States, legal actions, outcomes


@dataclass(frozen=True)
class State:
    """The game between shots, every ball at rest (C++ GameState), as plain
    Python values. Balls are numbered as on the table: 0 is the cue ball.

    Fields mirror the records' JSON form of a state: ``game``, ``phase``
    (``"break_shot"``, ``"shot"``, ``"push_out_choice"``,
    ``"illegal_break_choice"``, ``"eight_on_break_choice"``,
    ``"game_over"``), ``player`` (0 or 1, to act), ``breaker``,
    ``ball_in_hand`` (``"none"``, ``"kitchen"``, ``"anywhere"``),
    ``kitchen_shot``, ``group`` (8-ball groups by seat: ``"none"``,
    ``"solids"``, ``"stripes"``), ``fouls_in_a_row`` (by seat),
    ``push_out_allowed``, ``after_push_out``, ``scratch_on_break``,
    ``winner`` (-1: none yet, or a draw once over), ``result`` (why the game
    ended), ``shots``, ``innings``, ``rack_seed``, ``racks``, ``position``
    ((x, y) by ball number, meaningful where on the table) and ``on_table``
    (bools by ball number). ``targets`` are the balls the player to act may
    legally hit first.

    Snooker (balls 1-15 the reds, 16-21 yellow, green, brown, blue, pink,
    black; phase ``"foul_choice"``, ball in hand ``"d"``): ``snooker`` is
    the records' snooker part, a dict with ``score`` (by seat), ``break``
    (the points of the visit in progress), ``colour_on`` (a red was potted:
    a colour is to be nominated), ``free_ball``, ``respotted_black``,
    ``misses`` and ``replace`` (the table a miss's ``replace_balls``
    restores, or None); ``snooker_figures`` what the table leaves:
    ``balls_on``, ``points_remaining`` and ``snookers_required`` (by seat).
    Both are None in the other games.

    Three-cushion (balls 0 the white, the breaker's cue ball, 1 the yellow,
    the other player's, 2 the red): ``carom`` is the records' carom part,
    a dict with ``score`` (by seat), ``run`` (the points of the inning in
    progress), ``innings`` (begun by each seat) and ``equalizing`` (the
    inning in progress is the equalizing inning); ``carom_figures`` what
    the score panel shows: ``cue_ball`` (the ball the player to act
    strikes), ``general_average`` and ``highest_run`` (by seat, the inning
    in progress included). Both None in the other games.
    """

    game: str
    phase: str
    player: int
    breaker: int
    ball_in_hand: str
    kitchen_shot: bool
    group: Tuple[str, str]
    fouls_in_a_row: Tuple[int, int]
    push_out_allowed: bool
    after_push_out: bool
    scratch_on_break: bool
    winner: int
    result: str
    shots: int
    innings: int
    rack_seed: int
    racks: int
    position: Tuple[Tuple[float, float], ...]
    on_table: Tuple[bool, ...]
    targets: Tuple[int, ...] = ()
    snooker: Optional[dict] = field(default=None, hash=False)
    snooker_figures: Optional[dict] = field(default=None, hash=False)
    carom: Optional[dict] = field(default=None, hash=False)
    carom_figures: Optional[dict] = field(default=None, hash=False)

    @classmethod
    def from_dict(cls, d: dict, targets: Sequence[int] = (),
                  snooker_figures: Optional[dict] = None,
                  carom_figures: Optional[dict] = None) -> "State":
        """A State from the records' JSON form of a state (and, in snooker
        and three-cushion, the figures of ``Game.state``)."""
        return cls(
            game=d["game"], phase=d["phase"], player=d["player"], breaker=d["breaker"],
            ball_in_hand=d["ball_in_hand"], kitchen_shot=d["kitchen_shot"],
            group=tuple(d["group"]), fouls_in_a_row=tuple(d["fouls_in_a_row"]),
            push_out_allowed=d["push_out_allowed"], after_push_out=d["after_push_out"],
            scratch_on_break=d["scratch_on_break"], winner=d["winner"], result=d["result"],
            shots=d["shots"], innings=d["innings"], rack_seed=int(d["rack_seed"]),
            racks=d["racks"], position=tuple((p[0], p[1]) for p in d["position"]),
            on_table=tuple(bool(f) for f in d["on_table"]), targets=tuple(targets),
            snooker=d.get("snooker"), snooker_figures=snooker_figures, carom=d.get("carom"),
            carom_figures=carom_figures)

    def to_dict(self) -> dict:
        """The records' JSON form (rack_seed as a decimal string, on_table as 0/1)."""
        d = {
            "game": self.game, "phase": self.phase, "player": self.player,
            "breaker": self.breaker, "ball_in_hand": self.ball_in_hand,
            "kitchen_shot": self.kitchen_shot, "group": list(self.group),
            "fouls_in_a_row": list(self.fouls_in_a_row),
            "push_out_allowed": self.push_out_allowed, "after_push_out": self.after_push_out,
            "scratch_on_break": self.scratch_on_break, "winner": self.winner,
            "result": self.result, "shots": self.shots, "innings": self.innings,
            "rack_seed": str(self.rack_seed), "racks": self.racks,
            "position": [list(p) for p in self.position],
            "on_table": [1 if f else 0 for f in self.on_table],
        }
        if self.snooker is not None:
            d["snooker"] = self.snooker
        if self.carom is not None:
            d["carom"] = self.carom
        return d

    @property
    def score(self) -> Optional[Tuple[int, int]]:
        """Snooker and three-cushion: the score by seat; None in the other games."""
        if self.carom is not None:
            return tuple(self.carom["score"])
        return None if self.snooker is None else tuple(self.snooker["score"])

    @property
    def positions(self) -> np.ndarray:
        """Positions by ball number as a float64 array (n, 2); rows of balls
        off the table hold their last recorded position (see ``on_table``)."""
        return np.array(self.position, dtype=np.float64).reshape(-1, 2)

    @property
    def balls(self) -> dict:
        """The balls on the table: {number: (x, y)}."""
        return {i: p for i, (p, on) in enumerate(zip(self.position, self.on_table)) if on}

    @property
    def over(self) -> bool:
        """True once the phase is ``game_over``."""
        return self.phase == "game_over"

    @property
    def lowest_ball(self) -> Optional[int]:
        """9-ball and 10-ball: the lowest-numbered object ball on the table
        (the ball on); None in other games or with none left."""
        if self.game not in ("nine_ball", "ten_ball"):
            return None
        on = [i for i in range(1, len(self.on_table)) if self.on_table[i]]
        return min(on) if on else None

    def __repr__(self) -> str:
        left = sum(self.on_table[1:])
        extra = f" winner={self.winner}" if self.over else ""
        return (f"<breakshot.State {self.game} phase={self.phase} player={self.player} "
                f"ball_in_hand={self.ball_in_hand} object_balls={left} shots={self.shots}"
                f"{extra}>")


@dataclass(frozen=True)
class LegalActions:
    """What the player to act may do now (C++ LegalActions).

    ``kinds`` lists the action types allowed (``"place_cue_ball"``,
    ``"shoot"``, ``"decide"``); ``place`` where the cue ball may be placed
    (``"none"``, ``"kitchen"`` (x <= the table's head_string),
    ``"anywhere"`` or, in snooker, ``"d"``); ``must_place`` is True when the cue ball is off the
    table and must be placed before a shot; ``shoot`` whether a shot may be
    played; ``push_out`` whether it may be declared a push-out (9-ball);
    ``call`` whether shots carry calls (8-ball); ``targets`` the balls the
    cue ball may legally hit first; ``choices`` the :class:`Decide` choices
    on offer (in snooker ``"concede"`` is among them whenever a shot is
    due). Snooker: ``nominate`` the balls a shot may nominate
    (``Shot.nominate``) and ``must_nominate`` whether it must (a colour
    after a red); empty and False in the other games.
    """

    kinds: Tuple[str, ...]
    place: str
    must_place: bool
    shoot: bool
    push_out: bool
    call: bool
    targets: Tuple[int, ...]
    choices: Tuple[str, ...]
    nominate: Tuple[int, ...] = ()
    must_nominate: bool = False

    @classmethod
    def _of(cls, d: dict) -> "LegalActions":
        kinds = []
        if d["place"] != "none":
            kinds.append("place_cue_ball")
        if d["shoot"]:
            kinds.append("shoot")
        if d["choices"]:
            kinds.append("decide")
        return cls(kinds=tuple(kinds), place=d["place"], must_place=d["must_place"],
                   shoot=d["shoot"], push_out=d["push_out"], call=d["call"],
                   targets=tuple(d["targets"]), choices=tuple(d["choices"]),
                   nominate=tuple(d.get("nominate", ())),
                   must_nominate=d.get("must_nominate", False))


@dataclass(frozen=True)
class Outcome:
    """What an action did (Game.apply's answer).

    ``index`` is the action's index in the game, ``player`` who acted,
    ``action`` the action as executed (a shot after the seat's noise),
    ``intended`` the strike chosen before noise (a dict, shots only),
    ``noise_seed`` the seed of that noise, ``ruling`` the ruling as the
    records write it (a dict: fouls, legal_break, turn_continues, assigned,
    spotted, winner, text, call_made), ``events`` the shot's events (dicts
    as in a result file, but ``balls`` are ball numbers and a
    ``ball_pocket`` event gives ``pocket`` as an index and
    ``pocket_name``), ``facts`` what the rules read from them (first_hit,
    pocketed, pocket_of, miscue, cushion_after_contact,
    object_balls_to_cushion; the web facade's ``facts``) and ``state`` the
    state after the action.
    """

    index: int
    player: int
    action: Action
    intended: Optional[dict]
    noise_seed: int
    ruling: dict
    facts: dict
    events: list
    state: State

    @property
    def text(self) -> str:
        """The ruling in words, as the record writes it."""
        return self.ruling["text"]

    @property
    def fouls(self) -> list:
        """The fouls committed (names), empty for none."""
        return self.ruling["fouls"]

    def __repr__(self) -> str:
        return (f"<breakshot.Outcome #{self.index} player={self.player} "
                f"{type(self.action).__name__} {self.text!r}>")


# ---------------------------------------------------------------------------
# The game


def _pair(value, what: str) -> Tuple[Any, Any]:
    if isinstance(value, (str, bytes)) or not isinstance(value, (tuple, list)):
        return (value, value)
    if len(value) != 2:
        raise ValueError(f"{what}: expected one value or two (one per seat), not {len(value)}")
    return (value[0], value[1])


def _seed(value, what: str = "seed") -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise ValueError(f"{what}: expected a whole number in [0, 2^64), not {value!r}")
    v = int(value)
    if v < 0 or v >= 1 << 64:
        raise ValueError(f"{what}: expected a whole number in [0, 2^64), not {v}")
    return v


class Game:
    """One game on the C++ game session: the rules, the seeds and the record.

    ``Game(game="eight_ball", table=None, seed=0, breaker=0,
    players=("Player 1", "Player 2"), noise="none", max_shots=None)``.
    ``game`` is one of :func:`games` (``"eight_ball"``, ``"nine_ball"``,
    ``"snooker"``, ``"three_cushion"``); ``table`` the table size: ``"7ft"``,
    ``"8ft"`` or ``"9ft"`` (None: ``"9ft"``), in snooker ``"12ft"`` (None:
    that one, with snooker balls), in three-cushion ``"10ft"`` (None: that
    one, the carom table with carom balls; only the ``"baseline"`` plays it); ``seed`` (0 to 2^64 - 1) gives the
    rack and the noise of every action, so the same seed and the same
    actions give the same game; ``breaker`` (0 or 1) breaks. ``players``
    are the seats' names in the record, or :class:`Player` objects (their
    names; a player's own noise then becomes its seat's noise, as in a
    match). ``noise`` is the noise the seats shoot with, a spec such as
    ``"none"``, ``"tournament"``, ``"2x"`` or
    ``"custom:phi=0.1,speed=0.05"``, or one per seat. ``max_shots`` (None:
    the rules' 400) ends a game still going after that many shots as a
    draw; 0 means no limit. ``physics`` (None: the defaults) chooses the
    pool model's laws, as ``breakshot match`` does: a dict with any of
    ``"cushion_model"`` (``"han_2005"``, the default, ``"han_2005_v0"``,
    the legacy law, ``"mathavan_2010"``, ``"impulse_frictional"`` or
    ``"stronge_compliant"``),
    ``"ball_ball_model"`` (``"friction"`` or ``"mathavan_2014"``),
    ``"ball_ball_friction"`` (a number, or a curve ``{"a": .., "b": ..,
    "c": ..}``), ``"airborne"`` (true by default) and ``"spinning_friction"``
    (0.0117 by default, the legacy 0.044); see :func:`physics_of`. A
    preset's name is its physics: ``physics="legacy"`` is breakshot 0.1's
    (``breakshot match --physics legacy``).

    Game g of ``breakshot match --seed S`` is ``Game(game, seed=mix_seed(S,
    g), breaker=g % 2, players=(p0, p1), noise=...)`` with
    ``Player`` objects deciding: see :class:`Player`.
    """

    def __init__(self, game: str = "eight_ball", table: Optional[str] = None, seed: int = 0,
                 breaker: int = 0, players: Sequence = ("Player 1", "Player 2"),
                 noise: Union[str, Sequence[str]] = "none", max_shots: Optional[int] = None,
                 physics: Union[None, str, dict] = None, *, _core_game=None):
        if _core_game is not None:
            self._g = _core_game
            return
        if breaker not in (0, 1) or isinstance(breaker, bool):
            raise ValueError(f"breaker: must be 0 or 1, not {breaker!r}")
        seats = _pair(players, "players")
        noises = list(_pair(noise, "noise"))
        names = []
        for i, p in enumerate(seats):
            if isinstance(p, Player):
                names.append(p.name)
                if p.noise is not None:
                    noises[i] = p.noise
            elif isinstance(p, str):
                names.append(p)
            else:
                raise ValueError(f"players[{i}]: expected a name or a breakshot.Player, "
                                 f"not {type(p).__name__}")
        for i, n in enumerate(noises):
            if not isinstance(n, str):
                raise ValueError(f"noise: expected a noise spec string, not {type(n).__name__}")
        if max_shots is not None and (isinstance(max_shots, bool) or not isinstance(max_shots, int)):
            raise ValueError(f"max_shots: expected a whole number or None, not {max_shots!r}")
        if table is None:
            table = _default_table(game)
        if not isinstance(game, str) or not isinstance(table, str):
            raise ValueError("game and table: expected names (strings)")
        if max_shots is not None and max_shots < 0:
            raise ValueError(f"max_shots: must be 0 (no limit) or more, not {max_shots}")
        self._g = _core.GameCore(game, table, _seed(seed), int(breaker), names, noises,
                                 -1 if max_shots is None else max_shots, _physics(physics))

    # -- reading -------------------------------------------------------------

    @property
    def state(self) -> State:
        """The state now (after the last action)."""
        return self.state_before(self._g.actions)

    def state_before(self, i: int) -> State:
        """The state before action i (0: the start; ``actions``: now)."""
        d = json.loads(self._g.state_json(int(i)))
        targets = self._g.targets() if i == self._g.actions else ()
        figures = self._g.figures_json(int(i))
        figures = None if figures is None else _figures(json.loads(figures))
        return State.from_dict(d, targets,
                               snooker_figures=figures if d["game"] == "snooker" else None,
                               carom_figures=figures if d["game"] == "three_cushion" else None)

    @property
    def positions(self) -> np.ndarray:
        """The balls' positions now, by ball number, as an array (n, 2)."""
        return self.state.positions

    @property
    def game(self) -> str:
        """The game's name (``"eight_ball"``, ``"nine_ball"``, ...)."""
        return json.loads(self._g.config_json())["game"]

    @property
    def config(self) -> dict:
        """The game's config as the record writes it (game, table_size,
        ball_radius, ball_mass, max_shots)."""
        return json.loads(self._g.config_json())

    @property
    def physics(self) -> dict:
        """The physics the game is played with: cushion_model,
        ball_ball_model, ball_ball_friction (a number or {"a", "b", "c"})
        airborne (a bool; a record writes it only when true) and
        spinning_friction (a record writes it only when it is not the legacy
        0.044)."""
        p = json.loads(self._g.physics_json())
        p.setdefault("airborne", False)
        p.setdefault("spinning_friction", 0.044)
        return p

    @property
    def table(self) -> dict:
        """The table, as the web facade's ``bs_web_game_table`` gives it (one
        encoding, src/io/table_json.hpp; points as (x, y) tuples): size,
        length and width (m), ball_radius, ball_count, head_string (x of the
        kitchen's edge), head_spot, foot_spot, outline (the corners), walls
        (kind, a, b, normal, radius, name) and the pockets (centre, radius,
        name) in the index order calls use;
        in snooker also ``snooker``: the markings (``baulk_line``, the x of
        the baulk line; ``d_centre`` and ``d_radius``, the D; ``spots``, the
        six colour spots by colour); in three-cushion also ``carom``: the
        markings (``top_spot``, ``centre_spot``, ``bottom_spot``, the two
        ``starting_spots`` and the ``diamonds`` on the cushion lines)."""
        return _table(json.loads(self._g.table_json()))

    @property
    def seed(self) -> int:
        """The game's seed."""
        return self._g.seed

    @property
    def players(self) -> Tuple[str, str]:
        """The seats' names."""
        return tuple(self._g.names())

    @property
    def noise(self) -> Tuple[str, str]:
        """The noise each seat shoots with, as spec strings."""
        return tuple(self._g.noise())

    @property
    def actions(self) -> int:
        """The number of actions played."""
        return self._g.actions

    @property
    def over(self) -> bool:
        """True once the game has ended."""
        return self._g.over

    @property
    def winner(self) -> Optional[int]:
        """The winning seat (0 or 1), or None while going or for a draw."""
        w = self.state.winner
        return None if w < 0 else w

    @property
    def result(self) -> str:
        """Why the game ended, in words ("" while it goes on)."""
        return self.state.result

    @property
    def player_seed(self) -> int:
        """The seed the match runner gives the player deciding the next
        action (GameSeeds::player(seed, actions))."""
        return self._g.next_player_seed

    @property
    def noise_seed(self) -> int:
        """The seed of the next action's noise (GameSeeds::noise)."""
        return self._g.next_noise_seed

    def legal_actions(self) -> LegalActions:
        """What the player to act may do now (nothing once the game is over)."""
        return LegalActions._of(json.loads(self._g.legal_json()))

    def check(self, action) -> Optional[str]:
        """Why the rules refuse ``action`` now, or None if they allow it.
        A malformed action raises ValueError naming the field."""
        return self._g.check(_action_text(action))

    def check_placement(self, x: float, y: float) -> Optional[str]:
        """Why the cue ball may not be placed at (x, y) now, or None."""
        return self._g.check_placement(float(x), float(y))

    # -- playing -------------------------------------------------------------

    def apply(self, action) -> Outcome:
        """Plays ``action`` for the seat to act and returns its Outcome.

        A shot is played as perturbed by the seat's noise (seeded by
        ``noise_seed``). A refused action raises ValueError with the rules'
        reason, and the game is unchanged."""
        d = json.loads(self._g.apply(_action_text(action)))
        return Outcome(
            index=d["index"], player=d["player"], action=action_from_dict(d["executed"]),
            intended=d["intended"], noise_seed=int(d["noise_seed"]), ruling=d["ruling"],
            facts=d["facts"], events=d["events"],
            state=State.from_dict(d["state"], self._g.targets()))

    def take_back(self, n: int = 1) -> None:
        """Takes back the last n actions (0 <= n <= actions)."""
        if isinstance(n, bool) or not isinstance(n, int) or n < 0 or n > self._g.actions:
            raise ValueError(f"take_back: n must be a whole number in [0, {self._g.actions}], "
                             f"not {n!r}")
        self._g.take_back_to(self._g.actions - n)

    def play(self, players: Sequence["Player"], max_actions: Optional[int] = None) -> "Game":
        """Lets ``players`` (one per seat) play until the game is over (or
        ``max_actions`` more actions), each deciding with its seed stream;
        returns self."""
        ps = _pair(players, "players")
        n = 0
        while not self.over and (max_actions is None or n < max_actions):
            self.apply(ps[self.state.player].decide(self))
            n += 1
        return self

    # -- records -------------------------------------------------------------

    def record(self) -> str:
        """The game's record as JSON text, byte for byte what the match
        runner writes (``breakshot replay`` reads it)."""
        return self._g.record_text()

    def save(self, path: Union[str, os.PathLike]) -> None:
        """Writes record() to ``path``."""
        with open(path, "w", encoding="utf-8", newline="\n") as f:
            f.write(self.record())

    @classmethod
    def from_record(cls, record: Union[str, os.PathLike]) -> "Game":
        """The game of a record: a path, or the record's JSON text (a str
        starting with ``{``). The record is replayed and must come out
        identical; otherwise ValueError says where it differs. The game can
        then be continued."""
        text = str(record) if isinstance(record, str) and record.lstrip().startswith("{") else None
        if text is None:
            with open(record, encoding="utf-8") as f:
                text = f.read()
        return cls(_core_game=_core.GameCore.from_record(text))

    def copy(self) -> "Game":
        """An independent copy (the record so far and the seeds)."""
        return Game(_core_game=self._g.__copy__())

    __copy__ = copy

    def __repr__(self) -> str:
        s = self.state
        status = (f"over winner={s.winner}" if s.phase == "game_over"
                  else f"phase={s.phase} player={s.player}")
        return (f"<breakshot.Game {self.game} table={self.table['size']} seed={self.seed} "
                f"actions={self.actions} {status}>")


# ---------------------------------------------------------------------------
# Players and matches


class Player:
    """A computer player by name: ``"baseline"`` or an AI level (see
    :func:`players`), or either at a noise of its own, ``NAME@NOISE``
    (``"champion@0.5x"``: the champion shooting, and planning, at half the
    tournament noise; NOISE is a noise spec as ``breakshot match --noise``
    takes it).

    ``Player(level="baseline", seed=None, threads=None)``. ``decide(game)``
    returns the player's action for the game's state now. The decision's
    seed: with ``seed=None`` it is the game's own player stream
    (``game.player_seed``, GameSeeds::player(game seed, action index)),
    exactly what ``breakshot match`` gives its players, so a game played
    with ``decide`` and ``apply`` from the seed and breaker of match game g
    is that game, action for action. With ``seed=S`` it is
    GameSeeds::player(S, action index): a stream of the player's own. The
    AI's decisions are the same for any ``threads`` (None: the level's
    default, every core but for "beginner"); the GIL is released while it
    thinks. ``noise`` is the player's own noise spec (the AI levels), or
    None (baseline: it shoots with the game's noise).
    """

    def __init__(self, level: str = "baseline", seed: Optional[int] = None,
                 threads: Optional[int] = None):
        if not isinstance(level, str):
            raise ValueError(f"level: expected a player name, not {type(level).__name__}")
        if threads is not None and (isinstance(threads, bool) or not isinstance(threads, int)
                                    or threads < 1):
            raise ValueError(f"threads: expected a whole number >= 1 or None, not {threads!r}")
        self._seed = None if seed is None else _seed(seed)
        self._p = _core.PlayerCore(level, 0 if threads is None else threads)
        self._level = level

    @property
    def name(self) -> str:
        """The player's name (its level)."""
        return self._p.name

    @property
    def seed(self) -> Optional[int]:
        """The player's own seed, or None (the game's player stream)."""
        return self._seed

    @property
    def noise(self) -> Optional[str]:
        """The player's own noise spec, or None for a player without one."""
        return self._p.noise

    @property
    def threads(self) -> int:
        """Worker threads of the AI's search (0: every core)."""
        return self._p.threads

    def decision_seed(self, game: Game) -> int:
        """The seed decide(game) uses for the game's next action."""
        if self._seed is None:
            return game.player_seed
        return _core.player_seed(self._seed, game.actions)

    def decide(self, game: Game, seed: Optional[int] = None) -> Action:
        """The player's action for ``game``'s state now (ValueError once the
        game is over). ``seed`` overrides the decision seed."""
        if not isinstance(game, Game):
            raise ValueError(f"decide: expected a breakshot.Game, not {type(game).__name__}")
        s = self.decision_seed(game) if seed is None else _seed(seed)
        return action_from_dict(json.loads(self._p.decide(game._g, s)))

    def __repr__(self) -> str:
        return (f"<breakshot.Player {self.name} noise={self.noise} seed={self._seed} "
                f"threads={self.threads}>")


def games() -> list:
    """The games the library plays, by name (``"eight_ball"``,
    ``"nine_ball"``, ...)."""
    return list(_core.game_names())


def players() -> list:
    """The computer players' names: ``"baseline"``, then the AI levels."""
    return list(_core.player_names())


def mix_seed(a: int, b: int) -> int:
    """SplitMix64 seed mixing: game g of a match with seed S has the seed
    mix_seed(S, g) (and is broken by seat g % 2)."""
    return _core.mix_seed(_seed(a, "a"), _seed(b, "b"))


def _default_table(game) -> str:
    """The table a game is played on when none is named (the package's one
    map, _position.default_table)."""
    return default_table(game)


# The physics presets, as breakshot match --physics NAME takes them: the
# arguments of physics_of that make each one.
PHYSICS_PRESETS = {
    "default": {"cushion_model": "han_2005", "ball_ball_model": "friction",
                "ball_ball_friction": "tpb3", "airborne": True,
                "spinning_friction": "measured"},
    "legacy": {"cushion_model": "han_2005_v0", "ball_ball_model": "friction",
               "ball_ball_friction": "tpa28", "airborne": False,
               "spinning_friction": "legacy"},
}


def _physics(physics: Union[None, str, dict]) -> Optional[str]:
    """The physics argument as the JSON text _core takes (None: defaults);
    a string names a preset (physics_of)."""
    if physics is None:
        return None
    if isinstance(physics, str):
        if physics not in PHYSICS_PRESETS:
            raise ValueError(f"physics: expected a dict, a preset name "
                             f"({' or '.join(PHYSICS_PRESETS)}) or None, not {physics!r}")
        physics = physics_of(preset=physics)
    if not isinstance(physics, dict):
        raise ValueError(f"physics: expected a dict, a preset name or None, "
                         f"not {type(physics).__name__}")
    return json.dumps(physics)


def physics_of(cushion_model: Optional[str] = None, ball_ball_model: Optional[str] = None,
               ball_ball_friction: Union[None, float, dict, str] = None,
               airborne: Optional[bool] = None,
               spinning_friction: Union[None, float, str] = None, *,
               preset: str = "default") -> dict:
    """A physics dict for Game, match and match_json. ``preset`` is
    ``"default"`` (the engine's) or ``"legacy"`` (breakshot 0.1's:
    ``han_2005_v0`` cushions, the TP A-28 friction curve, balls that stay
    on the cloth, the legacy spinning friction), as ``breakshot match
    --physics``; every argument given wins over the preset's value, as an
    explicit option does on the command line (``physics_of(airborne=True,
    preset="legacy")``). ``ball_ball_friction`` may be a number, a curve
    ``{"a", "b", "c"}``, ``"tpb3"`` (Alciatore's refit to the measured
    throw, TP B-3, the default) or ``"tpa28"`` (his TP A-28 curve), as
    ``breakshot match --ball-ball-friction`` takes them;
    ``spinning_friction`` ``"measured"`` (0.0117, the default: side spin
    decays at 10 rad/s^2 on a pool ball) or ``"legacy"`` (0.044), as
    ``--spinning-friction`` takes them, or a number > 0.
    ``physics_of(preset="legacy")`` equals ``physics_of("han_2005_v0",
    "friction", "tpa28", airborne=False, spinning_friction="legacy")``."""
    if preset not in PHYSICS_PRESETS:
        raise ValueError(f"preset: unknown physics preset {preset!r} "
                         f"(known: {', '.join(PHYSICS_PRESETS)})")
    base = PHYSICS_PRESETS[preset]
    cushion_model = base["cushion_model"] if cushion_model is None else cushion_model
    ball_ball_model = base["ball_ball_model"] if ball_ball_model is None else ball_ball_model
    if ball_ball_friction is None:
        ball_ball_friction = base["ball_ball_friction"]
    airborne = base["airborne"] if airborne is None else airborne
    if spinning_friction is None:
        spinning_friction = base["spinning_friction"]
    curves = {"tpa28": {"a": 0.009951, "b": 0.108, "c": 1.088},
              "tpb3": {"a": 0.016, "b": 0.219, "c": 0.691}}
    if isinstance(ball_ball_friction, str):
        if ball_ball_friction not in curves:
            raise ValueError(f"ball_ball_friction: expected tpa28, tpb3, a number or "
                             f"{{'a', 'b', 'c'}}, not {ball_ball_friction!r}")
        ball_ball_friction = dict(curves[ball_ball_friction])
    spins = {"measured": 0.0117, "legacy": 0.044}
    if isinstance(spinning_friction, str):
        if spinning_friction not in spins:
            raise ValueError(f"spinning_friction: expected measured, legacy or a number > 0, "
                             f"not {spinning_friction!r}")
        spinning_friction = spins[spinning_friction]
    return {"cushion_model": cushion_model, "ball_ball_model": ball_ball_model,
            "ball_ball_friction": ball_ball_friction, "airborne": bool(airborne),
            "spinning_friction": spinning_friction}


def match_json(game: str, players: Sequence[str], games: int = 1, seed: int = 0,
               noise: str = "none", table: Optional[str] = None,
               records: Union[None, str, os.PathLike] = None,
               threads: Optional[int] = None, first_game: int = 0,
               physics: Union[None, str, dict] = None, jobs: int = 1) -> str:
    """The summary text ``breakshot match`` prints for the same arguments
    (``--game``, ``--players a,b``, ``--games``, ``--seed``, ``--noise``,
    ``--table``, ``--records DIR``, ``--first-game``, ``--jobs``), byte for
    byte. ``jobs`` plays that many games at once (0: one per core), each
    thread with its own players; the summary and the records are the same
    for any ``jobs``.
    ``threads`` sets the AI players' worker threads (the summary does not
    depend on it). ``first_game`` plays games first_game .. first_game +
    games - 1 of the match, each exactly as one match from game 0 plays it;
    such a chunk's summary says ``"first_game"`` and chunks add up
    (``breakshot match-sum``). ``physics`` (a dict, see :class:`Game` and
    :func:`physics_of`) is ``--cushion-model``, ``--ball-ball-model``,
    ``--ball-ball-friction``, ``--airborne`` and ``--spinning-friction``;
    the summary shows it only when it is not the
    default."""
    if table is None:
        table = _default_table(game)
    names = _pair(players, "players")
    if isinstance(players, str) or not all(isinstance(n, str) for n in names):
        raise ValueError("players: expected two player names")
    if isinstance(games, bool) or not isinstance(games, int):
        raise ValueError(f"games: expected a whole number of games >= 1, not {games!r}")
    if isinstance(first_game, bool) or not isinstance(first_game, int) or first_game < 0:
        raise ValueError(f"first_game: expected a whole number >= 0, not {first_game!r}")
    if threads is not None and (isinstance(threads, bool) or not isinstance(threads, int)
                                or threads < 1):
        raise ValueError(f"threads: expected a whole number >= 1 or None, not {threads!r}")
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 0:
        raise ValueError(f"jobs: expected a whole number >= 0 (0: one per core), not {jobs!r}")
    return _core.match_json(game, list(names), games, _seed(seed), noise, table,
                            None if records is None else os.fspath(records),
                            0 if threads is None else threads, first_game, _physics(physics),
                            jobs)


def match(game: str, players: Sequence[str], games: int = 1, seed: int = 0,
          noise: str = "none", table: Optional[str] = None,
          records: Union[None, str, os.PathLike] = None,
          threads: Optional[int] = None, first_game: int = 0,
          physics: Union[None, str, dict] = None, jobs: int = 1) -> dict:
    """Plays a match as ``breakshot match`` does and returns its summary
    (the parsed JSON it prints: game, table, seed, noise, games_played,
    draws, players with their figures). ``records`` is a folder to write
    every game's record to (game-0001.json, ...). ``first_game`` plays
    only games first_game .. first_game + games - 1 (``--first-game``).
    ``physics`` chooses the laws (see match_json). ``jobs`` plays that many
    games at once (``--jobs``; 0: one per core). See match_json."""
    return json.loads(match_json(game, players, games, seed, noise, table, records, threads,
                                 first_game, physics, jobs))
