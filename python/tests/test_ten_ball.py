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


def test_a_shot_the_ten_ball_rules_refuse_raises_and_loses_nothing():
    g = bs.Game("ten_ball", seed=3)
    players = [bs.Player("club"), bs.Player("club")]
    # The break and what follows, until a shot that must be called is due.
    for _ in range(40):
        la = g.legal_actions()
        if g.over or (la.call and not la.must_place and not la.push_out):
            break
        g.apply(players[g.state.player].decide(g))
    assert not g.over
    assert g.legal_actions().call
    before = g.record()
    n = g.actions
    uncalled = bs.Shot(phi=0.0, theta=5.0, speed=2.0)
    reason = g.check(uncalled)
    assert reason is not None and "call" in reason
    try:
        g.apply(uncalled)
    except ValueError as e:
        assert "call" in str(e)
    else:
        raise AssertionError("an uncalled 10-ball shot was played")
    # Nothing already played is lost: the record and the count are as before.
    assert g.actions == n
    assert g.record() == before
    # A called shot at the lowest ball is taken.
    lowest = g.state.lowest_ball
    assert g.check(bs.Shot(phi=0.0, theta=5.0, speed=2.0, call=(lowest, 0))) is None
