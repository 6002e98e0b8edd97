#!/usr/bin/env python3
"""The lists the docs keep about the tree, compared with the tree, so that they cannot drift.

    python3 scripts/check_doc_lists.py [ROOT]    (ctest docs:lists; ROOT defaults to this script's repository)

- CMake targets: the `add_library(sphtroch::X ALIAS ...)` of ROOT/CMakeLists.txt, the rows
  "| `sphtroch::X` |" of README.md's and docs/library.md's target tables, and the count word of
  docs/library.md's "<N> CMake targets" sentence.
- Guarded headers: the headers under include/sphtroch/ with an `#error` line, and the list between
  "<!-- guarded-headers -->" and "<!-- end guarded-headers -->" in docs/library.md (paths in
  backquotes, relative to include/sphtroch/); each listed header's #error names the target the
  list gives it.
- Umbrella: include/sphtroch/sphtroch.hpp includes every header under include/sphtroch/ but
  itself and exact_implementation.hpp (separate mode's one definition file); its opening comment
  names every top-level layer folder ("core/", ...).
- Folders: the folders README.md's target table names (backquoted "core/", "chain/",
  ... in its "| `sphtroch::X` |" rows) and the folders under include/sphtroch/ that hold a header
  (at any depth; nested ones too, "a/b/"), both ways.
- Binding files: the bind_*.cpp files named in the opening comment of python/src/bindings.hpp and
  the python/src/bind_*.cpp files, both ways; where the comment says "<N> topic files (...)", N is
  the number of bind_*.cpp names in that parenthesis.
- Test executables: the test executables declared under tests/ (the <name> of every
  `sphtroch_add_test(<name> ...)` and every `add_executable(test_...)` in tests/**/CMakeLists.txt
  and *.cmake, tests/third_party aside; comments ignored) and the backquoted `test_...` names of
  docs/library.md's `tests/` layout paragraph, both ways; the QUICK ones and the `test_...`
  names of its "- The edit-compile-test loop:" bullet, both ways.
Prints one line per disagreement; exit 1 if any, 0 otherwise, 2 on bad arguments.
"""
import pathlib
import re
import sys

COUNT_WORDS = {1: "One", 2: "Two", 3: "Three", 4: "Four", 5: "Five", 6: "Six", 7: "Seven", 8: "Eight"}
NOT_IN_UMBRELLA = {"sphtroch.hpp", "exact_implementation.hpp"}


def table_targets(text):
    return set(re.findall(r"^\| `(sphtroch::\w+)` \|", text, flags=re.M))


def check_targets(root, readme, library, problems):
    cmake = (root / "CMakeLists.txt").read_text(encoding="utf-8")
    defined = set(re.findall(r"add_library\((sphtroch::\w+) ALIAS", cmake))
    for name, text in (("README.md", readme), ("docs/library.md", library)):
        listed = table_targets(text)
        for t in sorted(defined - listed):
            problems.append(f"{name}: the target table lacks {t} (CMakeLists.txt defines it)")
        for t in sorted(listed - defined):
            problems.append(f"{name}: the target table lists {t}, which CMakeLists.txt does not define")
    m = re.search(r"\b(\w+) CMake targets", library)
    want = COUNT_WORDS.get(len(defined), str(len(defined)))
    if not m or m.group(1) != want:
        problems.append(f"docs/library.md: says '{m.group(1) if m else '?'} CMake targets', the tree has {want}")


def check_guarded(root, library, problems):
    include = root / "include" / "sphtroch"
    guarded = {}
    for h in sorted(include.rglob("*.hpp")):
        line = next((l for l in h.read_text(encoding="utf-8").splitlines() if l.startswith("#error")), None)
        if line:
            guarded[h.relative_to(include).as_posix()] = line
    m = re.search(r"<!-- guarded-headers -->(.*?)<!-- end guarded-headers -->", library, flags=re.S)
    if not m:
        problems.append("docs/library.md: no guarded-headers list (<!-- guarded-headers --> ... <!-- end guarded-headers -->)")
        return
    listed = {}
    # Groups separated by ";", each a list of backquoted header paths and then its target in parentheses.
    for group in m.group(1).split(";"):
        target = re.search(r"\(`(sphtroch::\w+)`\)", group)
        for header in re.findall(r"`([\w/]+\.hpp)`", group):
            listed[header] = target.group(1) if target else None
    for h in sorted(set(guarded) - set(listed)):
        problems.append(f"docs/library.md: the guarded-headers list lacks {h} (it has an #error)")
    for h in sorted(set(listed) - set(guarded)):
        problems.append(f"docs/library.md: the guarded-headers list names {h}, which has no #error")
    for h in sorted(set(listed) & set(guarded)):
        if listed[h] is None or listed[h] not in guarded[h]:
            problems.append(f"docs/library.md: {h} is listed under {listed[h]}, its #error says: {guarded[h][:100]}")


def check_umbrella(root, problems):
    include = root / "include" / "sphtroch"
    umbrella = (include / "sphtroch.hpp").read_text(encoding="utf-8")
    included = set(re.findall(r'^#include "sphtroch/([\w/]+\.hpp)"', umbrella, flags=re.M))
    for h in sorted(include.rglob("*.hpp")):
        rel = h.relative_to(include).as_posix()
        if rel not in NOT_IN_UMBRELLA and rel not in included:
            problems.append(f"include/sphtroch/sphtroch.hpp: does not include sphtroch/{rel}")
    comment = "\n".join(l for l in umbrella.splitlines() if l.startswith("//"))
    for folder in sorted(p.name for p in include.iterdir() if p.is_dir() and any(p.rglob("*.hpp"))):
        if f"{folder}/" not in comment:
            problems.append(f"include/sphtroch/sphtroch.hpp: its opening comment does not name {folder}/")


