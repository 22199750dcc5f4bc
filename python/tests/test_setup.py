"""setup.py's choice of CMake generator: Ninja where it is installed, else
CMake's default (a machine without ninja builds the package too)."""

import runpy

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
