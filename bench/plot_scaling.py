#!/usr/bin/python3
"""Runs bench/scaling (build/release) and draws how cost grows as SVG.

    /usr/bin/python3 bench/plot_scaling.py [--build build/release] [--out docs/images]
                                           [--max-balls 1000000] [--threads N]

Writes scaling-gas.svg (events per second and memory per ball of the lab's
ideal gas, 10^2 to --max-balls disks), scaling-breaks.svg (microseconds
and events per break against the balls in the rack) and
scaling-threads.svg (random shots per second and 9-ball games per minute
against threads), and the CSV each was drawn from beside it
(docs/performance.md, "Scaling"). Needs Debian's python3-matplotlib.
"""
import argparse
import csv
import io
import os
import subprocess
import sys

import matplotlib

matplotlib.use("svg")
matplotlib.rcParams["svg.hashsalt"] = "breakshot"  # the same SVG for the same figures
import matplotlib.pyplot as plt  # noqa: E402

SIZES = [100, 300, 1000, 3000, 10000, 30000, 100000, 300000, 1000000]


def run(exe, *args):
    out = subprocess.run([exe, *map(str, args)], check=True, capture_output=True, text=True)
    return out.stdout


def rows(text, header=None):
    lines = text.strip().splitlines()
    if header:
        lines = [header] + lines
    return list(csv.DictReader(io.StringIO("\n".join(lines))))


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, metadata={"Date": None})
    plt.close(fig)
    print("wrote", path)


def write_csv(path, data):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(data[0].keys()))
        w.writeheader()
        w.writerows(data)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build/release")
    ap.add_argument("--out", default="docs/images")
    ap.add_argument("--max-balls", type=int, default=1000000)
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--only", default="gas,breaks,threads",
                    help="which plots, comma-separated (default: all three)")
    a = ap.parse_args()
    exe = os.path.join(a.build, "bench", "scaling")
    if not os.access(exe, os.X_OK):
        sys.exit(f"plot_scaling.py: {exe} is missing (cmake --build --preset release)")
    os.makedirs(a.out, exist_ok=True)

    only = set(a.only.split(","))
    if "gas" in only:
        plot_gas(exe, a)
    if "breaks" in only:
        plot_breaks(exe, a)
    if "threads" in only:
        plot_threads(exe, a)


def plot_gas(exe, a):
    gas = []
    for n in [s for s in SIZES if s <= a.max_balls]:
        gas += rows(run(exe, "gas", n), "balls,events,seconds,events_per_second,bytes_per_ball,"
                    "bytes_per_ball_without_events,peak_rss_mib")
        print("gas", gas[-1], flush=True)
    write_csv(os.path.join(a.out, "scaling-gas.csv"), gas)
    n = [int(r["balls"]) for r in gas]
    eps = [float(r["events_per_second"]) / 1e6 for r in gas]
    us = [1e6 / float(r["events_per_second"]) for r in gas]
    mem = [float(r["bytes_per_ball"]) for r in gas]
    mem_balls = [float(r["bytes_per_ball_without_events"]) for r in gas]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    ax1.plot(n, eps, "o-", color="tab:blue", label="events / s (millions)")
    ax1.set_xscale("log")
    ax1.set_xlabel("balls")
    ax1.set_ylabel("million events per second", color="tab:blue")
    ax1b = ax1.twinx()
    ax1b.plot(n, us, "s--", color="tab:red")
    ax1b.set_ylabel("microseconds per event", color="tab:red")
    ax1.set_title("Ideal gas: events per second (one core)")
    ax1.grid(True, which="both", alpha=0.3)
    ax2.plot(n, mem, "o-", color="tab:green", label="with the events kept")
    ax2.plot(n, mem_balls, "s--", color="tab:olive", label="balls alone")
    ax2.set_xscale("log")
    ax2.set_yscale("log")
    ax2.set_xlabel("balls")
    ax2.set_ylabel("bytes per ball (peak allocated)")
    ax2.legend()
    ax2.set_title("Memory per ball")
    ax2.grid(True, which="both", alpha=0.3)
    save(fig, os.path.join(a.out, "scaling-gas.svg"))


def plot_breaks(exe, a):
    br = rows(run(exe, "breaks"))
    write_csv(os.path.join(a.out, "scaling-breaks.csv"), br)
    tri = [r for r in br if r["rack"] == "triangle"]
    games = [r for r in br if r["rack"] != "triangle"]
    balls = [int(r["balls"]) for r in tri]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(balls, [float(r["us_per_break"]) for r in tri], "o-", color="tab:blue",
            label="triangle, 9 ft: microseconds")
    ax.plot([int(r["balls"]) for r in games], [float(r["us_per_break"]) for r in games], "D",
            color="navy", label="the games' breaks: microseconds")
    for r in games:
        label = {"nine_ball": "9-ball", "eight_ball": "8-ball", "snooker": "snooker, 12 ft"}
        ax.annotate(label.get(r["rack"], r["rack"]), (int(r["balls"]), float(r["us_per_break"])),
                    textcoords="offset points", xytext=(7, -10), fontsize=8, color="navy")
    ax.set_xlabel("object balls in the rack")
    ax.set_ylabel("microseconds per break", color="tab:blue")
    axb = ax.twinx()
    axb.plot(balls, [float(r["events_per_break"]) for r in tri], "s--", color="tab:red",
             label="triangle: events")
    axb.set_ylabel("events per break (triangle)", color="tab:red")
    ax.set_title("Break cost against the rack (7.5 m/s, clusters)")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    save(fig, os.path.join(a.out, "scaling-breaks.svg"))


def plot_threads(exe, a):
    th = rows(run(exe, "threads", a.threads))
    write_csv(os.path.join(a.out, "scaling-threads.csv"), th)
    t = [int(r["threads"]) for r in th]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    for ax, key, scale, label, title in [
        (ax1, "shots_per_second", 1e3, "thousand shots per second", "Random 15-ball shots (play_shots)"),
        (ax2, "games_per_minute", 1.0, "games per minute", "9-ball baseline games (match --jobs)"),
    ]:
        y = [float(r[key]) / scale for r in th]
        ax.plot(t, y, "o-", color="tab:blue", label="measured")
        ax.plot(t, [y[0] * k for k in t], ":", color="gray", label="linear")
        ax.set_xlabel("threads")
        ax.set_xticks(t)
        ax.set_ylabel(label)
        ax.set_title(title)
        ax.set_ylim(bottom=0)
        ax.grid(True, alpha=0.3)
        ax.legend()
    save(fig, os.path.join(a.out, "scaling-threads.svg"))


if __name__ == "__main__":
    main()
