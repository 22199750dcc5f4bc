"""breakshot.Game, Player and match against the C++ side and the CLI:
games played from Python replay with `breakshot replay`, decide()+apply()
plays the match runner's games byte for byte, match() prints the CLI's
summary."""

from __future__ import annotations

import json

import numpy as np
import pytest

import breakshot
from breakshot import Decide, Game, PlaceCue, Player, Shot


def play_out(game, players):
    while not game.over:
        game.apply(players[game.state.player].decide(game))
    return game


# -- games and states --------------------------------------------------------


def test_games_and_players_come_from_the_cpp_side():
    assert breakshot.games() == ["eight_ball", "nine_ball", "snooker", "three_cushion", "ten_ball"]
    assert breakshot.players()[0] == "baseline"
    assert set(breakshot.players()[1:]) == {"beginner", "amateur", "club", "expert", "champion"}


@pytest.mark.parametrize("name,balls,targets", [("eight_ball", 16, None), ("nine_ball", 10, (1,))])
def test_new_game_state(name, balls, targets):
    g = Game(name, seed=7, breaker=1)
    s = g.state
    assert s.game == name and s.phase == "break_shot" and s.player == 1 and s.breaker == 1
    assert len(s.position) == balls and all(s.on_table)
    assert s.positions.shape == (balls, 2) and s.positions.dtype == np.float64
    assert s.ball_in_hand == "kitchen" and g.actions == 0 and not g.over and g.winner is None
    if targets:
        assert s.targets == targets and s.lowest_ball == 1
    la = g.legal_actions()
    assert la.kinds == ("place_cue_ball", "shoot") and la.place == "kitchen"
    assert la.shoot and not la.must_place and la.choices == ()
    assert g.table["ball_count"] == balls and len(g.table["pockets"]) == 6
    # The state as the record writes it, and back.
    assert breakshot.State.from_dict(s.to_dict(), s.targets) == s
    assert json.loads(g.record())["start"] == s.to_dict()


def test_same_seed_same_game_and_a_new_seed_a_new_rack():
    p = [Player("baseline"), Player("baseline")]
    a = play_out(Game("nine_ball", seed=11), p)
    b = play_out(Game("nine_ball", seed=11), p)
    assert a.record() == b.record()
    assert Game("nine_ball", seed=12).state.position != Game("nine_ball", seed=11).state.position


# -- playing, checking, errors -------------------------------------------------


def test_refused_actions_raise_the_rules_reason_and_change_nothing():
    g = Game("eight_ball", seed=1)
    beyond = g.table["head_string"] + 0.2
    why = g.check_placement(beyond, 0.6)
    assert "behind the head string" in why
    assert g.check(PlaceCue(beyond, 0.6)) == why
    before = g.record()
    with pytest.raises(ValueError, match="behind the head string"):
        g.apply(PlaceCue(beyond, 0.6))
    assert g.record() == before
    assert g.check(Decide("respot_eight")).startswith("there is no decision to make now")
    assert g.check(Shot(0, 0, 25.0)) == "strike speed must be in (0, 20] m/s"
    assert g.check(Shot(0, 0, 5.0, push_out=True)) == "8-ball has no push-out"
    assert g.check_placement(0.5, 0.6) is None and g.check(Shot(0, 0, 8.0)) is None


def test_malformed_actions_name_the_field():
    g = Game("nine_ball")
    with pytest.raises(ValueError, match=r"action\.type: unknown action type 'jump'"):
        g.apply({"type": "jump"})
    with pytest.raises(ValueError, match=r"action\.strike\.speed: missing"):
        g.check({"type": "shoot", "strike": {"phi": 0.0}})
    with pytest.raises(ValueError, match=r"action\.spin: unknown field"):
        g.check({"type": "shoot", "strike": {"phi": 0.0, "speed": 1.0}, "spin": 1})
    with pytest.raises(ValueError, match="action.choice"):
        g.check({"type": "decide", "choice": "forfeit"})
    with pytest.raises(ValueError, match="not float"):
        g.check(3.0)
    with pytest.raises(ValueError, match="known games: eight_ball, nine_ball, snooker"):
        Game("bowls")
    with pytest.raises(ValueError, match="table"):
        Game("nine_ball", table="10ft")
    with pytest.raises(ValueError, match="noise"):
        Game("nine_ball", noise="loud")
    with pytest.raises(ValueError, match="breaker"):
        Game("nine_ball", breaker=2)
    with pytest.raises(ValueError, match="seed"):
        Game("nine_ball", seed=-1)


