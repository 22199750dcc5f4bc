"""10-ball from Python: the game is in the list, a match is the
command's, a game starts with the 1 as the ball on."""

from __future__ import annotations

import json

import breakshot as bs


def test_ten_ball_plays_from_python_as_the_command(run_cli):
    assert "ten_ball" in bs.games()
    text = bs.match_json("ten_ball", ["club", "baseline"], games=2, seed=4, noise="tournament")
    cli = run_cli("match", "--game", "ten_ball", "--players", "club,baseline", "--games", "2",
                  "--seed", "4", "--noise", "tournament", check=True)
    assert text == cli.stdout
    assert json.loads(text)["game"] == "ten_ball"
    g = bs.Game("ten_ball", seed=3)
    assert g.state.lowest_ball == 1
    assert len(g.state.on_table) == 11
