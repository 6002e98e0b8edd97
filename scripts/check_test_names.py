#!/usr/bin/env python3
"""Fails (exit 1) when a ctest test name is too long or a Catch2 test case name would break ctest.

  python3 scripts/check_test_names.py CTEST BUILD_DIR [MAX]

Catch2 test cases become one ctest test each (catch_discover_tests), through CMake lists: a ";" in
a test case name splits it into two tests that run nothing, and an unbalanced "[" joins every
following name into one test (a result line of thousands of characters). So: every name that
`ctest -N` lists must be at most MAX (default 160) characters, and no TEST_CASE name in tests/
may hold ";" or an unbalanced "[".
"""
import pathlib
import re
import subprocess
import sys

ctest, build = sys.argv[1], sys.argv[2]
limit = int(sys.argv[3]) if len(sys.argv) > 3 else 160
listing = subprocess.run([ctest, "-N"], cwd=build, capture_output=True, text=True, check=True).stdout
names = re.findall(r"^\s*Test +#\d+: (.*)$", listing, re.M)
problems = [f"ctest name of {len(n)} characters (at most {limit}): {n[:200]}..." for n in names if len(n) > limit]
tests_dir = pathlib.Path(__file__).resolve().parent.parent / "tests"
sources = [p for p in sorted(tests_dir.rglob("*.cpp")) if "third_party" not in p.parts]
cases = 0
for path in sources:
    for name in re.findall(r'TEST_CASE\("([^"]*)"', path.read_text()):
        cases += 1
        if ";" in name or name.count("[") != name.count("]"):
            problems.append(f"{path.relative_to(tests_dir)}: TEST_CASE name with ';' or an unbalanced '[': {name}")
if cases < 50:
    problems.append(f"only {cases} TEST_CASE names read under {tests_dir}: the sources were not found")
for p in problems:
    print("check_test_names:", p)
if len(names) < 50:
    print(f"check_test_names: only {len(names)} tests listed: the listing was not read")
    sys.exit(1)
print(f"check_test_names: {len(names)} ctest names, longest {max(len(n) for n in names)} characters, "
      f"{len(problems)} problems")
sys.exit(1 if problems else 0)
