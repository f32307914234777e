"""The type stubs (.pyi) describe the module as it is, and every public
function, method and property has a docstring."""

import ast
import inspect
import pathlib

import hrspace
from hrspace import rs

PACKAGE = pathlib.Path(hrspace.__file__).parent


def stub_names(path):
    """{name: set of member names} for classes, {name: None} for functions."""
    tree = ast.parse(path.read_text())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            out[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
        elif isinstance(node, ast.FunctionDef):
            out[node.name] = None
    return out


def public(obj):
    return {n for n in dir(obj) if not n.startswith("_")}


def check(module, stub):
    names = stub_names(PACKAGE / stub)
    for name, members in names.items():
        assert hasattr(module, name), f"{stub}: {name} is not in the module"
        if members is not None:
            runtime = public(getattr(module, name))
            assert {m for m in members if not m.startswith("_")} == runtime, name
    exported = {n for n in module.__all__ if not inspect.ismodule(getattr(module, n))}
    assert exported == set(names), stub


def test_stubs_match_the_module():
    check(hrspace, "__init__.pyi")
    check(rs, "rs.pyi")


def test_every_public_callable_has_a_docstring():
    for module in (hrspace, rs):
        assert module.__doc__
        for name in module.__all__:
            obj = getattr(module, name)
            assert obj.__doc__, name
            if inspect.isclass(obj):
                for member in public(obj):
                    assert getattr(obj, member).__doc__, f"{name}.{member}"
