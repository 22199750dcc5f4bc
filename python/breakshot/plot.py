"""Plots for notebooks, with matplotlib.

``trajectories``, ``energy`` and ``momentum`` draw what ``breakshot
simulate --plot`` draws as SVG (src/io/svg_plot.cpp): the balls' paths on
the table, kinetic energy against time and linear momentum against time,
each ball in the same colour in all three, with the system total in black.
They take a result of ``breakshot.simulate(scenario, trace=True)`` (or its
``frames``). ``table`` draws a game position: the game's table (a pool
table with its pockets, the snooker table with its markings) and the balls
in their colours. ``pot_map`` draws a breakshot.PotMap as a heat map on the
table.

Every function draws into ``ax`` when given (a new figure otherwise) and
returns the axes it drew on. This module imports matplotlib; ``import
breakshot`` does not.
"""

from __future__ import annotations

from collections.abc import Mapping

import matplotlib.pyplot as plt
import numpy as np
from matplotlib import patches
from matplotlib.collections import PatchCollection
from matplotlib.colors import LinearSegmentedColormap

from . import _core
from ._position import game_position
from .frames import Frames
from .result import Result

__all__ = ["trajectories", "energy", "momentum", "table", "pot_map", "PALETTE", "BALL_COLOURS"]

# The SVG plots' palette: tab10, then its light companions, so the first 20
# balls get distinct colours and a ball has the same colour in every plot.
PALETTE = (
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf",
    "#aec7e8", "#ffbb78", "#98df8a", "#ff9896", "#c5b0d5",
    "#c49c94", "#f7b6d2", "#c7c7c7", "#dbdb8d", "#9edae5",
)
_OTHER = "#a0a0a0"
# Limits of the SVG plots: paths of at most 20 balls; time plots show every
# ball up to 12, else the first 10 (and always the total).
_MAX_PATHS = 20
_MAX_SERIES_ALL = 12
_MAX_SERIES_SOME = 10

# Pool balls by number: the cue ball white, 1-8 solid, 9-15 striped in the
# colours of 1-7.
BALL_COLOURS = {
    0: "#f8f6ec", 1: "#f2c500", 2: "#1f4fb4", 3: "#d0261d", 4: "#5b2d8e",
    5: "#f07d16", 6: "#16804a", 7: "#8c1c22", 8: "#141414",
}
for _n in range(9, 16):
    BALL_COLOURS[_n] = BALL_COLOURS[_n - 8]

# Snooker's balls by number: the cue ball, the reds 1-15, then the colours
# 16-21 (game.hpp's numbering).
_SNOOKER_COLOURS = {0: "#f8f6ec", **{n: "#c1121f" for n in range(1, 16)},
                    16: "#f5d000", 17: "#127a3c", 18: "#6b3a1e", 19: "#1f4fb4",
                    20: "#f29bb8", 21: "#141414"}
_SNOOKER_NAMES = {16: "yellow", 17: "green", 18: "brown", 19: "blue", 20: "pink", 21: "black"}

_CLOTH = "#2f7d4f"
_RAIL = "#5a3620"
_PLAY = "#e3f1e3"     # the lab's playing surface, as in the SVG
_OUTLINE = "#2f5d2f"


def _frames(result) -> Frames:
    if isinstance(result, Frames):
        return result
    if isinstance(result, Result):
        if result.frames is None:
            raise ValueError(
                "this result has no frames to plot: run it with "
                "breakshot.simulate(scenario, trace=True)")
        return result.frames
    raise TypeError(
        "plots take a result of breakshot.simulate(scenario, trace=True) or its frames, "
        f"not {type(result).__name__}")


def _axes(ax, **fig_kw):
    if ax is not None:
        return ax
    _, ax = plt.subplots(**fig_kw)
    return ax


def _plural(n, word):
    return f"{n} {word}" + ("" if n == 1 else "s")


def _time_range(f: Frames) -> str:
    if len(f) == 0:
        return "no frames"
    return f"t = {f.times[0]:.6g} to {f.times[-1]:.6g} s"


