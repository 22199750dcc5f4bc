"""Snooker from Python: the Game class on the 12 ft table (the score, the
ball on, nominations, the D, the choice after a foul, conceding), its
records, and batch shots on the snooker table."""

import json
import pathlib

import numpy as np
import pytest

import breakshot
from breakshot import Decide, Game, PlaceCue, Player, Shot

ROOT = pathlib.Path(__file__).resolve().parents[2]

REDS = tuple(range(1, 16))
COLOURS = (16, 17, 18, 19, 20, 21)  # yellow, green, brown, blue, pink, black


def test_snooker_is_a_game_on_the_12ft_table():
    assert "snooker" in breakshot.games()
    g = Game("snooker", seed=3)
    t = g.table
    assert t["size"] == "12ft"
    assert t["ball_count"] == 22  # the cue ball, 15 reds, 6 colours
    # WPBSA Official Rules, Section 1: playing area 3569 x 1778 mm, balls
    # of 52.5 mm, the baulk line 737 mm from the bottom cushion, the D of
    # radius 292 mm.
    assert (t["length"], t["width"]) == (3.569, 1.778)
    assert t["ball_radius"] == 0.02625
    assert t["snooker"]["baulk_line"] == 0.737
    assert t["snooker"]["d_radius"] == 0.292
    assert set(t["snooker"]["spots"]) == {"yellow", "green", "brown", "blue", "pink", "black"}
    # The pool tables have no snooker markings.
    assert "snooker" not in Game("nine_ball").table


def test_the_start_of_a_frame():
    g = Game("snooker", seed=3, players=("a", "b"))
    s = g.state
    assert s.game == "snooker" and s.phase == "break_shot" and s.ball_in_hand == "d"
    assert s.score == (0, 0)
    assert s.snooker["break"] == 0 and not s.snooker["colour_on"]
    # On a red; 15 reds each with the black, then the six colours
    # (2 + 3 + 4 + 5 + 6 + 7 = 27): 147, the maximum break.
    assert tuple(s.snooker_figures["balls_on"]) == REDS
    assert s.snooker_figures["points_remaining"] == 15 * 8 + 27 == 147
    assert tuple(s.snooker_figures["snookers_required"]) == (0, 0)
    la = g.legal_actions()
    assert la.place == "d" and la.must_place is False
    assert la.choices == ("concede",)
    assert la.nominate == REDS and la.must_nominate is False
    # The records' form keeps the snooker part.
    assert s.to_dict()["snooker"]["score"] == [0, 0]
    # Pool states have none of it.
    p = Game("eight_ball").state
    assert p.snooker is None and p.snooker_figures is None and p.score is None
    assert "snooker" not in p.to_dict()
    assert Game("eight_ball").legal_actions().nominate == ()


def test_the_cue_ball_in_hand_goes_in_the_d():
    g = Game("snooker", seed=3)
    m = g.table["snooker"]
    cx, cy = m["d_centre"]
    assert g.check_placement(m["baulk_line"], cy - 0.18) is None
    why = g.check_placement(m["baulk_line"] + 0.05, cy)
    assert why is not None and "the D" in why
    assert g.check_placement(cx - 0.1, cy + 0.3) is not None  # behind the line, outside the radius


def _play_to(g, players, stop, limit=80):
    """Plays the players' decisions until stop(g) or the game ends."""
    for _ in range(limit):
        if g.over or stop(g):
            return True if not g.over else stop(g)
        g.apply(players[g.state.player].decide(g))
    return stop(g)


