"""help() and inspect show the stub's signatures (issue 43): no pybind11 placeholders (`handle`,
`object`), the typed line(s) of the stub first in every docstring, and inspect.signature giving
the stub's names, kinds and defaults. The stub is read with ast (stub_info.py), the help text
parsed on its own: an independent comparison."""
import ast
import inspect
import pydoc
import re

import pytest

import sphtroch
from stub_info import functions

STUB = functions()
PLACEHOLDER = re.compile(r"(:\s*handle\b|->\s*handle\b|:\s*object\b|->\s*object\b)")


def runtime(key):
    obj = sphtroch
    for part in key.split("."):
        obj = getattr(obj, part)
    return obj


def parsed_def(line):
    """A signature line `name(...) -> T` parsed as a def (ast)."""
    return ast.parse(f"def {line}: ...").body[0]


def same_def(a, b):
    return ast.dump(a.args) == ast.dump(b.args) and ast.dump(a.returns) == ast.dump(b.returns) if a.returns else \
        ast.dump(a.args) == ast.dump(b.args) and b.returns is None


def test_the_stub_lists_every_public_call():
    assert {"GearTrain.classify", "GearTrain.trace", "GearTrain.__init__", "atlas", "fit", "crossings",
            "GearTrain.node_set", "GearTrain.plot", "PointSet.to_list"} <= set(STUB)
    assert len(STUB) >= 29  # 10 functions and 19 methods when this was written


@pytest.mark.parametrize("key", sorted(STUB))
def test_help_has_no_placeholders_and_starts_with_the_stubs_typed_lines(key):
    obj = runtime(key)
    text = pydoc.render_doc(obj, renderer=pydoc.plaintext)
    assert not PLACEHOLDER.search(text), (key, PLACEHOLDER.search(text).group(0), text[:400])
    overloads = STUB[key]
    lines = (obj.__doc__ or "").splitlines()[:len(overloads)]
    assert len(lines) == len(overloads), key
    name = key.rsplit(".", 1)[-1]
    for line, node in zip(lines, overloads):
        assert line.startswith(name + "("), (key, line)
        assert same_def(parsed_def(line), node), (key, line, ast.unparse(node.args))
        assert line in text  # help() shows it


def stub_parameters(overloads):
    """{name: (keyword_only, default)} merged over the overloads (default: literal value, or None
    when some overload lacks the parameter; inspect.Parameter.empty when required everywhere)."""
    merged = {}
    for node in overloads:
        a = node.args
        defaults = [None] * (len(a.args) - len(a.defaults)) + list(a.defaults)
        names = []
        for arg, d, kw in [(p, d, False) for p, d in zip(a.args, defaults)] + \
                          [(p, d, True) for p, d in zip(a.kwonlyargs, a.kw_defaults)]:
            names.append(arg.arg)
            kw_only, default = merged.get(arg.arg, (True, inspect.Parameter.empty))
            if d is not None and default is inspect.Parameter.empty:
                default = eval(ast.unparse(d), {"float": float})
            merged[arg.arg] = (kw_only and kw, default)
        for other in merged:
            if other not in names and merged[other][1] is inspect.Parameter.empty:
                merged[other] = (merged[other][0], None)
    for n in merged:
        if any(n not in [p.arg for p in o.args.args + o.args.kwonlyargs] for o in overloads) \
                and merged[n][1] is inspect.Parameter.empty:
            merged[n] = (merged[n][0], None)
    return merged


@pytest.mark.parametrize("key", sorted(STUB))
def test_inspect_signature_has_the_stubs_names_kinds_and_defaults(key):
    sig = inspect.signature(runtime(key))
    want = stub_parameters(STUB[key])
    assert list(sig.parameters) == list(want), key
    for name, p in sig.parameters.items():
        kw_only, default = want[name]
        assert (p.kind == inspect.Parameter.KEYWORD_ONLY) == kw_only, (key, name, p.kind)
        assert p.default == default or (p.default is inspect.Parameter.empty and default is inspect.Parameter.empty), \
            (key, name, p.default, default)


def test_classify_reads_as_in_the_stub():
    sig = inspect.signature(sphtroch.GearTrain.classify)
    assert str(sig) == "(self, *, literal=False, samples=None)"
    assert sphtroch.GearTrain.classify.__doc__.splitlines()[0] == \
        "classify(self, *, literal: Flag = False, samples: Optional[Count] = None) -> Classification"
    help_text = pydoc.render_doc(sphtroch.GearTrain, renderer=pydoc.plaintext)
    assert "a2: handle" not in help_text and "-> object" not in help_text
