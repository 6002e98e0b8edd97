"""The stub (python/sphtroch/__init__.pyi) read with ast, independently of the module: its
functions and methods with their overloads, and its typing-only classes (TypedDict, Protocol)."""
import ast
import os

SOURCE_DIR = os.environ.get("SPHTROCH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
STUB = os.path.join(SOURCE_DIR, "python", "sphtroch", "__init__.pyi")


def tree():
    with open(STUB) as f:
        return ast.parse(f.read())


def typing_only(node):
    """A class the stub declares for type checkers only (TypedDict, Protocol): no runtime object."""
    return isinstance(node, ast.ClassDef) and any(ast.unparse(b) in ("TypedDict", "Protocol") for b in node.bases)


def functions():
    """{"name" or "Class.name": [FunctionDef, ...]} of the public functions and methods (properties
    excluded), overloads in stub order."""
    out = {}

    def add(key, node):
        if not any(ast.unparse(d) == "property" for d in node.decorator_list):
            out.setdefault(key, []).append(node)

    for node in tree().body:
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
            add(node.name, node)
        if isinstance(node, ast.ClassDef) and not typing_only(node):
            for m in node.body:
                if isinstance(m, ast.FunctionDef) and (not m.name.startswith("_") or m.name in ("__init__", "_repr_svg_")):
                    add(node.name + "." + m.name, m)
    return out


def typed_dicts():
    """{name: {key: annotation text}} of every TypedDict, class syntax and functional syntax."""
    out = {}
    for node in tree().body:
        if isinstance(node, ast.ClassDef) and any(ast.unparse(b) == "TypedDict" for b in node.bases):
            out[node.name] = {a.target.id: ast.unparse(a.annotation) for a in node.body if isinstance(a, ast.AnnAssign)}
        if (isinstance(node, ast.Assign) and isinstance(node.value, ast.Call) and ast.unparse(node.value.func) == "TypedDict"):
            fields = node.value.args[1]
            out[node.targets[0].id] = {k.value: ast.unparse(v) for k, v in zip(fields.keys, fields.values)}
    return out