def _shown(n):
    return n if n <= _MAX_SERIES_ALL else _MAX_SERIES_SOME


def _legend_outside(ax, **kw):
    return ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0,
                     frameon=True, fontsize="small", **kw)


def _style(ax, grid=True):
    ax.set_axisbelow(True)
    if grid:
        ax.grid(True, color="#e4e4e4", linewidth=0.8)
    for s in ax.spines.values():
        s.set_color("#666666")
    ax.tick_params(colors="#333333", direction="out")


def _title(ax, title, subtitle):
    ax.set_title(f"{title}\n", loc="left", fontweight="bold", fontsize="medium")
    ax.text(0.0, 1.02, subtitle, transform=ax.transAxes, fontsize="small", color="#444444",
            va="bottom", ha="left")


def trajectories(result, ax=None):
    """The balls' paths on the table (the CLI's PREFIX-trajectories.svg).

    Each ball's path in its colour, a hollow circle at true radius where it
    starts and a filled one where it ends; the table's outline in green.
    Paths of the first 20 balls; the others' end positions in grey. Equal
    aspect, so a circle is round. ``result`` is a result of
    ``breakshot.simulate(scenario, trace=True)`` or its ``frames``. Returns
    the axes.
    """
    f = _frames(result)
    ax = _axes(ax, figsize=(8.0, 5.5), layout="constrained")
    n = len(f.ids)
    paths = min(n, _MAX_PATHS)
    tab = f.table
    outline = np.asarray(tab["outline"])
    if len(outline):
        ax.add_patch(patches.Polygon(outline, closed=True, facecolor=_PLAY, edgecolor="none",
                                     zorder=0))
        ax.add_patch(patches.Polygon(outline, closed=True, facecolor="none",
                                     edgecolor=_OUTLINE, linewidth=2.0, joinstyle="round",
                                     zorder=3))
    for name, x, y, r in tab["pockets"]:
        ax.add_patch(patches.Circle((x, y), r, facecolor="#333333", edgecolor="none",
                                    alpha=0.35, zorder=1))
    first = f.positions[0] if len(f) else np.zeros((n, 2))
    last = f.positions[-1] if len(f) else np.zeros((n, 2))
    if paths < n:
        ax.add_collection(PatchCollection(
            [patches.Circle(last[i], f.radii[i]) for i in range(paths, n)],
            facecolor=_OTHER, edgecolor="#555555", linewidth=0.5, zorder=4))
        ax.plot([], [], "o", color=_OTHER, markeredgecolor="#555555",
                label=f"other {n - paths} (end only)")
    for i in range(paths):
        c = PALETTE[i % len(PALETTE)]
        ax.plot(f.positions[:, i, 0], f.positions[:, i, 1], color=c, linewidth=1.5, alpha=0.9,
                solid_joinstyle="round", solid_capstyle="round", zorder=5, label=f.ids[i])
        ax.add_patch(patches.Circle(first[i], f.radii[i], facecolor="none", edgecolor=c,
                                    linewidth=1.5, zorder=6))
        ax.add_patch(patches.Circle(last[i], f.radii[i], facecolor=c, alpha=0.85,
                                    edgecolor="#222222", linewidth=0.8, zorder=7))
    ax.plot([], [], "o", markerfacecolor="none", markeredgecolor="#333333", label="start")
    ax.plot([], [], "o", color="#333333", label="end")
    # Extent: the table and everything a ball reached, 4 % padding.
    pts = [outline] if len(outline) else []
    if len(f):
        r = np.asarray(f.radii)[None, :, None]
        pts += [(f.positions - r).reshape(-1, 2), (f.positions + r).reshape(-1, 2)]
    pts = np.concatenate(pts) if pts else np.zeros((1, 2))
    pts = pts[np.isfinite(pts).all(axis=1)]
    lo = np.minimum(pts.min(axis=0), tab["min"])
    hi = np.maximum(pts.max(axis=0), tab["max"])
    pad = 0.04 * float(np.max(hi - lo)) if np.max(hi - lo) > 0 else 0.5
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.set_facecolor("#fafafa")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    _style(ax)
    sub = _time_range(f)
    sub += ("; circles at true radius: hollow at start, filled at end" if paths == n else
            f"; paths of the first {paths} of {n} balls, every ball's end position")
    _title(ax, f"{f.model} model, {_plural(n, 'ball')}: trajectories", sub)
    _legend_outside(ax)
    return ax