def test_dicts_and_objects_are_the_same_actions():
    shot = Shot(phi=3.0, theta=0.0, speed=9.0, a=0.1, b=-0.2)
    assert breakshot.action_from_dict(shot.to_dict()) == shot
    assert breakshot.action_from_dict({"type": "shoot", "strike": {"phi": 3.0, "speed": 9.0,
                                       "a": 0.1, "b": -0.2}}) == shot
    a, b = Game("nine_ball", seed=4), Game("nine_ball", seed=4)
    oa = a.apply(shot)
    ob = b.apply(shot.to_dict())
    assert a.record() == b.record()
    assert oa.events == ob.events and oa.ruling == ob.ruling


def test_outcome_of_a_break():
    g = Game("nine_ball", seed=2)
    g.apply(PlaceCue(0.5, 0.635))
    out = g.apply(Shot(0.0, 0.0, 8.0))
    assert out.index == 1 and out.player == 0
    assert out.events[0] == {"time": 0.0, "type": "cue_strike", "balls": [0]}
    assert out.facts["first_hit"] == 1  # the apex ball sits on the aim line
    assert out.text == json.loads(g.record())["actions"][1]["ruling"]["text"]
    assert out.state == g.state
    # Without noise the executed strike is the intended one.
    assert out.intended == Shot(0.0, 0.0, 8.0).to_dict()["strike"]
    assert out.action == Shot(0.0, 0.0, 8.0)
    pocketed = [e["balls"][0] for e in out.events if e["type"] == "ball_pocket"]
    assert pocketed == out.facts["pocketed"]


def test_take_back_returns_to_the_earlier_state():
    g = Game("eight_ball", seed=5)
    p = Player("baseline")
    for _ in range(4):
        g.apply(p.decide(g))
    record4 = g.record()
    s2 = g.state_before(2)
    g.take_back(2)
    assert g.actions == 2 and g.state.to_dict() == s2.to_dict()
    for _ in range(2):
        g.apply(p.decide(g))
    assert g.record() == record4  # the seeds follow the action index
    with pytest.raises(ValueError):
        g.take_back(5)


def test_a_noisy_shot_records_intended_and_executed():
    g = Game("nine_ball", seed=9, noise="tournament")
    g.apply(PlaceCue(0.5, 0.635))
    out = g.apply(Shot(0.0, 0.0, 8.0))
    assert out.intended == {"speed": 8.0, "phi": 0.0, "theta": 0.0, "a": 0.0, "b": 0.0}
    assert out.action != Shot(0.0, 0.0, 8.0)
    assert g.noise == ("tournament", "tournament")


# -- records and the CLI -------------------------------------------------------


