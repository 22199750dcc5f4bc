"""Games and matches with the physics to choose: the keywords
give the command's bytes (``breakshot match --cushion-model ...``), the
records carry the physics and replay with the command, and bad values are
ValueErrors naming the field."""

from __future__ import annotations

import json

import pytest

import breakshot as bs

MATHAVAN = {"cushion_model": "mathavan_2010",
            "ball_ball_friction": {"a": 0.016, "b": 0.219, "c": 0.691}}


def test_default_physics_is_the_engines_and_not_in_the_summary(run_cli):
    g = bs.Game("nine_ball", seed=3)
    assert g.physics == bs.physics_of()
    assert g.physics == {"cushion_model": "han_2005", "ball_ball_model": "friction",
                         "ball_ball_friction": {"a": 0.016, "b": 0.219, "c": 0.691},
                         "airborne": True, "spinning_friction": 0.0117}
    text = bs.match_json("nine_ball", ["baseline", "baseline"], seed=3, noise="tournament")
    assert "physics" not in text
    # The default physics by its names: the same bytes.
    assert bs.match_json("nine_ball", ["baseline", "baseline"], seed=3, noise="tournament",
                         physics=bs.physics_of()) == text
    # The legacy physics is named, and it equals the command's.
    legacy = bs.physics_of("han_2005_v0", "friction", "tpa28", airborne=False,
                           spinning_friction="legacy")
    old = bs.match_json("nine_ball", ["baseline", "baseline"], seed=3, noise="tournament",
                        physics=legacy)
    # A summary, as a record, writes "airborne" only when true and
    # "spinning_friction" only when it is not the legacy 0.044.
    assert legacy["airborne"] is False and legacy["spinning_friction"] == 0.044
    assert json.loads(old)["physics"] == {k: v for k, v in legacy.items()
                                          if k not in ("airborne", "spinning_friction")}
    cli = run_cli("match", "--game", "nine_ball", "--players", "baseline,baseline",
                  "--games", "1", "--seed", "3", "--noise", "tournament",
                  "--cushion-model", "han_2005_v0", "--ball-ball-friction", "tpa28",
                  "--airborne", "off", "--spinning-friction", "legacy", check=True)
    assert old == cli.stdout
    # The preset by its name: the same physics, the same bytes.
    assert bs.physics_of(preset="legacy") == legacy
    assert bs.Game("nine_ball", seed=3, physics="legacy").physics == legacy
    assert bs.match_json("nine_ball", ["baseline", "baseline"], seed=3, noise="tournament",
                         physics="legacy") == old
    preset = run_cli("match", "--game", "nine_ball", "--players", "baseline,baseline",
                     "--games", "1", "--seed", "3", "--noise", "tournament",
                     "--physics", "legacy", check=True)
    assert preset.stdout == old
    assert bs.physics_of(preset="default") == bs.physics_of()


def test_an_argument_given_with_a_preset_wins_over_it(run_cli):
    mixed = bs.physics_of(airborne=True, preset="legacy")
    assert mixed == dict(bs.physics_of(preset="legacy"), airborne=True)
    text = bs.match_json("nine_ball", ["baseline", "baseline"], seed=3, noise="tournament",
                         physics=mixed)
    cli = run_cli("match", "--game", "nine_ball", "--players", "baseline,baseline",
                  "--games", "1", "--seed", "3", "--noise", "tournament",
                  "--physics", "legacy", "--airborne", "on", check=True)
    assert text == cli.stdout
    with pytest.raises(ValueError, match="preset: unknown physics preset 'modern'"):
        bs.physics_of(preset="modern")
    with pytest.raises(ValueError, match="physics: expected a dict, a preset name "
                                         r"\(default or legacy\) or None, not 'modern'"):
        bs.Game("nine_ball", physics="modern")