def _series(ax, f: Frames, per_ball, total, ylabel):
    n = len(f.ids)
    shown = _shown(n)
    for i in range(shown):
        ax.plot(f.times, per_ball[:, i], color=PALETTE[i % len(PALETTE)], linewidth=1.5,
                label=f.ids[i], zorder=3)
    ax.plot(f.times, total, color="black", linewidth=3.0, label="total", zorder=2)
    if len(f):
        ax.set_xlim(f.times[0], f.times[-1] if f.times[-1] > f.times[0] else f.times[0] + 1.0)
    ax.set_ylabel(ylabel)
    _style(ax)
    # Rounding noise on a constant curve should read as a flat line: pad a
    # range narrower than a thousandth of the largest value.
    lo, hi = ax.get_ylim()
    values = np.concatenate([np.ravel(per_ball[:, :shown]), np.ravel(total)]) if len(f) else [0]
    big = float(np.max(np.abs(values))) if len(values) else 0.0
    span = 1e-3 * big if big > 0 else 1.0
    if hi - lo < span:
        mid = 0.5 * (lo + hi)
        ax.set_ylim(mid - span / 2, mid + span / 2)


def _legend_handles(ax, n):
    """Legend in the SVG's order: total first, then the balls."""
    handles, labels = ax.get_legend_handles_labels()
    order = [labels.index("total")] + [k for k in range(len(labels)) if labels[k] != "total"]
    handles = [handles[k] for k in order]
    labels = [labels[k] for k in order]
    if _shown(n) < n:
        handles.append(patches.Patch(visible=False))
        labels.append(f"({n - _shown(n)} more not shown)")
    return handles, labels


def energy(result, ax=None):
    """Kinetic energy against time (the CLI's PREFIX-energy.svg).

    The system total in black and each ball in its colour (every ball up to
    12, else the first 10), translational plus rotational, computed by the
    engine (``frames.energy``). Returns the axes.
    """
    f = _frames(result)
    ax = _axes(ax, figsize=(10.0, 4.8), layout="constrained")
    n = len(f.ids)
    _series(ax, f, f.energy, f.energy_total, "kinetic energy (J)")
    lo, hi = ax.get_ylim()
    ax.set_ylim(min(lo, 0.0) if lo > -0.04 * (hi - lo) else lo, hi)
    ax.set_xlabel("time (s)")
    who = ("system total (black) and each ball" if _shown(n) == n else
           f"system total (black) and the first {_MAX_SERIES_SOME} of {n} balls")
    _title(ax, f"{f.model} model, {_plural(n, 'ball')}: kinetic energy",
           f"{_time_range(f)}; translational + rotational; {who}")
    _legend_outside(ax, handles=_legend_handles(ax, n)[0], labels=_legend_handles(ax, n)[1])
    return ax


def momentum(result, ax=None):
    """Linear momentum against time (the CLI's PREFIX-momentum.svg): x
    momentum above, y momentum below, the system total in black and each
    ball in its colour. ``ax`` is a pair of axes (x, y) when given; a new
    figure with two panels sharing the time axis otherwise. Returns the
    pair.
    """
    f = _frames(result)
    if ax is None:
        fig, ax = plt.subplots(2, 1, sharex=True, figsize=(10.0, 6.4), layout="constrained")
    else:
        ax = np.ravel(np.asarray(ax, dtype=object))
        if len(ax) != 2:
            raise ValueError("momentum draws into two axes (x and y momentum): pass a pair")
    n = len(f.ids)
    for k, name in enumerate(("x momentum", "y momentum")):
        _series(ax[k], f, f.momentum[:, :, k], f.momentum_total[:, k], f"{name} (kg m/s)")
    ax[1].set_xlabel("time (s)")
    who = ("system total (black) and each ball" if _shown(n) == n else
           f"system total (black) and the first {_MAX_SERIES_SOME} of {n} balls")
    _title(ax[0], f"{f.model} model, {_plural(n, 'ball')}: linear momentum",
           f"{_time_range(f)}; {who}")
    handles, labels = _legend_handles(ax[0], n)
    _legend_outside(ax[0], handles=handles, labels=labels)
    return ax