@pytest.mark.parametrize("name", ["eight_ball", "nine_ball"])
def test_a_game_played_from_python_replays_with_the_cli(name, tmp_path, run_cli):
    players = [Player("baseline"), Player("baseline", seed=99)]
    g = Game(name, seed=21, players=("ann", "bob"), noise="tournament")
    play_out(g, players)
    assert g.over and g.state.phase == "game_over"
    path = tmp_path / "game.json"
    g.save(path)
    r = run_cli("replay", path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert f"replayed {g.actions} actions: identical" in r.stdout
    if g.winner is not None:
        assert f"({('ann', 'bob')[g.winner]})" in r.stdout
    again = Game.from_record(path)
    assert again.record() == g.record() and again.state == g.state
    assert Game.from_record(g.record()).record() == g.record()


def test_a_record_that_does_not_replay_is_refused(tmp_path):
    g = Game("nine_ball", seed=3)
    g.play([Player("baseline")] * 2, max_actions=3)
    doc = json.loads(g.record())
    # A ruling that the rules do not give (its words are not compared:
    # records keep replaying when the wording changes).
    ruling = doc["actions"][1]["ruling"]
    ruling["turn_continues"] = not ruling["turn_continues"]
    with pytest.raises(ValueError, match="does not replay"):
        Game.from_record(json.dumps(doc))
    worded = json.loads(g.record())
    worded["actions"][1]["ruling"]["text"] = "something else"
    assert Game.from_record(json.dumps(worded)).state == g.state
    with pytest.raises(ValueError, match="invalid record"):
        Game.from_record('{"format": "nope"}')
    # A game read from a record goes on.
    h = Game.from_record(g.record())
    h.play([Player("baseline")] * 2)
    assert h.over


def test_decide_and_apply_play_the_match_runners_games(tmp_path, run_cli):
    """Game g of `breakshot match --seed S` is Game(seed=mix_seed(S, g),
    breaker=g % 2) with Player objects deciding from the game's stream."""
    for game, names, noise in [("nine_ball", ("baseline", "club"), "none"),
                               ("eight_ball", ("baseline", "baseline"), "tournament")]:
        out = tmp_path / game
        run_cli("match", "--game", game, "--players", ",".join(names), "--games", "2",
                "--seed", "5", "--noise", noise, "--records", out, check=True)
        players = [Player(n) for n in names]
        for k in range(2):
            g = Game(game, seed=breakshot.mix_seed(5, k), breaker=k % 2, players=players,
                     noise=noise)
            play_out(g, players)
            assert g.record() == (out / f"game-{k + 1:04d}.json").read_text()


# -- players and matches -------------------------------------------------------


def test_players():
    b = Player("baseline")
    assert b.name == "baseline" and b.noise is None and b.seed is None
    c = Player("club", seed=3, threads=1)
    assert c.noise == "1.6x" and c.threads == 1 and "club" in repr(c)
    assert Player("champion").noise == "tournament"
    with pytest.raises(ValueError, match="known players: baseline, beginner"):
        Player("grandmaster")
    with pytest.raises(ValueError, match="threads"):
        Player("club", threads=0)
    g = Game("nine_ball", seed=1)
    # A player's own seed gives its own stream; None gives the game's.
    assert b.decision_seed(g) == g.player_seed
    assert Player("baseline", seed=3).decision_seed(g) != g.player_seed
    done = play_out(Game("nine_ball", seed=1), [b, b])
    with pytest.raises(ValueError, match="over"):
        b.decide(done)


def test_ai_decisions_do_not_depend_on_threads():
    g = Game("nine_ball", seed=8)
    g.play([Player("baseline")] * 2, max_actions=2)
    if not g.over:
        assert Player("amateur", threads=1).decide(g) == Player("amateur", threads=2).decide(g)


@pytest.mark.parametrize("game,players,games,seed,noise,table", [
    ("eight_ball", ("baseline", "baseline"), 3, 7, "tournament", "9ft"),
    ("nine_ball", ("baseline", "beginner"), 3, 2, "none", "7ft"),
])
def test_match_summary_equals_the_cli(game, players, games, seed, noise, table, run_cli,
                                      tmp_path):
    r = run_cli("match", "--game", game, "--players", ",".join(players), "--games", games,
                "--seed", seed, "--noise", noise, "--table", table, "--records",
                tmp_path / "cli", check=True)
    text = breakshot.match_json(game, players, games, seed, noise, table,
                                records=tmp_path / "py")
    assert text == r.stdout
    summary = breakshot.match(game, players, games, seed, noise, table)
    assert summary == json.loads(r.stdout)
    assert summary["games_played"] == games
    for k in range(games):
        name = f"game-{k + 1:04d}.json"
        assert (tmp_path / "py" / name).read_text() == (tmp_path / "cli" / name).read_text()


def test_match_argument_errors():
    with pytest.raises(ValueError, match="games"):
        breakshot.match("nine_ball", ("baseline", "baseline"), games=0)
    with pytest.raises(ValueError, match="unknown player"):
        breakshot.match("nine_ball", ("baseline", "nobody"))
    with pytest.raises(ValueError, match="noise"):
        breakshot.match("nine_ball", ("baseline", "baseline"), noise="loud")
