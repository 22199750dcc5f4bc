"""Shared fixtures of the Python tests: the repository, the command line
built by the release preset (scripts/test.sh builds it first), and a
helper that runs it."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def root() -> Path:
    return ROOT


@pytest.fixture(scope="session")
def cli() -> Path:
    """The `breakshot` command to compare with: $BREAKSHOT_CLI, else the
    release build's. Missing is a failure, not a skip."""
    path = Path(os.environ.get("BREAKSHOT_CLI", ROOT / "build" / "release" / "breakshot"))
    if not path.is_file():
        pytest.fail(f"no breakshot command at {path}: build the release preset "
                    "(cmake --preset release && cmake --build --preset release) "
                    "or set BREAKSHOT_CLI")
    return path


@pytest.fixture(scope="session")
def run_cli(cli):
    def run(*args, input=None, check=False):
        r = subprocess.run([str(cli), *map(str, args)], input=input,
                           capture_output=True, text=True)
        if check and r.returncode != 0:
            raise AssertionError(f"breakshot {' '.join(map(str, args))}: {r.stderr}")
        return r
    return run