# ---------------------------------------------------------------------------
# Game positions


def _draw_pool_table(ax, tab, ball_radius):
    """Rails, cloth, pockets and the markings: on a pool table the
    diamonds and the head string's spots, on a snooker table the baulk
    line, the D and the colours' spots."""
    L, W = tab["length"], tab["width"]
    rail = 0.11
    ax.add_patch(patches.FancyBboxPatch((-rail, -rail), L + 2 * rail, W + 2 * rail,
                                        boxstyle="round,pad=0,rounding_size=0.05",
                                        facecolor=_RAIL, edgecolor="#2b1a0e", linewidth=1.0,
                                        zorder=0))
    outline = np.asarray(tab["outline"])
    if len(outline):
        ax.add_patch(patches.Polygon(outline, closed=True, facecolor=_CLOTH,
                                     edgecolor="#1d5a36", linewidth=0.8, zorder=1))
    else:
        ax.add_patch(patches.Rectangle((0, 0), L, W, facecolor=_CLOTH, zorder=1))
    for name, x, y, r in tab["pockets"]:
        ax.add_patch(patches.Circle((x, y), r, facecolor="#0b0b0b", edgecolor="#444444",
                                    linewidth=0.6, zorder=2, gid=f"pocket:{name}"))
    marks = tab.get("snooker")
    if marks is not None:
        line = dict(color="#d8e8dc", linewidth=0.8, zorder=2)
        bx = marks["baulk_line"]
        ax.plot([bx, bx], [0.0, W], **line)
        (cx, cy), dr = marks["d_centre"], marks["d_radius"]
        ax.add_patch(patches.Arc((cx, cy), 2 * dr, 2 * dr, theta1=90.0, theta2=270.0,
                                 edgecolor="#d8e8dc", linewidth=0.8, zorder=2))
        for spot in marks["spots"]:
            ax.plot(*spot, marker="o", markersize=2.0, color="#d8e8dc", zorder=2)
    else:
        # Diamonds on the rails: every eighth of the length, quarter of the width.
        d = 0.5 * rail + 0.006
        dx = [L * k / 8 for k in range(1, 8) if k != 4]
        dy = [W * k / 4 for k in range(1, 4)]
        ax.scatter(dx + dx, [-d] * len(dx) + [W + d] * len(dx), marker="D", s=9,
                   color="#e8dcc0", zorder=2, linewidths=0)
        ax.scatter([-d] * len(dy) + [L + d] * len(dy), dy + dy, marker="D", s=9,
                   color="#e8dcc0", zorder=2, linewidths=0)
        for spot in (tab.get("head_spot"), tab.get("foot_spot")):
            if spot is not None:
                ax.plot(*spot, marker="o", markersize=2.5, color="#d8e8dc", zorder=2)
    ax.set_xlim(-rail - 0.02, L + rail + 0.02)
    ax.set_ylim(-rail - 0.02, W + rail + 0.02)