def test_match_with_other_physics_equals_the_cli_and_replays(tmp_path, run_cli):
    text = bs.match_json("nine_ball", ["baseline", "baseline"], seed=3, noise="tournament",
                         physics=MATHAVAN, records=tmp_path / "py")
    cli = run_cli("match", "--game", "nine_ball", "--players", "baseline,baseline",
                  "--games", "1", "--seed", "3", "--noise", "tournament",
                  "--cushion-model", "mathavan_2010", "--ball-ball-friction", "tpb3",
                  "--records", tmp_path / "cli", check=True)
    assert text == cli.stdout
    summary = json.loads(text)
    assert summary["physics"] == bs.physics_of("mathavan_2010", ball_ball_friction="tpb3")
    record = (tmp_path / "py" / "game-0001.json").read_text()
    assert record == (tmp_path / "cli" / "game-0001.json").read_text()
    head = json.loads(record)
    assert head["version"] == 2
    assert head["engine"] == {"version": bs.__version__}
    assert head["physics"]["cushion_model"] == "mathavan_2010"
    r = run_cli("replay", tmp_path / "py" / "game-0001.json")
    assert r.returncode == 0, r.stdout + r.stderr


def test_game_with_other_physics_records_it():
    g = bs.Game("eight_ball", seed=5, physics={"cushion_model": "han_2005",
                                               "ball_ball_model": "mathavan_2014",
                                               "ball_ball_friction": 0.06})
    assert g.physics == {"cushion_model": "han_2005", "ball_ball_model": "mathavan_2014",
                         "ball_ball_friction": 0.06, "airborne": True,
                         "spinning_friction": 0.0117}
    # Fields left out keep their defaults.
    h = bs.Game("eight_ball", seed=5, physics={"cushion_model": "mathavan_2010"})
    assert h.physics["ball_ball_model"] == "friction"
    assert h.physics["ball_ball_friction"] == {"a": 0.016, "b": 0.219, "c": 0.691}


@pytest.mark.parametrize("physics, message", [
    ({"cushion_model": "han_2006"}, "physics.cushion_model: unknown cushion model"),
    ({"ball_ball_model": "hertz"}, "physics.ball_ball_model: unknown ball-ball model"),
    ({"ball_ball_friction": {"a": 0.5, "b": 0.9, "c": 1}}, "physics.ball_ball_friction.b"),
    ({"ball_ball_friction": -1}, "physics.ball_ball_friction"),
    ({"jump": True}, "physics.jump: unknown field"),
    ({"spinning_friction": 0}, "physics.spinning_friction: must be > 0"),
    ({"spinning_friction": "fast"}, "physics.spinning_friction"),
    ("mathavan_2010", "physics: expected a dict"),
])
def test_bad_physics_is_a_value_error_naming_the_field(physics, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(".", r"\.")):
        bs.Game("nine_ball", physics=physics)
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(".", r"\.")):
        bs.match("nine_ball", ["baseline", "baseline"], physics=physics)


def test_physics_of_names_the_curves():
    assert bs.physics_of(ball_ball_friction="tpb3")["ball_ball_friction"] == \
        {"a": 0.016, "b": 0.219, "c": 0.691}
    with pytest.raises(ValueError, match="ball_ball_friction"):
        bs.physics_of(ball_ball_friction="tpb4")


def test_physics_of_names_the_spinning_friction_and_the_game_plays_it(run_cli):
    assert bs.physics_of()["spinning_friction"] == 0.0117
    assert bs.physics_of(spinning_friction="legacy")["spinning_friction"] == 0.044
    with pytest.raises(ValueError, match="spinning_friction"):
        bs.physics_of(spinning_friction="slow")
    # A game on the legacy spinning friction: its physics says so, its
    # summary equals the command's, and it differs from the measured one's.
    g = bs.Game("nine_ball", seed=4, physics={"spinning_friction": 0.044})
    assert g.physics["spinning_friction"] == 0.044
    text = bs.match_json("nine_ball", ["baseline", "baseline"], seed=4, noise="tournament",
                         physics=bs.physics_of(spinning_friction="legacy"))
    cli = run_cli("match", "--game", "nine_ball", "--players", "baseline,baseline",
                  "--games", "1", "--seed", "4", "--noise", "tournament",
                  "--spinning-friction", "legacy", check=True)
    assert text == cli.stdout
    assert json.loads(text)["physics"] == {k: v for k, v in bs.physics_of().items()
                                           if k != "spinning_friction"}
