#!/usr/bin/env python3
"""breakshot.shots against bench_pool's BM_RandomShot15, in one run.

    .venv/bin/python bench/python_shots.py [--build build/release] [--rounds 5] [--batches 3]

Plays the 4096 random 15-ball layouts and strikes of BM_RandomShot15
(bench/random_shots.hpp, written as JSON by export_random_shots: numpy has
no mt19937_64) with breakshot.shots on one thread and on two, runs the C++
benchmark (bench_pool --benchmark_filter=BM_RandomShot15, JSON output), and
prints the time per shot of each, Python's overhead per shot against C++
and the speedup on two threads. The three are measured in turn, --rounds
times, and each figure is the median of its rounds (a Python measurement
is the median of --batches batches of all 4096 shots; a C++ one is
bench_pool's). The layouts are read into breakshot.Scenario objects once,
before timing (docs/performance.md, "Python").
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import breakshot

ROOT = Path(__file__).resolve().parents[1]


def cxx_per_shot_us(build: Path, repetitions: int) -> float:
    """The median time per shot of BM_RandomShot15 (real time, us)."""
    out = subprocess.run(
        [str(build / "bench" / "bench_pool"), "--benchmark_filter=BM_RandomShot15",
         "--benchmark_format=json", f"--benchmark_repetitions={repetitions}"],
        check=True, capture_output=True, text=True).stdout
    runs = [b for b in json.loads(out)["benchmarks"]
            if b.get("run_type", "iteration") == "iteration"]
    scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}
    return statistics.median(b["real_time"] * scale[b["time_unit"]] for b in runs)


def python_per_shot_us(scenarios, strikes, threads: int, batches: int):
    """The median time per shot of breakshot.shots over `batches` batches."""
    times = []
    result = None
    for _ in range(batches):
        t0 = time.perf_counter()
        result = breakshot.shots(scenarios, strikes, threads=threads)
        times.append(time.perf_counter() - t0)
    return statistics.median(times) / len(strikes) * 1e6, result


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", type=Path, default=ROOT / "build" / "release",
                    help="the release build with bench_pool and export_random_shots")
    ap.add_argument("--rounds", type=int, default=5,
                    help="rounds of the three measurements (each figure: the median)")
    ap.add_argument("--batches", type=int, default=3,
                    help="batches of 4096 shots per Python measurement (median)")
    args = ap.parse_args()

    text = subprocess.run([str(args.build / "bench" / "export_random_shots")],
                          check=True, capture_output=True, text=True).stdout
    data = json.loads(text)
    scenarios = [breakshot.Scenario(s) for s in data["scenarios"]]
    strikes = np.array(data["strikes"], dtype=np.float64)
    load_before = os.getloadavg()

    # The three figures are taken in turn, --rounds times, and each is the
    # median of its rounds: a change in the machine's load during the run
    # then weighs on all three alike.
    py1s, cxxs, py2s = [], [], []
    for _ in range(args.rounds):
        t, r1 = python_per_shot_us(scenarios, strikes, 1, args.batches)
        py1s.append(t)
        cxxs.append(cxx_per_shot_us(args.build, 1))
        t, r2 = python_per_shot_us(scenarios, strikes, 2, args.batches)
        py2s.append(t)
    py1, cxx, py2 = (statistics.median(x) for x in (py1s, cxxs, py2s))
    load_after = os.getloadavg()

    same = all(np.array_equal(getattr(r1, a), getattr(r2, a))
               for a in ("final_positions", "pockets", "event_counts", "first_hit"))
    events = float(r1.event_counts.mean())
    print(f"breakshot {breakshot.__version__}, {os.cpu_count()} cores, "
          f"load average {load_before[0]:.2f} before, {load_after[0]:.2f} after")
    print(f"BM_RandomShot15 shots: {len(strikes)} layouts, {events:.1f} events per shot")
    print(f"C++      bench_pool, 1 thread     {cxx:8.2f} us/shot")
    print(f"Python   shots, threads=1         {py1:8.2f} us/shot   "
          f"overhead {100 * (py1 / cxx - 1):+.1f} % against C++")
    print(f"Python   shots, threads=2         {py2:8.2f} us/shot   "
          f"speedup {py1 / py2:.2f}x on 2 threads")
    print(f"threads=1 and threads=2 arrays identical: {same}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
