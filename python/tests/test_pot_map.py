"""breakshot.pot_chance and breakshot.pot_map: a ball in the jaws drops and
a boxed-in ball cannot be potted in every game with pockets, what counts
as a pot is the game's ruling (the 8 early, a colour while on a red are
none), a game and its state are taken whole, no array holds NaN, the grid
is the same for any thread count, bad arguments are refused by name, and
plot.pot_map draws the map."""

import json
import math

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import breakshot  # noqa: E402

R = 0.028575
LENGTH, WIDTH = 2.54, 1.27  # a 9 ft table's playing surface


TABLES = {"eight_ball": "9ft", "nine_ball": "9ft", "ten_ball": "9ft", "snooker": "12ft"}


def straight(game="nine_ball", ball=1, other=9, d_obj=0.08, d_cue=0.5, **extra):
    """`ball` d_obj from the top-right pocket's centre on the line toward
    (1.2, 0.5), the cue ball d_cue behind it on the same line, `other` out
    of the way at (0.5, 0.9)."""
    table = breakshot._core.game_table(game, TABLES[game])
    name, px, py, _ = table["pockets"][3]
    assert name == "top_right"
    u = np.array([1.2 - px, 0.5 - py])
    u /= np.linalg.norm(u)
    obj = np.array([px, py]) + u * d_obj
    cue = obj + u * d_cue
    balls = {ball: tuple(obj)}
    if other is not None:
        balls[other] = (0.5, 0.9)
    return dict({"game": game, "balls": balls}, **extra), tuple(cue)


def jaws(d_obj=0.08, d_cue=0.5):
    """9-ball: the 1 in the jaws of the top-right pocket, the 9 away."""
    return straight("nine_ball", 1, 9, d_obj, d_cue)


def boxed(game="nine_ball", ring=range(2, 8)):
    """The 1 in mid-table in a tight ring of six balls."""
    table = breakshot._core.game_table(game, TABLES[game])
    r = table["ball_radius"]
    c = np.array([table["length"] / 2, table["width"] / 2])
    balls = {1: tuple(c)}
    for k, n in enumerate(ring):
        a = k * math.pi / 3
        balls[n] = tuple(c + (2 * r + 0.0005) * np.array([math.cos(a), math.sin(a)]))
    return {"game": game, "balls": balls}


# Each game with pockets: a ball it may pot first and a ball to keep out
# of the way (snooker: a red and the black).
GAMES = [("eight_ball", 3, 8), ("nine_ball", 1, 9), ("ten_ball", 1, 10), ("snooker", 1, 21)]


def test_table_geometry():
    t = breakshot._core.game_table("nine_ball", "9ft")
    assert (t["length"], t["width"]) == pytest.approx((LENGTH, WIDTH), abs=0.01)
    assert [p[0] for p in t["pockets"]] == [
        "bottom_left", "side_bottom", "bottom_right", "top_right", "side_top", "top_left"]


@pytest.mark.parametrize("level", ["club", "expert", "champion"])
def test_ball_in_the_jaws_drops(level):
    position, cue = jaws()
    c = breakshot.pot_chance(position, cue, 1, "top_right", level, samples=32, candidates=4)
    assert c["placeable"] and c["shots"] > 0 and c["plays"] == 32
    # The cue ball straight behind: 1.6 times tournament noise (0.2 degrees
    # of aim) cannot miss a pocket from 8 cm, and the draw these levels try
    # keeps the cue ball out of it.
    assert c["probability"] == 1.0
    assert c["kind"] == "direct"
    assert c["aim"][4] < 0.0
    phi = math.degrees(math.atan2(-(cue[1] - position["balls"][1][1]),
                                  -(cue[0] - position["balls"][1][0])))
    assert c["aim"][0] == pytest.approx(phi, abs=1.0)


def test_centre_ball_players_scratch_straight_in():
    # The beginner and the amateur only hit the centre of the cue ball: from
    # 0.5 m it follows the 1 into the pocket, so no shot of theirs pots it.
    position, cue = jaws()
    for level in ("beginner", "amateur"):
        c = breakshot.pot_chance(position, cue, 1, "top_right", level)
        assert c["placeable"] and c["shots"] == 0 and c["probability"] == 0.0


def test_long_cut_is_harder_than_the_jaws():
    position, _ = jaws(d_obj=1.0)
    far = breakshot.pot_chance(position, (0.3, 0.2), 1, 3, "amateur", samples=48)
    assert far["placeable"] and far["shots"] > 0
    assert 0.0 < far["probability"] < 1.0


