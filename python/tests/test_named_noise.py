"""Players at a named noise, NAME@NOISE (docs/ai.md, "A player at a named
noise"): the same games and summaries as the command, the noise in the
summary and the records, and bad names refused naming what is wrong."""

from __future__ import annotations

import json

import pytest

import breakshot as bs


def test_a_level_at_a_named_noise_plays_as_the_command(run_cli, tmp_path):
    players = ["club@0.5x", "baseline@none"]
    text = bs.match_json("nine_ball", players, games=2, seed=1, noise="tournament",
                         records=tmp_path / "py")
    cli = run_cli("match", "--game", "nine_ball", "--players", ",".join(players), "--games", "2",
                  "--seed", "1", "--noise", "tournament", "--records", tmp_path / "cli",
                  check=True)
    assert text == cli.stdout
    summary = json.loads(text)
    assert [p["name"] for p in summary["players"]] == players
    assert [p["noise"] for p in summary["players"]] == ["0.5x", "none"]
    record = json.loads((tmp_path / "py" / "game-0001.json").read_text())
    assert record["players"] == players
    assert record["noise"][0]["phi"] == 0.0625  # half of tournament's 0.125 degrees
    assert record["noise"][1] == {"phi": 0.0, "theta": 0.0, "speed": 0.0, "a": 0.0, "b": 0.0}
    assert run_cli("replay", tmp_path / "py" / "game-0001.json").returncode == 0
    # The plain name keeps the level's own noise, and plays otherwise.
    plain = json.loads(bs.match_json("nine_ball", ["club", "baseline@none"], games=2, seed=1,
                                     noise="tournament"))
    assert plain["players"][0]["noise"] == bs.Player("club").noise != "0.5x"
    assert plain["players"][0]["pots_made"] != summary["players"][0]["pots_made"] or \
        plain["players"][0]["shots"] != summary["players"][0]["shots"]


def test_player_object_takes_the_name():
    p = bs.Player("champion@0.5x")
    assert p.name == "champion@0.5x"
    assert p.noise == "0.5x"
    assert bs.Player("champion").noise == "tournament"


@pytest.mark.parametrize("name, message", [
    ("club@", "no noise after the '@'"),
    ("@1x", "no player before the '@'"),
    ("club@fast", 'unknown spec "fast"'),
    ("club@1x@2x", "more than one '@'"),
    ("clubb@1x", 'unknown player "clubb"'),
])
def test_bad_names_are_value_errors(name, message, run_cli):
    with pytest.raises(ValueError, match=message):
        bs.match_json("nine_ball", [name, "baseline"], games=1, seed=1, noise="none")
    with pytest.raises(ValueError, match=message):
        bs.Player(name)
    r = run_cli("match", "--game", "nine_ball", "--players", f"{name},baseline", "--games", "1",
                "--seed", "1", "--noise", "none")
    assert r.returncode == 2
    assert message in r.stderr

