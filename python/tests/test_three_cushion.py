"""Three-cushion from Python: the Game class on the carom table (the UMB
starting position, the shooter's own cue ball, the score and innings),
the baseline playing it, matches as the command plays them, and the AI
levels refusing the game."""

import json
import subprocess

import pytest

import breakshot
from breakshot import Game, Shot

WHITE, YELLOW, RED = 0, 1, 2


def test_three_cushion_is_a_game_on_the_10ft_carom_table():
    assert "three_cushion" in breakshot.games()
    g = Game("three_cushion", seed=2)
    t = g.table
    assert t["size"] == "10ft"
    assert (t["length"], t["width"]) == (2.84, 1.42)
    assert t["ball_radius"] == 0.03075
    assert t["ball_count"] == 3
    assert t["pockets"] == []
    assert t["carom"]["top_spot"] == (2.13, 0.71)
    assert len(t["carom"]["diamonds"]) == 20
    with pytest.raises(ValueError, match="three_cushion: 10ft"):
        Game("three_cushion", table="9ft")


def test_the_start_and_a_shot():
    g = Game("three_cushion", seed=2, players=("a", "b"))
    s = g.state
    assert s.game == "three_cushion"
    assert s.phase == "break_shot"
    assert s.position[RED] == (2.13, 0.71)
    assert s.position[YELLOW] == (0.71, 0.71)
    assert s.score == (0, 0)
    assert s.carom["innings"] == [1, 0]
    assert list(g.legal_actions().targets) == [RED]
    # Straight at the red: no three cushions, the inning passes.
    x, y = s.position[WHITE]
    import math
    phi = math.degrees(math.atan2(0.71 - y, 2.13 - x))
    step = g.apply(Shot(phi=phi, theta=0.0, speed=3.0))
    assert step.ruling["carom"]["hit"][0] == RED
    assert g.state.player == 1
    assert g.state.carom["innings"] == [1, 1]
    # The wrong ball is a foul.
    step = g.apply(Shot(phi=0.0, theta=0.0, speed=2.0, cue_ball=WHITE))
    assert "wrong_cue_ball" in step.fouls
    assert step.ruling["carom"]["cue_ball"] == WHITE


def test_a_match_from_python_is_the_commands(cli):
    text = breakshot.match_json("three_cushion", ["baseline", "baseline"], games=2, seed=3,
                                noise="tournament")
    out = subprocess.run([cli, "match", "--game", "three_cushion", "--players",
                          "baseline,baseline", "--games", "2", "--seed", "3", "--noise",
                          "tournament"], capture_output=True, text=True, check=True).stdout
    assert text == out
    summary = json.loads(text)
    assert summary["table_size"] == "10ft"
    for p in summary["players"]:
        assert "general_average" in p["carom"]


def test_the_baseline_and_the_levels_play():
    g = Game("three_cushion", seed=5, noise="tournament")
    g.play([breakshot.Player("baseline"), breakshot.Player("baseline")], max_actions=12)
    assert g.state.shots == 12 or g.over
    total = sum(g.state.score)
    assert total >= 0
    action = breakshot.Player("beginner").decide(Game("three_cushion"))
    assert action is not None