def test_boxed_in_ball_gives_zero():
    for pocket in range(6):
        c = breakshot.pot_chance(boxed(), (0.4, 0.4), 1, pocket, "club", samples=8)
        assert c["placeable"] and c["shots"] == 0 and c["probability"] == 0.0


@pytest.mark.parametrize("game", ["nine_ball", "snooker"])
def test_grid_is_the_same_for_any_thread_count(game):
    position, _ = straight(game, 1, {"nine_ball": 9, "snooker": 21}[game])
    kw = dict(nx=4, ny=3, samples=6, candidates=3, seed=3)
    one = breakshot.pot_map(position, 1, "top_right", "club", threads=1, **kw)
    two = breakshot.pot_map(position, 1, "top_right", "club", threads=2, **kw)
    assert one.probability.shape == (3, 4) and one.aims.shape == (3, 4, 5)
    for name in ("valid", "shots", "plays"):
        np.testing.assert_array_equal(getattr(one, name), getattr(two, name))
    for name in ("probability", "aims"):
        a, b = getattr(one, name), getattr(two, name)
        np.testing.assert_array_equal(a.mask, b.mask)
        np.testing.assert_array_equal(a.data, b.data)
    assert one.kinds == two.kinds
    assert one.simulations == two.simulations > 0
    length = breakshot._core.game_table(game, TABLES[game])["length"]
    np.testing.assert_allclose(one.xs, (np.arange(4) + 0.5) * length / 4, rtol=1e-12)
    assert "PotMap" in repr(one) and "top_right" in repr(one)


def test_cells_where_the_cue_ball_cannot_go_are_masked():
    position, _ = jaws()
    nine = position["balls"][9]
    pm = breakshot.pot_map(position, 1, 3, "club", xs=[nine[0], 1.0, -0.2], ys=[nine[1]],
                           samples=4, candidates=2)
    assert pm.valid.tolist() == [[False, True, False]]
    assert isinstance(pm.probability, np.ma.MaskedArray)
    assert pm.probability.mask.tolist() == [[True, False, True]]
    assert pm.probability.filled(-1.0).tolist()[0][0] == -1.0
    assert not np.isnan(pm.probability.data).any() and not np.isnan(pm.aims.data).any()
    assert pm.aims.mask[0, 0].all() and pm.aims.mask[0, 2].all()
    assert pm.kinds[0][0] is None
    assert pm.mean() == float(pm.probability[0, 1]) == pm.probability.mean()


@pytest.mark.parametrize("game", ["nine_ball", "snooker"])
def test_no_nan_in_a_map_with_cells_on_a_ball_over_a_pocket_and_off_the_table(game):
    ball, other = {"nine_ball": (1, 9), "snooker": (1, 21)}[game]
    position, cue = straight(game, ball, other)
    obj = position["balls"][ball]
    _, px, py, _ = breakshot._core.game_table(game, TABLES[game])["pockets"][3]
    xs = [obj[0], px, -0.2, cue[0], 1.0]
    ys = [obj[1], py, cue[1]]
    pm = breakshot.pot_map(position, ball, "top_right", "club", xs=xs, ys=ys, samples=4,
                           candidates=2, seed=9)
    for name in ("probability", "aims"):
        data = np.ma.getdata(getattr(pm, name))
        assert np.isfinite(data).all(), name
    np.testing.assert_array_equal(pm.probability.mask, ~pm.valid)
    aimed = pm.valid & (pm.shots > 0)
    np.testing.assert_array_equal(pm.aims.mask, np.repeat(~aimed[..., None], 5, axis=-1))
    assert not pm.valid[0, 0] and not pm.valid[1, 1] and not pm.valid[:, 2].any()
    assert pm.valid[2, 3] and pm.probability[2, 3] > 0
    assert (pm.shots[~pm.valid] == 0).all() and (pm.plays[~pm.valid] == 0).all()
    assert 0.0 <= pm.mean() <= 1.0


@pytest.mark.parametrize("game,ball,other", GAMES)
def test_straight_pot_in_every_game_and_a_boxed_ball_in_none(game, ball, other):
    position, cue = straight(game, ball, other)
    c = breakshot.pot_chance(position, cue, ball, "top_right", "champion", samples=16,
                             candidates=2, seed=5)
    assert c["placeable"] and c["shots"] > 0 and c["plays"] == 16
    assert c["kind"] == "direct"
    # The champion's aim noise cannot make the ball miss a pocket from 8
    # cm; a play may still be spoilt by the cue ball following it in.
    assert c["probability"] >= 0.9
    assert not math.isnan(sum(c["aim"]))
    for pocket in range(6):
        b = breakshot.pot_chance(boxed(game), (0.4, 0.4), 1, pocket, "club", samples=8)
        assert b["shots"] == 0 and b["probability"] == 0.0 and b["plays"] == 0


