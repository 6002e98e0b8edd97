#!/usr/bin/env python3
"""Checks the include graph of include/sphtroch (CI runs it; exit 1 on a violation).

0. Folders are layers (docs/design.md, "Layers"): a header in folder F may include only headers
   of the folders LAYERS[F] allows; the entry headers at the top may include anything. A layer
   may have sub-layers, one folder deeper: a header's layer is its folder path, and a sub-layer
   names what it may include like any other layer (its parent included). CGAL is included only
   under exact/, except CGAL's interval type (CGAL headers only), which only
   interval/interval.hpp includes; nlohmann-json (header-only) from io/ upward, not in core/ or
   interval/; OpenCASCADE only under cad/, HEALPix only in machine/dwell_map.hpp (the
   folder says what a header costs).

1. No cycle: the headers must form a stack (every arrow points down). A cycle means some arrow
   runs back up; each one found is printed with its path.
2. No header uses another header's detail namespace: `detail::name` (or `xyz_detail::name`)
   may only name something the header itself defines in a detail namespace, or that a header it
   includes defines in the shared `detail` namespace it also opens... simpler and stricter: a
   header may only use `<prefix>_detail::` namespaces it defines itself, and `detail::` names it
   defines itself or that are listed in SHARED_DETAIL (small helpers meant to be shared).
Usage: python3 scripts/check_includes.py [include/sphtroch]
"""
import os
import re
import sys

# detail:: helpers every header may use (defined once, in the header named).
SHARED_DETAIL = {
    "trim": "io/parse.hpp",           # spaces around typed text
    "strict_double": "io/parse.hpp",  # a whole string as a finite double
    "strict_int": "io/parse.hpp",     # a whole string as an integer
}

# Which folders a header of each folder may include (a folder always includes its own).
LAYERS = {
    "core": [],                                   # types, errors, the train, the curve, sampling
    "interval": ["core"],                         # the interval number (CGAL's Interval_nt), 3-vectors, the Krawczyk step, root isolation
    "io": ["core"],                               # numbers as text, parsing, files, formats
    "draw": ["core", "io"],                       # SVG
    "map": ["core", "io"],                        # closed-form boundaries, criteria, g(b), events
    "census": ["core", "io", "map"],              # refinement, node assembly, the root census
    "chain": ["core", "interval", "io", "draw", "map", "census"],  # rotation chains: the certified census, events along a family, the picture
    "tolerance": ["core", "interval", "io", "map", "census"],      # how far a train is from a topology change; node enclosures over a box
    "synthesis": ["core", "interval", "io", "map", "census"],      # the inverse question: which train draws this
    "wrist": ["core", "interval", "io", "draw"],  # geared wrists with 2 or 3 motors: the model, the certified inverse kinematics, the folds (cap, atlas), the regions and their picture
    "exact": ["core", "interval", "io", "draw", "map", "census", "chain", "tolerance", "synthesis"],  # CGAL: crossings, classify, scenes, reports
    "atlas": ["core", "io", "draw", "map", "census"],  # the design map over a grid (no CGAL)
    "cad": ["core", "io"],                        # OpenCASCADE: the path as a STEP B-spline
    "machine": ["core", "io", "draw"],            # clinostats: gravity path, window means, dwell (HEALPix)
}
TOP_LEVEL_MAX = 8
HEAVY = re.compile(r'^\s*#\s*include\s+<CGAL/', re.M)
# nlohmann-json (header-only, like Eigen) writes every JSON from io/ upward; not in core/ or interval/.
JSON = re.compile(r'^\s*#\s*include\s+<nlohmann/', re.M)
NO_JSON = ("core", "interval")
# The one header that includes CGAL's interval number type (headers only, no GMP).
INTERVAL_NUMBER = "interval/interval.hpp"
INTERVAL_ONLY = re.compile(r'^\s*#\s*include\s+<(?!CGAL/Interval_nt\.h>)(CGAL|nlohmann)/', re.M)
# GMP or MPFR, directly or through mpreal / Eigen's MPRealSupport: exact/ only.
MULTIPRECISION = re.compile(r'^\s*#\s*include\s+<(gmp\.h|gmpxx\.h|mpfr\.h|mpreal\.h|unsupported/Eigen/MPRealSupport)>', re.M)
OPENCASCADE = re.compile(r'^\s*#\s*include\s+<\w+\.hxx>', re.M)
HEALPIX = re.compile(r'^\s*#\s*include\s+<(healpix_\w+|chealpix)\.h>', re.M)

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "include", "sphtroch")
headers = sorted(os.path.relpath(os.path.join(d, f), root).replace(os.sep, "/")
                 for d, _, files in os.walk(root) for f in files if f.endswith(".hpp"))
