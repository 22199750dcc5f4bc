#!/usr/bin/env python3
"""Writes gas_1000.json: 1000 equal disks at area fraction 0.3 in a square
box, on a jittered lattice with random velocities (fixed seed)."""
import json
import math
import random

N, R, PHI = 1000, 0.01, 0.3
side = math.sqrt(N * math.pi * R * R / PHI)
rng = random.Random(2026)
cols = math.ceil(math.sqrt(N))
pitch = side / cols
balls = []
for k in range(N):
    cx, cy = (k % cols + 0.5) * pitch, (k // cols + 0.5) * pitch
    slack = (pitch - 2 * R) / 2 * 0.9
    x = cx + rng.uniform(-slack, slack) - side / 2
    y = cy + rng.uniform(-slack, slack) - side / 2
    ang = rng.uniform(0, 2 * math.pi)
    speed = abs(rng.gauss(0.5, 0.2))
    balls.append({"id": f"g{k}", "position": [round(x, 6), round(y, 6)],
                  "velocity": [round(speed * math.cos(ang), 6), round(speed * math.sin(ang), 6)],
                  "radius": R, "mass": 0.01})
half = side / 2
scenario = {"physics": {"model": "ideal"},
            "table": {"shape": "rectangle", "min": [-half, -half], "max": [half, half]},
            "balls": balls, "until": {"time": 2.0}}
with open("gas_1000.json", "w") as f:
    json.dump(scenario, f, separators=(",", ":"))
    f.write("\n")
