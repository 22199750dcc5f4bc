"""The lab's two balls (examples/lab/two_balls.json) with the three plots of
`breakshot simulate --plot`, drawn with matplotlib and saved as PNG.

    .venv/bin/python examples/python/two_balls.py [OUT_DIR]     (default out/)
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")

import breakshot  # noqa: E402
import breakshot.plot  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
SCENARIO = HERE.parent / "lab" / "two_balls.json"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", nargs="?", default="out", help="output directory (default out/)")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    result = breakshot.simulate(SCENARIO, trace=True)
    f = result.frames
    print(result)
    print(f"{len(result.events)} events; kinetic energy {f.energy_total[0]:.6g} J at t = 0, "
          f"{f.energy_total[-1]:.6g} J at t = {f.times[-1]:g} s")

    for name, draw in (("trajectories", breakshot.plot.trajectories),
                       ("energy", breakshot.plot.energy),
                       ("momentum", breakshot.plot.momentum)):
        ax = draw(result)
        fig = (ax[0] if hasattr(ax, "__len__") else ax).figure
        path = out / f"two_balls-{name}.png"
        fig.savefig(path, dpi=110)
        matplotlib.pyplot.close(fig)
        print("wrote", path)


if __name__ == "__main__":
    main()
