#!/usr/bin/env python3
"""Fails (exit 1) when the project cites a file it does not contain (ctest docs:links).

  python3 scripts/check_doc_links.py [REPO_ROOT]

Scans README.md, docs/*.md and every tracked source file under include/, src/, python/, tests/
(not tests/third_party), scripts/, bench/, cmake/ and .ci/ for
  - relative Markdown links [text](path) (in .md files): the path must exist, relative to the
    file (an #anchor is ignored);
  - names ending in .hpp, .cpp, .py, .md, .sh, .cmake: a name with a folder must exist at that
    path from the repository root or from include/ (sphtroch/core/types.hpp); a bare name must be
    some tracked file's name.
Names of other projects' files (Eigen/, CGAL/, pybind11/, nlohmann/, catch2/, s2/ ...) and the
CHANGELOG's table of moved headers, if scanned (between the markers "moved-headers" and "end moved-headers",
whose left column names files that no longer exist) are skipped.
"""
import pathlib
import re
import subprocess
import sys

EXTERNAL = ("Eigen/", "CGAL/", "pybind11/", "nlohmann/", "catch2/", "s2/", "benchmark/", "boost/", "CLI/", "gmp", "mpfr",
            "emscripten", "fuzzer/")
NAME = re.compile(r"(?<![\w./$}-])((?:[\w.-]+/)*[\w-]+\.(?:hpp|cpp|py|md|sh|cmake))(?![\w/])")
LINK = re.compile(r"\]\(([^)\s]+)\)")
# Names that are not files of this project although they look like one (generic examples).
GENERIC = {"app.cpp", "main.cpp", "x.py", "setup.py", "conftest.py", "README.md", "CMakeLists.txt",
           "file.cpp", "sphtroch_impl.cpp", "cmd.sh", "page.md",  # page.md: bench/doc_figures.py's self-test page
           "docstrings.hpp"}  # generated into the build tree by python/gen_docstrings.py
# Paths of an install prefix (made by `cmake --install`), not of the source tree.
INSTALLED = ("share/", "lib/", "bin/")


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
    tracked = subprocess.check_output(["git", "ls-files"], cwd=root, text=True).split()
    tracked += subprocess.check_output(["git", "ls-files", "--others", "--exclude-standard"], cwd=root, text=True).split()
    names = {pathlib.PurePosixPath(f).name for f in tracked}
    paths = set(tracked)
    scan = [f for f in tracked if (f == "README.md" or f.startswith("docs/") and f.endswith(".md")
            or f.split("/")[0] in ("include", "src", "python", "tests", "scripts", "bench", "cmake", ".ci"))
            and "third_party" not in f and (root / f).is_file()]
    problems = []
    for f in scan:
        try:
            text = (root / f).read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        text = re.sub(r"<!-- moved-headers.*?<!-- end moved-headers -->", "", text, flags=re.S)
        for no, line in enumerate(text.splitlines(), 1):
            if f.endswith(".md"):
                for target in LINK.findall(line):
                    target = target.split("#")[0]
                    if not target or re.match(r"^[a-z]+:", target):
                        continue
                    if not (root / f).parent.joinpath(target).resolve().exists():
                        problems.append(f"{f}:{no}: link to {target}, which does not exist")
            for name in NAME.findall(line):
                stem = pathlib.PurePosixPath(name).stem
                if name.startswith(EXTERNAL + INSTALLED) or name in GENERIC or (stem.isupper() and not name.endswith(".md")):
                    continue  # another project's file, an installed path, a placeholder (OLD.hpp)
                if name.startswith("../") or name.startswith("./"):
                    ok = (root / f).parent.joinpath(name).resolve().exists()
                elif "/" in name:
                    ok = any(name in paths or p.endswith("/" + name) for p in ([name] if name in paths else paths))
                    ok = ok or name in paths or f"include/{name}" in paths
                else:
                    ok = name in names
                if not ok:
                    problems.append(f"{f}:{no}: names {name}, which is not a file of the project")
    for p in problems:
        print("check_doc_links:", p)
    print(f"check_doc_links: {len(scan)} files read, {len(problems)} names of missing files")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
