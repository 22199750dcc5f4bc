"""A pot probability map: how often the champion pots the 8 in a corner
pocket from every cue-ball position on a grid, under its own tournament
noise, drawn as a heat map with matplotlib and saved as PNG.

    .venv/bin/python examples/python/pot_map.py [--out DIR] [--nx 40] [--ny 20]
        [--samples N] [--level champion] [--threads N]

The defaults (the champion's own 128 samples per shot) take about a minute
on two cores; --nx 4 --ny 2 --samples 4 is a quick check.
"""

import argparse
import pathlib
import time

import matplotlib

matplotlib.use("Agg")

import breakshot  # noqa: E402
import breakshot.plot  # noqa: E402

# An 8-ball position at the end of a rack: the shooter has solids and has
# cleared them, so the 8 is the only legal ball; two stripes are in the way
# of some cue-ball positions.
POSITION = {
    "game": "eight_ball",
    "table": "9ft",
    "groups": ["solids", "stripes"],
    "balls": {8: (2.0, 0.95), 10: (1.55, 0.55), 13: (1.7, 1.08)},
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="out", help="output directory (default out/)")
    parser.add_argument("--nx", type=int, default=40, help="grid columns (default 40)")
    parser.add_argument("--ny", type=int, default=20, help="grid rows (default 20)")
    parser.add_argument("--samples", type=int, default=None,
                        help="noisy plays per candidate and per measurement "
                             "(default: the level's own)")
    parser.add_argument("--candidates", type=int, default=None,
                        help="candidates sampled (default: the level's own)")
    parser.add_argument("--level", default="champion", help="player level (default champion)")
    parser.add_argument("--ball", type=int, default=8, help="ball to pot (default 8)")
    parser.add_argument("--pocket", default="top_right", help="pocket (default top_right)")
    parser.add_argument("--threads", type=int, default=None, help="threads (default all cores)")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    samples = args.samples or "the level's"
    print(f"pot map: {args.level}, ball {args.ball} in {args.pocket}, "
          f"{args.nx} x {args.ny} grid, {samples} samples")
    start = time.perf_counter()
    pm = breakshot.pot_map(POSITION, args.ball, args.pocket, args.level, nx=args.nx, ny=args.ny,
                           samples=args.samples, candidates=args.candidates, seed=args.seed,
                           threads=args.threads)
    seconds = time.perf_counter() - start
    print(pm)
    print(f"{pm.simulations} noisy plays in {seconds:.1f} s")

    ax = breakshot.plot.pot_map(pm)
    path = out / "pot_map.png"
    ax.figure.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main()
