"""Frames of a traced run and the plots of breakshot.plot: energy and
momentum against their closed forms, the traced result's bytes against the
CLI's, the plots' artists, PNG output, game positions on a table."""

import json
import math
import pathlib

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import breakshot  # noqa: E402
import breakshot.plot as bplot  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
TWO_BALLS = ROOT / "examples" / "lab" / "two_balls.json"
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def head_on(e=1.0):
    """An ideal head-on collision of unequal balls on a big table, well
    before either can reach a wall."""
    return {
        "physics": {"model": "ideal", "ball_ball_restitution": e},
        "table": {"shape": "rectangle", "min": [-2.0, -2.0], "max": [2.0, 2.0]},
        "balls": [
            {"id": "a", "position": [-0.5, 0.0], "velocity": [0.8, 0.0], "radius": 0.03,
             "mass": 0.2},
            {"id": "b", "position": [0.2, 0.0], "radius": 0.03, "mass": 0.5},
        ],
        "until": {"time": 2.0},
    }


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def test_traced_run_keeps_the_result_bytes(run_cli):
    plain = breakshot.simulate(TWO_BALLS)
    traced = breakshot.simulate(TWO_BALLS, trace=True)
    assert traced.to_json() == plain.to_json() == run_cli("simulate", TWO_BALLS).stdout
    assert plain.frames is None
    f = traced.frames
    assert isinstance(f, breakshot.Frames)
    m, n = len(f), 2
    assert f.ids == ["white", "black"]
    assert f.positions.shape == (m, n, 2) and f.velocities.shape == (m, n, 2)
    assert f.spins.shape == (m, n, 3) and f.energy.shape == (m, n)
    assert f.momentum.shape == (m, n, 2) and f.momentum_total.shape == (m, 2)
    # 2000 evenly spaced times from 0 to the end, plus every event's time.
    assert f.times[0] == 0.0 and f.times[-1] == 5.0
    assert np.all(np.diff(f.times) > 0)
    event_times = {e["time"] for e in traced.events}
    assert event_times <= set(f.times.tolist())
    assert m >= 2000
    # Fewer points on request.
    assert len(breakshot.simulate(TWO_BALLS, trace=50).frames) < 50 + len(event_times) + 1
    assert "frames=" in repr(traced) and "Frames" in repr(f)
    # The final frame is the result's final state.
    for i, ball in enumerate(traced.final["balls"]):
        assert list(f.positions[-1, i]) == ball["position"]


def test_energy_at_zero_is_the_closed_form():
    scenario = json.loads(TWO_BALLS.read_text())
    f = breakshot.simulate(scenario, trace=True).frames
    want = 0.0
    for b in scenario["balls"]:
        vx, vy = b["velocity"]
        want += 0.5 * b["mass"] * (vx * vx + vy * vy)  # ideal model: no spin
    assert f.energy_total[0] == pytest.approx(want, rel=1e-15)
    assert f.energy[0, 0] == pytest.approx(0.5 * 0.02 * (0.3**2 + 0.05**2), rel=1e-15)
    assert f.energy[0, 1] == 0.0


