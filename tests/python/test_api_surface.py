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


def runtime_parameters(function):
    """Parameter names and defaults from pybind11's signature line, or None
    when the function is overloaded (several signature lines)."""
    doc = function.__doc__ or ""
    first = doc.splitlines()[0]
    if doc.count(function.__name__ + "(") != 1 or not first.startswith(function.__name__ + "("):
        return None
    inner = first[len(function.__name__) + 1:first.rindex(") ->")]
    names = []
    depth = 0
    part = ""
    for ch in inner + ",":
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        if ch == "," and depth == 0:
            part = part.strip()
            if part and part != "*":
                names.append((part.split(":")[0].strip(), part.split("=")[1].strip() if "=" in part else None))
            part = ""
        else:
            part += ch
    return names


def test_stub_functions_have_the_modules_keywords_and_defaults():
    tree = ast.parse((PACKAGE / "__init__.pyi").read_text())
    checked = 0
    for node in tree.body:
        if not isinstance(node, ast.FunctionDef):
            continue
        runtime = runtime_parameters(getattr(hrspace, node.name))
        if runtime is None:
            continue
        args = node.args
        stub = [(a.arg, None) for a in args.posonlyargs + args.args]
        defaults = [ast.unparse(d) for d in args.defaults]
        for i, d in enumerate(defaults):
            k = len(stub) - len(defaults) + i
            stub[k] = (stub[k][0], d)
        stub += [(a.arg, None if d is None else ast.unparse(d))
                 for a, d in zip(args.kwonlyargs, args.kw_defaults)]
        assert [n for n, _ in stub] == [n for n, _ in runtime], node.name
        for (name, ours), (_, theirs) in zip(stub, runtime):
            if ours is not None and theirs is not None:
                assert ours.replace('"', "'") == theirs.replace('"', "'"), f"{node.name}({name})"
        checked += 1
    assert checked >= 3  # design, plan, tour


def test_every_public_callable_has_a_docstring():
    for module in (hrspace, rs):
        assert module.__doc__
        for name in module.__all__:
            obj = getattr(module, name)
            assert obj.__doc__, name
            if inspect.isclass(obj):
                for member in public(obj):
                    assert getattr(obj, member).__doc__, f"{name}.{member}"
