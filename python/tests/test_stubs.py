"""The type stubs of breakshot._core (python/breakshot/_core.pyi) name
exactly what the extension has, so editors complete the real API."""

import ast
import inspect
import pathlib

import breakshot
import breakshot._core as core

STUB = pathlib.Path(breakshot.__file__).with_name("_core.pyi")


def _stub_names():
    tree = ast.parse(STUB.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            top.add(node.name)
            members[node.name] = {
                n.name if isinstance(n, ast.FunctionDef) else n.target.id
                for n in node.body
                if isinstance(n, ast.FunctionDef) or isinstance(n, ast.AnnAssign)
            }
        elif isinstance(node, ast.FunctionDef):
            top.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            top.add(node.target.id)
    return top, members


def _public(names):
    return {n for n in names if not n.startswith("_") or n in ("__copy__", "__deepcopy__")}


def test_stub_is_installed_with_the_package():
    assert STUB.is_file()
    assert pathlib.Path(breakshot.__file__).with_name("py.typed").is_file()


def test_stub_names_every_function_and_class_of_the_extension():
    top, members = _stub_names()
    real = _public(n for n in dir(core) if not inspect.ismodule(getattr(core, n)))
    assert top - {"ScenarioLike"} == real
    for cls, names in members.items():
        have = _public(vars(getattr(core, cls)))
        assert names - {"__init__"} == have, cls


def test_public_names_have_docstrings():
    for name in breakshot.__all__:
        obj = getattr(breakshot, name)
        if callable(obj):
            assert (obj.__doc__ or "").strip(), name