def test_the_eight_before_its_time_is_no_pot():
    # Solids to shoot with the 3 still up: the 8 early loses the game.
    position, cue = straight("eight_ball", 8, 3, groups=["solids", "stripes"])
    early = breakshot.pot_chance(position, cue, 8, "top_right", "champion", samples=16,
                                 candidates=2)
    assert early["shots"] == 0 and early["probability"] == 0.0
    del position["balls"][3]
    due = breakshot.pot_chance(position, cue, 8, "top_right", "champion", samples=16,
                               candidates=2)
    assert due["shots"] > 0 and due["probability"] >= 0.9


def test_snooker_colour_while_on_a_red_is_no_pot():
    # The blue in the jaws, a red up the table: on a red, the blue is a
    # foul; after a red (colour_on) it is the ball on, nominated.
    position, cue = straight("snooker", 19, 1)
    on_red = breakshot.pot_chance(position, cue, 19, "top_right", "champion", samples=16,
                                  candidates=2)
    assert on_red["shots"] == 0 and on_red["probability"] == 0.0
    on_colour = breakshot.pot_chance(dict(position, colour_on=True), cue, 19, "top_right",
                                     "champion", samples=16, candidates=2)
    assert on_colour["shots"] > 0 and on_colour["probability"] >= 0.9
    # The reds gone, the lowest colour is on: the yellow is, the blue not.
    colours = dict(position, balls={19: position["balls"][19], 16: (0.5, 0.9)})
    assert breakshot.pot_chance(colours, cue, 19, 3, "club", samples=4)["shots"] == 0


def test_a_game_and_its_state_are_taken_whole():
    game = breakshot.Game("snooker", seed=4)
    player = breakshot.Player("club")
    while game.state.phase != "shot" or game.state.ball_in_hand != "none":
        game.apply(player.decide(game))
    state = game.state
    reds = [n for n in range(1, 16) if state.on_table[n]]
    kw = dict(xs=[0.6, 1.8], ys=[0.5, 1.2], samples=4, candidates=2, seed=2)
    from_game = breakshot.pot_map(game, reds[0], 0, "club", **kw)
    from_state = breakshot.pot_map(state, reds[0], 0, "club", **kw)
    from_dict = breakshot.pot_map(dict(state.to_dict(), table="12ft"), reds[0], 0, "club", **kw)
    for other in (from_state, from_dict):
        np.testing.assert_array_equal(from_game.probability, other.probability)
        np.testing.assert_array_equal(from_game.aims.filled(0), other.aims.filled(0))
        assert from_game.simulations == other.simulations
    assert from_game.position["state"] is not None
    assert from_game.table["pockets"][0][0] == "bottom_left"
    assert from_game.ball_radius == pytest.approx(0.02625)
    # The position is the game's state itself, snooker's part included.
    assert json.loads(from_game.position["state"]) == state.to_dict()