def test_a_colour_must_be_nominated_after_a_red():
    players = (Player("baseline"), Player("baseline"))
    g = Game("snooker", seed=2026, players=players, noise="tournament")
    assert _play_to(g, players, lambda g: g.legal_actions().must_nominate)
    s = g.state
    la = g.legal_actions()
    assert s.snooker["colour_on"] and s.snooker["break"] >= 1
    assert la.nominate == COLOURS
    # A shot without a nomination, or nominating a red, is refused.
    assert "nominate" in g.check(Shot(phi=0.0, theta=0.0, speed=1.0))
    assert g.check(Shot(phi=0.0, theta=0.0, speed=1.0, nominate=1)) is not None
    assert g.check(Shot(phi=0.0, theta=0.0, speed=1.0, nominate=21)) is None
    # The baseline nominates, and the outcome's ruling says which.
    action = players[s.player].decide(g)
    assert isinstance(action, Shot) and action.nominate in COLOURS
    out = g.apply(action)
    assert out.action.nominate == action.nominate
    assert out.ruling["snooker"]["nominated"] == action.nominate
    # Nominations survive the dict form and the record.
    assert breakshot.action_from_dict(action.to_dict()) == action
    h = Game.from_record(g.record())
    assert h.state == g.state


def test_a_foul_gives_the_choice_and_points_to_the_opponent():
    g = Game("snooker", seed=5, players=("p1", "p2"))
    m = g.table["snooker"]
    g.apply(PlaceCue(m["baulk_line"], m["d_centre"][1] - 0.18))
    # Straight back into the bottom cushion: no ball is hit, a foul of at
    # least 4 points (WPBSA 3.12: the value of the ball on, a red, is less).
    out = g.apply(Shot(phi=180.0, theta=0.0, speed=0.5))
    assert "no_contact" in out.fouls
    assert out.ruling["snooker"]["penalty"] == 4
    s = g.state
    assert s.phase == "foul_choice" and s.player == 1
    assert s.score == (0, 4)
    la = g.legal_actions()
    assert {"play_on", "offender_again", "concede"} <= set(la.choices)
    assert la.kinds == ("decide",)
    g.apply(Decide("offender_again"))
    assert g.state.player == 0 and g.state.phase == "shot"


def test_conceding_ends_the_frame():
    g = Game("snooker", seed=5)
    out = g.apply(Decide("concede"))
    assert g.over and out.ruling["winner"] == 1 and g.winner == 1


def test_snooker_tables_and_players():
    with pytest.raises(ValueError, match="table"):
        Game("snooker", table="9ft")
    with pytest.raises(ValueError, match="table"):
        Game("eight_ball", table="12ft")
    g = Game("snooker", seed=1)
    # The AI levels and the baseline play snooker: the break-off from the D.
    for name in ("beginner", "baseline"):
        assert isinstance(Player(name).decide(g), (Shot, PlaceCue))


def test_a_snooker_match_from_python_is_the_commands(cli):
    import subprocess
    text = breakshot.match_json("snooker", ["baseline", "baseline"], games=1, seed=9,
                                noise="tournament")
    out = subprocess.run([str(cli), "match", "--game", "snooker", "--players",
                          "baseline,baseline", "--games", "1", "--seed", "9",
                          "--noise", "tournament"], capture_output=True, text=True, check=True)
    assert text == out.stdout
    assert json.loads(text)["table_size"] == "12ft"


def test_batch_shots_on_the_snooker_table_are_simulates():
    scenario = json.loads((ROOT / "examples" / "snooker" / "pot_corner.json").read_text())
    cue = scenario.pop("cue")
    strikes = np.array([[cue["phi"], cue["theta"], cue["speed"], cue["a"], cue["b"]],
                        [cue["phi"] + 3.0, 0.0, cue["speed"], 0.0, 0.0]])
    r = breakshot.shots(scenario, strikes, threads=2)
    for i, row in enumerate(strikes):
        one = dict(scenario, cue={"ball": "cue", "phi": row[0], "theta": row[1],
                                  "speed": row[2], "a": row[3], "b": row[4]})
        final = breakshot.simulate(one).final["balls"]
        assert np.array_equal(r.final_positions[i], np.array([b["position"] for b in final]))
    # The example's shot pots the red in a corner pocket.
    red = r.ball_ids.index("red1")
    assert r.pocketed[0, red]


def test_pool_env_stays_with_the_pool_games():
    from breakshot.env import PoolEnv
    with pytest.raises(ValueError, match="PoolEnv plays eight_ball and nine_ball"):
        PoolEnv(game="snooker", opponent="baseline")
