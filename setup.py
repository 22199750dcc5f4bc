"""Builds breakshot's Python package: the extension breakshot._core is built
by the project's CMake (python/CMakeLists.txt), with the same flags as the
library and the command; no other compiler flags are set here.

    pip install --no-build-isolation .          # into the active environment
    python3 -m build --no-isolation --wheel     # a wheel for cluster nodes

Environment: BREAKSHOT_BUILD_JOBS (parallel compile jobs, default all cores);
BREAKSHOT_CMAKE_BUILD_DIR (an existing, configured build tree of the project,
such as build/release, to build the extension in instead of a fresh one: the
engine it has compiled is not compiled again; scripts/python.sh gives it).
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, find_packages, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def version() -> str:
    text = (ROOT / "include" / "breakshot" / "version.hpp").read_text()
    m = re.search(r'kVersion = "([0-9]+\.[0-9]+\.[0-9]+)"', text)
    if not m:
        raise RuntimeError("no version in include/breakshot/version.hpp")
    return m.group(1)


def generator_args(which=shutil.which) -> list:
    """CMake's generator options: Ninja where the ninja command is found,
    else none (CMake's default generator, Unix Makefiles on Linux)."""
    return ["-G", "Ninja"] if which("ninja") else []


class CMakeExtension(Extension):
    def __init__(self, name: str):
        super().__init__(name, sources=[])


def cmake_commands(build_dir: Path, out_dir: Path, jobs: str, existing: bool,
                   which=shutil.which) -> list:
    """The configure and build commands of the extension in build_dir.

    A fresh tree (existing False) is configured for the extension alone.
    An existing build tree of the project (BREAKSHOT_CMAKE_BUILD_DIR, for
    example build/release, as scripts/python.sh gives) keeps its own
    settings and gains the target: the engine's objects it has already
    compiled are the extension's too, so the engine is not compiled again.
    """
    configure = ["cmake", "-S", str(ROOT), "-B", str(build_dir)]
    if not existing:
        configure += [
            "-DCMAKE_BUILD_TYPE=Release",
            "-DBREAKSHOT_BUILD_TESTS=OFF",
            "-DBREAKSHOT_BUILD_APPS=OFF",
            "-DBREAKSHOT_BUILD_BENCH=OFF",
            "-DBREAKSHOT_BUILD_C_API=OFF",
            "-DBREAKSHOT_WERROR=ON",
        ]
        configure += generator_args(which)
    configure += [
        "-DBREAKSHOT_BUILD_PYTHON=ON",
        f"-DPython_EXECUTABLE={sys.executable}",
        f"-DBREAKSHOT_PYTHON_OUTPUT_DIR={out_dir}",
    ]
    build = ["cmake", "--build", str(build_dir), "--target", "breakshot_python", "-j", jobs]
    return [configure, build]


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        out_dir = Path(self.get_ext_fullpath(ext.name)).resolve().parent
        tree = os.environ.get("BREAKSHOT_CMAKE_BUILD_DIR")
        if tree:
            build_dir = Path(tree).resolve()
            if not (build_dir / "CMakeCache.txt").is_file():
                raise RuntimeError(
                    f"BREAKSHOT_CMAKE_BUILD_DIR={tree}: not a configured CMake build tree "
                    f"(no CMakeCache.txt in {build_dir}); configure it first, "
                    "for example with cmake --preset release")
        else:
            build_dir = Path(self.build_temp).resolve() / "cmake"
            build_dir.mkdir(parents=True, exist_ok=True)
        jobs = os.environ.get("BREAKSHOT_BUILD_JOBS") or str(os.cpu_count() or 2)
        for command in cmake_commands(build_dir, out_dir, jobs, existing=bool(tree)):
            subprocess.run(command, check=True)


setup(
    version=version(),
    packages=find_packages(where="python", exclude=["tests"]),
    package_dir={"": "python"},
    package_data={"breakshot": ["py.typed", "*.pyi"]},
    ext_modules=[CMakeExtension("breakshot._core")],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
