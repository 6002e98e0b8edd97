"""python3 gen_docstrings.py STUB OUT — the module's runtime docstrings from its stub.

The stub (sphtroch/__init__.pyi) is the one source of the docstrings and signatures: this writes
OUT, a C++ header with an entry per documented function, method, property or class of the stub,
keyed "name" (a function or class) or "Class.member", which the bindings pass to pybind11
(bindings.hpp: doc()). A name the bindings ask for that the stub does not document fails the
module's import, so the two cannot drift apart.

Each function's entry holds two texts:
  * builtin: for a pybind11 function (the module disables pybind11's own signature line, which
    shows `handle` and `object` for arguments the bindings validate themselves). It starts with
    CPython's text signature, `name(a, b=1, *, c=None)\\n--\\n\\n` (names, kinds and defaults; no
    annotations, which inspect does not read there), which CPython turns into __text_signature__
    (inspect.signature works) and strips from __doc__; then the stub's typed signature line(s),
    one per @overload, a blank line and the docstring.
  * python: the typed line(s), a blank line and the docstring, for the package's pure-Python
    functions (node_set, plot, ...), whose signatures Python knows.
Properties and classes get their docstring only.
"""
import ast
import inspect
import math
import sys


def default_text(node):
    """A default as text inspect's text-signature parser reads (ast.literal_eval of it): the
    value's repr; an infinite float as 1e999 (repr "inf" is no literal); None for `...`."""
    if isinstance(node, ast.Constant) and node.value is Ellipsis:
        return "None"
    value = eval(compile(ast.Expression(node), "<stub>", "eval"), {"__builtins__": {"float": float}})
    if isinstance(value, float) and math.isinf(value):
        return "1e999" if value > 0 else "-1e999"
    text = repr(value)
    assert ast.literal_eval(text) == value, text
    return text


def parameters(node):
    """[(name, keyword_only, default node or None)] of a FunctionDef (the stub has no / or *args)."""
    a = node.args
    assert not a.posonlyargs and not a.vararg and not a.kwarg, node.name
    positional = [None] * (len(a.args) - len(a.defaults)) + list(a.defaults)
    return ([(p.arg, False, d) for p, d in zip(a.args, positional)] +
            [(p.arg, True, d) for p, d in zip(a.kwonlyargs, a.kw_defaults)])


def text_signature(name, overloads):
    """The runtime signature of the overloads merged: every parameter in order of first appearance,
    keyword-only unless positional in some overload; its default the first one an overload gives
    (`...` and a parameter some overload lacks read as None, the runtime's "not given")."""
    merged = {}
    for node in overloads:
        for pname, kw_only, default in parameters(node):
            m = merged.setdefault(pname, {"kw_only": True, "default": None, "everywhere": True})
            m["kw_only"] = m["kw_only"] and kw_only
            if default is not None and m["default"] is None:
                m["default"] = default
    for pname, m in merged.items():
        m["everywhere"] = all(pname in [p for p, _, _ in parameters(o)] for o in overloads)
    out, star = [], False
    for pname, m in merged.items():
        if m["kw_only"] and not star:
            out.append("*")
            star = True
        if m["default"] is not None:
            out.append(f"{pname}={default_text(m['default'])}")
        elif not m["everywhere"]:
            out.append(f"{pname}=None")
        else:
            out.append(pname)
    return f"{name}({', '.join(out)})"


def typed_line(name, node):
    """The stub's def line as written there: `name(a: T, b: U = 1, *, c: V = None) -> R`."""
    out, star = [], False
    for pname, kw_only, default in parameters(node):
        if kw_only and not star:
            out.append("*")
            star = True
        arg = next(a for a in node.args.args + node.args.kwonlyargs if a.arg == pname)
        text = pname + (f": {ast.unparse(arg.annotation)}" if arg.annotation else "")
        if default is not None:
            text += (" = " if arg.annotation else "=") + ast.unparse(default)
        out.append(text)
    returns = f" -> {ast.unparse(node.returns)}" if node.returns else ""
    return f"{name}({', '.join(out)}){returns}"


def is_property(node):
    return any(isinstance(d, ast.Name) and d.id == "property" for d in node.decorator_list)


def collect(tree):
    """{key: (docstring or "", [FunctionDef overloads] or None for classes and properties)}."""
    found = {}

    def add(key, node):
        text = ast.get_docstring(node) or ""
        if isinstance(node, ast.ClassDef) or is_property(node):
            if key not in found:
                found[key] = (text, None)
            return
        old_text, overloads = found.get(key, ("", []))
        found[key] = (old_text or text, overloads + [node])

    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            add(node.name, node)
        if isinstance(node, ast.ClassDef):
            for member in node.body:
                if isinstance(member, ast.FunctionDef):
                    add(node.name + "." + member.name, member)
    return found


def entry_texts(key, text, overloads):
    """(builtin, python) docstrings of one entry (see the module docstring)."""
    text = inspect.cleandoc(text)
    if overloads is None:
        return text, text
    name = key.rsplit(".", 1)[-1]
    typed = "\n".join(typed_line(name, o) for o in overloads)
    python = typed + ("\n\n" + text if text else "")
    return text_signature(name, overloads) + "\n--\n\n" + python, python


def main():
    stub, out = sys.argv[1:3]
    with open(stub) as f:
        entries = collect(ast.parse(f.read()))
    lines = ["// Generated by python/gen_docstrings.py from sphtroch/__init__.pyi: do not edit.",
             "#pragma once", "", "namespace sphtroch::python::stub_docs {", "",
             "struct Entry {", "  const char* name;", "  const char* builtin;  // text signature, typed line(s), docstring",
             "  const char* python;   // typed line(s), docstring", "};", "",
             "inline constexpr Entry kEntries[] = {"]
    for key, (text, overloads) in sorted(entries.items()):
        builtin, python = entry_texts(key, text, overloads)
        assert ')doc"' not in builtin, key
        lines.append(f'    {{"{key}", R"doc({builtin})doc", R"doc({python})doc"}},')
    lines += ["};", "", "}  // namespace sphtroch::python::stub_docs", ""]
    with open(out, "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()