text = {h: open(os.path.join(root, h), encoding="utf-8").read() for h in headers}
include_re = re.compile(r'^\s*#\s*include\s+"sphtroch/([^"]+)"', re.M)
graph = {h: include_re.findall(text[h]) for h in headers}

problems = []


def folder(h):
    """The header's layer: its folder path below include/sphtroch ("" at the top)."""
    return h.rsplit("/", 1)[0] if "/" in h else ""


# 0. Folder rules.
top = [h for h in headers if not folder(h)]
if len(top) > TOP_LEVEL_MAX:
    problems.append(f"{len(top)} headers at the top of include/sphtroch (at most {TOP_LEVEL_MAX}): {', '.join(top)}")
for h in headers:
    f = folder(h)
    if f and f not in LAYERS:
        problems.append(f"{h}: folder {f}/ is not a layer of LAYERS")
        continue
    for d in graph[h]:
        if f and folder(d) != f and folder(d) not in LAYERS[f]:
            problems.append(f"{h}: includes sphtroch/{d}, but {f}/ may include only "
                            + ", ".join(x + "/" for x in [f] + LAYERS[f]))
    if h == INTERVAL_NUMBER:
        if INTERVAL_ONLY.search(text[h]):
            problems.append(f"{h}: includes more of CGAL than <CGAL/Interval_nt.h>, or nlohmann-json")
    elif f != "exact" and f and HEAVY.search(text[h]):
        problems.append(f"{h}: includes CGAL outside exact/ (CGAL's intervals: only {INTERVAL_NUMBER})")
    if (f in NO_JSON or not f) and JSON.search(text[h]):
        problems.append(f"{h}: includes nlohmann-json in {f or 'the top'}/ (JSON is written from io/ upward)")
    if f != "exact" and MULTIPRECISION.search(text[h]):
        problems.append(f"{h}: includes GMP or MPFR outside exact/")
    if f != "cad" and OPENCASCADE.search(text[h]):
        problems.append(f"{h}: includes OpenCASCADE outside cad/")
    if h != "machine/dwell_map.hpp" and HEALPIX.search(text[h]):
        problems.append(f"{h}: includes HEALPix outside machine/dwell_map.hpp")

# 1. Cycles (depth-first search, reporting each back edge with the path).
state = {}
stack = []


def visit(h):
    state[h] = "open"
    stack.append(h)
    for d in graph.get(h, []):
        if d not in text:
            problems.append(f"{h}: includes sphtroch/{d}, which does not exist")
            continue
        if state.get(d) == "open":
            cycle = stack[stack.index(d):] + [d]
            problems.append("cycle (an arrow runs back up): " + " -> ".join(cycle))
        elif d not in state:
            visit(d)
    stack.pop()
    state[h] = "done"


for h in headers:
    if h not in state:
        visit(h)

# 2. detail namespaces used across headers.
def_re = re.compile(r"namespace\s+(\w*detail)\s*\{(.*?)^\}\s*//\s*namespace\s+\1", re.S | re.M)
name_re = re.compile(r"^(?:inline|constexpr|template|struct|class|using|enum)[^;{(=]*?\b(\w+)\s*(?:[({=;:<]|$)", re.M)
defined = {}
for h in headers:
    for ns, body in def_re.findall(text[h]):
        # Top-level declarations of the namespace body (no indentation in this code base): the
        # first name followed by ( [ = { ; on the line, and struct/class/enum/using names.
        for line in body.splitlines():
            if not line or line[0].isspace() or line.startswith(("//", "#", "}")):
                continue
            m = re.search(r"\b(?:struct|class|enum(?:\s+class)?|using)\s+(\w+)", line)
            if not m:
                m = re.search(r"(\w+)\s*(?:\(|\[|=|\{|;)", line)
            if m:
                defined.setdefault((ns, m.group(1)), set()).add(h)

use_re = re.compile(r"\b(\w*detail)::(\w+)")
for h in headers:
    code = re.sub(r"//.*", "", text[h])
    for ns, name in sorted(set(use_re.findall(code))):
        owners = defined.get((ns, name), set())
        if h in owners:
            continue
        if ns == "detail" and SHARED_DETAIL.get(name) in owners:
            continue
        where = ", ".join(sorted(owners)) or "unknown header"
        problems.append(f"{h}: uses {ns}::{name} of {where}")

for p in problems:
    print("check_includes:", p)
if problems:
    sys.exit(1)
print(f"check_includes: {len(headers)} headers ({len(top)} at the top, {len(LAYERS)} layer folders), "
      f"{sum(len(v) for v in graph.values())} arrows, folder rules hold, no cycle, "
      "no detail namespace used across headers")
