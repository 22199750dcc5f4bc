"""breakshot.pot_chance and breakshot.pot_map: a ball in the jaws drops, a
boxed-in ball cannot be potted, the grid is the same for any thread count,
bad arguments are refused by name, and plot.pot_map draws the map."""

import math

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import breakshot  # noqa: E402

R = 0.028575
LENGTH, WIDTH = 2.54, 1.27  # a 9 ft table's playing surface


def jaws(d_obj=0.08, d_cue=0.5):
    """9-ball: the 1 d_obj from the top-right pocket's centre on the line
    toward (1.2, 0.5), the cue ball d_cue behind it on the same line."""
    table = breakshot._core.pool_table("9ft")
    name, px, py, _ = table["pockets"][3]
    assert name == "top_right"
    u = np.array([1.2 - px, 0.5 - py])
    u /= np.linalg.norm(u)
    obj = np.array([px, py]) + u * d_obj
    cue = obj + u * d_cue
    position = {"game": "nine_ball", "balls": {1: tuple(obj), 9: (0.5, 0.9)}}
    return position, tuple(cue)


def boxed():
    """The 1 in mid-table in a tight ring of six balls."""
    c = np.array([LENGTH / 2, WIDTH / 2])
    balls = {1: tuple(c)}
    for k in range(6):
        a = k * math.pi / 3
        balls[2 + k] = tuple(c + (2 * R + 0.0005) * np.array([math.cos(a), math.sin(a)]))
    return {"game": "nine_ball", "balls": balls}


def test_table_geometry():
    t = breakshot._core.pool_table("9ft")
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


def test_grid_is_the_same_for_any_thread_count():
    position, _ = jaws()
    kw = dict(nx=4, ny=3, samples=6, candidates=3, seed=3)
    one = breakshot.pot_map(position, 1, "top_right", "club", threads=1, **kw)
    two = breakshot.pot_map(position, 1, "top_right", "club", threads=2, **kw)
    assert one.probability.shape == (3, 4) and one.aims.shape == (3, 4, 5)
    for name in ("probability", "aims", "valid", "shots", "plays"):
        np.testing.assert_array_equal(getattr(one, name), getattr(two, name))
    assert one.kinds == two.kinds
    assert one.simulations == two.simulations > 0
    np.testing.assert_allclose(one.xs, (np.arange(4) + 0.5) * LENGTH / 4, rtol=1e-3)
    assert "PotMap" in repr(one) and "top_right" in repr(one)


def test_cells_where_the_cue_ball_cannot_go_are_zero():
    position, _ = jaws()
    nine = position["balls"][9]
    pm = breakshot.pot_map(position, 1, 3, "club", xs=[nine[0], 1.0, -0.2], ys=[nine[1]],
                           samples=4, candidates=2)
    assert pm.valid.tolist() == [[False, True, False]]
    assert pm.probability[0, 0] == 0.0 and pm.probability[0, 2] == 0.0
    assert np.isnan(pm.aims[0, 0]).all()
    assert not math.isnan(pm.probability[0, 1])
    assert pm.kinds[0][0] is None


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


def test_plot_pot_map(tmp_path):
    position, _ = jaws(d_obj=0.4)
    pm = breakshot.pot_map(position, 1, "top_right", "amateur", nx=6, ny=3, samples=4, seed=1)
    ax = breakshot.plot.pot_map(pm)
    meshes = [c for c in ax.collections if isinstance(c, matplotlib.collections.QuadMesh)]
    assert len(meshes) == 1
    drawn = np.ma.filled(meshes[0].get_array().astype(float), np.nan).ravel()
    np.testing.assert_array_equal(drawn, pm.probability.ravel())
    balls = [p for p in ax.patches if str(p.get_gid()).startswith("ball:")]
    assert sorted(p.get_gid() for p in balls) == ["ball:1", "ball:9"]
    ax.figure.savefig(tmp_path / "pot_map.png", dpi=80)
    assert (tmp_path / "pot_map.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    plt.close("all")