def check_readme_folders(root, readme, problems):
    """README.md's target table against the folders of include/sphtroch/ that hold a header."""
    include = root / "include" / "sphtroch"
    present = {p.relative_to(include).as_posix() + "/" for p in include.rglob("*")
               if p.is_dir() and any(p.rglob("*.hpp"))}
    table = "\n".join(l for l in readme.splitlines() if l.startswith("| `sphtroch::"))
    named = set(re.findall(r"`((?:[\w-]+/)+)`", table))
    for folder in sorted(present - named):
        problems.append(f"README.md: the target table does not name `{folder}` (include/sphtroch/{folder} exists)")
    for folder in sorted(named - present):
        problems.append(f"README.md: the target table names `{folder}`, which include/sphtroch/ does not have")


def opening_comment(path):
    """The text of a file's opening // comment, the markers stripped, its lines joined by spaces."""
    lines = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.startswith("//"):
            break
        lines.append(line[2:].strip())
    return " ".join(lines)


def check_bindings(root, problems):
    """The binding files named in python/src/bindings.hpp's opening comment against python/src/bind_*.cpp."""
    src = root / "python" / "src"
    comment = opening_comment(src / "bindings.hpp")
    named = set(re.findall(r"\b(bind_\w+\.cpp)\b", comment))
    present = {p.name for p in src.glob("bind_*.cpp")}
    for f in sorted(present - named):
        problems.append(f"python/src/bindings.hpp: its opening comment does not name {f} (python/src/ has it)")
    for f in sorted(named - present):
        problems.append(f"python/src/bindings.hpp: its opening comment names {f}, which python/src/ does not have")
    m = re.search(r"\b(\w+) topic files? \(([^)]*)\)", comment)
    if m:
        topics = re.findall(r"\bbind_\w+\.cpp\b", m.group(2))
        want = COUNT_WORDS.get(len(topics), str(len(topics)))
        if m.group(1).lower() != want.lower():
            problems.append(f"python/src/bindings.hpp: its opening comment says '{m.group(1)} topic files' "
                            f"and lists {len(topics)}")


CMAKE_COMMENT = re.compile(r'("(?:[^"\\]|\\.)*")|#.*')


def declared_tests(root):
    """{name: (quick, file)} of the test executables declared in tests/'s CMake files."""
    tests = root / "tests"
    found = {}
    files = sorted(set(tests.rglob("CMakeLists.txt")) | set(tests.rglob("*.cmake")))
    for f in files:
        rel = f.relative_to(root).as_posix()
        if rel.startswith("tests/third_party/"):
            continue
        text = CMAKE_COMMENT.sub(lambda m: m.group(1) or "", f.read_text(encoding="utf-8"))
        for name, quick in re.findall(r"\bsphtroch_add_test\(\s*(\w+)(\s+QUICK\b)?", text):
            found[name] = (bool(quick), rel)
        for name in re.findall(r"\badd_executable\(\s*(test_\w+)", text):
            found.setdefault(name, (False, rel))
    return found


def compare_tests(where, listed, declared, problems, what):
    for name in sorted(set(declared) - listed):
        problems.append(f"docs/library.md: {where} does not name {name} ({declared[name]} declares it{what})")
    for name in sorted(listed - set(declared)):
        problems.append(f"docs/library.md: {where} names {name}, which tests/ does not declare{what}")


def check_tests(root, library, problems):
    """docs/library.md's lists of test executables against those tests/ declares."""
    declared = declared_tests(root)
    layout = re.search(r"^`tests/` (.*?) ·\s*$", library, flags=re.M | re.S)
    if not layout:
        problems.append("docs/library.md: no `tests/` paragraph (\"`tests/` ... ·\") in the layout")
    else:
        listed = set(re.findall(r"`(test_\w+)`", layout.group(1)))
        compare_tests("the `tests/` layout", listed, {n: f for n, (_, f) in declared.items()}, problems, "")
    loop = re.search(r"^- The edit-compile-test loop:(.*?)(?=^- |^#|\Z)", library, flags=re.M | re.S)
    if not loop:
        problems.append("docs/library.md: no \"- The edit-compile-test loop:\" bullet under Tests")
    else:
        listed = set(re.findall(r"`(test_\w+)`", loop.group(1)))
        quick = {n: f for n, (q, f) in declared.items() if q}
        compare_tests("the quick loop's list", listed, quick, problems, " with QUICK")


def main(argv):
    if len(argv) > 2 or len(argv) == 2 and not pathlib.Path(argv[1]).is_dir():
        print("usage: check_doc_lists.py [ROOT]", file=sys.stderr)
        return 2
    root = pathlib.Path(argv[1]) if len(argv) == 2 else pathlib.Path(__file__).resolve().parent.parent
    readme = (root / "README.md").read_text(encoding="utf-8")
    library = (root / "docs" / "library.md").read_text(encoding="utf-8")
    problems = []
    check_targets(root, readme, library, problems)
    check_guarded(root, library, problems)
    check_umbrella(root, problems)
    check_readme_folders(root, readme, problems)
    check_bindings(root, problems)
    check_tests(root, library, problems)
    for p in problems:
        print("check_doc_lists:", p)
    print(f"check_doc_lists: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
