"""The scripts in examples/python run and write their PNGs."""

import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples" / "python"
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def run(*args):
    r = subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True,
                       env={**os.environ, "MPLBACKEND": "Agg"}, timeout=600)
    assert r.returncode == 0, r.stderr
    return r.stdout


def test_two_balls(tmp_path):
    out = run(EXAMPLES / "two_balls.py", tmp_path)
    for name in ("trajectories", "energy", "momentum"):
        png = tmp_path / f"two_balls-{name}.png"
        assert png.read_bytes()[:8] == PNG_MAGIC, name
        assert f"wrote {png}" in out


def test_pot_map(tmp_path):
    out = run(EXAMPLES / "pot_map.py", "--out", tmp_path, "--nx", "3", "--ny", "2",
              "--samples", "2", "--candidates", "2", "--threads", "2")
    assert (tmp_path / "pot_map.png").read_bytes()[:8] == PNG_MAGIC
    assert "grid=3x2" in out