def test_energy_with_spin_is_translational_plus_rotational():
    # A pool stroke: after the strike at t = 0 the cue ball slides and spins.
    f = breakshot.simulate(ROOT / "examples" / "pool" / "draw_shot.json", trace=True).frames
    m, r = f.masses[0], f.radii[0]
    inertia = 0.4 * m * r * r
    for k in (0, len(f) // 7, len(f) // 3):
        v, w = f.velocities[k, 0], f.spins[k, 0]
        want = 0.5 * m * (v @ v) + 0.5 * inertia * (w @ w)
        assert f.energy[k, 0] == pytest.approx(want, rel=1e-12)
        assert f.energy_total[k] == pytest.approx(f.energy[k].sum(), rel=1e-12)
    assert np.any(f.spins[0, 0] != 0.0)


@pytest.mark.parametrize("e", [1.0, 0.6])
def test_momentum_is_conserved_across_a_collision(e):
    f = breakshot.simulate(head_on(e), trace=True).frames
    m1, m2, v = 0.2, 0.5, 0.8
    p = f.momentum_total
    before = f.times < 0.6 / v  # the gap of 0.64 m closes at t = 0.8 s
    after = f.times > 1.0
    assert before.any() and after.any()
    np.testing.assert_allclose(p[:, 0], m1 * v, rtol=1e-14)
    np.testing.assert_allclose(p[:, 1], 0.0, atol=1e-16)
    # Each ball after the collision: the closed form of a head-on impact.
    v1 = (m1 - e * m2) * v / (m1 + m2)
    v2 = (1 + e) * m1 * v / (m1 + m2)
    np.testing.assert_allclose(f.momentum[after, 0, 0], m1 * v1, rtol=1e-12)
    np.testing.assert_allclose(f.momentum[after, 1, 0], m2 * v2, rtol=1e-12)
    np.testing.assert_allclose(f.momentum[before, 0, 0], m1 * v, rtol=1e-15)
    # Energy: conserved for e = 1, lost by the closed-form amount otherwise.
    lost = 0.5 * m1 * m2 / (m1 + m2) * v * v * (1 - e * e)
    np.testing.assert_allclose(f.energy_total[after], 0.5 * m1 * v * v - lost, rtol=1e-12)


def data_lines(ax):
    return [ln for ln in ax.lines if len(ln.get_xdata()) > 0]


def test_trajectories_draws_each_ball(tmp_path):
    r = breakshot.simulate(TWO_BALLS, trace=True)
    ax = bplot.trajectories(r)
    lines = data_lines(ax)
    assert len(lines) == 2
    assert [ln.get_label() for ln in lines] == ["white", "black"]
    np.testing.assert_array_equal(lines[1].get_ydata(), r.frames.positions[:, 1, 1])
    circles = [p for p in ax.patches if isinstance(p, matplotlib.patches.Circle)]
    assert len(circles) == 4  # start and end of each ball
    assert circles[0].radius == 0.012
    assert ax.get_aspect() == 1.0
    texts = [t.get_text() for t in ax.get_legend().get_texts()]
    assert texts == ["white", "black", "start", "end"]
    out = tmp_path / "trajectories.png"
    ax.figure.savefig(out, dpi=80)
    assert out.read_bytes()[:8] == PNG_MAGIC


def test_energy_and_momentum_draw_total_and_balls(tmp_path):
    r = breakshot.simulate(TWO_BALLS, trace=True)
    ax = bplot.energy(r)
    lines = data_lines(ax)
    assert len(lines) == 3
    total = [ln for ln in lines if ln.get_label() == "total"]
    assert len(total) == 1 and total[0].get_linewidth() == 3.0
    np.testing.assert_array_equal(total[0].get_ydata(), r.frames.energy_total)
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["total", "white", "black"]
    ax.figure.savefig(tmp_path / "energy.png", dpi=80)
    axes = bplot.momentum(r)
    assert len(axes) == 2
    for k, a in enumerate(axes):
        lines = data_lines(a)
        assert len(lines) == 3
        np.testing.assert_array_equal(lines[0].get_ydata(), r.frames.momentum[:, 0, k])
    axes[0].figure.savefig(tmp_path / "momentum.png", dpi=80)
    for name in ("energy", "momentum"):
        assert (tmp_path / f"{name}.png").read_bytes()[:8] == PNG_MAGIC


def test_plots_draw_into_given_axes():
    r = breakshot.simulate(head_on(), trace=True)
    fig, axs = plt.subplots(2, 2)
    assert bplot.trajectories(r.frames, ax=axs[0, 0]) is axs[0, 0]
    assert bplot.energy(r, ax=axs[0, 1]) is axs[0, 1]
    got = bplot.momentum(r, ax=axs[1])
    assert got[0] is axs[1, 0] and got[1] is axs[1, 1]
    with pytest.raises(ValueError, match="pair"):
        bplot.momentum(r, ax=axs[0, 0])


def test_many_balls_show_ten_series_and_twenty_paths():
    f = breakshot.simulate(ROOT / "examples" / "pool" / "break_8ball.json", trace=200).frames
    assert len(f.ids) == 16
    ax = bplot.energy(f)
    assert len(data_lines(ax)) == 11  # the total and the first 10 balls
    assert ax.get_legend().get_texts()[-1].get_text() == "(6 more not shown)"
    assert len(data_lines(bplot.trajectories(f))) == 16


def test_result_without_frames_is_refused():
    r = breakshot.simulate(TWO_BALLS)
    for fn in (bplot.trajectories, bplot.energy, bplot.momentum):
        with pytest.raises(ValueError, match="trace=True"):
            fn(r)
    with pytest.raises(TypeError):
        bplot.energy({"balls": []})
    with pytest.raises(ValueError, match="trace"):
        breakshot.simulate(TWO_BALLS, trace=1)


def ball_patches(ax):
    return [p for p in ax.patches if str(p.get_gid()).startswith("ball:")]


def test_table_draws_every_ball(tmp_path):
    position = {"game": "nine_ball", "table": "9ft",
                "balls": {0: (0.6, 0.5), 1: (1.8, 0.7), 9: (2.1, 0.62), "5": (1.2, 1.1)}}
    ax = bplot.table(position)
    balls = ball_patches(ax)
    assert sorted(p.get_gid() for p in balls) == ["ball:0", "ball:1", "ball:5", "ball:9"]
    nine = next(p for p in balls if p.get_gid() == "ball:9")
    assert nine.center == (2.1, 0.62) and nine.radius == pytest.approx(0.028575)
    pockets = [p for p in ax.patches if str(p.get_gid()).startswith("pocket:")]
    assert len(pockets) == 6
    ax.figure.savefig(tmp_path / "table.png", dpi=80)
    assert (tmp_path / "table.png").read_bytes()[:8] == PNG_MAGIC
    # The other forms of a position.
    assert len(ball_patches(bplot.table([("cue", 0.5, 0.5), (3, 1.0, 0.5)]))) == 2
    listed = {"balls": [{"id": "cue", "position": [0.5, 0.5]}, {"id": "12", "position": [1, 1]}]}
    assert len(ball_patches(bplot.table(listed))) == 2
    arrays = {"game": "nine_ball", "positions": np.tile([[1.0, 0.6]], (10, 1)) +
              np.arange(10)[:, None] * [0.1, 0.0], "on_table": [1, 1, 0, 1, 0, 0, 0, 0, 0, 1]}
    assert len(ball_patches(bplot.table(arrays))) == 4

    class Game:
        state = position
    assert len(ball_patches(bplot.table(Game()))) == 4


def test_table_draws_a_game_being_played(tmp_path):
    game = breakshot.Game("eight_ball", table="7ft", seed=3)
    player = breakshot.Player("club")
    for _ in range(3):
        if game.over:
            break
        game.apply(player.decide(game))
    on = [i for i, f in enumerate(game.state.on_table) if f]
    for drawn in (game, game.state):
        balls = ball_patches(bplot.table(drawn))
        assert sorted(p.get_gid() for p in balls) == sorted(f"ball:{i}" for i in on)
        for p in balls:
            i = int(p.get_gid().split(":")[1])
            assert p.center == tuple(game.state.position[i])
    # The 7 ft table's outline, not the 9 ft default.
    ax = bplot.table(game)
    assert ax.get_xlim()[1] < 2.2
    ax.figure.savefig(tmp_path / "game.png", dpi=80)


def test_table_draws_a_racked_scenario():
    ax = bplot.table(ROOT / "examples" / "pool" / "break_9ball.json")
    assert len(ball_patches(ax)) == 10
    ax = bplot.table(TWO_BALLS)  # a lab table: its outline and its balls
    assert len(ball_patches(ax)) == 2


def test_table_refuses_bad_positions():
    with pytest.raises(ValueError, match="ball 12 is not a ball of nine_ball"):
        bplot.table({"game": "nine_ball", "balls": {12: (1, 1)}})
    with pytest.raises(ValueError, match="not 'white'"):
        bplot.table([("white", 1.0, 1.0)])
    with pytest.raises(ValueError, match="given twice"):
        bplot.table([(1, 1.0, 1.0), ("1", 1.2, 1.0)])