def test_bad_arguments_name_what_is_wrong():
    position, cue = jaws()
    with pytest.raises(ValueError, match="ball 12"):
        breakshot.pot_chance(position, cue, 12, 3, "club")
    with pytest.raises(ValueError, match="ball 4 is not on the table"):
        breakshot.pot_map(position, 4, 3, "club", nx=2, ny=2)
    with pytest.raises(ValueError, match="pocket 6 is out of range"):
        breakshot.pot_chance(position, cue, 1, 6, "club")
    with pytest.raises(ValueError, match="unknown pocket 'corner'"):
        breakshot.pot_map(position, 1, "corner", "club", nx=2, ny=2)
    with pytest.raises(ValueError, match='unknown AI level "grandmaster"'):
        breakshot.pot_map(position, 1, 3, "grandmaster", nx=2, ny=2)
    with pytest.raises(ValueError, match="samples"):
        breakshot.pot_map(position, 1, 3, "club", nx=2, ny=2, samples=-1)
    with pytest.raises(ValueError, match="overlap"):
        breakshot.pot_map({"balls": {1: (1.0, 0.5), 2: (1.01, 0.5)}}, 1, 3, "club")
    with pytest.raises(ValueError, match="empty"):
        breakshot.pot_map(position, 1, 3, "club", xs=[], ys=[0.5])
    # Where the cue ball cannot lie, pot_chance says why.
    with pytest.raises(ValueError, match=r"cannot be placed at \(0.5, 0.9\).*overlap ball 9"):
        breakshot.pot_chance(position, (0.5, 0.9), 1, 3, "club")
    with pytest.raises(ValueError, match="cannot be placed.*playing surface"):
        breakshot.pot_chance(position, (-0.2, 0.5), 1, 3, "club")
    # Games.
    carom = {"game": "three_cushion", "balls": {0: (0.5, 0.5), 1: (1.0, 0.5), 2: (1.5, 0.7)}}
    with pytest.raises(ValueError, match="pot maps need a table with pockets; three_cushion"):
        breakshot.pot_chance(carom, (0.3, 0.3), 2, 0, "club")
    with pytest.raises(ValueError, match="pot maps need a table with pockets"):
        breakshot.pot_map(breakshot.Game("three_cushion"), 2, 0, "club", nx=2, ny=2)
    with pytest.raises(ValueError, match="unknown game 'pyramid'"):
        breakshot.pot_map({"game": "pyramid", "balls": {1: (1, 0.5)}}, 1, 3, "club")
    with pytest.raises(ValueError, match="ball 22 is not a ball of snooker"):
        breakshot.pot_map({"game": "snooker", "balls": {22: (1, 0.5)}}, 1, 3, "club")
    with pytest.raises(ValueError, match="ten_ball has 11 balls; positions has 10"):
        breakshot.pot_map({"game": "ten_ball", "positions": np.ones((10, 2))}, 1, 3, "club")
    with pytest.raises(ValueError, match="ball 10 is not on the table"):
        breakshot.pot_chance({"game": "ten_ball", "balls": {1: (1.0, 0.5)}}, (0.4, 0.4), 10, 3,
                             "club")
    with pytest.raises(ValueError, match="does not lie on the playing surface"):
        breakshot.pot_map({"game": "snooker", "balls": {1: (5.0, 0.5)}}, 1, 3, "club")
    with pytest.raises(ValueError, match="groups are 8-ball's"):
        breakshot.pot_map(dict(position, groups=["solids", "stripes"]), 1, 3, "club")
    with pytest.raises(ValueError, match="colour_on is snooker's"):
        breakshot.pot_map(dict(position, colour_on=True), 1, 3, "club")
    with pytest.raises(ValueError, match="score must be two"):
        breakshot.pot_map({"game": "snooker", "balls": {1: (1, 0.5)}, "score": [3]}, 1, 3,
                          "club")
    with pytest.raises(ValueError, match="phase shot"):
        breakshot.pot_map(breakshot.Game("nine_ball"), 1, 3, "club", nx=2, ny=2)


def test_plot_pot_map(tmp_path):
    position, _ = jaws(d_obj=0.4)
    pm = breakshot.pot_map(position, 1, "top_right", "amateur", nx=6, ny=3, samples=4, seed=1)
    ax = breakshot.plot.pot_map(pm)
    meshes = [c for c in ax.collections if isinstance(c, matplotlib.collections.QuadMesh)]
    assert len(meshes) == 1
    drawn = meshes[0].get_array()
    np.testing.assert_array_equal(np.ma.getmaskarray(drawn).ravel(), ~pm.valid.ravel())
    np.testing.assert_array_equal(drawn.compressed(), pm.probability.compressed())
    balls = [p for p in ax.patches if str(p.get_gid()).startswith("ball:")]
    assert sorted(p.get_gid() for p in balls) == ["ball:1", "ball:9"]
    ax.figure.savefig(tmp_path / "pot_map.png", dpi=80)
    assert (tmp_path / "pot_map.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    plt.close("all")


def test_plot_snooker_pot_map(tmp_path):
    position, _ = straight("snooker", 19, 1, colour_on=True)
    position["balls"].update({2: (2.6, 1.0), 21: (3.24, 0.889)})
    table = breakshot._core.game_table("snooker", "12ft")
    xs = [0.2, 0.9, 1.6, 2.3, 3.0]
    pm = breakshot.pot_map(position, 19, "top_right", "club", xs=xs, ys=[0.3, 0.9, 1.5],
                           samples=4, candidates=2)
    ax = breakshot.plot.pot_map(pm)
    balls = sorted(p.get_gid() for p in ax.patches if str(p.get_gid()).startswith("ball:"))
    assert balls == ["ball:1", "ball:19", "ball:2", "ball:21"]
    blue = next(p for p in ax.patches if p.get_gid() == "ball:19")
    assert blue.radius == pytest.approx(table["ball_radius"])
    assert "the blue in the top right pocket" in ax.get_title(loc="left")
    assert ax.get_xlim()[1] > table["length"]
    ax.figure.savefig(tmp_path / "snooker.png", dpi=80)
    plt.close("all")