def _draw_ball(ax, number, xy, r, label=True, game=None):
    """A ball of `game`: in pool solid, or white with a band (9-15),
    numbered; in snooker a red or a colour, unnumbered. Returns its
    patches (the first is the ball's disk)."""
    x, y = xy
    if game == "snooker":
        disk = patches.Circle((x, y), r, facecolor=_SNOOKER_COLOURS.get(number, _OTHER),
                              edgecolor="#111111", linewidth=0.7, zorder=5, gid=f"ball:{number}")
        ax.add_patch(disk)
        return [disk]
    colour = BALL_COLOURS.get(number, _OTHER)
    striped = 9 <= number <= 15
    disk = patches.Circle((x, y), r, facecolor="white" if striped else colour,
                          edgecolor="#111111", linewidth=0.7, zorder=5, gid=f"ball:{number}")
    ax.add_patch(disk)
    made = [disk]
    if striped:
        band = patches.Rectangle((x - r, y - 0.55 * r), 2 * r, 1.1 * r, facecolor=colour,
                                 edgecolor="none", zorder=5.1)
        band.set_clip_path(disk)
        ax.add_patch(band)
        made.append(band)
    if label and number > 0:
        ax.add_patch(patches.Circle((x, y), 0.48 * r, facecolor="white", edgecolor="none",
                                    zorder=5.2))
        ax.text(x, y, str(number), ha="center", va="center",
                fontsize=5.5 if number < 10 else 4.6, fontweight="bold", color="#111111",
                zorder=5.3)
    return made


def _ball_name(game, number) -> str:
    """'ball 3'; in snooker 'red 3' or 'the blue'."""
    if game == "snooker":
        return f"the {_SNOOKER_NAMES[number]}" if number in _SNOOKER_NAMES else f"red {number}"
    return f"ball {number}"


def _layout(state):
    """(table dict, [(number or None, id, (x, y), radius)], game or None)
    of what table() accepts."""
    if isinstance(state, (str, bytes)) or hasattr(state, "__fspath__") or \
            isinstance(state, _core.Scenario) or (
                isinstance(state, Mapping) and ("physics" in state or "rack" in state)):
        lay = _core.layout(state)
        balls = []
        for i, bid in enumerate(lay["ids"]):
            num = 0 if bid == "cue" else int(bid) if bid.isdigit() else None
            balls.append((num, bid, lay["positions"][i], lay["radii"][i]))
        return lay["table"], balls, None
    pos = game_position(state)
    tab = _core.game_table(pos["game"], pos["table_size"])
    r = tab["ball_radius"]
    balls = [(n, "cue" if n == 0 else str(n), pos["positions"][n], r)
             for n in range(len(pos["positions"])) if pos["on_table"][n]]
    return tab, balls, pos["game"]


def table(state, ax=None, *, numbers=True):
    """Draws a game position: the game's table (rails, cloth, pockets;
    a pool table's diamonds, a snooker table's baulk line, D and spots)
    and the balls on it in their colours, numbered in pool.

    ``state`` is a game position (docs/python.md, "Game positions"): a game
    or its state, a dict ``{"game": "nine_ball", "table": "9ft", "balls":
    {1: (x, y), ...}}`` (balls also as a list of (id, x, y) or of {"id",
    "position"} dicts; or ``positions`` (n, 2) and ``on_table`` (n,) arrays
    by ball number), a plain list of (id, x, y) on a 9 ft table, anything
    with a ``state`` attribute of one of these forms, or a pool scenario (a
    dict with ``physics`` or ``rack``, a path, or a breakshot.Scenario; its
    balls as they stand at t = 0). Ids are ball numbers or "cue". Returns
    the axes.
    """
    tab, balls, game = _layout(state)
    ax = _axes(ax, figsize=(9.0, 5.0), layout="constrained")
    if tab.get("length"):
        _draw_pool_table(ax, tab, balls[0][3] if balls else 0.028575)
    else:
        outline = np.asarray(tab["outline"])
        ax.add_patch(patches.Polygon(outline, closed=True, facecolor=_PLAY,
                                     edgecolor=_OUTLINE, linewidth=2.0, zorder=1))
        lo, hi = np.asarray(tab["min"]), np.asarray(tab["max"])
        pad = 0.04 * float(np.max(hi - lo))
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
    for k, (num, bid, xy, r) in enumerate(balls):
        if num is None:  # a ball that is not a pool ball: palette colour, its id
            ax.add_patch(patches.Circle(xy, r, facecolor=PALETTE[k % len(PALETTE)],
                                        edgecolor="#111111", linewidth=0.7, zorder=5,
                                        gid=f"ball:{bid}"))
            if numbers:
                ax.text(*xy, bid, ha="center", va="center", fontsize=5.5, zorder=5.3)
        else:
            _draw_ball(ax, num, xy, r, label=numbers, game=game)
    ax.set_aspect("equal", adjustable="box")
    ax.set_axis_off()
    return ax


