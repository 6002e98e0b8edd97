"""The typing stub (__init__.pyi, next to the module) names exactly what the module defines, and
py.typed marks the package as typed."""
import ast
import inspect
import os
import pydoc

import sphtroch
from stub_info import typing_only


def stub_tree():
    path = os.path.join(os.path.dirname(sphtroch.__file__), "__init__.pyi")
    with open(path) as f:
        return ast.parse(f.read())


def test_py_typed_marker_is_installed_with_the_package():
    assert os.path.exists(os.path.join(os.path.dirname(sphtroch.__file__), "py.typed"))


def test_every_stub_name_exists_and_every_public_name_is_in_the_stub():
    tree = stub_tree()
    top = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef)) and not typing_only(n)}
    assert top <= set(dir(sphtroch)), top - set(dir(sphtroch))
    assert set(sphtroch.__all__) - {"__version__"} == top
    train = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "GearTrain")
    members = {n.name for n in train.body if isinstance(n, ast.FunctionDef)} - {"__init__", "__reduce__", "__eq__", "__hash__", "_repr_svg_"}
    public = {m for m in dir(sphtroch.GearTrain) if not m.startswith("_")}
    assert members == public, members ^ public


def test_stub_documents_every_function():
    documented, seen = set(), set()
    tree = stub_tree()
    typing_members = {m for c in tree.body if typing_only(c) for m in c.body}
    for node in ast.walk(tree):
        if node in typing_members:
            continue
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_") and node.name not in ("p", "q"):
            seen.add(node.name)
            if ast.get_docstring(node):
                documented.add(node.name)  # an overloaded function: on one of its overloads
    assert seen == documented, seen - documented


def test_every_stub_docstring_is_the_runtime_docstring():
    # One source (issue 21): python/gen_docstrings.py compiles the stub's docstrings into the module,
    # so help() and Jupyter's ? show them; pybind11 puts the signature line(s) first.
    tree = stub_tree()
    checked = 0
    for node in tree.body:
        if not isinstance(node, (ast.FunctionDef, ast.ClassDef)) or typing_only(node):
            continue
        obj = getattr(sphtroch, node.name)
        text = ast.get_docstring(node)
        if text:
            assert inspect.cleandoc(text) in (obj.__doc__ or ""), node.name
            checked += 1
        for member in getattr(node, "body", []):
            text = isinstance(member, ast.FunctionDef) and ast.get_docstring(member)
            if text:
                assert inspect.cleandoc(text) in (getattr(obj, member.name).__doc__ or ""), node.name + "." + member.name
                checked += 1
    assert checked >= 29  # 10 functions, 3 classes, 16 members of GearTrain (when this was written)
    assert "trajectory P(theta2)" in pydoc.render_doc(sphtroch.GearTrain.trace)
