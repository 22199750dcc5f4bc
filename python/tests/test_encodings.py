"""One encoding of each game fact (src/io/game_json.hpp, table_json.hpp):
Python's values for a game are the web facade's replies for the same game
(the native facade, through web_api_probe), field for field."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pytest

import breakshot

from conftest import ROOT


@pytest.fixture(scope="session")
def probe() -> Path:
    """The facade's native probe (web/tests/web_api_probe.cpp):
    $BREAKSHOT_WEB_API_PROBE, else the release build's. Missing is a
    failure, not a skip."""
    path = Path(os.environ.get("BREAKSHOT_WEB_API_PROBE",
                               ROOT / "build" / "release" / "web_api_probe"))
    if not path.is_file():
        pytest.fail(f"no web_api_probe at {path}: build the release preset or set "
                    "BREAKSHOT_WEB_API_PROBE")
    return path


def facade_replies(probe: Path, tmp_path: Path, steps: list) -> list:
    script = tmp_path / "script.json"
    script.write_text(json.dumps({"steps": steps}))
    r = subprocess.run([str(probe), "--root", str(ROOT), "--script", str(script)],
                       capture_output=True, text=True, check=True)
    return [line.split("\t", 1) for line in r.stdout.splitlines()]


def plain(v):
    """Python's values as JSON gives them: tuples as lists."""
    return json.loads(json.dumps(v))


def legal_dict(la: breakshot.LegalActions, game: str) -> dict:
    d = {"place": la.place, "must_place": la.must_place, "shoot": la.shoot,
         "push_out": la.push_out, "call": la.call, "targets": list(la.targets),
         "choices": list(la.choices)}
    if game == "snooker":
        d["nominate"] = list(la.nominate)
        d["must_nominate"] = la.must_nominate
    return d


@pytest.mark.parametrize("game,seat", [("nine_ball", "beginner"), ("snooker", "baseline"),
                                       ("three_cushion", "baseline")])
def test_python_values_are_the_facades_replies(probe, tmp_path, game, seat):
    g = breakshot.Game(game, seed=11)
    player = breakshot.Player(seat)
    outcomes = [g.apply(player.decide(g)) for _ in range(3) if not g.over]

    steps = [{"do": "game_new", "as": "g",
              "config": {"game": game, "seed": "11", "players": ["human", "human"]}},
             {"do": "table", "game": "g"}]
    steps += [{"do": "act", "game": "g", "action": o.action.to_dict()} for o in outcomes]
    replies = facade_replies(probe, tmp_path, steps)
    assert [label for label, _ in replies] == (["game_new g", "table g"]
                                               + ["act g"] * len(outcomes))
    table = json.loads(replies[1][1])
    assert plain(g.table) == table
    for o, (_, text) in zip(outcomes, replies[2:]):
        reply = json.loads(text)
        assert "error" not in reply, reply
        assert o.facts == reply["facts"]
        assert o.ruling == reply["ruling"]
        assert o.state.to_dict() == {k: v for k, v in reply["state"].items()
                                     if k not in ("players", "actions", "legal",
                                                  "snooker_figures", "carom_figures")}
    last = json.loads(replies[-1][1])["state"]
    s = g.state
    assert legal_dict(g.legal_actions(), game) == last["legal"]
    assert plain(s.snooker_figures) == last.get("snooker_figures")
    assert plain(s.carom_figures) == last.get("carom_figures")