# ---------------------------------------------------------------------------
# Pot maps

_POT_CMAP = LinearSegmentedColormap.from_list(
    "breakshot_pot", ["#3b0f70", "#8c2981", "#de4968", "#fe9f6d", "#fcfdbf"])


def pot_map(result, ax=None, *, colorbar=True, cmap=None):
    """A breakshot.PotMap as a heat map on its table: the chance of the pot
    from each cue-ball position (cells where the cue ball cannot be placed
    left clear), the object balls, the target ball ringed and an arrow
    from it into the pocket. Returns the axes.
    """
    pm = result
    if not hasattr(pm, "probability") or not hasattr(pm, "xs"):
        raise TypeError(f"plot.pot_map takes a breakshot.PotMap, not {type(pm).__name__}")
    ax = _axes(ax, figsize=(10.0, 5.4), layout="constrained")
    tab = pm.table
    _draw_pool_table(ax, tab, pm.ball_radius)
    xs, ys = np.asarray(pm.xs), np.asarray(pm.ys)

    def edges(c, lo, hi):
        if len(c) == 1:
            return np.array([lo, hi])
        mid = 0.5 * (c[1:] + c[:-1])
        return np.concatenate([[c[0] - (mid[0] - c[0])], mid, [c[-1] + (c[-1] - mid[-1])]])

    xe = edges(xs, 0.0, tab["length"])
    ye = edges(ys, 0.0, tab["width"])
    # Masked (drawn clear) where the cue ball cannot be placed.
    prob = np.ma.MaskedArray(np.asarray(np.ma.getdata(pm.probability), dtype=float),
                             mask=~np.asarray(pm.valid, dtype=bool))
    mesh = ax.pcolormesh(xe, ye, prob, cmap=cmap or _POT_CMAP, vmin=0.0, vmax=1.0,
                         shading="flat", zorder=3, alpha=0.92)
    # Keep the cloth's edge and the pockets visible over the map.
    for name, x, y, r in tab["pockets"]:
        ax.add_patch(patches.Circle((x, y), r, facecolor="#0b0b0b", edgecolor="#444444",
                                    linewidth=0.6, zorder=4))
    pos = pm.position
    game = pos["game"]
    r = pm.ball_radius
    for n in range(1, len(pos["positions"])):
        if pos["on_table"][n]:
            _draw_ball(ax, n, pos["positions"][n], r, game=game)
    bx, by = pos["positions"][pm.ball]
    ax.add_patch(patches.Circle((bx, by), 1.9 * r, facecolor="none", edgecolor="white",
                                linewidth=1.4, zorder=6))
    name, px, py, pr = tab["pockets"][pm.pocket]
    ax.annotate("", xy=(px, py), xytext=(bx, by),
                arrowprops=dict(arrowstyle="-|>", color="white", linewidth=1.4,
                                shrinkA=9, shrinkB=2), zorder=6)
    if colorbar:
        cb = ax.figure.colorbar(mesh, ax=ax, fraction=0.035, pad=0.02)
        cb.set_label("chance of the pot")
    samples = f"{pm.samples} samples" if pm.samples else "the level's samples"
    ax.set_title(f"{pm.level}: {_ball_name(game, pm.ball)} in the {name.replace('_', ' ')} "
                 f"pocket, by cue-ball position\n", loc="left", fontweight="bold",
                 fontsize="medium")
    mean = (f"mean {pm.mean():.2f} where the cue ball can be placed" if pm.valid.any()
            else "the cue ball can be placed nowhere")
    ax.text(0.0, 1.01, f"{prob.shape[1]} x {prob.shape[0]} grid, {samples} per shot; {mean}",
            transform=ax.transAxes, fontsize="small", color="#444444", va="bottom")
    ax.set_aspect("equal", adjustable="box")
    ax.set_axis_off()
    return ax
