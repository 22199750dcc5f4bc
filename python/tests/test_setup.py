"""setup.py's CMake commands: the generator (Ninja where it is installed,
else CMake's default: a machine without ninja builds the package too), a
fresh tree for the extension alone, or an existing build tree of the
project (BREAKSHOT_CMAKE_BUILD_DIR) that keeps its own settings."""

import runpy
import subprocess

import setuptools


def _setup_module(root, monkeypatch):
    # setup.py calls setuptools.setup at its end: read its functions only.
    monkeypatch.setattr(setuptools, "setup", lambda **kwargs: None)
    return runpy.run_path(str(root / "setup.py"), run_name="breakshot_setup")


def test_ninja_when_found_else_cmakes_default(root, monkeypatch):
    generator_args = _setup_module(root, monkeypatch)["generator_args"]
    assert generator_args(lambda name: "/usr/bin/ninja" if name == "ninja" else None) == \
        ["-G", "Ninja"]
    assert generator_args(lambda name: None) == []


def test_no_ninja_on_the_path_is_no_error(root, monkeypatch, tmp_path):
    # The default lookup, on a PATH without ninja: no generator named, no
    # FileNotFoundError.
    monkeypatch.setenv("PATH", str(tmp_path))
    assert _setup_module(root, monkeypatch)["generator_args"]() == []


def test_a_fresh_tree_is_configured_for_the_extension_alone(root, monkeypatch, tmp_path):
    cmake_commands = _setup_module(root, monkeypatch)["cmake_commands"]
    configure, build = cmake_commands(tmp_path / "cmake", tmp_path / "out", "2", existing=False,
                                      which=lambda name: None)
    for flag in ("-DCMAKE_BUILD_TYPE=Release", "-DBREAKSHOT_BUILD_TESTS=OFF",
                 "-DBREAKSHOT_BUILD_APPS=OFF", "-DBREAKSHOT_BUILD_BENCH=OFF",
                 "-DBREAKSHOT_BUILD_C_API=OFF", "-DBREAKSHOT_WERROR=ON",
                 "-DBREAKSHOT_BUILD_PYTHON=ON", f"-DBREAKSHOT_PYTHON_OUTPUT_DIR={tmp_path / 'out'}"):
        assert flag in configure
    assert build == ["cmake", "--build", str(tmp_path / "cmake"), "--target", "breakshot_python",
                     "-j", "2"]


def test_an_existing_tree_keeps_its_settings(root, monkeypatch, tmp_path):
    # BREAKSHOT_CMAKE_BUILD_DIR (scripts/python.sh gives build/release): the
    # tree's own tests, command and benchmarks stay on, no generator is
    # named (the tree has one), and the extension's target is added.
    cmake_commands = _setup_module(root, monkeypatch)["cmake_commands"]
    configure, build = cmake_commands(tmp_path, tmp_path / "out", "1", existing=True,
                                      which=lambda name: "/usr/bin/ninja")
    assert not [a for a in configure if a.startswith(("-DBREAKSHOT_BUILD_TESTS",
                                                      "-DBREAKSHOT_BUILD_APPS",
                                                      "-DCMAKE_BUILD_TYPE", "-G"))]
    assert "-DBREAKSHOT_BUILD_PYTHON=ON" in configure
    assert build[-3:] == ["breakshot_python", "-j", "1"]


def test_the_fresh_tree_configures(root, monkeypatch, tmp_path):
    # What `pip install .` runs first on a machine with no build tree: the
    # project configures for the extension alone (the compile itself is the
    # release tree's, where scripts/python.sh builds the same target).
    cmake_commands = _setup_module(root, monkeypatch)["cmake_commands"]
    configure, _ = cmake_commands(tmp_path / "cmake", tmp_path / "out", "2", existing=False)
    done = subprocess.run(configure, capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    cache = (tmp_path / "cmake" / "CMakeCache.txt").read_text()
    assert "BREAKSHOT_BUILD_PYTHON:BOOL=ON" in cache
    assert "BREAKSHOT_BUILD_TESTS:BOOL=OFF" in cache
