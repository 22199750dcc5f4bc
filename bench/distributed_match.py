#!/usr/bin/env python3
"""Games per second of breakshot.distributed.match on local clusters of 1
and 2 worker processes, and the scaling efficiency.

    .venv/bin/python bench/distributed_match.py [--game nine_ball] [--players club,club]
                                                [--games 200] [--seed 1] [--workers 1,2]

Each task runs its players with one thread (as every task does), so a
worker is one core. For each worker count a fresh local cluster is started
(not timed), the workers are checked (not timed), then the match is timed
from the first task sent to the summary added up. The summaries of all
worker counts are compared: they must be the same bytes. The figure for
one machine without Dask is breakshot.match in this process with one
thread, for the overhead of the cluster (docs/performance.md, "Matches on
a Dask cluster").
"""

from __future__ import annotations

import argparse
import os
import sys
import time

import breakshot
import breakshot.distributed as bd


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--game", default="nine_ball")
    ap.add_argument("--players", default="club,club")
    ap.add_argument("--games", type=int, default=200)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--noise", default="none")
    ap.add_argument("--workers", default="1,2", help="worker counts to measure")
    ap.add_argument("--chunk", type=int, default=None, help="games per task (default: the "
                    "module's choice)")
    args = ap.parse_args()
    players = args.players.split(",")
    counts = [int(w) for w in args.workers.split(",")]

    t0 = time.perf_counter()
    alone = breakshot.match_json(args.game, players, args.games, args.seed, args.noise,
                                 threads=1)
    t_alone = time.perf_counter() - t0

    rates = {}
    for w in counts:
        with bd.local_client(w) as client:
            bd.check_workers(client)
            t0 = time.perf_counter()
            text = bd.match_json(client, args.game, players, args.games, args.seed, args.noise,
                                 chunk=args.chunk, progress=False)
            rates[w] = args.games / (time.perf_counter() - t0)
        if text != alone:
            print(f"the summary with {w} workers differs from one process's", file=sys.stderr)
            return 1

    print(f"breakshot {breakshot.__version__}, {os.cpu_count()} cores; {args.game} "
          f"{args.players}, {args.games} games, seed {args.seed}, noise {args.noise}; "
          f"1 thread per task, chunk {args.chunk or 'default'}")
    print(f"one process, no Dask      {args.games / t_alone:8.2f} games/s")
    base = rates.get(1)
    for w in counts:
        eff = "" if base is None else f"   efficiency {rates[w] / (w * base):.2f}"
        print(f"{w} worker{'s' if w > 1 else ' '}                 {rates[w]:8.2f} games/s{eff}")
    print("summaries identical to one process: True")
    return 0


if __name__ == "__main__":
    sys.exit(main())
